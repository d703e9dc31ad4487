#pragma once

// How watch list errors read, shared by validation (watchlist.cpp), the JSON file
// (watchlistjson.cpp) and the CSV import (watchlistcsv.cpp): every message names its place
// ("table 2, item 5: ...", "line 7: ...").

#include "core/protocol/result.h"

#include <QString>
#include <QStringList>

namespace Fatek::WatchList::Errors {

ProtocolError fileError(const QString &message);
// "Invalid address ..." becomes "invalid address ..." after "table 2, item 5: ". Acronyms ("BCD
// ...") keep their case.
QString lowerFirst(const QString &text);
ProtocolError atPlace(const Message &place, const ProtocolError &error);
// A place that is data (a file name).
ProtocolError atPlace(const QString &place, const ProtocolError &error);

// The display format names, for "unknown format" messages.
QString knownFormats();
ProtocolError tooManyItems(qsizetype count);
// A key no reader of its object knows, refused rather than ignored (a misspelt "staton" would
// poll station 1): "unknown key "fromat" (known: ...); did you mean "format"?", the hint only
// when one known key is close. Plain text like the other watch list file errors.
QString unknownKey(const QString &key, const QStringList &known);

// Places count from 1; table and item are indices.
Message tablePlace(qsizetype table);
Message itemPlace(qsizetype table, qsizetype item);
Message linePlace(int line);

} // namespace Fatek::WatchList::Errors
