#pragma once

#include "sockettransport.h"

#include <QTimer>

namespace Fatek {

// TCP client with a connect timeout. Reconnecting is the session's job (it knows the backoff).
class TcpTransport final : public SocketTransport
{
    Q_OBJECT

public:
    explicit TcpTransport(const LinkSettings &settings, QObject *parent = nullptr);

    void open() override;
    void close() override;
    qint64 unsentBytes() const override;
    QByteArray takePending() override;
    QString describe() const override;

private:
    void fail(const Message &reason);
    // What the kernel holds now; `closed` set when the peer closed or the read failed.
    QByteArray readKernel(bool *closed);
    void failRead(); // after readKernel() said `closed`

    QTimer m_connectTimer{this};
};

} // namespace Fatek
