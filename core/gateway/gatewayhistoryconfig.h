#pragma once

#include "gatewayconfig.h"
#include "gatewayconfigreader.h"

#include <QJsonObject>

namespace Fatek::GatewayConfigRead {

// The "history" object of the gateway's configuration (GatewayConfig::History): every key known,
// "store" (a file relative to `baseDirectory`, or a postgresql:// URL without a password),
// "recordAll" (true: every item, with "deadband" and "heartbeatS"), "retention" ({"days",
// "maxMB"}). `json` empty (no "history" key): the defaults.
GatewayConfigProblem readHistory(const QJsonObject &json, const QString &baseDirectory,
                                 GatewayConfig::History *out);

} // namespace Fatek::GatewayConfigRead
