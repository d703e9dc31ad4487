#pragma once

// Wakes a thread that waits in poll() on a network socket, from another thread: a UDP socket
// on the loopback interface that sends to itself, polled beside the network socket. One
// mechanism for Linux and Windows, whose WSAPoll() takes sockets only (no pipes).

#ifdef _WIN32
#include <winsock2.h>
#else
#include <poll.h>
#endif

#include <string>

namespace Fatek {

class WakeSocket
{
public:
#ifdef _WIN32
    using Handle = SOCKET;
    static constexpr Handle InvalidHandle = INVALID_SOCKET;
#else
    using Handle = int;
    static constexpr Handle InvalidHandle = -1;
#endif

    WakeSocket() = default;
    ~WakeSocket();
    WakeSocket(const WakeSocket &) = delete;
    WakeSocket &operator=(const WakeSocket &) = delete;

    // Creates the socket; false (and error() says why) when the system refuses.
    bool open();
    bool isOpen() const
    {
        return m_handle != InvalidHandle;
    }
    Handle handle() const
    {
        return m_handle;
    }
    std::string error() const
    {
        return m_error;
    }

    // One datagram: the poll() that waits on handle() returns with POLLIN.
    void wake();
    // Reads what wake() sent, so that the next poll() waits again.
    void drain();

    // poll() on Linux, WSAPoll() on Windows.
    static int poll(pollfd *fds, unsigned count, int timeoutMs);

    // The system's words for a socket error: strerror() on Linux; on Windows the system message
    // of a Winsock code (WSAECONNREFUSED: "No connection could be made because the target
    // machine actively refused it."), which strerror() calls "Unknown error".
    static std::string errorText(int code);

private:
    Handle m_handle = InvalidHandle;
    std::string m_error;
};

} // namespace Fatek
