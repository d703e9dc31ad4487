// Part of messagelist.h (included at its end, no include guard on purpose): what the codecs, the
// deframers and the slaves say about frames and answers they cannot use.

// Answers the master cannot use. %1 of AnswerTo: the request ("read R100 x 2"), %2 a detail.
FATEK_MSG(AnswerTo, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Answer to %1: %2"))
FATEK_MSG(AnswerExpectedChars, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "expected %1 data characters (%2), got %3."))
FATEK_MSG(AnswerStatusByteNotHex, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "status byte \"%1\" is not hex."))
FATEK_MSG(AnswerDiscreteNotBinary, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "discrete status \"%1\" is not 0 or 1."))
FATEK_MSG(AnswerValueNotHex, 1, QT_TRANSLATE_NOOP("Fatek::Message", "value \"%1\" is not hex."))
FATEK_MSG(AnswerOddStatusChars, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "status bytes have an odd number of hex characters (%1)."))
FATEK_MSG(AnswerEchoDiffers, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "the echoed %1 bytes differ from the %2 bytes sent."))
FATEK_MSG(AnswerNoErrorByte, 0, QT_TRANSLATE_NOOP("Fatek::Message", "the error byte is missing."))
FATEK_MSG(AnswerDataBytes, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 data bytes instead of %2 (%3)."))
FATEK_MSG(AnswerValueNotDiscrete, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "value %1 for %2 is neither 00 nor 01."))
FATEK_MSG(AnswerWrongStation, 3,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Answer from station %1 while station %2 was asked (%3)."))
// %3 a command name message.
FATEK_MSG(FaconAnswerWrongCommand, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "Answer to command %1 while %2 (%3) was sent."))
FATEK_MSG(BinaryAnswerWrongCommand, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "Answer to command %1 while %2 was sent (%3)."))
FATEK_MSG(AnswerLoopbackDiffers, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Loopback data differs: sent \"%1\", received \"%2\"."))
FATEK_MSG(AnswerNoErrorDigit, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Answer to %1 has no error digit."))
FATEK_MSG(AnswerErrorDigitNotHex, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Answer to %1: error digit \"%2\" is not hex."))
FATEK_MSG(FaconTooManyDataChars, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1: %2 data characters; a FACON frame carries at most 500."))
FATEK_MSG(BinaryQueryEcho, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Received a query frame (51) instead of an answer (52): probably the "
                            "echo of our own query."))

// Frames that are not FACON frames (FaconWire, FaconDeframer).
FATEK_MSG(FaconFrameTooShort, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "FACON frame too short (%1 bytes; at least 8: STX, station, command, "
                            "LRC, ETX)."))
FATEK_MSG(FaconFrameTooLong, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON frame too long (%1 bytes; at most %2)."))
FATEK_MSG(FaconNoStx, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON frame does not start with STX."))
FATEK_MSG(FaconNoEtx, 0, QT_TRANSLATE_NOOP("Fatek::Message", "FACON frame does not end with ETX."))
FATEK_MSG(FaconStrayStxEtx, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON frame contains a stray STX or ETX inside."))
FATEK_MSG(FaconHeaderNotHex, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "FACON frame header \"%1\" is not station and command in hex."))
FATEK_MSG(FaconChecksumNotHex, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON checksum \"%1\" is not two hex characters."))
FATEK_MSG(FaconChecksumError, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON checksum error: frame says %1, computed %2."))
FATEK_MSG(FaconFrameTooShortLrc, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "FACON frame too short (%1 bytes): station, command and LRC do not "
                            "fit."))
FATEK_MSG(FaconFrameNonHexHeader, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON frame with a non-hex station or command."))
FATEK_MSG(FaconFrameChecksumNotHex, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "FACON frame whose checksum is not two hex characters."))
FATEK_MSG(FaconFrameNewStx, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Incomplete FACON frame: a new STX arrived before ETX."))
FATEK_MSG(FaconFrameNoEtx, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "FACON frame without ETX within %1 bytes."))

// Frames that are not binary frames (BinaryWire, BinaryDeframer).
FATEK_MSG(BinaryFrameTooShort, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Binary frame too short (%1 bytes): a frame has at least 10 bytes."))
FATEK_MSG(BinaryFrameBadHeader, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Binary frame starts with %1 instead of 51 (query) or 52 (answer)."))
FATEK_MSG(BinaryFrameBadId, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "Binary frame ID is %1 instead of 10."))
FATEK_MSG(BinaryFrameBadLength, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Binary frame length field says %1 payload bytes but the frame "
                            "carries %2."))
FATEK_MSG(BinaryFrameBadEnd, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Binary frame ends with %1 instead of the terminator 55 AA."))
FATEK_MSG(BinaryFrameBadCrc, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Binary frame CRC is %1, computed %2."))
FATEK_MSG(BinaryFrameNoStation, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "Binary frame without station and command."))
FATEK_MSG(BinaryFrameNoTerminator, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Binary frame of %1 bytes does not end with the terminator 55 AA."))
FATEK_MSG(BinaryFrameWrongCrc, 1,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "Binary frame of %1 bytes has a wrong CRC (line noise or a broken "
                            "frame)."))
