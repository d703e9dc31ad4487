#pragma once

#include <QAbstractTableModel>
#include <QPointer>

#include <map>

namespace Fatek {

class CheckoutRunner;

// The points of an I/O checkout as a table, in the plan's order (its groups together, the group
// named on its first row): group, point, name, kind, state, what was measured (or the live value),
// comment (editable). Refreshed from the runner's signals one row (or cell) at a time; reset only
// when the runner gets a new plan (planReset()). Passed and failed rows are coloured from the
// palette; the point under test is bold.
class CheckoutTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        GroupColumn,
        PointColumn,
        NameColumn,
        KindColumn,
        StateColumn,
        MeasuredColumn,
        CommentColumn,
        ColumnCount
    };

    explicit CheckoutTableModel(CheckoutRunner *runner, QObject *parent = nullptr);

    // The runner holds a new plan: every row anew.
    void planReset();
    // A row's cells anew (the output under test changed).
    void refreshRow(int row);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    // The comment is the engineer's to edit (saved with the checkout at once).
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

private:
    // The output under test, forced in the PLC and waiting for its answer.
    bool isForced(int row) const;

    QPointer<CheckoutRunner> m_runner;
    std::map<int, quint32> m_live; // the latest polled value of a row
    int m_current = -1;
    int m_forced = -1;
};

} // namespace Fatek
