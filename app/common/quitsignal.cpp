#include "quitsignal.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QObject>
#include <QPointer>

#ifdef Q_OS_UNIX
#include <QSocketNotifier>
#include <csignal>
#include <unistd.h>
#endif
#ifdef Q_OS_WIN
#include <windows.h>
#endif

namespace Fatek {

namespace {
std::function<void()> g_onQuit;
QPointer<QObject> g_context;
} // namespace

#ifdef Q_OS_UNIX
namespace {
// Self-pipe: the handler only writes the signal's number (async-signal-safe), the event loop
// reads it.
int g_signalPipe[2] = {-1, -1};
std::function<void()> g_onReload;

void onSignal(int signal)
{
    const auto c = static_cast<char>(signal);
    [[maybe_unused]] const auto n = ::write(g_signalPipe[1], &c, 1);
}
} // namespace

void onQuitSignal(QObject *context, std::function<void()> onQuit)
{
    if (g_signalPipe[0] >= 0 || ::pipe(g_signalPipe) != 0)
        return;
    g_onQuit = std::move(onQuit);
    g_context = context;
    auto *notifier = new QSocketNotifier(g_signalPipe[0], QSocketNotifier::Read, context);
    QObject::connect(notifier, &QSocketNotifier::activated, context, [] {
        char c = 0;
        if (::read(g_signalPipe[0], &c, 1) != 1)
            return;
        const std::function<void()> &handler = c == SIGHUP ? g_onReload : g_onQuit;
        if (handler)
            handler();
    });
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

void onReloadSignal(QObject *, std::function<void()> onReload)
{
    if (g_signalPipe[0] < 0)
        return;
    g_onReload = std::move(onReload);
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGHUP, &action, nullptr);
}
#elif defined(Q_OS_WIN)
namespace {
BOOL WINAPI onConsoleControl(DWORD event)
{
    // Runs on a thread of its own: hand over to the context's thread.
    if (g_context)
        QMetaObject::invokeMethod(
            g_context.data(),
            [] {
                if (g_onQuit)
                    g_onQuit();
            },
            Qt::QueuedConnection);
    // Closing the console window, logging off or shutting down ends the process as soon as the
    // handler returns: wait here instead, so that the clean stop (the gateway's "offline") runs;
    // the program's own exit ends this thread, and Windows kills a program that takes longer
    // than about 5 s.
    if (event == CTRL_CLOSE_EVENT || event == CTRL_LOGOFF_EVENT || event == CTRL_SHUTDOWN_EVENT)
        Sleep(INFINITE);
    return TRUE;
}
} // namespace

void onQuitSignal(QObject *context, std::function<void()> onQuit)
{
    g_onQuit = std::move(onQuit);
    g_context = context;
    SetConsoleCtrlHandler(onConsoleControl, TRUE);
}

void onReloadSignal(QObject *, std::function<void()>) {}
#else
void onQuitSignal(QObject *, std::function<void()>) {}
void onReloadSignal(QObject *, std::function<void()>) {}
#endif

} // namespace Fatek
