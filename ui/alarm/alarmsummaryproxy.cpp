#include "alarmsummaryproxy.h"

#include "alarmsummarymodel.h"

#include "core/alarm/alarmtypes.h"

namespace Fatek {

AlarmSummaryProxy::AlarmSummaryProxy(QObject *parent)
    : QSortFilterProxyModel(parent)
{
    setSortRole(AlarmSummaryModel::SortRole);
    setSortCaseSensitivity(Qt::CaseInsensitive);
}

void AlarmSummaryProxy::setPriorityFilter(std::optional<int> priority)
{
    m_priority = priority;
    invalidateRowsFilter();
}

void AlarmSummaryProxy::setStateFilter(StateFilter filter)
{
    m_state = filter;
    invalidateRowsFilter();
}

void AlarmSummaryProxy::setGroupFilter(const QString &group)
{
    m_group = group;
    invalidateRowsFilter();
}

void AlarmSummaryProxy::setText(const QString &text)
{
    m_text = text.trimmed();
    invalidateRowsFilter();
}

bool AlarmSummaryProxy::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    const QAbstractItemModel *m = sourceModel();
    const QModelIndex first = m->index(sourceRow, 0, sourceParent);
    if (m_priority && first.data(AlarmSummaryModel::PriorityRole).toInt() != *m_priority)
        return false;
    const auto state = static_cast<AlarmState>(first.data(AlarmSummaryModel::StateRole).toInt());
    switch (m_state) {
    case StateFilter::All: break;
    case StateFilter::Unacked:
        if (!Alarms::isUnacked(state))
            return false;
        break;
    case StateFilter::Active:
        if (state != AlarmState::ActiveUnacked && state != AlarmState::ActiveAcked)
            return false;
        break;
    case StateFilter::Shelved:
        if (state != AlarmState::Shelved)
            return false;
        break;
    case StateFilter::OutOfService:
        if (state != AlarmState::OutOfService)
            return false;
        break;
    }
    if (!m_group.isEmpty() && first.data(AlarmSummaryModel::GroupRole).toString() != m_group)
        return false;
    if (m_text.isEmpty())
        return true;
    for (int column : {AlarmSummaryModel::ItemColumn, AlarmSummaryModel::MessageColumn,
                       AlarmSummaryModel::GroupColumn, AlarmSummaryModel::ConnectionColumn}) {
        if (m->index(sourceRow, column, sourceParent)
                .data()
                .toString()
                .contains(m_text, Qt::CaseInsensitive))
            return true;
    }
    return false;
}

} // namespace Fatek
