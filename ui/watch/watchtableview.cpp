#include "watchtableview.h"

#include "watchtablemodel.h"

#include <QAccessible>
#include <QDrag>
#include <QDragEnterEvent>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QHeaderView>
#include <QMimeData>
#include <QPainter>

#include <algorithm>

namespace Fatek {

WatchTableView::WatchTableView(QWidget *parent)
    : QTableView(parent)
{
    setRowsMovable(true);
    setDropIndicatorShown(false); // the view's own is per cell; the line below is per row
}

void WatchTableView::setUpColumns()
{
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                    | QAbstractItemView::AnyKeyPressed);
    setAlternatingRowColors(true);
    setWordWrap(false);
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    verticalHeader()->hide();
    QHeaderView *header = horizontalHeader();
    header->setStretchLastSection(true);
    // Click a header to sort, again for the other way, a third time for the rows' own order.
    header->setSortIndicatorClearable(true);
    header->setSortIndicator(-1, Qt::AscendingOrder); // not sorted by the first column at start
    setSortingEnabled(true);
    const int em = fontMetrics().horizontalAdvance(QLatin1Char('M'));
    // Quality holds its age too ("good, 0.4 s", "no answer, 1.3 s"). The comment stretches into
    // what is left: its own width is the least it keeps (a stretched last section never gets
    // narrower than that).
    const int widths[] = {14, 7, 5, 13, 9, 12, 9, 3};
    for (int c = 0; c < WatchTableModel::ColumnCount; ++c)
        header->resizeSection(c, widths[c] * em);
    header->setMinimumSectionSize(3 * em);
    setTextElideMode(Qt::ElideRight);
    m_fitColumns = true;
}

bool WatchTableView::viewportEvent(QEvent *event)
{
    if (m_fitColumns && event->type() == QEvent::Resize)
        fitColumns();
    return QTableView::viewportEvent(event);
}

void WatchTableView::fitColumns()
{
    QHeaderView *header = horizontalHeader();
    const int em = fontMetrics().horizontalAdvance(QLatin1Char('M'));
    const int lastColumn = WatchTableModel::CommentColumn;
    int others = 0;
    for (int c = 0; c < lastColumn; ++c)
        others += header->isSectionHidden(c) ? 0 : header->sectionSize(c);
    int excess = others + 6 * em - viewport()->width();
    // The name gives room first (it elides), then the value and the time.
    for (const auto &[column, least] : {std::pair{int(WatchTableModel::NameColumn), 7 * em},
                                        std::pair{int(WatchTableModel::ValueColumn), 8 * em},
                                        std::pair{int(WatchTableModel::UpdatedColumn), 7 * em}}) {
        if (excess <= 0)
            break;
        const int size = header->sectionSize(column);
        const int give = std::clamp(size - least, 0, excess);
        if (give > 0) {
            header->resizeSection(column, size - give);
            excess -= give;
        }
    }
}

void WatchTableView::showInsertedRow(const QModelIndex &index)
{
    doItemsLayout();
    scrollTo(index);
}

void WatchTableView::setRowsMovable(bool movable)
{
    setDragEnabled(movable);
    setAcceptDrops(movable);
    setDragDropMode(movable ? QAbstractItemView::InternalMove : QAbstractItemView::NoDragDrop);
}

int WatchTableView::dropRow(const QPoint &pos) const
{
    const int row = rowAt(pos.y());
    if (row < 0)
        return model() ? model()->rowCount(rootIndex()) : 0;
    // The upper half of a row drops before it, the lower half after it.
    const int middle = rowViewportPosition(row) + rowHeight(row) / 2;
    return pos.y() < middle ? row : row + 1;
}

void WatchTableView::setDropLine(int row)
{
    if (row == m_dropRow)
        return;
    m_dropRow = row;
    viewport()->update();
}

QMimeData *WatchTableView::rowsMimeData() const
{
    if (!selectionModel())
        return nullptr;
    QList<int> rows;
    for (const QModelIndex &index : selectionModel()->selectedRows())
        rows.append(index.row());
    if (rows.isEmpty())
        return nullptr;
    std::sort(rows.begin(), rows.end());
    // The view names itself: rows of another table (or window) mean nothing here.
    QStringList words{QString::number(reinterpret_cast<quintptr>(this))};
    for (int r : std::as_const(rows))
        words << QString::number(r);
    auto *mime = new QMimeData;
    mime->setData(QLatin1String(rowsMimeType), words.join(QLatin1Char(' ')).toLatin1());
    return mime;
}

QList<int> WatchTableView::draggedRows(const QMimeData *mime) const
{
    if (!mime || !dragEnabled() || !mime->hasFormat(QLatin1String(rowsMimeType)))
        return {};
    const QList<QByteArray> words = mime->data(QLatin1String(rowsMimeType)).split(' ');
    if (words.size() < 2 || words.first() != QByteArray::number(reinterpret_cast<quintptr>(this)))
        return {};
    QList<int> rows;
    const int count = model() ? model()->rowCount(rootIndex()) : 0;
    for (qsizetype i = 1; i < words.size(); ++i) {
        bool ok = false;
        const int r = words.at(i).toInt(&ok);
        if (!ok || r < 0 || r >= count)
            return {};
        rows.append(r);
    }
    return rows;
}

