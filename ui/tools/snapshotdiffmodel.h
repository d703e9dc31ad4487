#pragma once

#include "core/commission/snapshotdiff.h"
#include "core/watch/csvfile.h"

#include <QAbstractTableModel>

#include <vector>

namespace Fatek {

// The differences of a comparison (or of a restore's read-back) as a table: address, before,
// after, formatted by core (SnapshotDiff, ValueFormat); the hex values in the tooltips.
class SnapshotDiffModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { AddressColumn, BeforeColumn, AfterColumn, ColumnCount };

    explicit SnapshotDiffModel(QObject *parent = nullptr);

    // Column titles: "Snapshot"/"PLC", "File 1"/"File 2", "Written"/"Read back".
    void setDifferences(std::vector<SnapshotDifference> differences, const QString &before,
                        const QString &after);
    const std::vector<SnapshotDifference> &differences() const { return m_differences; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // address,before,after,beforeHex,afterHex: the raw values (empty when absent), one row each.
    // The differences as a CSV file's bytes (CsvFile: the byte order mark, the line ends asked).
    QByteArray toCsv(CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf) const;

private:
    std::vector<SnapshotDifference> m_differences;
    QString m_before;
    QString m_after;
};

} // namespace Fatek
