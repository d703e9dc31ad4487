#include "trendview.h"

#include "core/watch/valueformat.h"
#include "trendchartview.h"
#include "trendhistory.h"
#include "trendnavigation.h"
#include "trendvalueaxes.h"
#include "ui/common/uitext.h"
#include "ui/watch/watchtablemodel.h"

#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QScrollBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QDateTimeAxis>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace Fatek {

namespace {

// Distinct on light and dark backgrounds.
const QColor linePalette[]
    = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
       QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
       QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};

qint64 nowMs()
{
    return QDateTime::currentMSecsSinceEpoch();
}

} // namespace

QList<qint64> TrendView::windowChoicesMs()
{
    return TrendNavigation::windowChoicesMs();
}

TrendView::TrendView(QWidget *parent)
    : QWidget(parent)
    , m_chart(new QChart)
    , m_valueAxes(m_chart)
{
    setObjectName(QStringLiteral("trendView"));
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_timeAxis = new QDateTimeAxis(m_chart);
    m_timeAxis->setFormat(QStringLiteral("HH:mm:ss"));
    m_timeAxis->setTitleText(tr("Time"));
    m_timeAxis->setTickCount(7);
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    connect(m_chart, &QChart::plotAreaChanged, this, [this](const QRectF &area) {
        m_valueAxes.setPlotHeight(area.height());
        QLegend *legend = m_chart->legend();
        if (legend->isVisible() && area.height() < usefulPlotHeight())
            legend->hide();
        else if (!legend->isVisible()
                 && area.height() > usefulPlotHeight() + 3 * fontMetrics().height())
            legend->show();
    });
    connect(m_chart, &QGraphicsWidget::geometryChanged, this,
            [this] { m_valueAxes.setChartWidth(m_chart->size().width()); });

    m_chartView = new TrendChartView(
        m_chart, m_timeAxis,
        [this] {
            std::vector<TrendChartView::CursorLine> lines;
            for (const auto &item : m_items)
                lines.push_back({displayName(item->spec), item->color, &item->buffer,
                                 [this, line = item.get()](qint64 t, double *v) {
                                     return m_history->valueAt(line, t, v);
                                 }});
            return lines;
        },
        this);
    m_chartView->setObjectName(QStringLiteral("trendChart"));
    m_chartView->setToolTip(tr("Drag a rectangle to zoom in, right-click to zoom out, wheel to "
                               "zoom the time axis, Shift+wheel to scroll it"));
    m_navigation = new TrendNavigation(m_chart, m_timeAxis, this);
    m_history = new TrendHistory(m_chart, m_timeAxis, this);

    m_pauseButton = new QToolButton(this);
    m_pauseButton->setObjectName(QStringLiteral("trendPause"));
    m_pauseButton->setIcon(QIcon(QStringLiteral(":/icons/pause.svg")));
    m_pauseButton->setText(tr("Pause"));
    m_pauseButton->setToolTip(tr("Freeze the trend (no new points until resumed)"));
    m_pauseButton->setCheckable(true);
    m_pauseButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_exportButton = new QToolButton(this);
    m_exportButton->setObjectName(QStringLiteral("trendExport"));
    m_exportButton->setText(tr("Export Range…"));
    // An icon only: the bar must fit a trend docked narrow beside the table.
    m_exportButton->setIcon(QIcon(QStringLiteral(":/icons/save.svg")));
    m_exportButton->setToolTip(tr("Write the recorded values of the items in the time range shown "
                                  "to a CSV file"));

    m_resetZoomButton = new QToolButton(this);
    m_resetZoomButton->setObjectName(QStringLiteral("trendResetZoom"));
    m_resetZoomButton->setText(tr("Reset Zoom"));
    m_resetZoomButton->setToolTip(tr("Show the whole time window again and follow the present"));

    m_axesButton = new QToolButton(this);
    m_axesButton->setObjectName(QStringLiteral("trendSeparateAxes"));
    m_axesButton->setText(tr("Separate Axes"));
    m_axesButton->setToolTip(tr("Give every item its own value axis (bits share one); off: one "
                                "value axis for all items except bits"));
    m_axesButton->setCheckable(true);
    m_axesButton->setChecked(m_separateAxes);

    m_removeButton = new QToolButton(this);
    m_removeButton->setObjectName(QStringLiteral("trendRemove"));
    m_removeButton->setIcon(QIcon(QStringLiteral(":/icons/remove.svg")));
    m_removeButton->setText(tr("Remove"));
    m_removeButton->setToolTip(tr("Remove the selected item from the trend"));
    m_removeButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_itemList = new QListWidget(this);
    m_itemList->setObjectName(QStringLiteral("trendItems"));
    m_itemList->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_itemList->setMaximumWidth(220);
    m_itemList->setContextMenuPolicy(Qt::ActionsContextMenu);
    auto *removeAction = new QAction(tr("&Remove from Trend"), m_itemList);
    removeAction->setShortcut(QKeySequence::Delete);
    removeAction->setShortcutContext(Qt::WidgetShortcut);
    m_itemList->addAction(removeAction);

    m_emptyHint = new QLabel(
        tr("Select rows in a watch table and choose \"Add to Trend\" from its context menu."),
        this);
    m_emptyHint->setWordWrap(true);

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_pauseButton);
    bar->addWidget(new QLabel(tr("Window:"), this));
    bar->addWidget(m_navigation->windowBox());
    bar->addWidget(m_resetZoomButton);
    bar->addWidget(m_axesButton);
    bar->addStretch(1);
    bar->addWidget(m_exportButton);
    bar->addWidget(m_removeButton);

    auto *side = new QVBoxLayout;
    side->addWidget(m_itemList, 1);
    side->addWidget(m_emptyHint);
    auto *body = new QHBoxLayout;
    body->addLayout(side);
    auto *chartColumn = new QVBoxLayout;
    chartColumn->setSpacing(0);
    chartColumn->addWidget(m_chartView, 1);
    chartColumn->addWidget(m_navigation->scrollBar());
    body->addLayout(chartColumn, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addLayout(body, 1);

    connect(m_pauseButton, &QToolButton::toggled, this, &TrendView::setPaused);
    connect(m_navigation, &TrendNavigation::windowChosen, this, &TrendView::setWindowMs);
    connect(m_navigation, &TrendNavigation::rangeChosen, this, &TrendView::showRange);
    connect(m_history, &TrendHistory::pointsArrived, this, &TrendView::refresh);
    connect(m_history, &TrendHistory::statusMessage, this, &TrendView::statusMessage);
    connect(m_exportButton, &QToolButton::clicked, this, [this] {
        CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf;
        if (const QString path = TrendHistory::askExportPath(this, &lineEnd); !path.isEmpty())
            exportRange(path, lineEnd);
    });
    connect(m_resetZoomButton, &QToolButton::clicked, this, &TrendView::resetZoom);
    connect(m_axesButton, &QToolButton::toggled, this, &TrendView::setSeparateAxes);
    auto removeSelected = [this] {
        std::vector<int> rows;
        for (const QModelIndex &i : m_itemList->selectionModel()->selectedRows())
            rows.push_back(i.row());
        std::sort(rows.rbegin(), rows.rend());
        for (int r : rows)
            removeItem(r);
    };
    connect(m_removeButton, &QToolButton::clicked, this, removeSelected);
    connect(removeAction, &QAction::triggered, this, removeSelected);
    connect(m_chartView, &TrendChartView::userZoomed, this, &TrendView::userZoomed);
    connect(m_timeAxis, &QDateTimeAxis::rangeChanged, this, [this] {
        if (!m_settingRange)
            userZoomed();
    });

    m_refreshTimer.setInterval(250);
    connect(&m_refreshTimer, &QTimer::timeout, this, &TrendView::refresh);
    m_refreshTimer.start();
    rebuildAxes();
    rebuildItemList();
    updateZoomUi();
    refresh();
}

