#include "alarmdefinition.h"

// Alarm definitions of watch items: names, checks and their part of the watch list file.

#include "watchlist.h"
#include "watchlisterrors.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>

#include <array>
#include <cmath>

namespace Fatek::Alarms {

using WatchList::Errors::fileError;

namespace {

struct KindName
{
    AlarmKind kind;
    const char *name;
    const char *text; // after the item's name in a default message
};

constexpr std::array<KindName, 7> kindNames{{
    {AlarmKind::HighHigh, "highHigh", "high-high"},
    {AlarmKind::High, "high", "high"},
    {AlarmKind::Low, "low", "low"},
    {AlarmKind::LowLow, "lowLow", "low-low"},
    {AlarmKind::On, "on", "on"},
    {AlarmKind::Off, "off", "off"},
    {AlarmKind::Quality, "quality", "not read"},
}};

constexpr std::array<std::pair<AlarmPriority, const char *>, 4> priorityNames{{
    {AlarmPriority::Critical, "critical"},
    {AlarmPriority::High, "high"},
    {AlarmPriority::Medium, "medium"},
    {AlarmPriority::Low, "low"},
}};

// Every key of an alarm object; anything else is a typing error refused by name.
const QStringList &knownKeys()
{
    static const QStringList keys{
        QStringLiteral("type"),      QStringLiteral("limit"),      QStringLiteral("deadband"),
        QStringLiteral("onDelayMs"), QStringLiteral("offDelayMs"), QStringLiteral("priority"),
        QStringLiteral("message"),   QStringLiteral("group"),      QStringLiteral("enabled"),
    };
    return keys;
}

QString kindNames_joined()
{
    QStringList names;
    for (const KindName &k : kindNames)
        names.append(QLatin1String(k.name));
    return names.join(QStringLiteral(", "));
}

QString numberText(double value)
{
    return QString::number(value, 'g', 15);
}

ProtocolError alarmError(qsizetype index, const QString &text)
{
    return WatchList::Errors::atPlace(QStringLiteral("alarm %1").arg(index + 1), fileError(text));
}

// One alarm object; `line` names the line of a key (0: not known).
Result<AlarmDefinition> alarmFromJson(const QJsonValue &value,
                                      const std::function<int(const QString &)> &line)
{
    if (!value.isObject())
        return fileError(QStringLiteral("an alarm must be a JSON object"));
    const QJsonObject object = value.toObject();
    const auto at = [&](const QString &key, const QString &text) {
        const int l = line ? line(key) : 0;
        return l > 0 ? fileError(QStringLiteral("line %1: %2").arg(l).arg(text)) : fileError(text);
    };
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!knownKeys().contains(it.key())) {
            return at(it.key(), WatchList::Errors::unknownKey(it.key(), knownKeys()));
        }
    }

    AlarmDefinition alarm;
    const QJsonValue type = object.value(QStringLiteral("type"));
    if (!type.isString())
        return fileError(
            QStringLiteral("the \"type\" is missing (one of: %1)").arg(kindNames_joined()));
    const auto kind = kindFromName(type.toString());
    if (!kind) {
        return at(QStringLiteral("type"), QStringLiteral("unknown type \"%1\" (known: %2)")
                                              .arg(type.toString(), kindNames_joined()));
    }
    alarm.kind = *kind;

    const auto number = [&](const QString &key, double &target) -> Status {
        const QJsonValue v = object.value(key);
        if (v.isUndefined())
            return Ok{};
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return at(key, QStringLiteral("\"%1\" must be a number").arg(key));
        target = v.toDouble();
        return Ok{};
    };
    const auto delay = [&](const QString &key, int &target) -> Status {
        const QJsonValue v = object.value(key);
        if (v.isUndefined())
            return Ok{};
        const double d = v.toDouble();
        if (!v.isDouble() || std::floor(d) != d || d < 0 || d > MaxDelayMs) {
            return at(key, QStringLiteral("\"%1\" must be a whole number of milliseconds from 0 "
                                          "to %2")
                               .arg(key)
                               .arg(MaxDelayMs));
        }
        target = static_cast<int>(d);
        return Ok{};
    };
    const auto text = [&](const QString &key, QString &target) -> Status {
        const QJsonValue v = object.value(key);
        if (v.isUndefined())
            return Ok{};
        if (!v.isString())
            return at(key, QStringLiteral("\"%1\" must be text").arg(key));
        target = v.toString();
        return Ok{};
    };

