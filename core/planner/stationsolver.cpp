#include "stationsolver.h"

#include "wiresize.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

// How plan() works (exact for its request model):
// - Per station, items of one element type whose numbers are congruent modulo the type's step
//   (DR0, DR2, ... but not DR1; WY0, WY16, ... but not WY8) form a chain: only those can share a
//   44/46 run. A chain is cut into segments wherever two neighbours are too far apart for one run.
// - Each segment is solved by dynamic programming over (items covered, items left to the pool):
//   every item either goes to the 48 pool or into a run that may bridge gaps (reading the elements
//   between items), with exact wire sizes. This yields, for each number of pooled items, the
//   cheapest (requests, bytes).
// - A knapsack over the pooled words of all segments of the station then picks the split that
//   minimises requests + ceil(pool words / 64), then bytes. The pool always packs into exactly
//   ceil(words / 64) mixed reads because element sizes are 1 or 2 words and 64 is even.
// Cost order is lexicographic (requests, bytes), which is compatible with addition, so keeping
// the best pair per DP state is exact. That is Solver::Reference, quadratic in a segment's items
// (a whole FBs snapshot took 0.2 s). Solver::Fast finds plans of the same cost with less work:
// - A gap-free segment (every element between its first and last item is an item: a snapshot, a
//   range in a watch list) needs no search: with j items pooled the other n - j form runs that
//   bridge nothing, so ceil((n - j) / limit) runs are the optimum for that j (fewest runs is also
//   fewest bytes, as every item costs the same in a run).
// - Pooled words count modulo 64 only: 64 more words are one more full list whichever words they
//   are, so the lists are added to the cost as they fill, and the DP and the knapsack keep 64
//   word columns instead of one per pooled item or word. ceil() is monotone in the words, so a
//   state that pools more words (mod 64) at no lower cost than another of the same row is dropped.
// Not used: reading discretes through their W views (WX0 for X0..X15). A slot carries a whole
// value (response.values[valueIndex]), not a bit of one, so it would need a contract change.

namespace Fatek {

namespace {

using PlanReads::runRead;
using WireSize::addressBytes;
using WireSize::valueBytes;

// Segments above this size are solved in pieces (the DP is quadratic in items per segment).
constexpr std::size_t maxSegmentItems = 512;

struct Cost
{
    std::uint32_t requests = 0;
    std::size_t bytes = 0;

    bool operator<(const Cost &o) const
    {
        return requests != o.requests ? requests < o.requests : bytes < o.bytes;
    }
    Cost operator+(const Cost &o) const { return {requests + o.requests, bytes + o.bytes}; }
};

constexpr Cost unreachable{std::numeric_limits<std::uint32_t>::max(),
                           std::numeric_limits<std::size_t>::max()};

bool isReachable(const Cost &c)
{
    return c.requests != unreachable.requests;
}

std::uint32_t maxRunElements(ElementType type)
{
    if (isDiscrete(type))
        return Limits::maxDiscretes;
    return Limits::maxRegisterWords / static_cast<std::uint32_t>(wordCount(type));
}

constexpr std::size_t listWords = Limits::maxMixedReadWords;

// One way to end a segment that the knapsack may choose.
struct SegmentOption
{
    std::size_t words = 0; // pooled (Fast: modulo 64, the full lists are in `cost`)
    Cost cost;
    std::uint32_t key = 0; // for reconstruct(): the final column, or the items pooled (gap-free)
};

// Items of one type and residue (numbers sorted, distinct) that are close enough to share runs.
struct Segment
{
    ElementType type = ElementType::R;
    std::vector<std::uint32_t> numbers;
    // The items follow each other without a gap: Fast solves it without a search.
    bool gapFree = false;

    // The search's tables (empty if there was none): the cost of the first i items, by column,
    // and the move that got there (-1: item i-1 pooled; k >= 0: items k..i-1 form one run).
    // Column: Reference, the items pooled; Fast, the pooled words modulo 64.
    std::size_t columns = 0;
    std::vector<Cost> cost;
    std::vector<std::int32_t> from;

    std::vector<SegmentOption> options; // ascending in words, none dominated by an earlier one

