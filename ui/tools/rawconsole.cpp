#include "rawconsole.h"

#include "core/link/plclink.h"
#include "core/session/trafficlog.h"
#include "core/watch/safefile.h"
#include "rawsendbar.h"
#include "trafficfilterproxy.h"
#include "trafficlogmodel.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QShowEvent>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

namespace Fatek {

RawConsole::RawConsole(QWidget *parent)
    : QWidget(parent)
    , m_model(new TrafficLogModel(this))
    , m_filter(new TrafficFilterProxy(this))
{
    auto *layout = new QVBoxLayout(this);
    m_targetLabel = new QLabel(this);
    m_targetLabel->setObjectName(QStringLiteral("targetLabel"));
    layout->addWidget(m_targetLabel);
    // The send line and its answer first: the console shares the bottom of the window with the
    // connections, and on a laptop only its top part shows without dragging the splitter.
    m_sendBar = new RawSendBar(this);
    layout->addWidget(m_sendBar);

    auto *filters = new QHBoxLayout;
    m_direction = new QComboBox(this);
    m_direction->setObjectName(QStringLiteral("directionFilter"));
    m_direction->addItem(tr("All directions"), -1);
    m_direction->addItem(tr("Sent"), static_cast<int>(TrafficEntry::Direction::Out));
    m_direction->addItem(tr("Received"), static_cast<int>(TrafficEntry::Direction::In));
    m_direction->addItem(tr("Events"), static_cast<int>(TrafficEntry::Direction::Event));
    m_stationFilter = new QSpinBox(this);
    m_stationFilter->setObjectName(QStringLiteral("stationFilter"));
    m_stationFilter->setRange(-1, Limits::maxStation);
    m_stationFilter->setSpecialValueText(tr("All stations"));
    m_stationFilter->setValue(-1);
    m_stationFilter->setPrefix(tr("Station "));
    m_command = new QComboBox(this);
    m_command->setObjectName(QStringLiteral("commandFilter"));
    m_command->addItem(tr("All commands"), -1);
    for (int code = 0x40; code <= 0x53; ++code) {
        if (!isKnownCommand(static_cast<std::uint8_t>(code)))
            continue;
        m_command->addItem(QString::number(code, 16).toUpper() + QLatin1Char(' ')
                               + UiText::commandName(static_cast<Command>(code)),
                           code);
    }
    m_errorsOnly = new QCheckBox(tr("Errors only"), this);
    m_errorsOnly->setObjectName(QStringLiteral("errorsOnly"));
    m_pause = new QPushButton(tr("Pause"), this);
    m_pause->setObjectName(QStringLiteral("pauseButton"));
    m_pause->setCheckable(true);
    auto *clearButton = new QPushButton(tr("Clear"), this);
    clearButton->setObjectName(QStringLiteral("clearButton"));
    auto *copyButton = new QPushButton(tr("Copy"), this);
    copyButton->setObjectName(QStringLiteral("copyButton"));
    auto *saveButton = new QPushButton(tr("Save\u2026"), this);
    saveButton->setObjectName(QStringLiteral("saveButton"));
    filters->addWidget(m_direction);
    filters->addWidget(m_stationFilter);
    filters->addWidget(m_command);
    filters->addWidget(m_errorsOnly);
    filters->addStretch(1);
    filters->addWidget(m_pause);
    filters->addWidget(clearButton);
    filters->addWidget(copyButton);
    filters->addWidget(saveButton);
    layout->addLayout(filters);

    m_model->setPalette(palette());
    m_filter->setSourceModel(m_model);
    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("trafficView"));
    m_view->setModel(m_filter);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 6);
    m_view->horizontalHeader()->setStretchLastSection(true);
    const QFontMetrics fm = m_view->fontMetrics();
    m_view->setColumnWidth(TrafficLogModel::TimeColumn,
                           fm.horizontalAdvance(QStringLiteral("00:00:00.000  ")));
    m_view->setColumnWidth(TrafficLogModel::DirectionColumn,
                           fm.horizontalAdvance(QStringLiteral("received  ")));
    m_view->setColumnWidth(TrafficLogModel::StationColumn,
                           fm.horizontalAdvance(QStringLiteral("Station  ")));
    m_view->setColumnWidth(TrafficLogModel::HexColumn, fm.horizontalAdvance(QLatin1Char('0')) * 30);
    m_view->setColumnWidth(TrafficLogModel::AsciiColumn,
                           fm.horizontalAdvance(QLatin1Char('0')) * 22);
    m_view->setColumnWidth(TrafficLogModel::MeaningColumn,
                           fm.horizontalAdvance(QLatin1Char('0')) * 34);
    layout->addWidget(m_view, 1);

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("consoleStatus"));
    layout->addWidget(m_status);

    connect(m_direction, &QComboBox::currentIndexChanged, this, &RawConsole::applyFilters);
    connect(m_stationFilter, &QSpinBox::valueChanged, this, &RawConsole::applyFilters);
    connect(m_command, &QComboBox::currentIndexChanged, this, &RawConsole::applyFilters);
    connect(m_errorsOnly, &QCheckBox::toggled, this, &RawConsole::applyFilters);
    connect(m_pause, &QPushButton::toggled, this, &RawConsole::setPaused);
    connect(clearButton, &QPushButton::clicked, this, &RawConsole::clear);
    connect(copyButton, &QPushButton::clicked, this, [this] { copyRows(); });
    connect(saveButton, &QPushButton::clicked, this, &RawConsole::save);
    // Follow new frames unless the user scrolled up to read; scrolling back down follows again.
    QScrollBar *bar = m_view->verticalScrollBar();
    connect(bar, &QScrollBar::actionTriggered, this, [this, bar] {
        QTimer::singleShot(0, this,
                           [this, bar] { m_followTail = bar->value() >= bar->maximum() - 1; });
    });
    // entriesAdded can come for every frame: gather them and append in batches.
    m_fetchTimer.setSingleShot(true);
    m_fetchTimer.setInterval(50);
    connect(&m_fetchTimer, &QTimer::timeout, this, &RawConsole::fetch);

    setTarget(PlcTarget());
}

