// Figure 1: poll packing. The planner's requests and wire bytes per cycle against (a) the optimum
// for the protocol limits, computed here by an exact solver of the bench's own, itself checked
// against a brute-force enumeration of every partition on small lists, and (b) one request per
// item. Byte counts come from encoding the frames with the codecs, not from the planner's own
// size formulas.
#include "bench.h"

#include "core/commission/memorysnapshot.h"
#include "core/commission/snapshotreader.h"
#include "core/planner/pollplanner.h"
#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"
#include "core/sim/simulatedplc.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>

namespace Fatek::Bench {

namespace {

struct Cost
{
    std::size_t requests = 0;
    std::size_t bytes = 0;

    bool operator<(const Cost &o) const
    {
        return requests != o.requests ? requests < o.requests : bytes < o.bytes;
    }
    Cost operator+(const Cost &o) const { return {requests + o.requests, bytes + o.bytes}; }
};

constexpr Cost infinite{std::numeric_limits<std::size_t>::max() / 4,
                        std::numeric_limits<std::size_t>::max() / 4};

struct Element
{
    std::uint8_t station = 1;
    Address address;

    auto operator<=>(const Element &) const = default;
};

// Wire sizes measured by encoding: query plus the successful answer.
class WireSizes
{
public:
    explicit WireSizes(Protocol protocol)
        : m_protocol(protocol)
    {
        if (protocol == Protocol::Facon)
            m_codec = &m_facon;
        else
            m_codec = &m_binary;
    }

    Protocol protocol() const { return m_protocol; }

    std::optional<std::size_t> bytes(const Request &r) const
    {
        if (!validateRequest(r, m_protocol))
            return std::nullopt;
        const Result<Bytes> query = m_codec->encodeRequest(r);
        if (!query)
            return std::nullopt;
        Response answer;
        answer.station = r.station;
        answer.command = r.command;
        answer.values.assign(r.expectedValueCount(), 0);
        return query.value().size() + m_codec->encodeResponse(r, answer).size();
    }

