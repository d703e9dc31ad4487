#include "alarmengine.h"

// The alarms of one plant connection: its values evaluated, its events reported.

#include "alarmmessages.h"

#include "core/plant/plantconnection.h"
#include "core/watch/osuser.h"
#include "core/watch/valueformat.h"

#include <QDateTime>

namespace Fatek {

namespace Alarms {
QString currentUser()
{
    const QString user = OsUser::name();
    return user.isEmpty() ? QStringLiteral("unknown") : user;
}
} // namespace Alarms

AlarmEngine::AlarmEngine(const QString &connection, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
    , m_clock([] { return QDateTime::currentMSecsSinceEpoch(); })
{
    m_timer.setInterval(250);
    connect(&m_timer, &QTimer::timeout, this, &AlarmEngine::tick);
}

AlarmEngine::~AlarmEngine()
{
    if (m_plant)
        m_plant->unsubscribe(this);
}

void AlarmEngine::setClock(Clock clock)
{
    m_clock = std::move(clock);
}

void AlarmEngine::setItems(const QList<WatchedItem> &items)
{
    const qint64 now = m_clock();
    std::vector<Item> newItems;
    std::vector<Alarm> newAlarms;
    QHash<QString, int> newIndex;
    // Events of definitions changed (enabled, disabled), reported once the new list is in place.
    std::vector<std::pair<int, AlarmStateMachine::Events>> changed;
    for (const WatchedItem &watched : items) {
        if (watched.spec.alarms.isEmpty())
            continue;
        Item item;
        item.watched = watched;
        item.width = ValueFormat::valueWidth(watched.spec.address, watched.spec.format);
        const int itemIndex = static_cast<int>(newItems.size());
        for (const AlarmDefinition &definition : watched.spec.alarms) {
            const QString id = Alarms::alarmId(watched.spec, definition.kind);
            if (newIndex.contains(id))
                continue; // the same item and kind in another table: the first one counts
            Alarm alarm{id,
                        itemIndex,
                        AlarmStateMachine(definition),
                        Alarms::messageOf(watched.spec, definition),
                        {},
                        {}};
            if (const int old = indexOf(id); old >= 0) {
                // The alarm stays: its state too, with the new definition.
                Alarm &kept = m_alarms[static_cast<std::size_t>(old)];
                alarm.machine = kept.machine;
                alarm.lastUser = kept.lastUser;
                alarm.lastComment = kept.lastComment;
                AlarmStateMachine::Events events;
                alarm.machine.setDefinition(definition, now, events);
                if (!events.empty())
                    changed.emplace_back(static_cast<int>(newAlarms.size()), std::move(events));
            }
            if (definition.kind != AlarmKind::Quality)
                item.hasNumberAlarm = true;
            newIndex.insert(id, static_cast<int>(newAlarms.size()));
            item.alarms.push_back(static_cast<int>(newAlarms.size()));
            newAlarms.push_back(std::move(alarm));
        }
        if (!item.alarms.empty())
            newItems.push_back(std::move(item));
    }
    // Keys in one run: a value finds its item by key - first, without a look-up.
    m_firstKey = newItems.empty() ? 0 : WatchedItem::newKeys(newItems.size());
    for (std::size_t i = 0; i < newItems.size(); ++i)
        newItems[i].watched.key = m_firstKey + i;
    m_items = std::move(newItems);
    m_alarms = std::move(newAlarms);
    m_alarmIndex = std::move(newIndex);
    for (const auto &[index, events] : changed)
        emitEvents(m_alarms[static_cast<std::size_t>(index)], events, now);
    subscribe();
    if (m_alarms.empty())
        m_timer.stop();
    else if (!m_timer.isActive())
        m_timer.start();
    Q_EMIT alarmsReset();
}

void AlarmEngine::attach(PlantConnection *plant)
{
    if (m_plant == plant)
        return;
    if (m_plant)
        m_plant->unsubscribe(this);
    m_plant = plant;
    subscribe();
}

void AlarmEngine::subscribe()
{
    if (!m_plant)
        return;
    QList<WatchedItem> watched;
    watched.reserve(static_cast<qsizetype>(m_items.size()));
    for (const Item &item : m_items)
        watched.append(item.watched);
    if (watched.isEmpty())
        m_plant->unsubscribe(this);
    else
        m_plant->subscribe(this, watched);
}

void AlarmEngine::holdForRestore()
{
    m_holding = true;
}

void AlarmEngine::restore(const QList<AlarmRecord> &records)
{
    for (const AlarmRecord &record : records) {
        if (record.connection != m_connection)
            continue;
        const int index = indexOf(record.alarmId);
        if (index >= 0)
            m_alarms[static_cast<std::size_t>(index)].machine.restore(record);
    }
    if (!m_holding)
        return;
    m_holding = false;
    const qint64 now = m_clock();
    for (Item &item : m_items)
        evaluate(item, now);
    Q_EMIT alarmsReset();
}

void AlarmEngine::plantValues(const QList<WatchItemValue> &values)
{
    const qint64 now = m_clock();
    for (const WatchItemValue &value : values) {
        const std::uint64_t index = value.key - m_firstKey;
        if (value.key < m_firstKey || index >= m_items.size())
            continue; // of an item list replaced since
        Item &item = m_items[index];
        item.bad = value.quality == ValueQuality::Stale || value.quality == ValueQuality::Error;
        // Only a value read now decides a limit or a bit (a late one is an old reading).
        const bool fresh = value.quality == ValueQuality::Good && value.hasValue;
        if (fresh) {
            item.raw = value.raw;
            item.hasValue = true;
        }
        if (m_holding)
            continue;
        if (fresh || !item.hasNumberAlarm || item.bad)
            evaluate(item, now);
    }
}

void AlarmEngine::evaluate(Item &item, qint64 nowMs)
{
    std::optional<double> number;
    if (item.hasValue && item.hasNumberAlarm && !item.bad) {
        const WatchItemSpec &spec = item.watched.spec;
        number = ValueFormat::number(item.raw, item.width, spec.format, spec.swapWords);
    }
    for (const int a : item.alarms) {
        Alarm &alarm = m_alarms[static_cast<std::size_t>(a)];
        m_events.clear();
        if (alarm.machine.definition().kind == AlarmKind::Quality)
            alarm.machine.qualitySeen(item.bad, nowMs, m_events);
        else if (number)
            alarm.machine.valueRead(*number, nowMs, m_events);
        if (!m_events.empty())
            emitEvents(alarm, m_events, nowMs);
    }
}

void AlarmEngine::plantLinkState(LinkState state, const Message &reason)
{
    Q_UNUSED(reason);
    if (state == LinkState::Connected)
        return;
    // No values come while the link is down: every item is stale from now.
    const qint64 now = m_clock();
    for (Item &item : m_items) {
        item.bad = true;
        if (!m_holding)
            evaluate(item, now);
    }
}

void AlarmEngine::tick()
{
    if (m_holding)
        return;
    const qint64 now = m_clock();
    for (Alarm &alarm : m_alarms) {
        m_events.clear();
        alarm.machine.tick(now, m_events);
        if (!m_events.empty())
            emitEvents(alarm, m_events, now);
    }
}

Status AlarmEngine::refused(const QString &alarmId, AlarmStateMachine::Refusal refusal) const
{
    const std::string id = alarmId.toStdString();
    switch (refusal) {
    case AlarmStateMachine::Refusal::None: return Ok{};
    case AlarmStateMachine::Refusal::NothingToAck:
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::AlarmNothingToAck>(id));
    case AlarmStateMachine::Refusal::NotShelved:
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::AlarmNotShelved>(id));
    case AlarmStateMachine::Refusal::ShelveExpired:
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::AlarmShelveExpired>(id));
    case AlarmStateMachine::Refusal::OutOfService:
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::AlarmOutOfService>(id));
    }
    return Ok{};
}

