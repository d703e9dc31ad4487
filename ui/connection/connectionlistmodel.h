#pragma once

#include <QAbstractTableModel>
#include <QIcon>

namespace Fatek {

class Connection;
class ConnectionManager;

// The open connections with their link state and statistics, one row each.
class ConnectionListModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        NameColumn,
        LinkColumn,
        StationColumn,
        PlcColumn,
        StateColumn,
        RateColumn,
        ErrorsColumn,
        RttColumn,
        ColumnCount
    };

    explicit ConnectionListModel(ConnectionManager *manager, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

    Connection *connectionAt(int row) const;

private:
    ConnectionManager *m_manager;
    QIcon m_silentIcon; // loaded once, not per paint
};

} // namespace Fatek
