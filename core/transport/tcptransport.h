#pragma once

#include "transport.h"

#include <QTimer>

class QTcpSocket;

namespace Fatek {

// TCP client with a connect timeout. Reconnecting is the session's job (it knows the backoff).
class TcpTransport final : public Transport
{
    Q_OBJECT

public:
    explicit TcpTransport(const LinkSettings &settings, QObject *parent = nullptr);
    ~TcpTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    bool write(const QByteArray &bytes) override;
    qint64 unsentBytes() const override;
    QByteArray takePending() override;
    QString describe() const override;

private:
    void fail(const Message &reason);
    // What the kernel holds now; `closed` set when the peer closed or the read failed.
    QByteArray readKernel(bool *closed);
    void failRead(); // after readKernel() said `closed`

    LinkSettings m_settings;
    QTcpSocket *m_socket = nullptr;
    QTimer m_connectTimer{this};
    bool m_open = false;
};

} // namespace Fatek
