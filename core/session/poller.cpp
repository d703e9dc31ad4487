#include "poller.h"

#include <algorithm>
#include <cmath>

namespace Fatek {

namespace {

QString secondsText(qint64 ms)
{
    return QString::number(static_cast<double>(ms) / 1000.0, 'f', 1);
}

} // namespace

Poller::Poller(SubmitFunction submit, Policy policy, QObject *parent)
    : QObject(parent)
    , m_submit(std::move(submit))
    , m_policy(policy)
{
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &Poller::onTimer);
}

void Poller::setProtocol(Protocol protocol)
{
    m_planner.emplace(protocol);
    for (auto &[key, group] : m_groups)
        replan(group);
}

void Poller::setWatchList(const QList<WatchEntry> &entries)
{
    // Items that stay keep their last good value (by id, only for this hand-over); the others'
    // are forgotten.
    QHash<std::uint64_t, LastGood> lastGood;
    for (const auto &[key, group] : m_groups) {
        for (std::size_t i = 0; i < group.items.size(); ++i) {
            if (group.lastGood[i].timestamp.isValid())
                lastGood.insert(group.items[i].id, group.lastGood[i]);
        }
    }
    // Results of cycles still on the wire belong to the old list: the generation tells them apart.
    m_groups.clear();
    std::set<quint8> stations;
    for (const WatchEntry &entry : entries) {
        const int interval = std::max(10, entry.intervalMs);
        Group &group = m_groups[{interval, entry.station}];
        group.intervalMs = interval;
        group.station = entry.station;
        group.items.push_back({entry.id, entry.station, entry.address});
        group.lastGood.push_back(lastGood.value(entry.id));
        stations.insert(entry.station);
    }
    lastGood = {};
    // A station that left the list starts afresh if it comes back.
    for (auto it = m_health.begin(); it != m_health.end();) {
        if (stations.contains(it->first)) {
            it->second.trialOut = false; // a probe of the old list is answered to nobody
            ++it;
            continue;
        }
        if (it->second.demoted)
            Q_EMIT stationHealthChanged(it->first, false, {}, 0);
        it = m_health.erase(it);
    }
    const qint64 now = m_clock.elapsed();
    // A station new to the list is probed first; its probe is due from now.
    for (const quint8 station : stations) {
        if (const auto [it, added] = m_health.try_emplace(station); added)
            it->second.until = now;
    }
    m_stations = std::move(stations);
    for (auto &[key, group] : m_groups) {
        group.generation = ++m_generation;
        group.deadline = now;
        group.lastDelivery = now;
        replan(group);
    }
    reschedule();
}

void Poller::setLinkUp(bool up)
{
    m_linkUp = up;
    if (up) {
        // Lateness counts from here: a link that was down has said so already.
        const qint64 now = m_clock.elapsed();
        for (auto &[key, group] : m_groups) {
            group.deadline = std::max(group.deadline, now);
            group.lastDelivery = std::max(group.lastDelivery, now);
        }
    }
    reschedule();
}

void Poller::replan(Group &group)
{
    // Until auto-detect decides, plan for FACON: its elements are a subset of binary's.
    if (!m_planner)
        m_planner.emplace(Protocol::Facon);
    group.plan = m_planner->plan(group.items, m_isolated);
    group.replan = false;
}

void Poller::reschedule()
{
    m_timer.stop();
    if (!m_linkUp)
        return;
    std::optional<qint64> next;
    const auto consider = [&next](qint64 at) {
        next = next ? std::min(*next, at) : at;
    };
    for (const auto &[key, group] : m_groups) {
        if (!group.inFlight && isPolled(group.station))
            consider(group.deadline);
        if (!group.lateReported && !group.goodLastTime.empty())
            consider(lateAt(group));
    }
    const qint64 now = m_clock.elapsed();
    if (!probeOut()) {
        for (const quint8 station : m_stations) {
            const StationHealth &health = m_health[station];
            if (!needsProbe(health))
                continue;
            // No slack now: a cycle's end reschedules; past one more rest it goes anyway.
            const std::optional<qint64> at = probeAt(health, now);
            consider(at ? *at : health.until + probePatience(health));
        }
    }
    if (!next)
        return;
    m_timer.start(static_cast<int>(std::max<qint64>(0, *next - now)));
}

