#include "pollplanner.h"

#include "stationsolver.h"
#include "wiresize.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

// Each station's reads are chosen by StationSolver (stationsolver.cpp says how); here they become
// the plan's steps.

namespace Fatek {

namespace {

using PlanReads::runRead;
using PlanReads::singleRead;

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

PollPlanner::PollPlanner(Protocol protocol, Solver solver)
    : m_protocol(protocol)
    , m_solver(solver)
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
    // The plannable items by station and address; a duplicate's ids stay in input order. A sorted
    // vector, not maps: a snapshot has thousands of items.
    struct Entry
    {
        StationAddress element;
        std::uint64_t id = 0;
        std::uint32_t index = 0; // position in `items`
    };
    std::vector<Entry> entries;
    entries.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        const WatchItem &item = items[i];
        const auto index = static_cast<std::uint32_t>(i);
        if (item.station == Limits::broadcastStation) {
            result.unplannable.push_back(
                {item.id, index, msg<MsgId::PlanBroadcast>(item.address.toString())});
            continue;
        }
        if (Status s = validateRequest(singleRead(item.station, item.address), m_protocol); !s) {
            result.unplannable.push_back({item.id, index, s.error().message});
            continue;
        }
        entries.push_back({{item.station, item.address}, item.id, index});
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry &a, const Entry &b) { return a.element < b.element; });

    StationSolver solver(m_protocol, m_solver);
    for (auto first = entries.cbegin(); first != entries.cend();) {
        const std::uint8_t station = first->element.station;
        const auto last = std::find_if(first, entries.cend(), [station](const Entry &e) {
            return e.element.station != station;
        });
        const std::span<const Entry> elements(first, last);
        first = last;
        auto slotsFor
            = [elements](const Address &a, std::uint32_t valueIndex, std::vector<PlanSlot> &out) {
                  auto it = std::lower_bound(
                      elements.begin(), elements.end(), a,
                      [](const Entry &e, const Address &x) { return e.element.address < x; });
                  for (; it != elements.end() && it->element.address == a; ++it)
                      out.push_back({it->id, valueIndex, it->index});
              };

        std::vector<Address> batchable;
        std::set<Address> blockers;
        for (const StationAddress &bad : isolated) {
            if (bad.station == station)
                blockers.insert(bad.address);
        }
        std::vector<PlanStep> steps;
        for (std::size_t k = 0; k < elements.size(); ++k) {
            const Address &a = elements[k].element.address;
            if (k > 0 && elements[k - 1].element.address == a)
                continue; // a duplicate: read once
            if (blockers.count(a)) {
                std::vector<PlanSlot> itemSlots;
                slotsFor(a, 0, itemSlots);
                steps.push_back(makeStep(singleRead(station, a), std::move(itemSlots)));
            } else {
                batchable.push_back(a);
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
                itemSlots.push_back({s.itemId, it->second, s.itemIndex});
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