TrendView::~TrendView()
{
    m_refreshTimer.stop();
    for (auto &item : m_items) {
        if (item->model)
            disconnect(item->model, nullptr, this, nullptr);
    }
}

QString TrendView::displayName(const WatchItemSpec &spec)
{
    const QString address = QString::fromStdString(spec.address.toString());
    return spec.name.trimmed().isEmpty() ? address
                                         : tr("%1 (%2)").arg(spec.name.trimmed(), address);
}

bool TrendView::addItem(WatchTableModel *model, int row, QString *error)
{
    if (!addOne(model, row, error))
        return false;
    Q_EMIT statusMessage(tr("%1 added to the trend.").arg(itemName(itemCount() - 1)));
    return true;
}

int TrendView::addItems(WatchTableModel *model, const QList<int> &rows)
{
    QStringList added, problems;
    for (int row : rows) {
        QString error;
        if (addOne(model, row, &error))
            added << itemName(itemCount() - 1);
        else
            problems << error;
    }
    QStringList message;
    if (added.size() > 3)
        message << tr("%n item(s) added to the trend.", nullptr, static_cast<int>(added.size()));
    else if (!added.isEmpty())
        message << tr("%1 added to the trend.").arg(added.join(QLatin1String(", ")));
    message += problems;
    if (!message.isEmpty())
        Q_EMIT statusMessage(message.join(QLatin1Char(' ')));
    return static_cast<int>(added.size());
}

