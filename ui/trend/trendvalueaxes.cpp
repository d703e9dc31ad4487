#include "trendvalueaxes.h"

#include <QFontMetrics>
#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>

namespace Fatek {

namespace {

// The bit axis: 0 and 1 with room above and below, so the line is never hidden by the frame.
constexpr double bitAxisMin = -0.25;
constexpr double bitAxisMax = 1.25;

// Digits after the point that a tick step needs (0.25 -> 2, 2.5 -> 1, 5 -> 0): the ticks are
// multiples of the step.
int decimalsFor(double step)
{
    if (!(step > 0) || !std::isfinite(step))
        return 0;
    for (int digits = 0; digits < 12; ++digits) {
        const double scaled = step * std::pow(10.0, digits);
        if (std::abs(scaled - std::round(scaled)) <= 1e-9 * scaled)
            return digits;
    }
    return 12;
}

// Ticks on round numbers for the visible range of an analog axis; labels with the digits the
// step needs.
void applyNiceTicks(QValueAxis *axis, double min, double max, int targetTicks)
{
    const double step = TrendValueAxes::niceStep(min, max, targetTicks);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(step);
    axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimalsFor(step)));
    axis->setTickType(QValueAxis::TicksDynamic);
}

} // namespace

TrendValueAxes::TrendValueAxes(QChart *chart)
    : m_chart(chart)
{}

void TrendValueAxes::setPlotHeight(double height)
{
    // QtCharts gives each label the height between two ticks (less its padding) and cuts a
    // label that is taller to "...": a short plot gets fewer, wider-spaced ticks.
    m_plotHeight = height;
    fitTitles();
    const int lineHeight = QFontMetrics(m_chart->font()).height();
    const int fit = static_cast<int>(height / (2.5 * lineHeight));
    const int target = std::clamp(fit, 1, 5);
    if (target == m_targetTicks)
        return;
    m_targetTicks = target;
    for (QValueAxis *axis : m_axes) {
        if (axis != m_bitAxis)
            applyNiceTicks(axis, axis->min(), axis->max(), m_targetTicks);
    }
}

namespace {

// QtCharts' share of the chart's width for all vertical axes together (CartesianChartLayout's
// maxAxisPortion), and its space beside a label (ChartAxisElement's labelPadding and titlePadding,
// ChartValueAxisY's tolerance).
constexpr double axesShare = 0.4;
constexpr double labelRoom = 4.0 + 2.0;
constexpr double titleRoom = 2.0 * 2.0;

} // namespace

void TrendValueAxes::fitTitles()
{
    if (m_plotHeight <= 0)
        return;
    for (QValueAxis *axis : m_axes) {
        const QString full = axis->property("fatekTitle").toString();
        const QString brief = axis->property("fatekBriefTitle").toString();
        const bool fits
            = QFontMetricsF(axis->titleFont()).horizontalAdvance(full) + titleRoom <= m_plotHeight;
        const QString title = fits || brief.isEmpty() ? full : brief;
        if (title != axis->titleText())
            axis->setTitleText(title);
    }
}

double TrendValueAxes::axisWidth(const QValueAxis *axis, bool title)
{
    const QFontMetricsF labels(axis->labelsFont());
    double widest = 0;
    // The labels QtCharts will draw: each tick in the axis' printf format.
    const QByteArray format = axis->labelFormat().toLatin1();
    for (double tick : tickValues(axis))
        widest = std::max(widest,
                          labels.boundingRect(QString::asprintf(format.constData(), tick)).width());
    double width = widest + labelRoom;
    if (title && !axis->titleText().isEmpty())
        width += QFontMetricsF(axis->titleFont()).height() + titleRoom;
    return width;
}

double TrendValueAxes::neededChartWidth(bool titles) const
{
    // Each side gets the share in proportion to its number of axes: the side whose axes want the
    // most per axis decides.
    double left = 0, right = 0;
    int leftCount = 0, rightCount = 0;
    for (const QValueAxis *axis : m_axes) {
        const bool onLeft = axis->alignment() & Qt::AlignLeft;
        (onLeft ? left : right) += axisWidth(axis, titles);
        ++(onLeft ? leftCount : rightCount);
    }
    const double perAxis
        = std::max(leftCount ? left / leftCount : 0.0, rightCount ? right / rightCount : 0.0);
    const QMarginsF margins = m_chart->margins();
    return perAxis * static_cast<double>(leftCount + rightCount) / axesShare + margins.left()
           + margins.right() + 2 * labelRoom;
}

int TrendValueAxes::minimumChartWidth() const
{
    return static_cast<int>(std::ceil(neededChartWidth(false)));
}

void TrendValueAxes::setChartWidth(double width)
{
    // QtCharts squeezes value axes that together want more than a share of the chart's width:
    // titles only where labels and titles fit together.
    m_chartWidth = width;
    const bool titles = width >= 640 && neededChartWidth(true) <= width;
    if (titles == m_titles)
        return;
    m_titles = titles;
    for (QValueAxis *axis : m_axes)
        axis->setTitleVisible(titles);
}

double TrendValueAxes::niceStep(double min, double max, int targetTicks)
{
    const double range = max - min;
    if (!(range > 0) || !std::isfinite(range))
        return 1.0;
    // Of the round steps (1, 2, 2.5 and 5 times a power of ten) the one whose ticks inside
    // min..max come closest to the target, and never fewer than three where three are wanted:
    // rounding the step alone could leave two labels on a laptop's plot, depending on the data.
    const int target = std::max(1, targetTicks);
    const int wanted = std::min(target, 3);
    const double power = std::pow(10.0, std::floor(std::log10(range)));
    double best = 0;
    int bestCount = 0;
    for (int exponent = 1; exponent >= -3; --exponent) {
        for (double mantissa : {5.0, 2.5, 2.0, 1.0}) {
            const double step = mantissa * power * std::pow(10.0, exponent);
            const auto count = static_cast<int>(std::floor(max / step + 1e-9)
                                                - std::ceil(min / step - 1e-9) + 1);
            if (count < wanted)
                continue;
            if (best == 0 || std::abs(count - target) < std::abs(bestCount - target)) {
                best = step;
                bestCount = count;
            }
        }
    }
    return best > 0 ? best : range;
}

