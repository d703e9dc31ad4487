// The messages of core, continued (see messagelist.h for the format): the program part of
// commissioning (issue 18). X-macro list, included only by message.h and message.cpp.

// The program header (page 0): %1 the family ("FBs", "M"), %2 the program size in words.
FATEK_MSG(ProgramModel, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 series, %2-word program"))

// Program backup files (core/commission/programimage.cpp). %1 of the first two: the file name.
FATEK_MSG(ProgramFileUnreadable, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read the program backup %1: %2"))
FATEK_MSG(ProgramFileUnwritable, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot write the program backup %1: %2"))
FATEK_MSG(ProgramFileNotJson, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "The program backup is not valid JSON: %1"))
FATEK_MSG(ProgramFileWrongFormat, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The file is not a program backup (format \"%1\", expected "
                            "\"fatek-program\")."))
FATEK_MSG(ProgramFileVersion, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The program backup has format version %1, which this program cannot "
                            "read."))
FATEK_MSG(ProgramFileField, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The program backup is damaged: the field \"%1\" is missing or wrong."))
FATEK_MSG(ProgramFilePageCount, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The program backup is damaged or truncated: it holds %1 pages, its "
                            "header needs %2."))
FATEK_MSG(ProgramFileBadPage, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The program backup is damaged: page %1 is not 64 words of 4 hex "
                            "digits."))
FATEK_MSG(ProgramFileChecksum, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The program backup is damaged: its checksum is %1, its words "
                            "give %2."))
FATEK_MSG(ProgramFileBadHeader, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The program backup is damaged: page 0 is not a program header."))

// Backup and restore on a PLC (core/commission/programtransfer.cpp).
FATEK_MSG(ProgramNoConnection, 0, QT_TRANSLATE_NOOP("Fatek::Message", "No connection to a PLC."))
FATEK_MSG(ProgramBusy, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "A program transfer is already running."))
FATEK_MSG(ProgramReadOnly, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Operator mode: restoring a program is refused; nothing was written."))
FATEK_MSG(ProgramNotStopped, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The PLC is in RUN: switch it to STOP before restoring a program; "
                            "nothing was written."))
FATEK_MSG(ProgramNoSize, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The PLC did not report its program size (detail status 53)."))
FATEK_MSG(ProgramPlcNoHeader, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "The PLC's page 0 is not a program header."))
// %1 the backup's model (ProgramModel), %2 the PLC's.
FATEK_MSG(ProgramModelMismatch, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The backup is for a %1, the PLC holds a %2: not restored, nothing "
                            "was written."))
// %1 the page number, %2 why (a message).
FATEK_MSG(ProgramReadPageFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Reading program page %1 failed: %2"))
FATEK_MSG(ProgramWritePageFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Writing program page %1 failed: %2"))
// %1 how many pages, %2 the page list ("3, 7-9").
FATEK_MSG(ProgramVerifyFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Verification failed: %1 pages on the PLC differ from the backup "
                            "(%2)."))
// %1 the page reached, %2 pages done, %3 pages in all.
FATEK_MSG(ProgramBackupCancelled, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Backup cancelled at page %1 (%2 of %3 pages read); no file saved."))
FATEK_MSG(ProgramRestoreCancelled, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Restore cancelled at page %1 (%2 of %3 pages written): the PLC's "
                            "program is incomplete."))
FATEK_MSG(ProgramCompareCancelled, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cancelled before anything was written."))
// %1 pages, %2 the model (ProgramModel).
FATEK_MSG(ProgramBackupDone, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Backup done: %1 pages of a %2."))
FATEK_MSG(ProgramRestoreDone, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Restore done: %1 pages written and verified."))
// Comparing a backup with the PLC before writing: %1 how many pages differ, %2 the list.
FATEK_MSG(ProgramPagesDiffer, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 pages differ from the PLC (%2)."))
FATEK_MSG(ProgramSameAsPlc, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "The PLC already holds this program."))
// What the transfer is doing (progress): reading, writing or reading back.
FATEK_MSG(ProgramPhaseReading, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Reading the program"))
FATEK_MSG(ProgramPhaseWriting, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Writing the program"))
FATEK_MSG(ProgramPhaseVerifying, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Reading the program back to verify"))
FATEK_MSG(ProgramVerifyCancelled, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Verification cancelled at page %1 (%2 of %3 pages checked); the "
                            "program was written completely."))
