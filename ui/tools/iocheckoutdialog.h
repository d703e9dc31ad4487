#pragma once

#include "tooldialogframe.h"

#include <QDialog>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;

namespace Fatek {

class CheckoutRunner;
class CheckoutTableModel;

// Tools -> I/O Checkout (issue 36): the plan (ranges, project, customer, engineer), the points in
// a table driven from the keyboard (Space: seen, or force the output and then seen; F: failed, or
// the forced output not seen; N: the next untested point; L and H: an analog point's low and high
// end), New / Open / Start / Stop and the report (PDF or CSV). The checkout is saved after every
// change (CheckoutRunner, CheckoutFile); a file that lists outputs left forced offers to release
// them. Every force asks first; in operator mode outputs are refused.
class IoCheckoutDialog : public QDialog
{
    Q_OBJECT

public:
    explicit IoCheckoutDialog(QWidget *parent = nullptr);
    ~IoCheckoutDialog() override;

    // Without a direct link the plan can be edited and files opened, nothing runs.
    void setTarget(const PlcTarget &target);
    // Tests answer the questions (force, release) and pick the files without modal dialogs.
    void setConfirmer(Confirmer confirmer) { m_frame->setConfirmer(std::move(confirmer)); }
    void setFileChooser(ToolDialogFrame::FileChooser chooser)
    {
        m_frame->setFileChooser(std::move(chooser));
    }

    CheckoutRunner *runner() const { return m_runner; }
    CheckoutTableModel *points() const { return m_model; }
    QTableView *table() const { return m_table; }
    QString messageText() const;

public Q_SLOTS:
    // Close, Esc, the window's button: results its file could not take ask first.
    void reject() override;
    // A new, empty checkout: the plan fields are edited again.
    void newCheckout();
    // Builds the plan from the fields when none is loaded (asking for the file it is saved in),
    // then watches the inputs.
    void start();
    void stop();
    bool openCheckout(const QString &path);
    // PDF when the name ends in .pdf, CSV otherwise; in the UI's language.
    bool writeReport(const QString &path);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void pressSeen(int index);
    void pressFailed(int index);
    void force(int index);
    void showCurrent(int index);
    void showMessage(const QString &text, bool error);
    void updateControls();
    QString pointText(int index) const;

    CheckoutRunner *m_runner;
    CheckoutTableModel *m_model;
    ToolDialogFrame *m_frame;
    bool m_loaded = false; // a plan is built or opened (the fields show it)
    bool m_following = false;

    QLineEdit *m_ranges;
    QLineEdit *m_project;
    QLineEdit *m_customer;
    QLineEdit *m_engineer;
    QPushButton *m_new;
    QPushButton *m_open;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_report;
    QLabel *m_summary;
    QTableView *m_table;
};

} // namespace Fatek
