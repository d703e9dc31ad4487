#include "tcptransport.h"

#include <QNetworkProxy>
#include <QTcpSocket>

namespace Fatek {

TcpTransport::TcpTransport(const LinkSettings &settings, QObject *parent)
    : Transport(parent)
    , m_settings(settings)
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        fail(msg<MsgId::LinkNoConnectionWithin>(describe().toStdString(),
                                                m_settings.connectTimeoutMs));
    });
}

TcpTransport::~TcpTransport()
{
    close();
}

void TcpTransport::open()
{
    close();
    m_socket = new QTcpSocket(this);
    // PLCs sit on the plant network: never route them through a desktop proxy setting.
    m_socket->setProxy(QNetworkProxy::NoProxy);
    connect(m_socket, &QTcpSocket::connected, this, [this] {
        m_connectTimer.stop();
        m_open = true;
        // Small queries: do not let Nagle hold them back.
        m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        Q_EMIT opened();
    });
    connect(m_socket, &QTcpSocket::bytesWritten, this, [this] {
        if (m_socket->bytesToWrite() == 0)
            Q_EMIT allSent();
    });
    connect(m_socket, &QTcpSocket::readyRead, this, [this] {
        const QByteArray bytes = m_socket->readAll();
        if (!bytes.isEmpty())
            Q_EMIT bytesReceived(bytes);
    });
    connect(m_socket, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError error) {
        if (error == QAbstractSocket::RemoteHostClosedError)
            fail(msg<MsgId::LinkPeerClosed>(describe().toStdString()));
        else
            fail(deviceError(m_socket->errorString()));
    });
    connect(m_socket, &QTcpSocket::disconnected, this,
            [this] { fail(msg<MsgId::LinkPeerClosed>(describe().toStdString())); });
    m_connectTimer.start(m_settings.connectTimeoutMs);
    m_socket->connectToHost(m_settings.host, m_settings.port);
}

void TcpTransport::fail(const Message &reason)
{
    if (!m_socket)
        return; // already reported
    close();
    Q_EMIT disconnected(reason);
}

void TcpTransport::close()
{
    m_connectTimer.stop();
    m_open = false;
    if (QTcpSocket *socket = std::exchange(m_socket, nullptr)) {
        socket->disconnect(this);
        // Graceful (FIN after what the kernel holds) once Qt's buffer is empty; what is still in
        // it here is what the session gave up on, and disconnectFromHost() would wait for it.
        if (socket->state() == QAbstractSocket::ConnectedState && socket->bytesToWrite() == 0)
            socket->disconnectFromHost();
        else
            socket->abort();
        socket->deleteLater();
    }
}

bool TcpTransport::isOpen() const
{
    return m_open;
}

bool TcpTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return false;
    if (m_socket->write(bytes) != bytes.size())
        return false;
    // Handed to the kernel now, not when the write notifier fires on a later turn of the event
    // loop (a turn more per query). allSent() may come from inside this call.
    m_socket->flush();
    return true;
}

qint64 TcpTransport::unsentBytes() const
{
    return m_socket ? m_socket->bytesToWrite() : 0;
}

QByteArray TcpTransport::takePending()
{
    return m_socket ? m_socket->readAll() : QByteArray();
}

QString TcpTransport::describe() const
{
    return QStringLiteral("TCP %1:%2").arg(m_settings.host).arg(m_settings.port);
}

} // namespace Fatek
