#include "plccontrolpanel.h"

#include "core/protocol/plcmodel.h"
#include "core/session/requesttracker.h"
#include "core/session/session.h"
#include "statusindicator.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QFontDatabase>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTime>
#include <QVBoxLayout>

namespace Fatek {

namespace {

// The detail status is only worth re-reading now and then; the lamps follow every tick.
constexpr int detailEveryTicks = 10;

QString hexBytes(const std::vector<std::uint8_t> &bytes)
{
    QStringList parts;
    for (std::uint8_t b : bytes)
        parts << QStringLiteral("%1").arg(b, 2, 16, QLatin1Char('0')).toUpper();
    return parts.join(QLatin1Char(' '));
}

QString count(const std::optional<std::uint16_t> &value)
{
    return value ? QString::number(*value) : QStringLiteral("\u2013");
}

} // namespace

PlcControlPanel::PlcControlPanel(QWidget *parent)
    : QWidget(parent)
    , m_requests(new RequestTracker(this))
{
    auto *layout = new QVBoxLayout(this);

    m_targetLabel = new QLabel(this);
    m_targetLabel->setObjectName(QStringLiteral("targetLabel"));
    layout->addWidget(m_targetLabel);

    auto *statusBox = new QGroupBox(tr("PLC status"), this);
    auto *statusLayout = new QVBoxLayout(statusBox);
    m_modeLabel = new QLabel(statusBox);
    m_modeLabel->setObjectName(QStringLiteral("modeLabel"));
    QFont big = m_modeLabel->font();
    big.setBold(true);
    big.setPointSizeF(big.pointSizeF() * 1.4);
    m_modeLabel->setFont(big);
    statusLayout->addWidget(m_modeLabel);

    struct Flag
    {
        const char *name;
        QString text;
        bool alarm;
    };
    const Flag flags[] = {
        {"running", tr("RUN"), false},
        {"batteryLow", tr("Battery low"), true},
        {"ladderChecksumError", tr("Ladder checksum error"), true},
        {"memoryPack", tr("Memory card / ROM pack"), false},
        {"watchdogError", tr("Watchdog error"), true},
        {"idSet", tr("ID set"), false},
        {"emergencyStop", tr("Emergency stop"), true},
    };
    auto *grid = new QGridLayout;
    int i = 0;
    for (const Flag &flag : flags) {
        auto *indicator = new StatusIndicator(flag.text, flag.alarm, statusBox);
        indicator->setObjectName(QLatin1String(flag.name));
        m_indicators << indicator;
        grid->addWidget(indicator, i / 2, i % 2);
        ++i;
    }
    statusLayout->addLayout(grid);

    auto *buttons = new QHBoxLayout;
    m_runButton = new QPushButton(tr("RUN"), statusBox);
    m_runButton->setObjectName(QStringLiteral("runButton"));
    m_stopButton = new QPushButton(tr("STOP"), statusBox);
    m_stopButton->setObjectName(QStringLiteral("stopButton"));
    m_refreshButton = new QPushButton(tr("Refresh"), statusBox);
    m_refreshButton->setObjectName(QStringLiteral("refreshButton"));
    buttons->addWidget(m_runButton);
    buttons->addWidget(m_stopButton);
    buttons->addStretch(1);
    buttons->addWidget(m_refreshButton);
    statusLayout->addLayout(buttons);

    m_outcomeLabel = new QLabel(statusBox);
    m_outcomeLabel->setObjectName(QStringLiteral("outcomeLabel"));
    m_outcomeLabel->setWordWrap(true);
    m_outcomeLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    statusLayout->addWidget(m_outcomeLabel);
    m_refreshLabel = new QLabel(statusBox);
    m_refreshLabel->setObjectName(QStringLiteral("refreshLabel"));
    m_refreshLabel->setWordWrap(true);
    statusLayout->addWidget(m_refreshLabel);
    layout->addWidget(statusBox);

    auto *detailBox = new QGroupBox(tr("Detail status (53)"), this);
    m_detailForm = new QFormLayout(detailBox);
    m_model = addDetailRow(tr("Model:"));
    m_io = addDetailRow(tr("I/O points:"));
    m_os = addDetailRow(tr("OS version:"));
    m_program = addDetailRow(tr("Program size:"));
    m_discretes = addDetailRow(tr("Digital inputs / outputs:"));
    m_analog = addDetailRow(tr("Analog inputs / outputs:"));
    m_relays = addDetailRow(tr("M / S / L relays:"));
    m_registers = addDetailRow(tr("R / D registers:"));
    m_timersCounters = addDetailRow(tr("Timers / counters:"));
    m_raw = addDetailRow(tr("Raw bytes:"));
    m_raw->setObjectName(QStringLiteral("rawDetail"));
    m_raw->setWordWrap(true);
    m_raw->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(detailBox);
    layout->addStretch(1);

    connect(m_runButton, &QPushButton::clicked, this, &PlcControlPanel::requestRun);
    connect(m_stopButton, &QPushButton::clicked, this, &PlcControlPanel::requestStop);
    connect(m_refreshButton, &QPushButton::clicked, this, [this] {
        refresh();
        refreshDetail();
    });
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        // A hidden panel (closed dock) must not keep loading a slow bus.
        if (!isVisible())
            return;
        refresh();
        if (++m_ticks % detailEveryTicks == 0)
            refreshDetail();
    });

    // A deleted session leaves the tool in "no connection".
    connect(m_requests, &RequestTracker::sessionDestroyed, this,
            [this] { setTarget(PlcTarget(nullptr, m_target.station(), {})); });
    setTarget(PlcTarget());
}

