#include "sessionworker.h"

#include "binarycodec.h"
#include "binarydeframer.h"
#include "crossthreadcall.h"
#include "faconcodec.h"
#include "facondeframer.h"
#include "rawframe.h"
#include "trafficlog.h"
#include "transport.h"

#include <algorithm>

namespace Fatek {

namespace {

std::string toStd(const QString &text)
{
    return text.toStdString();
}

std::span<const std::uint8_t> bytesOf(const QByteArray &bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()),
            static_cast<std::size_t>(bytes.size())};
}

QByteArray toQByteArray(const Bytes &bytes)
{
    return QByteArray(reinterpret_cast<const char *>(bytes.data()),
                      static_cast<qsizetype>(bytes.size()));
}

} // namespace

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
        closeNow(QStringLiteral("the session was closed after waiting %1 ms for queued writes")
                     .arg(m_drainTimer.interval()));
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
        [this](const Request &request, std::function<void(const SessionResult &)> done) {
            SessionJob job;
            job.request = request;
            job.priority = Priority::Poll;
            job.done = std::move(done);
            enqueue(std::move(job));
        },
        this);
    connect(m_poller, &Poller::values, this, &SessionWorker::values);
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
    const QString problem = m_settings.validate();
    if (!problem.isEmpty()) {
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
        connect(m_transport, &Transport::bytesReceived, this, &SessionWorker::onBytes);
        connect(m_transport, &Transport::allSent, this, &SessionWorker::onAllSent);
    }
    setState(LinkState::Connecting, m_transport->describe());
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
        closeNow(QStringLiteral("the session was closed"));
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
            m_log->append(TrafficEntry::Direction::Event, {}, QStringLiteral("closing"),
                          QStringLiteral("sending %1 queued write(s) first, at most %2 ms")
                              .arg(writes)
                              .arg(bound));
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
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::Cancelled, "the session was closed"), {}, job.raw));
    // A read on the wire holds the line only if a write must wait for its answer.
    if (m_current && !writesQueued && !isWriteJob(*m_current) && !m_current->probe
        && !m_awaitingSent)
        finishCurrent(SessionResult::fromError(
            makeError(ErrorKind::Cancelled, "the session was closed"), {}, m_current->raw));
}

void SessionWorker::checkDrained()
{
    if (!m_closing)
        return;
    if (m_current || !m_userQueue.empty() || !m_backgroundQueue.empty() || !m_pollQueue.empty())
        return; // pump() calls again when the job finishes
    if (m_transport && m_transport->isOpen() && m_transport->unsentBytes() > 0)
        return; // allSent() calls again
    closeNow(QStringLiteral("the session was closed"));
}

void SessionWorker::closeNow(const QString &reason)
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
        setState(LinkState::Closed, QStringLiteral("closed"));
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
    setState(LinkState::Connected, m_transport->describe());
    m_lastActivity.start();
    m_poller->setLinkUp(true);
    schedulePump();
}

void SessionWorker::onDisconnected(const QString &reason)
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
    m_log->append(TrafficEntry::Direction::Event, {}, QStringLiteral("link lost"), reason);
    failAll(ErrorKind::LinkError, QStringLiteral("link lost: %1").arg(reason), true);
    if (m_wantOpen && m_settings.autoReconnect) {
        const int delay = m_backoffMs;
        m_backoffMs = std::min(m_settings.reconnectMaxMs, m_backoffMs * 2);
        setState(
            LinkState::Reconnecting,
            QStringLiteral("%1; next attempt in %2 s").arg(reason).arg(delay / 1000.0, 0, 'f', 1));
        m_reconnectTimer.start(delay);
    } else {
        m_wantOpen = false;
        setState(LinkState::Closed, reason);
        if (m_closing || !m_whenClosed.empty())
            closeNow(QStringLiteral("the session was closed"));
    }
}

void SessionWorker::setState(LinkState state, const QString &reason)
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

// ---- queue ------------------------------------------------------------------------------------

std::deque<SessionJob> &SessionWorker::queueFor(Priority priority)
{
    switch (priority) {
    case Priority::User: return m_userQueue;
    case Priority::Background: return m_backgroundQueue;
    case Priority::Poll: return m_pollQueue;
    }
    return m_userQueue;
}