Status AlarmEngine::operate(const QString &alarmId, const QString &user, const QString &comment,
                            const Action &action)
{
    const int index = indexOf(alarmId);
    if (index < 0)
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::AlarmUnknown>(alarmId.toStdString()));
    Alarm &alarm = m_alarms[static_cast<std::size_t>(index)];
    const qint64 now = m_clock();
    m_events.clear();
    const auto refusal = action(alarm.machine, now, m_events);
    if (refusal != AlarmStateMachine::Refusal::None)
        return refused(alarmId, refusal);
    emitEvents(alarm, m_events, now, user.isEmpty() ? Alarms::currentUser() : user, comment);
    return Ok{};
}

Status AlarmEngine::acknowledge(const QString &alarmId, const QString &user, const QString &comment)
{
    return operate(alarmId, user, comment,
                   [](AlarmStateMachine &m, qint64 now, AlarmStateMachine::Events &events) {
                       return m.acknowledge(now, events);
                   });
}

Status AlarmEngine::shelve(const QString &alarmId, qint64 untilMs, const QString &user,
                           const QString &comment)
{
    return operate(alarmId, user, comment,
                   [untilMs](AlarmStateMachine &m, qint64 now, AlarmStateMachine::Events &events) {
                       return m.shelve(untilMs, now, events);
                   });
}

