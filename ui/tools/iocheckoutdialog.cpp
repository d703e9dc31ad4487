#include "iocheckoutdialog.h"

#include "checkoutkeys.h"
#include "checkoutpunchdialog.h"
#include "checkouttablemodel.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/watch/osuser.h"
#include "core/watch/safefile.h"
#include "report/checkoutpdf.h"
#include "ui/common/symbolnames.h"
#include "ui/common/uitext.h"

#include <QDir>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

namespace Fatek {

IoCheckoutDialog::IoCheckoutDialog(QWidget *parent)
    : QDialog(parent)
    , m_runner(new CheckoutRunner(this))
    , m_model(new CheckoutTableModel(m_runner, this))
    // Closed: nothing stays forced, nothing polls behind the person's back.
    , m_frame(new ToolDialogFrame(this, 2, QStringLiteral("message"), [this] { stop(); }))
{
    setWindowTitle(tr("I/O Checkout"));
    m_runner->setAutoAdvance(true);
    m_frame->setSettling([this] {
        return m_runner->hasForced()
               && (m_runner->isRunning() || m_runner->isRetryingRelease() || m_closing);
    });
    QVBoxLayout *layout = m_frame->content();

    // The plan: its ranges and who it is for, side by side (a laptop's height goes to the table).
    auto *plan = new QHBoxLayout;
    auto *left = new QFormLayout;
    m_ranges = new QLineEdit(this);
    m_ranges->setObjectName(QStringLiteral("ranges"));
    m_ranges->setPlaceholderText(tr("X0..X15, Y0..Y7, R100"));
    left->addRow(tr("Points:"), m_ranges);
    m_project = new QLineEdit(this);
    m_project->setObjectName(QStringLiteral("project"));
    left->addRow(tr("Project:"), m_project);
    auto *right = new QFormLayout;
    m_customer = new QLineEdit(this);
    m_customer->setObjectName(QStringLiteral("customer"));
    right->addRow(tr("Customer:"), m_customer);
    m_engineer = new QLineEdit(this);
    m_engineer->setObjectName(QStringLiteral("engineer"));
    // Who records the results (the report names them): the login until someone types a name.
    m_engineer->setText(OsUser::name());
    right->addRow(tr("Engineer:"), m_engineer);
    plan->addLayout(left, 3);
    plan->addLayout(right, 2);
    layout->addLayout(plan);

    auto *buttons = new QHBoxLayout;
    m_new = new QPushButton(tr("New"), this);
    m_new->setObjectName(QStringLiteral("newButton"));
    m_open = new QPushButton(tr("Open…"), this);
    m_open->setObjectName(QStringLiteral("openButton"));
    m_import = new QPushButton(tr("Import…"), this);
    m_import->setObjectName(QStringLiteral("importButton"));
    m_import->setToolTip(tr("A plan from a CSV file, or from the names imported in the main "
                            "window"));
    m_import->setMenu(importMenu());
    m_start = new QPushButton(tr("Start"), this);
    m_start->setObjectName(QStringLiteral("startButton"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_detailsButton = new QPushButton(tr("Details…"), this);
    m_detailsButton->setObjectName(QStringLiteral("detailsButton"));
    m_detailsButton->setToolTip(tr("Document ID, revision and who signs the report"));
    m_punch = new QPushButton(tr("Punch List…"), this);
    m_punch->setObjectName(QStringLiteral("punchButton"));
    m_punch->setToolTip(tr("The failed and deferred points: owner, close-out, CSV"));
    m_report = new QPushButton(tr("Report…"), this);
    m_report->setObjectName(QStringLiteral("reportButton"));
    m_report->setToolTip(tr("Write the report as PDF or CSV"));
    m_report->setMenu(reportMenu());
    for (QPushButton *b :
         {m_new, m_open, m_import, m_start, m_stop, m_detailsButton, m_punch, m_report})
        buttons->addWidget(b);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("summary"));
    buttons->addWidget(m_summary, 1);
    layout->addLayout(buttons);

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("points"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    // Only the comment is edited: a double-click, or F2 anywhere on the row (CheckoutKeys).
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked);
    // What was measured takes the room: times and values read whole on one line.
    QHeaderView *header = m_table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(CheckoutTableModel::NameColumn, QHeaderView::Interactive);
    header->setSectionResizeMode(CheckoutTableModel::MeasuredColumn, QHeaderView::Stretch);
    header->setSectionResizeMode(CheckoutTableModel::CommentColumn, QHeaderView::Interactive);
    header->resizeSection(CheckoutTableModel::NameColumn, 140);
    header->resizeSection(CheckoutTableModel::CommentColumn, 180);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    // Compact rows: a laptop's screen shows a cabinet's points at once.
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->setToolTip(CheckoutKeys::hint());
    m_table->installEventFilter(this);
    m_keys = new CheckoutKeys(m_runner, m_frame, m_table, this);
    layout->addWidget(m_table, 1);
    auto *keys = new QLabel(m_table->toolTip(), this);
    keys->setObjectName(QStringLiteral("keys"));
    keys->setWordWrap(true);
    layout->addWidget(keys);

    connect(m_new, &QPushButton::clicked, this, &IoCheckoutDialog::newCheckout);
    connect(m_start, &QPushButton::clicked, this, &IoCheckoutDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &IoCheckoutDialog::stop);
    connect(m_open, &QPushButton::clicked, this, [this] {
        const QString path
            = m_frame->chooseFile({false, tr("Open Checkout"), tr("Checkouts (*.json)"), {}});
        if (!path.isEmpty())
            openCheckout(path);
    });
    connect(m_detailsButton, &QPushButton::clicked, this, &IoCheckoutDialog::editDetails);
    connect(m_punch, &QPushButton::clicked, this, &IoCheckoutDialog::showPunchList);

    // The table follows the point under test, and choosing a row tests that point.
    connect(m_runner, &CheckoutRunner::currentPointChanged, this, &IoCheckoutDialog::showCurrent);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                if (!m_following && current.isValid())
                    m_runner->setCurrentPoint(current.row());
            });
    connect(m_runner, &CheckoutRunner::pointChanged, this, [this] { updateControls(); });
    connect(m_runner, &CheckoutRunner::started, this, [this] {
        if (m_runner->currentPoint() < 0)
            m_runner->nextPoint();
        showMessage(tr("Watching the inputs: actuate %1 in the field.")
                        .arg(pointText(m_runner->currentPoint())),
                    false);
        updateControls();
    });
    connect(m_runner, &CheckoutRunner::outputForced, this, [this](int index) {
        m_model->refreshRow(index);
        showMessage(tr("%1 is forced on. Seen in the field? Space: seen, F: not seen.")
                        .arg(pointText(index)),
                    false);
    });
    connect(m_runner, &CheckoutRunner::outputReleased, this, [this](const Address &address) {
        showMessage(tr("%1 is released.").arg(QString::fromStdString(address.toString())), false);
        updateControls();
        // Closing: gone once the last release is confirmed (and saved), from the event loop.
        if (m_closing && !m_runner->hasForced())
            QTimer::singleShot(0, this, [this] {
                if (m_closing && !m_runner->hasForced() && m_frame->mayDiscard())
                    QDialog::reject();
            });
    });
    connect(m_runner, &CheckoutRunner::refused, this, [this](const Message &message) {
        showMessage(translated(message), true);
        updateControls();
    });
    connect(m_runner, &CheckoutRunner::readAgain, this,
            [this](const Message &message) { showMessage(translated(message), false); });
    connect(m_runner, &CheckoutRunner::runConfirmationNeeded, this,
            [this](int index, const Message &question) {
                // Asked from the event loop, not from inside the runner's answer; what the answer
                // did is the message shown after it.
                QTimer::singleShot(0, this, [this, index, text = translated(question)] {
                    if (!m_runner->isRunning())
                        return;
                    if (!m_frame->ask(tr("Force Output"), text)) {
                        showMessage(translated(msg<MsgId::CheckoutRunNotConfirmed>()), false);
                        return;
                    }
                    m_runner->allowOutputsInRun(true);
                    m_runner->forceOutput(index);
                });
            });
    connect(m_runner, &CheckoutRunner::crossedWiring, this,
            [this](int, int, const Message &message) { showMessage(translated(message), true); });
    connect(m_runner, &CheckoutRunner::failed, this, [this](const ProtocolError &error) {
        showMessage(translated(error.message), true);
        updateControls();
    });
    connect(m_runner, &CheckoutRunner::leftoversReleased, this,
            [this](const Message &message) { showMessage(translated(message), false); });
    connect(m_runner, &CheckoutRunner::saveFailed, this,
            [this](const Message &message) { showMessage(translated(message), true); });

