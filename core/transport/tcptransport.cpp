#include "tcptransport.h"

#include <QTcpSocket>

#include <algorithm>

namespace Fatek {

TcpTransport::TcpTransport(const LinkSettings &settings, QObject *parent)
    : SocketTransport(settings, Ending::Graceful, parent)
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        fail(msg<MsgId::LinkNoConnectionWithin>(describe().toStdString(),
                                                linkSettings().connectTimeoutMs));
    });
}

void TcpTransport::open()
{
    close();
    auto *tcp = new QTcpSocket(this);
    adopt(tcp);
    connect(tcp, &QTcpSocket::connected, this, [this] {
        m_connectTimer.stop();
        setOpen();
        // Small queries: do not let Nagle hold them back.
        socket()->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        Q_EMIT opened();
    });
    connect(tcp, &QTcpSocket::bytesWritten, this, [this] {
        if (socket()->bytesToWrite() == 0)
            Q_EMIT allSent();
    });
    connect(tcp, &QTcpSocket::readyRead, this, [this] {
        bool closed = false;
        const QByteArray bytes = readKernel(&closed);
        if (!bytes.isEmpty())
            Q_EMIT bytesReceived(bytes);
        if (closed)
            failRead();
    });
    connect(tcp, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError error) {
        if (error == QAbstractSocket::RemoteHostClosedError)
            fail(msg<MsgId::LinkPeerClosed>(describe().toStdString()));
        else
            fail(deviceError(socket()->errorString()));
    });
    connect(tcp, &QTcpSocket::disconnected, this,
            [this] { fail(msg<MsgId::LinkPeerClosed>(describe().toStdString())); });
    m_connectTimer.start(linkSettings().connectTimeoutMs);
    // Unbuffered: a query goes to the kernel in the write() call itself. Buffered, Qt appends it
    // to its own buffer and switches the write notifier on and off around the flush; with the
    // glib event dispatcher each switch is a wake-up of the thread's own loop (an eventfd write,
    // a read and one more poll), about three system calls more per query than the send.
    tcp->connectToHost(linkSettings().host, linkSettings().port,
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
        const qint64 n = socket()->read(bytes.data() + have, chunk);
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
    if (!socket())
        return;
    if (socket()->error() == QAbstractSocket::RemoteHostClosedError)
        fail(msg<MsgId::LinkPeerClosed>(describe().toStdString()));
    else
        fail(deviceError(socket()->errorString()));
}

void TcpTransport::fail(const Message &reason)
{
    if (!socket())
        return; // already reported
    close();
    Q_EMIT disconnected(reason);
}

void TcpTransport::close()
{
    m_connectTimer.stop();
    SocketTransport::close();
}

qint64 TcpTransport::unsentBytes() const
{
    return socket() ? socket()->bytesToWrite() : 0;
}

QByteArray TcpTransport::takePending()
{
    if (!socket() || socket()->state() != QAbstractSocket::ConnectedState)
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
    return QStringLiteral("TCP %1:%2").arg(linkSettings().host).arg(linkSettings().port);
}

} // namespace Fatek