Status AlarmEngine::unshelve(const QString &alarmId, const QString &user)
{
    return operate(alarmId, user, {},
                   [](AlarmStateMachine &m, qint64 now, AlarmStateMachine::Events &events) {
                       return m.unshelve(now, events);
                   });
}

void AlarmEngine::emitEvents(Alarm &alarm, const AlarmStateMachine::Events &events, qint64 nowMs,
                             const QString &user, const QString &comment)
{
    const Item &item = m_items[static_cast<std::size_t>(alarm.item)];
    const AlarmDefinition &definition = alarm.machine.definition();
    AlarmRecord record = alarm.machine.record();
    record.connection = m_connection;
    record.alarmId = alarm.id;
    const bool byOperator = !user.isEmpty();
    if (byOperator) {
        alarm.lastUser = user;
        alarm.lastComment = comment;
    }
    for (const AlarmEventType type : events) {
        AlarmEvent event;
        event.timeMs = nowMs;
        event.utcOffsetS = QDateTime::fromMSecsSinceEpoch(nowMs).offsetFromUtc();
        event.connection = m_connection;
        event.alarmId = alarm.id;
        event.type = type;
        event.state = alarm.machine.state();
        event.kind = definition.kind;
        event.priority = definition.priority;
        event.message = alarm.message;
        event.group = definition.group;
        event.value = valueText(item);
        // An event that the operator's action caused carries who and why (an unshelve's raise
        // is the condition's, not the operator's).
        if (byOperator && type != AlarmEventType::Raised) {
            event.user = user;
            event.comment = comment;
        }
        event.shelvedUntilMs = alarm.machine.shelvedUntilMs();
        Q_EMIT alarmEvent(event, record);
    }
}

QString AlarmEngine::valueText(const Item &item) const
{
    if (!item.hasValue)
        return {};
    const WatchItemSpec &spec = item.watched.spec;
    return ValueFormat::format(item.raw, item.width, spec.format, spec.swapWords);
}

int AlarmEngine::indexOf(const QString &alarmId) const
{
    return m_alarmIndex.value(alarmId, -1);
}

AlarmStatus AlarmEngine::statusOf(const Alarm &alarm, qint64 nowMs) const
{
    const Item &item = m_items[static_cast<std::size_t>(alarm.item)];
    const WatchItemSpec &spec = item.watched.spec;
    AlarmStatus status;
    status.connection = m_connection;
    status.alarmId = alarm.id;
    status.definition = alarm.machine.definition();
    status.address = QString::fromStdString(spec.address.toString());
    status.itemName = spec.name.isEmpty() ? status.address : spec.name;
    status.station = spec.station;
    status.message = alarm.message;
    status.state = alarm.machine.state();
    status.conditionActive = alarm.machine.conditionActive();
    status.chattering = alarm.machine.chattering(nowMs);
    status.sinceMs = alarm.machine.sinceMs();
    status.raisedMs = alarm.machine.raisedMs();
    status.shelvedUntilMs = alarm.machine.shelvedUntilMs();
    status.value = valueText(item);
    status.lastUser = alarm.lastUser;
    status.lastComment = alarm.lastComment;
    return status;
}

QList<AlarmStatus> AlarmEngine::alarms() const
{
    const qint64 now = m_clock();
    QList<AlarmStatus> list;
    list.reserve(static_cast<qsizetype>(m_alarms.size()));
    for (const Alarm &alarm : m_alarms)
        list.append(statusOf(alarm, now));
    return list;
}

std::optional<AlarmStatus> AlarmEngine::status(const QString &alarmId) const
{
    const int index = indexOf(alarmId);
    if (index < 0)
        return std::nullopt;
    return statusOf(m_alarms[static_cast<std::size_t>(index)], m_clock());
}

int AlarmEngine::unackedCount() const
{
    int count = 0;
    for (const Alarm &alarm : m_alarms)
        count += Alarms::isUnacked(alarm.machine.state()) ? 1 : 0;
    return count;
}

} // namespace Fatek
