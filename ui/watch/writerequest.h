#pragma once

#include "request.h"
#include "watchlist.h"

#include <cstdint>

namespace Fatek {

// The write that puts `raw` (as ValueFormat::parse gives it, all elements of the item) into the
// PLC: 45 for a discrete, 47 over every register the item spans (a float over R100 writes R100
// and R101 in one request).
Request makeWriteRequest(const WatchItemSpec &item, std::uint64_t raw);

} // namespace Fatek
