#include "sessionworker.h"

#include "core/transport/transport.h"
#include "crossthreadcall.h"
#include "trafficlog.h"

namespace Fatek {

SessionWorker::SessionWorker(const LinkSettings &settings, std::shared_ptr<SessionShared> shared,
                             TrafficLog *log)
    : m_settings(settings)
    , m_shared(std::move(shared))
    , m_log(log)
    , m_exchange(m_settings, m_link, m_protocol, m_statistics, m_log,
                 {[this](SessionResult result) { finishCurrent(std::move(result)); },
                  [this] { schedulePump(); },
                  [this](const Message &reason) {
                      onDisconnected(reason);
                  }},
                 this)
{
    if (m_settings.protocol == LinkSettings::ProtocolChoice::Facon)
        setProtocol(Protocol::Facon);
    else if (m_settings.protocol == LinkSettings::ProtocolChoice::Binary)
        setProtocol(Protocol::Binary);

    connect(&m_link, &LinkKeeper::stateChanged, this, &SessionWorker::linkStateChanged);
    connect(&m_link, &LinkKeeper::opened, this, &SessionWorker::onOpened);
    connect(&m_link, &LinkKeeper::disconnected, this, &SessionWorker::onDisconnected);
    connect(&m_link, &LinkKeeper::bytesReceived, this, [this](const QByteArray &bytes) {
        // The next query leaves in this turn of the event loop, not in a queued pump().
        m_pumpHeld = true;
        m_exchange.onBytes(bytes);
        m_pumpHeld = false;
        if (std::exchange(m_pumpDue, false))
            pump();
    });
    connect(&m_link, &LinkKeeper::allSent, this, &SessionWorker::onAllSent);
    connect(&m_statistics, &StatisticsKeeper::statisticsChanged, this,
            &SessionWorker::statisticsChanged);
    m_drainTimer.setSingleShot(true);
    connect(&m_drainTimer, &QTimer::timeout, this, [this] {
        closeNow(msg<MsgId::LinkSessionClosedAfterWaiting>(m_drainTimer.interval()));
    });

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
        {m_settings.demoteAfter, m_settings.demotionMs, m_settings.timeoutMs,
         [this] {
             return m_statistics.roundTripP99Ms();
         }},
        this);
    connect(m_poller, &Poller::values, this, &SessionWorker::values);
    connect(m_poller, &Poller::stationHealthChanged, this, &SessionWorker::onStationHealth);
    connect(m_poller, &Poller::effectiveIntervalChanged, this,
            [this](quint8 station, int intervalMs, int effectiveMs) {
                m_log->append(TrafficEntry::Direction::Event, {},
                              effectiveMs > intervalMs
                                  ? msg<MsgId::LogPollSlower>(station, intervalMs, effectiveMs)
                                  : msg<MsgId::LogPollOnTime>(station, intervalMs));
            });
    connect(m_poller, &Poller::cycleCompleted, this, [this](double ms) {
        m_statistics.pollCycle(ms);
        m_statistics.publish();
    });
    if (m_protocol.protocol())
        m_poller->setProtocol(*m_protocol.protocol());
}

SessionWorker::~SessionWorker()
{
    // Internal jobs hold callbacks into the poller; drop them before it goes.
    m_queue.clear();
    m_exchange.abandon();
    if (Transport *transport = m_link.transport())
        transport->close();
    // The last the thread does with what the Session destroys after it (the traffic log).
    CrossThreadCall::threadEnds(m_shared.get());
}

void SessionWorker::startTimers()
{
    m_statistics.startTimer();
}

bool SessionWorker::event(QEvent *event)
{
    return CrossThreadCall::deliver(this, event) || QObject::event(event);
}

// ---- link -------------------------------------------------------------------------------------

void SessionWorker::open()
{
    m_link.open();
}

