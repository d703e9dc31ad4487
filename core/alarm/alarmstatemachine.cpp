#include "alarmstatemachine.h"

// One alarm's ISA-18.2 state machine (docs/alarms.md draws it).

namespace Fatek {

AlarmStateMachine::AlarmStateMachine(const AlarmDefinition &definition)
    : m_definition(definition)
    , m_state(definition.enabled ? AlarmState::Normal : AlarmState::OutOfService)
{}

void AlarmStateMachine::setDefinition(const AlarmDefinition &definition, qint64 nowMs,
                                      Events &events)
{
    const bool wasEnabled = m_definition.enabled;
    const bool kindChanged = definition.kind != m_definition.kind;
    m_definition = definition;
    if (kindChanged) {
        // Another condition: what was pending or confirmed of the old one means nothing now.
        m_pendingSinceMs = -1;
    }
    if (wasEnabled && !definition.enabled) {
        m_pendingSinceMs = -1;
        enter(AlarmState::OutOfService, nowMs);
        events.push_back(AlarmEventType::OutOfService);
    } else if (!wasEnabled && definition.enabled) {
        enter(AlarmState::Normal, nowMs);
        events.push_back(AlarmEventType::InService);
        if (m_condition)
            raise(nowMs, events);
    }
}

bool AlarmStateMachine::rawCondition(double value) const
{
    const double limit = m_definition.limit;
    // The deadband holds a confirmed condition until the value is past the limit by it.
    const double band = m_condition ? m_definition.deadband : 0.0;
    switch (m_definition.kind) {
    case AlarmKind::HighHigh:
    case AlarmKind::High: return value >= limit - band;
    case AlarmKind::Low:
    case AlarmKind::LowLow: return value <= limit + band;
    case AlarmKind::On: return value != 0;
    case AlarmKind::Off: return value == 0;
    case AlarmKind::Quality: break;
    }
    return false;
}

void AlarmStateMachine::valueRead(double value, qint64 nowMs, Events &events)
{
    if (m_definition.kind == AlarmKind::Quality)
        return;
    conditionSeen(rawCondition(value), nowMs, events);
}

void AlarmStateMachine::qualitySeen(bool bad, qint64 nowMs, Events &events)
{
    if (m_definition.kind != AlarmKind::Quality)
        return;
    conditionSeen(bad, nowMs, events);
}

void AlarmStateMachine::tick(qint64 nowMs, Events &events)
{
    if (m_state == AlarmState::Shelved && nowMs >= m_shelvedUntilMs)
        unshelve(nowMs, events);
    // A quality condition holds while nothing new is read: time alone confirms it. A limit or
    // bit condition is confirmed only by a value read after its delay.
    if (m_definition.kind == AlarmKind::Quality)
        conditionSeen(m_lastRaw, nowMs, events);
}

void AlarmStateMachine::conditionSeen(bool raw, qint64 nowMs, Events &events)
{
    m_lastRaw = raw;
    if (raw == m_condition) {
        m_pendingSinceMs = -1;
        return;
    }
    if (m_pendingSinceMs < 0)
        m_pendingSinceMs = nowMs;
    const int delay = raw ? m_definition.onDelayMs : m_definition.offDelayMs;
    if (nowMs - m_pendingSinceMs >= delay) {
        m_pendingSinceMs = -1;
        confirm(raw, nowMs, events);
    }
}

void AlarmStateMachine::confirm(bool active, qint64 nowMs, Events &events)
{
    m_condition = active;
    switch (m_state) {
    case AlarmState::Shelved:
    case AlarmState::OutOfService:
        // Followed, not annunciated: unshelving or enabling shows the condition as it is then.
        return;
    case AlarmState::Normal:
        if (active)
            raise(nowMs, events);
        return;
    case AlarmState::ActiveUnacked:
        if (!active) {
            enter(AlarmState::ReturnedUnacked, nowMs);
            events.push_back(AlarmEventType::Returned);
        }
        return;
    case AlarmState::ActiveAcked:
        if (!active) {
            enter(AlarmState::Normal, nowMs);
            events.push_back(AlarmEventType::Returned);
        }
        return;
    case AlarmState::ReturnedUnacked:
        if (active)
            raise(nowMs, events);
        return;
    }
}

void AlarmStateMachine::raise(qint64 nowMs, Events &events)
{
    enter(AlarmState::ActiveUnacked, nowMs);
    m_raisedMs = nowMs;
    m_raises.push_back(nowMs);
    while (m_raises.size() > static_cast<std::size_t>(Alarms::ChatterCount))
        m_raises.pop_front();
    events.push_back(AlarmEventType::Raised);
}

void AlarmStateMachine::enter(AlarmState state, qint64 nowMs)
{
    m_state = state;
    m_sinceMs = nowMs;
}

AlarmStateMachine::Refusal AlarmStateMachine::acknowledge(qint64 nowMs, Events &events)
{
    if (m_state == AlarmState::ActiveUnacked)
        enter(AlarmState::ActiveAcked, nowMs);
    else if (m_state == AlarmState::ReturnedUnacked)
        enter(AlarmState::Normal, nowMs);
    else if (m_state == AlarmState::OutOfService)
        return Refusal::OutOfService;
    else
        return Refusal::NothingToAck;
    events.push_back(AlarmEventType::Acknowledged);
    return Refusal::None;
}

AlarmStateMachine::Refusal AlarmStateMachine::shelve(qint64 untilMs, qint64 nowMs, Events &events)
{
    if (m_state == AlarmState::OutOfService)
        return Refusal::OutOfService;
    if (untilMs <= nowMs)
        return Refusal::ShelveExpired;
    // Shelving again moves the expiry (and is journaled again).
    if (m_state != AlarmState::Shelved)
        enter(AlarmState::Shelved, nowMs);
    m_shelvedUntilMs = untilMs;
    events.push_back(AlarmEventType::Shelved);
    return Refusal::None;
}

AlarmStateMachine::Refusal AlarmStateMachine::unshelve(qint64 nowMs, Events &events)
{
    if (m_state != AlarmState::Shelved)
        return Refusal::NotShelved;
    m_shelvedUntilMs = 0;
    enter(AlarmState::Normal, nowMs);
    events.push_back(AlarmEventType::Unshelved);
    // A condition still present is annunciated as new: the operator has not seen it.
    if (m_condition)
        raise(nowMs, events);
    return Refusal::None;
}

void AlarmStateMachine::restore(const AlarmRecord &record)
{
    m_state = record.state;
    if (!m_definition.enabled)
        m_state = AlarmState::OutOfService;
    else if (m_state == AlarmState::OutOfService)
        m_state = AlarmState::Normal; // enabled since: in service again
    m_condition = record.conditionActive;
    m_lastRaw = record.conditionActive;
    m_pendingSinceMs = -1;
    m_sinceMs = record.sinceMs;
    m_raisedMs = record.raisedMs;
    m_shelvedUntilMs = m_state == AlarmState::Shelved ? record.shelvedUntilMs : 0;
}

AlarmRecord AlarmStateMachine::record() const
{
    AlarmRecord r;
    r.state = m_state;
    r.sinceMs = m_sinceMs;
    r.raisedMs = m_raisedMs;
    r.shelvedUntilMs = m_shelvedUntilMs;
    r.conditionActive = m_condition;
    return r;
}

bool AlarmStateMachine::chattering(qint64 nowMs) const
{
    if (m_raises.size() < static_cast<std::size_t>(Alarms::ChatterCount))
        return false;
    return nowMs - m_raises.front() <= Alarms::ChatterWindowMs;
}

} // namespace Fatek
