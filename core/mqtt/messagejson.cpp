#include "messagejson.h"

#include "core/watch/watchmessages.h"
#include "mqttmessages.h"

#include <QHash>
#include <QJsonArray>
#include <QString>

#include <span>

namespace Fatek {

namespace {

// The ids a message on the wire may have: those of the libraries up to this one. A gateway sends
// messages of these (its replies' refusals are in mqttmessagelist.h); a name not found here comes
// back as the English text (MessageJson::fromJson).
std::optional<MessageId> idFromName(const QString &name)
{
    static const QHash<QString, MessageId> ids = [] {
        QHash<QString, MessageId> map;
        for (const auto &list : {std::span<const MessageDef *const>(protocolMessages),
                                 std::span<const MessageDef *const>(watchMessages),
                                 std::span<const MessageDef *const>(mqttMessages)}) {
            for (const MessageDef *def : list)
                map.insert(QString::fromLatin1(def->name), *def);
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
    const std::optional<MessageId> id = idFromName(json.value(QStringLiteral("id")).toString());
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
