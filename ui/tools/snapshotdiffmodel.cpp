#include "snapshotdiffmodel.h"

#include "core/commission/commissionmessages.h"
#include "ui/common/uitext.h"

namespace Fatek {

SnapshotDiffModel::SnapshotDiffModel(QObject *parent)
    : QAbstractTableModel(parent)
    , m_before(tr("Before"))
    , m_after(tr("After"))
{}

void SnapshotDiffModel::setDifferences(std::vector<SnapshotDifference> differences,
                                       const QString &before, const QString &after)
{
    beginResetModel();
    m_differences = std::move(differences);
    m_before = before;
    m_after = after;
    endResetModel();
    Q_EMIT headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

int SnapshotDiffModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_differences.size());
}

int SnapshotDiffModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SnapshotDiffModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const SnapshotDifference &d = m_differences[static_cast<std::size_t>(index.row())];
    const std::optional<std::uint32_t> &side = index.column() == BeforeColumn ? d.before : d.after;
    switch (role) {
    case Qt::DisplayRole:
        if (index.column() == AddressColumn)
            return QString::fromStdString(d.address.toString());
        return side ? SnapshotDiff::valueText(d.address, side)
                    : translated(msg<MsgId::DiffAbsent>());
    case Qt::ToolTipRole:
        if (index.column() == AddressColumn)
            return UiText::elementName(d.address.type);
        return SnapshotDiff::hexText(d.address, side);
    default: return {};
    }
}

QVariant SnapshotDiffModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case AddressColumn: return tr("Address");
    case BeforeColumn: return m_before;
    case AfterColumn: return m_after;
    default: return {};
    }
}

QByteArray SnapshotDiffModel::toCsv(CsvFile::LineEnd lineEnd) const
{
    QString out = QStringLiteral("address,before,after,beforeHex,afterHex\n");
    auto raw = [](const std::optional<std::uint32_t> &v) {
        return v ? QString::number(*v) : QString();
    };
    for (const SnapshotDifference &d : m_differences) {
        out += QString::fromStdString(d.address.toString()) + QLatin1Char(',') + raw(d.before)
               + QLatin1Char(',') + raw(d.after) + QLatin1Char(',')
               + SnapshotDiff::hexText(d.address, d.before) + QLatin1Char(',')
               + SnapshotDiff::hexText(d.address, d.after) + QLatin1Char('\n');
    }
    return CsvFile::bytes(out, lineEnd);
}

} // namespace Fatek
