#pragma once

#include "codec.h"

namespace Fatek {

// FACON ASCII protocol (FBs series): STX station(2 hex) command(2 hex) data LRC(2 hex) ETX.
class FaconCodec final : public Codec
{
public:
    static constexpr std::uint8_t STX = 0x02;
    static constexpr std::uint8_t ETX = 0x03;
    static constexpr std::size_t maxDataChars = 500;
    static constexpr std::size_t maxFrameSize = 1 + 2 + 2 + maxDataChars + 2 + 1;

    // Sum of the bytes modulo 256 (the caller passes STX through the last data byte).
    static std::uint8_t lrc(std::span<const std::uint8_t> bytes);

    Protocol protocol() const override { return Protocol::Facon; }
    Result<Bytes> encodeRequest(const Request &request) const override;
    Result<Response> decodeResponse(std::span<const std::uint8_t> frame,
                                    const Request &request) const override;
    Result<Request> decodeRequest(std::span<const std::uint8_t> frame) const override;
    Bytes encodeResponse(const Request &request, const Response &response) const override;
    Bytes encodeErrorResponse(FrameHeader header, std::uint8_t errorCode) const override;
    std::optional<FrameHeader> frameHeader(std::span<const std::uint8_t> frame) const override;
    std::optional<FrameHeader> peekHeader(std::span<const std::uint8_t> frame) const override;
    Bytes wrap(std::span<const std::uint8_t> body, bool response = false) const override;
    Message summary(std::span<const std::uint8_t> frame) const override;
};

} // namespace Fatek
