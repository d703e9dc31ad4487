// The messages of core/alarm, one line each: FATEK_MSG(id, argument count, English template), the
// format of core/protocol/messagelist.h. An X-macro list, included only by alarmmessages.h (no
// include guard on purpose).

// Operator actions refused (core/alarm/alarmstatemachine.cpp, alarmengine.cpp); %1 the alarm's id.
FATEK_MSG(AlarmUnknown, 1, QT_TRANSLATE_NOOP("Fatek::Message", "There is no alarm %1."))
FATEK_MSG(AlarmNothingToAck, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Alarm %1 has nothing to acknowledge (it is not unacknowledged)."))
FATEK_MSG(AlarmNotShelved, 1, QT_TRANSLATE_NOOP("Fatek::Message", "Alarm %1 is not shelved."))
FATEK_MSG(AlarmShelveExpired, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Alarm %1 cannot be shelved until a time that has passed."))
FATEK_MSG(AlarmOutOfService, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Alarm %1 is out of service (disabled in its definition)."))
