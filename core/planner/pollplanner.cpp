#include "pollplanner.h"

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
// the best pair per DP state is exact.
// Not used: reading discretes through their W views (WX0 for X0..X15). A slot carries a whole
// value (response.values[valueIndex]), not a bit of one, so it would need a contract change.

namespace Fatek {

namespace {

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

Request singleRead(std::uint8_t station, const Address &a)
{
    return isDiscrete(a.type) ? Request::readDiscretes(station, a, 1)
                              : Request::readRegisters(station, a, 1);
}

Request runRead(std::uint8_t station, const Address &start, std::uint32_t count)
{
    return isDiscrete(start.type) ? Request::readDiscretes(station, start, count)
                                  : Request::readRegisters(station, start, count);
}

// Items of one type and residue (numbers sorted, distinct) that are close enough to share runs.
struct Segment
{
    ElementType type = ElementType::R;
    std::vector<std::uint32_t> numbers;

    // DP results: cost[i * (n + 1) + j] for the first i items with j of them pooled.
    std::vector<Cost> cost;
    // -1: item i-1 was pooled; k >= 0: items k..i-1 form one run.
    std::vector<std::int32_t> from;
    std::vector<std::uint32_t> options; // useful pooled counts j at i = n (not dominated)

    std::size_t n() const { return numbers.size(); }
    std::size_t at(std::size_t i, std::size_t j) const { return i * (n() + 1) + j; }
};

struct StationResult
{
    std::vector<std::pair<Address, std::uint32_t>> runs; // start, count
    std::vector<Address> pooled;
};

class StationSolver
{
public:
    explicit StationSolver(Protocol protocol)
        : m_protocol(protocol)
    {
        m_packOverhead = PollPlanner::queryBytes(Request::mixedRead(1, {}), protocol)
                         + PollPlanner::responseBytes(Request::mixedRead(1, {}), protocol);
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
        std::size_t totalWords = forcedWords;
        for (Segment &s : segments) {
            solveSegment(s);
            totalWords += s.n() * static_cast<std::size_t>(wordCount(s.type));
        }

        // Knapsack over pooled words.
        std::vector<Cost> best(totalWords + 1, unreachable);
        best[forcedWords] = {0, forcedBytes};
        std::size_t reach = forcedWords;
        std::vector<std::vector<std::uint32_t>> choice(segments.size());
        for (std::size_t si = 0; si < segments.size(); ++si) {
            const Segment &s = segments[si];
            const std::size_t w = static_cast<std::size_t>(wordCount(s.type));
            std::vector<Cost> next(totalWords + 1, unreachable);
            std::vector<std::uint32_t> &pick = choice[si];
            pick.assign(totalWords + 1, 0);
            std::size_t nextReach = 0;
            for (std::size_t W = 0; W <= reach; ++W) {
                if (!isReachable(best[W]))
                    continue;
                for (std::uint32_t j : s.options) {
                    const std::size_t to = W + j * w;
                    const Cost c = best[W] + s.cost[s.at(s.n(), j)];
                    if (c < next[to]) {
                        next[to] = c;
                        pick[to] = j;
                        nextReach = std::max(nextReach, to);
                    }
                }
            }
            best = std::move(next);
            reach = nextReach;
        }

        std::size_t bestWords = 0;
        Cost bestTotal = unreachable;
        for (std::size_t W = 0; W <= reach; ++W) {
            if (!isReachable(best[W]))
                continue;
            const std::size_t packs
                = (W + Limits::maxMixedReadWords - 1) / Limits::maxMixedReadWords;
            const Cost total
                = best[W] + Cost{static_cast<std::uint32_t>(packs), packs * m_packOverhead};
            if (total < bestTotal) {
                bestTotal = total;
                bestWords = W;
            }
        }

        std::size_t W = bestWords;
        for (std::size_t si = segments.size(); si-- > 0;) {
            const Segment &s = segments[si];
            const std::uint32_t j = choice[si][W];
            W -= j * static_cast<std::size_t>(wordCount(s.type));
            reconstruct(s, j, result);
        }
        return result;
    }

private:
    std::size_t poolItemBytes(ElementType type) const
    {
        return addressBytes(Address{type, 0}, m_protocol) + valueBytes(type, m_protocol);
    }

