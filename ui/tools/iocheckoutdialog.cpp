#include "iocheckoutdialog.h"

#include "checkouttablemodel.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/watch/osuser.h"
#include "core/watch/safefile.h"
#include "report/checkoutpdf.h"
#include "ui/common/uitext.h"

#include <QDateTime>
#include <QDir>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
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
    m_start = new QPushButton(tr("Start"), this);
    m_start->setObjectName(QStringLiteral("startButton"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_report = new QPushButton(tr("Report…"), this);
    m_report->setObjectName(QStringLiteral("reportButton"));
    m_report->setToolTip(tr("Write the report as PDF or CSV"));
    for (QPushButton *b : {m_new, m_open, m_start, m_stop, m_report})
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
    // Only the comment is edited: double-click or F2 (Space, F and N test the points).
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
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
    m_table->setToolTip(tr("Space: seen (an output is forced first), F: failed, N: next point, "
                           "L / H: analog low / high end"));
    m_table->installEventFilter(this);
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
    connect(m_report, &QPushButton::clicked, this, [this] {
        const QString path = m_frame->chooseFile(
            {true, tr("Checkout Report"), tr("PDF reports (*.pdf);;CSV files (*.csv)"), {}});
        if (!path.isEmpty())
            writeReport(path);
    });

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
    });
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
    if (m_frame->mayDiscard())
        QDialog::reject();
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
    const auto &points = m_runner->plan().points;
    if (index < 0 || index >= static_cast<int>(points.size()))
        return {};
    const CheckoutPoint &p = points[static_cast<std::size_t>(index)];
    return p.name.isEmpty()
               ? QString::fromStdString(p.address.toString())
               : tr("%1 (%2)").arg(QString::fromStdString(p.address.toString()), p.name);
}

void IoCheckoutDialog::newCheckout()
{
    stop();
    m_runner->setPlan(CheckoutPlan{});
    m_runner->setFilePath({});
    m_model->planReset();
    m_loaded = false;
    m_frame->clearMessage();
    updateControls();
    m_ranges->setFocus();
}

void IoCheckoutDialog::start()
{
    if (!m_frame->target().isDirect() || m_runner->isRunning())
        return;
    if (!m_loaded) {
        const auto plan = CheckoutPlan::fromRanges(m_ranges->text());
        if (!plan) {
            showMessage(translated(plan.error().message), true);
            return;
        }
        const QString path
            = m_frame->chooseFile({true, tr("Save Checkout"), tr("Checkouts (*.json)"), {}});
        if (path.isEmpty())
            return;
        CheckoutPlan p = plan.value();
        p.info.project = m_project->text();
        p.info.customer = m_customer->text();
        p.info.engineer = m_engineer->text();
        p.info.station = m_frame->target().station();
        p.info.created = QDateTime::currentDateTimeUtc();
        m_runner->setPlan(std::move(p));
        m_runner->setFilePath(path);
        m_model->planReset();
        m_loaded = true;
    }
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
    m_runner->setPlan(std::move(plan.value()));
    m_runner->setFilePath(path);
    m_model->planReset();
    m_loaded = true;
    showMessage(tr("Opened %1.").arg(QDir::toNativeSeparators(path)), false);
    updateControls();
    if (m_runner->hasForced()) {
        QStringList forced;
        for (const Address &a : m_runner->plan().forced)
            forced << QString::fromStdString(a.toString());
        const QString question = tr("The checkout left %1 forced on %2. Release them now?")
                                     .arg(forced.join(QStringLiteral(", ")), m_frame->targetText());
        if (m_frame->target().isDirect() && m_frame->ask(tr("Release Outputs"), question))
            start(); // start() releases them first
        else
            showMessage(tr("Still forced: %1 (Start releases them).")
                            .arg(forced.join(QStringLiteral(", "))),
                        true);
    }
    return true;
}

bool IoCheckoutDialog::writeReport(const QString &path)
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
        reason = SafeFile::write(path, report.toCsv(text));
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
    if (watched == m_table && event->type() == QEvent::KeyPress) {
        auto *key = static_cast<QKeyEvent *>(event);
        const int index = m_runner->currentPoint();
        // Plain keys only: Ctrl+N and the like stay the window's.
        if ((key->modifiers() & ~Qt::KeyboardModifiers(Qt::KeypadModifier)) != Qt::NoModifier)
            return QDialog::eventFilter(watched, event);
        switch (key->key()) {
        case Qt::Key_Space: pressSeen(index); return true;
        case Qt::Key_F: pressFailed(index); return true;
        case Qt::Key_N: m_runner->nextPoint(); return true;
        case Qt::Key_L:
        case Qt::Key_H:
            if (index >= 0
                && m_runner->plan().points[static_cast<std::size_t>(index)].kind
                       == CheckoutKind::Analog)
                m_runner->recordAnalog(index, key->key() == Qt::Key_H);
            return true;
        default: break;
        }
    }
    return QDialog::eventFilter(watched, event);
}

void IoCheckoutDialog::pressSeen(int index)
{
    if (index < 0 || !m_loaded)
        return;
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(index)];
    if (p.kind == CheckoutKind::Output) {
        if (m_runner->outputUnderTest() == index)
            m_runner->answerOutput(true);
        else
            force(index);
        return;
    }
    if (p.kind == CheckoutKind::Input)
        m_runner->record(index, CheckoutResult::Passed);
}

void IoCheckoutDialog::pressFailed(int index)
{
    if (index < 0 || !m_loaded)
        return;
    if (m_runner->outputUnderTest() == index)
        m_runner->answerOutput(false);
    else
        m_runner->record(index, CheckoutResult::Failed);
}

void IoCheckoutDialog::force(int index)
{
    if (!m_frame->target().isDirect() || !m_runner->isRunning())
        return;
    if (m_runner->outputUnderTest() >= 0) {
        showMessage(tr("Answer for %1 first (Space: seen, F: not seen).")
                        .arg(pointText(m_runner->outputUnderTest())),
                    true);
        return;
    }
    if (m_frame->target().isReadOnly()) {
        showMessage(tr("Operator mode: outputs are not forced."), true);
        return;
    }
    const QString question
        = tr("Force %1 on at %2? It stays on until you answer, then it is released.")
              .arg(pointText(index), m_frame->targetText());
    if (!m_frame->ask(tr("Force Output"), question)) {
        showMessage(tr("Not forced: nothing was written."), false);
        return;
    }
    m_runner->forceOutput(index);
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
        edit->setEnabled(!running);
    m_ranges->setEnabled(!running && !m_loaded);
    m_start->setEnabled(m_frame->target().isDirect() && !running);
    m_stop->setEnabled(running);
    // Another plan would forget an output whose release is still being tried.
    m_new->setEnabled(!running && !m_runner->isRetryingRelease());
    m_open->setEnabled(!running && !m_runner->isRetryingRelease());
    m_report->setEnabled(m_loaded);
    const CheckoutPlan &plan = m_runner->plan();
    m_summary->setText(plan.points.empty() ? QString()
                                           : translated(CheckoutReport::of(plan).summary));
}

} // namespace Fatek
