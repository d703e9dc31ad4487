#pragma once

#include "core/watch/csvfile.h"

#include <QCoreApplication>
#include <QString>

namespace Fatek {

// The file types of every save-as-CSV dialog: plain CSV (LF) and a second type, "CSV, Windows line
// ends", for the same *.csv files written with CRLF. Both are UTF-8 with the byte order mark
// (CsvFile), so Excel on Windows opens either right.
class CsvFileFilter
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::CsvFileFilter)

public:
    // "CSV files (*.csv)".
    static QString plain();
    // "CSV, Windows line ends (*.csv)".
    static QString windows();
    // Both, for a file dialog: "CSV files (*.csv);;CSV, Windows line ends (*.csv)".
    static QString both();
    // The line ends of the filter the person chose: CRLF for windows(), else LF.
    static CsvFile::LineEnd lineEnd(const QString &selectedFilter);
};

} // namespace Fatek
