#pragma once

#include <QColor>
#include <QCoreApplication>
#include <QList>
#include <QString>

#include <limits>
#include <map>
#include <vector>

class QChart;
class QValueAxis;

namespace Fatek {

// The value axes of the trend chart, by scale group: bits (0/1) share one axis of their own; each
// other line gets its own axis in its colour, alternately left and right (separate axes), or they
// all share one "Value" axis. Ticks fall on round numbers (1, 2 or 5 times a power of ten) of the
// visible range, also after a zoom.
class TrendValueAxes
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::TrendValueAxes)

public:
    // What decides the axis of one line.
    struct Line
    {
        QString title;
        QColor color;
        bool discrete = false; // 0/1: the bit axis
        // The title when `title` is longer than the plot is high ("R0" for "Scan counter (R0)").
        QString briefTitle;
    };
    // The values a line shows in the visible time range (min > max: none).
    struct Span
    {
        double min = std::numeric_limits<double>::max();
        double max = std::numeric_limits<double>::lowest();
    };

    explicit TrendValueAxes(QChart *chart);

    // Replaces the axes of the chart; returns the axis of each line. An empty chart still has
    // one value axis.
    std::vector<QValueAxis *> rebuild(const std::vector<Line> &lines, bool separate);
    // Ranges every axis to the values of its lines (with a margin); `zoomed`: only axes that came
    // since the last fit, the others keep the user's range.
    void fit(std::map<QValueAxis *, Span> spans, bool zoomed);
    const std::vector<QValueAxis *> &axes() const { return m_axes; }
    // The plot's height in pixels: as many ticks as leave every label room for its height, and
    // titles that fit it whole (QtCharts cut a longer one to "Scan count…": the brief one then).
    void setPlotHeight(double height);
    // The chart's width in pixels: in a narrow chart the axes show no titles (the legend and the
    // axes' colours name the lines), so that their labels keep the width they need.
    void setChartWidth(double width);
    // The narrowest chart in which every value axis shows its tick labels whole (without titles):
    // QtCharts gives the value axes together at most 40 % of the chart's width and cuts the
    // labels of axes squeezed below their width to "...".
    int minimumChartWidth() const;

    // The distance of the ticks on a value axis showing min..max: 1, 2, 2.5 or 5 times a power
    // of ten, about `targetTicks` ticks and at least min(targetTicks, 3).
    static double niceStep(double min, double max, int targetTicks = 5);
    // The ticks a value axis shows (round numbers in its range).
    static QList<double> tickValues(const QValueAxis *axis);

private:
    void fitTitles();
    // The width one value axis wants: its widest tick label, the label's padding and, with
    // `title`, the title's height (the title is turned on its side).
    static double axisWidth(const QValueAxis *axis, bool title);
    // The chart's width at which no value axis is squeezed (QtCharts shares 40 % of the width
    // among the axes, each side in proportion to its number of axes).
    double neededChartWidth(bool titles) const;

    QChart *m_chart;
    std::vector<QValueAxis *> m_axes;
    QValueAxis *m_bitAxis = nullptr;
    int m_targetTicks = 5;
    bool m_titles = true;
    double m_chartWidth = 0;
    double m_plotHeight = 0;
};

} // namespace Fatek
