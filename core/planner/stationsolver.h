#pragma once

#include "pollplanner.h"

#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace Fatek {

// The reads a plan is made of: one element alone, or a run of `count` elements from `start`
// (44 for discretes, 46 for registers).
namespace PlanReads {
Request singleRead(std::uint8_t station, const Address &a);
Request runRead(std::uint8_t station, const Address &start, std::uint32_t count);
} // namespace PlanReads

// How one station's batchable elements are read: in runs, and the rest pooled into 48 lists.
struct StationResult
{
    std::vector<std::pair<Address, std::uint32_t>> runs; // start, count
    std::vector<Address> pooled;
};

// Finds the cheapest reads (requests, then bytes) of one station's elements: which go in runs
// that may bridge gaps and which in the pool (stationsolver.cpp says how).
class StationSolver
{
public:
    StationSolver(Protocol protocol, PollPlanner::Solver solver);
    ~StationSolver();

    // `blockers`: elements that must not be read by a run bridging a gap (isolated bad elements).
    StationResult solve(const std::vector<Address> &addresses, const std::set<Address> &blockers);

private:
    class Search; // the search and its tables
    std::unique_ptr<Search> m_search;
};

} // namespace Fatek
