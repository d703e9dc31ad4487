// The messages of the protocol layer and the layers up to core/watch that need no list of their
// own, one line each: FATEK_MSG(id, argument count, English template). An X-macro list, included
// only by message.h (no include guard on purpose). The template is the text the program has always
// written in English; its %1..%n take the arguments in order (the count is checked where a message
// is built). lupdate reads the QT_TRANSLATE_NOOP marks (context "Fatek::Message"); tst_messages
// checks every id against both translations. Add new ids anywhere: nothing stores their order,
// they are compiled in and go on the wire by name. The list goes on in messagelistframes.h
// (included right after this file, to keep each file under 600 lines); the other libraries' lists
// are in their own folders (docs/architecture.md, "Messages").

// A text shown as it is in every language (data, or an operating system's own error text).
FATEK_MSG(Text, 1, "%1")

// Joins that translations may reorder: a subject and its detail.
FATEK_MSG(Joined, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1: %2"))
FATEK_MSG(Spaced, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 %2"))
FATEK_MSG(Listed, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1; %2"))

// PLC error codes (either protocol).
FATEK_MSG(PlcCodeNoError, 0, QT_TRANSLATE_NOOP("Fatek::Message", "no error"))
FATEK_MSG(PlcCodeIllegalValue, 0, QT_TRANSLATE_NOOP("Fatek::Message", "illegal value"))
FATEK_MSG(PlcCodeWriteProhibited, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "write prohibited (ROM pack)"))
FATEK_MSG(PlcCodeIllegalFormat, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "illegal format, or command cannot execute"))
FATEK_MSG(PlcCodeLadderChecksum, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "cannot RUN: ladder checksum error"))
FATEK_MSG(PlcCodeIdMismatch, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "cannot RUN: PLC ID differs from ladder ID"))
FATEK_MSG(PlcCodeSyntaxError, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "cannot RUN: syntax check error"))
FATEK_MSG(PlcCodeNotSupported, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "cannot RUN: function not supported"))
FATEK_MSG(PlcCodeIllegalAddress, 0, QT_TRANSLATE_NOOP("Fatek::Message", "illegal address"))
FATEK_MSG(PlcCodeUnknown, 0, QT_TRANSLATE_NOOP("Fatek::Message", "unknown error code"))
// %1 the code in hex, %2 its text (a PlcCode message), %3 what was asked ("R70000").
FATEK_MSG(PlcError, 2, QT_TRANSLATE_NOOP("Fatek::Message", "PLC error %1: %2"))
FATEK_MSG(PlcErrorAbout, 3, QT_TRANSLATE_NOOP("Fatek::Message", "PLC error %1: %2 %3"))

// Protocol command names.
FATEK_MSG(CommandBriefStatus, 0, QT_TRANSLATE_NOOP("Fatek::Message", "read brief status"))
FATEK_MSG(CommandRunStop, 0, QT_TRANSLATE_NOOP("Fatek::Message", "RUN/STOP control"))
FATEK_MSG(CommandDiscreteControl, 0, QT_TRANSLATE_NOOP("Fatek::Message", "single discrete control"))
FATEK_MSG(CommandReadEnableFlags, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "read enable/disable flags"))
FATEK_MSG(CommandReadDiscretes, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "read consecutive discretes"))
FATEK_MSG(CommandWriteDiscretes, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "write consecutive discretes"))
FATEK_MSG(CommandReadRegisters, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "read consecutive registers"))
FATEK_MSG(CommandWriteRegisters, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "write consecutive registers"))
FATEK_MSG(CommandMixedRead, 0, QT_TRANSLATE_NOOP("Fatek::Message", "mixed read"))
FATEK_MSG(CommandMixedWrite, 0, QT_TRANSLATE_NOOP("Fatek::Message", "mixed write"))
FATEK_MSG(CommandLoopback, 0, QT_TRANSLATE_NOOP("Fatek::Message", "loopback test"))
FATEK_MSG(CommandReadProgram, 0, QT_TRANSLATE_NOOP("Fatek::Message", "read program page"))
FATEK_MSG(CommandWriteProgram, 0, QT_TRANSLATE_NOOP("Fatek::Message", "write program page"))
FATEK_MSG(CommandDetailStatus, 0, QT_TRANSLATE_NOOP("Fatek::Message", "read detail status"))
FATEK_MSG(CommandUnknown, 0, QT_TRANSLATE_NOOP("Fatek::Message", "unknown command"))

