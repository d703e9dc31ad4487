#include "quitquestions.h"

#include "mainwindow.h"
#include "ui/connection/connectionmanager.h"
#include "ui/tools/tooldialogframe.h"
#include "ui/trend/tablelogger.h"
#include "watchlistdocument.h"

#include <QDialog>
#include <QDir>
#include <QMessageBox>
#include <QPushButton>

#include <algorithm>

namespace Fatek {

QuitQuestions::QuitQuestions(MainWindow *window, ConnectionManager *manager,
                             WatchListDocument *document)
    : QObject(window)
    , m_window(window)
    , m_manager(manager)
    , m_document(document)
{}

bool QuitQuestions::mayClose()
{
    // Unsaved tables and a running log first, as editors do; then writes not sent yet.
    if (!m_quitting && !m_quitConfirmed) {
        if (!settleToolDialogs() || !confirmQuit())
            return false;
        m_quitConfirmed = true;
    }
    const QList<Connection *> connections = m_manager->connections();
    const bool quitNow
        = m_quitting
              ? std::all_of(connections.begin(), connections.end(),
                            [](Connection *c) { return c->linkState() == LinkState::Closed; })
              : settlePendingWrites();
    if (!quitNow) {
        if (!m_quitting)
            m_quitConfirmed = false; // Cancel on the writes question: ask again next time
        return false;
    }
    m_quitConfirmed = false; // a window shown again asks again
    return true;
}

bool QuitQuestions::settleToolDialogs()
{
    for (ToolDialogFrame *frame : m_window->findChildren<ToolDialogFrame *>()) {
        if (!frame->hasUnsaved())
            continue;
        frame->dialog()->show();
        frame->dialog()->raise();
        frame->dialog()->activateWindow();
        if (!frame->mayDiscard())
            return false;
    }
    // A tool that holds the PLC (an output forced) undoes it first: its dialog closes once the
    // PLC confirmed it, and the window closes after it.
    for (ToolDialogFrame *frame : m_window->findChildren<ToolDialogFrame *>()) {
        if (!frame->isSettling())
            continue;
        QDialog *dialog = frame->dialog();
        dialog->show();
        dialog->raise();
        dialog->reject();
        if (!dialog->isVisible())
            continue;
        if (frame->isSettling())
            connect(dialog, &QDialog::finished, m_window, &MainWindow::close,
                    Qt::ConnectionType(Qt::QueuedConnection | Qt::SingleShotConnection));
        return false;
    }
    return true;
}

bool QuitQuestions::confirmQuit()
{
    const bool unsaved = m_document->isModified();
    const bool logging = m_window->tableLogger()->isLogging();
    if (!unsaved && !logging)
        return true;
    QStringList what;
    if (unsaved)
        what << tr("The watch list %1 has changes that are not saved.")
                    .arg(m_document->path().isEmpty()
                             ? tr("(untitled)")
                             : QDir::toNativeSeparators(m_document->path()));
    if (logging)
        what << tr("Data logging to %1 is running; quitting stops it.")
                    .arg(QDir::toNativeSeparators(m_window->tableLogger()->path()));
    QMessageBox box(QMessageBox::Question, tr("Quit FATEK Studio"), what.join(QLatin1Char('\n')),
                    QMessageBox::NoButton, m_window);
    box.setObjectName(QStringLiteral("quitQuestionBox"));
    QPushButton *save = nullptr;
    if (unsaved) {
        save = box.addButton(tr("&Save and Quit"), QMessageBox::AcceptRole);
        save->setObjectName(QStringLiteral("saveButton"));
    }
    QPushButton *quit
        = box.addButton(unsaved ? tr("Quit &Without Saving") : tr("Stop Logging and &Quit"),
                        QMessageBox::DestructiveRole);
    quit->setObjectName(QStringLiteral("quitButton"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    cancel->setObjectName(QStringLiteral("cancelButton"));
    // The safe answer is the default: Enter saves, or keeps the window open.
    box.setDefaultButton(save ? save : cancel);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == quit)
        return true;
    if (save && box.clickedButton() == save)
        return m_document->path().isEmpty() ? m_document->saveDialog()
                                            : bool(m_document->save(m_document->path()));
    return false;
}

bool QuitQuestions::settlePendingWrites()
{
    const QList<Connection *> connections = m_manager->connections();
    int pending = 0;
    int drainMs = 0;
    for (Connection *c : connections) {
        pending += c->pendingWrites();
        drainMs = std::max(drainMs, c->closeDrainMs());
    }
    if (pending == 0)
        return true;
    const int seconds = (drainMs + 999) / 1000;
    QMessageBox box(QMessageBox::Warning, tr("Writes not sent yet"),
                    tr("%n write(s) to the PLC have not been sent yet.", nullptr, pending),
                    QMessageBox::NoButton, m_window);
    box.setObjectName(QStringLiteral("pendingWritesBox"));
    box.setInformativeText(tr("Wait for them (at most %n second(s)), or drop them? Dropped writes "
                              "never reach the PLC.",
                              nullptr, seconds));
    QPushButton *wait = box.addButton(tr("&Wait and Quit"), QMessageBox::AcceptRole);
    wait->setObjectName(QStringLiteral("waitButton"));
    QPushButton *drop = box.addButton(tr("&Drop and Quit"), QMessageBox::DestructiveRole);
    drop->setObjectName(QStringLiteral("dropButton"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(wait);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == drop) {
        for (Connection *c : connections)
            c->closeDiscard();
        return true;
    }
    if (box.clickedButton() != wait)
        return false;
    // Non-blocking: the links drain while the window stays responsive; it closes when they are
    // all closed (each bounded by its drain time).
    m_quitting = true;
    Q_EMIT statusMessage(
        tr("Sending %n queued write(s) before quitting (at most %1 s)…", nullptr, pending)
            .arg(seconds));
    for (Connection *c : connections) {
        connect(c, &Connection::linkStateChanged, this, [this](LinkState state) {
            if (state != LinkState::Closed)
                return;
            const QList<Connection *> all = m_manager->connections();
            if (std::all_of(all.begin(), all.end(), [](const Connection *other) {
                    return other->linkState() == LinkState::Closed;
                }))
                m_window->close();
        });
        c->close();
    }
    return false;
}

} // namespace Fatek
