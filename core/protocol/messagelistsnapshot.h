// The messages of core, continued (see messagelist.h for the format): the snapshot part of
// commissioning (issue 18). X-macro list, included only by message.h and message.cpp.

// Reading a snapshot (core/commission/snapshotreader.cpp).
FATEK_MSG(SnapshotNoSession, 0, QT_TRANSLATE_NOOP("Fatek::Message", "No connection to read from."))
FATEK_MSG(SnapshotBusy, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "A snapshot or restore is already running."))
FATEK_MSG(SnapshotNeedsSizes, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The PLC did not report its memory sizes (%1): give the ranges to "
                            "read."))
FATEK_MSG(SnapshotNoRanges, 0, QT_TRANSLATE_NOOP("Fatek::Message", "No element ranges to read."))
FATEK_MSG(SnapshotTooMany, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 elements are more than a snapshot holds (at most %2)."))
FATEK_MSG(SnapshotCannotRead, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read %1: %2"))
FATEK_MSG(SnapshotCancelled, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Cancelled."))
FATEK_MSG(SnapshotTaken, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 values read in %2 requests."))

// Snapshot files (core/commission/snapshotfile.cpp): %1 of AtPlace says where.
FATEK_MSG(SnapshotPlaceValue, 1, QT_TRANSLATE_NOOP("Fatek::Message", "value %1"))
FATEK_MSG(SnapshotPlaceLineColumn, 2, QT_TRANSLATE_NOOP("Fatek::Message", "line %1, column %2"))
FATEK_MSG(SnapshotFileUnknownType, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1: a snapshot file name ends in .json or .csv."))
FATEK_MSG(SnapshotFileCannotRead, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Cannot open %1: %2"))
FATEK_MSG(SnapshotFileCannotWrite, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Cannot write %1: %2"))
FATEK_MSG(SnapshotJsonSyntax, 1, QT_TRANSLATE_NOOP("Fatek::Message", "not valid JSON (%1)"))
FATEK_MSG(SnapshotNotSnapshot, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "not a memory snapshot (\"format\" is not \"%1\")"))
FATEK_MSG(SnapshotVersion, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "snapshot version %1 is not supported (this program reads %2)"))
FATEK_MSG(SnapshotMissing, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is missing"))
FATEK_MSG(SnapshotNotNumber, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a whole number"))
FATEK_MSG(SnapshotOutOfRange, 3, QT_TRANSLATE_NOOP("Fatek::Message", "%1 does not fit %2 (0..%3)"))
FATEK_MSG(SnapshotHexMismatch, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "the hex column %1 differs from the value %2"))
FATEK_MSG(SnapshotDuplicate, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1 appears twice"))
FATEK_MSG(SnapshotCsvColumns, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "expected address,value[,hex]"))
FATEK_MSG(SnapshotCsvBadMeta, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "a metadata line reads \"# key: value\""))
FATEK_MSG(SnapshotEmpty, 0, QT_TRANSLATE_NOOP("Fatek::Message", "the snapshot holds no values"))

// Differences (core/commission/snapshotdiff.cpp).
FATEK_MSG(DiffAbsent, 0, QT_TRANSLATE_NOOP("Fatek::Message", "(absent)"))
FATEK_MSG(DiffLine, 3, QT_TRANSLATE_NOOP("Fatek::Message", "%1: %2 -> %3"))
FATEK_MSG(DiffNone, 0, QT_TRANSLATE_NOOP("Fatek::Message", "No differences."))
FATEK_MSG(DiffCount, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 of %2 values differ."))

// Restoring values (core/commission/valuesrestorer.cpp).
FATEK_MSG(RestoreReadOnly, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Operator mode: restoring values is refused; nothing was written."))
FATEK_MSG(RestoreNothing, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The chosen ranges hold no value of the snapshot: nothing to write."))
FATEK_MSG(RestoreWriteFailed, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Writing %1 failed: %2"))
FATEK_MSG(RestoreVerifyFailed, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Reading the values back failed: %1"))
FATEK_MSG(RestoreDiffer, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 of %2 values differ after the write (read back)."))
FATEK_MSG(RestoreDone, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 values written in %2 requests and read back equal."))
