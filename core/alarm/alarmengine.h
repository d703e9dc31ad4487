#pragma once

#include "alarmstatemachine.h"
#include "alarmtypes.h"

#include "core/plant/plantconnection.h"
#include "core/watch/itemassembler.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <vector>

namespace Fatek {

// The alarms of one plant connection: a consumer of the items that have alarm definitions, which
// evaluates each value as it arrives (one state machine per alarm) and reports every event. The
// one place where alarms are raised: the studio, the gateway and fatek-cli each run one per
// connection from the same watch list definitions. Lives in the plant connection's thread.
class AlarmEngine : public QObject, public PlantConsumer
{
    Q_OBJECT

public:
    using Clock = std::function<qint64()>; // ms since the epoch, UTC

    // `connection` names the connection in events, topics and the journal.
    explicit AlarmEngine(const QString &connection, QObject *parent = nullptr);
    ~AlarmEngine() override;

    QString connection() const { return m_connection; }
    // Tests drive the engine on a fake clock (and call tick() themselves).
    void setClock(Clock clock);

    // The items to watch (each with its poll interval; keys are the engine's own). Items without
    // alarms are skipped; an alarm id met twice (the same item and kind in two tables) is kept
    // once, the first. An alarm that stays keeps its state; a changed definition applies at
    // once (disabled: out of service); an alarm that goes is forgotten.
    void setItems(const QList<WatchedItem> &items);
    // Subscribes to `plant` (nullptr: detaches); values then come from its link.
    void attach(PlantConnection *plant);
    PlantConnection *plant() const { return m_plant; }

    // Operator actions, by alarm id. `user` empty: the OS user (Alarms::currentUser()).
    Status acknowledge(const QString &alarmId, const QString &user, const QString &comment);
    Status shelve(const QString &alarmId, qint64 untilMs, const QString &user,
                  const QString &comment);
    Status unshelve(const QString &alarmId, const QString &user);

    // Values are kept but not evaluated until restore(): the journal's states come first, so an
    // alarm active before a restart is not raised a second time (AlarmJournalWriter::attach).
    void holdForRestore();
    // Brings back the states the journal kept (records of other connections or unknown ids are
    // skipped); causes no event. Ends a hold: the values kept meanwhile are evaluated then.
    void restore(const QList<AlarmRecord> &records);

    int alarmCount() const { return static_cast<int>(m_alarms.size()); }
    QList<AlarmStatus> alarms() const;
    std::optional<AlarmStatus> status(const QString &alarmId) const;
    int unackedCount() const;

    // Shelve expiries and quality delays (the engine's timer calls it every 250 ms).
    void tick();

    void plantValues(const QList<WatchItemValue> &values) override;
    void plantLinkState(LinkState state, const Message &reason) override;

Q_SIGNALS:
    // Every event, with the alarm's record after it (what the journal keeps).
    void alarmEvent(const Fatek::AlarmEvent &event, const Fatek::AlarmRecord &record);
    // The alarms were replaced (setItems): a summary lists them again.
    void alarmsReset();

private:
    struct Item
    {
        WatchedItem watched;
        int width = 16;
        bool hasNumberAlarm = false; // limit or bit kinds
        std::vector<int> alarms;     // indices into m_alarms
        std::uint64_t raw = 0;
        bool hasValue = false;
        bool bad = true; // stale or in error
    };
    struct Alarm
    {
        QString id;
        int item = 0;
        AlarmStateMachine machine;
        QString message;
        QString lastUser;
        QString lastComment;
    };

    int indexOf(const QString &alarmId) const;
    AlarmStatus statusOf(const Alarm &alarm, qint64 nowMs) const;
    void emitEvents(Alarm &alarm, const AlarmStateMachine::Events &events, qint64 nowMs,
                    const QString &user = {}, const QString &comment = {});
    QString valueText(const Item &item) const;
    // Evaluates the alarms of one item with its last value and quality.
    void evaluate(Item &item, qint64 nowMs);
    Status refused(const QString &alarmId, AlarmStateMachine::Refusal refusal) const;
    // An operator action on one alarm: found, applied at now, its events reported with who.
    using Action = std::function<AlarmStateMachine::Refusal(AlarmStateMachine &, qint64,
                                                            AlarmStateMachine::Events &)>;
    Status operate(const QString &alarmId, const QString &user, const QString &comment,
                   const Action &action);
    void subscribe();

    QString m_connection;
    Clock m_clock;
    QPointer<PlantConnection> m_plant;
    std::vector<Item> m_items;
    std::vector<Alarm> m_alarms;
    QHash<QString, int> m_alarmIndex;
    std::uint64_t m_firstKey = 0;
    bool m_holding = false;
    AlarmStateMachine::Events m_events; // reused per evaluation
    QTimer m_timer;
};

namespace Alarms {
// The operator's name for the journal when none is given: the OS user.
QString currentUser();
} // namespace Alarms

} // namespace Fatek
