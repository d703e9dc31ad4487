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
        m_summary
            = tr("%1: %2 · %3 req/s · %4 errors · RTT %5")
                  .arg(c->name(), c->stateText())
                  .arg(c->requestsPerSecond(), 0, 'f', 1)
                  .arg(c->errorCount())
                  .arg(t.answers ? tr("%1 ms").arg(t.rttMeanMs, 0, 'f', 1) : QStringLiteral("–"));
    }
    showSummary(m_summary, c->linkReason().empty()
                               ? c->linkText()
                               : c->linkText() + QLatin1Char('\n') + translated(c->linkReason()));
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
