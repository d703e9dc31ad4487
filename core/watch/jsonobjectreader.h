#pragma once

#include "core/protocol/message.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QString>

#include <initializer_list>
#include <optional>

namespace Fatek {

// Reads optional typed keys of one JSON object of a file we read (the gateway's configuration,
// checkout files); the first problem wins and the rest is skipped.
// Every key asked for is a known key of the object: rejectUnknown() then refuses any other, so a
// misspelt setting ("readonly") is an error instead of a silent default.
class JsonObjectReader
{
public:
    explicit JsonObjectReader(const QJsonObject &object)
        : m_object(object)
    {}

    std::optional<Message> problem;

    bool has(const QString &key);
    // Keys read elsewhere (the format marker and version of the root object).
    void known(std::initializer_list<QString> keys);
    // After every key has been asked for: the first key (in order) that none was, with the known
    // key it most likely means when one is close enough.
    void rejectUnknown();

    QString string(const QString &key, const QString &fallback = {});
    bool boolean(const QString &key, bool fallback);
    // A whole number in [min, max]; nothing when absent.
    std::optional<qint64> integer(const QString &key, qint64 min, qint64 max);
    template<typename T>
    void integerInto(const QString &key, qint64 min, qint64 max, T *target)
    {
        if (const std::optional<qint64> v = integer(key, min, max))
            *target = static_cast<T>(*v);
    }
    // A finite number in [min, max]; nothing when absent.
    std::optional<double> number(const QString &key, double min, double max);
    QJsonArray array(const QString &key);
    QJsonObject object(const QString &key, bool required);

private:
    QJsonValue valueOf(const QString &key);
    void wrongType(const QString &key, Message type);

    QJsonObject m_object;
    QSet<QString> m_known;
};

} // namespace Fatek
