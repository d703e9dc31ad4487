#include "checkoutpdf.h"

#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/safefile.h"

#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextTable>

#include <cmath>

namespace Fatek::CheckoutPdf {

namespace {

QString esc(const QString &s)
{
    return s.toHtmlEscaped();
}

const char *resultColour(CheckoutResult r)
{
    switch (r) {
    case CheckoutResult::Passed: return "#1b7f1b";
    case CheckoutResult::Failed: return "#b00020";
    case CheckoutResult::Skipped: return "#8a6d00";
    case CheckoutResult::Untested: return "#555555";
    }
    return "#000000";
}

} // namespace

QString html(const CheckoutReport &report, const CheckoutReport::TextFunction &textFunction)
{
    const CheckoutReport::TextFunction text
        = textFunction ? textFunction : CheckoutReport::TextFunction(englishText);
    QString h;
    h += QStringLiteral("<html><body style=\"font-size:8pt\">");
    h += QStringLiteral("<h2>%1</h2>").arg(esc(text(msg<MsgId::ReportTitle>())));
    h += QStringLiteral("<table cellpadding=\"2\">");
    for (const CheckoutReport::Field &f : report.fields)
        h += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                 .arg(esc(text(f.label)), esc(text(f.value)));
    h += QStringLiteral("</table>");
    h += QStringLiteral("<h3>%1</h3><p>%2</p>")
             .arg(esc(text(msg<MsgId::ReportSummaryTitle>())), esc(text(report.summary)));
    h += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">"
                        "<tr>");
    for (const Message &c : CheckoutReport::columns())
        h += QStringLiteral("<th align=\"left\">%1</th>").arg(esc(text(c)));
    h += QStringLiteral("</tr>");
    for (const CheckoutReport::Row &r : report.rows) {
        h += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td>"
                            "<td><font color=\"%5\"><b>%6</b></font></td><td>%7</td><td>%8</td>"
                            "<td>%9</td>")
                 .arg(esc(r.address), esc(r.name), esc(r.group),
                      esc(text(checkoutKindMessage(r.kind))), QLatin1String(resultColour(r.result)),
                      esc(text(checkoutResultMessage(r.result))), esc(text(r.measured)),
                      esc(r.comment), esc(r.time));
        h += QStringLiteral("<td>%1</td></tr>").arg(esc(r.engineer));
    }
    h += QStringLiteral("</table>");
    h += QStringLiteral("<h3>%1</h3><table width=\"100%\" cellpadding=\"6\"><tr>")
             .arg(esc(text(msg<MsgId::ReportSignatures>())));
    for (const Message &who : {msg<MsgId::ReportSignEngineer>(), msg<MsgId::ReportSignCustomer>()})
        h += QStringLiteral("<td width=\"50%\"><br><br>______________________________<br>%1"
                            "<br><br>%2: ____________</td>")
                 .arg(esc(text(who)), esc(text(msg<MsgId::ReportDate>())));
    h += QStringLiteral("</tr></table></body></html>");
    return h;
}

// The last heading and the table after it (the signatures) on one page: when the page ends
// between them, the heading starts the next page.
void keepSignaturesTogether(QTextDocument &doc, qreal pageHeight)
{
    QTextTable *last = nullptr;
    for (QTextFrame *frame : doc.rootFrame()->childFrames()) {
        if (auto *table = qobject_cast<QTextTable *>(frame))
            last = table;
    }
    if (!last)
        return;
    QTextBlock heading = doc.findBlock(last->firstPosition()).previous();
    while (heading.isValid() && heading.text().trimmed().isEmpty())
        heading = heading.previous();
    if (!heading.isValid())
        return;
    QAbstractTextDocumentLayout *layout = doc.documentLayout();
    const auto pageOf = [pageHeight](qreal y) {
        return std::floor(y / pageHeight);
    };
    if (pageOf(layout->blockBoundingRect(heading).top())
        != pageOf(layout->frameBoundingRect(last).bottom() - 1)) {
        QTextBlockFormat format;
        format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
        QTextCursor(heading).mergeBlockFormat(format);
    }
}

QByteArray render(const CheckoutReport &report, const CheckoutReport::TextFunction &text)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        // Landscape: nine columns fit without breaking a comment or a time in two.
        writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape,
                                         QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter));
        writer.setTitle(text ? text(msg<MsgId::ReportTitle>())
                             : englishText(msg<MsgId::ReportTitle>()));
        writer.setCreator(QStringLiteral("FATEK Studio"));
        QTextDocument doc;
        doc.setHtml(html(report, text));
        // Laid out in pages here (at the screen's 96 dpi, which print() scales to the writer's),
        // so that the signatures' heading can go with its lines.
        const QSizeF page = writer.pageLayout().paintRect(QPageLayout::Inch).size() * qreal(96);
        doc.setPageSize(page);
        keepSignaturesTogether(doc, page.height());
        doc.print(&writer);
    } // the writer finishes the file when it goes
    return bytes;
}

Status write(const CheckoutReport &report, const QString &path,
             const CheckoutReport::TextFunction &text)
{
    const QString reason = SafeFile::write(path, render(report, text));
    if (!reason.isEmpty())
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::ReportCannotWrite>(path.toStdString(), Message::text(reason.toStdString())));
    return Ok{};
}

} // namespace Fatek::CheckoutPdf
