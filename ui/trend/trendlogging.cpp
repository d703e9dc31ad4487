#include "trendlogging.h"

#include "tablelogger.h"
#include "trendview.h"
#include "ui/common/csvfilefilter.h"
#include "ui/common/lastdirectory.h"
#include "ui/common/uitext.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QtCharts/QChart>

namespace Fatek {

TrendLogging::TrendLogging(QMainWindow *window, QDockWidget *tabWith, CurrentTable currentTable,
                           QMenu *toolsMenu, QMenu *viewMenu)
    : QObject(window)
    , m_window(window)
    , m_tabWith(tabWith)
    , m_currentTable(std::move(currentTable))
{
    setObjectName(QStringLiteral("trendLogging"));
    m_trendView = new TrendView(window);
    auto *dock = new QDockWidget(tr("Trend"), window);
    dock->setObjectName(QStringLiteral("trendDock"));
    dock->setWidget(m_trendView);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide(); // shown by Tools > Trend or "Add to Trend"
    m_trendDock = dock;
    QAction *toggle = dock->toggleViewAction();
    toggle->setText(tr("&Trend"));
    toggle->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G));
    toolsMenu->addAction(toggle);
    viewMenu->addAction(toggle);
    connect(m_trendView, &TrendView::statusMessage, this, &TrendLogging::statusMessage);
    connect(m_trendView->chart(), &QChart::plotAreaChanged, this, &TrendLogging::growPlot);

    m_tableLogger = new TableLogger(this);
    m_loggingLabel = new QLabel(window);
    m_loggingLabel->setObjectName(QStringLiteral("loggingStatus"));
    m_loggingLabel->hide();
    window->statusBar()->addPermanentWidget(m_loggingLabel);
    m_startLoggingAction
        = toolsMenu->addAction(QIcon(QStringLiteral(":/icons/save.svg")),
                               tr("Start &Data Logging…"), this, &TrendLogging::startLoggingDialog);
    m_startLoggingAction->setToolTip(tr("Write every value of the current watch table to a CSV "
                                        "file with timestamps"));
    m_stopLoggingAction
        = toolsMenu->addAction(tr("Stop Data Lo&gging"), this, &TrendLogging::stopLogging);
    m_stopLoggingAction->setEnabled(false);
    toolsMenu->addSeparator();
    connect(m_tableLogger, &TableLogger::rowWritten, this, &TrendLogging::updateLoggingStatus);
    connect(m_tableLogger, &TableLogger::stopped, this, [this](const QString &error) {
        updateLoggingStatus();
        if (!error.isEmpty()) {
            Q_EMIT statusMessage(tr("Data logging stopped: %1").arg(error));
            if (m_window->isVisible())
                QMessageBox::warning(m_window, tr("Data Logging"),
                                     tr("Data logging stopped:\n%1").arg(error));
        }
    });
}

void TrendLogging::showDemo()
{
    // Two ranges far apart, each on its own axis.
    WatchTableWidget *table = m_currentTable();
    if (!table)
        return;
    const WatchTableModel *model = table->model();
    QList<int> rows;
    for (const char *address : {"R1", "DR10"}) {
        for (int r = 0; r < model->rowCount(); ++r) {
            if (model->item(r).address.toString() == address)
                rows << r;
        }
    }
    if (rows.isEmpty())
        return;
    m_trendView->addItems(table->model(), rows);
    // One sine period fills the window: the wave is visible within seconds.
    m_trendView->setWindowMs(10000);
}