void Poller::onTimer()
{
    if (!m_linkUp)
        return;
    const qint64 now = m_clock.elapsed();
    for (auto &[key, group] : m_groups) {
        if (!group.inFlight && group.deadline <= now && isPolled(group.station))
            startCycle(group);
    }
    for (auto &[key, group] : m_groups) {
        if (!group.lateReported && !group.goodLastTime.empty() && now >= lateAt(group))
            reportLate(group, now);
    }
    // One probe at a time, after the due cycles have taken the line; the longest due first.
    if (!probeOut()) {
        std::optional<quint8> first;
        for (const quint8 station : m_stations) {
            const StationHealth &health = m_health[station];
            if (!needsProbe(health) || (first && m_health[*first].until <= health.until))
                continue;
            if (const std::optional<qint64> at = probeAt(health, now); at && *at <= now)
                first = station;
        }
        if (first)
            submitProbe(*first);
    }
    reschedule();
}

std::set<StationAddress> Poller::elementsOf(const PlanStep &step)
{
    std::set<StationAddress> elements;
    if (step.request.command == Command::MixedRead) {
        for (const Address &address : step.request.addresses)
            elements.insert({step.request.station, address});
    } else {
        elements.insert({step.request.station, step.request.start});
    }
    return elements;
}

bool Poller::noAnswer(const SessionResult &result)
{
    // Nobody answered at all. A refusal, a damaged frame or a wrong answer means someone is there.
    return !result.ok() && result.errorKind() == ErrorKind::Timeout;
}

bool Poller::isRefusal(const PlanStep &step) const
{
    // Isolated elements are planned alone: a step of one refused element.
    if (m_refusals.empty() || step.itemSlots.empty())
        return false;
    const std::set<StationAddress> elements = elementsOf(step);
    return elements.size() == 1 && m_refusals.contains(*elements.begin());
}

void Poller::startCycle(Group &group)
{
    const qint64 now = m_clock.elapsed();
    group.inFlight = true;
    group.cycleStart = now;
    // A new list every cycle: the last one went out as the batch, and its receivers on other
    // threads may still read it. (Writing into it once they let go is not safe: Qt tells an
    // unshared list by a relaxed load of its count, which orders nothing, and ThreadSanitizer
    // rightly reports the receivers' reads against the next cycle's writes.)
    group.cycleValues = QList<WatchValue>(static_cast<qsizetype>(group.items.size()));
    group.cycleFilled.assign(group.items.size(), false);
    group.pending.clear();
    group.outstanding = 0;
    const QDateTime wallNow = QDateTime::currentDateTimeUtc();
    for (const PlanStep &step : group.plan.steps) {
        if (isRefusal(step)) {
            const Refusal &refusal = m_refusals.at(*elementsOf(step).begin());
            if (now < refusal.recheckAt) {
                // Known to be refused: shown as such without asking the PLC every cycle.
                for (const PlanSlot &slot : step.itemSlots)
                    setCycleValue(group, slot.itemIndex,
                                  {slot.itemId, 0, wallNow, ValueQuality::Error, refusal.reason});
                continue;
            }
        }
        group.pending.push_back(step);
    }
    submitNext(group);
}

void Poller::submitNext(Group &group)
{
    // One request of the group in the queue at a time: the stations of a line and one-shot
    // requests take turns with it. A request refused at once (link down) finishes inside
    // m_submit; the loop then goes on instead of recursing.
    group.submitting = true;
    while (group.outstanding == 0 && !group.pending.empty()) {
        const PlanStep step = std::move(group.pending.front());
        group.pending.pop_front();
        ++group.outstanding;
        RequestOptions options;
        if (m_health[group.station].unanswered > 0)
            options.retries = 0; // a station that left a request unanswered gets one attempt
        options.expectRefusal = isRefusal(step);
        const GroupKey key{group.intervalMs, group.station};
        const quint64 generation = group.generation;
        m_submit(step.request, options, [this, key, generation, step](const SessionResult &result) {
            onStepDone(key, generation, step, result);
        });
    }
    group.submitting = false;
    if (group.outstanding == 0 && group.pending.empty() && group.inFlight)
        finishCycle(group);
}