// Traffic log: what a frame is (codecs' summaries).
// %1 station, %2 command code in hex, %3 the rest (command name and detail, or the answer).
FATEK_MSG(FrameStation, 3, QT_TRANSLATE_NOOP("Fatek::Message", "station %1, %2 %3"))
FATEK_MSG(FrameInvalidFacon, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "invalid FACON frame (%1 bytes): %2"))
FATEK_MSG(FrameBadBinary, 2, QT_TRANSLATE_NOOP("Fatek::Message", "bad binary frame (%1 bytes): %2"))
FATEK_MSG(FrameAnswerOk, 0, QT_TRANSLATE_NOOP("Fatek::Message", "answer: OK"))
FATEK_MSG(FrameAnswerOkChars, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "answer: OK, %1 data chars \"%2\""))
FATEK_MSG(FrameAnswerOkBytes, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "answer: OK, %1 data bytes: %2"))
FATEK_MSG(FrameAnswerNoErrorDigit, 0, QT_TRANSLATE_NOOP("Fatek::Message", "answer: no error digit"))
FATEK_MSG(FrameAnswerNoErrorByte, 0, QT_TRANSLATE_NOOP("Fatek::Message", "answer: no error byte"))
FATEK_MSG(FrameAnswerMalformed, 1, QT_TRANSLATE_NOOP("Fatek::Message", "answer: malformed \"%1\""))
FATEK_MSG(FrameAnswerEcho, 1, QT_TRANSLATE_NOOP("Fatek::Message", "answer: echo of %1 bytes"))
// %1 the code in hex, %2 its text (a PlcCode message).
FATEK_MSG(FrameAnswerError, 2, QT_TRANSLATE_NOOP("Fatek::Message", "answer: error %1 (%2)"))
FATEK_MSG(FrameUnknownCommand, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "unknown command, data \"%1\""))
FATEK_MSG(FrameChars, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 chars \"%2\""))
FATEK_MSG(FrameStopOrNoError, 0, QT_TRANSLATE_NOOP("Fatek::Message", "STOP, or answer: no error"))
// %2: the first elements, each after a space (" R0 R1 ..."), or nothing.
FATEK_MSG(FrameElements, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 elements%2"))
FATEK_MSG(FramePage, 1, QT_TRANSLATE_NOOP("Fatek::Message", "page %1"))
FATEK_MSG(FramePageWords, 1, QT_TRANSLATE_NOOP("Fatek::Message", "page %1, 64 words"))
FATEK_MSG(FrameDisable, 1, QT_TRANSLATE_NOOP("Fatek::Message", "disable %1"))
FATEK_MSG(FrameEnable, 1, QT_TRANSLATE_NOOP("Fatek::Message", "enable %1"))
FATEK_MSG(FrameSet, 1, QT_TRANSLATE_NOOP("Fatek::Message", "set %1"))
FATEK_MSG(FrameReset, 1, QT_TRANSLATE_NOOP("Fatek::Message", "reset %1"))

// Traffic log events and their notes.
FATEK_MSG(LogLinkLost, 0, QT_TRANSLATE_NOOP("Fatek::Message", "link lost"))
FATEK_MSG(LogStaleBytes, 0, QT_TRANSLATE_NOOP("Fatek::Message", "stale bytes discarded"))
FATEK_MSG(LogOutsideAnswer, 0, QT_TRANSLATE_NOOP("Fatek::Message", "received outside an answer"))
FATEK_MSG(LogUnexpectedBytes, 0, QT_TRANSLATE_NOOP("Fatek::Message", "unexpected bytes"))
FATEK_MSG(LogNoQueryPending, 0, QT_TRANSLATE_NOOP("Fatek::Message", "no query pending"))
FATEK_MSG(LogEchoOfQuery, 0, QT_TRANSLATE_NOOP("Fatek::Message", "echo of the query"))
FATEK_MSG(LogRawAnswer, 0, QT_TRANSLATE_NOOP("Fatek::Message", "raw answer"))
FATEK_MSG(LogRawFrame, 0, QT_TRANSLATE_NOOP("Fatek::Message", "raw frame"))
FATEK_MSG(LogNoCompleteFrame, 0, QT_TRANSLATE_NOOP("Fatek::Message", "no complete frame"))
FATEK_MSG(LogRestNotRead, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "more than %1 bytes: rest not read"))
FATEK_MSG(LogNoAnswerWithin, 1, QT_TRANSLATE_NOOP("Fatek::Message", "no answer within %1 ms"))
FATEK_MSG(LogProtocolDetected, 1, QT_TRANSLATE_NOOP("Fatek::Message", "protocol detected: %1"))
FATEK_MSG(LogBytesKept, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 bytes, first %2 kept"))
FATEK_MSG(LogClosing, 0, QT_TRANSLATE_NOOP("Fatek::Message", "closing"))
FATEK_MSG(LogSendingQueuedWrites, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "sending %1 queued write(s) first, at most %2 ms"))

