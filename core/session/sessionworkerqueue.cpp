// SessionWorker, the queue: priorities, cancelling, choosing and preparing the next job.
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

#include <algorithm>

namespace Fatek {

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
    if (m_state != LinkState::Connected && m_state != LinkState::Connecting) {
        Message why = m_state == LinkState::Closed
                          ? msg<MsgId::SessionLinkNotOpen>()
                          : msg<MsgId::SessionLinkDown>(linkStateMessage(m_state));
        deliver(job, SessionResult::fromError(makeError(ErrorKind::LinkError, std::move(why)), {},
                                              job.raw));
        return;
    }
    std::deque<SessionJob> &queue = queueFor(job.priority);
    // A caller that submits faster than the link answers must not grow memory without end. The
    // poll queue holds at most one cycle per group and is not capped here.
    if (job.priority != Priority::Poll && queue.size() >= maxQueuedRequests) {
        deliver(job,
                SessionResult::fromError(makeError(ErrorKind::LimitExceeded,
                                                   msg<MsgId::SessionQueueFull>(maxQueuedRequests)),
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
                             makeError(ErrorKind::Cancelled, msg<MsgId::SessionCancelled>()), {},
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

void SessionWorker::failAll(ErrorKind kind, const Message &reason, bool includePolls)
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
    if (!m_protocol && !job.probe && needsProtocol) {
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
                                  msg<MsgId::LogProtocolDetected>(protocolName(protocol)));
                    Q_EMIT protocolDetected(protocol);
                    queueFor(waiting->priority).push_front(std::move(*waiting));
                    schedulePump();
                } else if (protocol == Protocol::Facon && !linkDown) {
                    (*next)(Protocol::Binary);
                } else {
                    const ErrorKind kind = linkDown ? result.errorKind() : ErrorKind::Timeout;
                    deliver(*waiting, SessionResult::fromError(
                                          makeError(kind, msg<MsgId::LinkAutoDetectFailed>(
                                                              station, result.errorMessage())),
                                          {}, waiting->raw));
                }
            };
            m_userQueue.push_front(std::move(probe));
            schedulePump();
        };
        (*probeIn)(Protocol::Facon);
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
    // A change is sent once (docs/reliability.md): a copy sent again can land late, after the
    // deadline, behind a line that held the first one, and the PLC acts twice. Its unanswered
    // outcome is unknown, and a read-back (ChangeVerifier) tells what it became.
    if (isWriteCommand(job.request.command))
        return 0;
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

} // namespace Fatek
