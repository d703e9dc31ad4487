#pragma once

#include "core/protocol/result.h"
#include "core/watch/csvfile.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QRectF>

#include <functional>

class QAction;
class QDockWidget;
class QLabel;
class QMainWindow;
class QMenu;
class QWidget;

namespace Fatek {

class TableLogger;
class TrendView;
class WatchTableWidget;

// Trends and data logging in the main window: the trend dock (Tools > Trend), the Start/Stop Data
// Logging actions and the status bar label of a running log.
class TrendLogging : public QObject
{
    Q_OBJECT

public:
    using CurrentTable = std::function<WatchTableWidget *()>;

    // Adds the (hidden) trend dock to `window` and the entries to `toolsMenu` and `viewMenu`.
    // The trend opens as a tab beside `tabWith` (the connections dock); logging and the demo
    // act on the table `currentTable` returns.
    TrendLogging(QMainWindow *window, QDockWidget *tabWith, CurrentTable currentTable,
                 QMenu *toolsMenu, QMenu *viewMenu);

    TrendView *trendView() const { return m_trendView; }
    TableLogger *tableLogger() const { return m_tableLogger; }
    // Shows and raises the trend dock; returns the trend.
    QWidget *showTrend();
    // Adds rows of a watch table to the trend and shows the trend.
    void addToTrend(WatchTableWidget *table, const QList<int> &rows);
    // Logs the current watch table to `path` (CSV, appended); a log already running stops first.
    // A new log's lines end as `lineEnd`; an existing one keeps its own (DataLogger).
    Status startLogging(const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
    void stopLogging();
    // The demo's sine (R1, +-1000) and ramp (DR10, 0..99999) of the current table into the trend.
    void showDemo();

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    void startLoggingDialog();
    void growPlot(const QRectF &plot);
    void updateLoggingStatus();

    QMainWindow *m_window;
    QPointer<QDockWidget> m_tabWith;
    CurrentTable m_currentTable;
    TrendView *m_trendView;
    QDockWidget *m_trendDock;
    TableLogger *m_tableLogger;
    QLabel *m_loggingLabel;
    QAction *m_startLoggingAction;
    QAction *m_stopLoggingAction;
    bool m_growPlot = false; // the dock was just arranged: grow it once for the plot
};

} // namespace Fatek
