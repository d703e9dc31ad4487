#pragma once

#include <QAbstractTableModel>
#include <QPointer>
#include <QString>

#include <map>

namespace Fatek {

class CheckoutRunner;
struct CheckoutPoint;

// The points of an I/O checkout as a table, in the plan's order (its groups together, the group
// named on its first row): group, point, name, kind, state, what was measured (or the live value),
// comment (editable). Refreshed from the runner's signals one row (or cell) at a time; reset only
// when the runner gets a new plan (planReset()). Each status has its colour from the palette; the
// point under test is bold; the state says which attempt it is, its tooltip the earlier ones (who,
// when, what); an analog point's measured cell says which check is next and what it expects.
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
    // An analog point's first check not read as found yet (an index into its scale's checks);
    // -1 when every check is read.
    static int nextCheck(const CheckoutPoint &point);
    // "25 %: 8.00 mA expected".
    static QString checkText(const CheckoutPoint &point, int check);
    // The earlier attempts of a point, one line each (who, when, what); empty when none.
    static QString history(const CheckoutPoint &point);

    // The comment is the engineer's to edit (saved with the checkout at once).
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

private:
    // The output under test, forced in the PLC and waiting for its answer.
    bool isForced(int row) const;
    QString stateText(int row) const;
    QString measuredText(int row) const;

    QPointer<CheckoutRunner> m_runner;
    std::map<int, quint32> m_live; // the latest polled value of a row
    int m_current = -1;
    int m_forced = -1;
};

} // namespace Fatek
