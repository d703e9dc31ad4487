#pragma once

#include "core/watch/itemassembler.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace Fatek {

class Connection;
class ConnectionManager;
class HistoryRecorder;
class HistoryWriter;
class WatchTableModel;
class WatchTableWidget;
struct WatchItemSpec;

// The studio's history (issue 51): one HistoryRecorder per open connection, fed with the rows
// that have a history setting in every watch table bound to that connection (followed as rows,
// settings and intervals are edited and as tables change connection or close), and one store for
// the studio (HistoryWriter, its own thread). The store is opened when first needed (the first
// recorded row, or the trend reading a store that exists): a studio that records nothing makes no
// file. Nothing here draws: the tables' actions, the status bar and the trend use it.
class HistoryCenter : public QObject
{
    Q_OBJECT

public:
    // What the studio keeps: 30 days (docs/history.md says so).
    static constexpr int RetentionDays = 30;

    // `location` empty: defaultLocation().
    explicit HistoryCenter(ConnectionManager *manager, const QString &location = {},
                           QObject *parent = nullptr);
    ~HistoryCenter() override;

    // $FATEK_HISTORY when set (tests point it into a temporary folder; a postgresql:// URL
    // shares a gateway's store), else QStandardPaths::AppDataLocation + "/history.sqlite".
    static QString defaultLocation();
    QString location() const { return m_location; }
    // The store's writer, opened now if it was not.
    HistoryWriter *writer();
    // For reading: the writer when it is open or when the store exists (a database, or a file
    // that is there); nullptr when nothing was ever recorded, and no file is made for asking.
    HistoryWriter *readableWriter();
    bool isOpen() const { return m_writer != nullptr; }

    // The table's recorded rows count from now on, on the connection it polls through.
    void addTable(WatchTableWidget *table);

    // The recorder of a connection (nullptr until it has a recorded row).
    HistoryRecorder *recorder(const QString &connection) const;
    // "Line 1/1-R100": the series a row of `model` is recorded as (its table's connection and
    // the row's station and address); empty when the table polls through no connection.
    QString seriesKey(const WatchTableModel *model, const WatchItemSpec &spec) const;
    // "1-R100": the item of a series.
    static QString itemKey(const WatchItemSpec &spec);

    // Feeds the recorders now instead of on the next turn of the event loop (tests).
    void updateNow();

Q_SIGNALS:
    // The store cannot be opened or written, or writes again, in words (the status bar).
    void statusMessage(const QString &text);

private:
    struct Recorder
    {
        QPointer<Connection> connection;
        HistoryRecorder *recorder = nullptr; // made with the first recorded row
        // What it was last given, without the keys (which are made afresh per call).
        QList<WatchedItem> items;
    };

    void onConnectionAdded(Connection *connection);
    void onConnectionRemoved(Connection *connection);
    void scheduleUpdate() { m_updateTimer.start(); }
    void update();

    ConnectionManager *m_manager;
    QString m_location;
    HistoryWriter *m_writer = nullptr;
    std::vector<Recorder> m_recorders;
    QList<QPointer<WatchTableWidget>> m_tables;
    // Edits come in bursts (a pasted list, a loaded file): the recorders are fed once per burst.
    QTimer m_updateTimer;
};

} // namespace Fatek