QLabel *PlcControlPanel::addDetailRow(const QString &label)
{
    auto *value = new QLabel(this);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_detailForm->addRow(label, value);
    return value;
}

void PlcControlPanel::setTarget(const PlcTarget &target)
{
    m_target = target;
    target.aim(m_requests);
    disconnect(m_linkWatch);
    if (Session *session = target.session())
        m_linkWatch
            = connect(session, &Session::linkStateChanged, this, [this] { updateEnabled(); });
    m_requests->forgetPending(); // answers meant for the previous target are ignored
    m_briefPending = m_detailPending = m_modePending = false;
    m_status.reset();
    m_detail.reset();
    m_ticks = 0;
    showStatus(std::nullopt);
    showDetail();
    ToolPalette::showMessage(m_outcomeLabel, {}, false);
    ToolPalette::showMessage(m_refreshLabel, {}, false);
    if (!target.isDirect()) {
        m_targetLabel->setText(tr("No connection: choose a connection and a station."));
        m_timer.stop();
    } else {
        m_targetLabel->setText(
            tr("Station %1 on \u201c%2\u201d").arg(target.station()).arg(target.connectionName()));
        m_timer.start();
        refresh();
        refreshDetail();
    }
    updateEnabled();
}

void PlcControlPanel::setRefreshInterval(int ms)
{
    m_timer.setInterval(ms);
}

QString PlcControlPanel::outcomeText() const
{
    return m_outcomeLabel->text();
}

void PlcControlPanel::updateEnabled()
{
    const bool connected = m_target.isDirect();
    // A link that is down cannot carry RUN/STOP: the buttons wait for it and say why.
    const LinkState link = connected ? m_target.session()->linkState() : LinkState::Closed;
    // Operator mode: the session would refuse RUN/STOP anyway; say so on the buttons.
    const bool writable = connected && link == LinkState::Connected && !m_target.isReadOnly();
    const QString tip
        = !connected || writable ? QString()
          : link != LinkState::Connected
              ? tr("The link is %1: RUN/STOP waits for it to connect.").arg(UiText::linkState(link))
              : tr("Read-only (operator) mode: RUN/STOP is disabled.");
    for (QPushButton *b : {m_runButton, m_stopButton}) {
        b->setEnabled(writable && !m_modePending);
        b->setToolTip(tip);
    }
    m_refreshButton->setEnabled(connected);
}

void PlcControlPanel::refresh()
{
    // One status read in flight at most: a slow link must not pile up requests.
    if (!m_target.isDirect() || m_briefPending)
        return;
    m_briefPending = m_requests->submit(Request::briefStatus(m_target.station()),
                                        [this](const SessionResult &r) { onBriefStatus(r); })
                     != 0;
}

void PlcControlPanel::refreshDetail()
{
    if (!m_target.isDirect() || m_detailPending)
        return;
    m_detailPending = m_requests->submit(Request::detailStatus(m_target.station()),
                                         [this](const SessionResult &r) { onDetailStatus(r); })
                      != 0;
}

void PlcControlPanel::requestRun()
{
    requestMode(true);
}

void PlcControlPanel::requestStop()
{
    requestMode(false);
}

void PlcControlPanel::requestMode(bool run)
{
    if (!m_target.isDirect() || m_modePending)
        return;
    const QString mode = run ? QStringLiteral("RUN") : QStringLiteral("STOP");
    const QString question = tr("Put %1 into %2?").arg(ToolConfirmation::target(m_target), mode);
    if (!ToolConfirmation::ask(this, tr("PLC %1").arg(mode), question, m_confirmer)) {
        ToolPalette::showMessage(m_outcomeLabel, tr("%1 not sent: cancelled.").arg(mode), false);
        return;
    }
    m_modePending = true;
    ToolPalette::showMessage(m_outcomeLabel, tr("Sending %1\u2026").arg(mode), false);
    m_requests->submitChange(
        Request::runStop(m_target.station(), run),
        [this, mode](const ChangeReport &report) {
            if (!report.final) {
                // Sent, not answered: not refused. The status is read back until it tells.
                ToolPalette::showMessage(m_outcomeLabel,
                                         tr("%1: %2").arg(mode, translated(report.message)), true);
                return;
            }
            m_modePending = false;
            switch (report.outcome) {
            case ChangeOutcome::Done:
                ToolPalette::showMessage(
                    m_outcomeLabel,
                    report.message.empty()
                        ? tr("%1 accepted by station %2.").arg(mode).arg(m_target.station())
                        : tr("%1: %2").arg(mode, translated(report.message)),
                    false);
                break;
            case ChangeOutcome::Refused:
                ToolPalette::showMessage(m_outcomeLabel,
                                         tr("%1 refused: %2").arg(mode, translated(report.message)),
                                         true);
                break;
            case ChangeOutcome::Unknown:
                ToolPalette::showMessage(m_outcomeLabel,
                                         tr("%1: %2").arg(mode, translated(report.message)), true);
                break;
            }
            updateEnabled();
            refresh();
            refreshDetail(); // its STATUS1 changes too
        },
        m_target.confirmedNow());
    updateEnabled();
}

