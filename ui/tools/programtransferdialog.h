#pragma once

#include "core/commission/programtransfer.h"
#include "ui/common/toolconfirmation.h"

#include <QDialog>
#include <QElapsedTimer>
#include <QPointer>

#include <functional>

class QLabel;
class QProgressBar;
class QPushButton;

namespace Fatek {

class MessageLine;
class RequestTracker;
class Session;

// Tools → Program Backup / Restore…: the PLC's program to a file and back (core's
// ProgramTransfer over 4F/50). A restore checks the model first, then asks to switch a PLC in RUN
// to STOP, shows what it will write (model, size, the pages that differ) before it writes, offers
// RUN again once verified or, when it stopped the PLC, once it ends with nothing written (default
// No), says the PLC's state at the end, and is refused in operator mode.
class ProgramTransferDialog : public QDialog
{
    Q_OBJECT

public:
    // Picks a file: `save` true for a backup. Empty: the person cancelled.
    using FileChooser = std::function<QString(bool save)>;

    explicit ProgramTransferDialog(QWidget *parent = nullptr);

    // session may be nullptr: the dialog shows "no connection" and cannot start.
    void setTarget(Fatek::Session *session, quint8 station, const QString &connectionName);
    // Tests answer the questions and pick the files without modal dialogs.
    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }

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

    enum class Step { None, Backup, Check, Restore };

    ProgramTransfer *m_transfer;
    RequestTracker *m_requests; // 41 STOP when the person agrees
    QPointer<Session> m_session;
    quint8 m_station = 1;
    QString m_connectionName;
    Confirmer m_confirmer;
    FileChooser m_chooser;
    Step m_step = Step::None;
    bool m_stopping = false; // a STOP or RUN request is on its way
    bool m_askedStop = false;
    bool m_stoppedForRestore = false; // this restore switched the PLC to STOP
    QString m_path;
    ProgramImage m_image;
    QElapsedTimer m_elapsed;
    QString m_progressLine; // the last count, without the time left

    QLabel *m_targetLabel;
    QLabel *m_modeLabel;
    QPushButton *m_backupButton;
    QPushButton *m_restoreButton;
    QPushButton *m_cancelButton;
    QProgressBar *m_progress;
    QLabel *m_progressLabel;
    MessageLine *m_message;
};

} // namespace Fatek