void Poller::onStepDone(GroupKey key, quint64 generation, const PlanStep &step,
                        const SessionResult &result)
{
    noteAnswer(step.request.station, result); // whether or not the list changed meanwhile
    auto it = m_groups.find(key);
    if (it == m_groups.end() || it->second.generation != generation)
        return; // the watch list changed meanwhile
    Group &group = it->second;
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const bool recheck = isRefusal(step);

    if (result.ok()) {
        if (recheck) {
            // The PLC takes the element now (another PLC, a changed configuration).
            const StationAddress element = *elementsOf(step).begin();
            m_refusals.erase(element);
            m_isolated.erase(element);
            group.replan = true;
        }
        const Response &response = result.response();
        for (const PlanSlot &slot : step.itemSlots) {
            WatchValue value;
            value.itemId = slot.itemId;
            value.timestamp = now;
            if (slot.valueIndex < response.values.size()) {
                value.value = response.values[slot.valueIndex];
                value.quality = ValueQuality::Good;
                group.lastGood[slot.itemIndex] = {value.value, now};
            } else {
                value.quality = ValueQuality::Error;
                value.error = msg<MsgId::SessionFewerValues>();
            }
            setCycleValue(group, slot.itemIndex, std::move(value));
        }
    } else if (result.errorKind() == ErrorKind::PlcError
               && (result.error().plcCode == 0xA || result.error().plcCode == 2)) {
        // One bad address must not blank the whole batch: split until it is found.
        const std::vector<PlanStep> halves = m_planner->split(step);
        if (!halves.empty()) {
            for (auto half = halves.rbegin(); half != halves.rend(); ++half)
                group.pending.push_front(*half);
        } else {
            const qint64 recheckAt = m_clock.elapsed() + refusalRecheckMs;
            for (const StationAddress &element : elementsOf(step)) {
                if (m_isolated.insert(element).second)
                    group.replan = true;
                m_refusals[element] = {result.errorMessage(), recheckAt};
            }
            for (const PlanSlot &slot : step.itemSlots)
                setCycleValue(group, slot.itemIndex,
                              {slot.itemId, 0, now, ValueQuality::Error, result.errorMessage()});
        }
    } else if (result.errorKind() == ErrorKind::PlcError
               || result.errorKind() == ErrorKind::InvalidAddress
               || result.errorKind() == ErrorKind::InvalidRequest
               || result.errorKind() == ErrorKind::LimitExceeded
               || result.errorKind() == ErrorKind::Unsupported) {
        for (const PlanSlot &slot : step.itemSlots)
            setCycleValue(group, slot.itemIndex,
                          {slot.itemId, 0, now, ValueQuality::Error, result.errorMessage()});
    } else {
        // Timeout, link down, damaged answers: the old value is kept, marked stale (with the
        // demotion, when this was the request that demoted the station).
        const auto health = m_health.find(step.request.station);
        const Message reason
            = noAnswer(result) && health != m_health.end() && health->second.demoted
                  ? demotedReason(step.request.station)
                  : result.errorMessage();
        for (const PlanSlot &slot : step.itemSlots) {
            const LastGood &last = group.lastGood[slot.itemIndex];
            setCycleValue(group, slot.itemIndex,
                          {slot.itemId, last.value, last.timestamp, ValueQuality::Stale, reason});
        }
    }

    --group.outstanding;
    if (group.submitting)
        return; // submitNext() goes on
    if (!group.pending.empty())
        submitNext(group);
    else if (group.outstanding == 0)
        finishCycle(group);
}

qint64 Poller::recentCycle(const Group &group)
{
    return *std::max_element(group.recentCycleMs.begin(), group.recentCycleMs.end());
}