void SessionWorker::enqueue(SessionJob job)
{
    // Operator mode: refuse before anything can reach the wire (checked again when sent, in
    // case the mode changed while the job waited).
    if (m_shared->readOnly.load() && (job.raw || isWriteCommand(job.request.command))) {
        const QString what = job.raw ? QStringLiteral("raw frame")
                                     : QString::fromStdString(job.request.describe());
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::ReadOnly,
                                   toStd(QStringLiteral("Read-only mode: \"%1\" was not sent. "
                                                        "Leave operator mode to change the PLC.")
                                             .arg(what))),
                         {}, job.raw));
        return;
    }
    if (m_closing) {
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::LinkError, "Not sent: the link is closing."), {},
                         job.raw));
        return;
    }
    if (m_state != LinkState::Connected && m_state != LinkState::Connecting) {
        const QString why
            = m_state == LinkState::Closed
                  ? QStringLiteral("the link is not open")
                  : QStringLiteral("the link is down (%1)").arg(linkStateName(m_state));
        deliver(job,
                SessionResult::fromError(makeError(ErrorKind::LinkError,
                                                   toStd(QStringLiteral("Not sent: %1.").arg(why))),
                                         {}, job.raw));
        return;
    }
    std::deque<SessionJob> &queue = queueFor(job.priority);
    // A caller that submits faster than the link answers must not grow memory without end. The
    // poll queue holds at most one cycle per group and is not capped here.
    if (job.priority != Priority::Poll && queue.size() >= maxQueuedRequests) {
        deliver(job, SessionResult::fromError(
                         makeError(ErrorKind::LimitExceeded,
                                   toStd(QStringLiteral("Not sent: %1 requests are already "
                                                        "waiting on this link (the PLC answers "
                                                        "slower than requests arrive).")
                                             .arg(maxQueuedRequests))),
                         {}, job.raw));
        return;
    }
    if (!job.pendingWrite && isWriteJob(job)) {
        job.pendingWrite = true;
        m_shared->pendingWrites.fetch_add(1);
    }
    queue.push_back(std::move(job));
    schedulePump();
}

bool SessionWorker::isWriteJob(const SessionJob &job)
{
    return !job.probe && (job.raw || isWriteCommand(job.request.command));
}

void SessionWorker::cancel(quint64 id)
{
    for (auto *queue : {&m_userQueue, &m_backgroundQueue, &m_pollQueue}) {
        auto it = std::find_if(queue->begin(), queue->end(),
                               [id](const SessionJob &job) { return job.id == id; });
        if (it != queue->end()) {
            SessionJob job = std::move(*it);
            queue->erase(it);
            deliver(job, SessionResult::fromError(
                             makeError(ErrorKind::Cancelled, "Cancelled before it was sent."), {},
                             job.raw));
            return;
        }
    }
}

bool SessionWorker::takeNext(SessionJob &job)
{
    for (auto *queue : {&m_userQueue, &m_backgroundQueue, &m_pollQueue}) {
        if (!queue->empty()) {
            job = std::move(queue->front());
            queue->pop_front();
            return true;
        }
    }
    return false;
}

void SessionWorker::failAll(ErrorKind kind, const QString &reason, bool includePolls)
{
    std::vector<SessionJob> jobs;
    if (m_current) {
        jobs.push_back(std::move(*m_current));
        m_current.reset();
    }
    for (auto *queue : {&m_userQueue, &m_backgroundQueue, &m_pollQueue}) {
        if (queue == &m_pollQueue && !includePolls)
            continue;
        for (auto &job : *queue)
            jobs.push_back(std::move(job));
        queue->clear();
    }
    for (auto &job : jobs)
        deliver(job, SessionResult::fromError(makeError(kind, toStd(reason)), {}, job.raw));
}

void SessionWorker::schedulePump()
{
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
    while (!m_current && m_state == LinkState::Connected) {
        SessionJob job;
        if (!takeNext(job)) {
            checkDrained();
            return;
        }
        if (m_closing && !isWriteJob(job) && !job.probe) {
            // A read that waited for a protocol probe while the link began to close.
            deliver(job,
                    SessionResult::fromError(
                        makeError(ErrorKind::Cancelled, "the session was closed"), {}, job.raw));
            continue;
        }
        if (prepare(job)) {
            m_current = std::move(job);
            proceed();
        }
    }
}