void PlcControlPanel::onBriefStatus(const SessionResult &result)
{
    m_briefPending = false;
    if (!result.ok() || result.response().data.empty()) {
        showStatus(std::nullopt);
        ToolPalette::showMessage(m_refreshLabel,
                                 tr("Status unknown: %1")
                                     .arg(result.ok() ? tr("the PLC sent no status bytes.")
                                                      : translated(result.errorMessage())),
                                 true);
        return;
    }
    showStatus(PlcStatus::fromStatus1(result.response().data.front()));
    updateEnabled(); // follows a change of operator mode
    ToolPalette::showMessage(
        m_refreshLabel,
        tr("Status read at %1.").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))),
        false);
}

void PlcControlPanel::onDetailStatus(const SessionResult &result)
{
    m_detailPending = false;
    if (!result.ok()) {
        m_detail.reset();
        showDetail();
        m_raw->setText(tr("Not available: %1").arg(translated(result.errorMessage())));
        return;
    }
    m_detail = DetailStatus::decode(result.response().data);
    showDetail();
}

void PlcControlPanel::showStatus(const std::optional<PlcStatus> &status)
{
    m_status = status;
    using S = StatusIndicator::State;
    auto state = [&](bool on) {
        return !status ? S::Unknown : on ? S::On : S::Off;
    };
    const PlcStatus s = status.value_or(PlcStatus{});
    const bool values[] = {s.running,       s.batteryLow, s.ladderChecksumError, s.memoryPack,
                           s.watchdogError, s.idSet,      s.emergencyStop};
    for (int i = 0; i < m_indicators.size(); ++i)
        m_indicators.at(i)->setState(state(values[i]));
    m_modeLabel->setText(!status ? tr("Mode unknown") : s.running ? tr("RUN") : tr("STOP"));
}

void PlcControlPanel::showDetail()
{
    const QString none = QStringLiteral("\u2013");
    QLabel *const decoded[] = {m_model,  m_io,     m_os,        m_program,       m_discretes,
                               m_analog, m_relays, m_registers, m_timersCounters};
    for (QLabel *label : decoded)
        label->setText(none);
    m_raw->setText(none);
    if (!m_detail)
        return;
    const DetailStatus &d = *m_detail;
    m_raw->setText(d.raw.empty() ? tr("(no bytes)") : hexBytes(d.raw));
    // The binary protocol does not document the 53 answer: only STATUS1 and the raw bytes.
    if (m_target.protocol() == Protocol::Binary) {
        m_model->setText(tr("not documented for the binary protocol (see raw bytes)"));
        return;
    }
    if (const std::optional<std::string> model = d.modelName()) {
        m_model->setText(QString::fromStdString(*model)); // as printed on the unit
    } else if (d.mainUnitType) {
        // A type documented for no FBs unit (an M-series PLC answers 255) is no number to show:
        // the family the answer shows, or that the PLC does not say.
        const std::optional<PlcModel> family = PlcModel::fromDetailStatus(d);
        m_model->setText(*d.mainUnitType == 0   ? tr("main unit MA/MU")
                         : *d.mainUnitType == 1 ? tr("main unit MC")
                         : family && family->family == PlcModel::Family::M
                             ? tr("M series (the unit does not report its type)")
                             : tr("not reported"));
    }
    if (d.ioPointsCode) {
        const std::optional<int> points = d.ioPoints();
        m_io->setText(points ? QString::number(*points) : tr("not reported"));
    }
    if (d.osVersion) {
        const std::optional<std::string> os = d.osVersionText();
        m_os->setText(os ? QString::fromStdString(*os)
                         : tr("code 0x%1").arg(*d.osVersion, 2, 16, QLatin1Char('0')));
    }
    if (d.ladderSize)
        m_program->setText(tr("%1 words").arg(*d.ladderSize));
    auto pair = [&](QLabel *label, const auto &a, const auto &b) {
        if (a || b)
            label->setText(QStringLiteral("%1 / %2").arg(count(a), count(b)));
    };
    pair(m_discretes, d.discreteInputs, d.discreteOutputs);
    pair(m_analog, d.analogInputs, d.analogOutputs);
    if (d.mRelays || d.sRelays || d.lRelays)
        m_relays->setText(QStringLiteral("%1 / %2 / %3")
                              .arg(count(d.mRelays), count(d.sRelays), count(d.lRelays)));
    pair(m_registers, d.rRegisters, d.dRegisters);
    pair(m_timersCounters, d.timers, d.counters);
}

} // namespace Fatek
