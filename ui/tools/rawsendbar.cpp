#include "rawsendbar.h"

#include "core/protocol/frametext.h"
#include "core/protocol/rawframe.h"
#include "core/session/qtbytes.h"
#include "core/session/requesttracker.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace Fatek {

namespace {

QString asciiOf(const QByteArray &a)
{
    return QString::fromStdString(FrameText::toAscii(bytesOf(a)));
}

} // namespace

RawSendBar::RawSendBar(QWidget *parent)
    : QWidget(parent)
    , m_requests(new RequestTracker(this))
{
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("sendMode"));
    m_mode->addItem(tr("Hex"));
    m_mode->addItem(tr("ASCII"));
    m_input = new QLineEdit(this);
    m_input->setObjectName(QStringLiteral("sendInput"));
    m_input->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_framing = new QCheckBox(this);
    m_framing->setObjectName(QStringLiteral("addFraming"));
    m_framing->setChecked(true);
    m_send = new QPushButton(tr("Send"), this);
    m_send->setObjectName(QStringLiteral("sendButton"));
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("sendResult"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_result->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(m_mode, 0, 0);
    layout->addWidget(m_input, 0, 1);
    layout->addWidget(m_framing, 0, 2);
    layout->addWidget(m_send, 0, 3);
    layout->addWidget(m_result, 1, 0, 1, 4);
    layout->setColumnStretch(1, 1);

    connect(m_send, &QPushButton::clicked, this, &RawSendBar::send);
    connect(m_input, &QLineEdit::returnPressed, this, &RawSendBar::send);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &RawSendBar::updateFramingLabel);
    connect(m_framing, &QCheckBox::toggled, this, &RawSendBar::updateFramingLabel);
    setTarget(PlcTarget());
}

void RawSendBar::setTarget(const PlcTarget &target)
{
    disconnect(m_protocolDetected);
    m_target = target;
    target.aim(m_requests);
    m_requests->forgetPending();
    m_busy = false;
    m_protocolDetected = target.onProtocolDetected(this, [this] { updateFramingLabel(); });
    ToolPalette::showMessage(m_result, target.isDirect() ? QString() : tr("No connection."), false);
    updateFramingLabel();
    updateEnabled();
}

void RawSendBar::setMode(Mode mode)
{
    m_mode->setCurrentIndex(mode == Mode::Hex ? 0 : 1);
}

void RawSendBar::setText(const QString &text)
{
    m_input->setText(text);
}

void RawSendBar::setAddFraming(bool on)
{
    m_framing->setChecked(on);
}

QString RawSendBar::resultText() const
{
    return m_result->text();
}

bool RawSendBar::framingIsFacon() const
{
    return m_target.framing() == Protocol::Facon;
}

void RawSendBar::updateFramingLabel()
{
    const bool facon = framingIsFacon();
    m_framing->setText(facon ? tr("Add STX, LRC, ETX (FACON)")
                             : tr("Add header, length, CRC (binary)"));
    const bool hex = m_mode->currentIndex() == 0;
    if (m_framing->isChecked())
        m_input->setPlaceholderText(
            facon ? (hex ? tr("body in hex, e.g. 30 31 34 30") : tr("body, e.g. 014603R00012"))
                  : (hex ? tr("payload, e.g. 01 46 03 52 00 0C") : tr("payload as ASCII")));
    else
        m_input->setPlaceholderText(hex ? tr("whole frame in hex, e.g. 02 30 31 34 30 43 37 03")
                                        : tr("whole frame, e.g. <STX>0140C7<ETX>"));
}

void RawSendBar::updateEnabled()
{
    m_send->setEnabled(m_target.isDirect() && !m_busy);
}

void RawSendBar::send()
{
    if (!m_target.isDirect() || m_busy)
        return;
    const bool hex = m_mode->currentIndex() == 0;
    const Result<Bytes> typed = FrameText::parse(
        m_input->text().toStdString(), hex ? FrameText::Typed::Hex : FrameText::Typed::Ascii);
    if (!typed) {
        ToolPalette::showMessage(m_result, translated(typed.error().message), true);
        return;
    }
    const bool framing = m_framing->isChecked();
    // The framing the label names is the one the session adds (it frames with RawFrame too), so
    // the frame shown and confirmed is the frame sent.
    const Protocol protocol = framingIsFacon() ? Protocol::Facon : Protocol::Binary;
    const QByteArray frame
        = toQByteArray(RawFrame::frame(*typed, framing ? std::optional(protocol) : std::nullopt));
    // A raw frame can do anything: ask unless it is clearly a command that only reads.
    const auto header = RawFrame::peek(bytesOf(frame));
    const bool harmless = header && isKnownCommand(header->command)
                          && !isWriteCommand(static_cast<Command>(header->command));
    // In operator mode the session refuses it with its own message: no question first.
    if (!harmless && !m_target.isReadOnly()) {
        // Name the command as the PLC manual does ("RUN/STOP control"), with its code.
        const QString what
            = header ? (isKnownCommand(header->command)
                            ? tr("%1 (command %2) to station %3")
                                  .arg(UiText::commandName(static_cast<Command>(header->command)))
                                  .arg(QString::number(header->command, 16).toUpper())
                                  .arg(header->station)
                            : tr("unknown command %1 to station %2")
                                  .arg(QString::number(header->command, 16).toUpper())
                                  .arg(header->station))
                     : tr("an unrecognized frame");
        const QString question = tr("Send %1 (%2) on %3? It may change the PLC.")
                                     .arg(what, asciiOf(frame), ToolConfirmation::target(m_target));
        if (!ToolConfirmation::ask(this, tr("Send raw frame"), question, m_confirmer)) {
            ToolPalette::showMessage(m_result, tr("Cancelled: nothing sent."), false);
            return;
        }
    }
    m_busy = true;
    updateEnabled();
    // "Sending": the session may still refuse it before the wire (operator mode, a link down).
    ToolPalette::showMessage(
        m_result, tr("Sending %1\nwaiting for the answer \u2026").arg(asciiOf(frame)), false);
    // The station the frame is for (the session's statistics); the framing is named, so no
    // auto-detect probe goes first.
    RequestOptions options;
    options.station = m_target.station();
    if (framing)
        options.framing = protocol;
    m_requests->sendRaw(
        toQByteArray(*typed), framing,
        [this, frame](const SessionResult &r) { onAnswer(frame, r); }, options);
}

void RawSendBar::onAnswer(const QByteArray &sent, const SessionResult &result)
{
    m_busy = false;
    updateEnabled();
    if (!result.ok() && result.attempts() == 0) {
        // Refused before the wire: nothing was sent, so no "Sent" line.
        ToolPalette::showMessage(
            m_result, tr("Not sent: %1\n%2").arg(asciiOf(sent), translated(result.errorMessage())),
            true);
        return;
    }
    const QString sentLine = tr("Sent    %1").arg(asciiOf(sent));
    if (!result.ok()) {
        ToolPalette::showMessage(
            m_result, tr("%1\nFailed  %2").arg(sentLine, translated(result.errorMessage())), true);
        return;
    }
    ++m_answers;
    m_lastAnswer = result.rawAnswer();
    const QString meaning = QString::fromStdString(RawFrame::summarize(bytesOf(m_lastAnswer)));
    ToolPalette::showMessage(
        m_result,
        tr("%1\nAnswer  %2\n        %3\nMeaning %4")
            .arg(sentLine, asciiOf(m_lastAnswer),
                 QString::fromStdString(FrameText::toHex(bytesOf(m_lastAnswer))), meaning),
        false);
}

} // namespace Fatek