bool SessionWorker::prepare(SessionJob &job)
{
    if (m_shared->readOnly.load() && (job.raw || isWriteCommand(job.request.command))) {
        enqueue(std::move(job)); // refuses it with the read-only message
        return false;
    }
    // A raw frame goes as typed, or in the framing the caller chose: it needs no protocol.
    const bool needsProtocol = !job.raw || (job.addFraming && !job.options.framing);
    if (!m_protocol && !job.probe && needsProtocol) {
        // Auto-detect: ask the job's station for its status in FACON, then binary.
        const quint8 station = stationOf(job) == 0 ? 1 : stationOf(job);
        auto waiting = std::make_shared<SessionJob>(std::move(job));
        using ProbeFn = std::function<void(Protocol)>;
        auto probeIn = std::make_shared<ProbeFn>();
        // The probe callback holds the function strongly, the function itself weakly: no cycle.
        std::weak_ptr<ProbeFn> weakProbeIn = probeIn;
        *probeIn = [this, station, waiting, weakProbeIn](Protocol protocol) {
            SessionJob probe;
            probe.request = Request::briefStatus(station);
            probe.probe = protocol;
            probe.options.retries = 0;
            probe.done = [this, station, waiting, next = weakProbeIn.lock(),
                          protocol](const SessionResult &result) {
                // A PLC error is an answer too: the protocol is right.
                const bool answered = result.ok() || result.errorKind() == ErrorKind::PlcError;
                const bool linkDown = !result.ok()
                                      && (result.errorKind() == ErrorKind::LinkError
                                          || result.errorKind() == ErrorKind::Cancelled);
                if (answered) {
                    setProtocol(protocol);
                    m_log->append(TrafficEntry::Direction::Event, {},
                                  QStringLiteral("protocol detected: %1")
                                      .arg(QString::fromUtf8(protocolName(protocol))));
                    Q_EMIT protocolDetected(protocol);
                    queueFor(waiting->priority).push_front(std::move(*waiting));
                    schedulePump();
                } else if (protocol == Protocol::Facon && !linkDown) {
                    (*next)(Protocol::Binary);
                } else {
                    const ErrorKind kind = linkDown ? result.errorKind() : ErrorKind::Timeout;
                    deliver(
                        *waiting,
                        SessionResult::fromError(
                            makeError(kind, toStd(QStringLiteral(
                                                      "Protocol auto-detect: station %1 answered "
                                                      "neither in FACON nor in binary (%2)")
                                                      .arg(station)
                                                      .arg(result.errorText()))),
                            {}, waiting->raw));
                }
            };
            m_userQueue.push_front(std::move(probe));
            schedulePump();
        };
        (*probeIn)(Protocol::Facon);
        return false;
    }
    if (!job.raw) {
        const Protocol protocol = job.probe ? *job.probe : *m_protocol;
        const Status valid = validateRequest(job.request, protocol);
        if (!valid) {
            deliver(job, SessionResult::fromError(valid.error()));
            return false;
        }
    }
    return true;
}

int SessionWorker::timeoutFor(const SessionJob &job) const
{
    return job.options.timeoutMs > 0 ? job.options.timeoutMs : m_settings.timeoutMs;
}

int SessionWorker::retriesFor(const SessionJob &job) const
{
    if (job.raw)
        return 0; // a console frame is sent once, as typed
    return job.options.retries >= 0 ? job.options.retries : m_settings.retries;
}

quint8 SessionWorker::stationOf(const SessionJob &job) const
{
    if (job.raw)
        return job.options.station > 0 && job.options.station <= Limits::maxStation
                   ? static_cast<quint8>(job.options.station)
                   : quint8(0);
    return job.request.station;
}

// ---- one query on the wire ----------------------------------------------------------------------

void SessionWorker::proceed()
{
    if (!m_current) {
        schedulePump();
        return;
    }
    if (m_state != LinkState::Connected)
        return;
    // Serial: the PLC needs a silent line between frames.
    if (m_settings.kind == LinkSettings::Kind::Serial && m_settings.interFrameMs > 0) {
        const qint64 quiet = m_lastActivity.elapsed();
        if (quiet < m_settings.interFrameMs) {
            m_silenceTimer.start(static_cast<int>(m_settings.interFrameMs - quiet));
            return;
        }
    }
    startAttempt();
}

