#include "sessionworker.h"

#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "core/protocol/faconcodec.h"
#include "core/protocol/facondeframer.h"
#include "core/protocol/rawframe.h"
#include "core/transport/transport.h"
#include "crossthreadcall.h"
#include "qtbytes.h"
#include "trafficlog.h"

#include <QRandomGenerator>

#include <algorithm>

namespace Fatek {

SessionWorker::SessionWorker(const LinkSettings &settings, std::shared_ptr<SessionShared> shared,
                             TrafficLog *log)
    : m_settings(settings)
    , m_shared(std::move(shared))
    , m_log(log)
    , m_faconCodec(std::make_unique<FaconCodec>())
    , m_binaryCodec(std::make_unique<BinaryCodec>())
    , m_faconDeframer(std::make_unique<FaconDeframer>())
    , m_binaryDeframer(std::make_unique<BinaryDeframer>(BinaryDeframer::Direction::Response))
{
    if (m_settings.protocol == LinkSettings::ProtocolChoice::Facon)
        setProtocol(Protocol::Facon);
    else if (m_settings.protocol == LinkSettings::ProtocolChoice::Binary)
        setProtocol(Protocol::Binary);

    m_timeoutTimer.setSingleShot(true);
    m_silenceTimer.setSingleShot(true);
    m_reconnectTimer.setSingleShot(true);
    m_timeoutTimer.setTimerType(Qt::PreciseTimer);
    m_silenceTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_timeoutTimer, &QTimer::timeout, this, &SessionWorker::onTimeout);
    connect(&m_silenceTimer, &QTimer::timeout, this, &SessionWorker::proceed);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &SessionWorker::startConnect);
    m_drainTimer.setSingleShot(true);
    connect(&m_drainTimer, &QTimer::timeout, this, [this] {
        closeNow(msg<MsgId::LinkSessionClosedAfterWaiting>(m_drainTimer.interval()));
    });
    // Statistics go out at most 4 times a second, however busy the link.
    m_statsTimer.setInterval(250);
    connect(&m_statsTimer, &QTimer::timeout, this, [this] {
        publishStatistics();
        if (!m_statsDirty)
            return;
        m_statsDirty = false;
        Q_EMIT statisticsChanged(m_statistics);
    });
    m_lastActivity.start();

    m_poller = new Poller(
        [this](const Request &request, const RequestOptions &options,
               std::function<void(const SessionResult &)> done) {
            SessionJob job;
            job.request = request;
            job.priority = Priority::Poll;
            job.fromPoller = true;
            job.options = options;
            job.done = std::move(done);
            enqueue(std::move(job));
        },
        {m_settings.demoteAfter, m_settings.demotionMs}, this);
    connect(m_poller, &Poller::values, this, &SessionWorker::values);
    connect(m_poller, &Poller::stationHealthChanged, this, &SessionWorker::onStationHealth);
    connect(m_poller, &Poller::cycleCompleted, this, [this](double ms) {
        ++m_statistics.pollCycles;
        m_statistics.lastCycleMs = ms;
        statisticsChangedInternally();
        publishStatistics();
    });
    if (m_protocol)
        m_poller->setProtocol(*m_protocol);
}

SessionWorker::~SessionWorker()
{
    // Internal jobs hold callbacks into the poller; drop them before it goes.
    m_userQueue.clear();
    m_backgroundQueue.clear();
    m_pollQueue.clear();
    m_current.reset();
    if (m_transport)
        m_transport->close();
    // The last the thread does with what the Session destroys after it (the traffic log).
    CrossThreadCall::threadEnds(m_shared.get());
}

// ---- link -------------------------------------------------------------------------------------

void SessionWorker::startTimers()
{
    m_statsTimer.start();
}

bool SessionWorker::event(QEvent *event)
{
    return CrossThreadCall::deliver(this, event) || QObject::event(event);
}

void SessionWorker::open()
{
    m_wantOpen = true;
    if (m_state == LinkState::Connecting || m_state == LinkState::Connected)
        return;
    m_reconnectTimer.stop(); // "connect now" during a reconnect backoff
    const Message problem = m_settings.validate();
    if (!problem.empty()) {
        m_wantOpen = false;
        setState(LinkState::Closed, problem);
        return;
    }
    m_backoffMs = m_settings.reconnectMinMs;
    startConnect();
}

