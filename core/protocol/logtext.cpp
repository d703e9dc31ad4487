#include "logtext.h"

#include <array>
#include <cstdint>

namespace Fatek {

namespace {

void appendHex(std::string &out, std::uint32_t value, int digits)
{
    static constexpr std::array<char, 16> hex{'0', '1', '2', '3', '4', '5', '6', '7',
                                              '8', '9', 'a', 'b', 'c', 'd', 'e', 'f'};
    for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4)
        out += hex[(value >> static_cast<unsigned>(shift)) & 0xFU];
}

// The bidirectional control at `i` (U+061C, U+200E/F, U+202A..U+202E, U+2066..U+2069), else 0.
std::uint32_t bidiControlAt(std::string_view utf8, std::size_t i)
{
    const auto at = [&utf8, i](std::size_t k) {
        return i + k < utf8.size() ? static_cast<unsigned char>(utf8[i + k]) : 0U;
    };
    if (at(0) == 0xD8 && at(1) == 0x9C)
        return 0x061C;
    if (at(0) != 0xE2)
        return 0;
    const std::uint32_t code = 0x2000U | ((at(1) & 0x3FU) << 6) | (at(2) & 0x3FU);
    const bool bidi = (at(1) == 0x80
                       && (code == 0x200E || code == 0x200F || (code >= 0x202A && code <= 0x202E)))
                      || (at(1) == 0x81 && code >= 0x2066 && code <= 0x2069);
    return bidi && (at(2) & 0xC0U) == 0x80 ? code : 0;
}

} // namespace

std::string escapedForLog(std::string_view utf8)
{
    std::string out;
    out.reserve(utf8.size());
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c < 0x20 || c == 0x7F) {
            out += "\\x";
            appendHex(out, c, 2);
        } else if (c == 0xC2 && i + 1 < utf8.size()
                   && static_cast<unsigned char>(utf8[i + 1]) >= 0x80
                   && static_cast<unsigned char>(utf8[i + 1]) <= 0x9F) {
            // U+0080..U+009F (C1 controls, NEL among them)
            out += "\\u00";
            appendHex(out, static_cast<unsigned char>(utf8[i + 1]), 2);
            ++i;
        } else if (c == 0xE2 && i + 2 < utf8.size()
                   && static_cast<unsigned char>(utf8[i + 1]) == 0x80
                   && (static_cast<unsigned char>(utf8[i + 2]) == 0xA8
                       || static_cast<unsigned char>(utf8[i + 2]) == 0xA9)) {
            // U+2028 LINE SEPARATOR, U+2029 PARAGRAPH SEPARATOR
            out += static_cast<unsigned char>(utf8[i + 2]) == 0xA8 ? "\\u2028" : "\\u2029";
            i += 2;
        } else if (const std::uint32_t bidi = bidiControlAt(utf8, i); bidi != 0) {
            out += "\\u";
            appendHex(out, bidi, 4);
            i += bidi == 0x061C ? std::size_t{1} : std::size_t{2};
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

std::string quotedFieldForLog(std::string_view utf8)
{
    std::string out;
    out.reserve(utf8.size());
    for (const char c : utf8) {
        if (c == '\\' || c == '"')
            out += '\\';
        out += c;
    }
    return out;
}

} // namespace Fatek
