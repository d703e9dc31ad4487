#pragma once

// Quoted CSV fields: read the same way by the watch-list CSV import (watchlistcsv.cpp) and the
// names import (symbolimport.cpp), written the same way by every CSV the programs write (data
// logs, the CLI's --csv, checkout reports).

#include <QString>
#include <QStringView>

namespace Fatek::CsvField {

// Reads the quoted field that starts at text[i] (a '"'): "" inside is one quote. On return i is
// just after the closing quote, or at the end of text when there is none (then false). Line ends
// inside the field are kept and counted into *lineEnds when given.
bool readQuoted(QStringView text, qsizetype &i, QString &field, int *lineEnds = nullptr);

// The text as one field: quoted ("" for a quote) when it holds a separator (',' or ';'), a quote
// or a line end; else as it is.
QString quoted(const QString &text);

} // namespace Fatek::CsvField
