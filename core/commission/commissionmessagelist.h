// The messages of commissioning (core/commission; issue 18), one line each: FATEK_MSG(id, argument
// count, English template), the format of core/protocol/messagelist.h. An X-macro list, included
// only by commissionmessages.h (no include guard on purpose).

// The program part. (ProgramModel, which the program header of core/protocol uses, is in
// core/protocol/messagelist.h.)

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
// The PLC's side of ProgramModelMismatch before its page 0 is read, from the detail status:
// %1 the model it names ("FBs-28MC"), %2 the program size in words.
FATEK_MSG(ProgramPlcModelSize, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 with a %2-word program"))
FATEK_MSG(ProgramPlcUnknownModelSize, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1-word program (the PLC does not name its model)"))
// %1 the page number, %2 why (a message).
FATEK_MSG(ProgramReadPageFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Reading program page %1 failed: %2"))
FATEK_MSG(ProgramWritePageFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Writing program page %1 failed: %2"))
// A restore stopped by a fault while writing: %1 what failed (a message), %2 pages written,
// %3 pages in all.
FATEK_MSG(ProgramRestoreInterrupted, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 The PLC now holds a mixed program (%2 of %3 {3:page|pages} "
                            "written from the backup, the rest from its old program) and "
                            "stays in STOP: restore the same file again before switching it "
                            "to RUN."))
// %1 how many pages, %2 the page list ("3, 7-9").
FATEK_MSG(ProgramVerifyFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Verification failed: %1 {1:page|pages} on the PLC "
                                              "{1:differs|differ} from the backup (%2)."))
// %1 the page reached, %2 pages done, %3 pages in all.
FATEK_MSG(ProgramBackupCancelled, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Backup cancelled at page %1 (%2 of %3 {3:page|pages} read); no "
                            "file saved."))
FATEK_MSG(ProgramRestoreCancelled, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Restore cancelled at page %1 (%2 of %3 {3:page|pages} written): "
                            "the PLC's program is incomplete."))
FATEK_MSG(ProgramCompareCancelled, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cancelled before anything was written."))
// %1 pages, %2 the model (ProgramModel).
FATEK_MSG(ProgramBackupDone, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Backup done: %1 {1:page|pages} of a %2."))
FATEK_MSG(ProgramRestoreDone, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Restore done: %1 {1:page|pages} written and verified."))
// Comparing a backup with the PLC before writing: %1 how many pages differ, %2 the list.
FATEK_MSG(ProgramPagesDiffer, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 {1:page differs|pages differ} from the PLC (%2)."))
FATEK_MSG(ProgramSameAsPlc, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "The PLC already holds this program."))
// What the transfer is doing (progress): reading, writing or reading back.
FATEK_MSG(ProgramPhaseReading, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Reading the program"))
FATEK_MSG(ProgramPhaseWriting, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Writing the program"))
FATEK_MSG(ProgramPhaseVerifying, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Reading the program back to verify"))
FATEK_MSG(ProgramVerifyCancelled, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Verification cancelled at page %1 (%2 of %3 {3:page|pages} "
                            "checked); the program was written completely."))

// The snapshot part.

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
FATEK_MSG(SnapshotTaken, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 {1:value|values} read in %2 {2:request|requests}."))

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
FATEK_MSG(DiffCount, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 of %2 {2:value|values} {1:differs|differ}."))

// Restoring values (core/commission/valuesrestorer.cpp).
FATEK_MSG(RestoreReadOnly, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Operator mode: restoring values is refused; nothing was written."))
FATEK_MSG(RestoreNothing, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The chosen ranges hold no value of the snapshot: nothing to write."))
// Checked before the first write, from the PLC's detail status: %1 the snapshot's model, %2 the
// PLC's (model texts: "M series, OS V3.1, program 16384 words").
FATEK_MSG(RestoreOtherModel, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The snapshot is of another model (%1) than the PLC (%2): not "
                            "restored, nothing was written."))
// %1 the elements ("R5000-5023, D3000"), %2 how many, %3 the PLC's model text, %4 what it has of
// those kinds ("R0-3839, D0-2999").
FATEK_MSG(RestoreOutOfRange, 4,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%2 {2:value|values} of the snapshot {2:is|are} not on the PLC: %1. "
                            "The PLC (%3) has %4. Not restored, nothing was written."))
FATEK_MSG(RestoreCheckFailed, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Reading the PLC's model and ranges failed (%1): nothing was "
                            "written."))
FATEK_MSG(RestoreWriteFailed, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Writing %1 failed: %2"))
// %1 the elements, %2 why the write's outcome is unknown (ChangeStillUnknown).
FATEK_MSG(RestoreWriteUnknown, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Stopped at the write of %1: %2"))
// Writing stopped half-way (a fault, a cancel): %1 why, %2 values written, %3 values in all.
FATEK_MSG(RestoreInterrupted, 3,
          QT_TRANSLATE_NOOP(
              "Fatek::Message",
              "%1 %2 of %3 {3:value|values} had been written when it stopped; the others may "
              "still hold their old values: restore the same file again."))
FATEK_MSG(RestoreVerifyFailed, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Reading the values back failed: %1"))
FATEK_MSG(RestoreDiffer, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 of %2 {2:value|values} {1:differs|differ} after the write "
                            "(read back)."))
FATEK_MSG(RestoreDone, 2,
          QT_TRANSLATE_NOOP(
              "Fatek::Message",
              "%1 {1:value|values} written in %2 {2:request|requests} and read back equal."))

// The I/O checkout (issue 36).

// Checkout plans (core/commission/checkoutplan.cpp).
FATEK_MSG(CheckoutPlanBadKind, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 cannot be checked: a checkout takes inputs X, outputs Y and "
                            "registers R or D."))
FATEK_MSG(CheckoutPlanEmpty, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "The checkout plan holds no points."))
FATEK_MSG(CheckoutPlanDuplicate, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 appears twice in the checkout plan."))
FATEK_MSG(CheckoutPlanNoSymbols, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "No imported name of an input or output starts with \"%1\"."))
// Plan CSV: %1 the line number, %2 what is wrong.
FATEK_MSG(CheckoutCsvLine, 2, QT_TRANSLATE_NOOP("Fatek::Message", "checkout plan line %1: %2"))
// %1 the columns ("address,name,comment,group,low,high,tolerance").
FATEK_MSG(CheckoutCsvColumns, 1, QT_TRANSLATE_NOOP("Fatek::Message", "expected the columns %1"))
FATEK_MSG(CheckoutCsvNumber, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a number"))
FATEK_MSG(CheckoutAnalogNeedsRange, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: an analog point needs its expected low and high values"))

// Checkout files (core/commission/checkoutfile.cpp): %1 the file, %2 why.
FATEK_MSG(CheckoutFileVersion, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "checkout file version %1 is not supported (this program reads 1 to "
                            "%2)"))
FATEK_MSG(CheckoutPlaceInfo, 0, QT_TRANSLATE_NOOP("Fatek::Message", "info"))
// %1 the point's number in the file, %2 its address when known.
FATEK_MSG(CheckoutPlacePoint, 2, QT_TRANSLATE_NOOP("Fatek::Message", "point %1 (%2)"))
FATEK_MSG(CheckoutPlaceEarlier, 1, QT_TRANSLATE_NOOP("Fatek::Message", "earlier attempt %1"))
FATEK_MSG(CheckoutPlaceReading, 1, QT_TRANSLATE_NOOP("Fatek::Message", "reading %1"))
FATEK_MSG(CheckoutPlaceScale, 0, QT_TRANSLATE_NOOP("Fatek::Message", "scale"))
FATEK_MSG(CheckoutPlacePunch, 0, QT_TRANSLATE_NOOP("Fatek::Message", "punch"))
// %1 the key, %2 its value as written.
FATEK_MSG(CheckoutFileBadValue, 2, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" cannot be \"%2\""))
FATEK_MSG(CheckoutFileCannotRead, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot open the checkout %1: %2"))
FATEK_MSG(CheckoutFileCannotWrite, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot save the checkout %1: %2"))
FATEK_MSG(CheckoutFileDamaged, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "The checkout %1 is damaged: %2"))
FATEK_MSG(CheckoutFileNotCheckout, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "not a checkout (\"format\" is not \"%1\")"))

// Running a checkout (core/commission/checkoutrunner.cpp).
FATEK_MSG(CheckoutNoSession, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "No connection to a PLC: the checkout waits."))
FATEK_MSG(CheckoutReadOnly, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Operator mode: testing outputs is refused; nothing was forced."))
FATEK_MSG(CheckoutOutputBusy, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 is still under test: answer for it before the next output."))
FATEK_MSG(CheckoutNotOutput, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 is not an output of the checkout plan."))
// %1 the input that changed, %2 the one under test.
FATEK_MSG(CheckoutCrossedWiring, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 changed while testing %2: crossed wiring?"))
// The question before the first output forced in RUN (%1 the output), and what "no" did.
FATEK_MSG(CheckoutPlcInRun, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The PLC is in RUN: its program drives the outputs too. Force %1 on "
                            "anyway? Yes: %1 and then each output tested is forced on until its "
                            "answer, whatever the program does. No: nothing is forced."))
FATEK_MSG(CheckoutRunNotConfirmed, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not forced: the PLC is in RUN and forcing was not confirmed. The "
                            "outputs stay untested."))
FATEK_MSG(CheckoutForceFailed, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Forcing %1 failed: %2"))
FATEK_MSG(CheckoutReleaseFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Releasing %1 failed: %2. It stays recorded as forced; the release "
                            "is tried again until the PLC confirms it."))
FATEK_MSG(CheckoutStillReleasing, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 is not released yet (the PLC has not confirmed it): it is forced "
                            "again only after that."))
// %1 the outputs released ("Y0, Y3").
FATEK_MSG(CheckoutReleased, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Released the outputs the checkout had forced: %1."))
FATEK_MSG(CheckoutLinkLost, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The link is lost: a forced output is released as soon as it is "
                            "back."))
FATEK_MSG(CheckoutReadFailed, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Reading %1 failed: %2"))

// The checkout's words (reports, the GUI): kinds and results of a point.
FATEK_MSG(CheckoutKindInput, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Input"))
FATEK_MSG(CheckoutKindOutput, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Output"))
FATEK_MSG(CheckoutKindAnalog, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Analog"))
FATEK_MSG(CheckoutUntested, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Untested"))
FATEK_MSG(CheckoutPassed, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Passed"))
FATEK_MSG(CheckoutFailed, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Failed"))
FATEK_MSG(CheckoutPassedWithRemark, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Passed with remark"))
FATEK_MSG(CheckoutDeferred, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Deferred"))
FATEK_MSG(CheckoutNotApplicable, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Not applicable"))
// What was measured: %1 and %2 the times 0->1 and 1->0 were seen ("-" when not).
FATEK_MSG(CheckoutInputTimes, 2, QT_TRANSLATE_NOOP("Fatek::Message", "0->1 at %1, 1->0 at %2"))
FATEK_MSG(CheckoutOutputSeen, 0, QT_TRANSLATE_NOOP("Fatek::Message", "seen in the field"))
FATEK_MSG(CheckoutOutputNotSeen, 0, QT_TRANSLATE_NOOP("Fatek::Message", "not seen in the field"))
// %1 %2 the raw values read at the low and high end ("-" when not), %3 %4 expected, %5 the
// tolerance.
// Analog readings: %1 the check (per cent of the span), %2 the value in engineering units with
// its unit; %3 as left, or what was expected.
FATEK_MSG(CheckoutAnalogFound, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 %: %2"))
FATEK_MSG(CheckoutAnalogFoundLeft, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 %: found %2, left %3"))
FATEK_MSG(CheckoutAnalogOff, 3, QT_TRANSLATE_NOOP("Fatek::Message", "%1 %: %2, expected %3"))
// %1 the readings, %2 the tolerance with its unit.
FATEK_MSG(CheckoutAnalogReadings, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 (tolerance %2)"))
// Flagged on an input: %1 the inputs that changed while it was under test.
FATEK_MSG(CheckoutChangedWith, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "also changed while it was tested: %1"))

// What the runner refuses to record (core/commission/checkoutrunner.cpp); %1 the point.
FATEK_MSG(CheckoutAnalogNoScale, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 has no expected values: give its scale (raw and engineering low "
                            "and high) in the plan before it can pass"))
FATEK_MSG(CheckoutNoEngineer, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Name the engineer who records the results: the report says who "
                            "tested each point."))
FATEK_MSG(CheckoutNotRunning, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The checkout is not running: start it first. Nothing was forced."))
FATEK_MSG(CheckoutNoSuchPoint, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 is not a point of the checkout"))
FATEK_MSG(CheckoutNotAnalog, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1 is not an analog point"))
FATEK_MSG(CheckoutNeedsRemark, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1: \"passed with remark\" needs the remark"))
FATEK_MSG(CheckoutNeedsReason, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1: \"deferred\" needs the reason"))
FATEK_MSG(CheckoutCrossedCannotPass, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 cannot pass clean: %2 changed while it was tested (crossed "
                            "wiring?). Re-test it, or pass it with a remark."))
FATEK_MSG(CheckoutMeasuredOnly, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 passes or fails by what is read: read it at each check"))
FATEK_MSG(CheckoutNoCheck, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 has no check at %2 %"))
FATEK_MSG(CheckoutNoAsFound, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 at %2 %: read the value as found before the value as left"))
FATEK_MSG(CheckoutPunchStillFailing, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 still fails: re-test it before its punch item is closed out"))
FATEK_MSG(CheckoutNotOnPunchList, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 is not on the punch list"))
// The plan against the PLC: %1 the points, %2 the PLC's answer, %3 how many.
FATEK_MSG(CheckoutPointsRefused, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The PLC refuses %1 (%2): %3 {3:point|points} to take out of the "
                            "plan. Nothing was forced."))
FATEK_MSG(CheckoutReadAgain, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1 are read again"))
FATEK_MSG(CheckoutCsvChecks, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "checks \"%1\": per cents from 0 to 100 separated by \"/\""))

// The report (core/commission/checkoutreport.cpp, report/checkoutpdf.cpp).
FATEK_MSG(ReportTitle, 0, QT_TRANSLATE_NOOP("Fatek::Message", "I/O checkout report"))
FATEK_MSG(ReportProject, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Project"))
FATEK_MSG(ReportCustomer, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Customer"))
FATEK_MSG(ReportPlcModel, 0, QT_TRANSLATE_NOOP("Fatek::Message", "PLC model"))
FATEK_MSG(ReportOsVersion, 0, QT_TRANSLATE_NOOP("Fatek::Message", "OS version"))
FATEK_MSG(ReportStation, 0, QT_TRANSLATE_NOOP("Fatek::Message", "PLC station"))
FATEK_MSG(ReportDate, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Date"))
FATEK_MSG(ReportEngineer, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Engineer"))
FATEK_MSG(ReportNotReported, 0, QT_TRANSLATE_NOOP("Fatek::Message", "not reported by the PLC"))
FATEK_MSG(ReportPoint, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Point"))
FATEK_MSG(ReportName, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Name"))
FATEK_MSG(ReportGroup, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Group"))
FATEK_MSG(ReportKind, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Kind"))
FATEK_MSG(ReportResult, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Result"))
FATEK_MSG(ReportMeasured, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Measured"))
FATEK_MSG(ReportComment, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Comment"))
FATEK_MSG(ReportTested, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Tested at"))
// %1 points in all, %2 passed, %3 failed, %4 skipped, %5 untested.
FATEK_MSG(ReportSummary, 7,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 {1:point|points}: %2 passed, %3 passed with remark, %4 failed, "
                            "%5 deferred, %6 not applicable, %7 untested."))
FATEK_MSG(ReportSummaryTitle, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Summary"))
FATEK_MSG(ReportSignatures, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Signatures"))
FATEK_MSG(ReportSignEngineer, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Commissioning engineer"))
FATEK_MSG(ReportSignCustomer, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Customer representative"))
FATEK_MSG(ReportSignWitness, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Witness"))
FATEK_MSG(ReportSignRole, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Role"))
FATEK_MSG(ReportSignName, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Printed name"))
FATEK_MSG(ReportSignCompany, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Company"))
FATEK_MSG(ReportSignature, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Signature"))
FATEK_MSG(ReportTestDates, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Tested"))
// %1 the first result's time, %2 the last one's (with their UTC offsets).
FATEK_MSG(ReportTestRange, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 to %2"))
FATEK_MSG(ReportNotYet, 0, QT_TRANSLATE_NOOP("Fatek::Message", "nothing recorded yet"))
FATEK_MSG(ReportMade, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Report made"))
// %1 who, %2 how many points they recorded.
FATEK_MSG(ReportEngineerPoints, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 (%2 {2:point|points})"))
FATEK_MSG(ReportUnnamed, 0, QT_TRANSLATE_NOOP("Fatek::Message", "not named"))
// %1 this page, %2 the report's pages.
FATEK_MSG(ReportPageOf, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Page %1 of %2"))
FATEK_MSG(ReportResults, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Results"))
FATEK_MSG(ReportPunchList, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Punch list"))
FATEK_MSG(ReportNoFailed, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "The punch list is empty: no point failed or was "
                                              "deferred."))
FATEK_MSG(ReportAttempts, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Attempts"))
FATEK_MSG(ReportOwner, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Owner"))
FATEK_MSG(ReportPunchState, 0, QT_TRANSLATE_NOOP("Fatek::Message", "State"))
FATEK_MSG(ReportPunchOpen, 0, QT_TRANSLATE_NOOP("Fatek::Message", "open"))
// %1 when, %2 who.
FATEK_MSG(ReportPunchClosed, 2, QT_TRANSLATE_NOOP("Fatek::Message", "closed %1 by %2"))
FATEK_MSG(ReportDocument, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Document"))
FATEK_MSG(ReportRevision, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Revision"))
// %1 how many, %2 their addresses.
FATEK_MSG(ReportUntestedList, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Not tested (%1): %2"))
FATEK_MSG(ReportCannotWrite, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Cannot write the report %1: %2"))
FATEK_MSG(ReportUnknownType, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1: a report file name ends in .pdf or .csv."))
