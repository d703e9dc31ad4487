#pragma once

#include "core/transport/linksettings.h"
#include "sessiontypes.h"

#include <QObject>
#include <QTimer>

#include <memory>

namespace Fatek {

struct SessionShared;
class Transport;

// Connection upkeep of the session's worker: the transport, opening it, the link state (also
// published in SessionShared) and reconnecting with a growing, jittered backoff.
class LinkKeeper : public QObject
{
    Q_OBJECT

public:
    LinkKeeper(const LinkSettings &settings, std::shared_ptr<SessionShared> shared,
               QObject *parent);

    LinkState state() const { return m_state; }
    // The link is open or meant to be (reopened after a loss).
    bool isWanted() const { return m_wantOpen; }
    // Null until the first open().
    Transport *transport() const { return m_transport; }
    // Connects now, also during a reconnect backoff; a no-op while connecting or connected.
    void open();
    // No reconnecting any more (a close was asked).
    void unwant();
    // unwant(), and the transport closed.
    void shutDown();
    // After a loss: the next attempt after the backoff if the link is wanted and the settings
    // reconnect (true), or Closed (false).
    bool reconnectOrClose(const Message &reason);
    void setState(LinkState state, const Message &reason);

Q_SIGNALS:
    void stateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    // The transport's, relayed (after the state became Connected, for opened()).
    void opened();
    void disconnected(const Fatek::Message &reason);
    void bytesReceived(const QByteArray &bytes);
    void allSent();

private:
    void startConnect();

    const LinkSettings &m_settings;
    std::shared_ptr<SessionShared> m_shared;
    Transport *m_transport = nullptr;
    LinkState m_state = LinkState::Closed;
    bool m_wantOpen = false;
    int m_backoffMs = 0;
    QTimer m_reconnectTimer{this};
};

} // namespace Fatek
