#pragma once

#include "core/session/trafficlog.h"

#include <QSortFilterProxyModel>

#include <optional>

namespace Fatek {

// Filters the traffic log view by direction, station, command and "errors only".
class TrafficFilterProxy : public QSortFilterProxyModel
{
    Q_OBJECT

public:
    explicit TrafficFilterProxy(QObject *parent = nullptr);

    // nullopt: any. Rows without a frame header (events) are hidden by a station/command filter.
    void setDirection(std::optional<TrafficEntry::Direction> direction);
    void setStation(std::optional<quint8> station);
    void setCommand(std::optional<quint8> command);
    void setErrorsOnly(bool errorsOnly);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    std::optional<TrafficEntry::Direction> m_direction;
    std::optional<quint8> m_station;
    std::optional<quint8> m_command;
    bool m_errorsOnly = false;
};

} // namespace Fatek
