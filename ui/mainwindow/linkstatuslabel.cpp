#include "linkstatuslabel.h"

#include "ui/common/uitext.h"
#include "ui/connection/connection.h"

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
        const int over = fontMetrics().horizontalAdvance(whole) - m_room;
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
    showSummary(m_summary, tip);
}

void LinkStatusLabel::setRoom(int px)
{
    if (px == m_room)
        return;
    m_room = px;
    showSummary(m_summary, m_tip);
}

void LinkStatusLabel::showSummary(const QString &summary, const QString &tip)
{
    m_summary = summary;
    m_tip = tip;
    const QString shown = fontMetrics().elidedText(summary, Qt::ElideRight, m_room);
    setText(shown);
    setToolTip(shown == summary ? tip
               : tip.isEmpty()  ? summary
                                : summary + QLatin1Char('\n') + tip);
}

} // namespace Fatek
