#pragma once

#include "core/protocol/message.h"

#include <QJsonObject>

#include <optional>

namespace Fatek {

// A core Message across a process boundary (the gateway's payloads), so that the receiving GUI
// shows it in its own language: {"id":"LinkLost","args":["text", {"id":...}],"text":"English"}.
// "text" is the English form for readers without the message table (a SCADA, mosquitto_sub).
namespace MessageJson {

QJsonObject toJson(const Message &message);
// The message again; an unknown id or a wrong argument count gives the English "text" verbatim
// (a newer gateway than this program), nullopt when there is neither.
std::optional<Message> fromJson(const QJsonObject &json);

} // namespace MessageJson

} // namespace Fatek
