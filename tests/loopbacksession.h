#pragma once

#include "core/session/session.h"

#include <QDeadlineTimer>
#include <QTest>

#include <memory>

namespace TestUtil {

// A Session on the simulator listening on loopback TCP `port` (FACON, no reconnects), opened and
// waited for (up to 10 s: the caller checks linkState()).
inline std::unique_ptr<Fatek::Session> openLoopbackSession(quint16 port, int timeoutMs, int retries)
{
    using namespace Fatek;
    LinkSettings settings
        = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port, LinkSettings::ProtocolChoice::Facon);
    settings.timeoutMs = timeoutMs;
    settings.retries = retries;
    settings.autoReconnect = false;
    auto session = std::make_unique<Session>(settings);
    session->open();
    QDeadlineTimer deadline(10000);
    while (session->linkState() != LinkState::Connected && !deadline.hasExpired())
        QTest::qWait(2);
    return session;
}

} // namespace TestUtil
