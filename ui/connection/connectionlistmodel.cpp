#include "connectionlistmodel.h"

#include "connectionmanager.h"
#include "ui/common/uitext.h"

namespace Fatek {

ConnectionListModel::ConnectionListModel(ConnectionManager *manager, QObject *parent)
    : QAbstractTableModel(parent)
    , m_manager(manager)
    , m_silentIcon(QStringLiteral(":/icons/error.svg"))
{
    // The manager signals before/after; rows map 1:1 to manager->connections().
    connect(manager, &ConnectionManager::connectionAdded, this, [this](Connection *c) {
        const int row = m_manager->indexOf(c);
        beginInsertRows({}, row, row);
        endInsertRows();
    });
    connect(manager, &ConnectionManager::connectionAboutToBeRemoved, this, [this](Connection *c) {
        const int row = m_manager->indexOf(c);
        beginRemoveRows({}, row, row);
    });
    connect(manager, &ConnectionManager::connectionRemoved, this, [this] { endRemoveRows(); });
    connect(manager, &ConnectionManager::connectionChanged, this, [this](Connection *c) {
        const int row = m_manager->indexOf(c);
        if (row >= 0)
            Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1));
    });
}

int ConnectionListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_manager->connections().size());
}

int ConnectionListModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

Connection *ConnectionListModel::connectionAt(int row) const
{
    return m_manager->connection(row);
}

QVariant ConnectionListModel::data(const QModelIndex &index, int role) const
{
    const Connection *c = connectionAt(index.row());
    if (!c)
        return {};
    const StationStatistics &t = c->statistics().total;
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case NameColumn: return c->name();
        case LinkColumn: return c->linkText();
        case StationColumn: return c->station();
        case PlcColumn: {
            const QString text = c->plcText();
            return text.isEmpty() ? QStringLiteral("–") : text;
        }
        case StateColumn: return c->stateText();
        case RateColumn: return QString::number(c->requestsPerSecond(), 'f', 1);
        case ErrorsColumn: return QString::number(c->errorCount());
        case RttColumn:
            return t.answers ? QStringLiteral("%1 ms").arg(t.rttMeanMs, 0, 'f', 1)
                             : QStringLiteral("–");
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (index.column()) {
        case StateColumn:
            return c->linkReason().empty() ? UiText::linkState(c->linkState())
                                           : translated(c->linkReason());
        case ErrorsColumn:
            return tr("%1 timeouts, %2 checksum errors, %3 PLC errors, %4 retries, %5 link "
                      "failures")
                .arg(t.timeouts)
                .arg(t.checksumErrors)
                .arg(t.plcErrors)
                .arg(t.retries)
                .arg(c->linkFailures());
        case RttColumn:
            return tr("Round trip: last %1 ms, median %2 ms, 99% %3 ms")
                .arg(t.rttLastMs, 0, 'f', 1)
                .arg(t.rttP50Ms, 0, 'f', 1)
                .arg(t.rttP99Ms, 0, 'f', 1);
        case StationColumn: return tr("Station the tools act on; double-click to change");
        case PlcColumn: {
            const std::optional<DetailStatus> detail = c->plcDetail();
            const std::optional<std::string> model
                = detail ? detail->modelName() : std::optional<std::string>();
            // More about the PLC (OS, program size) is in Tools > PLC Control.
            return model ? tr("Station %1: %2 (RUN/STOP read every %3 s)")
                               .arg(c->station())
                               .arg(QString::fromStdString(*model))
                               .arg(Connection::plcStatusIntervalMs / 1000)
                         : tr("The PLC has not said what it is yet");
        }
        default: {
            // Per station: several PLCs on one RS-485 line share a connection.
            QStringList lines{c->linkText()};
            // What fatek-cli --link and named links take, to copy into a script.
            if (!c->isGateway())
                lines << tr("URL: %1").arg(c->saved().settings.toUrl(c->station()));
            const SessionStatistics statistics = c->statistics();
            for (auto it = statistics.stations.cbegin(); it != statistics.stations.cend(); ++it) {
                const StationStatistics &s = it.value();
                lines << tr("Station %1: %2 requests, %3 errors, RTT %4 ms")
                             .arg(it.key())
                             .arg(s.requests)
                             .arg(s.timeouts + s.checksumErrors + s.plcErrors)
                             .arg(s.rttMeanMs, 0, 'f', 1);
                if (s.demoted && s.nextTry.isValid())
                    lines.last()
                        += tr("; not answering, polled again at %1")
                               .arg(s.nextTry.toLocalTime().toString(QStringLiteral("HH:mm:ss")));
            }
            return lines.join(QLatin1Char('\n'));
        }
        }
    }
    // A silent station is a fault, not a healthy link: it gets the error mark of the tables.
    if (role == Qt::DecorationRole && index.column() == StateColumn
        && !c->silentStations().isEmpty())
        return m_silentIcon;
    if (role == Qt::TextAlignmentRole && index.column() >= StationColumn
        && index.column() != StateColumn && index.column() != PlcColumn)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant ConnectionListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn: return tr("Name");
    case LinkColumn: return tr("Link");
    case StationColumn: return tr("Station");
    case PlcColumn: return tr("PLC");
    case StateColumn: return tr("State");
    case RateColumn: return tr("Req/s");
    case ErrorsColumn: return tr("Errors");
    case RttColumn: return tr("RTT");
    default: return {};
    }
}

Qt::ItemFlags ConnectionListModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.column() == StationColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

bool ConnectionListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    Connection *c = connectionAt(index.row());
    if (!c || role != Qt::EditRole || index.column() != StationColumn)
        return false;
    bool ok = false;
    const int station = value.toInt(&ok);
    if (!ok || station < 0 || station > 254)
        return false;
    c->setStation(static_cast<quint8>(station));
    return true;
}

} // namespace Fatek
