#include "checkoutpdf.h"

#include "pagedlayout.h"

#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/safefile.h"

#include <QBuffer>
#include <QGuiApplication>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextOption>

#include <algorithm>
#include <utility>

namespace Fatek::CheckoutPdf {

namespace {

// Laid out in device pixels at this resolution (fonts in points scale with it).
constexpr int Dpi = 300;

qreal mm(qreal millimetres)
{
    return millimetres * Dpi / 25.4;
}

QColor resultColour(CheckoutResult r)
{
    switch (r) {
    case CheckoutResult::Passed: return QColor(0x1b, 0x7f, 0x1b);
    case CheckoutResult::PassedWithRemark: return QColor(0x1b, 0x6f, 0x5f);
    case CheckoutResult::Failed: return QColor(0xb0, 0x00, 0x20);
    case CheckoutResult::Deferred: return QColor(0x8a, 0x6d, 0x00);
    case CheckoutResult::NotApplicable: return QColor(0x44, 0x44, 0x88);
    case CheckoutResult::Untested: return QColor(0x55, 0x55, 0x55);
    }
    return Qt::black;
}

struct Cell
{
    QString text;
    QColor colour = Qt::black;
    bool bold = false;
};

// Builds the report's blocks (measured with the PDF's own painter, so what is measured is what
// is drawn) and paints them page by page with the running header and footer.
class ReportLayout
{
public:
    ReportLayout(QPainter &painter, const QRectF &page, const CheckoutReport &report,
                 CheckoutReport::TextFunction text)
        : m_painter(painter)
        , m_page(page)
        , m_report(report)
        , m_text(std::move(text))
        , m_layout(QRectF(page.left(), page.top() + BandHeight, page.width(),
                          page.height() - 2 * BandHeight))
    {
        m_body = QGuiApplication::font();
        m_body.setPointSizeF(8);
        m_bold = m_body;
        m_bold.setBold(true);
        m_heading = m_bold;
        m_heading.setPointSizeF(11);
        m_title = m_bold;
        m_title.setPointSizeF(15);
        m_wrap.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    }

    void build()
    {
        addParagraph(m_text(msg<MsgId::ReportTitle>()), m_title, mm(2));
        addFields();
        addHeading(msg<MsgId::ReportSummaryTitle>(), false);
        addParagraph(m_text(m_report.summary), m_body, mm(1));
        addPunchList();
        addResults();
        m_layout.paginate();
    }

    void paint(QPdfWriter &writer)
    {
        for (int page = 0; page < m_layout.pageCount(); ++page) {
            if (page > 0)
                writer.newPage();
            paintBands(page);
            m_layout.paintPage(m_painter, page);
        }
    }

private:
    static constexpr qreal BandHeight = 10 * Dpi / 25.4; // running header, footer: 10 mm
    static constexpr qreal Pad = 1.2 * Dpi / 25.4;

    QString text(const Message &m) const { return m_text(m); }

    qreal textHeight(const QString &s, const QFont &font, qreal width) const
    {
        m_painter.setFont(font);
        return m_painter
            .boundingRect(QRectF(0, 0, width, 1e6), s.isEmpty() ? QStringLiteral(" ") : s, m_wrap)
            .height();
    }

    void addParagraph(const QString &s, const QFont &font, qreal spaceAfter,
                      bool keepWithNext = false, bool pageBreakBefore = false)
    {
        const qreal height = textHeight(s, font, m_page.width()) + spaceAfter;
        m_layout.add({height,
                      [this, s, font](QPainter &p, const QRectF &r) {
                          p.setFont(font);
                          p.drawText(r, s, m_wrap);
                      },
                      -1, keepWithNext, pageBreakBefore});
    }

    void addSpace(qreal height)
    {
        m_layout.add({height, [](QPainter &, const QRectF &) {
                      }});
    }

