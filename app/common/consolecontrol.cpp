#include "consolecontrol.h"

#include <QMetaObject>
#include <QObject>
#include <QPointer>

#ifdef Q_OS_WIN
#include <windows.h>
#endif

namespace Fatek {

namespace {
std::function<void()> g_onQuit;
QPointer<QObject> g_context;
} // namespace

void ConsoleControl::install(QObject *context, std::function<void()> onQuit)
{
    g_onQuit = std::move(onQuit);
    g_context = context;
#ifdef Q_OS_WIN
    SetConsoleCtrlHandler(&ConsoleControl::systemHandler, TRUE);
#endif
}

ConsoleControl::Then ConsoleControl::handle(Event event)
{
    if (g_context)
        QMetaObject::invokeMethod(
            g_context.data(),
            [] {
                if (g_onQuit)
                    g_onQuit();
            },
            Qt::QueuedConnection);
    switch (event) {
    case Event::Interrupt:
    case Event::Break: return Then::Return;
    case Event::Close:
    case Event::Logoff:
    case Event::Shutdown: break;
    }
    return Then::HoldUntilExit;
}

#ifdef Q_OS_WIN
int __stdcall ConsoleControl::systemHandler(unsigned long event)
{
    Event e = Event::Interrupt;
    switch (event) {
    case CTRL_C_EVENT: e = Event::Interrupt; break;
    case CTRL_BREAK_EVENT: e = Event::Break; break;
    case CTRL_CLOSE_EVENT: e = Event::Close; break;
    case CTRL_LOGOFF_EVENT: e = Event::Logoff; break;
    case CTRL_SHUTDOWN_EVENT: e = Event::Shutdown; break;
    default: return FALSE; // not ours: the next handler, or the system's default
    }
    // (The program's own exit ends this thread.)
    if (handle(e) == Then::HoldUntilExit)
        Sleep(INFINITE);
    return TRUE;
}
#endif

} // namespace Fatek