void RawConsole::setTarget(const PlcTarget &target)
{
    m_sendBar->setTarget(target);
    const bool sameLink = m_attached && target.isDirect() && m_target.link() == target.link();
    m_target = target;
    if (!sameLink) {
        disconnect(m_linkGone);
        listen(false);
        m_attached = target.isDirect();
        m_lastSequence = 0;
        m_followTail = true;
        m_model->clear();
    }
    if (!target.isDirect()) {
        m_targetLabel->setText(tr("No connection: choose a connection to see its traffic."));
        ToolPalette::showMessage(m_status, {}, false);
        return;
    }
    // The log belongs to the link, not one station: every frame of the connection is shown.
    m_targetLabel->setText(tr("Traffic of \u201c%1\u201d (sending to station %2)")
                               .arg(target.connectionName())
                               .arg(target.station()));
    if (sameLink)
        return;
    // A closed link leaves the console in "no connection".
    m_linkGone = connect(target.link(), &QObject::destroyed, this,
                         [this] { setTarget(PlcTarget(nullptr, m_target.station(), {})); });
    if (isOnScreen())
        startShowing();
}

void RawConsole::listen(bool on)
{
    // Connected only while on screen: a log with no listener does not wake this thread per frame.
    if (on == bool(m_logListener))
        return;
    if (!on) {
        disconnect(m_logListener);
        m_logListener = {};
        return;
    }
    m_logListener = connect(m_target.trafficLog(), &TrafficLog::entriesAdded, this, [this] {
        if (isOnScreen() && !m_fetchTimer.isActive())
            m_fetchTimer.start();
    });
}

void RawConsole::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    listen(false);
}

void RawConsole::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_target.isDirect() && isOnScreen())
        startShowing();
}

void RawConsole::setOnScreen(bool onScreen)
{
    m_tabShown = onScreen;
    if (m_target.isDirect() && isOnScreen())
        startShowing();
    else if (!isOnScreen())
        listen(false);
}

void RawConsole::startShowing()
{
    m_target.trafficLog()->growCapacity(TrafficLog::fullCapacity);
    listen(true);
    fetch();
}

void RawConsole::setConfirmer(Confirmer confirmer)
{
    m_sendBar->setConfirmer(std::move(confirmer));
}

