#pragma once

#include <QString>
#include <QStringList>

#include <vector>

// A PDF read back by poppler's pdftotext, as a person reading the printout would: its plain text,
// or its words page by page with where they are. Under Wine the host's Linux pdftotext runs (the
// Windows side gets its output through a file renamed into place). A missing tool makes the text
// say so, so the test fails rather than skips.
namespace PdfText {

// `pdftotext -layout`, Kangxi radicals read as the ideographs they stand for.
QString plain(const QString &pdf);

struct Word
{
    QString text;
    double top = 0;
    double bottom = 0;
};
using Page = std::vector<Word>;

// `pdftotext -bbox`: every page's words in reading order (empty when the tool failed).
std::vector<Page> pages(const QString &pdf);
// A page's words joined with single spaces.
QString pageText(const Page &page);

} // namespace PdfText