    std::size_t n() const { return numbers.size(); }
    std::size_t at(std::size_t i, std::size_t column) const { return i * columns + column; }
};

} // namespace

Request PlanReads::singleRead(std::uint8_t station, const Address &a)
{
    return isDiscrete(a.type) ? Request::readDiscretes(station, a, 1)
                              : Request::readRegisters(station, a, 1);
}

Request PlanReads::runRead(std::uint8_t station, const Address &start, std::uint32_t count)
{
    return isDiscrete(start.type) ? Request::readDiscretes(station, start, count)
                                  : Request::readRegisters(station, start, count);
}

class StationSolver::Search
{
public:
    Search(Protocol protocol, PollPlanner::Solver solver)
        : m_protocol(protocol)
        , m_fast(solver == PollPlanner::Solver::Fast)
    {
        const Request empty = Request::mixedRead(1, {});
        m_list = {1, PollPlanner::queryBytes(empty, protocol)
                         + PollPlanner::responseBytes(empty, protocol)};
    }

    // `blockers`: elements that must not be read by a run bridging a gap (isolated bad elements).
    StationResult solve(const std::vector<Address> &addresses, const std::set<Address> &blockers)
    {
        StationResult result;
        std::vector<Segment> segments = buildSegments(addresses, blockers, result);
        std::size_t forcedWords = 0;
        std::size_t forcedBytes = 0;
        for (const Address &a : result.pooled) {
            forcedWords += static_cast<std::size_t>(a.words());
            forcedBytes += poolItemBytes(a.type);
        }
        for (Segment &s : segments)
            solveSegment(s);

        // Knapsack over pooled words: best[W] is the cheapest choice for the segments so far that
        // pools W words. Fast folds the word counts that agree modulo 64 into one state, the full
        // lists (W / 64) counted in the cost already: a list costs the same whichever words fill
        // it, so the optimum is the same, with 64 states instead of thousands (a snapshot).
        std::size_t reach = 0;
        const Cost start = land(forcedWords, reach) + Cost{0, forcedBytes};
        std::vector<Cost> best(reach + 1, unreachable);
        best[reach] = start;
        std::vector<Cost> next;
        std::vector<std::vector<std::uint32_t>> choice(segments.size()); // option index
        for (std::size_t si = 0; si < segments.size(); ++si) {
            const Segment &s = segments[si];
            const std::size_t bound = m_fast ? listWords - 1 : reach + s.options.back().words;
            next.assign(bound + 1, unreachable);
            std::vector<std::uint32_t> &pick = choice[si];
            pick.assign(bound + 1, 0);
            std::size_t nextReach = 0;
            for (std::size_t W = 0; W <= reach; ++W) {
                if (!isReachable(best[W]))
                    continue;
                for (std::size_t k = 0; k < s.options.size(); ++k) {
                    const SegmentOption &o = s.options[k];
                    std::size_t to = 0;
                    const Cost lists = land(W + o.words, to);
                    const Cost c = best[W] + o.cost + lists;
                    if (c < next[to]) {
                        next[to] = c;
                        pick[to] = static_cast<std::uint32_t>(k);
                        nextReach = std::max(nextReach, to);
                    }
                }
            }
            best.swap(next);
            reach = nextReach;
        }

        std::size_t bestWords = 0;
        Cost bestTotal = unreachable;
        for (std::size_t W = 0; W <= reach; ++W) {
            if (!isReachable(best[W]))
                continue;
            const std::size_t packs = (W + listWords - 1) / listWords;
            const Cost total
                = best[W] + Cost{static_cast<std::uint32_t>(packs), packs * m_list.bytes};
            if (total < bestTotal) {
                bestTotal = total;
                bestWords = W;
            }
        }

        std::size_t W = bestWords;
        for (std::size_t si = segments.size(); si-- > 0;) {
            const Segment &s = segments[si];
            const SegmentOption &o = s.options[choice[si][W]];
            W = m_fast ? (W + listWords - o.words) % listWords : W - o.words;
            reconstruct(s, o.key, result);
        }
        return result;
    }

private:
    // The state `words` pooled words land in, and the cost of the full lists Fast folds away.
    Cost land(std::size_t words, std::size_t &state) const
    {
        state = m_fast ? words % listWords : words;
        const std::size_t lists = m_fast ? words / listWords : 0;
        return Cost{static_cast<std::uint32_t>(lists), lists * m_list.bytes};
    }

    std::size_t poolItemBytes(ElementType type) const
    {
        return addressBytes(Address{type, 0}, m_protocol) + valueBytes(type, m_protocol);
    }

    std::size_t runBytes(ElementType type, std::uint32_t span) const
    {
        const Request r = runRead(1, Address{type, 0}, span);
        return PollPlanner::queryBytes(r, m_protocol) + PollPlanner::responseBytes(r, m_protocol);
    }

