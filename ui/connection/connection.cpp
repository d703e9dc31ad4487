#include "connection.h"

#include "core/protocol/plcmodel.h"
#include "core/session/requesttracker.h"
#include "core/session/session.h"
#include "ui/common/uitext.h"

#include <QSet>

namespace Fatek {

Connection::Connection(const SavedConnection &saved, QObject *parent)
    : QObject(parent)
    , m_saved(saved)
{
    // Requests per second over the last second; a timer so the rate falls to 0 when idle.
    m_rateTimer.setInterval(1000);
    connect(&m_rateTimer, &QTimer::timeout, this, &Connection::updateRate);
    m_rateClock.start();
    // The session's count starts at 0 with the link: the first second already has a rate.
    m_rateSamples.emplace_back(0, 0);
    // The saved connection says which kind of link (PlantConnection makes it).
    m_plant = saved.gateway ? PlantConnection::throughGateway(*saved.gateway, this)
                            : PlantConnection::direct(saved.settings, {}, this);
    m_link = m_plant->link();
    m_session = m_link->session();
    connect(m_plant, &PlantConnection::linkStateChanged, this, &Connection::onLinkState);
    connect(m_plant, &PlantConnection::valuesArrived, this, &Connection::itemValues);
    connect(m_plant, &PlantConnection::statisticsChanged, this,
            [this](const SessionStatistics &statistics) {
                m_statistics = statistics;
                Q_EMIT changed();
            });
    if (!m_session)
        return;
    // What the PLC says it is, and its RUN/STOP state: asked through its own session.
    m_plcRequests = new RequestTracker(this);
    m_plcRequests->setSession(m_session);
    m_statusTimer.setInterval(plcStatusIntervalMs);
    connect(&m_statusTimer, &QTimer::timeout, this, &Connection::readStatus);
    m_rateTimer.start();
}

void Connection::onLinkState(LinkState state, const Message &reason)
{
    const bool cameUp = state == LinkState::Connected && m_state != state;
    m_state = state;
    if (m_session && cameUp) {
        readIdentity();
        m_statusTimer.start();
    } else if (m_session && state != LinkState::Connected) {
        // Down: RUN/STOP is unknown, not "the last we saw".
        m_statusTimer.stop();
        m_plcRequests->forgetPending();
        m_statusPending = false;
        m_plcStatus.reset();
    }
    Q_EMIT linkStateChanged(state, reason);
    Q_EMIT changed();
}

Connection::~Connection()
{
    // The session's destructor stops its thread; nothing may poll into a half-destroyed object.
    disconnect(m_plant, nullptr, this, nullptr);
}

void Connection::setStation(quint8 station)
{
    if (m_saved.station == station)
        return;
    m_saved.station = station;
    // Another station is another PLC: forget what the last one said and ask this one.
    m_detail.reset();
    m_plcStatus.reset();
    m_statusPending = false;
    if (m_session) {
        m_plcRequests->forgetPending();
        if (m_state == LinkState::Connected)
            readIdentity();
    }
    Q_EMIT changed();
}

quint64 Connection::errorCount() const
{
    const StationStatistics &t = m_statistics.total;
    return t.timeouts + t.checksumErrors + t.plcErrors + m_plant->linkFailures();
}

QList<quint8> Connection::silentStations() const
{
    QList<quint8> silent;
    if (linkState() != LinkState::Connected)
        return silent; // a link that is down says so itself
    // Only stations someone uses: a station scan leaves every empty address unanswered.
    QSet<quint8> used = m_plant->watchedStations();
    used.insert(m_saved.station);
    for (auto it = m_statistics.stations.cbegin(); it != m_statistics.stations.cend(); ++it) {
        if (it.value().unanswered > 0 && it.key() != 0 && used.contains(it.key()))
            silent << it.key();
    }
    return silent;
}

QString Connection::stateText() const
{
    const QString state = UiText::linkState(linkState());
    const QList<quint8> silent = silentStations();
    if (silent.isEmpty())
        return state;
    QStringList numbers;
    QStringList demoted;
    for (quint8 s : silent) {
        const StationStatistics station = m_statistics.stations.value(s);
        if (station.demoted && station.nextTry.isValid())
            demoted << tr("station %1 rests until %2")
                           .arg(s)
                           .arg(station.nextTry.toLocalTime().toString(QStringLiteral("HH:mm:ss")));
        numbers << QString::number(s);
    }
    QString text
        = tr("%1, no answer from station %2").arg(state, numbers.join(QStringLiteral(", ")));
    if (!demoted.isEmpty())
        text += QStringLiteral(" (%1)").arg(demoted.join(QStringLiteral(", ")));
    return text;
}

QString Connection::plcText() const
{
    if (!m_session)
        return m_link->peerText(); // what the far end talks to
    QStringList parts;
    if (m_detail) {
        // A PLC without a documented model name (the M series) is named by its family.
        const std::optional<PlcModel> family = PlcModel::fromDetailStatus(*m_detail);
        if (const std::optional<std::string> model = m_detail->modelName())
            parts << QString::fromStdString(*model);
        else if (family && family->family == PlcModel::Family::M)
            parts << tr("M series");
    }
    if (m_plcStatus)
        parts << (m_plcStatus->running ? tr("RUN") : tr("STOP"));
    return parts.join(QStringLiteral(" · "));
}

void Connection::readIdentity()
{
    const quint8 station = m_saved.station;
    m_statusPending = true;
    m_plcRequests->submit(
        Request::detailStatus(station),
        [this, station](const SessionResult &result) {
            m_statusPending = false;
            if (station != m_saved.station || !result.ok())
                return; // a silent station shows as such; the status timer asks again
            const DetailStatus detail = DetailStatus::decode(result.response().data);
            m_detail = detail;
            m_plcStatus = detail.status;
            Q_EMIT changed();
        },
        {}, Priority::Poll);
}

void Connection::readStatus()
{
    if (m_statusPending || m_state != LinkState::Connected)
        return; // one question at a time, whatever the line's speed
    if (!m_detail) {
        readIdentity();
        return;
    }
    const quint8 station = m_saved.station;
    m_statusPending = true;
    m_plcRequests->submit(
        Request::briefStatus(station),
        [this, station](const SessionResult &result) {
            m_statusPending = false;
            if (station != m_saved.station)
                return;
            std::optional<PlcStatus> status;
            if (result.ok() && !result.response().data.empty())
                status = PlcStatus::fromStatus1(result.response().data.front());
            if (status != m_plcStatus) {
                m_plcStatus = status;
                Q_EMIT changed();
            }
        },
        {}, Priority::Poll);
}

void Connection::open()
{
    m_plant->open();
}

void Connection::reconnectNow()
{
    if (m_state == LinkState::Connected || m_state == LinkState::Connecting)
        return;
    m_plant->reconnectNow();
}

void Connection::close()
{
    m_plant->close();
}

void Connection::closeDiscard()
{
    m_plant->close(CloseMode::Discard);
}

void Connection::setReadOnly(bool readOnly)
{
    m_link->setReadOnly(readOnly);
}

bool Connection::isReadOnly() const
{
    return m_link->isReadOnly();
}

int Connection::pendingWrites() const
{
    return m_link->pendingWrites();
}

int Connection::closeDrainMs() const
{
    return m_link->closeDrainMs();
}

void Connection::updateRate()
{
    // Over the last 3 s, not 1: the counts arrive in 250 ms reports, so a 1 s window would show
    // a line polled twice a second as 1.0 one second and 3.0 the next.
    constexpr qint64 rateWindowMs = 3000;
    const qint64 now = m_rateClock.elapsed();
    m_rateSamples.emplace_back(now, m_statistics.total.requests);
    while (m_rateSamples.size() > 2 && now - m_rateSamples[1].first >= rateWindowMs)
        m_rateSamples.pop_front();
    const auto &[since, requestsThen] = m_rateSamples.front();
    const quint64 requests = m_rateSamples.back().second;
    const quint64 delta = requests >= requestsThen ? requests - requestsThen : 0;
    const qint64 ms = now - since;
    const double rate
        = ms > 0 ? static_cast<double>(delta) * 1000.0 / static_cast<double>(ms) : 0.0;
    if (rate != m_rate) {
        m_rate = rate;
        Q_EMIT changed();
    }
}

} // namespace Fatek