    if (isLimitKind(alarm.kind)) {
        if (!object.contains(QStringLiteral("limit")))
            return fileError(QStringLiteral("a %1 alarm needs a \"limit\"").arg(type.toString()));
    } else if (object.contains(QStringLiteral("limit"))) {
        return at(QStringLiteral("limit"),
                  QStringLiteral("a %1 alarm has no \"limit\"").arg(type.toString()));
    }
    if (Status s = number(QStringLiteral("limit"), alarm.limit); !s)
        return s.error();
    if (Status s = number(QStringLiteral("deadband"), alarm.deadband); !s)
        return s.error();
    if (Status s = delay(QStringLiteral("onDelayMs"), alarm.onDelayMs); !s)
        return s.error();
    if (Status s = delay(QStringLiteral("offDelayMs"), alarm.offDelayMs); !s)
        return s.error();
    QString priority;
    if (Status s = text(QStringLiteral("priority"), priority); !s)
        return s.error();
    if (!priority.isEmpty()) {
        const auto p = priorityFromName(priority);
        if (!p) {
            return at(QStringLiteral("priority"),
                      QStringLiteral("unknown priority \"%1\" (known: critical, high, medium, low)")
                          .arg(priority));
        }
        alarm.priority = *p;
    }
    if (Status s = text(QStringLiteral("message"), alarm.message); !s)
        return s.error();
    if (Status s = text(QStringLiteral("group"), alarm.group); !s)
        return s.error();
    const QJsonValue enabled = object.value(QStringLiteral("enabled"));
    if (!enabled.isUndefined()) {
        if (!enabled.isBool())
            return at(QStringLiteral("enabled"),
                      QStringLiteral("\"enabled\" must be true or false"));
        alarm.enabled = enabled.toBool();
    }
    return alarm;
}

} // namespace

QString kindName(AlarmKind kind)
{
    for (const KindName &k : kindNames) {
        if (k.kind == kind)
            return QLatin1String(k.name);
    }
    return {};
}

std::optional<AlarmKind> kindFromName(const QString &name)
{
    for (const KindName &k : kindNames) {
        if (name == QLatin1String(k.name))
            return k.kind;
    }
    return std::nullopt;
}

QList<AlarmKind> allKinds()
{
    QList<AlarmKind> kinds;
    for (const KindName &k : kindNames)
        kinds.append(k.kind);
    return kinds;
}

QString priorityName(AlarmPriority priority)
{
    for (const auto &[p, name] : priorityNames) {
        if (p == priority)
            return QLatin1String(name);
    }
    return {};
}

std::optional<AlarmPriority> priorityFromName(const QString &name)
{
    for (const auto &[p, text] : priorityNames) {
        if (name == QLatin1String(text))
            return p;
    }
    return std::nullopt;
}

bool isLimitKind(AlarmKind kind)
{
    return kind == AlarmKind::HighHigh || kind == AlarmKind::High || kind == AlarmKind::Low
           || kind == AlarmKind::LowLow;
}

bool isBitKind(AlarmKind kind)
{
    return kind == AlarmKind::On || kind == AlarmKind::Off;
}

QString alarmId(const WatchItemSpec &item, AlarmKind kind)
{
    return WatchList::itemId(item) + QLatin1Char('-') + kindName(kind);
}

QString defaultMessage(const WatchItemSpec &item, AlarmKind kind)
{
    const QString who
        = item.name.isEmpty() ? QString::fromStdString(item.address.toString()) : item.name;
    for (const KindName &k : kindNames) {
        if (k.kind == kind)
            return who + QLatin1Char(' ') + QLatin1String(k.text);
    }
    return who;
}

QString messageOf(const WatchItemSpec &item, const AlarmDefinition &alarm)
{
    return alarm.message.isEmpty() ? defaultMessage(item, alarm.kind) : alarm.message;
}