    std::size_t runFixedBytes(ElementType type) const
    {
        return runBytes(type, 1) - valueBytes(type, m_protocol);
    }

    std::vector<Segment> buildSegments(const std::vector<Address> &addresses,
                                       const std::set<Address> &blockers,
                                       StationResult &result) const
    {
        // addresses are sorted and distinct; group by (type, residue).
        std::map<std::pair<ElementType, std::uint32_t>, std::vector<std::uint32_t>> chains;
        for (const Address &a : addresses)
            chains[{a.type, a.number % a.info().step}].push_back(a.number);

        std::vector<Segment> segments;
        for (auto &[key, numbers] : chains) {
            const ElementType type = key.first;
            const std::uint32_t step = elementInfo(type).step;
            const std::uint32_t limit = maxRunElements(type);
            std::vector<std::uint32_t> current;
            auto flush = [&] {
                if (current.size() == 1) {
                    // A lone item is never better in a run of its own: in the pool it adds at most
                    // one request and never more bytes.
                    result.pooled.push_back(Address{type, current.front()});
                } else if (!current.empty()) {
                    Segment segment;
                    segment.type = type;
                    segment.numbers = current;
                    segment.gapFree = current.back() - current.front()
                                      == (current.size() - 1) * std::size_t{step};
                    segments.push_back(std::move(segment));
                }
                current.clear();
            };
            auto blockedBetween = [&](std::uint32_t low, std::uint32_t high) {
                for (auto it = blockers.upper_bound(Address{type, low});
                     it != blockers.end() && it->type == type && it->number < high; ++it) {
                    if (it->number % step == low % step)
                        return true;
                }
                return false;
            };
            for (std::uint32_t number : numbers) {
                const bool tooFar
                    = !current.empty() && (number - current.back()) / step + 1 > limit;
                if (tooFar || current.size() >= maxSegmentItems
                    || (!current.empty() && blockedBetween(current.back(), number)))
                    flush();
                current.push_back(number);
            }
            flush();
        }
        return segments;
    }

    void solveSegment(Segment &s) const
    {
        const std::vector<SegmentOption> ends = m_fast && s.gapFree ? gapFreeEnds(s) : search(s);
        // Pooling more words only helps if it saves requests or bytes.
        s.options.clear();
        for (const SegmentOption &e : ends) {
            const bool dominated
                = std::any_of(s.options.begin(), s.options.end(), [&e](const SegmentOption &o) {
                      return o.cost.requests <= e.cost.requests && o.cost.bytes <= e.cost.bytes;
                  });
            if (!dominated)
                s.options.push_back(e);
        }
    }

    // With j items pooled, the other n - j items go in the fewest full runs (see the top); the
    // cheapest j for each number of pooled words modulo 64.
    std::vector<SegmentOption> gapFreeEnds(const Segment &s) const
    {
        const std::size_t n = s.n();
        const std::size_t w = static_cast<std::size_t>(wordCount(s.type));
        const std::size_t limit = maxRunElements(s.type);
        const std::size_t pooledBytes = poolItemBytes(s.type);
        const std::size_t runFixed = runFixedBytes(s.type);
        const std::size_t perValue = valueBytes(s.type, m_protocol);
        std::vector<SegmentOption> byWords(listWords, SegmentOption{0, unreachable, 0});
        for (std::size_t j = 0; j <= n; ++j) {
            const std::size_t inRuns = n - j;
            const std::size_t runs = (inRuns + limit - 1) / limit;
            std::size_t words = 0;
            const Cost c = Cost{static_cast<std::uint32_t>(runs),
                                runs * runFixed + inRuns * perValue + j * pooledBytes}
                           + land(j * w, words);
            if (c < byWords[words].cost)
                byWords[words] = {words, c, static_cast<std::uint32_t>(j)};
        }
        std::vector<SegmentOption> ends;
        for (const SegmentOption &e : byWords) {
            if (isReachable(e.cost))
                ends.push_back(e);
        }
        return ends;
    }

