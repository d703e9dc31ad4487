#pragma once

#include "core/watch/itemassembler.h"
#include "core/watch/watchlist.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QObject>
#include <QTimer>

#include <functional>
#include <optional>
#include <vector>

namespace Fatek {

// The values of a watch table's rows, apart from what the rows watch (WatchTableModel's items):
// each row's latest value, quality and time as the link reports them under the row's item key,
// their ages, the flash of a changed value, the forced flags and the stations that answer
// nothing. Values arrive in batches (applyValues, or queueValues while polling) and are applied
// in time slices; only the cells that really change are reported (cellsChanged), for the model
// to coalesce into dataChanged.
class WatchValueState : public QObject
{
    Q_OBJECT

public:
    // How long a changed value stays highlighted.
    static constexpr int flashMs = 700;
    // How often the value ages ("good, 0.4 s") are repainted.
    static constexpr int ageRefreshMs = 250;
    static constexpr int frameMs = 16;
    static constexpr int sliceBudgetMs = 3;

    // The cells of a row that its value changes.
    enum class Cell { Name, Value, Quality, Updated };

    struct RowValue
    {
        // What the link knows the item by; a new one when the item spans other elements, so
        // that values still arriving for the old ones match nothing.
        quint64 itemKey = 0;
        std::uint64_t raw = 0;
        ValueQuality quality = ValueQuality::Stale;
        Message error;         // translated when shown
        QDateTime updated;     // when its value was last read
        QString peerName;      // the far end's name for the item, shown when it has none
        bool received = false; // every element has been read once
        // Sequence number of the batch that set it: a newer batch wins, so applying queued
        // batches newest first ends as applying them in order would.
        quint64 batch = 0;
        QString writeOutcome;
        qint64 flashUntil = 0;
        std::optional<bool> forced;
        quint64 slice = 0;        // last apply slice that touched the row
        std::uint64_t before = 0; // the row's value when that slice first touched it
        bool hadValue = false;    // and whether it had one
    };

    // What row `row` watches (the model's item): its station and address for the forced flags
    // and silent stations, its own name for whether the far end's one shows.
    using SpecOf = std::function<const WatchItemSpec &(int row)>;
    explicit WatchValueState(SpecOf specOf, QObject *parent = nullptr);

    // The rows follow the model's: inserted without values, removed, reordered (row i becomes
    // the row that was order[i]).
    void insertRows(int row, int count);
    void removeRows(int row, int count);
    void reorder(const QList<int> &order);
    // No rows; values queued for the old ones have nowhere to go.
    void clear();
    // The row spans other elements now: a new item key, no value yet.
    void resetRow(int row);

    const RowValue &at(int row) const { return m_rows.at(row); }
    // Milliseconds since the row's value was last read (-1: never).
    qint64 ageMs(int row) const;
    bool isFlashing(int row) const;
    bool isSilent(quint8 station) const { return m_silentStations.contains(station); }

    // See WatchTableModel: the age rows, the batches and their slices, stale marks, write
    // outcomes, forced flags and silent stations.
    void setAgeRows(std::function<std::vector<int>()> rowsOnScreen);
    void applyValues(const QList<WatchItemValue> &values);
    void queueValues(const QList<WatchItemValue> &values);
    bool hasQueuedValues() const { return !m_queue.empty(); }
    void flushValues();
    void markAllStale(const Message &reason);
    void setWriteOutcome(int row, const QString &text);
    void setForcedFlags(quint8 station, const Address &start,
                        const std::vector<std::uint32_t> &flags);
    void clearForced();
    void setSilentStations(const QList<quint8> &stations);

Q_SIGNALS:
    // The `cell` of `rows` changed, in the given roles (none: all of them).
    void cellsChanged(const std::vector<int> &rows, Fatek::WatchValueState::Cell cell,
                      const QList<int> &roles);

private:
    struct Batch
    {
        QList<WatchItemValue> values;
        quint64 sequence = 0;
        qsizetype next = 0; // values before this one are applied or skipped
    };

    static void resetValue(RowValue &row);
    void rebuildIndex();
    void refreshAges();
    void scheduleSlice();
    void applySlice(qint64 budgetNs);
    void applyOne(const WatchItemValue &v, quint64 batch);
    void finishSlice();
    void expireFlashes();
    void report(std::vector<int> rows, Cell cell, const QList<int> &roles = {});

    SpecOf m_specOf;
    QList<RowValue> m_rows;
    QHash<quint64, int> m_index; // item key -> row
    QElapsedTimer m_clock;
    QTimer m_flashTimer;
    QTimer m_ageTimer;
    std::function<std::vector<int>()> m_ageRows;
    QList<quint8> m_silentStations;

    // Queued batches, oldest first; applied newest first (older values of an element that a
    // newer batch already set are skipped).
    std::vector<Batch> m_queue;
    quint64 m_batchSequence = 0;
    QTimer m_sliceTimer;
    QElapsedTimer m_roundStart; // start of the last round of slices
    bool m_inRound = false;     // slices follow each other until the queue is empty
    // The slice under way: its number and the rows whose cells it changed.
    quint64 m_slice = 0;
    std::vector<int> m_touchedRows;
    std::vector<int> m_valueRows;
    std::vector<int> m_qualityRows;
    std::vector<int> m_updatedRows;
    std::vector<int> m_nameRows;
};

} // namespace Fatek
