#pragma once

#include "message.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace Fatek {

// Page 0 of a FACON program (4F/50), as the FACON documentation draws it, byte 0 = high byte of
// word 0: 'F', the family ('B' FBs, 'M' M series), two ASCII digits, the ladder size in words
// (hi, lo), then 0xFF to the end of the page.
struct ProgramHeader
{
    char family = 'B';
    char digits[2] = {'0', '0'};
    std::uint16_t ladderSize = 0; // program capacity in words (13184 = 0x3380)

    bool operator==(const ProgramHeader &) const = default;

    // The header in a 64-word page 0; nothing when the page is not a header.
    static std::optional<ProgramHeader> decode(std::span<const std::uint32_t> page);
    static std::optional<ProgramHeader> decode(std::span<const std::uint16_t> page);
    // The 64 words of page 0.
    std::vector<std::uint16_t> encode() const;

    // Pages 4F/50 address: page 0 plus ceil(ladderSize / 64) pages of program.
    std::uint16_t pageCount() const;
    // "FBs", "M".
    std::string familyName() const;
    // "FBs series, 13184-word program".
    Message model() const;
    // Same family and capacity: a program of one fits the other.
    bool sameModel(const ProgramHeader &other) const
    {
        return family == other.family && ladderSize == other.ladderSize;
    }
};

// Pages in a list as "1, 3-5, 9" (ranges joined); at most `limit` items, then "...".
std::string pageListText(const std::vector<std::uint16_t> &pages, std::size_t limit = 12);

} // namespace Fatek
