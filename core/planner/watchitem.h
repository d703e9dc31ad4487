#pragma once

#include "core/protocol/address.h"

#include <compare>
#include <cstdint>

namespace Fatek {

// One value the user wants polled: an element of one PLC station. `id` is the caller's handle
// (a table row); the planner hands it back in PlanSlot so the caller can route values.
struct WatchItem
{
    std::uint64_t id = 0;
    std::uint8_t station = 1;
    Address address;
};

// An element of one station, without the caller's id: what the session remembers as "bad"
// (answered error A or 2 alone) so the next plan keeps it out of batches.
struct StationAddress
{
    std::uint8_t station = 1;
    Address address;

    auto operator<=>(const StationAddress &) const = default;
};

} // namespace Fatek
