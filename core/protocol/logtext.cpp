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
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

} // namespace Fatek
