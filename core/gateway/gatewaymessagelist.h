// The messages of the MQTT gateway (fatek-gateway, core/gateway; issue 20), one line each:
// FATEK_MSG(id, argument count, English template), the format of core/protocol/messagelist.h.
// An X-macro list, included only by gatewaymessages.h (no include guard on purpose).

// The configuration file (core/gateway/gatewayconfig.cpp). Places nest with AtPlace:
// "connection 2 (line1): link: port 70000 is out of range (1..65535)".
FATEK_MSG(GatewayConfigCannotRead, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read %1: %2"))
FATEK_MSG(GatewayConfigNotJson, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The configuration is not a JSON object: %1"))
// %1 the key, %2 the value it needs (typed as they are, so arguments, not words to translate).
FATEK_MSG(GatewayConfigWrongFormat, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not a gateway configuration: \"%1\" must be \"%2\"."))
FATEK_MSG(GatewayConfigWrongVersion, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Configuration version %1 is not supported (this program reads "
                            "version %2)."))
FATEK_MSG(GatewayConfigNoConnections, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "No connections: the configuration needs at least one."))
FATEK_MSG(GatewayConfigBadName, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a usable connection name: 1 to 64 letters, digits, "
                            "'-', '_' or '.', and not a number."))
FATEK_MSG(GatewayConfigDuplicateName, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The connection name \"%1\" is used twice."))
FATEK_MSG(GatewayConfigBadPrefix, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a usable topic prefix: levels separated by '/', "
                            "none empty, without '+', '#' or a NUL character, not starting with "
                            "'$'."))
// %2..%4 the words to write instead (as typed).
FATEK_MSG(GatewayConfigBadKind, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a link kind: write %2, %3 or %4."))
FATEK_MSG(GatewayConfigBadProtocol, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a protocol: write %2, %3 or %4."))
FATEK_MSG(GatewayConfigNoItems, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Nothing to watch: give at least one watch list with items."))
FATEK_MSG(GatewayConfigDuplicateItem, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "station %1 %2 is watched twice (each address has one topic)"))
// Issue 55: %1 the host as written.
FATEK_MSG(GatewayConfigBadHost, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a host: write an IP address (192.168.1.5) or a host "
                            "name (letters, digits, '-' and '.')."))
// Issue 55: %1 and %2 the connections' names, %3 the Home Assistant id both would get.
FATEK_MSG(GatewayConfigDiscoveryIdTwice, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Connections \"%1\" and \"%2\" would get the same Home Assistant id "
                            "\"%3\" (characters other than letters, digits, '-' and '_' become "
                            "'_'): rename one."))
FATEK_MSG(GatewayConfigPasswordTwice, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Give the broker \"%1\" or a \"%2\", not both."))
FATEK_MSG(GatewayPlaceConnection, 2, QT_TRANSLATE_NOOP("Fatek::Message", "connection %1 (%2)"))
FATEK_MSG(GatewayPlaceConnectionNumber, 1, QT_TRANSLATE_NOOP("Fatek::Message", "connection %1"))
FATEK_MSG(GatewayPlaceLink, 0, QT_TRANSLATE_NOOP("Fatek::Message", "link"))
FATEK_MSG(GatewayPlaceBroker, 0, QT_TRANSLATE_NOOP("Fatek::Message", "broker"))
FATEK_MSG(GatewayPlaceWatchList, 1, QT_TRANSLATE_NOOP("Fatek::Message", "watch list %1"))
FATEK_MSG(GatewayPlaceAllow, 1, QT_TRANSLATE_NOOP("Fatek::Message", "allow \"%1\""))

// Writes (core/gateway/gatewaylink.cpp): the log's outcome of a write, an ignored command. The
// refusals a reply carries are core/mqtt's (mqttmessagelist.h): the studio decodes them.
FATEK_MSG(GatewayWriteDone, 0, QT_TRANSLATE_NOOP("Fatek::Message", "written"))
FATEK_MSG(GatewayWriteBadTopic, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Ignored a command on %1: not an item of this connection."))

// A command on a topic that names no item, answered on its reply topic: %1 the topic, %2 why.
FATEK_MSG(GatewayLogBadTopicRefused, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "refused a command on \"%1\": %2"))

// Log lines of fatek-gateway (one per event, on standard error).
// %1 station, %2 address, %3 the value as sent, %4 the command id, %5 the outcome.
FATEK_MSG(GatewayLogWrite, 5,
          QT_TRANSLATE_NOOP("Fatek::Message", "write station %1 %2 = \"%3\" (id \"%4\"): %5"))