    // A 48 list costs base + the sum of its elements' marginal bytes.
    std::size_t mixedBase() const
    {
        const Address r0{ElementType::R, 0};
        return *bytes(Request::mixedRead(1, {r0})) - mixedMarginal(ElementType::R);
    }
    std::size_t mixedMarginal(ElementType type) const
    {
        const auto it = m_marginal.find(type);
        if (it != m_marginal.end())
            return it->second;
        const Address a{type, 0};
        const std::size_t one = *bytes(Request::mixedRead(1, {a}));
        const std::size_t two = *bytes(Request::mixedRead(1, {a, a}));
        m_marginal[type] = two - one;
        return two - one;
    }

private:
    Protocol m_protocol;
    FaconCodec m_facon;
    BinaryCodec m_binary;
    const Codec *m_codec = nullptr;
    mutable std::map<ElementType, std::size_t> m_marginal;
};

Request runRequest(std::uint8_t station, const Address &start, std::uint32_t count)
{
    return isDiscrete(start.type) ? Request::readDiscretes(station, start, count)
                                  : Request::readRegisters(station, start, count);
}

std::uint32_t maxRun(ElementType type)
{
    return isDiscrete(type)
               ? Limits::maxDiscretes
               : Limits::maxRegisterWords / static_cast<std::uint32_t>(wordCount(type));
}

// Exact optimum for the request model "44/46 runs (reading the elements in between) + 48
// lists": a run covers a contiguous stretch of one chain (same type, same number modulo the
// step); everything else goes to 48 lists, which always pack into ceil(words / 64) requests
// since elements are 1 or 2 words. Per chain a DP over (items done, items pooled), then per
// station a knapsack over pooled words.
Cost exactOptimum(const std::vector<Element> &elements, const WireSizes &sizes)
{
    std::map<std::uint8_t,
             std::map<std::pair<ElementType, std::uint32_t>, std::vector<std::uint32_t>>>
        chains;
    for (const Element &e : elements) {
        const std::uint32_t step = e.address.info().step;
        chains[e.station][{e.address.type, e.address.number % step}].push_back(e.address.number);
    }
    Cost total;
    const std::size_t base = sizes.mixedBase();
    for (auto &stationEntry : chains) {
        // Not a structured binding: clang before 16 cannot capture one in the lambda below.
        const auto station = stationEntry.first;
        auto &stationChains = stationEntry.second;
        std::vector<Cost> pool{Cost{}}; // pool[w]: best cost of the runs with w words pooled
        for (auto &[key, numbers] : stationChains) {
            std::sort(numbers.begin(), numbers.end());
            numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
            const ElementType type = key.first;
            const std::uint32_t step = elementInfo(type).step;
            const std::size_t n = numbers.size();
            const auto ws = static_cast<std::size_t>(wordCount(type));
            const std::size_t marginal = sizes.mixedMarginal(type);
            std::map<std::uint32_t, std::optional<std::size_t>> runCache;
            auto runCost = [&](std::uint32_t first, std::uint32_t count) {
                const Request r = runRequest(station, Address{type, first}, count);
                if (!validateRequest(r, sizes.protocol()))
                    return std::optional<std::size_t>();
                auto it = runCache.find(count);
                if (it == runCache.end())
                    it = runCache.emplace(count, sizes.bytes(r)).first;
                return it->second;
            };
            // f[i * (n + 1) + j]: first i items, j of them pooled.
            std::vector<Cost> f((n + 1) * (n + 1), infinite);
            f[0] = Cost{};
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t j = 0; j <= i; ++j) {
                    const Cost &c = f[i * (n + 1) + j];
                    if (c.requests >= infinite.requests)
                        continue;
                    Cost &pooled = f[(i + 1) * (n + 1) + j + 1];
                    pooled = std::min(pooled, c + Cost{0, marginal});
                }
                // Runs ending at item i, starting at item k.
                for (std::size_t k = i + 1; k-- > 0;) {
                    const std::uint32_t count = (numbers[i] - numbers[k]) / step + 1;
                    if (count > maxRun(type))
                        break;
                    const std::optional<std::size_t> b = runCost(numbers[k], count);
                    if (!b)
                        continue;
                    for (std::size_t j = 0; j <= k; ++j) {
                        const Cost &c = f[k * (n + 1) + j];
                        if (c.requests >= infinite.requests)
                            continue;
                        Cost &run = f[(i + 1) * (n + 1) + j];
                        run = std::min(run, c + Cost{1, *b});
                    }
                }
            }
            std::vector<Cost> next(pool.size() + n * ws, infinite);
            for (std::size_t w = 0; w < pool.size(); ++w) {
                if (pool[w].requests >= infinite.requests)
                    continue;
                for (std::size_t j = 0; j <= n; ++j) {
                    const Cost &c = f[n * (n + 1) + j];
                    if (c.requests >= infinite.requests)
                        continue;
                    Cost &slot = next[w + j * ws];
                    slot = std::min(slot, pool[w] + c);
                }
            }
            pool = std::move(next);
        }
        Cost best = infinite;
        for (std::size_t w = 0; w < pool.size(); ++w) {
            if (pool[w].requests >= infinite.requests)
                continue;
            const std::size_t lists
                = (w + Limits::maxMixedReadWords - 1) / Limits::maxMixedReadWords;
            best = std::min(best, pool[w] + Cost{lists, lists * base});
        }
        total = total + best;
    }
    return total;
}

// Brute force: every partition of the elements into blocks, each block read by the cheapest
// single valid request covering exactly it. Only for a handful of elements.
Cost bruteForce(const std::vector<Element> &elements, const WireSizes &sizes)
{
    const std::size_t n = elements.size();
    std::vector<std::optional<std::optional<std::size_t>>> blockCache(std::size_t{1} << n);
    auto blockCost = [&](std::size_t mask) -> std::optional<std::size_t> {
        auto &cached = blockCache[mask];
        if (cached)
            return *cached;
        std::vector<Element> block;
        for (std::size_t k = 0; k < n; ++k) {
            if (mask & (std::size_t{1} << k))
                block.push_back(elements[k]);
        }
        std::optional<std::size_t> best;
        const bool oneStation = std::all_of(block.begin(), block.end(), [&](const Element &e) {
            return e.station == block.front().station;
        });
        if (oneStation) {
            std::vector<Address> list;
            for (const Element &e : block)
                list.push_back(e.address);
            best = sizes.bytes(Request::mixedRead(block.front().station, list));
            const Address lo = std::min_element(block.begin(), block.end())->address;
            const Address hi = std::max_element(block.begin(), block.end())->address;
            const bool oneChain = std::all_of(block.begin(), block.end(), [&](const Element &e) {
                return e.address.type == lo.type
                       && e.address.number % lo.info().step == lo.number % lo.info().step;
            });
            if (oneChain) {
                const auto run = sizes.bytes(runRequest(
                    block.front().station, lo, (hi.number - lo.number) / lo.info().step + 1));
                if (run && (!best || *run < *best))
                    best = run;
            }
        }
        cached = best;
        return best;
    };
    // Restricted growth strings: element i joins one of the blocks so far or opens a new one.
    std::vector<std::size_t> blocks;
    Cost best = infinite;
    std::function<void(std::size_t)> assign = [&](std::size_t i) {
        if (i == n) {
            Cost c;
            for (std::size_t mask : blocks) {
                const std::optional<std::size_t> b = blockCost(mask);
                if (!b)
                    return;
                c = c + Cost{1, *b};
            }
            best = std::min(best, c);
            return;
        }
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            blocks[b] |= std::size_t{1} << i;
            assign(i + 1);
            blocks[b] &= ~(std::size_t{1} << i);
        }
        blocks.push_back(std::size_t{1} << i);
        assign(i + 1);
        blocks.pop_back();
    };
    assign(0);
    return best;
}