void SessionWorker::startAttempt()
{
    SessionJob &job = *m_current;
    const std::optional<Protocol> chosen = job.probe ? job.probe
                                           : job.raw ? job.options.framing
                                                     : std::nullopt;
    const Codec *activeCodec
        = chosen ? (*chosen == Protocol::Facon ? m_faconCodec.get() : m_binaryCodec.get())
                 : codec();

    // Stale bytes (a late answer to a timed-out query, noise) must not join the next answer.
    const QByteArray stale = m_transport->takePending();
    const std::size_t partial
        = m_faconDeframer->bufferedBytes() + m_binaryDeframer->bufferedBytes();
    m_faconDeframer->reset();
    m_binaryDeframer->reset();
    if (!stale.isEmpty()) {
        m_log->append(TrafficEntry::Direction::In, stale, QStringLiteral("stale bytes discarded"),
                      QStringLiteral("received outside an answer"));
    }
    if (!stale.isEmpty() || partial > 0) {
        m_statistics.bytesDiscarded += static_cast<quint64>(stale.size()) + partial;
        m_statistics.total.bytesIn += static_cast<quint64>(stale.size());
    }

    QByteArray frame;
    if (job.raw) {
        frame = toQByteArray(RawFrame::frame(bytesOf(job.rawBytes),
                                             job.addFraming ? std::optional(activeCodec->protocol())
                                                            : std::nullopt));
    } else {
        const Result<Bytes> encoded = activeCodec->encodeRequest(job.request);
        if (!encoded) {
            finishCurrent(SessionResult::fromError(encoded.error()));
            return;
        }
        frame = toQByteArray(*encoded);
    }

    ++job.attempts;
    const quint8 station = stationOf(job);
    if (job.attempts > 1)
        countForStation(station, [](StationStatistics &s) { ++s.retries; });
    m_answer.clear();
    m_sentFrame = frame;
    if (!m_transport->write(frame)) {
        // The transport reports the failure itself (disconnected); make sure the job ends.
        finishCurrent(SessionResult::fromError(
            makeError(ErrorKind::LinkError,
                      toStd(QStringLiteral("Could not write to %1.").arg(m_transport->describe()))),
            {}, job.raw));
        return;
    }
    m_lastActivity.start();
    m_roundTrip.start();
    countForStation(station, [&frame](StationStatistics &s) {
        s.bytesOut += static_cast<quint64>(frame.size());
    });
    m_log->append(TrafficEntry::Direction::Out, frame, summarize(frame));

    if (!job.raw && job.request.station == Limits::broadcastStation) {
        // Broadcast: every PLC acts and none answers. Done once the frame has left this machine,
        // not when it is only queued: a close right after the result must not lose it.
        if (m_transport->unsentBytes() > 0) {
            m_awaitingSent = true;
            m_timeoutTimer.start(timeoutFor(job));
            return;
        }
        finishBroadcast();
        return;
    }
    m_timeoutTimer.start(timeoutFor(job));
}

void SessionWorker::finishBroadcast()
{
    Response response;
    response.station = 0;
    response.command = m_current->request.command;
    finishCurrent(SessionResult(Result<Response>(response)));
}

QString SessionWorker::summarize(const QByteArray &frame) const
{
    if (const Codec *c = codec())
        return QString::fromStdString(c->summarize(bytesOf(frame)));
    // Protocol not known yet: the frame's first byte tells.
    return QString::fromStdString(RawFrame::summarize(bytesOf(frame)));
}

