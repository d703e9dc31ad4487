#pragma once

#include "core/watch/watchlist.h"
#include "trendhistory.h"
#include "trendline.h"
#include "trendnavigation.h"
#include "trendvalueaxes.h"

#include <QTimer>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QChart;
class QComboBox;
class QDateTimeAxis;
class QLabel;
class QLineSeries;
class QListWidget;
class QScrollBar;
class QToolButton;
class QValueAxis;

namespace Fatek {

class HistoryCenter;
class TrendChartView;
class WatchTableModel;

// A trend of watch table items over time (Qt Charts): one line per item in a shared time axis.
// Value axes by scale group: bits (0/1) share one axis of their own; each other item gets its own
// axis in its colour, alternately left and right (Separate Axes, the default), or they all share
// one "Value" axis. Ticks fall on round numbers (1, 2 or 5 times a power of ten) of the visible
// range. Moving the mouse over the chart shows a cursor line and a read-out: the time and each
// item's value there.
// Samples come from the watch table models as their values arrive; a value that is not fresh
// (stale, refused, polling paused, trend paused) ends the line, so a gap shows where nothing
// fresh was read. Pause freezes the picture; the time window (10 s .. 7 days, or a custom range)
// follows the present until the user zooms (rubber band, mouse wheel) or scrolls back (the scroll
// bar, Shift+wheel), Reset Zoom goes back to following. Before what a line's live buffer holds,
// its recorded past is drawn from the history (TrendHistory), and a range can be exported to CSV.
class TrendView : public QWidget
{
    Q_OBJECT
    // For the screenshot of --tool trend: how much history the trend holds.
    Q_PROPERTY(qint64 spanMs READ spanMs)

public:
    // The time windows the window box offers.
    static QList<qint64> windowChoicesMs();
    // Looks at [fromMs, toMs] (no longer following the present until resetZoom()).
    void showRange(qint64 fromMs, qint64 toMs);

    explicit TrendView(QWidget *parent = nullptr);
    ~TrendView() override;

    // Trends the row of `model` (followed by its row key while rows move). False, with `error`,
    // for a value that has no height (ASCII) or an item already in the trend.
    bool addItem(WatchTableModel *model, int row, QString *error = nullptr);
    // Adds several rows; one status message names what was added ("Sine (R1), Blink (Y0) added
    // to the trend.", or a count for more than three) and what was refused. Returns how many.
    int addItems(WatchTableModel *model, const QList<int> &rows);
    void removeItem(int index);
    int itemCount() const { return static_cast<int>(m_items.size()); }
    QString itemName(int index) const;
    const TrendBuffer &buffer(int index) const;
    // The line pieces currently drawn for an item (one per stretch without a gap).
    QList<QLineSeries *> series(int index) const;

    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    qint64 windowMs() const { return m_windowMs; }
    void setWindowMs(qint64 ms);
    bool isZoomed() const { return m_zoomed; }
    // factor > 1 zooms in around the middle of the time axis (the wheel zooms around the mouse).
    void zoomBy(double factor);
    void resetZoom();

    QChart *chart() const { return m_chart; }
    // The least plot height that shows four value labels an axis (TrendValueAxes): a shorter plot
    // gives the legend's rows to it (the item list names the lines in their colours), and the
    // trend dock grows to it when it first opens.
    int usefulPlotHeight() const { return 10 * fontMetrics().height(); }
    QDateTimeAxis *timeAxis() const { return m_timeAxis; }
    // The value axis of an item (the first axis when there is no such item).
    QValueAxis *valueAxis(int index = 0) const;
    QList<QValueAxis *> valueAxes() const;
    // True (the default): every analog item has its own value axis; false: they share one.
    bool hasSeparateAxes() const { return m_separateAxes; }
    void setSeparateAxes(bool separate);
    // Tick steps and ticks of the value axes (see TrendValueAxes).
    static double niceStep(double min, double max, int targetTicks = 5)
    {
        return TrendValueAxes::niceStep(min, max, targetTicks);
    }
    static QList<double> tickValues(const QValueAxis *axis)
    {
        return TrendValueAxes::tickValues(axis);
    }

    // The cursor read-out (mouse over the chart): its text, one line for the time and one per
    // item ("Sine (R1): -309"); empty while hidden.
    QString readoutText() const;
    qint64 spanMs() const;

    // Redraws now (the view also redraws four times a second while not paused).
    void refresh();

    // The recorded past (issue 51): read from `center`'s store (nullptr: live buffers only).
    void setHistoryCenter(HistoryCenter *center)
    {
        m_history->setCenter(center);
        refresh();
    }
    TrendHistory *history() const { return m_history; }
    // The recorded pieces drawn for an item (one per stretch without a gap).
    QList<QLineSeries *> historySeries(int index) const
    {
        return m_history->series(m_items.at(static_cast<std::size_t>(index)).get());
    }
    QScrollBar *scrollBar() const { return m_navigation->scrollBar(); }
    QComboBox *windowBox() const { return m_navigation->windowBox(); }
    // The recorded samples of every item in the visible range to `path` (CSV, not blocking:
    // TrendHistory::exportFinished).
    void exportRange(const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    using Item = TrendLine;
    bool addOne(WatchTableModel *model, int row, QString *error);
    void keepAxisLabelsWhole();
    void rebuildAxes();

    void onDataChanged(WatchTableModel *model, const QModelIndex &topLeft,
                       const QModelIndex &bottomRight);
    void renameItems(WatchTableModel *model, int firstRow, int lastRow);
    void sample(Item &item);
    void rebuildItemList();
    void setTimeRange(qint64 fromMs, qint64 toMs);
    void userZoomed();
    void updateZoomUi();
    static QString displayName(const WatchItemSpec &spec);

    std::vector<std::unique_ptr<Item>> m_items;
    QChart *m_chart;
    TrendChartView *m_chartView;
    QDateTimeAxis *m_timeAxis;
    TrendValueAxes m_valueAxes;
    QToolButton *m_axesButton;
    QListWidget *m_itemList;
    QToolButton *m_pauseButton;
    QToolButton *m_resetZoomButton;
    QToolButton *m_removeButton;
    QToolButton *m_exportButton;
    TrendNavigation *m_navigation;
    TrendHistory *m_history;
    QLabel *m_emptyHint;
    QTimer m_refreshTimer;
    qint64 m_windowMs = 60000;
    bool m_paused = false;
    bool m_zoomed = false;
    bool m_separateAxes = true;
    bool m_settingRange = false;
    int m_colorIndex = 0;
};

} // namespace Fatek
