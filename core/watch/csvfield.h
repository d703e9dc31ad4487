#pragma once

// Quoted CSV fields, written the same way by every CSV the programs write (data logs, the CLI's
// --csv, checkout reports); CsvReader reads them.

#include <QString>

namespace Fatek::CsvField {

// The text as one field: quoted ("" for a quote) when it holds a separator (',' or ';'), a quote
// or a line end; else as it is.
QString quoted(const QString &text);

} // namespace Fatek::CsvField
