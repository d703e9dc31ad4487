#pragma once

#include "core/protocol/addressrange.h"

#include <QAbstractTableModel>
#include <QPalette>
#include <QPointer>

#include <optional>
#include <vector>

namespace Fatek {

class SymbolNames;

// One row per discrete of a range: its ON/OFF state (44) and whether it is disabled (43).
// Unknown values (not read yet, or the read failed) show as "?". With the window's names
// (setSymbols) the Name column shows the ladder project's name of each point, its comment in the
// tooltip.
class DiscreteTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { PointColumn, StateColumn, ForcedColumn, NameColumn, ColumnCount };

    explicit DiscreteTableModel(QObject *parent = nullptr);

    void setRange(const AddressRange &range);
    AddressRange range() const { return m_range; }
    // Values of 44 / 43 for the whole range; a size mismatch or nullopt marks them unknown.
    void setStates(const std::optional<std::vector<std::uint32_t>> &values);
    void setDisabled(const std::optional<std::vector<std::uint32_t>> &values);
    void setPalette(const QPalette &palette) { m_palette = palette; }
    // Not owned; nullptr: no names. The Name column follows their changes.
    void setSymbols(const SymbolNames *symbols);

    Address addressAt(int row) const { return m_range.start.advanced(static_cast<quint32>(row)); }
    std::optional<bool> stateAt(int row) const;
    std::optional<bool> disabledAt(int row) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    void assign(std::vector<std::optional<bool>> &target,
                const std::optional<std::vector<std::uint32_t>> &values);

    AddressRange m_range;
    std::vector<std::optional<bool>> m_states;
    std::vector<std::optional<bool>> m_disabled;
    QPalette m_palette;
    QPointer<const SymbolNames> m_symbols;
};

} // namespace Fatek
