#pragma once

#include "core/protocol/message.h"

#include <QByteArray>

#include <QList>
#include <QString>

#include <optional>
#include <variant>

namespace Fatek::JsonKeys {

// The first key that appears twice in one object of `json` (text QJsonDocument already accepted),
// as "line 4: duplicate key "format"": QJsonDocument keeps the last value without a word, so a
// file or command that says a thing twice would silently mean the second. Keys compare after
// their escapes are decoded ("a" and "\u0061" are the same key). Nothing when every object's keys
// differ.
std::optional<Message> firstDuplicate(const QByteArray &json);

// A place in a JSON document: object keys and array indices from the root.
using Path = QList<std::variant<QString, qsizetype>>;
// The line of `key` in the object at `path` of `json` (text QJsonDocument accepted), or 0 when
// there is none: an error about one key names the line an editor shows.
int keyLine(const QByteArray &json, const Path &path, const QString &key);

} // namespace Fatek::JsonKeys
