#include "gatewaystatistics.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace Fatek {

QByteArray GatewayStatistics::encode(const GatewayStatistics &gateway,
                                     const SessionStatistics &session, const QString &link,
                                     const QDateTime &time)
{
    const StationStatistics &t = session.total;
    const auto n = [](quint64 value) {
        return static_cast<double>(value);
    };
    const QJsonObject sessionJson{
        {QStringLiteral("requests"), n(t.requests)},
        {QStringLiteral("answers"), n(t.answers)},
        {QStringLiteral("timeouts"), n(t.timeouts)},
        {QStringLiteral("checksumErrors"), n(t.checksumErrors)},
        {QStringLiteral("plcErrors"), n(t.plcErrors)},
        {QStringLiteral("frameErrors"), n(t.frameErrors)},
        {QStringLiteral("retries"), n(t.retries)},
        {QStringLiteral("bytesOut"), n(t.bytesOut)},
        {QStringLiteral("bytesIn"), n(t.bytesIn)},
        {QStringLiteral("rttLastMs"), t.rttLastMs},
        {QStringLiteral("rttMeanMs"), t.rttMeanMs},
        {QStringLiteral("rttP50Ms"), t.rttP50Ms},
        {QStringLiteral("rttP99Ms"), t.rttP99Ms},
        {QStringLiteral("pollCycles"), n(session.pollCycles)},
        {QStringLiteral("lastCycleMs"), session.lastCycleMs},
        {QStringLiteral("bytesDiscarded"), n(session.bytesDiscarded)},
        {QStringLiteral("linkLosses"), n(session.linkLosses)},
    };
    // Per station: a silent one is demoted (issue 31); when it is tried again.
    QJsonArray stations;
    for (auto it = session.stations.cbegin(); it != session.stations.cend(); ++it) {
        const StationStatistics &s = it.value();
        QJsonObject station{
            {QStringLiteral("station"), it.key()},
            {QStringLiteral("requests"), n(s.requests)},
            {QStringLiteral("timeouts"), n(s.timeouts)},
            {QStringLiteral("unanswered"), n(s.unanswered)},
            {QStringLiteral("demoted"), s.demoted},
            {QStringLiteral("demotions"), n(s.demotions)},
        };
        if (s.demoted && s.nextTry.isValid())
            station.insert(QStringLiteral("nextTry"),
                           s.nextTry.toUTC().toString(Qt::ISODateWithMs));
        stations.append(station);
    }
    const QJsonObject gatewayJson{
        {QStringLiteral("published"), n(gateway.published)},
        {QStringLiteral("superseded"), n(gateway.superseded)},
        {QStringLiteral("repliesDropped"), n(gateway.repliesDropped)},
        {QStringLiteral("waiting"), n(gateway.waiting)},
        {QStringLiteral("writesAccepted"), n(gateway.writesAccepted)},
        {QStringLiteral("writesRefused"), n(gateway.writesRefused)},
        {QStringLiteral("writesFailed"), n(gateway.writesFailed)},
        {QStringLiteral("writesUnknown"), n(gateway.writesUnknown)},
        {QStringLiteral("delayP50Ms"), static_cast<double>(gateway.delayP50Ms)},
        {QStringLiteral("delayP99Ms"), static_cast<double>(gateway.delayP99Ms)},
        {QStringLiteral("delayMaxMs"), static_cast<double>(gateway.delayMaxMs)},
    };
    const QJsonObject object{
        {QStringLiteral("time"), time.toUTC().toString(Qt::ISODateWithMs)},
        {QStringLiteral("link"), link},
        {QStringLiteral("session"), sessionJson},
        {QStringLiteral("stations"), stations},
        {QStringLiteral("gateway"), gatewayJson},
    };
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

} // namespace Fatek
