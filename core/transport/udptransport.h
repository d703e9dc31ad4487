#pragma once

#include "sockettransport.h"

class QUdpSocket;

namespace Fatek {

// UDP: one datagram per query, answers accepted only from the PLC's address and port. Datagrams
// are read at their real size (64 DR values in FACON are over 512 bytes).
class UdpTransport final : public SocketTransport
{
    Q_OBJECT

public:
    explicit UdpTransport(const LinkSettings &settings, QObject *parent = nullptr);

    void open() override;
    qint64 unsentBytes() const override;
    QByteArray takePending() override;
    QString describe() const override;

private:
    QUdpSocket *udp() const;
    QByteArray readDatagrams();
};

} // namespace Fatek
