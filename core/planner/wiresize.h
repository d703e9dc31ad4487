#pragma once

// Exact sizes on the wire of queries, answers and their fields, per protocol: the costs the poll
// planner minimises (PollPlanner::queryBytes and responseBytes are these).

#include "core/protocol/request.h"

#include <cstddef>

namespace Fatek::WireSize {

// One address, one value as the frames carry them.
std::size_t addressBytes(const Address &a, Protocol p);
std::size_t valueBytes(ElementType type, Protocol p);

// Exact frame size of the query; 0 if the command does not exist in `p`.
std::size_t queryBytes(const Request &r, Protocol p);
// Exact size of a successful answer; 0 if it is not known in advance (53 detail status) or the
// command does not exist in `p`.
std::size_t responseBytes(const Request &r, Protocol p);

} // namespace Fatek::WireSize