bool TrendView::addOne(WatchTableModel *model, int row, QString *error)
{
    if (!model || row < 0 || row >= model->rowCount()) {
        if (error)
            *error = tr("No watch table row to trend.");
        return false;
    }
    const WatchItemSpec spec = model->item(row);
    const quint64 key = model->rowKey(row);
    for (const auto &item : m_items) {
        if (item->model == model && item->rowKey == key) {
            if (error)
                *error = tr("%1 is already in the trend.").arg(displayName(spec));
            return false;
        }
    }
    if (!trendValue(spec, 0)) {
        if (error)
            *error = tr("%1 is shown as %2, which has no value to plot.")
                         .arg(displayName(spec), UiText::format(spec.format));
        return false;
    }
    auto item = std::make_unique<Item>();
    item->spec = spec;
    item->model = model;
    item->rowKey = key;
    item->color = linePalette[m_colorIndex++ % static_cast<int>(std::size(linePalette))];
    item->discrete = ValueFormat::valueWidth(spec.address, spec.format) == 1;
    // One connection per model: the first item of a model connects it.
    const bool connected = std::any_of(m_items.cbegin(), m_items.cend(),
                                       [model](const auto &i) { return i->model == model; });
    m_items.push_back(std::move(item));
    if (!connected) {
        connect(model, &QAbstractItemModel::dataChanged, this,
                [this, model](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
                    onDataChanged(model, topLeft, bottomRight);
                });
    }
    sample(*m_items.back());
    rebuildAxes();
    rebuildItemList();
    refresh();
    return true;
}

void TrendView::removeItem(int index)
{
    if (index < 0 || index >= itemCount())
        return;
    auto it = m_items.begin() + index;
    m_history->remove(it->get());
    (*it)->removeFrom(m_chart);
    QPointer<WatchTableModel> model = (*it)->model;
    m_items.erase(it);
    if (model && std::none_of(m_items.cbegin(), m_items.cend(), [&model](const auto &i) {
            return i->model == model;
        }))
        disconnect(model, nullptr, this, nullptr);
    rebuildAxes();
    rebuildItemList();
    refresh();
}

QString TrendView::itemName(int index) const
{
    return displayName(m_items.at(static_cast<std::size_t>(index))->spec);
}

const TrendBuffer &TrendView::buffer(int index) const
{
    return m_items.at(static_cast<std::size_t>(index))->buffer;
}

QList<QLineSeries *> TrendView::series(int index) const
{
    QList<QLineSeries *> list;
    for (QLineSeries *s : m_items.at(static_cast<std::size_t>(index))->series) {
        if (s->count() > 0)
            list.append(s);
    }
    return list;
}