void SessionWorker::startConnect()
{
    if (!m_wantOpen)
        return;
    if (!m_transport) {
        m_transport = Transport::create(m_settings, this);
        connect(m_transport, &Transport::opened, this, &SessionWorker::onOpened);
        connect(m_transport, &Transport::disconnected, this, &SessionWorker::onDisconnected);
        connect(m_transport, &Transport::bytesReceived, this, [this](const QByteArray &bytes) {
            // The next query leaves in this turn of the event loop, not in a queued pump().
            m_pumpHeld = true;
            onBytes(bytes);
            m_pumpHeld = false;
            if (std::exchange(m_pumpDue, false))
                pump();
        });
        connect(m_transport, &Transport::allSent, this, &SessionWorker::onAllSent);
    }
    setState(LinkState::Connecting, Message::text(m_transport->describe().toStdString()));
    m_transport->open();
}

void SessionWorker::close(bool drain, std::function<void()> closed)
{
    if (closed)
        m_whenClosed.push_back(std::move(closed));
    m_wantOpen = false;
    m_reconnectTimer.stop();
    const bool linkUp = m_state == LinkState::Connected || m_state == LinkState::Connecting;
    if (!drain || !linkUp || !m_transport) {
        closeNow(msg<MsgId::LinkSessionClosed>());
        return;
    }
    if (!m_closing) {
        // A write the caller was told is accepted must reach the PLC (or fail visibly): it goes
        // before the link does, within a bound so that a dead line cannot hold the close.
        m_closing = true;
        m_poller->setLinkUp(false);
        cancelReadsForClose();
        const int bound = m_shared->closeDrainMs.load();
        const int writes = m_shared->pendingWrites.load();
        if (writes > 0 || m_transport->unsentBytes() > 0)
            m_log->append(TrafficEntry::Direction::Event, {}, msg<MsgId::LogClosing>(),
                          msg<MsgId::LogSendingQueuedWrites>(writes, bound));
        m_drainTimer.start(bound);
    }
    checkDrained();
}

void SessionWorker::cancelReadsForClose()
{
    // Reads and polls are pointless once the link goes: only what changes the PLC is drained.
    // Probes stay: a queued write may wait for the protocol they detect.
    std::vector<SessionJob> cancelled;
    bool writesQueued = false;
    for (auto *queue : {&m_userQueue, &m_backgroundQueue, &m_pollQueue}) {
        std::deque<SessionJob> kept;
        for (auto &job : *queue) {
            if (isWriteJob(job) || job.probe) {
                writesQueued = true;
                kept.push_back(std::move(job));
            } else {
                cancelled.push_back(std::move(job));
            }
        }
        queue->swap(kept);
    }
    for (auto &job : cancelled)
        deliver(job,
                SessionResult::fromError(
                    makeError(ErrorKind::Cancelled, msg<MsgId::LinkSessionClosed>()), {}, job.raw));
    // A read on the wire holds the line only if a write must wait for its answer.
    if (m_current && !writesQueued && !isWriteJob(*m_current) && !m_current->probe
        && !m_awaitingSent)
        finishCurrent(SessionResult::fromError(
            makeError(ErrorKind::Cancelled, msg<MsgId::LinkSessionClosed>()), {}, m_current->raw));
}

void SessionWorker::checkDrained()
{
    if (!m_closing)
        return;
    if (m_current || !m_userQueue.empty() || !m_backgroundQueue.empty() || !m_pollQueue.empty())
        return; // pump() calls again when the job finishes
    if (m_transport && m_transport->isOpen() && m_transport->unsentBytes() > 0)
        return; // allSent() calls again
    closeNow(msg<MsgId::LinkSessionClosed>());
}

void SessionWorker::closeNow(const Message &reason)
{
    m_closing = false;
    m_awaitingSent = false;
    m_wantOpen = false;
    m_drainTimer.stop();
    m_reconnectTimer.stop();
    m_silenceTimer.stop();
    m_timeoutTimer.stop();
    if (m_transport)
        m_transport->close();
    m_poller->setLinkUp(false);
    failAll(ErrorKind::Cancelled, reason, true);
    if (m_state != LinkState::Closed)
        setState(LinkState::Closed, msg<MsgId::LinkClosed>());
    const auto whenClosed = std::exchange(m_whenClosed, {});
    for (const auto &callback : whenClosed)
        callback();
}

void SessionWorker::onAllSent()
{
    if (m_awaitingSent && m_current) {
        m_awaitingSent = false;
        m_timeoutTimer.stop();
        finishBroadcast();
    }
    checkDrained();
}

void SessionWorker::onOpened()
{
    m_backoffMs = m_settings.reconnectMinMs;
    m_lineQuiet = false;
    setState(LinkState::Connected, Message::text(m_transport->describe().toStdString()));
    m_lastActivity.start();
    m_poller->setLinkUp(true);
    schedulePump();
}