    // The checkout saves itself after every answer; only results its file refused (a full disk,
    // a removed stick) are in no file, and are asked about before they go.
    m_frame->setUnsaved(
        [this] {
            const std::optional<Message> &error = m_runner->saveError();
            if (!m_loaded || !error)
                return QString();
            return tr("The latest results of the checkout are not saved: %1")
                .arg(translated(*error));
        },
        [this] {
            const QString path
                = m_frame->chooseFile({true, tr("Save Checkout"), tr("Checkouts (*.json)"), {}});
            if (path.isEmpty())
                return false;
            if (const Status s = CheckoutFile::saveToFile(m_runner->plan(), path); !s) {
                showMessage(translated(s.error().message), true);
                return false;
            }
            m_runner->setFilePath(path); // later answers go there too
            return true;
        });
    setTarget(PlcTarget());
    resize(980, 620);
}

void IoCheckoutDialog::reject()
{
    if (m_runner->hasForced()) {
        // Released first: the file is cleared once the PLC confirmed it, so the next Open has
        // nothing to ask (a runner destroyed now would never hear the answer).
        if (!m_closing && (m_runner->isRunning() || m_runner->isRetryingRelease())) {
            m_closing = true;
            stop();
            if (m_runner->hasForced()) {
                showMessage(tr("Releasing %1… the window closes once the PLC confirms it.")
                                .arg(forcedText()),
                            false);
                return;
            }
        } else if (!m_frame->ask(tr("Close I/O Checkout"),
                                 tr("%1 is not confirmed released on %2. Close anyway? The "
                                    "checkout file keeps it listed: the next Open releases it.")
                                     .arg(forcedText(), m_frame->targetText()))) {
            m_closing = false; // kept open: it no longer closes by itself
            updateControls();
            return;
        }
    }
    if (m_frame->mayDiscard())
        QDialog::reject();
}