    std::size_t runBytes(ElementType type, std::uint32_t span) const
    {
        const Request r = runRead(1, Address{type, 0}, span);
        return PollPlanner::queryBytes(r, m_protocol) + PollPlanner::responseBytes(r, m_protocol);
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
                    segments.push_back(Segment{type, current, {}, {}, {}});
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
        const std::size_t n = s.n();
        const std::uint32_t step = elementInfo(s.type).step;
        const std::uint32_t limit = maxRunElements(s.type);
        const std::size_t pooledBytes = poolItemBytes(s.type);
        const std::size_t runFixed = runBytes(s.type, 1) - valueBytes(s.type, m_protocol);
        const std::size_t perValue = valueBytes(s.type, m_protocol);

        s.cost.assign((n + 1) * (n + 1), unreachable);
        s.from.assign((n + 1) * (n + 1), -1);
        s.cost[s.at(0, 0)] = {0, 0};
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j <= i; ++j) {
                const Cost here = s.cost[s.at(i, j)];
                if (!isReachable(here))
                    continue;
                const Cost pooled = here + Cost{0, pooledBytes};
                if (pooled < s.cost[s.at(i + 1, j + 1)]) {
                    s.cost[s.at(i + 1, j + 1)] = pooled;
                    s.from[s.at(i + 1, j + 1)] = -1;
                }
                for (std::size_t m = i + 1; m <= n; ++m) {
                    const std::uint32_t span = (s.numbers[m - 1] - s.numbers[i]) / step + 1;
                    if (span > limit)
                        break;
                    const Cost run = here + Cost{1, runFixed + span * perValue};
                    if (run < s.cost[s.at(m, j)]) {
                        s.cost[s.at(m, j)] = run;
                        s.from[s.at(m, j)] = static_cast<std::int32_t>(i);
                    }
                }
            }
        }
        // Pooling more items only helps if it saves requests or bytes.
        s.options.clear();
        for (std::size_t j = 0; j <= n; ++j) {
            const Cost c = s.cost[s.at(n, j)];
            if (!isReachable(c))
                continue;
            bool dominated = false;
            for (std::uint32_t k : s.options) {
                const Cost o = s.cost[s.at(n, k)];
                if (o.requests <= c.requests && o.bytes <= c.bytes) {
                    dominated = true;
                    break;
                }
            }
            if (!dominated)
                s.options.push_back(static_cast<std::uint32_t>(j));
        }
    }

    void reconstruct(const Segment &s, std::uint32_t pooledCount, StationResult &result) const
    {
        const std::uint32_t step = elementInfo(s.type).step;
        std::size_t i = s.n();
        std::size_t j = pooledCount;
        while (i > 0) {
            const std::int32_t f = s.from[s.at(i, j)];
            if (f < 0) {
                result.pooled.push_back(Address{s.type, s.numbers[i - 1]});
                --i;
                --j;
            } else {
                const auto k = static_cast<std::size_t>(f);
                const std::uint32_t span = (s.numbers[i - 1] - s.numbers[k]) / step + 1;
                result.runs.emplace_back(Address{s.type, s.numbers[k]}, span);
                i = k;
            }
        }
    }

    Protocol m_protocol;
    std::size_t m_packOverhead = 0;
};

// Packs pooled elements into ceil(words / 64) lists: 32-bit elements first (they fill a list to
// exactly 64), then the 1-word ones fill the gaps. Each list is sorted by address.
std::vector<std::vector<Address>> packPool(std::vector<Address> pooled)
{
    std::sort(pooled.begin(), pooled.end());
    std::stable_partition(pooled.begin(), pooled.end(),
                          [](const Address &a) { return a.words() == 2; });
    std::vector<std::vector<Address>> packs;
    std::vector<std::uint32_t> used;
    for (const Address &a : pooled) {
        const auto w = static_cast<std::uint32_t>(a.words());
        bool placed = false;
        for (std::size_t p = 0; p < packs.size() && !placed; ++p) {
            if (used[p] + w <= Limits::maxMixedReadWords) {
                packs[p].push_back(a);
                used[p] += w;
                placed = true;
            }
        }
        if (!placed) {
            packs.push_back({a});
            used.push_back(w);
        }
    }
    for (auto &p : packs)
        std::sort(p.begin(), p.end());
    return packs;
}

Address firstAddress(const Request &r)
{
    if (r.command == Command::MixedRead && !r.addresses.empty())
        return r.addresses.front();
    return r.start;
}

} // namespace

PollPlanner::PollPlanner(Protocol protocol)
    : m_protocol(protocol)
{}

PlanStep PollPlanner::makeStep(Request request, std::vector<PlanSlot> itemSlots) const
{
    PlanStep step;
    step.wireBytes = queryBytes(request, m_protocol) + responseBytes(request, m_protocol);
    step.request = std::move(request);
    step.itemSlots = std::move(itemSlots);
    return step;
}

Plan PollPlanner::plan(std::span<const WatchItem> items) const
{
    return plan(items, {});
}

