#include "gatewayconfigreader.h"

#include "gatewaymessages.h"

#include "core/watch/jsonkeys.h"

#include <QDir>
#include <QStringList>

#include <cmath>
#include <limits>

namespace Fatek::GatewayConfigRead {

namespace {

std::string keyText(const QString &key)
{
    return key.toStdString();
}

} // namespace

Message at(Message place, Message error)
{
    return msg<MsgId::AtPlace>(std::move(place), std::move(error));
}

QString resolve(const QString &baseDirectory, const QString &file)
{
    return QDir(baseDirectory).absoluteFilePath(file);
}

bool Reader::has(const QString &key)
{
    m_known.insert(key);
    return m_object.contains(key);
}

void Reader::known(std::initializer_list<QString> keys)
{
    for (const QString &key : keys)
        m_known.insert(key);
}

void Reader::rejectUnknown()
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
    problem = nearest.isEmpty()
                  ? msg<MsgId::GatewayConfigUnknownKey>(keyText(key))
                  : msg<MsgId::GatewayConfigUnknownKeyNear>(keyText(key), keyText(nearest));
}

QString Reader::string(const QString &key, const QString &fallback)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return fallback;
    if (!value.isString()) {
        wrongType(key, msg<MsgId::GatewayTypeString>());
        return fallback;
    }
    return value.toString();
}

bool Reader::boolean(const QString &key, bool fallback)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return fallback;
    if (!value.isBool()) {
        wrongType(key, msg<MsgId::GatewayTypeBool>("true", "false"));
        return fallback;
    }
    return value.toBool();
}

std::optional<qint64> Reader::integer(const QString &key, qint64 min, qint64 max)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return std::nullopt;
    const double number = value.toDouble(std::numeric_limits<double>::quiet_NaN());
    if (!value.isDouble() || !std::isfinite(number) || number != std::floor(number)) {
        wrongType(key, msg<MsgId::GatewayTypeNumber>());
        return std::nullopt;
    }
    if (number < static_cast<double>(min) || number > static_cast<double>(max)) {
        problem = msg<MsgId::GatewayConfigOutOfRange>(
            keyText(key), QString::number(number, 'g', 17).toStdString(), min, max);
        return std::nullopt;
    }
    return static_cast<qint64>(number);
}

std::optional<double> Reader::number(const QString &key, double min, double max)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return std::nullopt;
    const double number = value.toDouble(std::numeric_limits<double>::quiet_NaN());
    if (!value.isDouble() || !std::isfinite(number)) {
        wrongType(key, msg<MsgId::GatewayTypeNumber>());
        return std::nullopt;
    }
    if (number < min || number > max) {
        problem = msg<MsgId::GatewayConfigOutOfRange>(
            keyText(key), QString::number(number, 'g', 17).toStdString(),
            QString::number(min, 'g', 17).toStdString(),
            QString::number(max, 'g', 17).toStdString());
        return std::nullopt;
    }
    return number;
}

QJsonArray Reader::array(const QString &key)
{
    const QJsonValue value = valueOf(key);
    if (value.isUndefined() || problem)
        return {};
    if (!value.isArray()) {
        wrongType(key, msg<MsgId::GatewayTypeArray>());
        return {};
    }
    return value.toArray();
}

QJsonObject Reader::object(const QString &key, bool required)
{
    const QJsonValue value = valueOf(key);
    if (problem)
        return {};
    if (value.isUndefined()) {
        if (required)
            problem = msg<MsgId::GatewayConfigMissing>(keyText(key));
        return {};
    }
    if (!value.isObject()) {
        wrongType(key, msg<MsgId::GatewayTypeObject>());
        return {};
    }
    return value.toObject();
}

QJsonValue Reader::valueOf(const QString &key)
{
    m_known.insert(key);
    return m_object.value(key);
}

void Reader::wrongType(const QString &key, Message type)
{
    problem = msg<MsgId::GatewayConfigWrongType>(keyText(key), std::move(type));
}

} // namespace Fatek::GatewayConfigRead
