#include "linkstatuslabel.h"

#include "ui/common/uitext.h"
#include "ui/connection/connection.h"

#include <algorithm>

namespace Fatek {

LinkStatusLabel::LinkStatusLabel(QWidget *parent)
    : QLabel(parent)
{
    setObjectName(QStringLiteral("linkStatus"));
    showConnection(nullptr);
}

void LinkStatusLabel::showConnection(const Connection *c)
{
    if (!c) {
        showSummary(tr("No connection"), {});
        return;
    }
    const StationStatistics &t = c->statistics().total;
    QString whole; // the summary before its state gave way
    const LinkState state = c->linkState();
    if (state != LinkState::Connected) {
        // A link that is down has no rate or round trip worth showing: say why and how often.
        QString text = tr("%1: %2").arg(c->name(), c->stateText());
        if (c->linkFailures() > 0)
            text += tr(" · %n failed attempt(s)", nullptr, static_cast<int>(c->linkFailures()));
        if (state == LinkState::Reconnecting || state == LinkState::Lost)
            text += tr(" · F5 reconnects now");
        m_summary = text;
    } else if (c->isGateway()) {
        // The gateway polls; this program only reads the broker: no rate or round trip of its own.
        m_summary = tr("%1: %2 · through the MQTT gateway").arg(c->name(), c->stateText());
    } else {
        const auto summary = [&](const QString &stateWords) {
            return tr("%1: %2 · %3 req/s · %4 errors · RTT %5")
                .arg(c->name(), stateWords)
                .arg(c->requestsPerSecond(), 0, 'f', 1)
                .arg(c->errorCount())
                .arg(t.answers ? tr("%1 ms").arg(t.rttMeanMs, 0, 'f', 1) : QStringLiteral("–"));
        };
        // Too long for its room: the state (its silent stations) gives way, the figures stay.
        const QString words = c->stateText();
        whole = summary(words);
        const int over = fontMetrics().horizontalAdvance(whole) - effectiveRoom();
        m_summary = over <= 0
                        ? whole
                        : summary(fontMetrics().elidedText(
                            words, Qt::ElideRight, fontMetrics().horizontalAdvance(words) - over));
    }
    QString tip = c->linkReason().empty()
                      ? c->linkText()
                      : c->linkText() + QLatin1Char('\n') + translated(c->linkReason());
    if (!whole.isEmpty() && whole != m_summary)
        tip = whole + QLatin1Char('\n') + tip;
    showSummary(m_summary, tip, whole);
}

void LinkStatusLabel::setRoom(int px)
{
    if (px == m_room)
        return;
    m_room = px;
    showElided();
    updateGeometry();
}

void LinkStatusLabel::showSummary(const QString &summary, const QString &tip, const QString &whole)
{
    m_summary = summary;
    m_tip = tip;
    // The label asks for the whole text (what it would show with room enough), not for what it
    // shows now: asking for the shortened text would keep it short.
    const QString wanted = whole.isEmpty() ? summary : whole;
    const bool resize = wanted != m_wanted;
    m_wanted = wanted;
    showElided();
    if (resize)
        updateGeometry();
}

int LinkStatusLabel::effectiveRoom() const
{
    // Before the first layout the label has no width of its own yet: the room decides.
    if (!isVisible())
        return m_room;
    return std::max(0, std::min(m_room, contentsRect().width()));
}

void LinkStatusLabel::showElided()
{
    const QString shown = fontMetrics().elidedText(m_summary, Qt::ElideRight, effectiveRoom());
    if (shown != text())
        setText(shown);
    setToolTip(shown == m_summary ? m_tip
               : m_tip.isEmpty()  ? m_summary
                                  : m_summary + QLatin1Char('\n') + m_tip);
}

QSize LinkStatusLabel::sizeHint() const
{
    const int margins = contentsMargins().left() + contentsMargins().right();
    const int wanted = fontMetrics().horizontalAdvance(m_wanted) + margins + 1;
    return {std::max(0, std::min(wanted, m_room + margins)), QLabel::sizeHint().height()};
}

QSize LinkStatusLabel::minimumSizeHint() const
{
    // Room for a few words and the ellipsis; the rest goes to the message beside it.
    return {std::min(sizeHint().width(), fontMetrics().horizontalAdvance(QLatin1Char('x')) * 12),
            QLabel::minimumSizeHint().height()};
}

void LinkStatusLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    showElided();
}

} // namespace Fatek
