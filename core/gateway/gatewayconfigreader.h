#pragma once

#include "core/protocol/message.h"
#include "core/watch/jsonobjectreader.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QString>

#include <initializer_list>
#include <optional>

namespace Fatek {

// The reading of the gateway's configuration file, shared by its parts (gatewayconfig.cpp,
// gatewayhistoryconfig.cpp). A failed step: the message, already nested in its places.
using GatewayConfigProblem = std::optional<Message>;

namespace GatewayConfigRead {

// `error` at `place` ("connection 2 (line1): link: ...").
Message at(Message place, Message error);
// `file` relative to `baseDirectory`, absolute.
QString resolve(const QString &baseDirectory, const QString &file);

// The strict reader of one object (core/watch), as the configuration's parts call it.
using Reader = JsonObjectReader;

} // namespace GatewayConfigRead

} // namespace Fatek
