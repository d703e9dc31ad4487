#include "loopbackdialog.h"

#include "core/protocol/frametext.h"
#include "core/session/requesttracker.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTextCursor>
#include <QVBoxLayout>

namespace Fatek {

LoopbackDialog::LoopbackDialog(QWidget *parent)
    : QDialog(parent)
    , m_requests(new RequestTracker(this))
    , m_frame(new ToolDialogFrame(this, 2, QStringLiteral("loopbackMessage"), [this] { stop(); }))
{
    setWindowTitle(tr("Loopback test"));
    QVBoxLayout *layout = m_frame->content();

    auto *form = new QFormLayout;
    auto *dataRow = new QHBoxLayout;
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("dataMode"));
    m_mode->addItem(tr("Text"));
    m_mode->addItem(tr("Hex bytes"));
    m_mode->addItem(tr("Generated pattern"));
    m_mode->setCurrentIndex(2);
    // Test data, the same in every language: FACON carries printable ASCII only, and the
    // greyed line (pattern mode) shows no English sentence in a translated window.
    m_text = new QLineEdit(QStringLiteral("FATEK 0123456789"), this);
    m_text->setObjectName(QStringLiteral("dataText"));
    m_length = new QSpinBox(this);
    m_length->setObjectName(QStringLiteral("patternLength"));
    m_length->setRange(0, static_cast<int>(Limits::maxLoopback));
    m_length->setValue(64);
    m_length->setSuffix(tr(" bytes"));
    dataRow->addWidget(m_mode);
    dataRow->addWidget(m_text, 1);
    dataRow->addWidget(m_length);
    form->addRow(tr("Test data:"), dataRow);
    m_repeat = new QSpinBox(this);
    m_repeat->setObjectName(QStringLiteral("repeatCount"));
    m_repeat->setRange(1, 1000000);
    m_repeat->setValue(100);
    form->addRow(tr("Repeat:"), m_repeat);
    m_interval = new QSpinBox(this);
    m_interval->setObjectName(QStringLiteral("interval"));
    m_interval->setRange(0, 60000);
    m_interval->setValue(0);
    m_interval->setSuffix(tr(" ms"));
    form->addRow(tr("Interval:"), m_interval);
    layout->addLayout(form);

    auto *buttons = new QHBoxLayout;
    m_start = new QPushButton(tr("Start"), this);
    m_start->setObjectName(QStringLiteral("startButton"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("stopButton"));
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    buttons->addStretch(1);
    layout->addLayout(buttons);

    m_runs = new QPlainTextEdit(this);
    m_runs->setObjectName(QStringLiteral("runLog"));
    m_runs->setReadOnly(true);
    m_runs->setMaximumBlockCount(5000);
    m_runs->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(m_runs, 1);
    m_totals = new QLabel(this);
    m_totals->setObjectName(QStringLiteral("totals"));
    m_totals->setWordWrap(true);
    m_totals->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_totals);

    connect(m_start, &QPushButton::clicked, this, &LoopbackDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &LoopbackDialog::stop);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &LoopbackDialog::updateControls);
    m_intervalTimer.setSingleShot(true);
    connect(&m_intervalTimer, &QTimer::timeout, this, &LoopbackDialog::runNext);

    // A deleted session leaves the tool in "no connection".
    connect(m_requests, &RequestTracker::sessionDestroyed, this,
            [this] { setTarget(PlcTarget(nullptr, m_frame->target().station(), {})); });
    setTarget(PlcTarget());
}

void LoopbackDialog::setTarget(const PlcTarget &target)
{
    if (m_running)
        finish(tr("Stopped: the target changed."));
    m_frame->setTarget(target);
    target.aim(m_requests);
    m_requests->forgetPending();
    updateControls();
}

void LoopbackDialog::setDataMode(DataMode mode)
{
    m_mode->setCurrentIndex(static_cast<int>(mode));
}

void LoopbackDialog::setData(const QString &text)
{
    m_text->setText(text);
}

void LoopbackDialog::setPatternLength(int bytes)
{
    m_length->setValue(bytes);
}

void LoopbackDialog::setRepeatCount(int runs)
{
    m_repeat->setValue(runs);
}

void LoopbackDialog::setIntervalMs(int ms)
{
    m_interval->setValue(ms);
}

QString LoopbackDialog::messageText() const
{
    return m_frame->messageText();
}

QString LoopbackDialog::totalsText() const
{
    return m_totals->text();
}

void LoopbackDialog::updateControls()
{
    const auto mode = static_cast<DataMode>(m_mode->currentIndex());
    m_text->setEnabled(mode != DataMode::Pattern && !m_running);
    m_length->setEnabled(mode == DataMode::Pattern && !m_running);
    m_mode->setEnabled(!m_running);
    m_repeat->setEnabled(!m_running);
    m_interval->setEnabled(!m_running);
    m_start->setEnabled(m_frame->target().isDirect() && !m_running);
    m_stop->setEnabled(m_running);
}