QString IoCheckoutDialog::forcedText() const
{
    QStringList forced;
    for (const Address &a : m_runner->plan().forced)
        forced << QString::fromStdString(a.toString());
    return forced.join(QStringLiteral(", "));
}

IoCheckoutDialog::~IoCheckoutDialog() = default;

void IoCheckoutDialog::setTarget(const PlcTarget &target)
{
    if (m_runner->isRunning() && !target.isSamePlc(m_frame->target())) {
        stop();
        showMessage(tr("Stopped: the target changed."), true);
    }
    m_frame->setTarget(target, target.isReadOnly() ? tr("(operator mode: outputs are not forced)")
                                                   : QString());
    target.aim(m_runner);
    updateControls();
}

QString IoCheckoutDialog::messageText() const
{
    return m_frame->messageText();
}

QString IoCheckoutDialog::pointText(int index) const
{
    return CheckoutKeys::pointText(m_runner->plan(), index);
}

void IoCheckoutDialog::newCheckout()
{
    stop();
    m_runner->setPlan(CheckoutPlan{});
    m_runner->setFilePath({});
    m_model->planReset();
    m_loaded = false;
    m_details = CheckoutInfo{};
    m_frame->clearMessage();
    updateControls();
    m_ranges->setFocus();
}

void IoCheckoutDialog::start()
{
    if (!m_frame->target().isDirect() || m_runner->isRunning())
        return;
    if (!m_loaded) {
        const auto plan
            = CheckoutPlan::fromRanges(m_ranges->text(), m_symbols ? &m_symbols->table() : nullptr);
        if (!plan) {
            showMessage(translated(plan.error().message), true);
            return;
        }
        loadPlan(plan.value(), QString(), false);
    }
    if (m_runner->filePath().isEmpty()) {
        const QString path
            = m_frame->chooseFile({true, tr("Save Checkout"), tr("Checkouts (*.json)"), {}});
        if (path.isEmpty())
            return;
        m_runner->setFilePath(path);
    }
    applyInfo();
    m_runner->setEngineer(m_engineer->text());
    showMessage(tr("Reading the PLC's status…"), false);
    m_runner->start();
    updateControls();
    m_table->setFocus();
}

void IoCheckoutDialog::stop()
{
    if (m_runner->isRunning())
        m_runner->stop();
    updateControls();
}

bool IoCheckoutDialog::openCheckout(const QString &path)
{
    auto plan = CheckoutFile::loadFromFile(path);
    if (!plan) {
        showMessage(translated(plan.error().message), true);
        return false;
    }
    stop();
    m_ranges->clear();
    m_project->setText(plan->info.project);
    m_customer->setText(plan->info.customer);
    m_engineer->setText(plan->info.engineer.isEmpty() ? OsUser::name() : plan->info.engineer);
    m_details = plan->info;
    m_runner->setPlan(std::move(plan.value()));
    m_runner->setFilePath(path);
    m_model->planReset();
    m_loaded = true;
    showMessage(tr("Opened %1.").arg(QDir::toNativeSeparators(path)), false);
    updateControls();
    if (m_runner->hasForced()) {
        const QString question = tr("The checkout left %1 forced on %2. Release them now?")
                                     .arg(forcedText(), m_frame->targetText());
        if (m_frame->target().isDirect() && m_frame->ask(tr("Release Outputs"), question))
            start(); // start() releases them first
        else
            showMessage(tr("Still forced: %1 (Start releases them).").arg(forcedText()), true);
    }
    return true;
}

