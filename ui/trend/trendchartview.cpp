#include "trendchartview.h"

#include <QDateTime>
#include <QGraphicsLineItem>
#include <QGraphicsRectItem>
#include <QGraphicsTextItem>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace Fatek {

namespace {

// A value as the read-out shows it: whole numbers without a point, others with 7 digits.
QString readoutValue(double v)
{
    if (std::abs(v) < 1e15 && v == std::round(v))
        return QString::number(static_cast<qint64>(v));
    return QString::number(v, 'g', 7);
}

} // namespace

TrendChartView::TrendChartView(QChart *chart, QDateTimeAxis *timeAxis, LinesSource lines,
                               QWidget *parent)
    : QChartView(chart, parent)
    , m_timeAxis(timeAxis)
    , m_lines(std::move(lines))
{
    setRubberBand(QChartView::RectangleRubberBand);
    setRenderHint(QPainter::Antialiasing);
    // The cursor read-out follows the mouse without a button held.
    setMouseTracking(true);
    viewport()->setMouseTracking(true);

    // The cursor: a vertical line and a read-out box, above the lines.
    m_cursorLine = new QGraphicsLineItem(chart);
    m_cursorLine->setPen(QPen(QColor(0x60, 0x60, 0x60), 1, Qt::DashLine));
    m_cursorLine->setZValue(100);
    m_cursorLine->hide();
    m_readoutBox = new QGraphicsRectItem(chart);
    m_readoutBox->setPen(QPen(QColor(0xa0, 0xa0, 0xa0)));
    m_readoutBox->setBrush(QColor(255, 255, 255, 230));
    m_readoutBox->setZValue(101);
    m_readoutBox->hide();
    m_readout = new QGraphicsTextItem(m_readoutBox);
    m_readout->setDefaultTextColor(QColor(0x20, 0x20, 0x20));
}

void TrendChartView::mouseMoveEvent(QMouseEvent *event)
{
    hoverAt(event->position());
    QChartView::mouseMoveEvent(event);
}

void TrendChartView::leaveEvent(QEvent *event)
{
    hoverAt(std::nullopt);
    QChartView::leaveEvent(event);
}

void TrendChartView::wheelEvent(QWheelEvent *event)
{
    // Shift+wheel scrolls the time axis, a notch an eighth of it (some systems turn a wheel with
    // Shift held into a horizontal one).
    if (event->modifiers() & Qt::ShiftModifier) {
        const int notches
            = event->angleDelta().y() != 0 ? event->angleDelta().y() : event->angleDelta().x();
        if (notches == 0)
            return QChartView::wheelEvent(event);
        Q_EMIT userZoomed();
        chart()->scroll(-notches / 120.0 * chart()->plotArea().width() / 8, 0);
        event->accept();
        return;
    }
    const int delta = event->angleDelta().y();
    if (delta == 0)
        return QChartView::wheelEvent(event);
    const double factor = std::pow(1.0015, delta); // one notch (120) = about 20 %
    const QRectF area = chart()->plotArea();
    const double x = std::clamp(event->position().x(), area.left(), area.right());
    QRectF zoomed = area;
    zoomed.setWidth(area.width() / factor);
    zoomed.moveLeft(x - (x - area.left()) / factor);
    Q_EMIT userZoomed();
    chart()->zoomIn(zoomed); // the time axis only
    event->accept();
}

void TrendChartView::mouseReleaseEvent(QMouseEvent *event)
{
    // A finished rubber band (or the right-click zoom out) changes the axes.
    if (event->button() == Qt::LeftButton || event->button() == Qt::RightButton)
        Q_EMIT userZoomed();
    QChartView::mouseReleaseEvent(event);
}

void TrendChartView::hoverAt(std::optional<QPointF> viewportPos)
{
    m_hoverPos = viewportPos;
    updateReadout();
}

void TrendChartView::updateReadout()
{
    QChart *chart = this->chart();
    const QRectF area = chart->plotArea();
    const std::vector<CursorLine> lines = m_lines ? m_lines() : std::vector<CursorLine>();
    QPointF at;
    if (m_hoverPos)
        at = chart->mapFromScene(mapToScene(m_hoverPos->toPoint()));
    if (!m_hoverPos || lines.empty() || !area.contains(at) || area.width() <= 0) {
        m_cursorLine->hide();
        m_readoutBox->hide();
        m_readoutText.clear();
        return;
    }
    const qint64 fromMs = m_timeAxis->min().toMSecsSinceEpoch();
    const qint64 toMs = m_timeAxis->max().toMSecsSinceEpoch();
    const auto timeMs = fromMs
                        + static_cast<qint64>(std::llround((at.x() - area.left()) / area.width()
                                                           * static_cast<double>(toMs - fromMs)));
    const QString time
        = QDateTime::fromMSecsSinceEpoch(timeMs).toString(QStringLiteral("HH:mm:ss.zzz"));
    QStringList texts{time};
    QString html = QStringLiteral("<b>%1</b>").arg(time.toHtmlEscaped());
    for (const CursorLine &line : lines) {
        // The last sample at or before the cursor; a gap there means no fresh value.
        const TrendBuffer &b = *line.buffer;
        qsizetype lo = 0, hi = b.size();
        while (lo < hi) {
            const qsizetype mid = (lo + hi) / 2;
            if (b.at(mid).timeMs <= timeMs)
                lo = mid + 1;
            else
                hi = mid;
        }
        double past = 0;
        const QString value = line.recorded && line.recorded(timeMs, &past)
                                  ? (std::isnan(past) ? tr("no value") : readoutValue(past))
                              : lo == 0 || b.at(lo - 1).gap ? tr("no value")
                                                            : readoutValue(b.at(lo - 1).value);
        texts << tr("%1: %2").arg(line.name, value);
        html += QStringLiteral("<br><span style=\"color:%1\">&#9632;</span> %2")
                    .arg(line.color.name(), tr("%1: %2").arg(line.name, value).toHtmlEscaped());
    }
    m_readoutText = texts.join(QLatin1Char('\n'));
    m_readout->setHtml(html);
    m_cursorLine->setLine(at.x(), area.top(), at.x(), area.bottom());
    m_cursorLine->show();
    const QRectF text = m_readout->boundingRect();
    // Beside the line, on the side with room.
    double x = at.x() + 8;
    if (x + text.width() > area.right())
        x = std::max(area.left(), at.x() - 8 - text.width());
    m_readoutBox->setRect(0, 0, text.width(), text.height());
    m_readoutBox->setPos(x, area.top() + 4);
    m_readoutBox->show();
}

} // namespace Fatek
