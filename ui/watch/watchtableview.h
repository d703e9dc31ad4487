#pragma once

#include <QTableView>

namespace Fatek {

// The watch table's view: a QTableView that repaints exactly the visible cells of a changed range.
// Qt 6.4's QTableView repaints a range one pixel wider and taller than its cells, so the visible
// cells of the next column (and one more row) were painted again at every poll too: with the value
// and time columns changing on every visible row, that doubled the painting (measured with the
// bench's 10,000 items: value, format, time and comment columns painted for value and time).
// One cell, moved sections and hidden rows or columns keep QTableView's own handling.
class WatchTableView : public QTableView
{
    Q_OBJECT

public:
    using QTableView::QTableView;

protected:
    void dataChanged(const QModelIndex &topLeft, const QModelIndex &bottomRight,
                     const QList<int> &roles = QList<int>()) override;
};

} // namespace Fatek
