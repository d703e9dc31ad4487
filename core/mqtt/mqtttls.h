#pragma once

#include "core/protocol/message.h"

#include <string>

struct mosquitto;

namespace Fatek {

struct MqttBrokerSettings;

// TLS as libmosquitto does it (OpenSSL), for the checks a start makes before it connects and the
// words of a handshake that failed (issue 55).
namespace MqttTls {

// What libmosquitto does with the TLS files when it connects (the CA file loaded as trust, the
// client certificate and its key loaded and matched), done without connecting: empty when they
// are usable, else which file and why. MqttBrokerSettings::validate() asks it, so --check, a
// start and a reload refuse the same files.
Message checkFiles(const MqttBrokerSettings &settings);

// Why OpenSSL refused the broker's certificate in the handshake under way on `mosq` ("certificate
// has expired", "unable to get local issuer certificate", "hostname mismatch"); empty when it did
// not. Only while the library reports the failure (its log callback): the connection is freed
// after.
std::string verifyFailure(struct mosquitto *mosq);

} // namespace MqttTls

} // namespace Fatek