Plan PollPlanner::plan(std::span<const WatchItem> items,
                       const std::set<StationAddress> &isolated) const
{
    Plan result;
    // station -> address -> ids (input order)
    std::map<std::uint8_t, std::map<Address, std::vector<std::uint64_t>>> stations;
    for (const WatchItem &item : items) {
        if (item.station == Limits::broadcastStation) {
            result.unplannable.push_back(
                {item.id, msg<MsgId::PlanBroadcast>(item.address.toString())});
            continue;
        }
        if (Status s = validateRequest(singleRead(item.station, item.address), m_protocol); !s) {
            result.unplannable.push_back({item.id, s.error().message});
            continue;
        }
        stations[item.station][item.address].push_back(item.id);
    }

    StationSolver solver(m_protocol);
    for (const auto &stationEntry : stations) {
        // Named references, not a structured binding: clang before 16 cannot capture a binding.
        const std::uint8_t station = stationEntry.first;
        const auto &elements = stationEntry.second;
        auto slotsFor
            = [&elements](const Address &a, std::uint32_t valueIndex, std::vector<PlanSlot> &out) {
                  const auto it = elements.find(a);
                  if (it == elements.end())
                      return;
                  for (std::uint64_t id : it->second)
                      out.push_back({id, valueIndex});
              };

        std::vector<Address> batchable;
        std::set<Address> blockers;
        for (const StationAddress &bad : isolated) {
            if (bad.station == station)
                blockers.insert(bad.address);
        }
        std::vector<PlanStep> steps;
        for (const auto &entry : elements) {
            if (blockers.count(entry.first)) {
                std::vector<PlanSlot> itemSlots;
                slotsFor(entry.first, 0, itemSlots);
                steps.push_back(makeStep(singleRead(station, entry.first), std::move(itemSlots)));
            } else {
                batchable.push_back(entry.first);
            }
        }

        const StationResult solved = solver.solve(batchable, blockers);
        for (const auto &[start, count] : solved.runs) {
            std::vector<PlanSlot> itemSlots;
            for (std::uint32_t k = 0; k < count; ++k)
                slotsFor(start.advanced(k), k, itemSlots);
            steps.push_back(makeStep(runRead(station, start, count), std::move(itemSlots)));
        }
        for (std::vector<Address> &pack : packPool(solved.pooled)) {
            std::vector<PlanSlot> itemSlots;
            for (std::size_t k = 0; k < pack.size(); ++k)
                slotsFor(pack[k], static_cast<std::uint32_t>(k), itemSlots);
            // A mixed read of one element costs exactly as much as a plain read of it; the plain
            // read is easier to follow in the traffic log.
            Request r = pack.size() == 1 ? singleRead(station, pack.front())
                                         : Request::mixedRead(station, std::move(pack));
            steps.push_back(makeStep(std::move(r), std::move(itemSlots)));
        }
        std::sort(steps.begin(), steps.end(), [](const PlanStep &a, const PlanStep &b) {
            const Address fa = firstAddress(a.request);
            const Address fb = firstAddress(b.request);
            if (fa != fb)
                return fa < fb;
            return a.request.command < b.request.command;
        });
        for (PlanStep &s : steps) {
            result.wireBytes += s.wireBytes;
            result.steps.push_back(std::move(s));
        }
    }
    return result;
}

std::vector<PlanStep> PollPlanner::split(const PlanStep &failed) const
{
    const Request &r = failed.request;
    if (r.command != Command::ReadDiscretes && r.command != Command::ReadRegisters
        && r.command != Command::MixedRead) {
        return {};
    }
    std::vector<std::uint32_t> used;
    for (const PlanSlot &s : failed.itemSlots) {
        if (r.command == Command::MixedRead ? s.valueIndex < r.addresses.size()
                                            : s.valueIndex < r.count)
            used.push_back(s.valueIndex);
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    if (used.size() < 2)
        return {};

    auto addressAt = [&r](std::uint32_t index) {
        return r.command == Command::MixedRead ? r.addresses[index] : r.start.advanced(index);
    };
    const std::size_t half = (used.size() + 1) / 2;
    std::vector<PlanStep> out;
    for (const auto &[begin, end] :
         {std::pair{std::size_t{0}, half}, std::pair{half, used.size()}}) {
        const std::vector<std::uint32_t> part(used.begin() + static_cast<std::ptrdiff_t>(begin),
                                              used.begin() + static_cast<std::ptrdiff_t>(end));
        // old value index -> new value index
        std::map<std::uint32_t, std::uint32_t> remap;
        Request next;
        if (r.command == Command::MixedRead && part.size() > 1) {
            std::vector<Address> list;
            for (std::uint32_t index : part) {
                remap[index] = static_cast<std::uint32_t>(list.size());
                list.push_back(addressAt(index));
            }
            next = Request::mixedRead(r.station, std::move(list));
        } else {
            // A run trimmed to the items it serves (the elements read only to bridge a gap go).
            for (std::uint32_t index : part)
                remap[index] = index - part.front();
            next = runRead(r.station, addressAt(part.front()), part.back() - part.front() + 1);
        }
        std::vector<PlanSlot> itemSlots;
        for (const PlanSlot &s : failed.itemSlots) {
            const auto it = remap.find(s.valueIndex);
            if (it != remap.end())
                itemSlots.push_back({s.itemId, it->second});
        }
        out.push_back(makeStep(std::move(next), std::move(itemSlots)));
    }
    return out;
}

std::size_t PollPlanner::queryBytes(const Request &r, Protocol p)
{
    return WireSize::queryBytes(r, p);
}

std::size_t PollPlanner::responseBytes(const Request &r, Protocol p)
{
    return WireSize::responseBytes(r, p);
}

} // namespace Fatek