// Link states and reasons (%1 of LinkLostBecause and NextAttempt: a reason message).
FATEK_MSG(LinkClosed, 0, QT_TRANSLATE_NOOP("Fatek::Message", "closed"))
FATEK_MSG(LinkConnecting, 0, QT_TRANSLATE_NOOP("Fatek::Message", "connecting"))
FATEK_MSG(LinkConnected, 0, QT_TRANSLATE_NOOP("Fatek::Message", "connected"))
FATEK_MSG(LinkLost, 0, QT_TRANSLATE_NOOP("Fatek::Message", "lost"))
FATEK_MSG(LinkReconnecting, 0, QT_TRANSLATE_NOOP("Fatek::Message", "reconnecting"))
FATEK_MSG(LinkLostBecause, 1, QT_TRANSLATE_NOOP("Fatek::Message", "link lost: %1"))
FATEK_MSG(LinkNextAttempt, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1; next attempt in %2 s"))
FATEK_MSG(LinkSessionClosed, 0, QT_TRANSLATE_NOOP("Fatek::Message", "the session was closed"))
FATEK_MSG(LinkSessionClosedAfterWaiting, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "the session was closed after waiting %1 ms for queued writes"))
FATEK_MSG(LinkDoesNotTakeData, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1 does not take data"))
FATEK_MSG(LinkNoConnectionWithin, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "no connection to %1 within %2 ms"))
FATEK_MSG(LinkPeerClosed, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1 closed the connection"))
// %2: the operating system's text (Qt's, already in the UI language).
FATEK_MSG(LinkCannotOpen, 2, QT_TRANSLATE_NOOP("Fatek::Message", "cannot open %1: %2"))
FATEK_MSG(LinkAutoDetectFailed, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Protocol auto-detect: station %1 answered neither in FACON nor in "
                            "binary (%2)"))
FATEK_MSG(LinkBroadcastNeedsProtocol, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not sent: a broadcast (station 0) has no station to detect the "
                            "protocol with; give --protocol for a broadcast (or choose FACON or "
                            "binary in the connection)"))

// Requests the session did not complete.
FATEK_MSG(SessionNoAnswerFromStation, 4,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "No answer from station %1 within %2 ms (attempt %3 of %4)."))
FATEK_MSG(SessionNoAnswerWithin, 1, QT_TRANSLATE_NOOP("Fatek::Message", "No answer within %1 ms."))
FATEK_MSG(SessionLinkNotOpen, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Not sent: the link is not open."))
FATEK_MSG(SessionLinkDown, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Not sent: the link is down (%1)."))
FATEK_MSG(SessionQueueFull, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not sent: %1 requests are already waiting on this link (the PLC "
                            "answers slower than requests arrive)."))
FATEK_MSG(SessionReadOnly, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Read-only mode: \"%1\" was not sent. Leave operator mode to change "
                            "the PLC."))
FATEK_MSG(SessionCancelled, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Cancelled before it was sent."))
FATEK_MSG(SessionLinkClosing, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Not sent: the link is closing."))
FATEK_MSG(SessionFrameNotTaken, 4,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not sent: %1 did not take the frame within %2 ms (%3 of %4 bytes "
                            "unsent)."))
FATEK_MSG(SessionFewerValues, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "The answer carries fewer values than asked."))
FATEK_MSG(SessionCouldNotWrite, 1, QT_TRANSLATE_NOOP("Fatek::Message", "Could not write to %1."))
FATEK_MSG(SessionNotExecuted, 0, QT_TRANSLATE_NOOP("Fatek::Message", "not executed"))
// The outcome of a change whose answer was lost (ChangeVerifier). They do not name the change:
// whoever shows them says what was asked ("Write of R50 = 3333: ..."). %1 why it is unknown, or
// why the read-back failed (a sentence).
FATEK_MSG(ChangeUnknown, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Outcome unknown: %1 It may have been carried out; reading it back as "
                            "soon as the PLC answers."))
FATEK_MSG(ChangeReadBackDone, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Done: confirmed by reading it back."))
FATEK_MSG(ChangeReadBackNotDone, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not done: read back afterwards, the PLC does not hold what was sent "
                            "(not carried out, or changed since by its program)."))
FATEK_MSG(
    ChangeStillUnknown, 1,
    QT_TRANSLATE_NOOP("Fatek::Message",
                      "Outcome still unknown: it could not be read back (%1). Check the PLC."))
// Why a read-back was not trusted (after ChangeStillUnknown's "could not be read back (").
FATEK_MSG(
    ChangeAnswersLost, 0,
    QT_TRANSLATE_NOOP("Fatek::Message",
                      "other queries to the PLC kept going unanswered meanwhile, so an answer "
                      "could not be told apart from a late one"))
FATEK_MSG(ChangeNoReadBack, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Outcome unknown: no read can tell whether it was carried out. Check "
                            "the PLC."))
