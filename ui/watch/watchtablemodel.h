#pragma once

#include "core/watch/itemassembler.h"
#include "core/watch/watchlist.h"
#include "watchtableedits.h"
#include "watchvaluestate.h"

#include <QAbstractTableModel>
#include <QIcon>
#include <QPointer>

#include <functional>
#include <optional>
#include <vector>

namespace Fatek {

class SymbolNames;
class SymbolTable;

// Rows of one watch table: what to watch (WatchItemSpec) plus the latest value, its quality and
// time (WatchValueState). Every item spans one or more elements (a float over R100 is R100+R101);
// ItemValues makes them. The link (PlcLink) reports each row's value as one item value, its
// elements joined (ItemAssembler), under the row's item key. Values arrive in batches (applyValues,
// or queueValues while polling); changed rows are reported with coalesced dataChanged, one per run
// of rows and changed column. Values are formatted in data(), that is only for the rows a view asks
// about (the visible ones). The edits a person makes are steps of WatchTableEdits.
class WatchTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        NameColumn,
        AddressColumn,
        StationColumn,
        ValueColumn,
        FormatColumn,
        QualityColumn,
        UpdatedColumn,
        CommentColumn,
        ColumnCount
    };
    // How long a changed value stays highlighted.
    static constexpr int flashMs = WatchValueState::flashMs;
    // How often the quality column's value ages ("good, 0.4 s") are repainted.
    static constexpr int ageRefreshMs = WatchValueState::ageRefreshMs;
    // What a sorting proxy compares: numbers for addresses, values and times, else the text.
    static constexpr int SortRole = Qt::UserRole + 1;

    explicit WatchTableModel(QObject *parent = nullptr);

    // The rows whose age the refresh repaints; without one, every row. A view gives the rows it
    // shows: behind a sort/filter proxy (Qt 6.4 filters every changed row again, whatever the
    // role) a 10,000-row table would otherwise be filtered four times a second for a repaint of
    // the 30 rows on screen.
    void setAgeRows(std::function<std::vector<int>()> rowsOnScreen)
    {
        m_valueState.setAgeRows(std::move(rowsOnScreen));
    }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    // Value column: text typed in the row's format (or a check state for discretes) is parsed and
    // becomes writeRequested(); the model itself changes only when the PLC reports the new value.
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    bool removeRows(int row, int count, const QModelIndex &parent = {}) override;

    // Edits a person makes to the rows (typed, pasted, dragged, removed, formats) are steps on
    // undoStack(); each of the calls below is one step. Values written to the PLC never are: a
    // write cannot be taken back. setItems (a list loaded) starts a new history.
    QUndoStack *undoStack() { return m_edits.undoStack(); }
    // Rows whose name or comment is empty take those of the window's names (setSymbols).
    void addItems(const QList<WatchItemSpec> &items) { insertItems(rowCount(), items); }
    void insertItems(int row, const QList<WatchItemSpec> &items)
    {
        m_edits.insertItems(row, items);
    }
    void removeItems(QList<int> rows) { m_edits.removeItems(std::move(rows)); }
    // Moves `rows` one place up (delta -1) or down (+1), as a block past their neighbour;
    // false when nothing can move (at the top or bottom already).
    bool moveItems(const QList<int> &rows, int delta) { return m_edits.moveItems(rows, delta); }
    // Moves `rows` to stand, in their order, before the row that is `destination` now
    // (rowCount(): at the end).
    bool moveItemsTo(const QList<int> &rows, int destination)
    {
        return m_edits.moveItemsTo(rows, destination);
    }
    // Replaces row `row`'s item (address, name, comment, station, format), validated as a file's
    // entry is.
    Status editItem(int row, const WatchItemSpec &spec) { return m_edits.editItem(row, spec); }
    // One format for several rows, one step; rows whose element cannot show it keep theirs and
    // the first refusal is returned.
    Status setFormats(const QList<int> &rows, DisplayFormat format)
    {
        return m_edits.setFormats(rows, format);
    }
    // The row's alarm definitions (issue 50), checked as a file's are; one step.
    Status setAlarms(int row, const QList<AlarmDefinition> &alarms)
    {
        return m_edits.setAlarms(row, alarms);
    }
    // How the rows are recorded in the history (issue 51; nothing: not recorded), one step;
    // refused when the setting is out of range.
    Status setHistory(const QList<int> &rows, const std::optional<HistorySetting> &setting)
    {
        return m_edits.setHistory(rows, setting);
    }
    void setItems(const QList<WatchItemSpec> &items);
    // The window's names (the ladder project's, see SymbolNames), not owned; nullptr: none.
    // Rows added from now on get the names their addresses have there when theirs are empty,
    // and the rows follow every change of the names: a name or comment that is empty or was
    // the address's old imported one takes the new one; one a person typed stays.
    void setSymbols(const SymbolNames *symbols);
    QList<WatchItemSpec> items() const;
    WatchItemSpec item(int row) const { return m_rows.at(row).values.item(); }
    // Changes the format (and word order), one step; refused with a message when it does not
    // fit the item.
    Status setFormat(int row, DisplayFormat format, bool swapWords)
    {
        return m_edits.setFormat(row, format, swapWords);
    }
    QList<DisplayFormat> availableFormats(int row) const;

    // Bits of the row's value (1, 16, 32 or 64) and whether a value has arrived.
    int valueWidth(int row) const;
    bool hasValue(int row) const { return m_valueState.at(row).received; }
    std::uint64_t rawValue(int row) const { return m_valueState.at(row).raw; }
    ValueQuality quality(int row) const { return m_valueState.at(row).quality; }
    // Milliseconds since the row's value was last read (-1: never).
    qint64 ageMs(int row) const { return m_valueState.ageMs(row); }
    QString qualityReason(int row) const;
    QString valueText(int row) const;
    // The rows as tab-separated text in the given order, a header line first (address, name,
    // value, format, quality, comment): what a copy of them puts on the clipboard.
    QString rowsText(const QList<int> &rows) const;

    // What the link watches for this table: one item per row, under the row's item key.
    QList<WatchedItem> watchItems(int intervalMs) const;
    // Applies a batch now: every value is in the model when this returns.
    void applyValues(const QList<WatchItemValue> &values) { m_valueState.applyValues(values); }
    // Polling: the batch is kept and applied from the event loop, in slices of at most
    // sliceBudgetMs and at most one round of slices started per frameMs, so that a batch of
    // 10,000 values (or a burst of batches) never holds the UI thread for a frame. Batches queued
    // meanwhile are coalesced: the newest value of each item wins, older ones are skipped,
    // none is lost (an item missing from a newer batch keeps its newest older value).
    void queueValues(const QList<WatchItemValue> &values) { m_valueState.queueValues(values); }
    bool hasQueuedValues() const { return m_valueState.hasQueuedValues(); }
    // Applies everything queued now. markAllStale does so first: a good value queued before must
    // not turn a row fresh after it. Rows may be added or removed meanwhile (values are found by
    // item key when applied; those of removed rows are dropped); setItems drops the queue.
    void flushValues() { m_valueState.flushValues(); }
    static constexpr int frameMs = WatchValueState::frameMs;
    static constexpr int sliceBudgetMs = WatchValueState::sliceBudgetMs;
    // No values are coming (no connection, paused): every row keeps its value, marked stale.
    // The reason is a core message ("link lost: ...") or the UI's own text.
    void markAllStale(const Message &reason) { m_valueState.markAllStale(reason); }
    void markAllStale(const QString &reason) { markAllStale(Message::text(reason.toStdString())); }

    // Stable handle of a row across inserts and removals (for writes that finish later).
    quint64 rowKey(int row) const { return m_rows.at(row).key; }
    int rowOfKey(quint64 key) const;
    void setWriteOutcome(int row, const QString &text) { m_valueState.setWriteOutcome(row, text); }

    // Forcing: whether a discrete row is disabled from the ladder (43 flags); nothing for
    // registers and before the first read.
    std::optional<bool> isForced(int row) const { return m_valueState.at(row).forced; }
    // Flags of `flags.size()` points from `start` on `station`, as 43 answered them.
    void setForcedFlags(quint8 station, const Address &start,
                        const std::vector<std::uint32_t> &flags)
    {
        m_valueState.setForcedFlags(station, start, flags);
    }
    void clearForced() { m_valueState.clearForced(); }

    // Stations that answer nothing at present (every attempt of their last request timed out):
    // their rows say "no answer from station N" instead of "waiting" or "stale".
    void setSilentStations(const QList<quint8> &stations)
    {
        m_valueState.setSilentStations(stations);
    }