void TrendView::onDataChanged(WatchTableModel *model, const QModelIndex &topLeft,
                              const QModelIndex &bottomRight)
{
    const int firstRow = topLeft.row();
    const int lastRow = bottomRight.row();
    // A row's name changed (typed, or imported names): the legend, item list and axes follow.
    if (topLeft.column() == WatchTableModel::NameColumn)
        renameItems(model, firstRow, lastRow);
    // Value batches and staleness touch the columns up to Updated; the end of a change highlight
    // touches the value column only, a comment the comment column: nothing new to sample.
    if (m_paused || bottomRight.column() < WatchTableModel::QualityColumn
        || topLeft.column() > WatchTableModel::UpdatedColumn)
        return;
    for (auto &item : m_items) {
        if (item->model != model)
            continue;
        const int row = model->rowOfKey(item->rowKey);
        if (row >= firstRow && row <= lastRow)
            sample(*item);
    }
}

void TrendView::renameItems(WatchTableModel *model, int firstRow, int lastRow)
{
    bool renamed = false;
    for (auto &item : m_items) {
        const int row = item->model == model ? model->rowOfKey(item->rowKey) : -1;
        if (row < firstRow || row > lastRow || row < 0)
            continue;
        const QString name = model->item(row).name;
        if (name == item->spec.name)
            continue;
        item->spec.name = name;
        for (QLineSeries *s : item->series)
            s->setName(displayName(item->spec));
        renamed = true;
    }
    if (!renamed)
        return;
    rebuildAxes();
    rebuildItemList();
}

void TrendView::sample(Item &item)
{
    if (m_paused || !item.model)
        return;
    const qint64 now = nowMs();
    const int row = item.model->rowOfKey(item.rowKey);
    if (row < 0) {
        item.buffer.appendGap(now);
        return;
    }
    const WatchItemSpec spec = item.model->item(row);
    std::optional<double> value;
    // A changed format changes what the number means: the old line ends there.
    if (spec.format == item.spec.format && spec.swapWords == item.spec.swapWords
        && item.model->hasValue(row) && item.model->quality(row) == ValueQuality::Good)
        value = trendValue(spec, item.model->rawValue(row));
    if (value)
        item.buffer.append(now, *value);
    else
        item.buffer.appendGap(now);
}

void TrendView::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    const QSignalBlocker block(m_pauseButton);
    m_pauseButton->setChecked(paused);
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    // Whatever happens while paused is not seen: the line must not bridge it.
    if (paused) {
        for (auto &item : m_items)
            item->buffer.appendGap(nowMs());
        m_refreshTimer.stop();
    } else {
        m_refreshTimer.start();
        refresh();
    }
}

void TrendView::setWindowMs(qint64 ms)
{
    m_windowMs = std::max<qint64>(ms, 1000);
    m_navigation->showWindow(m_windowMs);
    m_zoomed = false;
    updateZoomUi();
    refresh();
}

void TrendView::zoomBy(double factor)
{
    if (factor <= 0)
        return;
    userZoomed();
    const QRectF area = m_chart->plotArea();
    QRectF zoomed = area;
    zoomed.setWidth(area.width() / factor);
    zoomed.moveCenter(area.center());
    m_chart->zoomIn(zoomed); // the time axis only
    refresh();
}

void TrendView::showRange(qint64 fromMs, qint64 toMs)
{
    if (toMs <= fromMs)
        return;
    userZoomed();
    setTimeRange(fromMs, toMs);
    refresh();
}

void TrendView::resetZoom()
{
    m_navigation->showWindow(m_windowMs);
    m_zoomed = false;
    updateZoomUi();
    refresh();
}

void TrendView::userZoomed()
{
    if (m_zoomed)
        return;
    m_zoomed = true;
    updateZoomUi();
}

void TrendView::updateZoomUi()
{
    m_resetZoomButton->setEnabled(m_zoomed);
}

qint64 TrendView::spanMs() const
{
    qint64 span = 0;
    for (const auto &item : m_items)
        span = std::max(span, item->spanMs());
    return span;
}

void TrendView::rebuildItemList()
{
    m_itemList->clear();
    for (const auto &item : m_items) {
        QPixmap swatch(12, 12);
        swatch.fill(item->color);
        auto *entry = new QListWidgetItem(QIcon(swatch), displayName(item->spec), m_itemList);
        entry->setToolTip(
            tr("Station %1, %2").arg(item->spec.station).arg(UiText::format(item->spec.format)));
    }
    m_emptyHint->setVisible(m_items.empty());
    m_removeButton->setEnabled(!m_items.empty());
}