void SessionWorker::onDisconnected(const Message &reason)
{
    if (!m_wantOpen && m_state == LinkState::Closed)
        return; // a late report from a link the user already closed
    if (m_state == LinkState::Connected) {
        ++m_statistics.linkLosses;
        statisticsChangedInternally();
        publishStatistics();
    }
    m_timeoutTimer.stop();
    m_silenceTimer.stop();
    m_poller->setLinkUp(false);
    setState(LinkState::Lost, reason);
    m_log->append(TrafficEntry::Direction::Event, {}, msg<MsgId::LogLinkLost>(), reason);
    failAll(ErrorKind::LinkError, msg<MsgId::LinkLostBecause>(reason), true);
    if (m_wantOpen && m_settings.autoReconnect) {
        // Up to a quarter longer, at random: the links of a gateway (or a studio) that lost
        // their PLCs together do not all come back in the same instant.
        const int delay
            = m_backoffMs
              + static_cast<int>(QRandomGenerator::global()->bounded(m_backoffMs / 4 + 1));
        m_backoffMs = std::min(m_settings.reconnectMaxMs, m_backoffMs * 2);
        setState(LinkState::Reconnecting,
                 msg<MsgId::LinkNextAttempt>(
                     reason, QString::number(delay / 1000.0, 'f', 1).toStdString()));
        m_reconnectTimer.start(delay);
    } else {
        m_wantOpen = false;
        setState(LinkState::Closed, reason);
        if (m_closing || !m_whenClosed.empty())
            closeNow(msg<MsgId::LinkSessionClosed>());
    }
}

void SessionWorker::setState(LinkState state, const Message &reason)
{
    m_state = state;
    m_shared->linkState.store(static_cast<int>(state));
    Q_EMIT linkStateChanged(state, reason);
}

void SessionWorker::setProtocol(Protocol protocol)
{
    const bool changed = !m_protocol || *m_protocol != protocol;
    m_protocol = protocol;
    m_shared->protocol.store(static_cast<int>(protocol));
    if (m_poller && changed)
        m_poller->setProtocol(protocol);
}

const Codec *SessionWorker::codec() const
{
    if (!m_protocol)
        return nullptr;
    return *m_protocol == Protocol::Facon ? m_faconCodec.get() : m_binaryCodec.get();
}

// ---- statistics -------------------------------------------------------------------------------

void SessionWorker::countDeframerNoise()
{
    // Deframers count skipped noise since construction; the statistics want it once.
    const std::size_t total
        = m_faconDeframer->discardedBytes() + m_binaryDeframer->discardedBytes();
    if (total > m_deframerNoise) {
        m_statistics.bytesDiscarded += static_cast<quint64>(total - m_deframerNoise);
        statisticsChangedInternally();
    }
    m_deframerNoise = total;
}

void SessionWorker::countForStation(quint8 station,
                                    const std::function<void(StationStatistics &)> &update)
{
    update(m_statistics.total);
    if (station != 0)
        update(m_statistics.stations[station]);
    statisticsChangedInternally();
}

void SessionWorker::statisticsChangedInternally()
{
    m_statsDirty = true;
    m_sharedStale = true;
}

void SessionWorker::publishStatistics()
{
    // Copied for Session::statistics() once per finished request, not once per counter change;
    // the figures only, not the round-trip windows (docs/performance.md).
    if (!m_sharedStale)
        return;
    m_sharedStale = false;
    const std::lock_guard locker(m_shared->mutex);
    m_shared->statistics.assignFigures(m_statistics);
}

void SessionWorker::resetStatistics()
{
    m_statistics = SessionStatistics();
    statisticsChangedInternally();
    publishStatistics();
}

void SessionWorker::onStationHealth(quint8 station, bool demoted, const QDateTime &nextTry,
                                    int unanswered)
{
    StationStatistics &stats = m_statistics.stations[station];
    stats.demoted = demoted;
    stats.nextTry = nextTry;
    if (demoted) {
        ++stats.demotions;
        ++m_statistics.total.demotions;
        m_log->append(
            TrafficEntry::Direction::Event, {},
            msg<MsgId::LogStationDemoted>(
                station, unanswered,
                nextTry.toLocalTime().toString(QStringLiteral("HH:mm:ss")).toStdString()));
    } else {
        m_log->append(TrafficEntry::Direction::Event, {},
                      msg<MsgId::LogStationAnswersAgain>(station));
    }
    statisticsChangedInternally();
    publishStatistics();
}

void SessionWorker::setWatchList(const QList<WatchEntry> &entries)
{
    m_poller->setWatchList(entries);
}

} // namespace Fatek