void SessionWorker::close(bool drain, std::function<void()> closed)
{
    if (closed)
        m_whenClosed.push_back(std::move(closed));
    m_link.unwant();
    const LinkState state = m_link.state();
    const bool linkUp = state == LinkState::Connected || state == LinkState::Connecting;
    if (!drain || !linkUp || !m_link.transport()) {
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
        if (writes > 0 || m_link.transport()->unsentBytes() > 0)
            m_log->append(TrafficEntry::Direction::Event, {}, msg<MsgId::LogClosing>(),
                          msg<MsgId::LogSendingQueuedWrites>(writes, bound));
        m_drainTimer.start(bound);
    }
    checkDrained();
}

void SessionWorker::cancelReadsForClose()
{
    // Reads and polls are pointless once the link goes: only what changes the PLC is drained.
    bool writesQueued = false;
    std::vector<SessionJob> cancelled = m_queue.takeReads(&writesQueued);
    for (auto &job : cancelled)
        deliver(job,
                SessionResult::fromError(
                    makeError(ErrorKind::Cancelled, msg<MsgId::LinkSessionClosed>()), {}, job.raw));
    // A read on the wire holds the line only if a write must wait for its answer.
    const SessionJob *current = m_exchange.current();
    if (current && !writesQueued && !current->isWrite() && !current->probe
        && !m_exchange.isAwaitingSent())
        finishCurrent(SessionResult::fromError(
            makeError(ErrorKind::Cancelled, msg<MsgId::LinkSessionClosed>()), {}, current->raw));
}

void SessionWorker::checkDrained()
{
    if (!m_closing)
        return;
    if (m_exchange.isBusy() || !m_queue.isEmpty())
        return; // pump() calls again when the job finishes
    const Transport *transport = m_link.transport();
    if (transport && transport->isOpen() && transport->unsentBytes() > 0)
        return; // allSent() calls again
    closeNow(msg<MsgId::LinkSessionClosed>());
}

void SessionWorker::closeNow(const Message &reason)
{
    m_closing = false;
    m_drainTimer.stop();
    m_exchange.halt();
    m_link.shutDown();
    m_poller->setLinkUp(false);
    failAll(ErrorKind::Cancelled, reason, true);
    if (m_link.state() != LinkState::Closed)
        m_link.setState(LinkState::Closed, msg<MsgId::LinkClosed>());
    const auto whenClosed = std::exchange(m_whenClosed, {});
    for (const auto &callback : whenClosed)
        callback();
}

void SessionWorker::onAllSent()
{
    m_exchange.onAllSent();
    checkDrained();
}

void SessionWorker::onOpened()
{
    m_exchange.linkOpened();
    m_poller->setLinkUp(true);
    schedulePump();
}

void SessionWorker::onDisconnected(const Message &reason)
{
    if (!m_link.isWanted() && m_link.state() == LinkState::Closed)
        return; // a late report from a link the user already closed
    if (m_link.state() == LinkState::Connected) {
        m_statistics.linkLost();
        m_statistics.publish();
    }
    m_exchange.stopTimers();
    m_poller->setLinkUp(false);
    m_link.setState(LinkState::Lost, reason);
    m_log->append(TrafficEntry::Direction::Event, {}, msg<MsgId::LogLinkLost>(), reason);
    failAll(ErrorKind::LinkError, msg<MsgId::LinkLostBecause>(reason), true);
    if (!m_link.reconnectOrClose(reason) && (m_closing || !m_whenClosed.empty()))
        closeNow(msg<MsgId::LinkSessionClosed>());
}

void SessionWorker::setProtocol(Protocol protocol)
{
    const bool changed = m_protocol.set(protocol);
    if (m_poller && changed)
        m_poller->setProtocol(protocol);
}

// ---- queue ------------------------------------------------------------------------------------