struct Measured
{
    Cost cost;
    bool bytesAgree = true; // the planner's own wireBytes matches the encoded frames
    std::size_t unplannable = 0;
};

Measured planned(const std::vector<Element> &elements, const WireSizes &sizes)
{
    std::vector<WatchItem> items;
    for (const Element &e : elements)
        items.push_back({items.size() + 1, e.station, e.address});
    const Plan plan = PollPlanner(sizes.protocol()).plan(items);
    Measured m;
    m.cost.requests = plan.requestCount();
    for (const PlanStep &step : plan.steps)
        m.cost.bytes += sizes.bytes(step.request).value_or(0);
    m.bytesAgree = m.cost.bytes == plan.wireBytes;
    m.unplannable = plan.unplannable.size();
    return m;
}

Cost onePerItem(const std::vector<Element> &elements, const WireSizes &sizes)
{
    Cost c;
    for (const Element &e : elements) {
        c.requests += 1;
        c.bytes += sizes.bytes(runRequest(e.station, e.address, 1)).value_or(0);
    }
    return c;
}

std::vector<Element> distinctSorted(std::vector<Element> v)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

// `count` distinct numbers in [0, range) that are multiples of `multiple`, from a fixed seed.
std::vector<std::uint32_t> scattered(std::mt19937 &rng, std::size_t count, std::uint32_t range,
                                     std::uint32_t multiple = 1)
{
    std::set<std::uint32_t> picked;
    std::uniform_int_distribution<std::uint32_t> pick(0, range / multiple - 1);
    while (picked.size() < count)
        picked.insert(pick(rng) * multiple);
    return {picked.begin(), picked.end()};
}

struct NamedList
{
    QString name;
    std::vector<Element> elements;
};

std::vector<NamedList> watchLists()
{
    std::mt19937 rng(7);
    std::vector<NamedList> lists;
    NamedList scatteredR{QStringLiteral("200 scattered R (R0..R3999)"), {}};
    for (std::uint32_t n : scattered(rng, 200, 4000))
        scatteredR.elements.push_back({1, {ElementType::R, n}});
    lists.push_back(scatteredR);

    NamedList range{QStringLiteral("R0..R999"), {}};
    for (std::uint32_t n = 0; n < 1000; ++n)
        range.elements.push_back({1, {ElementType::R, n}});
    lists.push_back(range);

    auto mixed = [&rng](std::uint8_t station, std::size_t scale) {
        std::vector<Element> v;
        for (std::uint32_t n : scattered(rng, 4 * scale, 256))
            v.push_back({station, {ElementType::X, n}});
        for (std::uint32_t n : scattered(rng, 3 * scale, 256))
            v.push_back({station, {ElementType::Y, n}});
        for (std::uint32_t n : scattered(rng, 6 * scale, 2000))
            v.push_back({station, {ElementType::M, n}});
        for (std::uint32_t n : scattered(rng, 2 * scale, 400, 2))
            v.push_back({station, {ElementType::DR, n}});
        for (std::uint32_t n : scattered(rng, scale, 256, 8))
            v.push_back({station, {ElementType::WY, n}});
        for (std::uint32_t n : scattered(rng, 2 * scale, 1000))
            v.push_back({station, {ElementType::R, n}});
        return v;
    };
    lists.push_back({QStringLiteral("mixed X/Y/M/R + DR + WY (180)"), mixed(1, 10)});
    NamedList stations{QStringLiteral("3 stations x mixed (3 x 90)"), {}};
    for (std::uint8_t s = 1; s <= 3; ++s) {
        const std::vector<Element> v = mixed(s, 5);
        stations.elements.insert(stations.elements.end(), v.begin(), v.end());
    }
    lists.push_back(stations);
    for (NamedList &l : lists)
        l.elements = distinctSorted(l.elements);
    return lists;
}

