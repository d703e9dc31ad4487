#include "faconwire.h"

#include "faconcodec.h"

namespace Fatek::FaconWire {

namespace {

// Smallest frame: STX, station (2), command (2), LRC (2), ETX.
constexpr std::size_t kMinFrameSize = 8;

} // namespace

std::optional<std::uint32_t> hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return static_cast<std::uint32_t>(c - '0');
    if (c >= 'A' && c <= 'F')
        return static_cast<std::uint32_t>(c - 'A' + 10);
    // Lower case is not what the PLC sends, but costs nothing to accept.
    if (c >= 'a' && c <= 'f')
        return static_cast<std::uint32_t>(c - 'a' + 10);
    return std::nullopt;
}

std::optional<std::uint32_t> parseHex(std::string_view text)
{
    if (text.empty() || text.size() > 8)
        return std::nullopt;
    std::uint32_t value = 0;
    for (char c : text) {
        const auto digit = hexValue(c);
        if (!digit)
            return std::nullopt;
        value = (value << 4) | *digit;
    }
    return value;
}

void appendHex(std::string &out, std::uint32_t value, int digits)
{
    for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4)
        out += kHexDigits[(value >> shift) & 0xFu];
}

std::string hex2(std::uint32_t value)
{
    std::string s;
    appendHex(s, value, 2);
    return s;
}

std::size_t valueChars(ElementType type)
{
    switch (elementInfo(type).width) {
    case ElementWidth::Bit: return 1;
    case ElementWidth::Word: return 4;
    case ElementWidth::DoubleWord: return 8;
    }
    return 4;
}

void appendValue(std::string &out, ElementType type, std::uint32_t value)
{
    if (isDiscrete(type))
        out += value != 0 ? '1' : '0';
    else
        appendHex(out, value, static_cast<int>(valueChars(type)));
}

std::string printable(std::string_view text, std::size_t maxChars)
{
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < maxChars; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c <= 0x7E) {
            out += static_cast<char>(c);
        } else {
            out += "<";
            out += hex2(c);
            out += ">";
        }
    }
    if (text.size() > maxChars)
        out += "...";
    return out;
}

Bytes frameOf(std::string_view body)
{
    Bytes frame;
    frame.reserve(body.size() + 4);
    frame.push_back(FaconCodec::STX);
    for (char c : body)
        frame.push_back(static_cast<std::uint8_t>(c));
    const std::uint8_t sum = FaconCodec::lrc(frame);
    frame.push_back(static_cast<std::uint8_t>(kHexDigits[sum >> 4]));
    frame.push_back(static_cast<std::uint8_t>(kHexDigits[sum & 0xF]));
    frame.push_back(FaconCodec::ETX);
    return frame;
}

std::string headerText(std::uint8_t station, std::uint8_t command)
{
    return hex2(station) + hex2(command);
}

Result<ParsedFrame> parseFrame(std::span<const std::uint8_t> frame)
{
    if (frame.size() < kMinFrameSize) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::FaconFrameTooShort>(frame.size()));
    }
    if (frame.size() > FaconCodec::maxFrameSize) {
        return makeError(ErrorKind::BadFrame,
                         msg<MsgId::FaconFrameTooLong>(frame.size(), FaconCodec::maxFrameSize));
    }
    if (frame.front() != FaconCodec::STX)
        return makeError(ErrorKind::BadFrame, msg<MsgId::FaconNoStx>());
    if (frame.back() != FaconCodec::ETX)
        return makeError(ErrorKind::BadFrame, msg<MsgId::FaconNoEtx>());
    const std::string_view text(reinterpret_cast<const char *>(frame.data()), frame.size());
    for (std::size_t i = 1; i + 1 < text.size(); ++i) {
        if (frame[i] == FaconCodec::STX || frame[i] == FaconCodec::ETX)
            return makeError(ErrorKind::BadFrame, msg<MsgId::FaconStrayStxEtx>());
    }
    const auto station = parseHex(text.substr(1, 2));
    const auto command = parseHex(text.substr(3, 2));
    if (!station || !command) {
        return makeError(ErrorKind::BadFrame,
                         msg<MsgId::FaconHeaderNotHex>(printable(text.substr(1, 4), 4)));
    }
    const auto received = parseHex(text.substr(text.size() - 3, 2));
    if (!received) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::FaconChecksumNotHex>(
                                                  printable(text.substr(text.size() - 3, 2), 2)));
    }
    const std::uint8_t computed = FaconCodec::lrc(frame.first(frame.size() - 3));
    if (computed != *received) {
        return makeError(ErrorKind::BadChecksum,
                         msg<MsgId::FaconChecksumError>(hex2(*received), hex2(computed)));
    }
    ParsedFrame parsed;
    parsed.station = static_cast<std::uint8_t>(*station);
    parsed.command = static_cast<std::uint8_t>(*command);
    parsed.data = text.substr(5, text.size() - 8);
    return parsed;
}

} // namespace Fatek::FaconWire
