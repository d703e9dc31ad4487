#pragma once

#include <QTableView>

class QMimeData;

namespace Fatek {

// The watch table's view: a QTableView that repaints exactly the visible cells of a changed range.
// Qt 6.4's QTableView repaints a range one pixel wider and taller than its cells, so the visible
// cells of the next column (and one more row) were painted again at every poll too: with the value
// and time columns changing on every visible row, that doubled the painting (measured with the
// bench's 10,000 items: value, format, time and comment columns painted for value and time).
// One cell, moved sections and hidden rows or columns keep QTableView's own handling.
// Rows are reordered by dragging the selected ones: the view says where they were dropped
// (rowsDropped) and the table moves them in its model; nothing is removed or copied by the drag.
class WatchTableView : public QTableView
{
    Q_OBJECT

public:
    explicit WatchTableView(QWidget *parent = nullptr);

    // The watch table's look, once its model is set: whole rows selected, sorted by a header
    // click, the columns' widths, and from now on the widest columns narrowed when the view is
    // too narrow for them all (the comment column stretches into what is left, so the table never
    // scrolls sideways).
    void setUpColumns();

    // While off (sorted or filtered rows), rows cannot be dragged.
    void setRowsMovable(bool movable);
    // Scrolls a row just inserted into view (the scroll range is laid out first: it is updated
    // later otherwise, and the scroll would stop at the old end).
    void showInsertedRow(const QModelIndex &index);
    // What a drag of the selected rows carries (only this view takes it); nullptr: none selected.
    QMimeData *rowsMimeData() const;
    static constexpr const char *rowsMimeType = "application/x-fatek-watch-rows";

Q_SIGNALS:
    // `rows` (the view's, ascending) dropped to stand before the view's row `destination`
    // (rowCount: at the end).
    void rowsDropped(const QList<int> &rows, int destination);

protected:
    void dataChanged(const QModelIndex &topLeft, const QModelIndex &bottomRight,
                     const QList<int> &roles = QList<int>()) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dragLeaveEvent(QDragLeaveEvent *event) override;
    void dropEvent(QDropEvent *event) override;
    void startDrag(Qt::DropActions supportedActions) override;
    void paintEvent(QPaintEvent *event) override;
    bool viewportEvent(QEvent *event) override;

private:
    // The row a drop at `pos` (viewport) goes before.
    int dropRow(const QPoint &pos) const;
    // The view's rows a drag of this view carries; empty when it is not this view's.
    QList<int> draggedRows(const QMimeData *mime) const;
    void setDropLine(int row);
    void fitColumns();

    int m_dropRow = -1; // where the drop line is drawn, -1: none
    bool m_fitColumns = false;
};

} // namespace Fatek
