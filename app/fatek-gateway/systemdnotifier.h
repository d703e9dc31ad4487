#pragma once

#include <QByteArray>
#include <QObject>
#include <QTimer>

namespace Fatek {

// The service manager protocol of systemd (sd_notify(3)) without libsystemd: each state is one
// datagram to the unix socket named by $NOTIFY_SOCKET ('@' first: an abstract socket). Under
// Type=notify the gateway says READY=1 once its links run, RELOADING=1/READY=1 around a reload
// and STOPPING=1; with WatchdogSec= ($WATCHDOG_USEC) it sends WATCHDOG=1 from the event loop
// at half the interval, so a hung loop gets the service restarted. Without $NOTIFY_SOCKET
// (started by hand, or not on Linux) every call does nothing.
class SystemdNotifier : public QObject
{
    Q_OBJECT

public:
    explicit SystemdNotifier(QObject *parent = nullptr);

    bool isActive() const { return !m_socket.isEmpty(); }
    // Sends `state` ("READY=1", ...); false when there is nobody to tell or it did not go.
    bool notify(const QByteArray &state) const;
    // RELOADING=1 with the reload's start (READY=1 ends it).
    bool reloading() const;
    // Starts WATCHDOG=1 at half of $WATCHDOG_USEC when that is set for this process.
    void startWatchdog();
    int watchdogIntervalMs() const { return m_watchdog.interval(); }

private:
    QByteArray m_socket;
    QTimer m_watchdog;
};

} // namespace Fatek