FATEK_MSG(GatewayLogPlcLink, 2, QT_TRANSLATE_NOOP("Fatek::Message", "PLC link %1: %2"))
FATEK_MSG(GatewayLogPlcLinkState, 1, QT_TRANSLATE_NOOP("Fatek::Message", "PLC link %1"))
// What the PLCs do (issue 55; stationactivity.cpp): %1 the station, %2 why (the session's
// reason, or for an item %2 its address and %3 the PLC's error).
FATEK_MSG(GatewayLogStationSilent, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "station %1 does not answer: %2"))
FATEK_MSG(GatewayLogStationDemoted, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "station %1 demoted: %2"))
FATEK_MSG(GatewayLogStationAnswers, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "station %1 answers again"))
FATEK_MSG(GatewayLogItemError, 3, QT_TRANSLATE_NOOP("Fatek::Message", "station %1 %2: %3"))
FATEK_MSG(GatewayLogItemReadAgain, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "station %1 %2 read again"))
FATEK_MSG(GatewayLogBrokerUp, 1, QT_TRANSLATE_NOOP("Fatek::Message", "broker %1 connected"))
FATEK_MSG(GatewayLogBrokerDown, 1, QT_TRANSLATE_NOOP("Fatek::Message", "broker down: %1"))
FATEK_MSG(GatewayLogStarted, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "started: %1 {1:item|items} from %2, broker %3"))
FATEK_MSG(GatewayLogStopped, 0, QT_TRANSLATE_NOOP("Fatek::Message", "stopped (status offline)"))
// SIGHUP: %1 the configuration file; %2 why it was not taken.
FATEK_MSG(GatewayLogReloading, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "reloading %1: changed connections restart, the others keep running"))
FATEK_MSG(GatewayLogReloadFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "not reloaded, the running configuration stays: %1: %2"))
FATEK_MSG(GatewayLogReloaded, 0, QT_TRANSLATE_NOOP("Fatek::Message", "reloaded"))

// Alarms (issue 50; core/gateway/alarmnorth.cpp, alarmpayload.cpp). A command's refusals go in
// its reply; the log says what happened to every alarm.
// %1 the alarm id as the topic names it.
FATEK_MSG(GatewayAlarmUnknown, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Refused: no alarm \"%1\" on this connection."))
FATEK_MSG(GatewayAlarmRetained, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Refused: a retained alarm command would be carried out again at "
                            "every restart; publish it without the retain flag."))
// %1 the key as written, %2 the keys the command takes (typed as they are, so an argument).
FATEK_MSG(GatewayAlarmUnknownKey, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a key of this alarm command (it takes %2)."))
FATEK_MSG(GatewayAlarmNotText, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" must be text."))
// %1 the longest shelve in seconds.
FATEK_MSG(GatewayAlarmBadShelve, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "A shelve needs \"until\" (ISO 8601 with its offset, ahead of now) or "
                            "\"durationSec\" (1..%1), one of the two."))
// Log lines. %1 the alarm id, %2 its priority, %3 its message, %4 the item's value.
FATEK_MSG(GatewayLogAlarmRaised, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "alarm %1 raised (%2 priority): %3 (value %4)"))
FATEK_MSG(GatewayLogAlarmReturned, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "alarm %1 returned to normal: %2 (value %3)"))
// %2 the event ("acknowledged", "shelved", "unshelved"), %3 who, %4 the comment.
FATEK_MSG(GatewayLogAlarmAction, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "alarm %1 %2 by %3 (comment \"%4\")"))
// Shelve expiries and definitions taken out of or back into service: %2 the event.
FATEK_MSG(GatewayLogAlarmEvent, 2, QT_TRANSLATE_NOOP("Fatek::Message", "alarm %1 %2"))
// A command refused: %1 the alarm id, %2 the action, %3 the command id, %4 why.
FATEK_MSG(GatewayLogAlarmRefused, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "alarm %1 %2 (id \"%3\") refused: %4"))
FATEK_MSG(GatewayLogAlarmJournal, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "alarm journal failed (alarms still run, not journaled): %1"))
FATEK_MSG(GatewayConfigEmptyFile, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" must name a file."))

// The history (issue 51): gatewayhistoryconfig.cpp, gateway.cpp. %1 the key given.
FATEK_MSG(GatewayConfigHistoryDefaultsUnused, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is the setting of every item recorded with \"recordAll\": "
                            "give \"recordAll\": true, or put \"history\" on the items in their "
                            "watch lists."))
FATEK_MSG(GatewayConfigHistoryPassword, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The history store's URL holds a password: keep it in ~/.pgpass or "
                            "$PGPASSWORD (the service's EnvironmentFile), out of the "
                            "configuration."))
FATEK_MSG(GatewayLogHistory, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "history store failed (values still polled and published, not "
                            "recorded): %1"))
FATEK_MSG(GatewayLogHistoryRecovered, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "history store %1 written again"))
