#include "sockettransport.h"

#include <QAbstractSocket>
#include <QNetworkProxy>

namespace Fatek {

SocketTransport::SocketTransport(const LinkSettings &settings, Ending ending, QObject *parent)
    : Transport(parent)
    , m_settings(settings)
    , m_ending(ending)
{}

SocketTransport::~SocketTransport()
{
    // A subclass's own parts (a connect timer) are gone by now; the socket is closed here.
    SocketTransport::close();
}

void SocketTransport::adopt(QAbstractSocket *socket)
{
    m_socket = socket;
    // PLCs sit on the plant network: never route them through a desktop proxy setting.
    m_socket->setProxy(QNetworkProxy::NoProxy);
}

void SocketTransport::close()
{
    m_open = false;
    if (QAbstractSocket *socket = std::exchange(m_socket, nullptr)) {
        socket->disconnect(this);
        // Graceful once Qt's buffer is empty; what is still in it here is what the session gave
        // up on, and disconnectFromHost() would wait for it.
        if (m_ending == Ending::Graceful && socket->state() == QAbstractSocket::ConnectedState
            && socket->bytesToWrite() == 0)
            socket->disconnectFromHost();
        else
            socket->abort();
        socket->deleteLater();
    }
}

bool SocketTransport::isOpen() const
{
    return m_open;
}

bool SocketTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return false;
    // TCP is unbuffered: handed to the kernel now; what it did not take waits in Qt's buffer for
    // the write notifier, and allSent() comes when that has left. A connected UDP socket hands
    // the datagram to the system at once.
    return m_socket->write(bytes) == bytes.size();
}

} // namespace Fatek
