#include "wakesocket.h"

#ifdef _WIN32
#include <windows.h>
#include <ws2tcpip.h>
#else
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#endif

namespace Fatek {

namespace {

#ifdef _WIN32
std::string lastSocketError()
{
    return WakeSocket::errorText(WSAGetLastError());
}
void closeHandle(WakeSocket::Handle h)
{
    ::closesocket(h);
}
#else
std::string lastSocketError()
{
    return WakeSocket::errorText(errno);
}
void closeHandle(WakeSocket::Handle h)
{
    ::close(h);
}
#endif

} // namespace

WakeSocket::~WakeSocket()
{
    if (isOpen())
        closeHandle(m_handle);
}

bool WakeSocket::open()
{
    if (isOpen())
        return true;
#ifdef _WIN32
    // Counted by Windows: one more start-up beside libmosquitto's own is harmless.
    WSADATA data;
    if (const int rc = WSAStartup(MAKEWORD(2, 2), &data); rc != 0) {
        m_error = "Windows socket error " + std::to_string(rc);
        return false;
    }
    Handle h = ::socket(AF_INET, SOCK_DGRAM, IPPROTO_UDP);
#else
    Handle h = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
#endif
    if (h == InvalidHandle) {
        m_error = lastSocketError();
        return false;
    }
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;
    socklen_t length = sizeof address;
    // Bound to a free loopback port, then connected to itself: send() reaches its own queue.
    const bool ok = ::bind(h, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
                    && ::getsockname(h, reinterpret_cast<sockaddr *>(&address), &length) == 0
                    && ::connect(h, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0;
#ifdef _WIN32
    u_long nonBlocking = 1;
    // FIONBIO is an unsigned constant that ioctlsocket() takes as a long.
    const bool nonBlockingSet = ::ioctlsocket(h, static_cast<long>(FIONBIO), &nonBlocking) == 0;
#else
    const bool nonBlockingSet = true;
#endif
    if (!ok || !nonBlockingSet) {
        m_error = lastSocketError();
        closeHandle(h);
        return false;
    }
    m_handle = h;
    return true;
}

void WakeSocket::wake()
{
    const char byte = 1;
    [[maybe_unused]] const auto sent = ::send(m_handle, &byte, 1, 0);
}

void WakeSocket::drain()
{
    char bytes[64];
    while (::recv(m_handle, bytes, sizeof bytes, 0) > 0) {
    }
}

int WakeSocket::poll(pollfd *fds, unsigned count, int timeoutMs)
{
#ifdef _WIN32
    return ::WSAPoll(fds, count, timeoutMs);
#else
    return ::poll(fds, count, timeoutMs);
#endif
}

std::string WakeSocket::errorText(int code)
{
#ifdef _WIN32
    wchar_t *buffer = nullptr;
    const DWORD length = FormatMessageW(
        FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
        nullptr, static_cast<DWORD>(code), 0, reinterpret_cast<wchar_t *>(&buffer), 0, nullptr);
    std::string text;
    if (length > 0) {
        const int size = WideCharToMultiByte(CP_UTF8, 0, buffer, static_cast<int>(length), nullptr,
                                             0, nullptr, nullptr);
        text.resize(static_cast<std::size_t>(size));
        WideCharToMultiByte(CP_UTF8, 0, buffer, static_cast<int>(length), text.data(), size,
                            nullptr, nullptr);
        LocalFree(buffer);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
        text.pop_back();
    return text.empty() ? "Windows socket error " + std::to_string(code) : text;
#else
    return std::strerror(code);
#endif
}

} // namespace Fatek
