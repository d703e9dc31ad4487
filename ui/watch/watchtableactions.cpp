#include "watchtableactions.h"

#include <QAction>
#include <QIcon>
#include <QMenu>
#include <QTableView>
#include <QUndoStack>

namespace Fatek {

namespace {

// A shortcut that acts while the focus is in the table (several tables may be open).
void setTableShortcut(QAction *action, const QKeySequence &key)
{
    action->setShortcut(key);
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
}

} // namespace

WatchTableActions::WatchTableActions(QWidget *table, QTableView *view, QUndoStack *undoStack)
{
    write = new QAction(tr("&Write Value…"), view);
    setTableShortcut(write, QKeySequence(Qt::CTRL | Qt::Key_W));
    swapWords = new QAction(tr("&Swap Words"), view);
    swapWords->setToolTip(
        tr("Low word first for 32- and 64-bit values (some HMIs store floats so)"));
    copy = new QAction(tr("&Copy Rows"), view);
    copy->setObjectName(QStringLiteral("copyRowsAction"));
    setTableShortcut(copy, QKeySequence::Copy);
    copy->setToolTip(tr("Address, name, value, format, quality and comment of the selected "
                        "rows as tab-separated text"));
    paste = new QAction(tr("&Paste Items"), view);
    paste->setObjectName(QStringLiteral("pasteItemsAction"));
    setTableShortcut(paste, QKeySequence::Paste);
    remove = new QAction(QIcon(QStringLiteral(":/icons/remove.svg")), tr("&Remove"), view);
    setTableShortcut(remove, QKeySequence::Delete);
    // The steps of the rows' edits; writes to the PLC are not among them.
    undo = undoStack->createUndoAction(table, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    setTableShortcut(undo, QKeySequence(Qt::CTRL | Qt::Key_Z));
    redo = undoStack->createRedoAction(table, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)});
    redo->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    table->addActions({undo, redo});
    moveUp = new QAction(tr("Move &Up"), view);
    moveUp->setObjectName(QStringLiteral("moveUpAction"));
    setTableShortcut(moveUp, QKeySequence(Qt::CTRL | Qt::Key_Up));
    moveDown = new QAction(tr("Move &Down"), view);
    moveDown->setObjectName(QStringLiteral("moveDownAction"));
    setTableShortcut(moveDown, QKeySequence(Qt::CTRL | Qt::Key_Down));
    moveRefused = new QAction(table);
    moveRefused->setObjectName(QStringLiteral("moveRefusedAction"));
    moveRefused->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Up), QKeySequence(Qt::CTRL | Qt::Key_Down)});
    moveRefused->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    moveRefused->setEnabled(false);
    table->addAction(moveRefused); // not in the rows' context menu
    ownOrder = new QAction(tr("Own &Order"), view);
    ownOrder->setObjectName(QStringLiteral("ownOrderAction"));
    ownOrder->setToolTip(tr("Show the rows in the order you gave them, not sorted"));
    formatMenu = new QMenu(tr("Set &Format"), table);
    formatMenu->setObjectName(QStringLiteral("formatMenu"));
    auto *separator = new QAction(view);
    separator->setSeparator(true);
    auto *separator2 = new QAction(view);
    separator2->setSeparator(true);
    trend = new QAction(tr("Add to &Trend"), view);
    trend->setToolTip(tr("Plot the selected items over time in the trend view"));
    view->setContextMenuPolicy(Qt::ActionsContextMenu);
    view->addActions({write, formatMenu->menuAction(), swapWords, separator, undo, redo, copy,
                      paste, remove, separator2, moveUp, moveDown, ownOrder, trend});
}

void WatchTableActions::setRowsMovable(bool movable)
{
    moveUp->setEnabled(movable);
    moveDown->setEnabled(movable);
    moveRefused->setEnabled(!movable);
}

} // namespace Fatek
