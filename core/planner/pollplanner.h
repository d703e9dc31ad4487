#pragma once

#include "core/protocol/request.h"
#include "watchitem.h"

#include <cstddef>
#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace Fatek {

// Where one watch item's value sits in the answer of a step.
struct PlanSlot
{
    std::uint64_t itemId = 0;
    std::uint32_t valueIndex = 0; // response.values[valueIndex] is the item's value
    // The item's position in the list given to plan(): a poller keeps per-item state in arrays
    // by position, not in hash tables by id (memory per watched item, docs/performance.md).
    std::uint32_t itemIndex = 0;
};

// One request of a poll cycle and the items it serves.
struct PlanStep
{
    Request request;
    std::vector<PlanSlot> itemSlots;
    std::size_t wireBytes = 0; // query + successful answer bytes
};

// A watch item that cannot be polled at all (bad station, address out of range, element type
// the protocol cannot read). It is left out of the steps and reported here once.
struct UnplannableItem
{
    std::uint64_t itemId = 0;
    std::uint32_t itemIndex = 0; // its position in the list given to plan()
    Message reason; // technician words, e.g. "F12: F elements are not available in the FACON
                    // protocol ..."
};

struct Plan
{
    std::vector<PlanStep> steps;
    std::size_t wireBytes = 0; // sum of the steps' wireBytes: bytes on the wire per poll cycle
    std::vector<UnplannableItem> unplannable;

    std::size_t requestCount() const { return steps.size(); }
};

// Packs watch items into the fewest read requests the protocol allows, then the fewest wire bytes:
// consecutive runs of one element type via 44 (discretes, <= 256 points) or 46 (registers,
// <= 64 words, 32-bit elements count 2), everything else packed into 48 mixed reads (<= 64 words).
// Reading the elements between two items (bridging a gap) is chosen whenever it is cheaper in
// bytes than the alternatives. The optimisation is exact for this request model (see
// pollplanner.cpp). Pure and stateless: re-plan whenever the watch list (or the set of isolated
// elements) changes.
class PollPlanner
{
public:
    // How the optimum is found. Reference: the plain search (quadratic in the items of a stretch).
    // Fast: the known optimum where no search is needed (gap-free stretches, such as a memory
    // snapshot), and a smaller search elsewhere (see pollplanner.cpp). Both give plans of the same
    // requests and bytes; tests compare them.
    enum class Solver { Fast, Reference };

    explicit PollPlanner(Protocol protocol, Solver solver = Solver::Fast);

    Protocol protocol() const { return m_protocol; }

    // Duplicates (same station and address) are read once; each duplicate gets its own slot.
    // Output is deterministic: steps ordered by station, then by first address.
    Plan plan(std::span<const WatchItem> items) const;
    // Same, but elements in `isolated` (remembered as answering error A or 2) are never batched:
    // each gets a request of its own, so its error cannot blank the other items.
    Plan plan(std::span<const WatchItem> items, const std::set<StationAddress> &isolated) const;

    // Isolation: split a failed step into two halves (each a valid request, trimmed to the items it
    // serves), or nothing if it serves a single element. Repeating on the failing half finds one
    // bad element among n in ceil(log2 n) rounds.
    std::vector<PlanStep> split(const PlanStep &failed) const;

    // Exact frame size on the wire of the query; 0 if the command does not exist in `p`.
    static std::size_t queryBytes(const Request &r, Protocol p);
    // Exact size of a successful answer; 0 if it is not known in advance (53 detail status) or the
    // command does not exist in `p`.
    static std::size_t responseBytes(const Request &r, Protocol p);

private:
    PlanStep makeStep(Request request, std::vector<PlanSlot> itemSlots) const;

    Protocol m_protocol;
    Solver m_solver;
};

} // namespace Fatek
