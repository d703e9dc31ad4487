#include "messagejson.h"

#include <QHash>
#include <QJsonArray>
#include <QString>

namespace Fatek {

namespace {

std::optional<MsgId> idFromName(const QString &name)
{
    static const QHash<QString, MsgId> ids = [] {
        QHash<QString, MsgId> map;
        for (std::size_t i = 0; i < messageIdCount; ++i) {
            const auto id = static_cast<MsgId>(i);
            map.insert(QString::fromLatin1(messageIdName(id)), id);
        }
        return map;
    }();
    const auto it = ids.constFind(name);
    if (it == ids.constEnd())
        return std::nullopt;
    return *it;
}

} // namespace

QJsonObject MessageJson::toJson(const Message &message)
{
    QJsonArray args;
    for (const MessageArg &arg : message.args) {
        if (arg.message)
            args.append(toJson(*arg.message));
        else
            args.append(QString::fromStdString(arg.text));
    }
    return QJsonObject{{QStringLiteral("id"), QString::fromLatin1(messageIdName(message.id))},
                       {QStringLiteral("args"), args},
                       {QStringLiteral("text"), QString::fromStdString(english(message))}};
}

std::optional<Message> MessageJson::fromJson(const QJsonObject &json)
{
    const QString englishText = json.value(QStringLiteral("text")).toString();
    auto fallback = [&]() -> std::optional<Message> {
        if (englishText.isEmpty())
            return std::nullopt;
        return Message::text(englishText.toStdString());
    };
    const std::optional<MsgId> id = idFromName(json.value(QStringLiteral("id")).toString());
    const QJsonArray args = json.value(QStringLiteral("args")).toArray();
    if (!id || args.size() != messageArgCount(*id))
        return fallback();
    Message message{*id, {}};
    for (const auto &arg : args) {
        if (arg.isObject()) {
            std::optional<Message> nested = fromJson(arg.toObject());
            if (!nested)
                return fallback();
            message.args.emplace_back(std::move(*nested));
        } else if (arg.isString()) {
            message.args.emplace_back(arg.toString().toStdString());
        } else {
            return fallback();
        }
    }
    return message;
}

} // namespace Fatek
