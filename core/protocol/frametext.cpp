#include "frametext.h"

#include "textscan.h"

#include <array>
#include <cctype>

namespace Fatek {

namespace {

using TextScan::hexValue;
using TextScan::isBlank;
using TextScan::trimmed;

constexpr std::array<std::string_view, 32> controlNames
    = {"NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS",  "HT",  "LF",
       "VT",  "FF",  "CR",  "SO",  "SI",  "DLE", "DC1", "DC2", "DC3", "DC4", "NAK",
       "SYN", "ETB", "CAN", "EM",  "SUB", "ESC", "FS",  "GS",  "RS",  "US"};

constexpr char hexDigits[] = "0123456789ABCDEF";

void appendHex(std::string &out, std::uint8_t b)
{
    out += hexDigits[b >> 4];
    out += hexDigits[b & 0xF];
}

bool isHexPair(std::string_view text)
{
    return text.size() == 2 && hexValue(text[0]) >= 0 && hexValue(text[1]) >= 0;
}

// The whole UTF-8 character starting at `at`, so a message quotes "é" and not half of it.
std::string_view characterAt(std::string_view text, std::size_t at)
{
    std::size_t end = at + 1;
    while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
        ++end;
    return text.substr(at, end - at);
}

std::string upper(std::string_view text)
{
    std::string out(text);
    for (char &c : out)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// "01 40", "0a 0B 3c": at least two blank-separated pairs of hex digits.
bool isSpacedHexPairs(std::string_view text)
{
    std::size_t pairs = 0;
    std::size_t i = 0;
    while (i < text.size()) {
        if (i + 2 > text.size() || hexValue(text[i]) < 0 || hexValue(text[i + 1]) < 0)
            return false;
        ++pairs;
        i += 2;
        if (i == text.size())
            break;
        if (!isBlank(text[i]))
            return false;
        while (i < text.size() && isBlank(text[i]))
            ++i;
    }
    return pairs >= 2;
}

bool startsWithNoCase(std::string_view text, std::string_view prefix)
{
    return text.size() >= prefix.size() && upper(text.substr(0, prefix.size())) == upper(prefix);
}

} // namespace

std::string FrameText::toHex(std::span<const std::uint8_t> bytes)
{
    std::string out;
    out.reserve(bytes.size() * 3);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (i > 0)
            out += ' ';
        appendHex(out, bytes[i]);
    }
    return out;
}

std::string FrameText::toAscii(std::span<const std::uint8_t> bytes, Controls controls)
{
    std::string out;
    out.reserve(bytes.size());
    for (const std::uint8_t b : bytes) {
        if (b >= 32 && b < 127) {
            out += static_cast<char>(b);
            continue;
        }
        out += '<';
        if (b < 32 && controls == Controls::Names && !isHexPair(controlNames[b]))
            out += controlNames[b];
        else
            appendHex(out, b); // also form feed: <FF> is the byte FF
        out += '>';
    }
    return out;
}

Result<Bytes> FrameText::parseHex(std::string_view text)
{
    std::string digits;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        // A 0x prefix belongs to the byte after it; a lone "0x" is a typing error reported below.
        if (c == '0' && i + 2 < text.size() && (text[i + 1] == 'x' || text[i + 1] == 'X')
            && hexValue(text[i + 2]) >= 0) {
            ++i;
            continue;
        }
        if (isBlank(c) || c == ',' || c == ';' || c == ':' || c == '-')
            continue;
        if (hexValue(c) < 0) {
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::FrameTextNotHex>(characterAt(text, i)));
        }
        digits += c;
    }
    if (digits.empty())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::FrameTextNothingHex>());
    if (digits.size() % 2 != 0)
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::FrameTextOddDigits>());
    Bytes out;
    out.reserve(digits.size() / 2);
    for (std::size_t i = 0; i < digits.size(); i += 2)
        out.push_back(
            static_cast<std::uint8_t>(hexValue(digits[i]) * 16 + hexValue(digits[i + 1])));
    return out;
}

Result<Bytes> FrameText::parseAscii(std::string_view text)
{
    Bytes out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '<') {
            const std::size_t end = text.find('>', i + 1);
            if (end != std::string_view::npos && end > i + 1) {
                const std::string name = upper(text.substr(i + 1, end - i - 1));
                // Hex first: <FF> is the byte FF, as toAscii() writes it, not form feed.
                bool found = false;
                if (isHexPair(name)) {
                    out.push_back(
                        static_cast<std::uint8_t>(hexValue(name[0]) * 16 + hexValue(name[1])));
                    found = true;
                }
                for (std::size_t code = 0; !found && code < controlNames.size(); ++code) {
                    if (name == controlNames[code]) {
                        out.push_back(static_cast<std::uint8_t>(code));
                        found = true;
                    }
                }
                if (found) {
                    i = end;
                    continue;
                }
            }
        }
        const auto u = static_cast<unsigned char>(c);
        if (u < 32 || u > 126) {
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::FrameTextNotAscii>());
        }
        out.push_back(u);
    }
    if (out.empty())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::FrameTextNothing>());
    return out;
}

Result<Bytes> FrameText::parse(std::string_view text, Typed typed, bool *wasHex)
{
    bool hex = typed == Typed::Hex;
    if (typed == Typed::Guess) {
        text = trimmed(text);
        if (startsWithNoCase(text, "hex:")) {
            hex = true;
            text.remove_prefix(4);
        } else {
            hex = isSpacedHexPairs(text) || startsWithNoCase(text, "0x");
        }
    }
    if (wasHex)
        *wasHex = hex;
    return hex ? parseHex(text) : parseAscii(text);
}

} // namespace Fatek
