#include "watchtableview.h"

#include <QAccessible>
#include <QHeaderView>

namespace Fatek {

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