void TrendView::setTimeRange(qint64 fromMs, qint64 toMs)
{
    m_settingRange = true;
    m_timeAxis->setRange(QDateTime::fromMSecsSinceEpoch(fromMs),
                         QDateTime::fromMSecsSinceEpoch(toMs));
    m_settingRange = false;
}

QValueAxis *TrendView::valueAxis(int index) const
{
    if (index >= 0 && index < itemCount())
        return m_items.at(static_cast<std::size_t>(index))->axis;
    return m_valueAxes.axes().empty() ? nullptr : m_valueAxes.axes().front();
}

QList<QValueAxis *> TrendView::valueAxes() const
{
    return QList<QValueAxis *>(m_valueAxes.axes().cbegin(), m_valueAxes.axes().cend());
}

void TrendView::setSeparateAxes(bool separate)
{
    if (separate == m_separateAxes)
        return;
    m_separateAxes = separate;
    const QSignalBlocker block(m_axesButton);
    m_axesButton->setChecked(separate);
    rebuildAxes();
    refresh();
}

void TrendView::rebuildAxes()
{
    std::vector<TrendValueAxes::Line> lines;
    for (const auto &item : m_items)
        lines.push_back({displayName(item->spec), item->color, item->discrete,
                         QString::fromStdString(item->spec.address.toString())});
    const std::vector<QValueAxis *> axes = m_valueAxes.rebuild(lines, m_separateAxes);
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        m_items[i]->axis = axes[i];
        for (QLineSeries *s : m_items[i]->series)
            s->attachAxis(axes[i]);
    }
    keepAxisLabelsWhole();
}

void TrendView::keepAxisLabelsWhole()
{
    // The chart is never narrower than its value axes' labels need: a dock dragged narrow stops
    // there instead of the labels being cut to "...". It grows at once and shrinks by more than
    // a few pixels only, so that labels changing with the values do not make the layout jitter.
    const int needed = m_valueAxes.minimumChartWidth() + 2 * m_chartView->frameWidth();
    const int now = m_chartView->minimumWidth();
    if (needed > now || needed < now - 16)
        m_chartView->setMinimumWidth(needed);
}

QString TrendView::readoutText() const
{
    return m_chartView->readoutText();
}

void TrendView::refresh()
{
    qint64 fromMs = 0, toMs = 0;
    if (m_zoomed) {
        fromMs = m_timeAxis->min().toMSecsSinceEpoch();
        toMs = m_timeAxis->max().toMSecsSinceEpoch();
    } else {
        toMs = nowMs();
        // Paused: the picture stays where it stopped.
        for (const auto &item : m_items) {
            if (m_paused && !item->buffer.isEmpty())
                toMs = std::min(toMs, item->buffer.last().timeMs);
        }
        fromMs = toMs - m_windowMs;
    }
    // About two points per pixel column: more cannot be seen.
    const qsizetype maxPoints = std::max<qsizetype>(400, 2 * m_chartView->width());
    const int pixels = std::max(100, static_cast<int>(m_chart->plotArea().width()));
    std::map<QValueAxis *, TrendValueAxes::Span> spans;
    for (auto &item : m_items) {
        TrendValueAxes::Span &span = spans[item->axis];
        const QString name = displayName(item->spec);
        item->draw(m_chart, m_timeAxis, name, fromMs, toMs, maxPoints, span);
        m_history->draw(*item, name, fromMs, toMs, pixels, span);
    }
    m_valueAxes.fit(std::move(spans), m_zoomed);
    keepAxisLabelsWhole();
    if (!m_zoomed)
        setTimeRange(fromMs, toMs);
    m_navigation->showRange(fromMs, toMs, nowMs());
    m_chartView->updateReadout(); // the time under the mouse moved with the axis
}

void TrendView::exportRange(const QString &path, CsvFile::LineEnd lineEnd)
{
    m_history->exportRange(m_items, m_timeAxis->min().toMSecsSinceEpoch(),
                           m_timeAxis->max().toMSecsSinceEpoch(), path, lineEnd);
}

} // namespace Fatek
