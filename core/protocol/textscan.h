#pragma once

// Character helpers shared by the protocol's text parsers (addresses, ranges, typed frames).

#include <cctype>
#include <string_view>

namespace Fatek::TextScan {

inline bool isBlank(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

inline std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && isBlank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && isBlank(text.back()))
        text.remove_suffix(1);
    return text;
}

// 0..15 for a hex digit in either case, -1 otherwise.
inline int hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

} // namespace Fatek::TextScan