    void addHeading(const Message &heading, bool pageBreakBefore)
    {
        m_layout.add({textHeight(text(heading), m_heading, m_page.width()) + mm(4),
                      [this, s = text(heading)](QPainter &p, const QRectF &r) {
                          p.setFont(m_heading);
                          p.drawText(r.adjusted(0, mm(3), 0, 0), s, m_wrap);
                      },
                      -1, true, pageBreakBefore});
    }

    // Column edges of a table spanning the page, from relative widths.
    std::vector<qreal> edges(const std::vector<qreal> &widths) const
    {
        qreal total = 0;
        for (qreal w : widths)
            total += w;
        std::vector<qreal> x{0};
        for (qreal w : widths)
            x.push_back(x.back() + m_page.width() * w / total);
        return x;
    }

    qreal rowHeight(const std::vector<Cell> &cells, const std::vector<qreal> &x) const
    {
        qreal height = 0;
        for (std::size_t c = 0; c < cells.size(); ++c)
            height = std::max(height, textHeight(cells[c].text, cells[c].bold ? m_bold : m_body,
                                                 x[c + 1] - x[c] - 2 * Pad));
        return height + 2 * Pad;
    }

    PagedLayout::Paint rowPainter(std::vector<Cell> cells, std::vector<qreal> x, bool shaded) const
    {
        return [this, cells = std::move(cells), x = std::move(x), shaded](QPainter &p,
                                                                          const QRectF &r) {
            if (shaded)
                p.fillRect(r, QColor(0xe8, 0xe8, 0xe8));
            p.setPen(QPen(QColor(0x80, 0x80, 0x80), 1.5));
            p.drawLine(r.bottomLeft(), r.bottomRight());
            if (shaded)
                p.drawLine(r.topLeft(), r.topRight());
            for (std::size_t c = 0; c < cells.size(); ++c) {
                const QRectF cell(r.left() + x[c], r.top(), x[c + 1] - x[c], r.height());
                p.setPen(QPen(QColor(0x80, 0x80, 0x80), 1.5));
                p.drawLine(cell.topLeft(), cell.bottomLeft());
                if (c + 1 == cells.size())
                    p.drawLine(cell.topRight(), cell.bottomRight());
                p.setFont(cells[c].bold ? m_bold : m_body);
                p.setPen(cells[c].colour);
                p.drawText(cell.adjusted(Pad, Pad, -Pad, -Pad), cells[c].text, m_wrap);
            }
        };
    }

    int addTableHeader(const std::vector<Message> &titles, const std::vector<qreal> &x)
    {
        std::vector<Cell> cells;
        cells.reserve(titles.size());
        for (const Message &t : titles)
            cells.push_back({text(t), Qt::black, true});
        return m_layout.addHeader(rowHeight(cells, x), rowPainter(cells, x, true));
    }

    void addRow(std::vector<Cell> cells, const std::vector<qreal> &x, int header,
                bool keepWithNext = false)
    {
        const qreal height = rowHeight(cells, x);
        m_layout.add({height, rowPainter(std::move(cells), x, false), header, keepWithNext});
    }

    void addFields()
    {
        const std::vector<qreal> x = edges({1, 4});
        for (const CheckoutReport::Field &f : m_report.fields)
            addRow({{text(f.label), Qt::black, true}, {text(f.value)}}, x, -1);
    }

    void addPunchList()
    {
        addHeading(msg<MsgId::ReportPunchList>(), false);
        QStringList untested;
        for (const CheckoutReport::Row &r : m_report.rows) {
            if (r.result == CheckoutResult::Untested)
                untested << r.address;
        }
        if (m_report.punch.empty()) {
            addParagraph(text(msg<MsgId::ReportNoFailed>()), m_body, mm(1));
        } else {
            const std::vector<qreal> x = edges({7, 18, 11, 34, 14, 16});
            std::vector<Message> titles = CheckoutReport::punchColumns();
            const int header = addTableHeader(titles, x);
            for (const CheckoutReport::PunchRow &r : m_report.punch)
                addRow({{r.address, Qt::black, true},
                        {r.name},
                        {text(checkoutResultMessage(r.result)), resultColour(r.result), true},
                        {r.remark},
                        {r.owner},
                        {text(r.state),
                         r.closed ? resultColour(CheckoutResult::Passed)
                                  : resultColour(CheckoutResult::Failed),
                         !r.closed}},
                       x, header);
        }
        if (!untested.isEmpty()) {
            addSpace(mm(2));
            addParagraph(text(msg<MsgId::ReportUntestedList>(
                             untested.size(), untested.join(QStringLiteral(", ")).toStdString())),
                         m_body, mm(1));
        }
    }

