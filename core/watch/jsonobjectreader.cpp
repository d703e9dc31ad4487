#include "jsonobjectreader.h"

#include "jsonkeys.h"
#include "watchmessages.h"

#include <QStringList>

#include <cmath>
#include <limits>

namespace Fatek {

namespace {

std::string keyText(const QString &key)
{
    return key.toStdString();
}

} // namespace

bool JsonObjectReader::has(const QString &key)
{
    m_known.insert(key);
    return m_object.contains(key);
}

void JsonObjectReader::known(std::initializer_list<QString> keys)
{
    for (const QString &key : keys)
        m_known.insert(key);
}

void JsonObjectReader::rejectUnknown()
{
    if (problem)
        return;
    QStringList unknown;
    for (const QString &key : m_object.keys()) {
        if (!m_known.contains(key))
            unknown.append(key);
    }
    if (unknown.isEmpty())
        return;
    const QString key = unknown.first();
    QStringList candidates(m_known.cbegin(), m_known.cend());
    candidates.sort(); // ties: the same choice whatever the set's order
    const QString nearest = JsonKeys::nearest(key, candidates);
    problem = nearest.isEmpty() ? msg<MsgId::JsonUnknownKey>(keyText(key))
                                : msg<MsgId::JsonUnknownKeyNear>(keyText(key), keyText(nearest));
}

QString JsonObjectReader::string(const QString &key, const QString &fallback)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return fallback;
    if (!value.isString()) {
        wrongType(key, msg<MsgId::JsonTypeString>());
        return fallback;
    }
    return value.toString();
}

bool JsonObjectReader::boolean(const QString &key, bool fallback)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return fallback;
    if (!value.isBool()) {
        wrongType(key, msg<MsgId::JsonTypeBool>("true", "false"));
        return fallback;
    }
    return value.toBool();
}

std::optional<qint64> JsonObjectReader::integer(const QString &key, qint64 min, qint64 max)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return std::nullopt;
    const double number = value.toDouble(std::numeric_limits<double>::quiet_NaN());
    if (!value.isDouble() || !std::isfinite(number) || number != std::floor(number)) {
        wrongType(key, msg<MsgId::JsonTypeNumber>());
        return std::nullopt;
    }
    if (number < static_cast<double>(min) || number > static_cast<double>(max)) {
        problem = msg<MsgId::JsonOutOfRange>(
            keyText(key), QString::number(number, 'g', 17).toStdString(), min, max);
        return std::nullopt;
    }
    return static_cast<qint64>(number);
}

std::optional<double> JsonObjectReader::number(const QString &key, double min, double max)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return std::nullopt;
    const double number = value.toDouble(std::numeric_limits<double>::quiet_NaN());
    if (!value.isDouble() || !std::isfinite(number)) {
        wrongType(key, msg<MsgId::JsonTypeNumber>());
        return std::nullopt;
    }
    if (number < min || number > max) {
        problem = msg<MsgId::JsonOutOfRange>(keyText(key),
                                             QString::number(number, 'g', 17).toStdString(),
                                             QString::number(min, 'g', 17).toStdString(),
                                             QString::number(max, 'g', 17).toStdString());
        return std::nullopt;
    }
    return number;
}

QJsonArray JsonObjectReader::array(const QString &key)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return {};
    if (!value.isArray()) {
        wrongType(key, msg<MsgId::JsonTypeArray>());
        return {};
    }
    return value.toArray();
}

QJsonObject JsonObjectReader::object(const QString &key, bool required)
{
    const QJsonValue value = valueOf(key);
    if (problem)
        return {};
    if (value.isUndefined()) {
        if (required)
            problem = msg<MsgId::JsonKeyMissing>(keyText(key));
        return {};
    }
    if (!value.isObject()) {
        wrongType(key, msg<MsgId::JsonTypeObject>());
        return {};
    }
    return value.toObject();
}

QJsonValue JsonObjectReader::valueOf(const QString &key)
{
    m_known.insert(key);
    return m_object.value(key);
}

void JsonObjectReader::wrongType(const QString &key, Message type)
{
    problem = msg<MsgId::JsonWrongType>(keyText(key), std::move(type));
}

} // namespace Fatek
