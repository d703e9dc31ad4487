#include "jsonkeys.h"

#include "watchmessages.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <QString>

#include <vector>

namespace Fatek::JsonKeys {

namespace {

struct Frame
{
    bool object = false;
    bool expectKey = false;
    QSet<QString> keys;
};

QString keyText(const QByteArray &json, qsizetype begin, qsizetype end)
{
    const QByteArray body = json.mid(begin + 1, end - begin - 1);
    if (!body.contains('\\'))
        return QString::fromUtf8(body);
    // Escapes: Qt's parser decodes them (rare in keys, so the detour costs nothing).
    const QJsonDocument one = QJsonDocument::fromJson('[' + json.mid(begin, end - begin + 1) + ']');
    return one.array().at(0).toString();
}

} // namespace

std::optional<Message> firstDuplicate(const QByteArray &json)
{
    std::vector<Frame> stack;
    int line = 1;
    const qsizetype size = json.size();
    for (qsizetype i = 0; i < size; ++i) {
        const char c = json.at(i);
        switch (c) {
        case '\n': ++line; break;
        case '{': stack.push_back({true, true, {}}); break;
        case '[': stack.push_back({false, false, {}}); break;
        case '}':
        case ']':
            if (!stack.empty())
                stack.pop_back();
            break;
        case ',':
            if (!stack.empty() && stack.back().object)
                stack.back().expectKey = true;
            break;
        case '"': {
            const qsizetype begin = i;
            for (++i; i < size && json.at(i) != '"'; ++i) {
                if (json.at(i) == '\\')
                    ++i; // the escaped character, a quote included
            }
            if (stack.empty() || !stack.back().object || !stack.back().expectKey)
                break; // a value
            Frame &frame = stack.back();
            frame.expectKey = false;
            const QString key = keyText(json, begin, i);
            if (frame.keys.contains(key))
                return msg<MsgId::AtPlace>(msg<MsgId::PlaceLine>(line),
                                           msg<MsgId::JsonDuplicateKey>(key.toStdString()));
            frame.keys.insert(key);
            break;
        }
        default: break;
        }
    }
    return std::nullopt;
}

} // namespace Fatek::JsonKeys
