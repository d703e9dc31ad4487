#include "systemdnotifier.h"

#include <QCoreApplication>

#include <algorithm>

#ifdef Q_OS_LINUX
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <ctime>
#endif

namespace Fatek {

SystemdNotifier::SystemdNotifier(QObject *parent)
    : QObject(parent)
{
#ifdef Q_OS_LINUX
    m_socket = qgetenv("NOTIFY_SOCKET");
#endif
    connect(&m_watchdog, &QTimer::timeout, this, [this] { notify("WATCHDOG=1"); });
}

bool SystemdNotifier::notify(const QByteArray &state) const
{
#ifdef Q_OS_LINUX
    sockaddr_un address = {};
    address.sun_family = AF_UNIX;
    if (m_socket.isEmpty() || m_socket.size() >= static_cast<qsizetype>(sizeof address.sun_path)
        || (m_socket[0] != '/' && m_socket[0] != '@'))
        return false;
    std::memcpy(address.sun_path, m_socket.constData(), static_cast<std::size_t>(m_socket.size()));
    if (m_socket[0] == '@')
        address.sun_path[0] = '\0'; // abstract: the name's length counts, no terminating zero
    const auto length
        = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + std::size_t(m_socket.size()));
    const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return false;
    const ssize_t sent = ::sendto(fd, state.constData(), std::size_t(state.size()), MSG_NOSIGNAL,
                                  reinterpret_cast<const sockaddr *>(&address), length);
    ::close(fd);
    return sent == state.size();
#else
    Q_UNUSED(state)
    return false;
#endif
}

bool SystemdNotifier::reloading() const
{
#ifdef Q_OS_LINUX
    // systemd 253 and later (Type=notify-reload) want the reload's start on CLOCK_MONOTONIC.
    timespec now = {};
    clock_gettime(CLOCK_MONOTONIC, &now);
    const qint64 usec = qint64(now.tv_sec) * 1000000 + now.tv_nsec / 1000;
    return notify("RELOADING=1\nMONOTONIC_USEC=" + QByteArray::number(usec));
#else
    return false;
#endif
}

void SystemdNotifier::startWatchdog()
{
#ifdef Q_OS_LINUX
    bool ok = false;
    const qulonglong usec = qEnvironmentVariable("WATCHDOG_USEC").toULongLong(&ok);
    if (!isActive() || !ok || usec == 0)
        return;
    // WATCHDOG_PID, when set, names the process meant (a child inherits the environment).
    const QString pid = qEnvironmentVariable("WATCHDOG_PID");
    if (!pid.isEmpty() && pid.toLongLong() != QCoreApplication::applicationPid())
        return;
    m_watchdog.start(static_cast<int>(std::clamp<qulonglong>(usec / 2000, 1, 3600000)));
    notify("WATCHDOG=1");
#endif
}

} // namespace Fatek
