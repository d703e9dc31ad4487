#include "trafficfilterproxy.h"

#include "trafficlogmodel.h"

namespace Fatek {

TrafficFilterProxy::TrafficFilterProxy(QObject *parent)
    : QSortFilterProxyModel(parent)
{}

void TrafficFilterProxy::setDirection(std::optional<TrafficEntry::Direction> direction)
{
    m_direction = direction;
    invalidateFilter();
}

void TrafficFilterProxy::setStation(std::optional<quint8> station)
{
    m_station = station;
    invalidateFilter();
}

void TrafficFilterProxy::setCommand(std::optional<quint8> command)
{
    m_command = command;
    invalidateFilter();
}

void TrafficFilterProxy::setErrorsOnly(bool errorsOnly)
{
    m_errorsOnly = errorsOnly;
    invalidateFilter();
}

bool TrafficFilterProxy::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    if (m_errorsOnly && !index.data(TrafficLogModel::IsErrorRole).toBool())
        return false;
    if (m_direction
        && index.data(TrafficLogModel::DirectionRole).toInt() != static_cast<int>(*m_direction))
        return false;
    if (m_station
        && index.data(TrafficLogModel::StationRole).toInt() != static_cast<int>(*m_station))
        return false;
    if (m_command
        && index.data(TrafficLogModel::CommandRole).toInt() != static_cast<int>(*m_command))
        return false;
    return true;
}

} // namespace Fatek