// Small lists for the brute force: a few elements close together, so runs, bridging and 48
// lists all compete.
std::vector<Element> smallList(std::mt19937 &rng)
{
    static const ElementType types[]
        = {ElementType::X, ElementType::Y,  ElementType::M,  ElementType::R,
           ElementType::D, ElementType::DR, ElementType::WY, ElementType::WM};
    std::uniform_int_distribution<int> size(3, 8);
    std::uniform_int_distribution<int> typePick(0, 7);
    std::uniform_int_distribution<int> stationPick(1, 4);
    std::vector<Element> v;
    const int n = size(rng);
    const bool twoStations = stationPick(rng) == 1;
    const ElementType main = types[typePick(rng)];
    while (static_cast<int>(v.size()) < n) {
        // Mostly one type, so that runs matter; sometimes another one.
        const ElementType type = stationPick(rng) == 1 ? types[typePick(rng)] : main;
        const ElementInfo &info = elementInfo(type);
        const std::uint32_t window = isDiscrete(type) ? 300 : (isDoubleWord(type) ? 80 : 90);
        std::uniform_int_distribution<std::uint32_t> offset(0, window);
        std::uint32_t number = offset(rng) * (info.alignment > 1 ? info.alignment : 1);
        if (type == ElementType::DR)
            number -= number % 2; // one chain: the even ones
        const auto station = static_cast<std::uint8_t>(twoStations ? 1 + v.size() % 2 : 1);
        v.push_back({station, {type, number}});
        v = distinctSorted(v);
    }
    return v;
}

