#pragma once

#include "core/alarm/alarmtypes.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QList>
#include <QTimer>

#include <vector>

namespace Fatek {

// The alarms the summary lists (every state but normal) of every connection: one row per alarm.
// Changes are queued (updateAlarm) and applied once per turn of the event loop: rows that stay
// are reported with one dataChanged per run of consecutive rows, rows that go are removed and new
// ones appended in one step each, never a reset. Unacknowledged rows flash: a timer turns their
// FlashRole (and background) on and off, reporting only those rows, in runs.
class AlarmSummaryModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        StateColumn,
        PriorityColumn,
        TimeColumn,
        ConnectionColumn,
        ItemColumn,
        MessageColumn,
        ValueColumn,
        GroupColumn,
        ColumnCount
    };
    enum Role {
        SortRole = Qt::UserRole + 1, // numbers for state, priority, time; else the text
        StateRole,                   // AlarmState as int
        PriorityRole,                // AlarmPriority as int
        GroupRole,
        FlashRole, // true while an unacknowledged row shows its flash colour
        ConnectionRole,
        AlarmIdRole,
    };
    static constexpr int flashMs = 500;

    explicit AlarmSummaryModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // The alarm as it is now: listed, updated or removed (normal) with the next batch.
    void updateAlarm(const AlarmStatus &status);
    // Every alarm of `connection` as it is now (its engine was reset); those not among them go.
    void setAlarms(const QString &connection, const QList<AlarmStatus> &alarms);
    // Applies what is queued now (tests; the event loop does it otherwise).
    void flush();

    const AlarmStatus &status(int row) const { return m_rows.at(row); }
    int rowOf(const QString &connection, const QString &alarmId) const;
    bool isFlashOn() const { return m_flashOn; }

private:
    static QString keyOf(const QString &connection, const QString &alarmId);
    void queue(const AlarmStatus &status);
    void flash();
    void emitRuns(std::vector<int> rows, int firstColumn, int lastColumn, const QList<int> &roles);
    void rebuildIndex();

    QList<AlarmStatus> m_rows;
    QHash<QString, int> m_rowOf;
    // The alarms' newest statuses, in the order they first came (new rows are appended so),
    // applied by flush(); key -> place in m_pending.
    QList<AlarmStatus> m_pending;
    QHash<QString, int> m_pendingIndex;
    QTimer m_flushTimer;
    QTimer m_flashTimer;
    bool m_flashOn = false;
};

} // namespace Fatek
