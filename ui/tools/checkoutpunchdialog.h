#pragma once

#include "core/watch/csvfile.h"

#include <QDialog>

#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace Fatek {

class CheckoutRunner;
class ToolDialogFrame;

// I/O Checkout > Punch List…: the points that failed or were deferred (now, or earlier and since
// mended), with the remark, who mends each (the Owner cell, typed in) and whether it is closed
// out. Close Out closes the chosen item (the runner refuses one that still fails); Export CSV…
// writes the list as the report's punch CSV. Follows the runner: a point re-tested shows at once.
class CheckoutPunchDialog : public QDialog
{
    Q_OBJECT

public:
    enum Column { PointColumn, NameColumn, ResultColumn, RemarkColumn, OwnerColumn, StateColumn };

    // `frame`: the checkout dialog's, for its file chooser.
    CheckoutPunchDialog(CheckoutRunner *runner, ToolDialogFrame *frame, QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }
    // The plan index of each row.
    const std::vector<int> &points() const { return m_points; }
    QString messageText() const;

    void closeOut(int row);
    bool exportCsv(const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);

private:
    void fill();
    void showMessage(const QString &text, bool error);

    CheckoutRunner *m_runner;
    ToolDialogFrame *m_frame;
    QTableWidget *m_table;
    QPushButton *m_close;
    QPushButton *m_export;
    QLabel *m_message;
    std::vector<int> m_points;
    bool m_filling = false;
};

} // namespace Fatek
