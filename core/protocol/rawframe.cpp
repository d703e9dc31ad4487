#include "rawframe.h"

#include "binarycodec.h"
#include "faconcodec.h"

namespace Fatek {

const Codec &RawFrame::codec(Protocol protocol)
{
    // Codecs are stateless: one of each serves every caller.
    static const FaconCodec facon;
    static const BinaryCodec binary;
    if (protocol == Protocol::Facon)
        return facon;
    return binary;
}

Bytes RawFrame::frame(std::span<const std::uint8_t> typed, std::optional<Protocol> framing)
{
    if (!framing)
        return {typed.begin(), typed.end()};
    return codec(*framing).wrap(typed);
}

std::optional<Protocol> RawFrame::protocolOf(std::span<const std::uint8_t> frame)
{
    if (frame.empty())
        return std::nullopt;
    if (frame.front() == FaconCodec::STX)
        return Protocol::Facon;
    if (frame.front() == BinaryCodec::queryHeader || frame.front() == BinaryCodec::responseHeader)
        return Protocol::Binary;
    return std::nullopt;
}

std::optional<RawFrame::Peek> RawFrame::peek(std::span<const std::uint8_t> frame)
{
    const std::optional<Protocol> protocol = protocolOf(frame);
    if (!protocol)
        return std::nullopt;
    const std::optional<FrameHeader> header = codec(*protocol).peekHeader(frame);
    if (!header)
        return std::nullopt;
    return Peek{*protocol, header->station, header->command};
}

Message RawFrame::summary(std::span<const std::uint8_t> frame)
{
    return codec(protocolOf(frame).value_or(Protocol::Binary)).summary(frame);
}

std::string RawFrame::summarize(std::span<const std::uint8_t> frame)
{
    return english(summary(frame));
}

} // namespace Fatek
