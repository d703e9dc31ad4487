#pragma once

#include "core/qtbridge/qtmessage.h"
#include "linksettings.h"

#include <QByteArray>
#include <QObject>

namespace Fatek {

// One byte pipe to the PLC(s), living in the session's worker thread. Opening is asynchronous:
// open() ends in opened() or in disconnected(reason); an open link that fails emits
// disconnected(reason) too. Datagram transports deliver each datagram in one bytesReceived().
class Transport : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    // A transport of the kind `settings` names; the caller owns it (parent may be null).
    static Transport *create(const LinkSettings &settings, QObject *parent = nullptr);

    virtual void open() = 0;
    // Closes without emitting disconnected(), gracefully (TCP: FIN, not RST). Bytes still unsent
    // are dropped: the session drains them first (unsentBytes(), allSent()) when it may.
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // Queues bytes for sending; false (and nothing sent) if the link is not open.
    virtual bool write(const QByteArray &bytes) = 0;
    // Bytes write() accepted that have not left this machine yet: Qt's buffer, and on a serial
    // port the driver's output queue where the system tells. 0 when everything is on the wire.
    virtual qint64 unsentBytes() const = 0;
    // Reads and returns bytes already received but not yet delivered (stale bytes before a query).
    virtual QByteArray takePending() = 0;
    // "TCP 127.0.0.1:500" for messages.
    virtual QString describe() const = 0;
    // "TCP 127.0.0.1:500: <the system's error text>", for disconnected().
    Message deviceError(const QString &systemText) const
    {
        return msg<MsgId::Joined>(describe().toStdString(),
                                  Message::text(systemText.toStdString()));
    }

Q_SIGNALS:
    void opened();
    void disconnected(const Fatek::Message &reason);
    void bytesReceived(const QByteArray &bytes);
    // unsentBytes() fell to 0 (emitted after a write() that could not finish at once).
    void allSent();
};

} // namespace Fatek
