#include "programtransferdialog.h"

#include "core/commission/commissionmessages.h"
#include "core/protocol/plcstatus.h"
#include "core/session/requesttracker.h"
#include "ui/common/uitext.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace Fatek {

ProgramTransferDialog::ProgramTransferDialog(QWidget *parent)
    : QDialog(parent)
    , m_transfer(new ProgramTransfer(this))
    , m_requests(new RequestTracker(this))
    , m_frame(new ToolDialogFrame(this, 3, QStringLiteral("programMessage"), [this] { cancel(); }))
{
    setWindowTitle(tr("Program Backup / Restore"));
    QVBoxLayout *layout = m_frame->content();
    m_modeLabel = new QLabel(this);
    m_modeLabel->setObjectName(QStringLiteral("modeLabel"));
    m_modeLabel->setWordWrap(true);
    layout->addWidget(m_modeLabel);

    auto *buttons = new QHBoxLayout;
    m_backupButton = new QPushButton(tr("&Back Up to File…"), this);
    m_backupButton->setObjectName(QStringLiteral("backupButton"));
    m_backupButton->setToolTip(tr("Read the PLC's program (every page) and save it in a file"));
    m_restoreButton = new QPushButton(tr("&Restore from File…"), this);
    m_restoreButton->setObjectName(QStringLiteral("restoreButton"));
    m_cancelButton = new QPushButton(tr("Cancel"), this);
    m_cancelButton->setObjectName(QStringLiteral("cancelButton"));
    m_cancelButton->setToolTip(tr("Stop after the page in progress"));
    buttons->addWidget(m_backupButton);
    buttons->addWidget(m_restoreButton);
    buttons->addWidget(m_cancelButton);
    buttons->addStretch(1);
    layout->addLayout(buttons);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("progressBar"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    layout->addWidget(m_progress);
    m_progressLabel = new QLabel(this);
    m_progressLabel->setObjectName(QStringLiteral("progressLabel"));
    // Two lines kept for it: a longer count wraps instead of widening the dialog.
    m_progressLabel->setWordWrap(true);
    m_progressLabel->setMinimumHeight(2 * fontMetrics().lineSpacing());
    m_progressLabel->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    layout->addWidget(m_progressLabel);

    connect(m_backupButton, &QPushButton::clicked, this, &ProgramTransferDialog::backup);
    connect(m_restoreButton, &QPushButton::clicked, this, &ProgramTransferDialog::restore);
    connect(m_cancelButton, &QPushButton::clicked, this, &ProgramTransferDialog::cancel);
    connect(m_transfer, &ProgramTransfer::progress, this, &ProgramTransferDialog::onProgress);
    connect(m_transfer, &ProgramTransfer::finished, this, &ProgramTransferDialog::onFinished);
    connect(m_requests, &RequestTracker::sessionDestroyed, this,
            [this] { setTarget(PlcTarget(nullptr, station(), {})); });
    setTarget(PlcTarget());
    // A width of its own: room for the title beside a window manager's icon and buttons (a
    // narrow dialog shows "Program Backup /… e"), and no resizing while the texts change.
    const QFontMetrics fm = fontMetrics();
    setFixedWidth(std::max({sizeHint().width(),
                            fm.horizontalAdvance(windowTitle()) + 24 * fm.averageCharWidth(),
                            56 * fm.averageCharWidth()}));
}

void ProgramTransferDialog::setTarget(const PlcTarget &target)
{
    if (!target.isSamePlc(m_frame->target())) {
        if (m_transfer->isRunning())
            m_transfer->cancel();
        m_step = Step::None;
        m_stopping = false;
    }
    m_frame->setTarget(target);
    target.aim(m_requests);
    target.aim(m_transfer);
    m_transfer->setStation(target.station());
    updateControls();
}

QString ProgramTransferDialog::messageText() const
{
    return m_frame->messageText();
}

bool ProgramTransferDialog::messageIsError() const
{
    return m_frame->messageIsError();
}

QString ProgramTransferDialog::progressText() const
{
    return m_progressLabel->text();
}

QString ProgramTransferDialog::chooseFile(bool save)
{
    const QString filter = tr("Program backups (*.fprog *.json);;All files (*)");
    if (save)
        return m_frame->chooseFile(
            {true, tr("Back Up the PLC Program"), filter, QStringLiteral("plc-program.fprog")});
    return m_frame->chooseFile({false, tr("Restore a PLC Program"), filter, {}});
}

void ProgramTransferDialog::backup()
{
    if (!m_frame->target().isDirect() || isRunning())
        return;
    const QString path = chooseFile(true);
    if (path.isEmpty())
        return;
    m_path = path;
    m_step = Step::Backup;
    m_frame->clearMessage();
    m_elapsed.start();
    m_transfer->backup();
    updateControls();
}

void ProgramTransferDialog::restore()
{
    if (!m_frame->target().isDirect() || isRunning())
        return;
    if (m_frame->target().isReadOnly()) {
        showMessage(translated(msg<MsgId::ProgramReadOnly>()), true);
        return;
    }
    const QString path = chooseFile(false);
    if (path.isEmpty())
        return;
    const ProgramImage::LoadResult loaded = ProgramImage::load(path);
    if (!loaded.ok()) {
        showMessage(translated(loaded.error().message), true);
        return;
    }
    m_path = path;
    m_image = loaded.image();
    m_askedStop = false;
    m_stoppedForRestore = false;
    m_frame->clearMessage();
    startCheck();
}

void ProgramTransferDialog::startCheck()
{
    m_step = Step::Check;
    m_elapsed.start();
    m_transfer->checkRestore(m_image);
    updateControls();
}

void ProgramTransferDialog::cancel()
{
    if (m_transfer->isRunning())
        m_transfer->cancel();
}

void ProgramTransferDialog::askToStop()
{
    const QString question
        = tr("The PLC at %1 is in RUN. A program can only be written in STOP.\n\n"
             "Switch the PLC to STOP now?")
              .arg(m_frame->targetText());
    if (!m_frame->ask(tr("Restore Program"), question)) {
        showMessage(tr("Not restored: the PLC stays in RUN. Nothing was written."), false);
        return;
    }
    m_askedStop = true;
    m_stopping = true;
    updateControls();
    m_requests->submitChange(
        Request::runStop(station(), false),
        [this](const ChangeReport &r) {
            if (!r.final) {
                // Sent, not answered: the status is read back before anything else happens.
                showMessage(tr("STOP: %1").arg(translated(r.message)), true);
                return;
            }
            m_stopping = false;
            if (r.outcome != ChangeOutcome::Done) {
                showMessage(r.outcome == ChangeOutcome::Refused
                                ? tr("STOP failed: %1").arg(translated(r.message))
                                : tr("STOP: %1").arg(translated(r.message)),
                            true);
                updateControls();
                return;
            }
            m_stoppedForRestore = true;
            startCheck();
        },
        m_frame->target().confirmedNow());
}

void ProgramTransferDialog::offerRun(const QString &done, bool restored, bool error)
{
    // Default No: a program starts machinery; the person says when the machine is ready (an
    // Enter pressed by habit must not start it). The PLC is in STOP for the restore.
    const QString target = m_frame->targetText();
    const QString question
        = restored ? tr("%1\n\nSwitch the PLC at %2 to RUN now? It starts the restored program.")
                         .arg(done, target)
                   : tr("%1\n\nThe PLC at %2 was switched to STOP for the restore. Switch it back "
                        "to RUN now? It runs its program as before.")
                         .arg(done, target);
    if (!m_frame->ask(tr("Restore Program"), question)) {
        showMessage(
            tr("%1 The PLC stays in STOP: switch it to RUN when the machine is ready.").arg(done),
            error);
        return;
    }
    m_stopping = true;
    updateControls();
    m_requests->submitChange(
        Request::runStop(station(), true),
        [this, done, error](const ChangeReport &r) {
            if (!r.final) {
                showMessage(tr("%1 RUN: %2").arg(done, translated(r.message)), true);
                return;
            }
            m_stopping = false;
            updateControls();
            switch (r.outcome) {
            case ChangeOutcome::Done:
                showMessage(tr("%1 The PLC is in RUN.").arg(done), error);
                break;
            case ChangeOutcome::Refused:
                showMessage(
                    tr("%1 RUN failed: %2 The PLC stays in STOP.").arg(done, translated(r.message)),
                    true);
                break;
            case ChangeOutcome::Unknown:
                showMessage(tr("%1 RUN: %2").arg(done, translated(r.message)), true);
                break;
            }
        },
        m_frame->target().confirmedNow());
}

void ProgramTransferDialog::restoreFailed(const ProgramTransferResult &result)
{
    QString text = translated(result.message);
    // The interrupted write says it already (and what to do).
    if (result.message.id != MsgId::ProgramRestoreInterrupted)
        text = tr("%1 The PLC stays in STOP: check the program before switching it to RUN.")
                   .arg(text);
    showMessage(text, true);
}

void ProgramTransferDialog::onProgress(int done, int total)
{
    m_progress->setRange(0, qMax(1, total));
    m_progress->setValue(done);
    QString left;
    if (done > 0 && done < total) {
        const double perPage = double(m_elapsed.elapsed()) / done;
        const int seconds = qMax(1, int(perPage * (total - done) / 1000.0 + 0.5));
        left = tr(", about %n s left", nullptr, seconds);
    }
    m_progressLine = progressLine(done, total);
    m_progressLabel->setText(m_progressLine + left);
}

QString ProgramTransferDialog::progressLine(int done, int total) const
{
    // A restore counts every page twice, written then read back: each half is named (207 pages
    // are "writing 207, verifying 207", not "414 of 414 pages").
    if (m_step == Step::Restore && total > 0) {
        const int pages = total / 2;
        return tr("Writing %1 of %2 pages, verifying %3 of %2")
            .arg(qMin(done, pages))
            .arg(pages)
            .arg(qMax(0, done - pages));
    }
    return tr("%1: %2 of %3 pages")
        .arg(translated(ProgramTransfer::phaseMessage(m_transfer->phase())))
        .arg(done)
        .arg(total);
}

void ProgramTransferDialog::onFinished(const ProgramTransferResult &result)
{
    // Done, cancelled or failed: the count stays, the time left goes.
    m_progressLabel->setText(m_progressLine);
    const Step step = m_step;
    m_step = Step::None;
    updateControls();
    if (step == Step::Backup && result.ok()) {
        if (const auto error = m_transfer->plcImage().save(m_path)) {
            showMessage(translated(error->message), true);
            return;
        }
        showMessage(
            tr("%1 Saved in %2.").arg(translated(result.message), QFileInfo(m_path).fileName()),
            false);
        return;
    }
    if (step == Step::Check && result.ok()) {
        QString pages = translated(result.message);
        const QString question
            = tr("Write the program from %1 to the PLC at %2?\n\n"
                 "Backup: %3%4, %5 pages.\n%6\n\n"
                 "The PLC's program is replaced; every page is read back and compared.")
                  .arg(QFileInfo(m_path).fileName(), m_frame->targetText(),
                       translated(m_image.header().model()),
                       m_image.modelText().isEmpty()
                           ? QString()
                           : QStringLiteral(" (%1)").arg(m_image.modelText()))
                  .arg(m_image.pageCount())
                  .arg(pages);
        if (!m_frame->ask(tr("Restore Program"), question)) {
            const QString declined = tr("Not restored: nothing was written.");
            if (m_stoppedForRestore)
                return offerRun(declined, false);
            showMessage(declined, false);
            return;
        }
        m_step = Step::Restore;
        m_elapsed.start();
        m_transfer->restore(m_image);
        updateControls();
        return;
    }
    if (step == Step::Restore && result.ok()) {
        offerRun(translated(result.message), true);
        return;
    }
    // A restore that wrote a page (a write that failed may have too) did not verify.
    if (step == Step::Restore
        && (result.pagesDone > 0 || result.message.id == MsgId::ProgramRestoreInterrupted))
        return restoreFailed(result);
    if (step == Step::Check && result.problem == ProgramTransferResult::Problem::Running
        && !m_askedStop) {
        askToStop();
        return;
    }
    // Ended before writing (cancelled, the link): a PLC stopped for it may run again.
    if (step != Step::Backup && m_stoppedForRestore)
        return offerRun(translated(result.message), false, !result.ok());
    showMessage(translated(result.message), !result.ok());
}

void ProgramTransferDialog::showMessage(const QString &text, bool error)
{
    m_frame->showMessage(text, error);
}

void ProgramTransferDialog::updateControls()
{
    const bool connected = m_frame->target().isDirect();
    const bool busy = isRunning();
    const bool readOnly = connected && m_frame->target().isReadOnly();
    m_backupButton->setEnabled(connected && !busy);
    m_restoreButton->setEnabled(connected && !busy && !readOnly);
    m_restoreButton->setToolTip(
        readOnly ? tr("Read-only (operator) mode: restoring a program is disabled.")
                 : tr("Write a program backup to the PLC (it must be in STOP)"));
    m_modeLabel->setText(readOnly ? tr("Operator mode: a backup can be made; restoring a program "
                                       "is disabled.")
                                  : QString());
    m_modeLabel->setVisible(readOnly);
    m_cancelButton->setEnabled(m_transfer->isRunning());
}

} // namespace Fatek