Result<Bytes> LoopbackDialog::testData() const
{
    const bool binary = m_frame->target().protocol() == Protocol::Binary;
    Bytes bytesOut;
    switch (static_cast<DataMode>(m_mode->currentIndex())) {
    case DataMode::Text: {
        const QByteArray text = m_text->text().toLatin1();
        bytesOut.assign(text.begin(), text.end());
        break;
    }
    case DataMode::Hex: {
        if (m_text->text().trimmed().isEmpty())
            break; // no data is a valid loopback
        Result<Bytes> bytes = FrameText::parseHex(m_text->text().toStdString());
        if (!bytes)
            return bytes.error();
        bytesOut = std::move(bytes).value();
        break;
    }
    case DataMode::Pattern: {
        // Binary links carry every byte value; FACON only printable characters ('!' .. '~').
        const int length = m_length->value();
        for (int i = 0; i < length; ++i)
            bytesOut.push_back(binary ? static_cast<std::uint8_t>(i & 0xFF)
                                      : static_cast<std::uint8_t>(0x21 + i % 94));
        break;
    }
    }
    const Protocol protocol = binary ? Protocol::Binary : Protocol::Facon;
    if (const Status s
        = validateRequest(Request::loopback(m_frame->target().station(), bytesOut), protocol);
        !s)
        return s.error();
    return bytesOut;
}

void LoopbackDialog::start()
{
    if (!m_frame->target().isDirect() || m_running)
        return;
    const Result<Bytes> prepared = testData();
    if (!prepared) {
        m_frame->showMessage(translated(prepared.error().message), true);
        return;
    }
    m_data = *prepared;
    m_stats.reset();
    m_run = 0;
    m_running = true;
    m_runs->clear();
    ToolPalette::showMessage(m_totals, m_stats.summary(), false);
    m_frame->showMessage(tr("Running %1 loopback tests of %2 bytes \u2026")
                             .arg(m_repeat->value())
                             .arg(m_data.size()),
                         false);
    updateControls();
    runNext();
}

void LoopbackDialog::stop()
{
    if (m_running)
        finish(tr("Stopped after %1 runs.").arg(m_stats.runs()));
}

void LoopbackDialog::runNext()
{
    if (!m_running || !m_frame->target().isDirect())
        return;
    const int run = ++m_run;
    auto clock = std::make_shared<QElapsedTimer>();
    clock->start();
    m_requests->submit(Request::loopback(m_frame->target().station(), m_data),
                       [this, run, clock](const SessionResult &r) {
                           onAnswer(run, r, static_cast<double>(clock->nsecsElapsed()) / 1e6);
                       });
}

void LoopbackDialog::onAnswer(int run, const SessionResult &result, double rttMs)
{
    if (!m_running)
        return;
    const QString prefix = QStringLiteral("%1").arg(run, 6);
    if (result.ok() && result.response().data == m_data) {
        m_stats.add(LoopbackStats::Outcome::Success, rttMs);
        appendLine(tr("%1  OK        %2 ms").arg(prefix).arg(rttMs, 0, 'f', 1), false);
    } else if (result.ok()) {
        m_stats.add(LoopbackStats::Outcome::Mismatch, rttMs);
        appendLine(tr("%1  MISMATCH  %2 ms: got %3")
                       .arg(prefix)
                       .arg(rttMs, 0, 'f', 1)
                       .arg(QString::fromStdString(FrameText::toAscii(result.response().data))),
                   true);
    } else if (result.errorKind() == ErrorKind::Timeout) {
        m_stats.add(LoopbackStats::Outcome::Timeout);
        appendLine(tr("%1  TIMEOUT   %2").arg(prefix, translated(result.errorMessage())), true);
    } else {
        m_stats.add(LoopbackStats::Outcome::Error);
        appendLine(tr("%1  ERROR     %2").arg(prefix, translated(result.errorMessage())), true);
    }
    ToolPalette::showMessage(m_totals, m_stats.summary(), m_stats.successes() != m_stats.runs());
    if (m_run >= m_repeat->value()) {
        finish(tr("Done."));
        return;
    }
    // Keep going after an error: a cabling check needs the whole series.
    m_intervalTimer.start(m_interval->value());
}

void LoopbackDialog::appendLine(const QString &line, bool error)
{
    QTextCharFormat format;
    if (error)
        format.setForeground(ToolPalette::errorText(palette()));
    QTextCursor cursor(m_runs->document());
    cursor.movePosition(QTextCursor::End);
    if (!m_runs->document()->isEmpty())
        cursor.insertBlock();
    cursor.insertText(line, format);
    m_runs->ensureCursorVisible();
}

void LoopbackDialog::finish(const QString &why)
{
    m_running = false;
    m_intervalTimer.stop();
    m_requests->forgetPending();
    const bool clean = m_stats.successes() == m_stats.runs();
    m_frame->showMessage(why, false);
    ToolPalette::showMessage(m_totals, m_stats.summary(), !clean);
    updateControls();
}

} // namespace Fatek
