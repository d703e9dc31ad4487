#include "trendtimeticks.h"

#include <QDateTime>
#include <QtCharts/QAbstractSeries>
#include <QtCharts/QCategoryAxis>
#include <QtCharts/QChart>
#include <QtCharts/QDateTimeAxis>

#include <array>
#include <cmath>
#include <vector>

namespace Fatek {

namespace {

constexpr qint64 secondMs = 1000;
constexpr qint64 minuteMs = 60 * secondMs;
constexpr qint64 hourMs = 60 * minuteMs;
constexpr qint64 dayMs = 24 * hourMs;
constexpr std::array<qint64, 19> roundSteps
    = {secondMs,      2 * secondMs,  5 * secondMs, 10 * secondMs, 15 * secondMs,
       30 * secondMs, minuteMs,      2 * minuteMs, 5 * minuteMs,  10 * minuteMs,
       15 * minuteMs, 30 * minuteMs, hourMs,       2 * hourMs,    3 * hourMs,
       6 * hourMs,    12 * hourMs,   dayMs,        2 * dayMs};

// Where local time's round moments fall: the offset from UTC at `ms` (summer time included).
qint64 localOffsetMs(qint64 ms)
{
    return qint64(QDateTime::fromMSecsSinceEpoch(ms).offsetFromUtc()) * secondMs;
}

} // namespace

TrendTimeTicks::TrendTimeTicks(QChart *chart, QDateTimeAxis *timeAxis, QObject *parent)
    : QObject(parent)
    , m_timeAxis(timeAxis)
    , m_axis(new QCategoryAxis(chart))
{
    m_axis->setObjectName(QStringLiteral("trendTimeLabels"));
    m_axis->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    m_axis->setLabelsFont(timeAxis->labelsFont());
    m_axis->setGridLinePen(timeAxis->gridLinePen());
    m_axis->setTitleVisible(false);
    // The date-time axis keeps the series' range; its own evenly spread labels are not shown.
    timeAxis->setVisible(false);
    chart->addAxis(m_axis, Qt::AlignBottom);
    connect(timeAxis, &QDateTimeAxis::rangeChanged, this, &TrendTimeTicks::update);
    update();
}

QList<qint64> TrendTimeTicks::ticksOfStep(qint64 fromMs, qint64 toMs, qint64 stepMs)
{
    QList<qint64> out;
    if (toMs <= fromMs || stepMs <= 0)
        return out;
    const qint64 offset = localOffsetMs(fromMs);
    // The first multiple of the step, in local time, at or after the start.
    const qint64 local = fromMs + offset;
    qint64 first = (local / stepMs) * stepMs;
    if (first < local)
        first += stepMs;
    for (qint64 t = first - offset; t <= toMs; t += stepMs)
        out << t;
    return out;
}

qint64 TrendTimeTicks::stepMs(qint64 fromMs, qint64 toMs, int maxTicks)
{
    // The smallest round step with no more labels than fit; at least one label (a step just
    // over the range may hold none: the one before it then, with a label more than asked).
    std::vector<qint64> steps(roundSteps.cbegin(), roundSteps.cend());
    for (qint64 days = 7; steps.back() < toMs - fromMs; days *= 2)
        steps.push_back(days * dayMs);
    qint64 previous = 0;
    for (qint64 step : steps) {
        const qsizetype count = ticksOfStep(fromMs, toMs, step).size();
        if (count <= std::max(1, maxTicks))
            return count > 0 || previous == 0 ? step : previous;
        previous = step;
    }
    return steps.back();
}

QList<qint64> TrendTimeTicks::ticks(qint64 fromMs, qint64 toMs, int maxTicks)
{
    return ticksOfStep(fromMs, toMs, stepMs(fromMs, toMs, maxTicks));
}

void TrendTimeTicks::attach(QChart *chart, QAbstractSeries *series)
{
    for (QAbstractAxis *axis : chart->axes(Qt::Horizontal)) {
        if (axis->objectName() == QLatin1String("trendTimeLabels"))
            series->attachAxis(axis);
    }
}

void TrendTimeTicks::setFormat(const QString &format)
{
    if (format == m_format)
        return;
    m_format = format;
    m_rebuild = true;
    update();
}

void TrendTimeTicks::setMaxTicks(int maxTicks)
{
    if (maxTicks == m_maxTicks)
        return;
    m_maxTicks = maxTicks;
    m_rebuild = true;
    update();
}

void TrendTimeTicks::update()
{
    const qint64 fromMs = m_timeAxis->min().toMSecsSinceEpoch();
    const qint64 toMs = m_timeAxis->max().toMSecsSinceEpoch();
    QList<qint64> wanted = ticks(fromMs, toMs, m_maxTicks);
    wanted.removeIf([fromMs](qint64 t) { return t <= fromMs; }); // a category ends after its start
    QList<qint64> shown;
    for (const QString &label : m_axis->categoriesLabels())
        shown << qint64(m_axis->endValue(label));
    // Following the present, the labels shown stay where they are: the ones that left go, the
    // ones that came are appended (rebuilt at every redraw, they were missing from a picture
    // taken between two layouts).
    const bool continues = !m_rebuild && !shown.isEmpty() && !wanted.isEmpty()
                           && shown.contains(wanted.first())
                           && (wanted.size() < 2 || shown.size() < 2
                               || wanted.at(1) - wanted.at(0) == shown.at(1) - shown.at(0));
    m_rebuild = false;
    const QStringList labels = m_axis->categoriesLabels();
    for (qsizetype i = 0; i < labels.size(); ++i) {
        if (!continues || shown.at(i) < wanted.first())
            m_axis->remove(labels.at(i));
    }
    m_axis->setStartValue(double(fromMs));
    m_axis->setRange(double(fromMs), double(toMs));
    const qint64 last = continues ? shown.constLast() : fromMs;
    for (qint64 t : std::as_const(wanted)) {
        if (t <= last)
            continue;
        // A category's label is its key: the same text twice (a day's wrap in "HH:mm") gets an
        // invisible mark to stay a label of its own.
        QString label = QDateTime::fromMSecsSinceEpoch(t).toString(m_format);
        while (m_axis->categoriesLabels().contains(label))
            label += QChar(0x200B);
        m_axis->append(label, double(t));
    }
}

} // namespace Fatek