QList<double> TrendValueAxes::tickValues(const QValueAxis *axis)
{
    QList<double> ticks;
    if (!axis)
        return ticks;
    const double min = axis->min(), max = axis->max();
    if (axis->tickType() == QValueAxis::TicksDynamic) {
        const double step = axis->tickInterval();
        if (!(step > 0) || (max - min) / step > 1000)
            return ticks;
        const double anchor = axis->tickAnchor();
        for (double k = std::ceil((min - anchor) / step - 1e-9);
             anchor + k * step <= max + 1e-9 * step; k += 1)
            ticks << anchor + k * step;
        return ticks;
    }
    const int count = axis->tickCount();
    for (int i = 0; i < count && count > 1; ++i)
        ticks << min + (max - min) * i / (count - 1);
    return ticks;
}

std::vector<QValueAxis *> TrendValueAxes::rebuild(const std::vector<Line> &lines, bool separate)
{
    for (QValueAxis *axis : m_axes) {
        m_chart->removeAxis(axis); // detaches the series
        delete axis;
    }
    m_axes.clear();
    m_bitAxis = nullptr;
    QValueAxis *shared = nullptr;
    int analogAxes = 0;
    auto make = [this, &analogAxes](const QString &title, const QColor &color, bool bits,
                                    const QString &brief = {}) {
        auto *axis = new QValueAxis;
        axis->setTitleText(title);
        axis->setProperty("fatekTitle", title);
        axis->setProperty("fatekBriefTitle", brief);
        axis->setMinorTickCount(0);
        // A number cut to "1..." is worse than none; the view keeps the chart wide enough for
        // whole labels (minimumChartWidth()).
        axis->setTruncateLabels(false);
        if (color.isValid()) {
            // The axis in its line's colour: which scale belongs to which line is plain.
            QPen pen = axis->linePen();
            pen.setColor(color);
            axis->setLinePen(pen);
            axis->setLabelsColor(color);
            axis->setTitleBrush(color);
        }
        // Analog axes left, right, left, ...: the plot keeps its width in the middle; the bit
        // axis on the right.
        const bool left = !bits && analogAxes++ % 2 == 0;
        m_chart->addAxis(axis, left ? Qt::AlignLeft : Qt::AlignRight);
        axis->setProperty("fatekFresh", true); // ranged by the next fit, also when zoomed
        axis->setTitleVisible(m_titles);
        m_axes.push_back(axis);
        return axis;
    };
    std::vector<QValueAxis *> lineAxes;
    for (const Line &line : lines) {
        if (line.discrete) {
            if (!m_bitAxis) {
                m_bitAxis = make(tr("Bits"), QColor(), true);
                m_bitAxis->setRange(bitAxisMin, bitAxisMax);
                m_bitAxis->setTickAnchor(0);
                m_bitAxis->setTickInterval(1);
                m_bitAxis->setTickType(QValueAxis::TicksDynamic);
                m_bitAxis->setLabelFormat(QStringLiteral("%.0f"));
            }
            lineAxes.push_back(m_bitAxis);
        } else if (separate) {
            lineAxes.push_back(make(line.title, line.color, false, line.briefTitle));
        } else {
            if (!shared)
                shared = make(tr("Value"), QColor(), false);
            lineAxes.push_back(shared);
        }
    }
    if (m_axes.empty()) // an empty chart still has its value axis
        make(tr("Value"), QColor(), false)->setRange(0, 1);
    fitTitles();
    for (QValueAxis *axis : m_axes) {
        if (axis == m_bitAxis)
            continue;
        applyNiceTicks(axis, axis->min(), axis->max(), m_targetTicks);
        // A zoom (rubber band) changes the range: the ticks follow it.
        QObject::connect(axis, &QValueAxis::rangeChanged, axis, [this, axis](qreal min, qreal max) {
            applyNiceTicks(axis, min, max, m_targetTicks);
        });
    }
    return lineAxes;
}

void TrendValueAxes::fit(std::map<QValueAxis *, Span> spans, bool zoomed)
{
    for (QValueAxis *axis : m_axes) {
        // Zoomed, the user's ranges stay; an axis that came since gets one.
        if (zoomed && !axis->property("fatekFresh").toBool())
            continue;
        axis->setProperty("fatekFresh", false);
        if (axis == m_bitAxis) {
            axis->setRange(bitAxisMin, bitAxisMax);
            continue;
        }
        Span span = spans[axis];
        if (span.min > span.max) {
            span.min = 0;
            span.max = 1;
        }
        const double margin = span.max > span.min ? (span.max - span.min) * 0.05
                                                  : std::max(1.0, std::abs(span.max) * 0.05);
        // The new range's step first: the axis lays its ticks out at once when the range
        // changes, and the old step over a range 1000 times wider would be a million ticks.
        applyNiceTicks(axis, span.min - margin, span.max + margin, m_targetTicks);
        axis->setRange(span.min - margin, span.max + margin);
    }
    // New ranges, new labels: the titles fit beside them or not.
    if (m_chartWidth > 0)
        setChartWidth(m_chartWidth);
}

} // namespace Fatek