QWidget *TrendLogging::showTrend()
{
    const bool wasHidden = m_trendDock->isHidden();
    m_trendDock->show();
    m_trendDock->raise();
    // A chart needs room: on first showing, the trend becomes a tab of the bottom area (beside the
    // connections and the console) with the full width and a good height; afterwards the user's
    // arrangement stays.
    QDockWidget *connectionsDock = m_tabWith.data();
    if (wasHidden && connectionsDock && !connectionsDock->isHidden() && !m_trendDock->isFloating()
        && m_window->dockWidgetArea(m_trendDock) == Qt::BottomDockWidgetArea
        && m_window->dockWidgetArea(connectionsDock) == Qt::BottomDockWidgetArea
        && m_window->tabifiedDockWidgets(m_trendDock).isEmpty()) {
        m_window->tabifyDockWidget(connectionsDock, m_trendDock);
        m_trendDock->raise();
        m_window->resizeDocks({m_trendDock}, {m_window->height() * 2 / 5}, Qt::Vertical);
        // At a laptop's height 2/5 of the window left a plot of about 100 px (one value label
        // per axis): while the dock settles, it grows until the plot has a useful height.
        m_growPlot = true;
        QMetaObject::invokeMethod(
            this, [this] { growPlot(m_trendView->chart()->plotArea()); }, Qt::QueuedConnection);
        QTimer::singleShot(1000, this, [this] { m_growPlot = false; });
    }
    return m_trendView;
}

void TrendLogging::growPlot(const QRectF &plot)
{
    if (!m_growPlot || !m_trendDock->isVisible() || plot.height() <= 0)
        return;
    const int missing = m_trendView->usefulPlotHeight() - static_cast<int>(plot.height());
    // The tables keep the larger part of the window.
    const int most = m_window->height() * 11 / 20;
    if (missing > 0 && m_trendDock->height() < most)
        m_window->resizeDocks({m_trendDock}, {std::min(most, m_trendDock->height() + missing)},
                              Qt::Vertical);
}

void TrendLogging::addToTrend(WatchTableWidget *table, const QList<int> &rows)
{
    if (!table)
        return;
    // One status message names everything added (and refused).
    m_trendView->addItems(table->model(), rows);
    showTrend();
}

Status TrendLogging::startLogging(const QString &path, CsvFile::LineEnd lineEnd)
{
    WatchTableWidget *table = m_currentTable();
    if (!table)
        return makeError(ErrorKind::InvalidRequest, tr("No watch table to log.").toStdString());
    if (const Status s = m_tableLogger->start(table->model(), path, lineEnd); !s)
        return s;
    updateLoggingStatus();
    Q_EMIT statusMessage(
        tr("Logging %1 to %2.").arg(table->name(), QDir::toNativeSeparators(path)));
    return Ok{};
}

void TrendLogging::stopLogging()
{
    if (!m_tableLogger || !m_tableLogger->isLogging())
        return;
    const QString path = m_tableLogger->path();
    const qint64 rows = m_tableLogger->rowCount();
    m_tableLogger->stop();
    Q_EMIT statusMessage(tr("Logging stopped: %n row(s) in %1.", nullptr, static_cast<int>(rows))
                             .arg(QDir::toNativeSeparators(path)));
}

void TrendLogging::startLoggingDialog()
{
    WatchTableWidget *table = m_currentTable();
    if (!table || table->model()->rowCount() == 0) {
        QMessageBox::information(m_window, tr("Data Logging"),
                                 tr("Add items to a watch table first: logging writes the rows of "
                                    "the current table."));
        return;
    }
    QString filter;
    QString path = QFileDialog::getSaveFileName(
        m_window, tr("Log Watch Table to CSV"), lastDirectory(), CsvFileFilter::both(), &filter,
        QFileDialog::DontConfirmOverwrite); // an existing log is appended to, not replaced
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".csv");
    setLastDirectory(path);
    if (const Status s = startLogging(path, CsvFileFilter::lineEnd(filter)); !s)
        QMessageBox::warning(m_window, tr("Data Logging"), translated(s.error().message));
}

void TrendLogging::updateLoggingStatus()
{
    const bool on = m_tableLogger->isLogging();
    m_startLoggingAction->setEnabled(true);
    m_stopLoggingAction->setEnabled(on);
    m_loggingLabel->setVisible(on);
    if (on) {
        m_loggingLabel->setText(
            tr("Logging to %1 (%n row(s))", nullptr, static_cast<int>(m_tableLogger->rowCount()))
                .arg(QFileInfo(m_tableLogger->path()).fileName()));
        m_loggingLabel->setToolTip(QDir::toNativeSeparators(m_tableLogger->path()));
    }
}

} // namespace Fatek
