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
#include "consolecontrol.h"
#endif

namespace Fatek {

#ifdef Q_OS_UNIX
namespace {
std::function<void()> g_onQuit;
QPointer<QObject> g_context;
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
void onQuitSignal(QObject *context, std::function<void()> onQuit)
{
    ConsoleControl::install(context, std::move(onQuit));
}

void onReloadSignal(QObject *, std::function<void()>) {}
#else
void onQuitSignal(QObject *, std::function<void()>) {}
void onReloadSignal(QObject *, std::function<void()>) {}
#endif

} // namespace Fatek