qint64 Poller::expectedPeriod(const Group &group)
{
    return std::max<qint64>(group.intervalMs, recentCycle(group));
}

qint64 Poller::lateAt(const Group &group)
{
    return group.lastDelivery + 2 * expectedPeriod(group);
}

void Poller::noteCycleTime(Group &group, qint64 ms)
{
    group.recentCycleMs[group.recentNext] = ms;
    group.recentNext = (group.recentNext + 1) % group.recentCycleMs.size();
    // Said once per change, with a band between (1 to 1.5 x the interval) so that a cycle time
    // close to the interval does not flap the message either.
    const qint64 recent = recentCycle(group);
    if (!group.slowed && 2 * recent > 3 * static_cast<qint64>(group.intervalMs)) {
        group.slowed = true;
        Q_EMIT effectiveIntervalChanged(group.station, group.intervalMs, static_cast<int>(recent));
    } else if (group.slowed && recent <= group.intervalMs) {
        group.slowed = false;
        Q_EMIT effectiveIntervalChanged(group.station, group.intervalMs, group.intervalMs);
    }
}

void Poller::reportLate(Group &group, qint64 now)
{
    group.lateReported = true;
    const QDateTime wallNow = QDateTime::currentDateTimeUtc();
    QList<WatchValue> batch;
    for (const std::uint32_t index : group.goodLastTime) {
        const LastGood &last = group.lastGood[index];
        const qint64 age
            = last.timestamp.isValid() ? last.timestamp.msecsTo(wallNow) : now - group.lastDelivery;
        batch.append({group.items[index].id, last.value, last.timestamp, ValueQuality::Late,
                      msg<MsgId::SessionValueLate>(secondsText(age).toStdString(),
                                                   static_cast<int>(expectedPeriod(group)))});
    }
    group.goodLastTime.clear();
    if (!batch.isEmpty())
        Q_EMIT values(batch);
}

void Poller::setCycleValue(Group &group, std::uint32_t index, WatchValue value)
{
    group.cycleValues[index] = std::move(value);
    group.cycleFilled[index] = true;
}

void Poller::finishCycle(Group &group)
{
    const qint64 now = m_clock.elapsed();
    for (const UnplannableItem &item : group.plan.unplannable)
        setCycleValue(
            group, item.itemIndex,
            {item.itemId, 0, QDateTime::currentDateTimeUtc(), ValueQuality::Error, item.reason});
    group.goodLastTime.clear();
    const std::size_t count = group.items.size();
    std::size_t filled = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!group.cycleFilled[i])
            continue;
        ++filled;
        if (group.cycleValues.at(static_cast<qsizetype>(i)).quality == ValueQuality::Good)
            group.goodLastTime.push_back(static_cast<std::uint32_t>(i));
    }
    // Usually every item has its value: the batch is the cycle's list itself (shared, not
    // copied). Items without one (a cycle cut short) are left out, in item order.
    QList<WatchValue> batch;
    if (filled == count) {
        batch = group.cycleValues;
    } else {
        batch.reserve(static_cast<qsizetype>(filled));
        for (std::size_t i = 0; i < count; ++i) {
            if (group.cycleFilled[i])
                batch.append(group.cycleValues.at(static_cast<qsizetype>(i)));
        }
    }
    group.inFlight = false;
    const StationHealth &health = m_health[group.station];
    noteCycleTime(group, now - group.cycleStart);
    if (group.replan)
        replan(group);
    // Absolute deadlines: the next cycle is one interval after the previous deadline, or right
    // now if this cycle overran it (never a burst of missed cycles).
    group.deadline = std::max(group.deadline + group.intervalMs, now);
    if (health.demoted)
        group.deadline = std::max(group.deadline, health.until);
    group.lastDelivery = now;
    group.lateReported = false;
    Q_EMIT cycleCompleted(static_cast<double>(now - group.cycleStart));
    Q_EMIT values(batch);
    reschedule();
}

} // namespace Fatek