void WatchTableView::startDrag(Qt::DropActions supportedActions)
{
    Q_UNUSED(supportedActions)
    QMimeData *mime = rowsMimeData();
    if (!mime)
        return;
    // The rows are moved where they are dropped; nothing is removed here when the drag ends.
    auto *drag = new QDrag(this);
    drag->setMimeData(mime);
    drag->exec(Qt::MoveAction, Qt::MoveAction);
}

void WatchTableView::dragEnterEvent(QDragEnterEvent *event)
{
    if (draggedRows(event->mimeData()).isEmpty()) {
        event->ignore();
        return;
    }
    setState(DraggingState);
    event->setDropAction(Qt::MoveAction);
    event->accept();
}

void WatchTableView::dragMoveEvent(QDragMoveEvent *event)
{
    if (draggedRows(event->mimeData()).isEmpty()) {
        event->ignore();
        return;
    }
    setDropLine(dropRow(event->position().toPoint()));
    event->setDropAction(Qt::MoveAction);
    event->accept();
}

void WatchTableView::dragLeaveEvent(QDragLeaveEvent *event)
{
    setDropLine(-1);
    setState(NoState);
    QTableView::dragLeaveEvent(event);
}

void WatchTableView::dropEvent(QDropEvent *event)
{
    setDropLine(-1);
    stopAutoScroll();
    setState(NoState);
    const QList<int> rows = draggedRows(event->mimeData());
    if (rows.isEmpty()) {
        event->ignore();
        return;
    }
    event->setDropAction(Qt::MoveAction);
    event->accept();
    Q_EMIT rowsDropped(rows, dropRow(event->position().toPoint()));
}

void WatchTableView::paintEvent(QPaintEvent *event)
{
    QTableView::paintEvent(event);
    if (m_dropRow < 0 || !model())
        return;
    const int rows = model()->rowCount(rootIndex());
    const int y = m_dropRow < rows ? rowViewportPosition(m_dropRow)
                  : rows > 0       ? rowViewportPosition(rows - 1) + rowHeight(rows - 1)
                                   : 0;
    QPainter painter(viewport());
    painter.setPen(QPen(palette().color(QPalette::Highlight), 2));
    painter.drawLine(0, y, viewport()->width(), y);
}

void WatchTableView::dataChanged(const QModelIndex &topLeft, const QModelIndex &bottomRight,
                                 const QList<int> &roles)
{
    const bool plain = topLeft.isValid() && bottomRight.isValid() && topLeft != bottomRight
                       && topLeft.model() == model() && bottomRight.model() == model()
                       && topLeft.parent() == rootIndex() && bottomRight.parent() == rootIndex()
                       && !horizontalHeader()->sectionsMoved() && !verticalHeader()->sectionsMoved()
                       && !isRowHidden(topLeft.row()) && !isRowHidden(bottomRight.row());
    bool columnsShown = plain;
    for (int c = topLeft.column(); columnsShown && c <= bottomRight.column(); ++c)
        columnsShown = !isColumnHidden(c);
    if (!columnsShown) {
        QTableView::dataChanged(topLeft, bottomRight, roles);
        return;
    }
    // What the base does for a range, with the exact rectangle. An open editor is refreshed as
    // the base would (its delegate decides whether that changes anything).
    if (state() == EditingState) {
        const QModelIndex current = currentIndex();
        if (current.parent() == rootIndex() && current.row() >= topLeft.row()
            && current.row() <= bottomRight.row() && current.column() >= topLeft.column()
            && current.column() <= bottomRight.column())
            QTableView::dataChanged(current, current, roles);
    }
#if QT_CONFIG(accessibility)
    if (QAccessible::isActive()) {
        QAccessibleTableModelChangeEvent event(this, QAccessibleTableModelChangeEvent::DataChanged);
        event.setFirstRow(topLeft.row());
        event.setFirstColumn(topLeft.column());
        event.setLastRow(bottomRight.row());
        event.setLastColumn(bottomRight.column());
        QAccessible::updateAccessibility(&event);
    }
#endif
    if (!isVisible())
        return;
    const int left = columnViewportPosition(topLeft.column());
    const int right
        = columnViewportPosition(bottomRight.column()) + columnWidth(bottomRight.column());
    const int top = rowViewportPosition(topLeft.row());
    const int bottom = rowViewportPosition(bottomRight.row()) + rowHeight(bottomRight.row());
    const QRect cells
        = QRect(left, top, right - left, bottom - top).intersected(viewport()->rect());
    if (!cells.isEmpty())
        viewport()->update(cells);
}

} // namespace Fatek
