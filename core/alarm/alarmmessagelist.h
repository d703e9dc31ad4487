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

// The journal (core/alarm/alarmjournal.cpp): %1 is always the file; a reason from SQLite
// travels as a text argument, in SQLite's English.
FATEK_MSG(JournalOpenFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot open the alarm journal %1: %2"))
FATEK_MSG(JournalMissing, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The alarm journal %1 does not exist."))
FATEK_MSG(JournalNotJournal, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 is not an alarm journal (another program's SQLite database); it "
                            "was left as it is."))
FATEK_MSG(JournalNewer, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The alarm journal %1 has format %2, newer than this program reads "
                            "(%3); it was left as it is."))
FATEK_MSG(JournalLocked, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The alarm journal %1 is locked by another program (it holds a write "
                            "transaction open)."))
FATEK_MSG(JournalWriteFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot write to the alarm journal %1: %2"))
FATEK_MSG(JournalReadFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read the alarm journal %1: %2"))
// %2: the event's row number; %3: the column ("state", "event", "kind", "priority"); %4: its text.
FATEK_MSG(JournalEventUnknown, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "The alarm journal %1, event %2: unknown %3 \"%4\"."))
// %2: the alarm's id.
FATEK_MSG(JournalStateUnknown, 4,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The alarm journal %1, the kept state of %2: unknown %3 \"%4\"."))
