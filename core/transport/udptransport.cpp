#include "udptransport.h"

#include <QNetworkDatagram>
#include <QUdpSocket>

namespace Fatek {

UdpTransport::UdpTransport(const LinkSettings &settings, QObject *parent)
    : SocketTransport(settings, Ending::Abort, parent)
{}

QUdpSocket *UdpTransport::udp() const
{
    return static_cast<QUdpSocket *>(socket()); // adopt()ed in open(): always a QUdpSocket
}

void UdpTransport::open()
{
    close();
    auto *udpSocket = new QUdpSocket(this);
    adopt(udpSocket);
    // A "connected" UDP socket resolves the host name once and drops datagrams from anyone else.
    connect(udpSocket, &QUdpSocket::connected, this, [this] {
        setOpen();
        Q_EMIT opened();
    });
    connect(udpSocket, &QUdpSocket::readyRead, this, [this] {
        // One signal per datagram: a datagram is one frame (or one piece of garbage).
        while (udp() && udp()->hasPendingDatagrams()) {
            const QNetworkDatagram datagram = udp()->receiveDatagram();
            if (!datagram.data().isEmpty())
                Q_EMIT bytesReceived(datagram.data());
        }
    });
    connect(udpSocket, &QUdpSocket::errorOccurred, this,
            [this](QAbstractSocket::SocketError error) {
                // An ICMP "port unreachable" only means this query got no answer: the session's
                // timeout reports it. Only a failure before the socket is usable ends the link.
                Q_UNUSED(error);
                if (isOpen())
                    return;
                const Message reason = deviceError(socket()->errorString());
                close();
                Q_EMIT disconnected(reason);
            });
    udpSocket->connectToHost(linkSettings().host, linkSettings().port);
}

qint64 UdpTransport::unsentBytes() const
{
    // A connected UDP socket is unbuffered: write() hands the datagram to the system at once.
    return 0;
}

QByteArray UdpTransport::readDatagrams()
{
    QByteArray all;
    while (udp() && udp()->hasPendingDatagrams())
        all += udp()->receiveDatagram().data();
    return all;
}

QByteArray UdpTransport::takePending()
{
    return readDatagrams();
}

QString UdpTransport::describe() const
{
    return QStringLiteral("UDP %1:%2").arg(linkSettings().host).arg(linkSettings().port);
}

} // namespace Fatek
