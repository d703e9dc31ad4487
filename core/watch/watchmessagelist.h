// The messages of core/watch that are not in core/protocol/messagelist.h, one line each:
// FATEK_MSG(id, argument count, English template), the format of core/protocol/messagelist.h.
// An X-macro list, included only by watchmessages.h (no include guard on purpose).

// The names part of commissioning (issue 18).

// Importing a comment/symbol list of the ladder project (core/watch/symbolimport.cpp).
FATEK_MSG(SymbolsCannotRead, 2, QT_TRANSLATE_NOOP("Fatek::Message", "Cannot read %1: %2"))
FATEK_MSG(SymbolsNoBig5, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "The file is not UTF-8 text, and this build cannot decode Big5."))
// Why a line was skipped (after "line 7: ").
FATEK_MSG(SymbolsNotBig5, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "the line is neither UTF-8 nor Big5 text"))
FATEK_MSG(SymbolsNoAddress, 0,
          QT_TRANSLATE_NOOP("Fatek::Message", "no address in the first column"))
FATEK_MSG(SymbolsNoName, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "%1 has neither a name nor a comment"))
FATEK_MSG(SymbolsQuoteNotClosed, 0,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "a quoted field is not closed on its line (missing \")"))
FATEK_MSG(SymbolsTextAfterQuote, 1,
          QT_TRANSLATE_NOOP("Fatek::Message", "text after the quoted field \"%1\""))
// The outcome: %1 names imported, %2 lines skipped, %3 the first reasons (joined by Listed).
FATEK_MSG(SymbolsSummary, 2,
          QT_TRANSLATE_NOOP("Fatek::Message", "Names imported: %1, lines skipped: %2"))
FATEK_MSG(SymbolsSummaryProblems, 3,
          QT_TRANSLATE_NOOP("Fatek::Message", "Names imported: %1, lines skipped: %2 (%3)"))
FATEK_MSG(SymbolsMoreSkipped, 1, QT_TRANSLATE_NOOP("Fatek::Message", "and %1 more"))
FATEK_MSG(SymbolsReadAsBig5, 1, QT_TRANSLATE_NOOP("Fatek::Message", "%1; read as Big5"))
// Watch list files: the place of an error in "symbols" (%1 counts from 1).
FATEK_MSG(PlaceSymbol, 1, QT_TRANSLATE_NOOP("Fatek::Message", "symbol %1"))

// An item of a gateway connection not read in the last cycle (core/watch/itemassembler.cpp; the
// gateway publishes it as the item's error).
FATEK_MSG(GatewayNoValueThisCycle, 0, QT_TRANSLATE_NOOP("Fatek::Message", "not read in this cycle"))

// JSON text that names a key twice in one object (core/watch/jsonkeys.cpp; after "line 4: "):
// watch lists, the gateway's configuration and its commands.
FATEK_MSG(JsonDuplicateKey, 1, QT_TRANSLATE_NOOP("Fatek::Message", "duplicate key \"%1\""))

// A write of NaN or an infinity to a float or double item (core/watch/itemvalues.cpp); %2 is the
// watch list item's option that allows it.
FATEK_MSG(ValueNotFinite, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "%1 is not a finite number: NaN and infinities are written only to an "
                            "item whose \"%2\" option is on"))

// Strict reading of JSON objects (core/watch/jsonobjectreader.cpp): %1 the key as written; a
// key no reader of that object knows is refused, with the known key it most likely means.
FATEK_MSG(JsonKeyMissing, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is missing."))
FATEK_MSG(JsonOutOfRange, 4, QT_TRANSLATE_NOOP("Fatek::Message", "%1 %2 is out of range (%3..%4)"))
FATEK_MSG(JsonUnknownKeyNear, 2,
          QT_TRANSLATE_NOOP("Fatek::Message",
                            "\"%1\" is not a known setting; did you mean \"%2\"?"))
FATEK_MSG(JsonUnknownKey, 1, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" is not a known setting."))
FATEK_MSG(JsonWrongType, 2, QT_TRANSLATE_NOOP("Fatek::Message", "\"%1\" must be %2."))
FATEK_MSG(JsonTypeArray, 0, QT_TRANSLATE_NOOP("Fatek::Message", "a list"))
FATEK_MSG(JsonTypeBool, 2, QT_TRANSLATE_NOOP("Fatek::Message", "%1 or %2"))
FATEK_MSG(JsonTypeNumber, 0, QT_TRANSLATE_NOOP("Fatek::Message", "a whole number"))
FATEK_MSG(JsonTypeObject, 0, QT_TRANSLATE_NOOP("Fatek::Message", "an object"))
FATEK_MSG(JsonTypeString, 0, QT_TRANSLATE_NOOP("Fatek::Message", "a string"))
