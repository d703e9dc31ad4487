// The messages of the GUI's links (core/link), one line each: FATEK_MSG(id, argument count,
// English template), the format of core/protocol/messagelist.h. An X-macro list, included only by
// linkmessages.h (no include guard on purpose).

// Watching a gateway connection from the GUI (core/link/gatewaywatch.cpp,
// gatewaywatchsettings.cpp): %1 the gateway's connection name unless said otherwise.
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
FATEK_MSG(GatewayWriteUnanswered, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Outcome unknown: %1 went to the gateway and no final reply came "
                            "(%2); it may have been carried out."))
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
