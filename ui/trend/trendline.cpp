#include "trendline.h"

#include "trendtimeticks.h"

#include <QPen>
#include <QtCharts/QChart>
#include <QtCharts/QDateTimeAxis>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>

namespace Fatek {

void TrendLine::draw(QChart *chart, QDateTimeAxis *timeAxis, const QString &name, qint64 fromMs,
                     qint64 toMs, qsizetype maxPoints, TrendValueAxes::Span &span)
{
    const QList<QList<QPointF>> pieces = buffer.segments(fromMs, toMs, maxPoints);
    while (series.size() < static_cast<std::size_t>(pieces.size())) {
        auto *s = new QLineSeries;
        s->setName(name);
        QPen pen(color);
        pen.setWidthF(1.8);
        s->setPen(pen);
        chart->addSeries(s);
        s->attachAxis(timeAxis);
        TrendTimeTicks::attach(chart, s); // the labels on round moments follow its range
        s->attachAxis(axis);
        // One legend entry per item, not per line piece.
        const auto markers = chart->legend()->markers(s);
        for (QLegendMarker *m : markers)
            m->setVisible(series.empty());
        series.push_back(s);
    }
    for (std::size_t i = 0; i < series.size(); ++i) {
        if (i < static_cast<std::size_t>(pieces.size())) {
            const QList<QPointF> &points = pieces.at(static_cast<qsizetype>(i));
            series[i]->replace(points);
            for (const QPointF &p : points) {
                if (p.x() < static_cast<double>(fromMs) || p.x() > static_cast<double>(toMs))
                    continue;
                span.min = std::min(span.min, p.y());
                span.max = std::max(span.max, p.y());
            }
        } else if (series[i]->count() > 0) {
            series[i]->clear();
        }
    }
}

void TrendLine::removeFrom(QChart *chart)
{
    for (QLineSeries *s : series) {
        chart->removeSeries(s);
        delete s;
    }
    series.clear();
}

qint64 TrendLine::spanMs() const
{
    qint64 first = -1, last = -1;
    for (qsizetype i = 0; i < buffer.size(); ++i) {
        if (!buffer.at(i).gap) {
            first = buffer.at(i).timeMs;
            break;
        }
    }
    for (qsizetype i = buffer.size() - 1; i >= 0; --i) {
        if (!buffer.at(i).gap) {
            last = buffer.at(i).timeMs;
            break;
        }
    }
    return first >= 0 ? last - first : 0;
}

} // namespace Fatek