    void addResults()
    {
        addHeading(msg<MsgId::ReportResults>(), true);
        const std::vector<qreal> x = edges({6, 12, 7, 6, 8, 16, 17, 17, 9, 7});
        const int header = addTableHeader(CheckoutReport::columns(), x);
        for (std::size_t i = 0; i < m_report.rows.size(); ++i) {
            const CheckoutReport::Row &r = m_report.rows[i];
            // The last row goes with the signatures: they never stand alone on a page.
            addRow({{r.address, Qt::black, true},
                    {r.name},
                    {r.group},
                    {text(checkoutKindMessage(r.kind))},
                    {text(checkoutResultMessage(r.result)), resultColour(r.result), true},
                    {text(r.measured)},
                    {r.comment},
                    {r.time},
                    {r.engineer},
                    {r.attempts > 1 ? QString::number(r.attempts) : QString()}},
                   x, header, i + 1 == m_report.rows.size());
        }
        addSignatures();
    }

    void addSignatures()
    {
        const std::vector<qreal> x = edges({14, 18, 18, 30, 14});
        const std::vector<Cell> titles{{text(msg<MsgId::ReportSignRole>()), Qt::black, true},
                                       {text(msg<MsgId::ReportSignName>()), Qt::black, true},
                                       {text(msg<MsgId::ReportSignCompany>()), Qt::black, true},
                                       {text(msg<MsgId::ReportSignature>()), Qt::black, true},
                                       {text(msg<MsgId::ReportDate>()), Qt::black, true}};
        const std::vector<std::vector<Cell>> rows{{{text(msg<MsgId::ReportSignEngineer>())},
                                                   {m_report.engineer},
                                                   {m_report.info.engineerCompany},
                                                   {},
                                                   {}},
                                                  {{text(msg<MsgId::ReportSignWitness>())},
                                                   {m_report.info.witness},
                                                   {m_report.info.witnessCompany},
                                                   {},
                                                   {}},
                                                  {{text(msg<MsgId::ReportSignCustomer>())},
                                                   {m_report.info.customerSignatory},
                                                   {m_report.customer},
                                                   {},
                                                   {}}};
        const QString heading = text(msg<MsgId::ReportSignatures>());
        const qreal headingHeight = textHeight(heading, m_heading, m_page.width()) + mm(4);
        const qreal titleHeight = rowHeight(titles, x);
        // Room to sign by hand.
        const qreal signHeight = std::max(mm(13), rowHeight(rows[0], x));
        const PagedLayout::Paint titlePaint = rowPainter(titles, x, true);
        std::vector<PagedLayout::Paint> rowPaints;
        rowPaints.reserve(rows.size());
        for (const std::vector<Cell> &row : rows)
            rowPaints.push_back(rowPainter(row, x, false));
        m_layout.add(
            {headingHeight + titleHeight + 3 * signHeight, [=, this](QPainter &p, const QRectF &r) {
                 p.setFont(m_heading);
                 p.drawText(r.adjusted(0, mm(3), 0, 0), heading, m_wrap);
                 qreal y = r.top() + headingHeight;
                 titlePaint(p, QRectF(r.left(), y, r.width(), titleHeight));
                 y += titleHeight;
                 for (const PagedLayout::Paint &row : rowPaints) {
                     row(p, QRectF(r.left(), y, r.width(), signHeight));
                     y += signHeight;
                 }
             }});
    }

