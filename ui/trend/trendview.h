#pragma once

#include "trendbuffer.h"
#include "watchlist.h"

#include <QColor>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <memory>
#include <vector>

class QChart;
class QComboBox;
class QDateTimeAxis;
class QLabel;
class QLineSeries;
class QListWidget;
class QToolButton;
class QValueAxis;

namespace Fatek {

class TrendChartView;
class WatchTableModel;

// A trend of watch table items over time (Qt Charts): one line per item in a shared time axis.
// Samples come from the watch table models as their values arrive; a value that is not fresh
// (stale, refused, polling paused, trend paused) ends the line, so a gap shows where nothing
// fresh was read. Pause freezes the picture; the time window (10 s .. 1 h) follows the present
// until the user zooms (rubber band, mouse wheel), Reset Zoom goes back to following.
class TrendView : public QWidget
{
    Q_OBJECT
    // For the screenshot of --tool trend: how much history the trend holds.
    Q_PROPERTY(qint64 spanMs READ spanMs)

public:
    // The time windows the window box offers.
    static QList<qint64> windowChoicesMs();

    explicit TrendView(QWidget *parent = nullptr);
    ~TrendView() override;

    // Trends the row of `model` (followed by its row key while rows move). False, with `error`,
    // for a value that has no height (ASCII) or an item already in the trend.
    bool addItem(WatchTableModel *model, int row, QString *error = nullptr);
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
    QDateTimeAxis *timeAxis() const { return m_timeAxis; }
    QValueAxis *valueAxis() const { return m_valueAxis; }
    qint64 spanMs() const;

    // Redraws now (the view also redraws four times a second while not paused).
    void refresh();

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    struct Item
    {
        WatchItemSpec spec;
        QPointer<WatchTableModel> model;
        quint64 rowKey = 0;
        QColor color;
        TrendBuffer buffer;
        std::vector<QLineSeries *> series;
    };
    friend class TrendChartView;

    void onDataChanged(WatchTableModel *model, int firstRow, int lastRow, int lastColumn);
    void sample(Item &item);
    void rebuildItemList();
    void setAxesRange(qint64 fromMs, qint64 toMs, double yMin, double yMax);
    void userZoomed();
    void updateZoomUi();
    static QString displayName(const WatchItemSpec &spec);

    std::vector<std::unique_ptr<Item>> m_items;
    QChart *m_chart;
    TrendChartView *m_chartView;
    QDateTimeAxis *m_timeAxis;
    QValueAxis *m_valueAxis;
    QListWidget *m_itemList;
    QToolButton *m_pauseButton;
    QToolButton *m_resetZoomButton;
    QToolButton *m_removeButton;
    QComboBox *m_windowBox;
    QLabel *m_emptyHint;
    QTimer m_refreshTimer;
    qint64 m_windowMs = 60000;
    bool m_paused = false;
    bool m_zoomed = false;
    bool m_settingRange = false;
    int m_colorIndex = 0;
};

} // namespace Fatek
