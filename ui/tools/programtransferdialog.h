#pragma once

#include "core/commission/programtransfer.h"
#include "tooldialogframe.h"

#include <QDialog>
#include <QElapsedTimer>

class QLabel;
class QProgressBar;
class QPushButton;

namespace Fatek {

class RequestTracker;

// Tools → Program Backup / Restore…: the PLC's program to a file and back (core's
// ProgramTransfer over 4F/50). A restore checks the model first, then asks to switch a PLC in RUN
// to STOP, shows what it will write (model, size, the pages that differ) before it writes, offers
// RUN again once verified or, when it stopped the PLC, once it ends with nothing written (default
// No), says the PLC's state at the end, and is refused in operator mode.
class ProgramTransferDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ProgramTransferDialog(QWidget *parent = nullptr);

    // Without a direct link the dialog shows "no connection" and cannot start.
    void setTarget(const PlcTarget &target);
    // Tests answer the questions and pick the files (a backup saves, a restore opens) without
    // modal dialogs.
    void setConfirmer(Confirmer confirmer) { m_frame->setConfirmer(std::move(confirmer)); }
    void setFileChooser(ToolDialogFrame::FileChooser chooser)
    {
        m_frame->setFileChooser(std::move(chooser));
    }

    bool isRunning() const { return m_transfer->isRunning() || m_stopping; }
    QString messageText() const;
    bool messageIsError() const;
    QString progressText() const;

public Q_SLOTS:
    void backup();
    void restore();
    void cancel();

private:
    QString chooseFile(bool save);
    void startCheck();
    void onFinished(const ProgramTransferResult &result);
    void onProgress(int done, int total);
    // "Reading the program: 12 of 207 pages", without the time left.
    QString progressLine(int done, int total) const;
    void askToStop();
    // After a restore that verified, or one the dialog stopped the PLC for that wrote nothing:
    // RUN again? (default No). `done` the outcome, shown with the PLC's state either way.
    void offerRun(const QString &done, bool restored, bool error = false);
    // How a restore that wrote and did not verify ends: the PLC stays in STOP (its program may
    // be incomplete), and the message says so.
    void restoreFailed(const ProgramTransferResult &result);
    void showMessage(const QString &text, bool error);
    void updateControls();
    quint8 station() const { return m_frame->target().station(); }

    enum class Step { None, Backup, Check, Restore };

    ProgramTransfer *m_transfer;
    RequestTracker *m_requests; // 41 STOP when the person agrees
    ToolDialogFrame *m_frame;
    Step m_step = Step::None;
    bool m_stopping = false; // a STOP or RUN request is on its way
    bool m_askedStop = false;
    bool m_stoppedForRestore = false; // this restore switched the PLC to STOP
    QString m_path;
    ProgramImage m_image;
    QElapsedTimer m_elapsed;
    QString m_progressLine; // the last count, without the time left

    QLabel *m_modeLabel;
    QPushButton *m_backupButton;
    QPushButton *m_restoreButton;
    QPushButton *m_cancelButton;
    QProgressBar *m_progress;
    QLabel *m_progressLabel;
};

} // namespace Fatek