// Median wall time of `plan` over `runs` runs, in ms (the first run is a warm-up, not counted).
template<typename F>
double medianMs(int runs, F &&plan)
{
    plan();
    std::vector<double> ms;
    for (int i = 0; i < runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        plan();
        const auto end = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

} // namespace

void runPlanTime(const Options &options, Report &report)
{
    // The items a default snapshot of the simulator's FBs packs (every element its 53 answer
    // reports, discretes through their word views): exactly what SnapshotReader plans.
    const SimulatedPlc plc;
    const Bytes status = plc.detailStatusBytes();
    const DetailStatus sizes = DetailStatus::decode(status);
    const std::vector<AddressRange> ranges = Snapshot::defaultRanges(sizes);
    const SnapshotReadItems snapshot = SnapshotReader::readItems(ranges, &sizes);
    const int runs = options.quick ? 5 : 21;

    double worstSnapshot = 0;
    double worstWatch = 0;
    for (Protocol protocol : {Protocol::Facon, Protocol::Binary}) {
        const QString proto = QString::fromUtf8(protocolName(protocol).data());
        const PollPlanner planner(protocol);
        std::size_t requests = 0;
        const double snapshotMs
            = medianMs(runs, [&] { requests = planner.plan(snapshot.items).requestCount(); });
        worstSnapshot = std::max(worstSnapshot, snapshotMs);
        report.row(QStringLiteral("plan time %1: whole FBs snapshot (%2 elements, %3 items), ms")
                       .arg(proto)
                       .arg(snapshot.wanted.size())
                       .arg(snapshot.items.size()),
                   fmt(snapshotMs, 3), QStringLiteral("%1 requests").arg(requests), {},
                   QStringLiteral("<= 5 ms"));
        report.result(QStringLiteral("plan_time_fbs_snapshot_%1_ms").arg(proto.toLower()),
                      snapshotMs, QStringLiteral("<=5"), snapshotMs <= 5.0);

        for (const NamedList &list : watchLists()) {
            std::vector<WatchItem> items;
            for (const Element &e : list.elements)
                items.push_back({items.size() + 1, e.station, e.address});
            const double ms
                = medianMs(runs, [&] { requests = planner.plan(items).requestCount(); });
            worstWatch = std::max(worstWatch, ms);
            report.row(QStringLiteral("plan time %1: watch list %2, ms").arg(proto, list.name),
                       fmt(ms, 3), QStringLiteral("%1 requests").arg(requests), {},
                       QStringLiteral("<= 5 ms"));
        }
    }
    report.result(QStringLiteral("plan_time_watch_lists_ms"), worstWatch, QStringLiteral("<=5"),
                  worstWatch <= 5.0);
}

void runPacking(const Options &options, Report &report)
{
    double worstRequests = 0;
    double worstBytes = 0;
    bool agree = true;
    for (Protocol protocol : {Protocol::Facon, Protocol::Binary}) {
        const WireSizes sizes(protocol);
        const QString proto = QString::fromUtf8(protocolName(protocol).data());

        // Small lists: planner, exact solver and brute force must all agree.
        std::mt19937 rng(11);
        const int lists = options.quick ? 40 : 300;
        int plannerOptimal = 0;
        int solverOptimal = 0;
        double smallWorstBytes = 1.0;
        for (int i = 0; i < lists; ++i) {
            const std::vector<Element> v = smallList(rng);
            const Cost brute = bruteForce(v, sizes);
            const Measured p = planned(v, sizes);
            const Cost exact = exactOptimum(v, sizes);
            agree = agree && p.bytesAgree;
            if (p.cost.requests == brute.requests && p.cost.bytes <= brute.bytes)
                ++plannerOptimal;
            if (exact.requests == brute.requests && exact.bytes == brute.bytes)
                ++solverOptimal;
            worstRequests = std::max(worstRequests, static_cast<double>(p.cost.requests)
                                                        / static_cast<double>(brute.requests));
            smallWorstBytes = std::max(smallWorstBytes, static_cast<double>(p.cost.bytes)
                                                            / static_cast<double>(brute.bytes));
        }
        worstBytes = std::max(worstBytes, smallWorstBytes);
        report.row(QStringLiteral("packing %1: %2 small lists (3-8 items), planner optimal")
                       .arg(proto)
                       .arg(lists),
                   QString::number(plannerOptimal), QStringLiteral("brute force, all partitions"),
                   QStringLiteral("worst bytes %1").arg(fmt(smallWorstBytes, 3)),
                   QStringLiteral("all"));
        report.row(QStringLiteral("packing %1: exact solver = brute force (self-check)").arg(proto),
                   QString::number(solverOptimal), QString::number(lists), {},
                   QStringLiteral("all"));
        agree = agree && solverOptimal == lists;

        for (const NamedList &list : watchLists()) {
            const Measured p = planned(list.elements, sizes);
            const Cost opt = exactOptimum(list.elements, sizes);
            const Cost naive = onePerItem(list.elements, sizes);
            agree = agree && p.bytesAgree && p.unplannable == 0;
            const double rq
                = static_cast<double>(p.cost.requests) / static_cast<double>(opt.requests);
            const double rb = static_cast<double>(p.cost.bytes) / static_cast<double>(opt.bytes);
            worstRequests = std::max(worstRequests, rq);
            worstBytes = std::max(worstBytes, rb);
            report.row(QStringLiteral("packing %1 %2: requests/cycle").arg(proto, list.name),
                       QString::number(p.cost.requests),
                       QStringLiteral("opt %1, 1/item %2").arg(opt.requests).arg(naive.requests),
                       fmt(rq, 3), QStringLiteral("= opt"));
            report.row(QStringLiteral("packing %1 %2: wire bytes/cycle").arg(proto, list.name),
                       QString::number(p.cost.bytes),
                       QStringLiteral("opt %1, 1/item %2").arg(opt.bytes).arg(naive.bytes),
                       fmt(rb, 3), QStringLiteral("<= 1.05 x opt"));
        }
    }
    report.result(QStringLiteral("packing_requests_vs_optimum"), worstRequests,
                  QStringLiteral("<=1.00"), worstRequests <= 1.0 && agree);
    report.result(QStringLiteral("packing_bytes_vs_optimum"), worstBytes, QStringLiteral("<=1.05"),
                  worstBytes <= 1.05 && agree);
    if (!agree)
        report.row(QStringLiteral("packing: WARNING planner byte count, unplannable items or "
                                  "solver self-check disagree"),
                   QStringLiteral("see above"));
}

} // namespace Fatek::Bench
