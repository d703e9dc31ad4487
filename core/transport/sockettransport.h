#pragma once

#include "transport.h"

class QAbstractSocket;

namespace Fatek {

// A transport over a Qt network socket (TCP, UDP): the one owner of the socket's lifetime and of
// closing, the open flag and writing. The subclasses make the socket and read from it.
class SocketTransport : public Transport
{
    Q_OBJECT

public:
    ~SocketTransport() override;

    void close() override;
    bool isOpen() const override;
    bool write(const QByteArray &bytes) override;

protected:
    // How close() ends a connected socket that has nothing left to send.
    enum class Ending {
        Graceful, // TCP: FIN after what the kernel holds, not RST
        Abort,
    };

    SocketTransport(const LinkSettings &settings, Ending ending, QObject *parent);

    // `socket` (a child of this, made after close()) is the link's from now on.
    void adopt(QAbstractSocket *socket);
    QAbstractSocket *socket() const { return m_socket; }
    const LinkSettings &linkSettings() const { return m_settings; }
    // The socket is usable: write() sends from now on.
    void setOpen() { m_open = true; }

private:
    LinkSettings m_settings;
    Ending m_ending;
    QAbstractSocket *m_socket = nullptr;
    bool m_open = false;
};

} // namespace Fatek
