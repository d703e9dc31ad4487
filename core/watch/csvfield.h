#pragma once

// Quoted CSV fields, read the same way by the watch-list CSV import (watchlistcsv.cpp) and the
// names import (symbolimport.cpp). Internal to core/watch.

#include <QString>
#include <QStringView>

namespace Fatek::CsvField {

// Reads the quoted field that starts at text[i] (a '"'): "" inside is one quote. On return i is
// just after the closing quote, or at the end of text when there is none (then false). Line ends
// inside the field are kept and counted into *lineEnds when given.
bool readQuoted(QStringView text, qsizetype &i, QString &field, int *lineEnds = nullptr);

} // namespace Fatek::CsvField
