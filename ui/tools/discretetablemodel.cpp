#include "discretetablemodel.h"

#include "ui/common/symbolnames.h"
#include "ui/common/toolpalette.h"

#include <QFont>

namespace Fatek {

DiscreteTableModel::DiscreteTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_range.count = 0;
}

void DiscreteTableModel::setRange(const AddressRange &range)
{
    beginResetModel();
    m_range = range;
    m_states.assign(range.count, std::nullopt);
    m_disabled.assign(range.count, std::nullopt);
    endResetModel();
}

void DiscreteTableModel::setSymbols(const SymbolNames *symbols)
{
    if (m_symbols)
        disconnect(m_symbols, nullptr, this, nullptr);
    m_symbols = symbols;
    const auto namesChanged = [this] {
        if (rowCount() > 0)
            Q_EMIT dataChanged(index(0, NameColumn), index(rowCount() - 1, NameColumn));
    };
    if (symbols)
        connect(symbols, &SymbolNames::changed, this, namesChanged);
    namesChanged();
}

void DiscreteTableModel::assign(std::vector<std::optional<bool>> &target,
                                const std::optional<std::vector<std::uint32_t>> &values)
{
    for (std::size_t i = 0; i < target.size(); ++i) {
        if (values && values->size() == target.size())
            target[i] = (*values)[i] != 0;
        else
            target[i] = std::nullopt;
    }
    if (!target.empty())
        Q_EMIT dataChanged(index(0, PointColumn),
                           index(static_cast<int>(target.size()) - 1, ColumnCount - 1),
                           {Qt::DisplayRole, Qt::FontRole, Qt::BackgroundRole});
}

void DiscreteTableModel::setStates(const std::optional<std::vector<std::uint32_t>> &values)
{
    assign(m_states, values);
}

void DiscreteTableModel::setDisabled(const std::optional<std::vector<std::uint32_t>> &values)
{
    assign(m_disabled, values);
}

std::optional<bool> DiscreteTableModel::stateAt(int row) const
{
    if (row < 0 || static_cast<std::size_t>(row) >= m_states.size())
        return std::nullopt;
    return m_states[static_cast<std::size_t>(row)];
}

std::optional<bool> DiscreteTableModel::disabledAt(int row) const
{
    if (row < 0 || static_cast<std::size_t>(row) >= m_disabled.size())
        return std::nullopt;
    return m_disabled[static_cast<std::size_t>(row)];
}

int DiscreteTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_states.size());
}

int DiscreteTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant DiscreteTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const int row = index.row();
    const std::optional<bool> state = stateAt(row);
    const std::optional<bool> disabled = disabledAt(row);
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case PointColumn: return QString::fromStdString(addressAt(row).toString());
        case StateColumn: return !state ? QStringLiteral("?") : *state ? tr("ON") : tr("OFF");
        case ForcedColumn:
            return !disabled   ? QStringLiteral("?")
                   : *disabled ? tr("disabled (forced)")
                               : tr("enabled");
        case NameColumn: return m_symbols ? m_symbols->name(addressAt(row)) : QString();
        default: return {};
        }
    case Qt::ToolTipRole:
        if (m_symbols && (index.column() == PointColumn || index.column() == NameColumn)) {
            const QString comment = m_symbols->table().comment(addressAt(row));
            if (!comment.isEmpty())
                return comment;
        }
        return {};
    case Qt::FontRole:
        if ((index.column() == StateColumn && state.value_or(false))
            || (index.column() == ForcedColumn && disabled.value_or(false))) {
            QFont font;
            font.setBold(true);
            return font;
        }
        return {};
    case Qt::BackgroundRole:
        // A forced point must stand out: the engineer has to enable it again before leaving.
        if (disabled.value_or(false))
            return ToolPalette::blend(m_palette.color(QPalette::Base),
                                      m_palette.color(QPalette::Highlight), 0.25);
        return {};
    default: return {};
    }
}

QVariant DiscreteTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case PointColumn: return tr("Point");
    case StateColumn: return tr("State");
    case ForcedColumn: return tr("Forcing");
    case NameColumn: return tr("Name");
    default: return {};
    }
}

} // namespace Fatek