void RawConsole::setPaused(bool paused)
{
    if (m_pause->isChecked() != paused)
        m_pause->setChecked(paused);
    m_pause->setText(paused ? tr("Resume") : tr("Pause"));
    if (paused)
        m_pausedSinceFetch = true;
    if (!paused)
        fetch();
    else
        ToolPalette::showMessage(
            m_status, tr("Paused: new frames are kept in the log and shown on Resume."), false);
}

bool RawConsole::isPaused() const
{
    return m_pause->isChecked();
}

void RawConsole::fetch()
{
    if (!m_target.isDirect() || isPaused() || !isOnScreen())
        return;
    const QList<TrafficEntry> entries = m_target.trafficLog()->entries(m_lastSequence);
    if (entries.isEmpty())
        return;
    if (entries.first().sequence > m_lastSequence + 1) {
        // Paused, the log went on without the console; closed, it kept only a short log.
        ToolPalette::showMessage(
            m_status,
            m_pausedSinceFetch && m_lastSequence != 0
                ? tr("%1 older frames were dropped from the log while paused.")
                      .arg(entries.first().sequence - m_lastSequence - 1)
                : tr("Older frames were not kept while the console was closed; the newest are "
                     "shown."),
            false);
    } else {
        ToolPalette::showMessage(m_status, {}, false);
    }
    m_pausedSinceFetch = false;
    m_lastSequence = entries.last().sequence;
    m_model->append(entries);
    if (m_followTail)
        m_view->scrollToBottom();
}

void RawConsole::clear()
{
    m_model->clear();
    m_followTail = true;
}

void RawConsole::applyFilters()
{
    const int direction = m_direction->currentData().toInt();
    m_filter->setDirection(direction < 0
                               ? std::nullopt
                               : std::optional(static_cast<TrafficEntry::Direction>(direction)));
    m_filter->setStation(m_stationFilter->value() < 0
                             ? std::nullopt
                             : std::optional(static_cast<quint8>(m_stationFilter->value())));
    const int command = m_command->currentData().toInt();
    m_filter->setCommand(command < 0 ? std::nullopt : std::optional(static_cast<quint8>(command)));
    m_filter->setErrorsOnly(m_errorsOnly->isChecked());
}

QString RawConsole::rowsText(bool selectedOnly) const
{
    QList<int> rows;
    if (selectedOnly) {
        for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
            rows << index.row();
        std::sort(rows.begin(), rows.end());
    } else {
        for (int r = 0; r < m_filter->rowCount(); ++r)
            rows << r;
    }
    QStringList lines;
    for (int r : rows)
        lines << m_model->rowText(m_filter->mapToSource(m_filter->index(r, 0)).row());
    return lines.join(QLatin1Char('\n'));
}

QString RawConsole::copyRows() const
{
    const bool selected = m_view->selectionModel()->hasSelection();
    const QString text = rowsText(selected);
    QApplication::clipboard()->setText(text);
    return text;
}

QString RawConsole::saveToFile(const QString &path) const
{
    QStringList header;
    for (int c = 0; c < TrafficLogModel::ColumnCount; ++c)
        header << m_model->headerData(c, Qt::Horizontal).toString();
    const QByteArray text
        = header.join(QLatin1Char('\t')).toUtf8() + '\n' + rowsText(false).toUtf8() + '\n';
    if (const QString reason = SafeFile::write(path, text); !reason.isEmpty())
        return tr("Cannot write %1: %2").arg(path, reason);
    return {};
}

void RawConsole::save()
{
    const QString path
        = QFileDialog::getSaveFileName(this, tr("Save traffic"), QStringLiteral("traffic.tsv"),
                                       tr("Tab-separated text (*.tsv *.txt)"));
    if (path.isEmpty())
        return;
    const QString error = saveToFile(path);
    ToolPalette::showMessage(m_status, error.isEmpty() ? tr("Saved to %1.").arg(path) : error,
                             !error.isEmpty());
}

void RawConsole::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::PaletteChange) {
        m_model->setPalette(palette());
        m_view->viewport()->update();
    }
    QWidget::changeEvent(event);
}

} // namespace Fatek
