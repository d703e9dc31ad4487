// The messages of core/history, one line each: FATEK_MSG(id, argument count, English template),
// the format of core/protocol/messagelist.h. An X-macro list, included only by
// historymessages.h (no include guard on purpose).

// The store (historystore.cpp, sqlitehistorystore.cpp, postgreshistorystore.cpp): %1 is always
// the location (a file, or a PostgreSQL URL without its password); a reason from SQLite or
// PostgreSQL travels as a text argument, in its own words.
FATEK_MSG(HistoryOpenFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot open the history store %1: %2"))
FATEK_MSG(HistoryMissing, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The history store %1 does not exist."))
FATEK_MSG(HistoryNotHistory, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 is not a history store (another program's database); it was left "
                            "as it is."))
FATEK_MSG(HistoryNewer, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The history store %1 has format %2, newer than this program reads "
                            "(%3); it was left as it is."))
FATEK_MSG(HistoryLocked, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The history store %1 is locked by another program (it holds a write "
                            "transaction open)."))
FATEK_MSG(HistoryWriteFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot write to the history store %1: %2"))
FATEK_MSG(HistoryReadFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read the history store %1: %2"))
// %2: the series' key ("line1/1-R100").
FATEK_MSG(HistoryUnknownSeries, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The history store %1 has no series %2."))
FATEK_MSG(HistoryNoPostgres, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Cannot open the history store %1: this build of FATEK Studio has no "
                            "PostgreSQL client (use an SQLite file)."))

// The writer (historywriter.cpp): %1 the location; %2 how many samples.
FATEK_MSG(HistorySamplesDropped, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The history store %1 could not be written for a while: %2 samples "
                            "were lost (the oldest)."))

// The SQLite store (sqlitehistorystore.cpp, sqlitehistoryretention.cpp): %1 the file; %2 its
// folder.
FATEK_MSG(HistoryNoFolder, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Cannot create the history store %1: cannot create its folder %2."))
FATEK_MSG(HistoryReadOnly, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The history store %1 was opened to read only; nothing was written."))
// %2 the series' id, %3 the sample's time (ms since the epoch), %4 the number found.
FATEK_MSG(HistoryQualityUnknown, 4,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The history store %1, series %2 at %3: unknown quality %4."))
