#pragma once

#include "core/link/plclink.h"
#include "core/protocol/request.h"
#include "core/session/sessiontypes.h"

#include <QMetaObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <optional>

namespace Fatek {

class Session;
class TrafficLog;

// What a commissioning tool acts on: one PLC (a station) behind a link, and the name of the
// connection it is reached through (for the tool's label and its questions). A value, copied
// into each tool. The link is held weakly: a closed connection leaves the target without a link
// (isDirect() false), never dangling.
class PlcTarget
{
public:
    // No target: the tools show "no connection".
    PlcTarget() = default;
    PlcTarget(PlcLink *link, quint8 station, const QString &connectionName);

    PlcLink *link() const { return m_link.data(); }
    quint8 station() const { return m_station; }
    QString connectionName() const { return m_connectionName; }

    // The tools can talk to the PLC: a direct link, still there. A gateway's connection (another
    // program owns the PLC's link) or none is not.
    bool isDirect() const { return session() != nullptr; }
    // Operator mode: the link refuses changes.
    bool isReadOnly() const;
    // How long the link waits for an answer, per attempt; 0 without a direct link.
    int timeoutMs() const;
    // The protocol the PLC was found to speak; nullopt until it answered (or without a link).
    std::optional<Protocol> protocol() const;
    // The protocol a frame goes out in: the one found, else the link's setting (FACON unless
    // binary was chosen).
    Protocol framing() const;
    // Every frame of the link (all its stations); nullptr without a direct link.
    TrafficLog *trafficLog() const;
    // Calls `slot` on `context`'s thread when the link has found the PLC's protocol; no
    // connection without a direct link.
    QMetaObject::Connection onProtocolDetected(QObject *context,
                                               const std::function<void()> &slot) const;
    // A change confirmed now by a person goes out no later than a timeout from now
    // (ChangeVerifier::confirmedNow).
    RequestOptions confirmedNow() const;

    // Hands this target's session to one of core's engines that run on a session
    // (RequestTracker, SnapshotReader, ValuesRestorer, ProgramTransfer, CheckoutRunner): the
    // one place a tool's session is passed on. nullptr without a direct link.
    template<typename Engine>
    void aim(Engine *engine) const
    {
        engine->setSession(session());
    }
    // The direct link's session, for the engines above and StationScanner; nullptr without one.
    Session *session() const;

    // The same PLC: the same link and station (the name is only how it is shown).
    bool isSamePlc(const PlcTarget &other) const
    {
        return m_link == other.m_link && m_station == other.m_station;
    }

private:
    QPointer<PlcLink> m_link;
    quint8 m_station = 1;
    QString m_connectionName;
};

} // namespace Fatek
