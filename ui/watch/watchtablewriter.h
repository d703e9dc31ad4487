#pragma once

#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace Fatek {

struct LinkWriteResult;
class WatchTableModel;
class WatchTableWidget;

// Asks "write this?"; true = go. Tests put an automatic answer here.
using ConfirmHandler = std::function<bool(QWidget *parent, const QString &question)>;

// A watch table's writes to the PLC: the value asked for, the question before it goes (unless
// the table writes without one), the write on the table's connection and its outcome, shown in
// the row's tooltip and said in the table's message line (message()).
class WatchTableWriter : public QObject
{
    Q_OBJECT

public:
    WatchTableWriter(WatchTableModel *model, WatchTableWidget *table);

    void setConfirmHandler(ConfirmHandler handler) { m_confirm = std::move(handler); }
    // Asks for the value of `row` and writes it (through the model, as a typed value).
    void askAndWrite(int row);
    // Starts a write of `raw` to `row` (after confirmation).
    void write(int row, quint64 raw);

Q_SIGNALS:
    void message(const QString &text, bool error);
    // The PLC's link refused the write of `what` (after message()).
    void refused(const QString &what);

private:
    void onWritten(quint64 rowKey, const QString &what, const LinkWriteResult &result);

    WatchTableModel *m_model;
    WatchTableWidget *m_table;
    ConfirmHandler m_confirm;
};

} // namespace Fatek
