// The messages of the MQTT client and the gateway's payloads (core/mqtt; issue 20), one line each:
// FATEK_MSG(id, argument count, English template), the format of core/protocol/messagelist.h.
// An X-macro list, included only by mqttmessages.h (no include guard on purpose).

// Broker settings (core/mqtt/mqttbrokersettings.cpp).
FATEK_MSG(MqttUrlEmpty, 0, QT_TRANSLATE_NOOP("Fatek::Message", "No broker given."))
FATEK_MSG(MqttUrlInvalid, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a broker address: write mqtt://host:1883 or "
                            "mqtts://user@host:8883."))
FATEK_MSG(MqttTlsFileMissing, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read the TLS file %1."))
FATEK_MSG(MqttTlsCertNeedsKey, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "A client certificate needs its key file, and a key its certificate."))
// TLS settings with an mqtt:// URL (issue 55: they passed and the connection went in clear text):
// %1 the setting as typed.
FATEK_MSG(MqttTlsWithoutTls, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 is a TLS setting, but the broker URL is mqtt:// (clear text): "
                            "write mqtts://, or remove %1."))
// The TLS files as libmosquitto loads them when it connects (MqttTls::checkFiles): %1 the file,
// %2 OpenSSL's reason.
FATEK_MSG(MqttTlsCaUnusable, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The CA file %1 holds no usable certificate: %2."))
FATEK_MSG(MqttTlsCertUnusable, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The certificate file %1 is not usable: %2."))
FATEK_MSG(MqttTlsKeyUnusable, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The key file %1 is not usable: %2."))
FATEK_MSG(MqttTlsKeyMismatch, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The key file %1 is not the key of the certificate %2."))
FATEK_MSG(MqttTlsUnavailable, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 needs TLS, which this build's MQTT library does not have (the "
                            "Windows build has none yet): use an mqtt:// broker."))
FATEK_MSG(MqttPasswordNeedsUser, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "A broker password needs a user name."))
FATEK_MSG(MqttTimingInvalid, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Broker timing out of range: keep-alive at least 5 s, reconnect "
                            "delays at least 10 ms, the longest not below the first."))
// The link to the broker (core/mqtt/mqttclient.cpp): %1 the broker's URL, %2 the library's reason.
FATEK_MSG(MqttConnectFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot reach the broker %1: %2"))
FATEK_MSG(MqttRefused, 2, QT_TRANSLATE_NOOP("Fatek::Message", "The broker %1 refused us: %2"))
// A connection attempt the broker dropped before its CONNACK (TLS: no client certificate).
FATEK_MSG(MqttClosedBeforeAccepting, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "the broker closed the connection before accepting it"))
FATEK_MSG(MqttMaybeNeedsCertificate, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1; the broker may require a client certificate, and none is "
                            "configured (certFile, keyFile)"))
FATEK_MSG(MqttTlsFailed, 0, QT_TRANSLATE_NOOP("Fatek::Message", "the TLS handshake failed"))
// %1 a reason, %2 the MQTT library's own words on it (its TLS checks), as it gives them.
FATEK_MSG(MqttErrorDetail, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 (the library says: %2)"))
FATEK_MSG(MqttLinkLost, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Link to the broker %1 lost: %2"))
// Issue 55: %1 the broker, %2 how many sessions in a row it ended right after accepting them,
// %3 the client id.
FATEK_MSG(MqttTakenOver, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The broker %1 closed the connection right after accepting it, %2 "
                            "times in a row: another client with the same client id \"%3\" took "
                            "over (a second gateway with this configuration?); trying again less "
                            "often."))
FATEK_MSG(MqttClosed, 1, QT_TRANSLATE_NOOP("Fatek::Message", "Disconnected from the broker %1."))
// %2 of MqttLinkLost when the broker stopped answering (libmosquitto's MOSQ_ERR_KEEPALIVE, which
// its own mosquitto_strerror() calls "Unknown error"): %1 the keep-alive in seconds.
FATEK_MSG(MqttKeepaliveTimeout, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "keep-alive timeout: the broker did not answer within %1 s"))
FATEK_MSG(MqttLibraryError, 1, QT_TRANSLATE_NOOP("Fatek::Message", "MQTT library error: %1"))

// Write commands on <item>/set (core/mqtt/gatewaypayload.cpp).
FATEK_MSG(GatewaySetNotJson, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The command starts with { but is not a JSON object."))
FATEK_MSG(GatewaySetNoValue, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The command has no value: send the text to write, or "
                            "{\"value\": ...}."))
FATEK_MSG(GatewaySetBadFormat, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a value format."))
// A boolean key with another value ("swapWords":"yes"): refused, never read as false. %1 the
// key, %2 and %3 the values it takes (typed as they are, so arguments).
// A text key with another value ("format":5): %1 the key.
FATEK_MSG(GatewaySetNotString, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" must be a string."))
FATEK_MSG(GatewaySetNotBool, 3, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" must be %2 or %3."))
FATEK_MSG(GatewaySetBadWords, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"words\" must be a list of whole numbers from 0 to 4294967295."))
// %1 how many words the command has, %2 the item's address, %3 how many elements it spans.
FATEK_MSG(GatewaySetWordCount, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The command has %1 word(s), but %2 in this format spans %3."))

// "id" given as something the reply could not give back as it was (an object, a list, true).
FATEK_MSG(GatewaySetBadId, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"id\" must be text or a number."))
// A command whose time lies ahead of the gateway's clock by more than the bound: %1 seconds
// ahead, %2 the bound (core/gateway/gatewaylink.cpp).
FATEK_MSG(GatewayWriteFuture, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Refused: the command's \"time\" is %1 s ahead of the gateway's "
                            "clock (at most %2 s are taken); check the sender's clock."))

// The refusals of a write command, in the gateway's reply (core/gateway/gatewaylink.cpp), which
// the studio decodes and shows.
FATEK_MSG(GatewayWriteReadOnly, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Refused: the gateway is read-only."))
FATEK_MSG(GatewayWriteNotAllowed, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Refused: %1 is not in this connection's write allowlist."))
FATEK_MSG(GatewayWriteRetained, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Refused: a retained command would write again at every restart; "
                            "publish commands without the retain flag."))
FATEK_MSG(GatewayWriteTooLong, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Refused: a command longer than %1 bytes."))
FATEK_MSG(GatewayWriteBusy, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Refused: %1 writes are already waiting on this connection."))
// A command on <prefix>/<connection>/<station>/<address>/set whose levels name no item: %1 the
// station level, %2 the address level, as written.
FATEK_MSG(GatewayNoSuchItem, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Refused: no item \"%2\" on station \"%1\" (write the address as a "
                            "watch table shows it, R100, and the station as 1 to 254)."))
// Commands kept by the broker while the gateway was away (issue 33): never carried out late.
// %1 seconds, %2 the connection's commandMaxAgeSec.
FATEK_MSG(GatewayWriteExpired, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Expired: the command is %1 s old (commands older than %2 s are not "
                            "carried out); send it again."))
FATEK_MSG(GatewayWriteWaited, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Expired: the command waited at the broker while the gateway was "
                            "away, up to %1 s (commands older than %2 s are not carried out); "
                            "send it again."))
FATEK_MSG(GatewayWriteAgeUnknown, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not carried out: the command waited at the broker while the "
                            "gateway was away, for a time nobody knows; send it again, with "
                            "\"time\" so that its age can be checked (at most %1 s)."))
FATEK_MSG(GatewaySetBadTime, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"time\" must be a date and time in ISO 8601 with its offset "
                            "(2026-11-27T10:15:00.000Z), not \"%1\"."))
