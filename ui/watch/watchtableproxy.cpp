#include "watchtableproxy.h"

#include "watchtablemodel.h"

namespace Fatek {

WatchTableProxy::WatchTableProxy(QObject *parent)
    : QSortFilterProxyModel(parent)
{
    setSortRole(WatchTableModel::SortRole);
    // A change that names its roles is filtered again only when it names this one: the values'
    // age, repainted four times a second (DisplayRole only), never makes every row filtered and
    // sorted again. Edits and polls name no roles.
    setFilterRole(WatchTableModel::SortRole);
    setSortCaseSensitivity(Qt::CaseInsensitive);
    setSortLocaleAware(true);
    // sort(-1) (the header's third click) shows the model's own order again.
    connect(this, &QAbstractItemModel::layoutChanged, this, &WatchTableProxy::checkRearranged);
}

void WatchTableProxy::setFilterText(const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed == m_filter)
        return;
    // Qt 6.4 has no begin/endFilterChange; invalidateFilter re-reads filterAcceptsRow.
    m_filter = trimmed;
    invalidateFilter();
    checkRearranged();
}

bool WatchTableProxy::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (m_filter.isEmpty())
        return true;
    const QAbstractItemModel *model = sourceModel();
    for (int column : {WatchTableModel::AddressColumn, WatchTableModel::NameColumn,
                       WatchTableModel::CommentColumn}) {
        const QString text = model->index(sourceRow, column, sourceParent).data().toString();
        if (text.contains(m_filter, Qt::CaseInsensitive))
            return true;
    }
    return false;
}

void WatchTableProxy::checkRearranged()
{
    if (isRearranged() == m_rearranged)
        return;
    m_rearranged = isRearranged();
    Q_EMIT rearrangedChanged(m_rearranged);
}

} // namespace Fatek
