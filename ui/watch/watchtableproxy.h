#pragma once

#include <QSortFilterProxyModel>

namespace Fatek {

// Between a watch table's model and its view: the rows sorted by a column (or in the model's own
// order: sort column -1) and filtered by a text found in the address, name or comment. The model
// stays the one owner of the rows; this only changes what the view shows and in what order.
class WatchTableProxy : public QSortFilterProxyModel
{
    Q_OBJECT

public:
    explicit WatchTableProxy(QObject *parent = nullptr);

    QString filterText() const { return m_filter; }
    void setFilterText(const QString &text);
    // Sorted or filtered: the view's order is not the model's, so rows cannot be moved by hand.
    bool isRearranged() const { return sortColumn() >= 0 || !m_filter.isEmpty(); }

Q_SIGNALS:
    void rearrangedChanged(bool rearranged);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    void checkRearranged();

    QString m_filter;
    bool m_rearranged = false;
};

} // namespace Fatek
