#pragma once

#include "core/protocol/message.h"

#include <QByteArray>

#include <QList>
#include <QString>
#include <QStringList>

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

// The key of `known` that the unknown `key` most likely means, for "did you mean": the closest by
// edit distance (case ignored, two swapped neighbours one edit), when at most a third of its
// length (at least 1) away; empty when none is that close. Ties go to the first in `known`.
// Shared by the watch list and the gateway's configuration, so one slip reads the same in both.
QString nearest(const QString &key, const QStringList &known);

} // namespace Fatek::JsonKeys
