#pragma once

#include "core/watch/watchlist.h"
#include "trendbuffer.h"
#include "trendvalueaxes.h"

#include <QColor>
#include <QPointer>

#include <vector>

class QChart;
class QDateTimeAxis;
class QLineSeries;
class QValueAxis;

namespace Fatek {

class WatchTableModel;

// One item of a trend: the watch table row it follows, its samples and the line pieces drawn for
// them (one QLineSeries per stretch without a gap, so that a gap shows as a gap).
struct TrendLine
{
    WatchItemSpec spec;
    QPointer<WatchTableModel> model;
    quint64 rowKey = 0;
    QColor color;
    TrendBuffer buffer;
    std::vector<QLineSeries *> series;
    QValueAxis *axis = nullptr;
    bool discrete = false; // 0/1: the bit axis

    // Draws the samples of [fromMs, toMs] (at most `maxPoints` per piece) as `name`, adding
    // pieces to `chart` as needed and clearing those left over; widens `span` by the values drawn
    // inside the window (the value axis fits them).
    void draw(QChart *chart, QDateTimeAxis *timeAxis, const QString &name, qint64 fromMs,
              qint64 toMs, qsizetype maxPoints, TrendValueAxes::Span &span);
    // Takes the pieces off `chart`.
    void removeFrom(QChart *chart);
    // From the first sample to the last that are no gaps (0 without two).
    qint64 spanMs() const;
};

} // namespace Fatek
