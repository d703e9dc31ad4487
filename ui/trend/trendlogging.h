#pragma once

#include "core/protocol/result.h"

#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QWidget;

namespace Fatek {

class MainWindow;
class TableLogger;
class TrendView;
class WatchTableWidget;

// Trends and data logging in the main window: the trend dock (Tools > Trend), the Start/Stop Data
// Logging actions and the status bar label of a running log. The demo's sine and ramp go into the
// trend as soon as the demo is ready.
class TrendLogging : public QObject
{
    Q_OBJECT

public:
    // Adds the (hidden) trend dock to `window` and the entries to `toolsMenu` and `viewMenu`.
    TrendLogging(MainWindow *window, QMenu *toolsMenu, QMenu *viewMenu);

    TrendView *trendView() const { return m_trendView; }
    TableLogger *tableLogger() const { return m_tableLogger; }
    // Shows and raises the trend dock; returns the trend.
    QWidget *showTrend();
    // Adds rows of a watch table to the trend and shows the trend.
    void addToTrend(WatchTableWidget *table, const QList<int> &rows);
    // Logs the current watch table to `path` (CSV, appended); a log already running stops first.
    Status startLogging(const QString &path);
    void stopLogging();

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    void startLoggingDialog();
    void updateLoggingStatus();

    MainWindow *m_window;
    TrendView *m_trendView;
    QDockWidget *m_trendDock;
    TableLogger *m_tableLogger;
    QLabel *m_loggingLabel;
    QAction *m_startLoggingAction;
    QAction *m_stopLoggingAction;
};

} // namespace Fatek
