#pragma once

#include "core/commission/checkoutreport.h"
#include "core/protocol/result.h"

#include <QByteArray>
#include <QString>

namespace Fatek::CheckoutPdf {

// The report as an A4 landscape PDF (QPdfWriter and QPainter: Qt's own), laid out for signing:
// a summary page (the header fields, the summary, the failed points and those not tested), then
// one row per point, rows never split across pages, the column header repeated on every page,
// and the signature block (engineer, witness, customer) after the last row, never alone on a
// page. Every page carries the project, the customer, when the report was made and "Page N of
// M". Needs a QGuiApplication (the offscreen platform is enough: fonts are laid out, nothing is
// shown).
QByteArray render(const CheckoutReport &report, const CheckoutReport::TextFunction &text);
// Through SafeFile: written completely or an error (ReportCannotWrite), never a partial file.
Status write(const CheckoutReport &report, const QString &path,
             const CheckoutReport::TextFunction &text);

} // namespace Fatek::CheckoutPdf
