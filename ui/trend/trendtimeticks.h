#pragma once

#include <QList>
#include <QObject>
#include <QString>

class QAbstractSeries;
class QCategoryAxis;
class QChart;
class QDateTimeAxis;

namespace Fatek {

// The trend's time labels on round moments of local time (every 1, 2, 5, 10, 15 or 30 s, 1, 2,
// 5, 10, 15 or 30 min, 1, 2, 3, 6 or 12 h, whole days), evenly spaced at every zoom. QtCharts'
// date-time axis spreads its ticks evenly between the ends of the range, so a zoom gave uneven
// labels (:38 :40 :43 :45 :47): that axis keeps the range the series are drawn in but is hidden,
// and a category axis under the plot carries the labels and grid lines at the round moments.
class TrendTimeTicks : public QObject
{
    Q_OBJECT

public:
    TrendTimeTicks(QChart *chart, QDateTimeAxis *timeAxis, QObject *parent = nullptr);

    // The round moments `stepMs` apart within [fromMs, toMs], ascending.
    static QList<qint64> ticksOfStep(qint64 fromMs, qint64 toMs, qint64 stepMs);
    // The smallest round step that gives [fromMs, toMs] at most `maxTicks` labels, and at least
    // one (with one label more than asked when a longer step would give none).
    static qint64 stepMs(qint64 fromMs, qint64 toMs, int maxTicks);
    // The labels' moments: ticksOfStep() with stepMs().
    static QList<qint64> ticks(qint64 fromMs, qint64 toMs, int maxTicks);

    // Attaches `series` to the chart's time labels too (beside the date-time axis): QtCharts
    // places an axis' labels by the range of its series, and draws none without one.
    static void attach(QChart *chart, QAbstractSeries *series);

    QCategoryAxis *axis() const { return m_axis; }
    // The labels' format (QDateTime::toString) and how many fit.
    void setFormat(const QString &format);
    QString format() const { return m_format; }
    void setMaxTicks(int maxTicks);
    int maxTicks() const { return m_maxTicks; }

private:
    void update();

    QDateTimeAxis *m_timeAxis;
    QCategoryAxis *m_axis;
    QString m_format = QStringLiteral("HH:mm:ss");
    int m_maxTicks = 7;
    bool m_rebuild = true; // the format or the number of labels changed: all labels anew
};

} // namespace Fatek