bool IoCheckoutDialog::writeReport(const QString &path, CheckoutReport::LineEnds ends)
{
    const CheckoutReport report = CheckoutReport::of(m_runner->plan());
    const auto text = [](const Message &m) {
        return translated(m);
    };
    QString reason;
    if (path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) {
        const Status s = CheckoutPdf::write(report, path, text);
        if (!s)
            reason = translated(s.error().message);
    } else {
        reason = SafeFile::write(path, report.toCsv(text, ends));
    }
    if (!reason.isEmpty()) {
        showMessage(reason, true);
        return false;
    }
    showMessage(tr("Report written: %1").arg(QDir::toNativeSeparators(path)), false);
    return true;
}

bool IoCheckoutDialog::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_table && event->type() == QEvent::KeyPress && m_loaded
        && m_keys->handle(static_cast<QKeyEvent *>(event)))
        return true;
    return QDialog::eventFilter(watched, event);
}

void IoCheckoutDialog::showCurrent(int index)
{
    if (index < 0 || index >= m_model->rowCount())
        return;
    // Chosen in the table already (a click, F2 on its comment): the cell stays where it is.
    const QModelIndex shown = m_table->currentIndex();
    if (shown.isValid() && shown.row() == index)
        return;
    m_following = true;
    const QModelIndex cell = m_model->index(
        index, shown.isValid() ? shown.column() : int(CheckoutTableModel::PointColumn));
    m_table->setCurrentIndex(cell);
    m_table->scrollTo(cell);
    m_following = false;
}

void IoCheckoutDialog::showMessage(const QString &text, bool error)
{
    m_frame->showMessage(text, error);
}

void IoCheckoutDialog::updateControls()
{
    const bool running = m_runner->isRunning();
    for (QLineEdit *edit : {m_ranges, m_project, m_customer, m_engineer})
        edit->setEnabled(!running && !m_closing);
    m_ranges->setEnabled(!running && !m_loaded && !m_closing);
    m_start->setEnabled(m_frame->target().isDirect() && !running && !m_closing);
    m_stop->setEnabled(running);
    // Another plan would forget an output whose release is still being tried.
    const bool mayReplace = !running && !m_runner->isRetryingRelease() && !m_closing;
    m_new->setEnabled(mayReplace);
    m_open->setEnabled(mayReplace);
    m_import->setEnabled(mayReplace);
    // The plan's info is the runner's while it runs: Stop first.
    m_detailsButton->setEnabled(!running && !m_closing);
    m_punch->setEnabled(m_loaded);
    m_report->setEnabled(m_loaded);
    const CheckoutPlan &plan = m_runner->plan();
    m_summary->setText(plan.points.empty() ? QString()
                                           : translated(CheckoutReport::of(plan).summary));
}

QMenu *IoCheckoutDialog::reportMenu()
{
    auto *menu = new QMenu(this);
    menu->setObjectName(QStringLiteral("reportMenu"));
    const auto add = [this, menu](const QString &text, const char *name, const QString &filter,
                                  CheckoutReport::LineEnds ends) {
        QAction *action = menu->addAction(text, this, [this, filter, ends] {
            const QString path = m_frame->chooseFile({true, tr("Checkout Report"), filter, {}});
            if (!path.isEmpty())
                writeReport(path, ends);
        });
        action->setObjectName(QLatin1String(name));
    };
    add(tr("PDF…"), "reportPdfAction", tr("PDF reports (*.pdf)"), CheckoutReport::LineEnds::Lf);
    add(tr("CSV…"), "reportCsvAction", tr("CSV files (*.csv)"), CheckoutReport::LineEnds::Lf);
    // Excel on Windows reads either; some programs there want CRLF.
    add(tr("CSV with Windows Line Ends…"), "reportCsvCrlfAction", tr("CSV files (*.csv)"),
        CheckoutReport::LineEnds::CrLf);
    return menu;
}
void IoCheckoutDialog::showPunchList()
{
    if (!m_punchDialog)
        m_punchDialog = new CheckoutPunchDialog(m_runner, m_frame, this);
    m_punchDialog->show();
    m_punchDialog->raise();
    m_punchDialog->activateWindow();
}

} // namespace Fatek
