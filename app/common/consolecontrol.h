#pragma once

#include <functional>

class QObject;

namespace Fatek {

// What a console program does when the console asks it to stop (Windows: Ctrl-C, Ctrl-Break,
// closing the console window, log-off, shut-down; onQuitSignal installs it there). Portable, so
// that the suite checks it on every platform: Wine delivers no console event to a program.
class ConsoleControl
{
public:
    enum class Event { Interrupt, Break, Close, Logoff, Shutdown };
    enum class Then {
        Return,        // the program goes on and stops by itself
        HoldUntilExit, // the system ends the process when the handler returns: it must not
    };

    // onQuit is to run in context's thread (its event loop).
    static void install(QObject *context, std::function<void()> onQuit);
    // Called on the system's thread: queues onQuit to the context's thread and says whether the
    // caller must hold that thread until the program's own exit.
    static Then handle(Event event);

#ifdef _WIN32
    // The handler SetConsoleCtrlHandler is given (a PHANDLER_ROUTINE): handle(), then, for close,
    // log-off and shut-down, waits for the program's exit, so that a clean stop (the gateway's
    // "offline") goes out before Windows ends the process (about 5 s later at most).
    static int __stdcall systemHandler(unsigned long event);
#endif
};

} // namespace Fatek
