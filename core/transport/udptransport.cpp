#include "udptransport.h"

#include <QNetworkDatagram>
#include <QNetworkProxy>
#include <QUdpSocket>

namespace Fatek {

UdpTransport::UdpTransport(const LinkSettings &settings, QObject *parent)
    : Transport(parent)
    , m_settings(settings)
{}

UdpTransport::~UdpTransport()
{
    close();
}

void UdpTransport::open()
{
    close();
    m_socket = new QUdpSocket(this);
    // PLCs sit on the plant network: never route them through a desktop proxy setting.
    m_socket->setProxy(QNetworkProxy::NoProxy);
    // A "connected" UDP socket resolves the host name once and drops datagrams from anyone else.
    connect(m_socket, &QUdpSocket::connected, this, [this] {
        m_open = true;
        Q_EMIT opened();
    });
    connect(m_socket, &QUdpSocket::readyRead, this, [this] {
        // One signal per datagram: a datagram is one frame (or one piece of garbage).
        while (m_socket && m_socket->hasPendingDatagrams()) {
            const QNetworkDatagram datagram = m_socket->receiveDatagram();
            if (!datagram.data().isEmpty())
                Q_EMIT bytesReceived(datagram.data());
        }
    });
    connect(m_socket, &QUdpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError error) {
        // An ICMP "port unreachable" only means this query got no answer: the session's timeout
        // reports it. Only a failure before the socket is usable ends the link.
        Q_UNUSED(error);
        if (m_open)
            return;
        const Message reason = deviceError(m_socket->errorString());
        close();
        Q_EMIT disconnected(reason);
    });
    m_socket->connectToHost(m_settings.host, m_settings.port);
}

void UdpTransport::close()
{
    m_open = false;
    if (QUdpSocket *socket = std::exchange(m_socket, nullptr)) {
        socket->disconnect(this);
        socket->abort();
        socket->deleteLater();
    }
}

bool UdpTransport::isOpen() const
{
    return m_open;
}

bool UdpTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return false;
    return m_socket->write(bytes) == bytes.size();
}

qint64 UdpTransport::unsentBytes() const
{
    // A connected UDP socket is unbuffered: write() hands the datagram to the system at once.
    return 0;
}

QByteArray UdpTransport::readDatagrams()
{
    QByteArray all;
    while (m_socket && m_socket->hasPendingDatagrams())
        all += m_socket->receiveDatagram().data();
    return all;
}

QByteArray UdpTransport::takePending()
{
    return readDatagrams();
}

QString UdpTransport::describe() const
{
    return QStringLiteral("UDP %1:%2").arg(m_settings.host).arg(m_settings.port);
}

} // namespace Fatek
