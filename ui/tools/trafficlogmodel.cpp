#include "trafficlogmodel.h"

#include "core/protocol/frametext.h"
#include "core/session/qtbytes.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QFontDatabase>

namespace Fatek {

TrafficLogModel::TrafficLogModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void TrafficLogModel::setCapacity(int rows)
{
    m_capacity = qMax(1, rows);
    append({});
}

QString TrafficLogModel::directionText(TrafficEntry::Direction direction)
{
    switch (direction) {
    case TrafficEntry::Direction::Out: return tr("sent");
    case TrafficEntry::Direction::In: return tr("received");
    case TrafficEntry::Direction::Event: return tr("event");
    }
    return {};
}

void TrafficLogModel::append(const QList<TrafficEntry> &entries)
{
    // Only the newest `capacity` of a huge batch can survive anyway.
    const qsizetype skip = qMax<qsizetype>(0, entries.size() - m_capacity);
    const auto incoming = static_cast<std::size_t>(entries.size() - skip);
    const auto capacity = static_cast<std::size_t>(m_capacity);
    if (m_rows.size() + incoming > capacity) {
        const std::size_t drop = std::min(m_rows.size(), m_rows.size() + incoming - capacity);
        if (drop > 0) {
            beginRemoveRows({}, 0, static_cast<int>(drop) - 1);
            m_rows.erase(m_rows.begin(), m_rows.begin() + static_cast<std::ptrdiff_t>(drop));
            endRemoveRows();
        }
    }
    if (incoming == 0)
        return;
    const int first = static_cast<int>(m_rows.size());
    beginInsertRows({}, first, first + static_cast<int>(incoming) - 1);
    for (qsizetype i = skip; i < entries.size(); ++i) {
        const TrafficEntry &e = entries.at(i);
        const std::span<const std::uint8_t> bytes = bytesOf(e.bytes);
        m_rows.push_back(Row{e, RawFrame::peek(bytes),
                             e.timestamp.toLocalTime().toString(QStringLiteral("HH:mm:ss.zzz")),
                             QString::fromStdString(FrameText::toHex(bytes)),
                             QString::fromStdString(FrameText::toAscii(bytes)),
                             translated(e.summary), translated(e.error)});
    }
    endInsertRows();
}

void TrafficLogModel::clear()
{
    beginResetModel();
    m_rows.clear();
    endResetModel();
}

QString TrafficLogModel::rowText(int row) const
{
    QStringList cells;
    for (int c = 0; c < ColumnCount; ++c)
        cells << data(index(row, c), Qt::DisplayRole).toString();
    return cells.join(QLatin1Char('\t'));
}

int TrafficLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int TrafficLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TrafficLogModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const Row &row = m_rows[static_cast<std::size_t>(index.row())];
    const TrafficEntry &e = row.entry;
    const bool isError = !e.error.empty();
    switch (role) {
    case Qt::DisplayRole:
    case Qt::ToolTipRole:
        switch (index.column()) {
        case TimeColumn: return row.time;
        case DirectionColumn: return directionText(e.direction);
        case StationColumn: return row.header ? QVariant(row.header->station) : QVariant();
        case HexColumn: return row.hex;
        case AsciiColumn: return row.ascii;
        case MeaningColumn: return row.meaning;
        case ErrorColumn: return row.error;
        default: return {};
        }
    case Qt::FontRole:
        if (index.column() == HexColumn || index.column() == AsciiColumn)
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        return {};
    case Qt::ForegroundRole:
        return isError ? QVariant(ToolPalette::errorText(m_palette)) : QVariant();
    case Qt::BackgroundRole:
        return isError ? QVariant(ToolPalette::errorBackground(m_palette)) : QVariant();
    case DirectionRole: return static_cast<int>(e.direction);
    case StationRole: return row.header ? static_cast<int>(row.header->station) : -1;
    case CommandRole: return row.header ? static_cast<int>(row.header->command) : -1;
    case IsErrorRole: return isError;
    default: return {};
    }
}

QVariant TrafficLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case TimeColumn: return tr("Time");
    case DirectionColumn: return tr("Direction");
    case StationColumn: return tr("Station");
    case HexColumn: return tr("Bytes (hex)");
    case AsciiColumn: return tr("ASCII");
    case MeaningColumn: return tr("Meaning");
    case ErrorColumn: return tr("Error");
    default: return {};
    }
}

} // namespace Fatek
