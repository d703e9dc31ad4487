// The messages of core, continued (see messagelist.h for the format): the MQTT client and the
// gateway's payloads (issue 20). X-macro list, included only by message.h and message.cpp.

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
FATEK_MSG(MqttLinkLost, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Link to the broker %1 lost: %2"))
FATEK_MSG(MqttClosed, 1, QT_TRANSLATE_NOOP("Fatek::Message", "Disconnected from the broker %1."))
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
