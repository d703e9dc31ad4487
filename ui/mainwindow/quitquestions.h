#pragma once

#include <QObject>
#include <QString>

namespace Fatek {

class ConnectionManager;
class MainWindow;
class WatchListDocument;

// What must be settled before the main window closes: a tool dialog's unsaved work, a watch list
// with unsaved changes or a data log running (asked first, as editors do), then writes to the PLC
// not sent yet (waited for while the window stays responsive, or dropped).
class QuitQuestions : public QObject
{
    Q_OBJECT

public:
    QuitQuestions(MainWindow *window, ConnectionManager *manager, WatchListDocument *document);

    // Whether the window may close now. False: it stays open; it asks again at the next close,
    // or closes itself once the writes it waits for are sent.
    bool mayClose();

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    // Each open tool dialog that holds unsaved work (a memory snapshot) asks its own question,
    // in front; false: Cancel, stay open. A dialog that holds the PLC (an I/O checkout's forced
    // output) releases it first; false meanwhile, and the window closes once it is done.
    bool settleToolDialogs();
    // Asks before quitting with unsaved tables or a running data log; false: stay open.
    bool confirmQuit();
    // Quitting with writes not sent yet: asks to wait for them or drop them; false: stay open.
    bool settlePendingWrites();

    MainWindow *m_window;
    ConnectionManager *m_manager;
    WatchListDocument *m_document;
    // Quit chosen, links draining their queued writes: the window closes once they are closed.
    bool m_quitting = false;
    // The unsaved-tables/logging question was answered for this quit.
    bool m_quitConfirmed = false;
};

} // namespace Fatek
