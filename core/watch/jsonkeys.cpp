#include "jsonkeys.h"

#include "watchmessages.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <QString>

#include <algorithm>
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

// Edit distance with adjacent transpositions ("hots" -> "host" is 1), ignoring case.
qsizetype editDistance(const QString &a, const QString &b)
{
    const QString x = a.toCaseFolded();
    const QString y = b.toCaseFolded();
    std::vector<std::vector<qsizetype>> d(
        static_cast<std::size_t>(x.size() + 1),
        std::vector<qsizetype>(static_cast<std::size_t>(y.size() + 1)));
    const auto at = [&d](qsizetype i, qsizetype j) -> qsizetype & {
        return d[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    };
    for (qsizetype i = 0; i <= x.size(); ++i)
        at(i, 0) = i;
    for (qsizetype j = 0; j <= y.size(); ++j)
        at(0, j) = j;
    for (qsizetype i = 1; i <= x.size(); ++i) {
        for (qsizetype j = 1; j <= y.size(); ++j) {
            const qsizetype cost = x.at(i - 1) == y.at(j - 1) ? 0 : 1;
            at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
            if (i > 1 && j > 1 && x.at(i - 1) == y.at(j - 2) && x.at(i - 2) == y.at(j - 1))
                at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
        }
    }
    return at(x.size(), y.size());
}

} // namespace

QString nearest(const QString &key, const QStringList &known)
{
    QString best;
    qsizetype bestDistance = std::max<qsizetype>(1, key.size() / 3) + 1;
    for (const QString &candidate : known) {
        if (const qsizetype distance = editDistance(key, candidate); distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    return best;
}

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

int keyLine(const QByteArray &json, const Path &path, const QString &key)
{
    struct Level
    {
        bool object = false;
        bool expectKey = false;
        QString key;         // the object's current key
        qsizetype index = 0; // the array's current element
    };
    std::vector<Level> stack;
    const auto at = [&]() {
        // Whether the innermost object is the one at `path`.
        if (static_cast<qsizetype>(stack.size()) != path.size() + 1)
            return false;
        for (qsizetype i = 0; i < path.size(); ++i) {
            const Level &level = stack.at(static_cast<std::size_t>(i));
            const auto &step = path.at(i);
            if (level.object) {
                if (!std::holds_alternative<QString>(step) || std::get<QString>(step) != level.key)
                    return false;
            } else if (!std::holds_alternative<qsizetype>(step)
                       || std::get<qsizetype>(step) != level.index) {
                return false;
            }
        }
        return true;
    };
    int line = 1;
    const qsizetype size = json.size();
    for (qsizetype i = 0; i < size; ++i) {
        const char c = json.at(i);
        switch (c) {
        case '\n': ++line; break;
        case '{': stack.push_back({true, true, {}, 0}); break;
        case '[': stack.push_back({false, false, {}, 0}); break;
        case '}':
        case ']':
            if (!stack.empty())
                stack.pop_back();
            break;
        case ',':
            if (!stack.empty()) {
                if (stack.back().object)
                    stack.back().expectKey = true;
                else
                    ++stack.back().index;
            }
            break;
        case '"': {
            const qsizetype begin = i;
            for (++i; i < size && json.at(i) != '"'; ++i) {
                if (json.at(i) == '\\')
                    ++i;
            }
            if (stack.empty() || !stack.back().object || !stack.back().expectKey)
                break;
            Level &level = stack.back();
            level.expectKey = false;
            level.key = keyText(json, begin, i);
            if (level.key == key && at())
                return line;
            break;
        }
        default: break;
        }
    }
    return 0;
}

} // namespace Fatek::JsonKeys