void SessionWorker::enqueue(SessionJob job)
{
    // Operator mode: refuse before anything can reach the wire (checked again when sent, in
    // case the mode changed while the job waited).
    if (m_shared->readOnly.load() && (job.raw || isWriteCommand(job.request.command))) {
        const MessageArg what
            = job.raw ? MessageArg(msg<MsgId::LogRawFrame>()) : MessageArg(job.request.describe());
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::ReadOnly, msg<MsgId::SessionReadOnly>(what)), {},
                         job.raw));
        return;
    }
    if (m_closing) {
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::LinkError, msg<MsgId::SessionLinkClosing>()), {},
                         job.raw));
        return;
    }
    const LinkState state = m_link.state();
    if (state != LinkState::Connected && state != LinkState::Connecting) {
        Message why = state == LinkState::Closed
                          ? msg<MsgId::SessionLinkNotOpen>()
                          : msg<MsgId::SessionLinkDown>(linkStateMessage(state));
        deliver(job, SessionResult::fromError(makeError(ErrorKind::LinkError, std::move(why)), {},
                                              job.raw));
        return;
    }
    if (m_queue.isFull(job)) {
        deliver(job,
                SessionResult::fromError(makeError(ErrorKind::LimitExceeded,
                                                   msg<MsgId::SessionQueueFull>(maxQueuedRequests)),
                                         {}, job.raw));
        return;
    }
    if (!job.pendingWrite && job.isWrite()) {
        job.pendingWrite = true;
        m_shared->pendingWrites.fetch_add(1);
    }
    m_queue.pushBack(std::move(job));
    schedulePump();
}

void SessionWorker::cancel(quint64 id)
{
    if (std::optional<SessionJob> job = m_queue.take(id))
        deliver(*job,
                SessionResult::fromError(
                    makeError(ErrorKind::Cancelled, msg<MsgId::SessionCancelled>()), {}, job->raw));
}

void SessionWorker::failAll(ErrorKind kind, const Message &reason, bool includePolls)
{
    std::vector<SessionJob> jobs;
    if (std::optional<SessionJob> current = m_exchange.abandon())
        jobs.push_back(std::move(*current));
    for (auto &job : m_queue.takeAll(includePolls))
        jobs.push_back(std::move(job));
    for (auto &job : jobs)
        deliver(job, SessionResult::fromError(makeError(kind, reason), {}, job.raw));
}

void SessionWorker::schedulePump()
{
    if (m_pumpHeld || m_inbox.isRunning()) {
        m_pumpDue = true; // pumped when the answer's handling or the batch ends
        return;
    }
    if (m_pumpScheduled)
        return;
    m_pumpScheduled = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_pumpScheduled = false;
            pump();
        },
        Qt::QueuedConnection);
}

void SessionWorker::pump()
{
    while (!m_exchange.isBusy() && m_link.state() == LinkState::Connected) {
        SessionJob job;
        if (!m_queue.takeNext(job)) {
            checkDrained();
            return;
        }
        if (m_closing && !job.isWrite() && !job.probe) {
            // A read that waited for a protocol probe while the link began to close.
            deliver(job,
                    SessionResult::fromError(
                        makeError(ErrorKind::Cancelled, "the session was closed"), {}, job.raw));
            continue;
        }
        if (prepare(job))
            m_exchange.begin(std::move(job));
    }
}

bool SessionWorker::prepare(SessionJob &job)
{
    if (!job.probe && job.options.deadline.hasExpired()) {
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::Expired, msg<MsgId::SessionExpired>()), {}, job.raw));
        return false;
    }
    if (m_shared->readOnly.load() && (job.raw || isWriteCommand(job.request.command))) {
        enqueue(std::move(job)); // refuses it with the read-only message
        return false;
    }
    // A raw frame goes as typed, or in the framing the caller chose: it needs no protocol.
    const bool needsProtocol = !job.raw || (job.addFraming && !job.options.framing);
    if (!m_protocol.protocol() && !job.probe && needsProtocol) {
        // A broadcast has no station to ask: probing station 1 for it would talk to a PLC the
        // broadcast is not about (or to none). Refused here, nothing sent.
        const bool broadcast = job.raw ? job.options.station == Limits::broadcastStation
                                       : job.request.station == Limits::broadcastStation;
        if (broadcast) {
            deliver(job,
                    SessionResult::fromError(makeError(ErrorKind::InvalidRequest,
                                                       msg<MsgId::LinkBroadcastNeedsProtocol>()),
                                             {}, job.raw));
            return false;
        }
        detectProtocol(std::move(job));
        return false;
    }
    if (!job.raw && !job.probe && !job.fromPoller
        && job.request.station != Limits::broadcastStation) {
        // A station the poller found silent: the tools' routine reads (status, forced marks) wait
        // for its next try instead of holding up the line; other requests get one attempt.
        Message resting;
        if (job.priority == Priority::Poll && m_poller->isResting(job.request.station, &resting)) {
            deliver(job, SessionResult::fromError(makeError(ErrorKind::Timeout, resting)));
            return false;
        }
        if (job.options.retries < 0 && m_poller->isSuspect(job.request.station))
            job.options.retries = 0;
    }
    if (!job.raw) {
        const Protocol protocol = job.probe ? *job.probe : *m_protocol.protocol();
        const Status valid = validateRequest(job.request, protocol);
        if (!valid) {
            deliver(job, SessionResult::fromError(valid.error()));
            return false;
        }
    }
    return true;
}

