#pragma once

#include "element.h"
#include "result.h"

#include <compare>
#include <cstdint>
#include <string>
#include <string_view>

namespace Fatek {

// One element of a PLC: type and number (R12, DWM0, X16).
struct Address
{
    ElementType type = ElementType::R;
    std::uint32_t number = 0;

    auto operator<=>(const Address &) const = default;

    const ElementInfo &info() const { return elementInfo(type); }
    ElementWidth width() const { return info().width; }
    int words() const { return wordCount(type); }

    // Short form as users type it: "R12", "DWM0".
    std::string toString() const;
    // Fixed-width FACON form: "R00012", "X0016", "DWM0000". Empty if the type is not in FACON.
    std::string toFaconString() const;

    // The element `index` positions after this one in a consecutive read (WY0 + 1 = WY16).
    Address advanced(std::uint32_t index) const { return {type, number + index * info().step}; }

    // Accepts what users type: "R12", "r12", "DWM0", "X16", "D00012", " wy8 ".
    // Checks the number against the largest model's range and W/DW alignment.
    static Result<Address> parse(std::string_view text);
};

// Range and alignment check, with a message naming the address.
Status validateAddress(const Address &address);
// Checks that `count` consecutive elements from `start` all exist (1 <= count is not checked here).
Status validateSpan(const Address &start, std::uint32_t count);

} // namespace Fatek