FATEK_MSG(SessionExpired, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Not sent: it waited past its deadline (nothing reached the PLC)."))
// Polling a silent station (issue 31): %1 the station, %2 requests in a row without an answer, %3
// the time (HH:mm:ss) of the next try.
FATEK_MSG(SessionStationDemoted, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Station %1 does not answer (%2 requests in a row); polled again at "
                            "%3."))
// %1 seconds since the value was read, %2 the interval in ms.
FATEK_MSG(SessionValueLate, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Late: no new value for %1 s (polled every %2 ms); the line is busy "
                            "or slow."))
FATEK_MSG(LogStationDemoted, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "station %1 demoted after %2 requests without an answer; next try "
                            "at %3"))
FATEK_MSG(LogStationAnswersAgain, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "station %1 answers again; polled as usual"))
// A line slower than a poll interval (issue 55): %1 the station, %2 the interval asked (ms), %3 the
// period the line gives (ms), from which "late" is counted.
FATEK_MSG(LogPollSlower, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "station %1: items polled every %2 ms are read every %3 ms, as fast "
                            "as the line allows; late is counted from that"))
FATEK_MSG(LogPollOnTime, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "station %1: items polled every %2 ms are read on time again"))

// Addresses typed by the user.
FATEK_MSG(AddressEmpty, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Empty address: type an element such as R12 or X0."))
FATEK_MSG(AddressNoType, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Invalid address \"%1\": it must start with an element type such as "
                            "R, X or DWM."))
