#pragma once

#include "checkoutpunchdialog.h"
#include "core/commission/checkoutplan.h"
#include "core/commission/checkoutreport.h"
#include "tooldialogframe.h"
#include "ui/common/symbolnames.h"

#include <QDialog>
#include <QPointer>

class QLabel;
class QLineEdit;
class QMenu;
class QPushButton;
class QTableView;

namespace Fatek {

class CheckoutKeys;
class CheckoutRunner;
class CheckoutTableModel;

// Tools -> I/O Checkout (issues 36, 53): the plan (typed ranges, a plan CSV or the imported names;
// project, customer, engineer and the report's details), the points in a table driven from the
// keyboard (CheckoutKeys: every status, re-tests, analog checks), New / Open / Import / Start /
// Stop, the punch list and the report (PDF, CSV). The checkout is saved after every change
// (CheckoutRunner, CheckoutFile); a file that lists outputs left forced offers to release them.
// Every force asks first; in operator mode outputs are refused. Closed with an output forced, it
// releases it first and closes once the PLC confirmed it (the file then lists nothing forced).
class IoCheckoutDialog : public QDialog
{
    Q_OBJECT

public:
    explicit IoCheckoutDialog(QWidget *parent = nullptr);
    ~IoCheckoutDialog() override;

    // Without a direct link the plan can be edited and files opened, nothing runs.
    void setTarget(const PlcTarget &target);
    // The main window's names (the ladder project's): typed ranges get them, and a plan is made
    // from them (Import > Imported Names).
    void setSymbols(const SymbolNames *symbols) { m_symbols = symbols; }
    // Tests answer the questions (force, release), type the remarks and pick the files without
    // modal dialogs.
    void setConfirmer(Confirmer confirmer) { m_frame->setConfirmer(std::move(confirmer)); }
    void setFileChooser(ToolDialogFrame::FileChooser chooser)
    {
        m_frame->setFileChooser(std::move(chooser));
    }
    void setTextAsker(ToolDialogFrame::TextAsker asker) { m_frame->setTextAsker(std::move(asker)); }

    CheckoutRunner *runner() const { return m_runner; }
    CheckoutTableModel *points() const { return m_model; }
    QTableView *table() const { return m_table; }
    // The punch list's window once opened (nullptr before).
    CheckoutPunchDialog *punchDialog() const { return m_punchDialog; }
    QString messageText() const;

public Q_SLOTS:
    // Close, Esc, the window's button: an output forced is released first (the dialog closes
    // once the PLC confirmed it); results its file could not take ask first.
    void reject() override;
    // A new, empty checkout: the plan fields are edited again.
    void newCheckout();
    // Builds the plan from the fields when none is loaded, asks for the file it is saved in when
    // it has none, then watches the inputs.
    void start();
    void stop();
    bool openCheckout(const QString &path);
    // A plan CSV (the CLI's format and rules), or the imported names starting with `prefix`.
    bool importPlan(const QString &path);
    bool importNames(const QString &prefix);
    // PDF when the name ends in .pdf, CSV otherwise; in the UI's language.
    bool writeReport(const QString &path,
                     CheckoutReport::LineEnds ends = CheckoutReport::LineEnds::Lf);
    // The report's details (document id, revision, signatories), in a small dialog.
    void editDetails();
    void showPunchList();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void loadPlan(CheckoutPlan plan, const QString &done, bool imported = true);
    // The plan's info from the fields and the details; saved when it changed (not running).
    void applyInfo();
    CheckoutInfo infoFromFields() const;
    void showCurrent(int index);
    void showMessage(const QString &text, bool error);
    void updateControls();
    QString forcedText() const;
    QString pointText(int index) const;
    QMenu *reportMenu();
    QMenu *importMenu();

    CheckoutRunner *m_runner;
    CheckoutTableModel *m_model;
    ToolDialogFrame *m_frame;
    CheckoutKeys *m_keys = nullptr;
    QPointer<const SymbolNames> m_symbols;
    QPointer<CheckoutPunchDialog> m_punchDialog;
    bool m_loaded = false; // a plan is built, imported or opened (the fields show it)
    bool m_following = false;
    // Closed with an output forced: it closes once the release is confirmed.
    bool m_closing = false;
    // The report's details before a plan exists (and the plan's once it does).
    CheckoutInfo m_details;

    QLineEdit *m_ranges;
    QLineEdit *m_project;
    QLineEdit *m_customer;
    QLineEdit *m_engineer;
    QPushButton *m_new;
    QPushButton *m_open;
    QPushButton *m_import;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_detailsButton;
    QPushButton *m_punch;
    QPushButton *m_report;
    QLabel *m_summary;
    QTableView *m_table;
};

} // namespace Fatek
