#pragma once

#include "core/commission/checkoutreport.h"
#include "core/protocol/result.h"

#include <QByteArray>
#include <QString>

namespace Fatek::CheckoutPdf {

// The report as an A4 landscape PDF (QPdfWriter and QTextDocument: Qt's own): title, the header
// fields, the summary, one table row per point and the signature lines. Needs a QGuiApplication
// (the offscreen platform is enough: fonts are laid out, nothing is shown).
QByteArray render(const CheckoutReport &report, const CheckoutReport::TextFunction &text);
// The HTML the PDF is laid out from (tests, a GUI preview).
QString html(const CheckoutReport &report, const CheckoutReport::TextFunction &text);
// Through SafeFile: written completely or an error (ReportCannotWrite), never a partial file.
Status write(const CheckoutReport &report, const QString &path,
             const CheckoutReport::TextFunction &text);

} // namespace Fatek::CheckoutPdf
