#pragma once

#include <QCoreApplication>

class QAction;
class QMenu;
class QTableView;
class QUndoStack;
class QWidget;

namespace Fatek {

// The actions of a watch table's rows: its context menu (write, format, swap words, undo and redo,
// copy, paste, remove, move, own order, trend) with their shortcuts, which act while the table
// has the focus. Made here, connected by the table (WatchTableWidget).
class WatchTableActions
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::WatchTableActions)

public:
    // `undo`: the table's edits, whose steps the undo and redo actions take.
    WatchTableActions(QWidget *table, QTableView *view, QUndoStack *undo);

    QAction *write;
    QMenu *formatMenu; // filled with the selected rows' formats as it opens
    QAction *swapWords;
    QAction *undo;
    QAction *redo;
    QAction *copy;
    QAction *paste;
    QAction *remove;
    QAction *moveUp;
    QAction *moveDown;
    QAction *ownOrder;
    QAction *trend;
    // Ctrl+Up/Down while the rows cannot move (sorted or filtered): enabled instead of the move
    // actions, so that the keys say why instead of doing nothing.
    QAction *moveRefused;

    // The move actions while the rows can move, moveRefused while they cannot.
    void setRowsMovable(bool movable);
};

} // namespace Fatek
