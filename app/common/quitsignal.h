#pragma once

#include <functional>

class QObject;

namespace Fatek {

// Calls onQuit in the event loop of context's thread when the user asks the program to stop: Ctrl-C
// or SIGTERM on Unix, Ctrl-C / Ctrl-Break / closing the console on Windows. The handler is
// installed even where the signal was ignored at start: a program started in the background by a
// script without job control inherits an ignored SIGINT, and must still stop cleanly when told.
// Call once per program.
void onQuitSignal(QObject *context, std::function<void()> onQuit);

// Calls onReload in the event loop of context's thread on SIGHUP (Unix; elsewhere nothing is
// installed): the daemon convention for "read your configuration again" (systemctl reload).
// Call after onQuitSignal, once per program.
void onReloadSignal(QObject *context, std::function<void()> onReload);

} // namespace Fatek
