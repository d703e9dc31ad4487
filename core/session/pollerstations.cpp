#include "poller.h"

#include <algorithm>
#include <cmath>

// The Poller's stations (issue 31, issue 54): which answer, which rest, and the probes that find
// a resting station back in the line's slack. The cycles are in poller.cpp.

namespace Fatek {

void Poller::noteAnswer(quint8 station, const SessionResult &result)
{
    StationHealth &health = m_health[station];
    if (!noAnswer(result)) {
        if (!result.ok()
            && (result.errorKind() == ErrorKind::LinkError
                || result.errorKind() == ErrorKind::Cancelled))
            return; // says nothing about the station
        const bool wasProbed = needsProbe(health);
        const bool wasDemoted = health.demoted;
        health = StationHealth{};
        health.heard = true;
        if (wasDemoted)
            Q_EMIT stationHealthChanged(station, false, {}, 0);
        if (wasProbed) {
            const qint64 now = m_clock.elapsed();
            for (auto &[key, group] : m_groups) {
                if (group.station == station && !group.inFlight)
                    group.deadline = std::min(group.deadline, now);
            }
            reschedule();
        }
        return;
    }
    ++health.unanswered;
    // A resting station whose probe is unanswered rests again; another rests after demoteAfter
    // requests in a row (for a station new to the list these are probes: only the first one can
    // hold the line, the others wait for its slack).
    if (m_policy.demoteAfter <= 0)
        return;
    if (health.demoted ? !health.trialOut : health.unanswered < m_policy.demoteAfter)
        return;
    const qint64 now = m_clock.elapsed();
    health.demoted = true;
    health.trialOut = false;
    health.until = now + m_policy.demotionMs;
    Q_EMIT stationHealthChanged(station, true,
                                QDateTime::currentDateTimeUtc().addMSecs(m_policy.demotionMs),
                                health.unanswered);
    const QDateTime wallNow = QDateTime::currentDateTimeUtc();
    for (auto &[key, group] : m_groups) {
        if (group.station != station)
            continue;
        if (group.inFlight) {
            // The rest of the cycle is not sent: the station would only hold up the line.
            markDemoted(group, {group.pending.begin(), group.pending.end()});
            group.pending.clear();
            continue;
        }
        // Resting groups say so at once, with the next try.
        const Message reason = demotedReason(station);
        QList<WatchValue> batch;
        batch.reserve(static_cast<qsizetype>(group.items.size()));
        for (std::size_t i = 0; i < group.items.size(); ++i) {
            const LastGood &last = group.lastGood[i];
            batch.append({group.items[i].id, last.value,
                          last.timestamp.isValid() ? last.timestamp : wallNow, ValueQuality::Stale,
                          reason});
        }
        group.goodLastTime.clear();
        group.lastDelivery = now;
        group.deadline = health.until;
        if (!batch.isEmpty())
            Q_EMIT values(batch);
    }
    reschedule(); // its probe, when the rest ends
}

bool Poller::isSuspect(quint8 station) const
{
    const auto it = m_health.find(station);
    return it != m_health.end() && it->second.unanswered > 0;
}

bool Poller::isResting(quint8 station, Message *reason) const
{
    const auto it = m_health.find(station);
    if (it == m_health.end() || !it->second.demoted)
        return false;
    if (reason)
        *reason = demotedReason(station);
    return true;
}

Message Poller::demotedReason(quint8 station) const
{
    const auto it = m_health.find(station);
    const StationHealth health = it != m_health.end() ? it->second : StationHealth{};
    const QDateTime next = QDateTime::currentDateTime().addMSecs(
        std::max<qint64>(0, health.until - m_clock.elapsed()));
    return msg<MsgId::SessionStationDemoted>(
        station, health.unanswered, next.toString(QStringLiteral("HH:mm:ss")).toStdString());
}

void Poller::markDemoted(Group &group, const std::vector<PlanStep> &steps)
{
    const Message reason = demotedReason(group.station);
    for (const PlanStep &step : steps) {
        for (const PlanSlot &slot : step.itemSlots) {
            const LastGood &last = group.lastGood[slot.itemIndex];
            setCycleValue(
                group, slot.itemIndex,
                {slot.itemId, last.value,
                 last.timestamp.isValid() ? last.timestamp : QDateTime::currentDateTimeUtc(),
                 ValueQuality::Stale, reason});
        }
    }
}

int Poller::probeTimeoutMs() const
{
    const double roundTrip = m_policy.roundTripMs ? m_policy.roundTripMs() : 0.0;
    if (roundTrip <= 0)
        return m_policy.timeoutMs; // nothing measured yet: the link's own timeout
    const auto derived = static_cast<int>(std::ceil(roundTrip * probeRoundTrips));
    return std::clamp(derived, std::min(probeMinMs, m_policy.timeoutMs), m_policy.timeoutMs);
}

bool Poller::needsProbe(const StationHealth &health) const
{
    return m_policy.demoteAfter > 0 && (health.demoted || !health.heard);
}

bool Poller::isPolled(quint8 station) const
{
    const auto it = m_health.find(station);
    return it != m_health.end() ? !needsProbe(it->second) : m_policy.demoteAfter <= 0;
}

bool Poller::probeOut() const
{
    return std::any_of(m_health.begin(), m_health.end(),
                       [](const auto &entry) { return entry.second.trialOut; });
}

qint64 Poller::probePatience(const StationHealth &health) const
{
    // A resting station can wait one more rest; a new one waits one timeout between its probes,
    // or a busy line would keep its items without a word for many rests.
    return health.demoted ? m_policy.demotionMs : m_policy.timeoutMs;
}

std::optional<qint64> Poller::probeAt(const StationHealth &health, qint64 now) const
{
    const qint64 at = std::max(health.until, now);
    if (at >= health.until + probePatience(health))
        return at; // the line has no slack for it
    // The slack: no polled group on the line, and the probe's timeout ends before each one's
    // next cycle is due, or delays it by at most half of its spare time (interval minus cycle
    // time): it then neither loses an update nor turns late.
    std::optional<qint64> latest;
    for (const auto &[key, group] : m_groups) {
        if (!isPolled(group.station))
            continue;
        if (group.inFlight)
            return std::nullopt;
        const qint64 spare = std::max<qint64>(0, group.intervalMs - recentCycle(group));
        const qint64 until = group.deadline + spare / 2;
        latest = latest ? std::min(*latest, until) : until;
    }
    if (latest && at + probeTimeoutMs() > *latest)
        return std::nullopt;
    return at;
}

void Poller::submitProbe(quint8 station)
{
    StationHealth &health = m_health[station];
    health.trialOut = true;
    health.probe = ++m_probes;
    RequestOptions options;
    options.timeoutMs = probeTimeoutMs();
    options.retries = 0;
    m_submit(Request::briefStatus(station), options,
             [this, station, probe = health.probe](const SessionResult &result) {
                 onProbeDone(station, probe, result);
             });
}

void Poller::onProbeDone(quint8 station, quint64 probe, const SessionResult &result)
{
    const auto it = m_health.find(station);
    if (it == m_health.end() || it->second.probe != probe || !it->second.trialOut) {
        // The list changed, or other requests' answers (or silence) decided meanwhile.
        reschedule();
        return;
    }
    if (!result.ok()
        && (result.errorKind() == ErrorKind::LinkError || result.errorKind() == ErrorKind::Cancelled
            || result.errorKind() == ErrorKind::Expired)) {
        it->second.trialOut = false; // no verdict: probed again at the next slack
        reschedule();
        return;
    }
    noteAnswer(station, result); // an answer: polled from now on; none: it may rest (again)
    if (const auto again = m_health.find(station); again != m_health.end()) {
        again->second.trialOut = false;
        // Not resting yet (a new station): probed again, after the other stations' probes.
        if (needsProbe(again->second) && !again->second.demoted)
            again->second.until = m_clock.elapsed();
    }
    reschedule();
}

} // namespace Fatek
