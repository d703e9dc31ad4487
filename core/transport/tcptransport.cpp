#include "tcptransport.h"

#include <QNetworkProxy>
#include <QTcpSocket>

#include <algorithm>

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
        bool closed = false;
        const QByteArray bytes = readKernel(&closed);
        if (!bytes.isEmpty())
            Q_EMIT bytesReceived(bytes);
        if (closed)
            failRead();
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
    // Unbuffered: a query goes to the kernel in the write() call itself. Buffered, Qt appends it
    // to its own buffer and switches the write notifier on and off around the flush; with the
    // glib event dispatcher each switch is a wake-up of the thread's own loop (an eventfd write,
    // a read and one more poll), about three system calls more per query than the send.
    m_socket->connectToHost(m_settings.host, m_settings.port,
                            QIODevice::ReadWrite | QIODevice::Unbuffered);
}

QByteArray TcpTransport::readKernel(bool *closed)
{
    // An unbuffered socket reads straight from the kernel: one read() when less than a chunk
    // came, which for a PLC's answer is always.
    constexpr qint64 chunk = 4096;
    QByteArray bytes;
    for (;;) {
        const qsizetype have = bytes.size();
        bytes.resize(have + chunk);
        const qint64 n = m_socket->read(bytes.data() + have, chunk);
        bytes.resize(have + std::max<qint64>(n, 0));
        if (n < 0) {
            // Unbuffered, Qt reports the peer's close (or a read error) only here, as -1, and
            // emits neither disconnected() nor errorOccurred() for it.
            *closed = true;
            break;
        }
        if (n < chunk)
            break;
    }
    return bytes;
}

void TcpTransport::failRead()
{
    if (!m_socket)
        return;
    if (m_socket->error() == QAbstractSocket::RemoteHostClosedError)
        fail(msg<MsgId::LinkPeerClosed>(describe().toStdString()));
    else
        fail(deviceError(m_socket->errorString()));
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
    // Unbuffered: handed to the kernel now; what it did not take waits in Qt's buffer for the
    // write notifier, and allSent() comes when that has left.
    return m_socket->write(bytes) == bytes.size();
}

qint64 TcpTransport::unsentBytes() const
{
    return m_socket ? m_socket->bytesToWrite() : 0;
}

QByteArray TcpTransport::takePending()
{
    if (!m_socket || m_socket->state() != QAbstractSocket::ConnectedState)
        return {};
    bool closed = false;
    QByteArray bytes = readKernel(&closed);
    if (closed) {
        // Reported from the event loop, not from inside the session's call to this.
        QMetaObject::invokeMethod(this, &TcpTransport::failRead, Qt::QueuedConnection);
    }
    return bytes;
}

QString TcpTransport::describe() const
{
    return QStringLiteral("TCP %1:%2").arg(m_settings.host).arg(m_settings.port);
}

} // namespace Fatek
