#pragma once

#include "core/protocol/result.h"
#include "core/watch/watchlist.h"

#include <QCoreApplication>
#include <QList>
#include <QUndoStack>

#include <optional>

namespace Fatek {

class WatchTableModel;

// The edits a person makes to a watch table's rows (typed, pasted, dragged, removed, formats):
// each call is one step on undoStack(), made of the model's own changes (WatchRowsCommand).
// Rows are named by their position: every change of positions goes through the stack, and a
// loaded list (WatchTableModel::setItems) starts a new history. Values written to the PLC never
// are steps: a write cannot be taken back.
class WatchTableEdits
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::WatchTableEdits)

public:
    explicit WatchTableEdits(WatchTableModel *model);

    QUndoStack *undoStack() { return &m_undo; }
    // See WatchTableModel, which hands its edits on to these.
    void insertItems(int row, const QList<WatchItemSpec> &items);
    void removeItems(QList<int> rows);
    bool moveItems(const QList<int> &rows, int delta);
    bool moveItemsTo(const QList<int> &rows, int destination);
    Status editItem(int row, const WatchItemSpec &spec);
    Status setFormat(int row, DisplayFormat format, bool swapWords);
    Status setFormats(const QList<int> &rows, DisplayFormat format);
    Status setAlarms(int row, const QList<AlarmDefinition> &alarms);
    // Rows that cannot take the setting's deadband (bits, ASCII) get none; the first refusal is
    // returned, the other rows are set.
    Status setHistory(const QList<int> &rows, const std::optional<HistorySetting> &setting);

private:
    WatchTableModel *m_model;
    QUndoStack m_undo;
};

} // namespace Fatek
