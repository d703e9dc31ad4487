#pragma once

#include "core/session/sessionstatistics.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

namespace Fatek {

// The counters of one gateway connection, published (retained) on <prefix>/<conn>/statistics:
//   {"time":"...Z","link":"TCP 127.0.0.1:500, FACON",
//    "session":{"requests":..,"answers":..,"timeouts":..,"checksumErrors":..,"plcErrors":..,
//               "frameErrors":..,"retries":..,"bytesOut":..,"bytesIn":..,"rttLastMs":..,
//               "rttMeanMs":..,"rttP50Ms":..,"rttP99Ms":..,"pollCycles":..,"lastCycleMs":..,
//               "bytesDiscarded":..,"linkLosses":..},
//    "gateway":{"published":..,"superseded":..,"repliesDropped":..,"waiting":..,
//               "writesAccepted":..,"writesRefused":..,"writesFailed":..,"writesUnknown":..,
//               "delayP50Ms":..,"delayP99Ms":..,"delayMaxMs":..}}
struct GatewayStatistics
{
    quint64 published = 0;      // messages handed to the broker connection
    quint64 superseded = 0;     // states replaced before they went out (broker away or slow)
    quint64 repliesDropped = 0; // replies dropped because too many were waiting
    quint64 waiting = 0;        // messages waiting for the broker now
    quint64 writesAccepted = 0; // commands handed to the PLC link
    quint64 writesRefused = 0;  // commands refused by the gateway (read-only, allowlist, value)
    quint64 writesFailed = 0;   // accepted commands the PLC did not carry out (refused, read back)
    quint64 writesUnknown = 0;  // accepted commands whose outcome stayed unknown (no read-back)
    // From the PLC's answer to the item's hand-over to the broker connection, over the items
    // published since the previous statistics: how far behind the gateway is.
    qint64 delayP50Ms = 0;
    qint64 delayP99Ms = 0;
    qint64 delayMaxMs = 0;

    static QByteArray encode(const GatewayStatistics &gateway, const SessionStatistics &session,
                             const QString &link, const QDateTime &time);
};

} // namespace Fatek
