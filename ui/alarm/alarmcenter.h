#pragma once

#include "core/alarm/alarmtypes.h"
#include "core/protocol/result.h"
#include "core/watch/itemassembler.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace Fatek {

class AlarmEngine;
class AlarmJournalWriter;
class Connection;
class ConnectionManager;
class WatchTableWidget;

// The studio's alarms: one AlarmEngine per open connection, fed with the items that have alarm
// definitions in every watch table bound to that connection (followed as rows, definitions and
// intervals are edited and as tables change connection or close), and one journal for the studio
// (AlarmJournalWriter, its own thread). Operator actions go to the engine of the alarm's
// connection. Nothing here draws: the summary, the status bar and the table's dialog use it.
class AlarmCenter : public QObject
{
    Q_OBJECT

public:
    // `journalPath` empty: defaultJournalPath().
    AlarmCenter(ConnectionManager *manager, const QString &journalPath = {},
                QObject *parent = nullptr);
    ~AlarmCenter() override;

    // $FATEK_ALARM_JOURNAL when set (tests point it into a temporary folder), else
    // QStandardPaths::AppDataLocation + "/alarms.sqlite".
    static QString defaultJournalPath();
    QString journalPath() const { return m_journalPath; }
    // Opened when first needed (the first alarm definitions, or the journal viewer): a studio
    // without alarms makes no file.
    AlarmJournalWriter *journal();

    // The table's alarm-bearing rows count from now on, on the connection it polls through.
    void addTable(WatchTableWidget *table);

    QList<AlarmEngine *> engines() const;
    AlarmEngine *engine(const QString &connection) const;
    QStringList connectionNames() const;
    // Unacknowledged alarms of every connection (active or returned).
    int unackedCount() const;

    // Operator actions on one alarm; the refusal says why. The journal names the OS user.
    Status acknowledge(const QString &connection, const QString &alarmId, const QString &comment);
    Status shelve(const QString &connection, const QString &alarmId, qint64 untilMs,
                  const QString &comment);
    Status unshelve(const QString &connection, const QString &alarmId);

    // Feeds the engines now instead of on the next turn of the event loop (tests).
    void updateNow();

Q_SIGNALS:
    void alarmEvent(const Fatek::AlarmEvent &event, const Fatek::AlarmRecord &record);
    // The alarms of `connection` were replaced or went with it: list them again.
    void alarmsReset(const QString &connection);
    void unackedCountChanged(int count);
    // The journal could not be written or read, in words.
    void journalFailed(const QString &text);

private:
    struct Engine
    {
        QPointer<Connection> connection;
        AlarmEngine *engine = nullptr;
        // What it was last given, without the keys (which are made afresh per call).
        QList<WatchedItem> items;
        bool journaled = false;
    };

    void onConnectionAdded(Connection *connection);
    void onConnectionRemoved(Connection *connection);
    void scheduleUpdate();
    void update();
    // The count is summed at most once per turn of the event loop (a burst of events).
    void countChanged() { m_countTimer.start(); }
    void recount();
    Engine *entryOf(const QString &connection);

    ConnectionManager *m_manager;
    QString m_journalPath;
    AlarmJournalWriter *m_journal = nullptr;
    std::vector<Engine> m_engines;
    QList<QPointer<WatchTableWidget>> m_tables;
    // Edits come in bursts (a pasted list, a loaded file): the engines are fed once per burst.
    QTimer m_updateTimer;
    QTimer m_countTimer;
    int m_lastCount = 0;
};

} // namespace Fatek