void SessionWorker::onBytes(const QByteArray &bytes)
{
    m_lastActivity.start();
    if (!m_current || !m_timeoutTimer.isActive() || m_awaitingSent) {
        // Nothing asked: a late answer or noise. Dropped now, logged, and counted.
        m_log->append(TrafficEntry::Direction::In, bytes, QStringLiteral("unexpected bytes"),
                      QStringLiteral("no query pending"));
        m_statistics.total.bytesIn += static_cast<quint64>(bytes.size());
        m_statistics.bytesDiscarded += static_cast<quint64>(bytes.size());
        statisticsChangedInternally();
        return;
    }
    SessionJob &job = *m_current;
    const quint8 station = stationOf(job);
    countForStation(station, [&bytes](StationStatistics &s) {
        s.bytesIn += static_cast<quint64>(bytes.size());
    });
    if (job.raw) {
        onRawBytes(bytes);
        return;
    }

    const Protocol protocol = job.probe ? *job.probe : *m_protocol;
    const Codec *activeCodec
        = protocol == Protocol::Facon ? m_faconCodec.get() : m_binaryCodec.get();
    Deframer *deframer
        = protocol == Protocol::Facon ? m_faconDeframer.get() : m_binaryDeframer.get();
    std::vector<DeframedItem> items;
    deframer->feed(bytesOf(bytes), items);
    countDeframerNoise();
    for (DeframedItem &item : items) {
        const QByteArray frame = toQByteArray(item.frame);
        if (item.error) {
            m_log->append(TrafficEntry::Direction::In, frame, summarize(frame),
                          QString::fromStdString(item.error->message));
            if (item.error->kind == ErrorKind::BadChecksum)
                countForStation(station, [](StationStatistics &s) { ++s.checksumErrors; });
            else
                countForStation(station, [](StationStatistics &s) { ++s.frameErrors; });
            // A damaged answer: ask again (or give up with this error).
            m_timeoutTimer.stop();
            retryOrFail(*item.error);
            return;
        }
        Result<Response> decoded = activeCodec->decodeResponse(item.frame, job.request);
        if (!decoded && frame == m_sentFrame) {
            // 2-wire RS-485 hears its own query. (Only when it does not decode as an answer: a
            // FACON STOP or loopback answer is byte for byte the query.)
            m_log->append(TrafficEntry::Direction::In, frame, QStringLiteral("echo of the query"),
                          {});
            continue;
        }
        if (!decoded
            && (decoded.error().kind == ErrorKind::StationMismatch
                || decoded.error().kind == ErrorKind::CommandMismatch)) {
            // Another station on the bus, or a late answer to an earlier query: keep waiting.
            m_log->append(TrafficEntry::Direction::In, frame, summarize(frame),
                          QString::fromStdString(decoded.error().message));
            continue;
        }
        m_log->append(TrafficEntry::Direction::In, frame, summarize(frame),
                      decoded ? QString() : QString::fromStdString(decoded.error().message));
        const double rtt = static_cast<double>(m_roundTrip.nsecsElapsed()) / 1e6;
        const bool plcError = !decoded && decoded.error().kind == ErrorKind::PlcError;
        const bool malformed = !decoded && !plcError;
        countForStation(station, [rtt, plcError, malformed](StationStatistics &s) {
            ++s.answers;
            s.unanswered = 0;
            s.addRoundTrip(rtt);
            if (plcError)
                ++s.plcErrors;
            if (malformed)
                ++s.frameErrors;
        });
        m_answer = frame;
        finishCurrent(SessionResult(std::move(decoded), frame));
        return;
    }
}

void SessionWorker::onRawBytes(const QByteArray &bytes)
{
    m_answer += bytes;
    if (m_answer.size() > maxRawAnswerBytes) {
        // A peer that floods the console: keep what fits and end now rather than at the timeout.
        m_answer.truncate(maxRawAnswerBytes);
        m_log->append(TrafficEntry::Direction::In, m_answer, QStringLiteral("raw answer"),
                      QStringLiteral("more than %1 bytes: rest not read").arg(maxRawAnswerBytes));
        finishCurrent(SessionResult::fromRaw(m_answer));
        return;
    }
    // End early once a complete frame of the link's protocol came back (or of the protocol the
    // frame was framed in, or looks like); otherwise collect until the timeout.
    std::optional<Protocol> protocol = m_protocol;
    if (!protocol)
        protocol = m_current->options.framing;
    if (!protocol && RawFrame::protocolOf(bytesOf(m_sentFrame)) == Protocol::Facon)
        protocol = Protocol::Facon;
    if (!protocol)
        return;
    Deframer *deframer
        = *protocol == Protocol::Facon ? m_faconDeframer.get() : m_binaryDeframer.get();
    std::vector<DeframedItem> items;
    deframer->feed(bytesOf(bytes), items);
    // Bytes around a console answer are the answer, not noise.
    m_deframerNoise = m_faconDeframer->discardedBytes() + m_binaryDeframer->discardedBytes();
    for (const DeframedItem &item : items) {
        const QByteArray frame = toQByteArray(item.frame);
        const double rtt = static_cast<double>(m_roundTrip.nsecsElapsed()) / 1e6;
        countForStation(0, [rtt](StationStatistics &s) {
            ++s.answers;
            s.addRoundTrip(rtt);
        });
        if (item.error)
            countForStation(0, [](StationStatistics &s) { ++s.checksumErrors; });
        m_log->append(TrafficEntry::Direction::In, m_answer, summarize(frame),
                      item.error ? QString::fromStdString(item.error->message) : QString());
        finishCurrent(SessionResult::fromRaw(m_answer));
        return;
    }
}

