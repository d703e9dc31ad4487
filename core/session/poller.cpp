#include "poller.h"

#include <algorithm>

namespace Fatek {

Poller::Poller(SubmitFunction submit, QObject *parent)
    : QObject(parent)
    , m_submit(std::move(submit))
{
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &Poller::onTimer);
}

void Poller::setProtocol(Protocol protocol)
{
    m_planner.emplace(protocol);
    for (auto &[interval, group] : m_groups)
        replan(group);
}

void Poller::setWatchList(const QList<WatchEntry> &entries)
{
    // Results of cycles still on the wire belong to the old list: the generation tells them apart.
    m_groups.clear();
    QHash<std::uint64_t, LastGood> lastGood;
    for (const WatchEntry &entry : entries) {
        if (m_lastGood.contains(entry.id))
            lastGood.insert(entry.id, m_lastGood.value(entry.id));
        const int interval = std::max(10, entry.intervalMs);
        Group &group = m_groups[interval];
        group.intervalMs = interval;
        group.items.push_back({entry.id, entry.station, entry.address});
    }
    m_lastGood = lastGood; // forget items that left the list
    const qint64 now = m_clock.elapsed();
    for (auto &[interval, group] : m_groups) {
        group.generation = ++m_generation;
        group.deadline = now;
        replan(group);
    }
    reschedule();
}

void Poller::setLinkUp(bool up)
{
    m_linkUp = up;
    if (up) {
        const qint64 now = m_clock.elapsed();
        for (auto &[interval, group] : m_groups)
            group.deadline = std::max(group.deadline, now);
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
    for (const auto &[interval, group] : m_groups) {
        if (!group.inFlight)
            next = next ? std::min(*next, group.deadline) : group.deadline;
    }
    if (!next)
        return;
    m_timer.start(static_cast<int>(std::max<qint64>(0, *next - m_clock.elapsed())));
}

void Poller::onTimer()
{
    if (!m_linkUp)
        return;
    const qint64 now = m_clock.elapsed();
    for (auto &[interval, group] : m_groups) {
        if (!group.inFlight && group.deadline <= now)
            startCycle(group);
    }
    reschedule();
}

void Poller::startCycle(Group &group)
{
    group.inFlight = true;
    group.cycleStart = m_clock.elapsed();
    group.cycleValues.clear();

    // Several stations on one link: alternate between them so none waits for the others' batches.
    std::map<std::uint8_t, std::vector<const PlanStep *>> byStation;
    for (const PlanStep &step : group.plan.steps)
        byStation[step.request.station].push_back(&step);
    std::vector<const PlanStep *> order;
    for (std::size_t round = 0; order.size() < group.plan.steps.size(); ++round) {
        for (auto &[station, steps] : byStation) {
            if (round < steps.size())
                order.push_back(steps[round]);
        }
    }
    group.outstanding = static_cast<int>(order.size());
    if (order.empty()) {
        finishCycle(group);
        return;
    }
    // Copies: a step may be split while the plan is replaced.
    const std::vector<PlanStep> steps = [&order] {
        std::vector<PlanStep> copy;
        copy.reserve(order.size());
        for (const PlanStep *step : order)
            copy.push_back(*step);
        return copy;
    }();
    for (const PlanStep &step : steps)
        submitStep(group, step);
}

void Poller::submitStep(Group &group, const PlanStep &step)
{
    const int interval = group.intervalMs;
    const quint64 generation = group.generation;
    m_submit(step.request, [this, interval, generation, step](const SessionResult &result) {
        onStepDone(interval, generation, step, result);
    });
}

void Poller::onStepDone(int intervalMs, quint64 generation, const PlanStep &step,
                        const SessionResult &result)
{
    auto it = m_groups.find(intervalMs);
    if (it == m_groups.end() || it->second.generation != generation)
        return; // the watch list changed meanwhile
    Group &group = it->second;
    const QDateTime now = QDateTime::currentDateTimeUtc();

    if (result.ok()) {
        const Response &response = result.response();
        for (const PlanSlot &slot : step.itemSlots) {
            WatchValue value;
            value.itemId = slot.itemId;
            value.timestamp = now;
            if (slot.valueIndex < response.values.size()) {
                value.value = response.values[slot.valueIndex];
                value.quality = ValueQuality::Good;
                m_lastGood.insert(slot.itemId, {value.value, now});
            } else {
                value.quality = ValueQuality::Error;
                value.error = msg<MsgId::SessionFewerValues>();
            }
            group.cycleValues.insert(slot.itemId, value);
        }
    } else if (result.errorKind() == ErrorKind::PlcError
               && (result.error().plcCode == 0xA || result.error().plcCode == 2)) {
        // One bad address must not blank the whole batch: split until it is found.
        const std::vector<PlanStep> halves = m_planner->split(step);
        if (!halves.empty()) {
            group.outstanding += static_cast<int>(halves.size());
            for (const PlanStep &half : halves)
                submitStep(group, half);
        } else {
            std::set<StationAddress> elements;
            if (step.request.command == Command::MixedRead) {
                for (const Address &address : step.request.addresses)
                    elements.insert({step.request.station, address});
            } else {
                elements.insert({step.request.station, step.request.start});
            }
            for (const StationAddress &element : elements) {
                if (m_isolated.insert(element).second)
                    group.replan = true;
            }
            for (const PlanSlot &slot : step.itemSlots)
                group.cycleValues.insert(
                    slot.itemId, {slot.itemId, 0, now, ValueQuality::Error, result.errorMessage()});
        }
    } else if (result.errorKind() == ErrorKind::PlcError
               || result.errorKind() == ErrorKind::InvalidAddress
               || result.errorKind() == ErrorKind::InvalidRequest
               || result.errorKind() == ErrorKind::LimitExceeded
               || result.errorKind() == ErrorKind::Unsupported) {
        for (const PlanSlot &slot : step.itemSlots)
            group.cycleValues.insert(
                slot.itemId, {slot.itemId, 0, now, ValueQuality::Error, result.errorMessage()});
    } else {
        // Timeout, link down, damaged answers: the old value is kept, marked stale.
        for (const PlanSlot &slot : step.itemSlots) {
            const LastGood last = m_lastGood.value(slot.itemId);
            group.cycleValues.insert(slot.itemId, {slot.itemId, last.value, last.timestamp,
                                                   ValueQuality::Stale, result.errorMessage()});
        }
    }

    if (--group.outstanding == 0)
        finishCycle(group);
}

void Poller::finishCycle(Group &group)
{
    const qint64 now = m_clock.elapsed();
    QList<WatchValue> batch;
    batch.reserve(static_cast<qsizetype>(group.items.size()));
    for (const UnplannableItem &item : group.plan.unplannable)
        group.cycleValues.insert(item.itemId, {item.itemId, 0, QDateTime::currentDateTimeUtc(),
                                               ValueQuality::Error, item.reason});
    for (const WatchItem &item : group.items) {
        auto it = group.cycleValues.constFind(item.id);
        if (it != group.cycleValues.constEnd())
            batch.append(*it);
    }
    group.inFlight = false;
    if (group.replan)
        replan(group);
    // Absolute deadlines: the next cycle is one interval after the previous deadline, or right
    // now if this cycle overran it (never a burst of missed cycles).
    group.deadline = std::max(group.deadline + group.intervalMs, now);
    Q_EMIT cycleCompleted(static_cast<double>(now - group.cycleStart));
    Q_EMIT values(batch);
    reschedule();
}

} // namespace Fatek
