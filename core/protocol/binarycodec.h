#pragma once

#include "codec.h"

namespace Fatek {

// FATEK binary protocol (M series): 0x51|0x52, 0x10, length(2, BE), payload, CRC(2, low first), 55
// AA.
class BinaryCodec final : public Codec
{
public:
    static constexpr std::uint8_t queryHeader = 0x51;
    static constexpr std::uint8_t responseHeader = 0x52;
    static constexpr std::uint8_t frameId = 0x10;
    static constexpr std::uint8_t terminator[2] = {0x55, 0xAA};
    static constexpr std::size_t maxPayload
        = 512; // largest legal: 48 query with 64 W addresses, 323 bytes
    static constexpr std::size_t maxFrameSize = 4 + maxPayload + 4;

    // CRC-16/MODBUS (init 0xFFFF, reflected polynomial 0xA001).
    static std::uint16_t crc16(std::span<const std::uint8_t> bytes);

    Protocol protocol() const override { return Protocol::Binary; }
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