void SessionWorker::onTimeout()
{
    if (!m_current)
        return;
    SessionJob &job = *m_current;
    const int timeout = timeoutFor(job);
    if (m_awaitingSent) {
        // Never retried: the stuck copy may still leave, and the PLC would act twice.
        m_awaitingSent = false;
        const QString link = m_transport->describe();
        const QString message
            = QStringLiteral("Not sent: %1 did not take the frame within %2 ms (%3 of %4 bytes "
                             "unsent).")
                  .arg(link)
                  .arg(timeout)
                  .arg(std::min<qint64>(m_transport->unsentBytes(), m_sentFrame.size()))
                  .arg(m_sentFrame.size());
        m_log->append(TrafficEntry::Direction::Event, {},
                      QString::fromStdString(job.request.describe()), message);
        finishCurrent(SessionResult::fromError(makeError(ErrorKind::LinkError, toStd(message))));
        // Reported as not sent, so it must never leave later: drop the link and what it holds.
        m_transport->close();
        onDisconnected(QStringLiteral("%1 does not take data").arg(link));
        return;
    }
    if (job.raw) {
        if (m_answer.isEmpty()) {
            countForStation(0, [](StationStatistics &s) { ++s.timeouts; });
            m_log->append(TrafficEntry::Direction::Event, {}, QStringLiteral("raw frame"),
                          QStringLiteral("no answer within %1 ms").arg(timeout));
            finishCurrent(SessionResult::fromError(
                makeError(ErrorKind::Timeout,
                          toStd(QStringLiteral("No answer within %1 ms.").arg(timeout))),
                {}, true));
        } else {
            m_log->append(TrafficEntry::Direction::In, m_answer, QStringLiteral("raw answer"),
                          QStringLiteral("no complete frame"));
            finishCurrent(SessionResult::fromRaw(m_answer));
        }
        return;
    }
    const quint8 station = stationOf(job);
    countForStation(station, [](StationStatistics &s) { ++s.timeouts; });
    const int attempts = retriesFor(job) + 1;
    const QString message
        = QStringLiteral("No answer from station %1 within %2 ms (attempt %3 of %4).")
              .arg(station)
              .arg(timeout)
              .arg(job.attempts)
              .arg(attempts);
    m_log->append(TrafficEntry::Direction::Event, {},
                  QString::fromStdString(job.request.describe()), message);
    retryOrFail(makeError(ErrorKind::Timeout, toStd(message)));
}

void SessionWorker::retryOrFail(ProtocolError error)
{
    SessionJob &job = *m_current;
    if (job.attempts <= retriesFor(job)) {
        proceed();
        return;
    }
    finishCurrent(SessionResult::fromError(std::move(error), m_answer, job.raw));
}

void SessionWorker::finishCurrent(SessionResult result)
{
    m_timeoutTimer.stop();
    m_awaitingSent = false;
    m_faconDeframer->reset();
    m_binaryDeframer->reset();
    SessionJob job = std::move(*m_current);
    m_current.reset();
    result.setAttempts(job.attempts);
    if (!job.probe)
        countForStation(stationOf(job), [](StationStatistics &s) { ++s.requests; });
    // Probes count too: with auto-detect a silent station never gets past them.
    if (!job.raw && !result.ok() && result.errorKind() == ErrorKind::Timeout)
        countForStation(stationOf(job), [](StationStatistics &s) { ++s.unanswered; });
    publishStatistics(); // before the result, so statistics() already counts it
    deliver(job, std::move(result));
    schedulePump();
}

void SessionWorker::deliver(SessionJob &job, SessionResult result)
{
    if (job.pendingWrite) {
        job.pendingWrite = false;
        m_shared->pendingWrites.fetch_sub(1);
    }
    if (job.done) {
        auto done = std::move(job.done);
        done(result);
    } else if (job.id != 0) {
        Q_EMIT finished(job.id, result);
    }
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
    // Copied for Session::statistics() once per finished request, not once per counter change.
    if (!m_sharedStale)
        return;
    m_sharedStale = false;
    const std::lock_guard locker(m_shared->mutex);
    m_shared->statistics = m_statistics;
}

void SessionWorker::resetStatistics()
{
    m_statistics = SessionStatistics();
    statisticsChangedInternally();
    publishStatistics();
}

void SessionWorker::setWatchList(const QList<WatchEntry> &entries)
{
    m_poller->setWatchList(entries);
}

} // namespace Fatek
