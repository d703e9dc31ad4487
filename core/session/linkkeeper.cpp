#include "linkkeeper.h"

#include "core/transport/transport.h"
#include "sessionshared.h"

#include <QRandomGenerator>

#include <algorithm>

namespace Fatek {

LinkKeeper::LinkKeeper(const LinkSettings &settings, std::shared_ptr<SessionShared> shared,
                       QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_shared(std::move(shared))
{
    m_reconnectTimer.setSingleShot(true);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &LinkKeeper::startConnect);
}

void LinkKeeper::open()
{
    m_wantOpen = true;
    if (m_state == LinkState::Connecting || m_state == LinkState::Connected)
        return;
    m_reconnectTimer.stop(); // "connect now" during a reconnect backoff
    const Message problem = m_settings.validate();
    if (!problem.empty()) {
        m_wantOpen = false;
        setState(LinkState::Closed, problem);
        return;
    }
    m_backoffMs = m_settings.reconnectMinMs;
    startConnect();
}

void LinkKeeper::startConnect()
{
    if (!m_wantOpen)
        return;
    if (!m_transport) {
        m_transport = Transport::create(m_settings, this);
        connect(m_transport, &Transport::opened, this, [this] {
            m_backoffMs = m_settings.reconnectMinMs;
            setState(LinkState::Connected, Message::text(m_transport->describe().toStdString()));
            Q_EMIT opened();
        });
        connect(m_transport, &Transport::disconnected, this, &LinkKeeper::disconnected);
        connect(m_transport, &Transport::bytesReceived, this, &LinkKeeper::bytesReceived);
        connect(m_transport, &Transport::allSent, this, &LinkKeeper::allSent);
    }
    setState(LinkState::Connecting, Message::text(m_transport->describe().toStdString()));
    m_transport->open();
}

void LinkKeeper::unwant()
{
    m_wantOpen = false;
    m_reconnectTimer.stop();
}

void LinkKeeper::shutDown()
{
    unwant();
    if (m_transport)
        m_transport->close();
}

bool LinkKeeper::reconnectOrClose(const Message &reason)
{
    if (m_wantOpen && m_settings.autoReconnect) {
        // Up to a quarter longer, at random: the links of a gateway (or a studio) that lost
        // their PLCs together do not all come back in the same instant.
        const int delay
            = m_backoffMs
              + static_cast<int>(QRandomGenerator::global()->bounded(m_backoffMs / 4 + 1));
        m_backoffMs = std::min(m_settings.reconnectMaxMs, m_backoffMs * 2);
        setState(LinkState::Reconnecting,
                 msg<MsgId::LinkNextAttempt>(
                     reason, QString::number(delay / 1000.0, 'f', 1).toStdString()));
        m_reconnectTimer.start(delay);
        return true;
    }
    m_wantOpen = false;
    setState(LinkState::Closed, reason);
    return false;
}

void LinkKeeper::setState(LinkState state, const Message &reason)
{
    m_state = state;
    m_shared->linkState.store(static_cast<int>(state));
    Q_EMIT stateChanged(state, reason);
}

} // namespace Fatek
