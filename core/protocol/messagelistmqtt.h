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
FATEK_MSG(GatewaySetBadWords, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"words\" must be a list of whole numbers from 0 to 4294967295."))
// %1 how many words the command has, %2 the item's address, %3 how many elements it spans.
FATEK_MSG(GatewaySetWordCount, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The command has %1 word(s), but %2 in this format spans %3."))

// Watching a gateway connection from the GUI (core/mqtt/gatewaywatch.cpp): %1 the gateway's
// connection name unless said otherwise.
FATEK_MSG(GatewayNotPublished, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 (station %2) is not published by the gateway %3."))
FATEK_MSG(GatewayNoStatus, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "No status from the gateway %1 yet."))
FATEK_MSG(GatewayConnecting, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The gateway %1 is connecting to its PLC."))
FATEK_MSG(GatewayOffline, 1, QT_TRANSLATE_NOOP("Fatek::Message", "The gateway %1 is offline."))
FATEK_MSG(GatewayOfflineBecause, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The gateway %1 is offline: %2"))
FATEK_MSG(GatewayDown, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The gateway %1 lost its link to the PLC."))
FATEK_MSG(GatewayDownBecause, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The gateway %1 lost its link to the PLC: %2"))
// %1 what was to be written ("R100 (station 1) = 12.5"), %2 why.
FATEK_MSG(GatewayWriteNotSent, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 was not sent: %2"))
FATEK_MSG(GatewayPublishFailed, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The broker %1 did not take the command."))
// %2 seconds.
FATEK_MSG(GatewayNoReply, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "No reply from the gateway %1 within %2 s."))
FATEK_MSG(GatewayWriteFailed, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The gateway %1 did not write the value."))
FATEK_MSG(GatewayPrefixInvalid, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a topic prefix: levels separated by /, without + or #."))
FATEK_MSG(
    GatewayNameInvalid, 1,
    QT_TRANSLATE_NOOP("Fatek::Message",
                      "\"%1\" is not a gateway connection name: 1 to 64 letters, digits, -, _ "
                      "or ., and not a number."))