FATEK_MSG(AddressUnknownType, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Invalid address \"%1\": unknown element type \"%2\" (known: %3)."))
FATEK_MSG(AddressNoNumber, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Invalid address \"%1\": the element number is missing (e.g. %2)."))
FATEK_MSG(AddressNotDecimal, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Invalid address \"%1\": \"%2\" is not a decimal element number."))
FATEK_MSG(AddressNumberTooLarge, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Invalid address \"%1\": element number too large."))
FATEK_MSG(AddressOutOfRange, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Address %1 is out of range: %2 numbers go from 0 to %3."))
FATEK_MSG(AddressNotAligned, 4,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Address %1 is not aligned: %2 must start at a multiple of %3 (e.g. "
                            "%4)."))
FATEK_MSG(AddressRunPast, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 elements from %2 run past %3, the last %4."))

// Link settings checks.
FATEK_MSG(SettingsDemoteAfter, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Demote after %1 unanswered requests is out of range (0 to 100; 0 "
                            "never demotes)."))
FATEK_MSG(SettingsDemotion, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "A demotion of %1 ms is out of range (1000 to 600000 ms)."))
FATEK_MSG(SettingsNoHost, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Enter the PLC's IP address or host name."))
FATEK_MSG(SettingsPortZero, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Port 0 is not usable; FATEK Ethernet modules usually listen on 500."))
FATEK_MSG(SettingsNoSerialPort, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Choose a serial port."))
FATEK_MSG(SettingsBaudRate, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Baud rate %1 is out of range (1200 to 921600)."))
FATEK_MSG(SettingsDataBits, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Data bits must be 7 or 8, not %1."))
FATEK_MSG(SettingsStopBits, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Stop bits must be 1 or 2, not %1."))
FATEK_MSG(SettingsTimeout, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Timeout %1 ms is out of range (1 to 60000 ms)."))
FATEK_MSG(SettingsRetries, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Retries %1 is out of range (0 to 10)."))
FATEK_MSG(SettingsInterFrame, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Inter-frame silence %1 ms is out of range (0 to 1000 ms)."))
FATEK_MSG(SettingsConnectTimeout, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Connect timeout must be at least 1 ms."))
// Link URLs (LinkSettings::fromUrl): %1 the URL as given.
FATEK_MSG(SettingsUrlEmpty, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "No link given: write tcp://HOST[:PORT], udp://HOST[:PORT] or "
                            "serial://PORT."))
FATEK_MSG(SettingsUrlScheme, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Link \"%1\": start it with tcp://, udp:// or serial:// (for example "
                            "tcp://192.168.1.5:500 or serial:///dev/ttyUSB0)."))
FATEK_MSG(SettingsUrlHostPort, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Link \"%1\": write HOST or HOST:PORT with a port from 1 to 65535; an "
                            "IPv6 address goes in brackets, as in [fe80::1]:500."))
FATEK_MSG(SettingsUrlNoPort, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Link \"%1\": name the serial port, as in serial:///dev/ttyUSB0 or "
                            "serial://COM3."))
// %2 the setting's name, %3 the settings the link takes.
FATEK_MSG(SettingsUrlUnknown, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Link \"%1\": no setting \"%2\" (this link takes %3)."))
// %2 the setting's name, %3 its value, %4 what it takes.
FATEK_MSG(SettingsUrlValue, 4,
          QT_TRANSLATE_NOOP("Fatek::Message", "Link \"%1\": %2 takes %4, not \"%3\"."))
FATEK_MSG(SettingsReconnectDelays, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Reconnect delays must be positive, the maximum not below the "
                            "minimum."))

// Address ranges typed by the user (AddressRange, WatchList).
FATEK_MSG(RangeIncomplete, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Incomplete range \"%1\": write it as first..last, e.g. R100..R163."))
FATEK_MSG(RangeMixedTypes, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Range \"%1\" mixes %2 and %3: both ends must be the same element "
                            "type."))
FATEK_MSG(RangeBackwards, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Range \"%1\" runs backwards: write the lower address first (%2)."))
FATEK_MSG(RangeNotWhole, 5,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Range \"%1\" does not end on a whole element: %2 elements are %3 "
                            "apart (%4, %5, ...)."))
FATEK_MSG(RangeTooMany, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Range \"%1\" has %2 elements; at most %3 fit in one range."))
FATEK_MSG(RangeNoneGiven, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "No range given; write for example X0-255, Y0-255."))

// Bytes typed in the raw console (FrameText).
FATEK_MSG(
    FrameTextNotHex, 1,
    QT_TRANSLATE_NOOP("Fatek::Message",
                      "\u201c%1\u201d is not a hex digit; type bytes like 01 46 03 52 00 0C."))