Q_SIGNALS:
    void writeRequested(int row, quint64 raw);
    void inputRejected(const QString &message);
    // The set of watched items changed: hand watchItems() to the link again.
    void pollListChanged();
    // The rows (their items, their order) changed: what a saved list holds.
    void itemsEdited();

private:
    friend class WatchRowsCommand;

    struct Row
    {
        ItemValues values; // the item: its elements, their join, its text and parsing
        quint64 key = 0;   // the row's handle (rowKey)

        const WatchItemSpec &spec() const { return values.item(); }
    };

    static quint64 newRowKey();
    // The steps' own changes, without history.
    void applyInsert(int row, const QList<WatchItemSpec> &items);
    void applyRemove(int row, int count);
    void applySpec(int row, const WatchItemSpec &spec);
    // Row i becomes the row that was order[i].
    void applyOrder(const QList<int> &order);
    WatchItemSpec withSymbols(WatchItemSpec spec) const;
    void applySymbols(const SymbolTable &previous);
    void emitRowsChanged(std::vector<int> rows, int firstColumn, int lastColumn,
                         const QList<int> &roles = {});
    void emitCellsChanged(const std::vector<int> &rows, WatchValueState::Cell cell,
                          const QList<int> &roles);

    QList<Row> m_rows;
    WatchValueState m_valueState;
    WatchTableEdits m_edits;
    // Loaded once: a QIcon made per paint would parse its SVG every time.
    QIcon m_goodIcon;
    QIcon m_staleIcon;
    QIcon m_errorIcon;
    QIcon m_forcedIcon;
    QIcon m_alarmIcon;   // beside the address of a row with alarms
    QIcon m_historyIcon; // beside the name of a row recorded in the history
    QPointer<const SymbolNames> m_symbols;
};

} // namespace Fatek
