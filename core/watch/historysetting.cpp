#include "historysetting.h"

// History settings of watch items: their checks and their part of the watch list file.

#include "watchlist.h"
#include "watchlisterrors.h"

#include <QJsonObject>
#include <QStringList>

#include <cmath>

namespace Fatek::HistorySettings {

using WatchList::Errors::fileError;

namespace {

constexpr QLatin1String DeadbandKey("deadband");
constexpr QLatin1String HeartbeatKey("heartbeatS");

// Every key of a history object; anything else is a typing error refused by name.
const QStringList &knownKeys()
{
    static const QStringList keys{DeadbandKey, HeartbeatKey};
    return keys;
}

ProtocolError historyError(const ProtocolError &error)
{
    return WatchList::Errors::atPlace(QStringLiteral("history"), error);
}

QString heartbeatRange()
{
    return QStringLiteral("a whole number of seconds from %1 to %2")
        .arg(HistorySetting::MinHeartbeatS)
        .arg(HistorySetting::MaxHeartbeatS);
}

QString negative(double deadband)
{
    return QStringLiteral("the deadband %1 is negative").arg(QString::number(deadband, 'g', 15));
}

} // namespace

Status validate(const WatchItemSpec &item)
{
    if (!item.history)
        return Ok{};
    const HistorySetting &h = *item.history;
    if (!std::isfinite(h.deadband))
        return historyError(fileError(QStringLiteral("the deadband must be a number")));
    if (h.deadband < 0)
        return historyError(fileError(negative(h.deadband)));
    const int width = ValueFormat::valueWidth(item.address, item.format);
    if (h.deadband > 0 && (width <= 1 || item.format == DisplayFormat::Ascii)) {
        // A bit or text changes or does not: every change is kept.
        return historyError(
            fileError(QStringLiteral("an item shown as %1 has no deadband (every change is kept)")
                          .arg(ValueFormat::name(item.format))));
    }
    if (h.heartbeatS < HistorySetting::MinHeartbeatS
        || h.heartbeatS > HistorySetting::MaxHeartbeatS) {
        return historyError(
            fileError(QStringLiteral("the heartbeat must be %1").arg(heartbeatRange())));
    }
    return Ok{};
}

Result<std::optional<HistorySetting>> fromJson(const QJsonValue &value,
                                               const std::function<int(const QString &)> &keyLine)
{
    if (value.isUndefined())
        return std::optional<HistorySetting>{};
    if (!value.isObject())
        return fileError(QStringLiteral("\"history\" must be a JSON object"));
    const QJsonObject object = value.toObject();
    const auto at = [&](const QString &key, const QString &text) {
        const int l = keyLine ? keyLine(key) : 0;
        const ProtocolError e
            = l > 0 ? fileError(QStringLiteral("line %1: %2").arg(l).arg(text)) : fileError(text);
        return historyError(e);
    };
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!knownKeys().contains(it.key())) {
            return at(it.key(), WatchList::Errors::unknownKey(it.key(), knownKeys()));
        }
    }

    HistorySetting setting;
    const QJsonValue deadband = object.value(DeadbandKey);
    if (!deadband.isUndefined()) {
        if (!deadband.isDouble() || !std::isfinite(deadband.toDouble()))
            return at(DeadbandKey, QStringLiteral("\"deadband\" must be a number"));
        setting.deadband = deadband.toDouble();
        if (setting.deadband < 0)
            return at(DeadbandKey, negative(setting.deadband));
    }
    const QJsonValue heartbeat = object.value(HeartbeatKey);
    if (!heartbeat.isUndefined()) {
        const double s = heartbeat.toDouble();
        if (!heartbeat.isDouble() || std::floor(s) != s || s < HistorySetting::MinHeartbeatS
            || s > HistorySetting::MaxHeartbeatS) {
            return at(HeartbeatKey,
                      QStringLiteral("\"heartbeatS\" must be %1").arg(heartbeatRange()));
        }
        setting.heartbeatS = static_cast<int>(s);
    }
    return std::optional<HistorySetting>{setting};
}

QJsonValue toJson(const HistorySetting &setting)
{
    return QJsonObject{{DeadbandKey, setting.deadband}, {HeartbeatKey, setting.heartbeatS}};
}

} // namespace Fatek::HistorySettings
