#pragma once

#include "transport.h"

class QUdpSocket;

namespace Fatek {

// UDP: one datagram per query, answers accepted only from the PLC's address and port. Datagrams
// are read at their real size (64 DR values in FACON are over 512 bytes).
class UdpTransport final : public Transport
{
    Q_OBJECT

public:
    explicit UdpTransport(const LinkSettings &settings, QObject *parent = nullptr);
    ~UdpTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    bool write(const QByteArray &bytes) override;
    qint64 unsentBytes() const override;
    QByteArray takePending() override;
    QString describe() const override;

private:
    QByteArray readDatagrams();

    LinkSettings m_settings;
    QUdpSocket *m_socket = nullptr;
    bool m_open = false;
};

} // namespace Fatek
