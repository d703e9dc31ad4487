#include "gatewayhistoryconfig.h"

#include "core/history/historymessages.h"
#include "core/history/historystore.h"
#include "core/qtbridge/secrets.h"
#include "gatewaymessages.h"

namespace Fatek::GatewayConfigRead {

namespace {

bool isPostgresUrl(const QString &store)
{
    // As HistoryStore::open tells them: any case.
    return store.startsWith(QLatin1String("postgresql://"), Qt::CaseInsensitive)
           || store.startsWith(QLatin1String("postgres://"), Qt::CaseInsensitive);
}

GatewayConfigProblem readRetention(const QJsonObject &json, HistoryRetention *out)
{
    Reader r(json);
    // 100 years at most: a number that still fits every clock arithmetic.
    if (const std::optional<qint64> days = r.integer(QStringLiteral("days"), 0, 36500))
        out->maxAgeS = *days * 24 * 3600;
    if (const std::optional<qint64> mb = r.integer(QStringLiteral("maxMB"), 0, 1LL << 30))
        out->maxBytes = *mb * 1024 * 1024;
    r.rejectUnknown();
    return r.problem;
}

} // namespace

GatewayConfigProblem readHistory(const QJsonObject &json, const QString &baseDirectory,
                                 GatewayConfig::History *out)
{
    Reader r(json);
    const bool storeGiven = r.has(QStringLiteral("store"));
    const QString store = r.string(QStringLiteral("store"));
    const bool recordAll = r.boolean(QStringLiteral("recordAll"), false);
    HistorySetting setting;
    const bool deadbandGiven = r.has(QStringLiteral("deadband"));
    if (const std::optional<double> d
        = r.number(QStringLiteral("deadband"), 0, std::numeric_limits<double>::max()))
        setting.deadband = *d;
    const bool heartbeatGiven = r.has(QStringLiteral("heartbeatS"));
    r.integerInto(QStringLiteral("heartbeatS"), HistorySetting::MinHeartbeatS,
                  HistorySetting::MaxHeartbeatS, &setting.heartbeatS);
    const QJsonObject retention = r.object(QStringLiteral("retention"), false);
    r.rejectUnknown();
    if (r.problem)
        return r.problem;
    // The defaults of the recorded items only mean something when every item is recorded.
    if (!recordAll && (deadbandGiven || heartbeatGiven))
        return msg<MsgId::GatewayConfigHistoryDefaultsUnused>(deadbandGiven ? "deadband"
                                                                            : "heartbeatS");
    if (recordAll)
        out->recordAll = setting;
    if (GatewayConfigProblem p = readRetention(retention, &out->retention))
        return at(Message::text("retention"), *p);
    if (storeGiven && store.trimmed().isEmpty())
        return msg<MsgId::GatewayConfigEmptyFile>("store");
    if (!storeGiven) {
        out->store = GatewayConfig::defaultHistoryStore(baseDirectory);
    } else if (isPostgresUrl(store)) {
        // A password in the file would be shown by every --check and log line: refused first,
        // in the user info or as a "password=" parameter, and never quoted.
        if (Secrets::holdsPassword(store))
            return msg<MsgId::GatewayConfigHistoryPassword>();
        if (!HistoryStore::hasPostgres())
            return msg<MsgId::HistoryNoPostgres>(Secrets::maskUrl(store).toStdString());
        out->store = store;
    } else {
        out->store = resolve(baseDirectory, store);
    }
    return std::nullopt;
}

} // namespace Fatek::GatewayConfigRead