    // Dynamic programming over (items done, column), see the top. Fast also drops, row by row,
    // states that pool more words and cost no less than one that pools fewer: the same moves after
    // the other one cost no more and end with fewer words, which never costs more lists; so no
    // optimum is lost, only states (few per row are left).
    std::vector<SegmentOption> search(Segment &s) const
    {
        const std::size_t n = s.n();
        const std::uint32_t step = elementInfo(s.type).step;
        const std::uint32_t limit = maxRunElements(s.type);
        const std::size_t w = static_cast<std::size_t>(wordCount(s.type));
        const Cost pooledCost{0, poolItemBytes(s.type)};
        const std::size_t runFixed = runFixedBytes(s.type);
        const std::size_t perValue = valueBytes(s.type, m_protocol);

        // Fast: fewer columns when the segment cannot pool 64 words (nothing folds then).
        s.columns = m_fast ? std::min(listWords, n * w + 1) : n + 1;
        s.cost.assign((n + 1) * s.columns, unreachable);
        s.from.assign((n + 1) * s.columns, -1);
        s.cost[s.at(0, 0)] = {0, 0};
        std::vector<Cost> kept; // the states of row i expanded so far
        for (std::size_t i = 0; i < n; ++i) {
            kept.clear();
            for (std::size_t c = 0; c < s.columns; ++c) {
                const Cost here = s.cost[s.at(i, c)];
                if (!isReachable(here))
                    continue;
                if (m_fast) {
                    const bool dominated
                        = std::any_of(kept.begin(), kept.end(), [&here](const Cost &k) {
                              return k.requests <= here.requests && k.bytes <= here.bytes;
                          });
                    if (dominated)
                        continue;
                    kept.push_back(here);
                }
                std::size_t to = c + 1;
                Cost pooled = here + pooledCost;
                if (m_fast)
                    pooled = pooled + land(c + w, to);
                if (pooled < s.cost[s.at(i + 1, to)]) {
                    s.cost[s.at(i + 1, to)] = pooled;
                    s.from[s.at(i + 1, to)] = -1;
                }
                for (std::size_t m = i + 1; m <= n; ++m) {
                    const std::uint32_t span = (s.numbers[m - 1] - s.numbers[i]) / step + 1;
                    if (span > limit)
                        break;
                    const Cost run = here + Cost{1, runFixed + span * perValue};
                    if (run < s.cost[s.at(m, c)]) {
                        s.cost[s.at(m, c)] = run;
                        s.from[s.at(m, c)] = static_cast<std::int32_t>(i);
                    }
                }
            }
        }
        std::vector<SegmentOption> ends;
        for (std::size_t c = 0; c < s.columns; ++c) {
            const Cost end = s.cost[s.at(n, c)];
            if (isReachable(end))
                ends.push_back({m_fast ? c : c * w, end, static_cast<std::uint32_t>(c)});
        }
        return ends;
    }

    void reconstruct(const Segment &s, std::uint32_t key, StationResult &result) const
    {
        const std::uint32_t step = elementInfo(s.type).step;
        if (s.cost.empty()) {
            // Gap-free, `key` items pooled: full runs from the front, the last items to the pool.
            const std::size_t inRuns = s.n() - key;
            const std::size_t limit = maxRunElements(s.type);
            for (std::size_t k = 0; k < inRuns; k += limit) {
                const auto count = static_cast<std::uint32_t>(std::min(limit, inRuns - k));
                result.runs.emplace_back(Address{s.type, s.numbers[k]}, count);
            }
            for (std::size_t k = inRuns; k < s.n(); ++k)
                result.pooled.push_back(Address{s.type, s.numbers[k]});
            return;
        }
        const std::size_t w = static_cast<std::size_t>(wordCount(s.type));
        std::size_t i = s.n();
        std::size_t c = key;
        while (i > 0) {
            const std::int32_t f = s.from[s.at(i, c)];
            if (f < 0) {
                result.pooled.push_back(Address{s.type, s.numbers[i - 1]});
                --i;
                c = m_fast ? (c + listWords - w) % listWords : c - 1;
            } else {
                const auto k = static_cast<std::size_t>(f);
                const std::uint32_t span = (s.numbers[i - 1] - s.numbers[k]) / step + 1;
                result.runs.emplace_back(Address{s.type, s.numbers[k]}, span);
                i = k;
            }
        }
    }

    Protocol m_protocol;
    bool m_fast = true;
    Cost m_list; // one 48 list: a request and its frames
};

StationSolver::StationSolver(Protocol protocol, PollPlanner::Solver solver)
    : m_search(std::make_unique<Search>(protocol, solver))
{}

StationSolver::~StationSolver() = default;

StationResult StationSolver::solve(const std::vector<Address> &addresses,
                                   const std::set<Address> &blockers)
{
    return m_search->solve(addresses, blockers);
}

} // namespace Fatek
