#include "stationscandialog.h"

#include "core/session/stationscanner.h"

#include <algorithm>

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace Fatek {

StationScanDialog::StationScanDialog(const PlcTarget &target, QWidget *parent)
    : QDialog(parent)
    , m_target(target)
{
    setObjectName(QStringLiteral("stationScanDialog"));
    setWindowTitle(tr("Scan Stations"));
    auto *layout = new QVBoxLayout(this);
    auto *about = new QLabel(
        target.link() ? tr("Asks each station on \u201c%1\u201d for its status (command 40), "
                           "one at a time, and lists who answers.")
                            .arg(target.connectionName())
                      : tr("No connection: open one first."),
        this);
    about->setWordWrap(true);
    layout->addWidget(about);

    auto *form = new QFormLayout;
    auto *range = new QHBoxLayout;
    m_first = new QSpinBox(this);
    m_first->setObjectName(QStringLiteral("firstStation"));
    m_first->setRange(1, 254);
    m_first->setValue(1);
    m_last = new QSpinBox(this);
    m_last->setObjectName(QStringLiteral("lastStation"));
    m_last->setRange(1, 254);
    m_last->setValue(32);
    range->addWidget(m_first);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_last);
    range->addStretch(1);
    form->addRow(tr("Stations:"), range);
    m_timeout = new QSpinBox(this);
    m_timeout->setObjectName(QStringLiteral("scanTimeout"));
    m_timeout->setRange(20, 5000);
    m_timeout->setSingleStep(50);
    m_timeout->setSuffix(tr(" ms"));
    m_timeout->setValue(100);
    m_timeout->setToolTip(tr("How long each station has to answer (no retries). 100 ms suits "
                             "9600 baud and above; a modem or radio link needs more."));
    form->addRow(tr("Wait per station:"), m_timeout);
    layout->addLayout(form);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("scanProgress"));
    m_progress->setValue(0);
    layout->addWidget(m_progress);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("stationList"));
    layout->addWidget(m_list, 1);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("scanStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_start = buttons->addButton(tr("&Scan"), QDialogButtonBox::ActionRole);
    m_start->setObjectName(QStringLiteral("scanButton"));
    m_use = buttons->addButton(tr("&Use Station"), QDialogButtonBox::ActionRole);
    m_use->setObjectName(QStringLiteral("useStationButton"));
    m_use->setToolTip(tr("Make the selected station the one the tools and new tables use"));
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_start, &QPushButton::clicked, this, [this] {
        if (isScanning()) {
            m_scanner->cancel();
            return;
        }
        start();
    });
    connect(m_use, &QPushButton::clicked, this, &StationScanDialog::useSelected);
    connect(m_list, &QListWidget::itemDoubleClicked, this, &StationScanDialog::useSelected);
    connect(m_list, &QListWidget::itemSelectionChanged, this, &StationScanDialog::updateButtons);

    // A gateway connection has no link of its own to scan (ToolDocks does not open this on one).
    if (target.isDirect()) {
        m_scanner = new StationScanner(target.session(), this);
        connect(
            m_scanner, &StationScanner::stationFound, this,
            [this](const StationScanner::Hit &hit) { onFound(hit.station, hit.status.running); });
        connect(m_scanner, &StationScanner::progress, this, [this](int done, int total) {
            m_progress->setMaximum(total);
            m_progress->setValue(done);
        });
        connect(m_scanner, &StationScanner::finished, this, &StationScanDialog::onFinished);
    }
    updateButtons();
}

bool StationScanDialog::isScanning() const
{
    return m_scanner && m_scanner->isRunning();
}

QList<int> StationScanDialog::foundStations() const
{
    QList<int> stations;
    for (int i = 0; i < m_list->count(); ++i)
        stations << m_list->item(i)->data(Qt::UserRole).toInt();
    return stations;
}

void StationScanDialog::start()
{
    if (!m_scanner || !m_target.isDirect())
        return;
    const int first = std::min(m_first->value(), m_last->value());
    const int last = std::max(m_first->value(), m_last->value());
    m_list->clear();
    m_progress->setRange(0, last - first + 1);
    m_progress->setValue(0);
    m_status->setText(tr("Scanning stations %1 to %2 \u2026").arg(first).arg(last));
    m_scanner->start(first, last, m_timeout->value());
    updateButtons();
}

void StationScanDialog::onFound(int station, bool running)
{
    auto *item = new QListWidgetItem(
        tr("Station %1 \u2014 %2").arg(station).arg(running ? tr("RUN") : tr("STOP")), m_list);
    item->setData(Qt::UserRole, station);
    if (station == m_target.station())
        item->setText(item->text() + tr(" (in use)"));
}

void StationScanDialog::onFinished()
{
    const int found = m_list->count();
    m_status->setText(found == 0 ? tr("No station answered. Check the cable, the baud rate and "
                                      "parity, and that the PLCs are powered.")
                                 : tr("%n station(s) answered.", nullptr, found));
    if (found > 0 && m_list->selectedItems().isEmpty())
        m_list->setCurrentRow(0);
    updateButtons();
}

void StationScanDialog::useSelected()
{
    const QList<QListWidgetItem *> selected = m_list->selectedItems();
    if (selected.isEmpty() || !m_target.link())
        return;
    const int station = selected.first()->data(Qt::UserRole).toInt();
    m_target = PlcTarget(m_target.link(), static_cast<quint8>(station), m_target.connectionName());
    Q_EMIT stationChosen(static_cast<quint8>(station));
    m_status->setText(
        tr("\u201c%1\u201d now uses station %2.").arg(m_target.connectionName()).arg(station));
}

void StationScanDialog::updateButtons()
{
    const bool scanning = isScanning();
    m_start->setText(scanning ? tr("&Cancel Scan") : tr("&Scan"));
    m_start->setEnabled(m_target.link() != nullptr);
    m_use->setEnabled(!scanning && !m_list->selectedItems().isEmpty());
    m_first->setEnabled(!scanning);
    m_last->setEnabled(!scanning);
    m_timeout->setEnabled(!scanning);
}

} // namespace Fatek