Status validate(const WatchItemSpec &item)
{
    const int width = ValueFormat::valueWidth(item.address, item.format);
    const bool hasNumber = width > 1 && item.format != DisplayFormat::Ascii;
    QList<AlarmKind> seen;
    std::optional<double> limits[4]; // by AlarmKind HighHigh..LowLow
    for (qsizetype i = 0; i < item.alarms.size(); ++i) {
        const AlarmDefinition &a = item.alarms.at(i);
        const QString kind = kindName(a.kind);
        if (seen.contains(a.kind))
            return alarmError(
                i, QStringLiteral("a second %1 alarm (one of each type per item)").arg(kind));
        seen.append(a.kind);
        if (isLimitKind(a.kind) && !hasNumber) {
            return alarmError(i, QStringLiteral("a %1 alarm needs a number: this item is shown "
                                                "as %2")
                                     .arg(kind, ValueFormat::name(item.format)));
        }
        if (isBitKind(a.kind) && width != 1)
            return alarmError(
                i, QStringLiteral("an %1 alarm is for a bit (X, Y, M, S, T, C)").arg(kind));
        if (!std::isfinite(a.limit) || !std::isfinite(a.deadband))
            return alarmError(i, QStringLiteral("the limit and deadband must be numbers"));
        if (a.deadband < 0)
            return alarmError(
                i, QStringLiteral("the deadband %1 is negative").arg(numberText(a.deadband)));
        if (a.deadband > 0 && !isLimitKind(a.kind))
            return alarmError(i, QStringLiteral("a %1 alarm has no deadband").arg(kind));
        if (a.onDelayMs < 0 || a.offDelayMs < 0 || a.onDelayMs > MaxDelayMs
            || a.offDelayMs > MaxDelayMs) {
            return alarmError(i,
                              QStringLiteral("the delays must be from 0 to %1 ms").arg(MaxDelayMs));
        }
        if (isLimitKind(a.kind))
            limits[static_cast<int>(a.kind)] = a.limit;
    }
    // Nested limits: low-low <= low < high <= high-high, where given.
    const auto &hh = limits[static_cast<int>(AlarmKind::HighHigh)];
    const auto &h = limits[static_cast<int>(AlarmKind::High)];
    const auto &l = limits[static_cast<int>(AlarmKind::Low)];
    const auto &ll = limits[static_cast<int>(AlarmKind::LowLow)];
    const auto above = [](const char *a, double va, const char *b, double vb) {
        return fileError(
            QStringLiteral("the %1 limit %2 is above the %3 limit %4")
                .arg(QLatin1String(a), numberText(va), QLatin1String(b), numberText(vb)));
    };
    if (h && hh && *h > *hh)
        return above("high", *h, "high-high", *hh);
    if (ll && l && *ll > *l)
        return above("low-low", *ll, "low", *l);
    const std::optional<double> lowest = l ? l : ll;
    const std::optional<double> highest = h ? h : hh;
    if (lowest && highest && *lowest >= *highest)
        return above(l ? "low" : "low-low", *lowest, h ? "high" : "high-high", *highest);
    return Ok{};
}

Result<QList<AlarmDefinition>>
fromJson(const QJsonValue &value, const std::function<int(qsizetype, const QString &)> &keyLine)
{
    QList<AlarmDefinition> alarms;
    if (value.isUndefined())
        return alarms;
    if (!value.isArray())
        return fileError(QStringLiteral("\"alarms\" must be a list"));
    const QJsonArray array = value.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const auto line = [&](const QString &key) {
            return keyLine ? keyLine(i, key) : 0;
        };
        auto alarm = alarmFromJson(array.at(i), line);
        if (!alarm)
            return WatchList::Errors::atPlace(QStringLiteral("alarm %1").arg(i + 1), alarm.error());
        alarms.append(*alarm);
    }
    return alarms;
}

QJsonValue toJson(const QList<AlarmDefinition> &alarms)
{
    QJsonArray array;
    for (const AlarmDefinition &a : alarms) {
        QJsonObject object{{QStringLiteral("type"), kindName(a.kind)}};
        if (isLimitKind(a.kind))
            object.insert(QStringLiteral("limit"), a.limit);
        if (a.deadband != 0)
            object.insert(QStringLiteral("deadband"), a.deadband);
        if (a.onDelayMs != 0)
            object.insert(QStringLiteral("onDelayMs"), a.onDelayMs);
        if (a.offDelayMs != 0)
            object.insert(QStringLiteral("offDelayMs"), a.offDelayMs);
        object.insert(QStringLiteral("priority"), priorityName(a.priority));
        if (!a.message.isEmpty())
            object.insert(QStringLiteral("message"), a.message);
        if (!a.group.isEmpty())
            object.insert(QStringLiteral("group"), a.group);
        if (!a.enabled)
            object.insert(QStringLiteral("enabled"), false);
        array.append(object);
    }
    return array;
}

} // namespace Fatek::Alarms
