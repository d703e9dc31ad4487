#pragma once

#include "core/protocol/message.h"

#include <QByteArray>

#include <optional>

namespace Fatek::JsonKeys {

// The first key that appears twice in one object of `json` (text QJsonDocument already accepted),
// as "line 4: duplicate key "format"": QJsonDocument keeps the last value without a word, so a
// file or command that says a thing twice would silently mean the second. Keys compare after
// their escapes are decoded ("a" and "\u0061" are the same key). Nothing when every object's keys
// differ.
std::optional<Message> firstDuplicate(const QByteArray &json);

} // namespace Fatek::JsonKeys
