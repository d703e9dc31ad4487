#include "csvfilefilter.h"

namespace Fatek {

QString CsvFileFilter::plain()
{
    return tr("CSV files (*.csv)");
}

QString CsvFileFilter::windows()
{
    return tr("CSV, Windows line ends (*.csv)");
}

QString CsvFileFilter::both()
{
    return plain() + QStringLiteral(";;") + windows();
}

CsvFile::LineEnd CsvFileFilter::lineEnd(const QString &selectedFilter)
{
    return selectedFilter == windows() ? CsvFile::LineEnd::CrLf : CsvFile::LineEnd::Lf;
}

} // namespace Fatek