void SessionWorker::detectProtocol(SessionJob job)
{
    const quint8 station = job.station() == 0 ? 1 : job.station();
    SessionProtocol::ProbeHooks hooks;
    hooks.send = [this](SessionJob probe) {
        m_queue.pushFront(std::move(probe));
        schedulePump();
    };
    hooks.detected = [this](Protocol protocol, SessionJob &waiting) {
        setProtocol(protocol);
        m_log->append(TrafficEntry::Direction::Event, {},
                      msg<MsgId::LogProtocolDetected>(protocolName(protocol)));
        Q_EMIT protocolDetected(protocol);
        m_queue.pushFront(std::move(waiting));
        schedulePump();
    };
    hooks.failed = [this](SessionJob &waiting, SessionResult result) {
        deliver(waiting, std::move(result));
    };
    SessionProtocol::detect(std::move(job), station, std::move(hooks));
}

void SessionWorker::finishCurrent(SessionResult result)
{
    SessionJob job = m_exchange.end();
    result.setAttempts(job.attempts);
    if (!job.probe)
        m_statistics.count(job.station(), [](StationStatistics &s) { ++s.requests; });
    // Probes count too: with auto-detect a silent station never gets past them.
    if (!job.raw && !result.ok() && result.errorKind() == ErrorKind::Timeout)
        m_statistics.count(job.station(), [](StationStatistics &s) { ++s.unanswered; });
    if (!job.raw && !job.probe && !job.fromPoller
        && job.request.station != Limits::broadcastStation)
        m_poller->noteAnswer(job.request.station, result);
    m_statistics.publish(); // before the result, so statistics() already counts it
    deliver(job, std::move(result));
    schedulePump();
}

void SessionWorker::deliver(SessionJob &job, SessionResult result)
{
    if (job.pendingWrite) {
        job.pendingWrite = false;
        m_shared->pendingWrites.fetch_sub(1);
    }
    // Also when a job on the wire is cut off (link lost, close): its frame may have been acted on.
    result.setAttempts(job.attempts);
    if (job.done) {
        auto done = std::move(job.done);
        done(result);
    } else if (job.id != 0) {
        Q_EMIT finished(job.id, result);
    }
}

// ---- statistics -------------------------------------------------------------------------------

void SessionWorker::resetStatistics()
{
    m_statistics.reset();
    m_statistics.publish();
}

void SessionWorker::onStationHealth(quint8 station, bool demoted, const QDateTime &nextTry,
                                    int unanswered)
{
    m_statistics.stationHealth(station, demoted, nextTry);
    if (demoted) {
        m_log->append(
            TrafficEntry::Direction::Event, {},
            msg<MsgId::LogStationDemoted>(
                station, unanswered,
                nextTry.toLocalTime().toString(QStringLiteral("HH:mm:ss")).toStdString()));
    } else {
        m_log->append(TrafficEntry::Direction::Event, {},
                      msg<MsgId::LogStationAnswersAgain>(station));
    }
    m_statistics.publish();
}

void SessionWorker::setWatchList(const QList<WatchEntry> &entries)
{
    m_poller->setWatchList(entries);
}

} // namespace Fatek