FATEK_MSG(FrameTextNothingHex, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Nothing to send: type the frame's bytes in hex."))
FATEK_MSG(FrameTextOddDigits, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Odd number of hex digits: each byte needs two (0C, not C)."))
FATEK_MSG(FrameTextNotAscii, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Only printable ASCII can be typed; write control characters as "
                            "<STX>, <ETX> or <0D>."))
FATEK_MSG(FrameTextNothing, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Nothing to send: type the frame."))

// Values typed for a display format (ValueFormat::parse).
FATEK_MSG(ValueNotBcd, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a BCD number (digits 0-9 only)"))
FATEK_MSG(ValueNotHex, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a hexadecimal number"))
FATEK_MSG(ValueNotBinary, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a binary number (only 0 and 1)"))
FATEK_MSG(ValueNotNumber, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a number"))
FATEK_MSG(ValueBcdNegative, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "BCD values cannot be negative (\"%1\")"))
// %2: a width message (ValueWidth...).
FATEK_MSG(ValueBcdTooLarge, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 does not fit %2 as BCD (0..%3)"))
FATEK_MSG(ValueTooLarge, 3, QT_TRANSLATE_NOOP("Fatek::Message", "%1 does not fit %2 (%3)"))
FATEK_MSG(ValueNotBit, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a bit value: type ON, OFF, 1 or 0"))
FATEK_MSG(ValueFloatTooLarge, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 does not fit a 32-bit float (largest about ±%2)"))
FATEK_MSG(ValueDoubleTooLarge, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 does not fit a 64-bit double (largest about ±%2)"))
FATEK_MSG(ValueAsciiTooLong, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is too long: %2 holds %3 ASCII characters"))
FATEK_MSG(ValueNotPrintable, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" contains a character that is not plain printable ASCII "
                            "(letters, digits, punctuation and space only)"))
FATEK_MSG(ValueWidthBit, 0, QT_TRANSLATE_NOOP("Fatek::Message", "a bit"))
FATEK_MSG(ValueWidthRegister, 0, QT_TRANSLATE_NOOP("Fatek::Message", "a 16-bit register"))
FATEK_MSG(ValueWidthBits, 1, QT_TRANSLATE_NOOP("Fatek::Message", "a %1-bit value"))
FATEK_MSG(ValueCannotWriteWidth, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "A %1-bit value cannot be written (only 1, 16, 32 or 64 bits)."))
FATEK_MSG(ValueNoBitTyped, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "No value typed: type ON, OFF, 1 or 0."))
FATEK_MSG(ValueNoNumberTyped, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "No value typed: type a number such as 12, -5, 0x1A or 1Ah."))

// Requests the protocol cannot carry (validateRequest, the poll planner). %1 of the Command...
// ones: a command name message.
FATEK_MSG(RequestNotInFacon, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 elements are not available in the FACON protocol (binary "
                            "protocol only)."))
FATEK_MSG(RequestDiscreteValue, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Value %1 for %2: a discrete takes 0 (OFF) or 1 (ON)."))
FATEK_MSG(RequestRegisterValue, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Value %1 for %2 does not fit a 16-bit register (0..65535)."))
FATEK_MSG(RequestNeedsDiscrete, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 needs a discrete (X Y M S T C), not %2."))
FATEK_MSG(RequestTooManyPoints, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 points requested; one request carries 1 to 256 points."))
FATEK_MSG(RequestNeedsRegister, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 needs a register (R, D, WY, DR, ...), not %2; use discretes "
                            "commands for single points."))
FATEK_MSG(RequestTooManyRegisters16, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 16-bit registers requested; one request carries 1 to %3."))
FATEK_MSG(RequestTooManyRegisters32, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 32-bit registers requested; one request carries 1 to %3 "
                            "(32-bit registers count as two words)."))
FATEK_MSG(RequestNoElement, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1: no element given."))
FATEK_MSG(RequestTooManyElements, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 elements; at most %3 words fit in one request."))
FATEK_MSG(RequestTooManyWords, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 words requested; at most %3 fit in one request (a discrete or "
                            "16-bit element counts 1, a 32-bit element 2)."))
FATEK_MSG(RequestBadStation, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Station %1 is not valid: stations are 1 to 254 (0 = broadcast)."))
FATEK_MSG(RequestBadDiscreteOp, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Unknown discrete operation %1."))
FATEK_MSG(RequestMixedCounts, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Mixed write: %1 addresses but %2 values."))
FATEK_MSG(RequestLoopbackTooLong, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Loopback test data is %1 bytes; at most 256 fit in one request."))
FATEK_MSG(RequestLoopbackNotAscii, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "FACON loopback data must be printable ASCII characters."))
FATEK_MSG(RequestProgramFaconOnly, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Program pages (4F/50) exist only in the FACON protocol."))
FATEK_MSG(RequestProgramPageSize, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "A program page holds exactly 64 words; %1 given."))
FATEK_MSG(RequestProgramWords, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Program words are 16-bit (0..65535)."))
FATEK_MSG(RequestUnknownCommand, 1, QT_TRANSLATE_NOOP("Fatek::Message", "Unknown command code %1."))
FATEK_MSG(PlanBroadcast, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: station 0 is broadcast; PLCs do not answer it, so nothing can be "
                            "read there."))

// Watch list files: where an error is (%2 of AtPlace: the error, its first letter lowered in
// English, "table 2, item 5: invalid address ...").
FATEK_MSG(AtPlace, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1: %2"))
FATEK_MSG(PlaceTable, 1, QT_TRANSLATE_NOOP("Fatek::Message", "table %1"))
FATEK_MSG(PlaceItem, 2, QT_TRANSLATE_NOOP("Fatek::Message", "table %1, item %2"))
FATEK_MSG(PlaceLine, 1, QT_TRANSLATE_NOOP("Fatek::Message", "line %1"))
FATEK_MSG(PlaceNotSaved, 0, QT_TRANSLATE_NOOP("Fatek::Message", "Not saved"))
FATEK_MSG(WatchListTooManyItems, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 items are more than one table holds (at most %2)"))

// The program header (page 0, programheader.cpp): %1 the family ("FBs", "M"), %2 the program
// size in words.
FATEK_MSG(ProgramModel, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 series, %2-word program"))