    // The running header (title, project, customer) and footer (when made, page N of M).
    void paintBands(int page)
    {
        const QRectF top(m_page.left(), m_page.top(), m_page.width(), BandHeight - mm(3));
        const QRectF bottom(m_page.left(), m_page.bottom() - BandHeight + mm(3), m_page.width(),
                            BandHeight - mm(3));
        m_painter.setPen(Qt::black);
        m_painter.setFont(m_bold);
        const QString left
            = text(msg<MsgId::ReportTitle>()) + QStringLiteral(" \u2014 ") + m_report.project;
        m_painter.drawText(top, Qt::AlignLeft | Qt::AlignBottom, left);
        m_painter.setFont(m_body);
        // The document's identity on every page: a loose page still says what it belongs to.
        QString right
            = text(msg<MsgId::ReportCustomer>()) + QStringLiteral(": ") + m_report.customer;
        if (!m_report.documentId.isEmpty())
            right += QStringLiteral("   ") + text(msg<MsgId::ReportDocument>())
                     + QStringLiteral(": ") + m_report.documentId;
        if (!m_report.revision.isEmpty())
            right += QStringLiteral("   ") + text(msg<MsgId::ReportRevision>())
                     + QStringLiteral(": ") + m_report.revision;
        m_painter.drawText(top, Qt::AlignRight | Qt::AlignBottom, right);
        m_painter.setPen(QPen(Qt::black, 2));
        m_painter.drawLine(top.bottomLeft() + QPointF(0, mm(1)),
                           top.bottomRight() + QPointF(0, mm(1)));
        m_painter.drawLine(bottom.topLeft() - QPointF(0, mm(1)),
                           bottom.topRight() - QPointF(0, mm(1)));
        m_painter.drawText(bottom, Qt::AlignLeft | Qt::AlignTop,
                           text(msg<MsgId::ReportMade>()) + QStringLiteral(": ") + m_report.made);
        m_painter.setFont(m_bold);
        m_painter.drawText(bottom, Qt::AlignRight | Qt::AlignTop,
                           text(msg<MsgId::ReportPageOf>(page + 1, m_layout.pageCount())));
    }

    QPainter &m_painter;
    QRectF m_page;
    const CheckoutReport &m_report;
    CheckoutReport::TextFunction m_text;
    PagedLayout m_layout;
    QFont m_body;
    QFont m_bold;
    QFont m_heading;
    QFont m_title;
    QTextOption m_wrap;
};

} // namespace

QByteArray render(const CheckoutReport &report, const CheckoutReport::TextFunction &textFunction)
{
    const CheckoutReport::TextFunction text
        = textFunction ? textFunction : CheckoutReport::TextFunction(englishText);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setResolution(Dpi);
        // Landscape: nine columns fit without breaking a comment or a time in two.
        writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape,
                                         QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter));
        writer.setTitle(text(msg<MsgId::ReportTitle>()));
        writer.setCreator(QStringLiteral("FATEK Studio"));
        QPainter painter;
        if (!painter.begin(&writer))
            return {};
        const QRectF page(QPointF(0, 0), writer.pageLayout().paintRectPixels(Dpi).size());
        ReportLayout layout(painter, page, report, text);
        layout.build();
        layout.paint(writer);
        painter.end();
    } // the writer finishes the file when it goes
    return bytes;
}

Status write(const CheckoutReport &report, const QString &path,
             const CheckoutReport::TextFunction &text)
{
    const QByteArray pdf = render(report, text);
    const QString reason = pdf.isEmpty() ? QStringLiteral("the PDF could not be laid out")
                                         : SafeFile::write(path, pdf);
    if (!reason.isEmpty())
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::ReportCannotWrite>(path.toStdString(), Message::text(reason.toStdString())));
    return Ok{};
}

} // namespace Fatek::CheckoutPdf
