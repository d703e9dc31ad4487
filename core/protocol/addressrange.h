#pragma once

#include "address.h"

#include <string>
#include <string_view>
#include <vector>

namespace Fatek {

// A run of consecutive elements of one type, as users type it: "R0..R9", "R0..9", "Y0-255",
// "X16-X31" or one address ("M100"); blanks allowed around the separator and after the type.
struct AddressRange
{
    Address start{ElementType::X, 0};
    std::uint32_t count = 1; // elements, not numbers: WY0..WY32 is 3

    Address last() const { return start.advanced(count - 1); }
    std::vector<Address> addresses() const;
    // "Y0-255", "WY0-32", or "Y7" for one element; parse() reads it back.
    std::string toString() const;

    bool operator==(const AddressRange &) const = default;

    static Result<AddressRange> parse(std::string_view text);
    // Several, separated by commas, semicolons or blanks: "X0-255, Y0-255 M 0 - 999".
    static Result<std::vector<AddressRange>> parseList(std::string_view text);
};

} // namespace Fatek
