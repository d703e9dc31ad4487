#pragma once

#include "core/protocol/rawframe.h"
#include "core/session/trafficlog.h"

#include <QAbstractTableModel>
#include <QPalette>

#include <deque>
#include <optional>

namespace Fatek {

// The traffic log as a table: time, direction, station, hex, ASCII, meaning, error. Rows are
// appended in batches and capped (oldest dropped) so a long session stays responsive.
class TrafficLogModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        TimeColumn,
        DirectionColumn,
        StationColumn,
        HexColumn,
        AsciiColumn,
        MeaningColumn,
        ErrorColumn,
        ColumnCount
    };
    // Roles the filter reads: direction (int of TrafficEntry::Direction), station and command
    // (-1 when the row has none), whether the row is an error.
    enum Role { DirectionRole = Qt::UserRole + 1, StationRole, CommandRole, IsErrorRole };

    explicit TrafficLogModel(QObject *parent = nullptr);

    void setCapacity(int rows);
    int capacity() const { return m_capacity; }
    void setPalette(const QPalette &palette) { m_palette = palette; }

    void append(const QList<TrafficEntry> &entries);
    void clear();
    const TrafficEntry &entryAt(int row) const
    {
        return m_rows.at(static_cast<std::size_t>(row)).entry;
    }
    // One line of tab-separated text per row, for copy and save.
    QString rowText(int row) const;
    static QString directionText(TrafficEntry::Direction direction);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Row
    {
        TrafficEntry entry;
        std::optional<RawFrame::Peek> header;
        QString time; // local time, formatted once
        QString hex;
        QString ascii;
        QString meaning; // the entry's summary and error in the UI language, translated once
        QString error;
    };

    std::deque<Row> m_rows;
    int m_capacity = 20000;
    QPalette m_palette;
};

} // namespace Fatek
