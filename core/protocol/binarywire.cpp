#include "binarywire.h"

#include "binarycodec.h"

#include <cstdio>

namespace Fatek::BinaryWire {

namespace {

// header, ID, length (2) before the payload; CRC (2) and terminator (2) after it.
constexpr std::size_t kHeadSize = 4;
constexpr std::size_t kTailSize = 4;
constexpr std::size_t kOverhead = kHeadSize + kTailSize;

} // namespace

std::string hex2(std::uint32_t value)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02X", value & 0xFFu);
    return buf;
}

std::string hexBytes(std::span<const std::uint8_t> bytes, std::size_t maxBytes)
{
    std::string s;
    for (std::size_t i = 0; i < bytes.size() && i < maxBytes; ++i) {
        if (i)
            s += ' ';
        s += hex2(bytes[i]);
    }
    if (bytes.size() > maxBytes)
        s += " ...";
    return s;
}

std::string commandText(std::uint8_t code)
{
    if (!isKnownCommand(code))
        return hex2(code) + " unknown command";
    return hex2(code) + " " + std::string(commandName(static_cast<Command>(code)));
}

std::size_t valueSize(ElementType type)
{
    switch (elementInfo(type).width) {
    case ElementWidth::Bit: return 1;
    case ElementWidth::Word: return 2;
    case ElementWidth::DoubleWord: return 4;
    }
    return 2;
}

void appendValue(Bytes &out, ElementType type, std::uint32_t value)
{
    switch (valueSize(type)) {
    case 1: out.push_back(value != 0 ? 1 : 0); break;
    case 4:
        out.push_back(static_cast<std::uint8_t>(value >> 24));
        out.push_back(static_cast<std::uint8_t>(value >> 16));
        [[fallthrough]];
    default:
        out.push_back(static_cast<std::uint8_t>(value >> 8));
        out.push_back(static_cast<std::uint8_t>(value));
        break;
    }
}

std::uint32_t readNumber(std::span<const std::uint8_t> bytes, std::size_t pos, std::size_t size)
{
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < size; ++i)
        v = (v << 8) | bytes[pos + i];
    return v;
}

Result<ParsedFrame> parseFrame(std::span<const std::uint8_t> frame)
{
    if (frame.size() < kOverhead + 2) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::BinaryFrameTooShort>(frame.size()));
    }
    if (frame[0] != BinaryCodec::queryHeader && frame[0] != BinaryCodec::responseHeader) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::BinaryFrameBadHeader>(hex2(frame[0])));
    }
    if (frame[1] != BinaryCodec::frameId)
        return makeError(ErrorKind::BadFrame, msg<MsgId::BinaryFrameBadId>(hex2(frame[1])));
    const std::size_t length = readNumber(frame, 2, 2);
    if (length + kOverhead != frame.size()) {
        return makeError(ErrorKind::BadFrame,
                         msg<MsgId::BinaryFrameBadLength>(
                             length, frame.size() < kOverhead ? 0 : frame.size() - kOverhead));
    }
    if (frame[frame.size() - 2] != BinaryCodec::terminator[0]
        || frame[frame.size() - 1] != BinaryCodec::terminator[1]) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::BinaryFrameBadEnd>(
                                                  hexBytes(frame.subspan(frame.size() - 2), 2)));
    }
    const std::uint16_t expected = BinaryCodec::crc16(frame.subspan(2, length + 2));
    const std::uint16_t got = static_cast<std::uint16_t>(frame[kHeadSize + length]
                                                         | (frame[kHeadSize + length + 1] << 8));
    if (expected != got) {
        return makeError(
            ErrorKind::BadChecksum,
            msg<MsgId::BinaryFrameBadCrc>(hex2(got) + " " + hex2(got >> 8u),
                                          hex2(expected) + " "
                                              + hex2(static_cast<std::uint32_t>(expected) >> 8u)));
    }
    if (length < 2)
        return makeError(ErrorKind::BadFrame, msg<MsgId::BinaryFrameNoStation>());
    return ParsedFrame{frame[0], frame.subspan(kHeadSize, length)};
}

Bytes frameOf(std::uint8_t header, std::span<const std::uint8_t> payload)
{
    // The length field has 16 bits; nothing legal comes near it, so a longer body is cut.
    if (payload.size() > 0xFFFF)
        payload = payload.first(0xFFFF);
    Bytes frame;
    frame.reserve(payload.size() + kOverhead);
    frame.push_back(header);
    frame.push_back(BinaryCodec::frameId);
    frame.push_back(static_cast<std::uint8_t>(payload.size() >> 8));
    frame.push_back(static_cast<std::uint8_t>(payload.size()));
    frame.insert(frame.end(), payload.begin(), payload.end());
    const std::uint16_t crc = BinaryCodec::crc16(std::span<const std::uint8_t>(frame).subspan(2));
    frame.push_back(static_cast<std::uint8_t>(crc & 0xFFu));
    frame.push_back(static_cast<std::uint8_t>(crc >> 8));
    frame.push_back(BinaryCodec::terminator[0]);
    frame.push_back(BinaryCodec::terminator[1]);
    return frame;
}

} // namespace Fatek::BinaryWire
