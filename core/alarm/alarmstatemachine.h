#pragma once

#include "alarmtypes.h"

#include <deque>
#include <vector>

namespace Fatek {

// One alarm's ISA-18.2 state machine: the confirmed condition (deadband, on- and off-delay), the
// state, acknowledge, shelve with an expiry, out of service, chattering. No clock of its own and
// no I/O: every input carries its time (ms since the epoch), so a test drives it on a fake clock.
// Each input appends the events it caused to `events` (in order; most inputs cause none or one).
class AlarmStateMachine
{
public:
    using Events = std::vector<AlarmEventType>;

    explicit AlarmStateMachine(const AlarmDefinition &definition = {});

    const AlarmDefinition &definition() const { return m_definition; }
    // A changed definition keeps the state; enabling or disabling it moves in or out of service.
    void setDefinition(const AlarmDefinition &definition, qint64 nowMs, Events &events);

    // A fresh value read at `nowMs` (limit kinds: the number; bit kinds: 0 or 1). Ignored by a
    // quality alarm.
    void valueRead(double value, qint64 nowMs, Events &events);
    // The item's quality as of `nowMs`: bad is stale or in error (quality alarms only).
    void qualitySeen(bool bad, qint64 nowMs, Events &events);
    // Time passing: a shelve's expiry, a quality alarm's delays.
    void tick(qint64 nowMs, Events &events);

    // Why an operator action was refused (the engine words it with the alarm's id).
    enum class Refusal { None, NothingToAck, NotShelved, ShelveExpired, OutOfService };
    // Operator actions. A refusal changes nothing.
    Refusal acknowledge(qint64 nowMs, Events &events);
    Refusal shelve(qint64 untilMs, qint64 nowMs, Events &events);
    Refusal unshelve(qint64 nowMs, Events &events);

    // Brings back what the journal kept (after a restart); causes no event. The next value
    // confirms or ends the condition as it is now (an alarm active and unacknowledged whose value
    // is back in range becomes returned-unacknowledged then).
    void restore(const AlarmRecord &record);
    // The record of this alarm, for the journal (connection and id are the caller's).
    AlarmRecord record() const;

    AlarmState state() const { return m_state; }
    bool conditionActive() const { return m_condition; }
    qint64 sinceMs() const { return m_sinceMs; }
    qint64 raisedMs() const { return m_raisedMs; }
    qint64 shelvedUntilMs() const { return m_shelvedUntilMs; }
    // Raised Alarms::ChatterCount times or more within the last Alarms::ChatterWindowMs.
    bool chattering(qint64 nowMs) const;

private:
    // The raw condition of a value, before the delays: the deadband keeps a confirmed condition
    // until the value is past the limit by it.
    bool rawCondition(double value) const;
    // The raw condition seen at `nowMs`: confirmed once it has held for its delay.
    void conditionSeen(bool raw, qint64 nowMs, Events &events);
    void confirm(bool active, qint64 nowMs, Events &events);
    void enter(AlarmState state, qint64 nowMs);
    void raise(qint64 nowMs, Events &events);

    AlarmDefinition m_definition;
    AlarmState m_state = AlarmState::Normal;
    bool m_condition = false;     // confirmed
    bool m_lastRaw = false;       // the last raw condition seen (a quality alarm's, for tick)
    qint64 m_pendingSinceMs = -1; // since when the raw condition differs from the confirmed one
    qint64 m_sinceMs = 0;
    qint64 m_raisedMs = 0;
    qint64 m_shelvedUntilMs = 0;
    std::deque<qint64> m_raises; // within the chatter window
};

} // namespace Fatek
