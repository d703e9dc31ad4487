#include "session.h"

#include "crossthreadcall.h"
#include "crossthreadqueue.h"
#include "sessionworker.h"

#include <QDeadlineTimer>
#include <QHash>
#include <QPointer>

#include <algorithm>
#include <mutex>

namespace Fatek {

namespace {

// The completion of one request. `context` is cleared, under `mutex`, when the context object is
// destroyed (on its own thread), so the thread delivering the result never reaches a dead object:
// it posts while holding `mutex`, and an event posted before the destruction goes with the object.
struct PendingCompletion
{
    std::mutex mutex;
    QObject *context = nullptr;
    Session::Completion function;
    QMetaObject::Connection watch; // context's destroyed()
};

} // namespace

// Completions by request id, filled by submit() (any thread), emptied on the Session's thread.
struct SessionCompletions
{
    std::mutex mutex;
    QHash<quint64, std::shared_ptr<PendingCompletion>> pending;
};

Message linkStateMessage(LinkState state)
{
    switch (state) {
    case LinkState::Closed: return msg<MsgId::LinkClosed>();
    case LinkState::Connecting: return msg<MsgId::LinkConnecting>();
    case LinkState::Connected: return msg<MsgId::LinkConnected>();
    case LinkState::Lost: return msg<MsgId::LinkLost>();
    case LinkState::Reconnecting: return msg<MsgId::LinkReconnecting>();
    }
    return {};
}

QString linkStateName(LinkState state)
{
    return englishText(linkStateMessage(state));
}

void registerSessionMetaTypes()
{
    qRegisterMetaType<Fatek::SessionResult>();
    qRegisterMetaType<Fatek::SessionStatistics>();
    qRegisterMetaType<Fatek::LinkState>();
    qRegisterMetaType<Fatek::Priority>();
    qRegisterMetaType<Fatek::WatchValue>();
    qRegisterMetaType<QList<Fatek::WatchValue>>();
    qRegisterMetaType<Fatek::WatchEntry>();
    qRegisterMetaType<Fatek::TrafficEntry>();
    qRegisterMetaType<Fatek::LinkSettings>();
    qRegisterMetaType<Fatek::Message>();
}

Session::Session(const LinkSettings &settings, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_shared(std::make_shared<SessionShared>())
    , m_log(new TrafficLog(TrafficLog::idleCapacity, this))
    , m_completions(std::make_unique<SessionCompletions>())
    , m_inbox(std::make_unique<CrossThreadQueue>(this))
{
    registerSessionMetaTypes();
    m_thread.setObjectName(QStringLiteral("session %1").arg(settings.toString()));
    m_worker = new SessionWorker(settings, m_shared, m_log);
    m_worker->moveToThread(&m_thread);
    // The worker (and its sockets) is destroyed in its own thread when the thread ends.
    connect(&m_thread, &QThread::started, m_worker, &SessionWorker::startTimers);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    // The worker's signals are relayed to this object's thread through a CrossThreadQueue (one
    // event for all that came meanwhile, in order; a hand-over ThreadSanitizer can follow), then
    // emitted from here.
    connect(
        m_worker, &SessionWorker::finished, m_worker,
        [this](quint64 id, const SessionResult &result) {
            m_inbox->post([this, id, result] {
                // A receiver of finished() may delete this session: its completions go with it.
                const QPointer<Session> self(this);
                Q_EMIT finished(id, result);
                if (self)
                    complete(id, result);
            });
        },
        Qt::DirectConnection);
    connect(
        m_worker, &SessionWorker::linkStateChanged, m_worker,
        [this](LinkState state, const Message &reason) {
            m_inbox->post([this, state, reason] { Q_EMIT linkStateChanged(state, reason); });
        },
        Qt::DirectConnection);
    connect(
        m_worker, &SessionWorker::statisticsChanged, m_worker,
        [this](const SessionStatistics &statistics) {
            m_inbox->post([this, statistics] { Q_EMIT statisticsChanged(statistics); });
        },
        Qt::DirectConnection);
    connect(
        m_worker, &SessionWorker::protocolDetected, m_worker,
        [this](Protocol protocol) {
            m_inbox->post([this, protocol] { Q_EMIT protocolDetected(protocol); });
        },
        Qt::DirectConnection);
    connect(
        m_worker, &SessionWorker::values, m_worker,
        [this](const QList<WatchValue> &batch) {
            m_inbox->post([this, batch] { Q_EMIT values(batch); });
        },
        Qt::DirectConnection);
    m_thread.start();
}

Session::~Session()
{
    // Writes already accepted leave before the link goes (bounded); then the thread ends.
    QThread *thread = &m_thread;
    m_worker->inbox().post(
        [worker = m_worker, thread] { worker->close(true, [thread] { thread->quit(); }); });
    if (!m_thread.wait(QDeadlineTimer(m_shared->closeDrainMs.load() + 2000))) {
        m_thread.quit();
        m_thread.wait();
    }
    CrossThreadCall::threadEnded(m_shared.get());
    // Results that did not come are not signalled, and their completions are dropped the same way.
    const std::lock_guard locker(m_completions->mutex);
    for (const auto &pending : std::as_const(m_completions->pending))
        QObject::disconnect(pending->watch);
    m_completions->pending.clear();
}

void Session::open()
{
    m_worker->inbox().post([worker = m_worker] { worker->open(); });
}

void Session::close(CloseMode mode)
{
    const bool drain = mode == CloseMode::Drain;
    m_worker->inbox().post([worker = m_worker, drain] { worker->close(drain); });
}

int Session::pendingWrites() const
{
    return m_shared->pendingWrites.load();
}

void Session::setCloseDrainMs(int ms)
{
    m_shared->closeDrainMs.store(std::max(0, ms));
}

int Session::closeDrainMs() const
{
    return m_shared->closeDrainMs.load();
}

quint64 Session::submit(const Request &request, Priority priority, RequestOptions options)
{
    return submit(request, nullptr, {}, priority, options);
}

quint64 Session::submit(const Request &request, QObject *context, Completion completion,
                        Priority priority, RequestOptions options)
{
    SessionJob job;
    job.request = request;
    job.priority = priority;
    job.options = options;
    return enqueue(job, context, std::move(completion));
}

quint64 Session::sendRaw(const QByteArray &bytes, bool addFraming, RequestOptions options)
{
    return sendRaw(bytes, addFraming, nullptr, {}, options);
}

quint64 Session::sendRaw(const QByteArray &bytes, bool addFraming, QObject *context,
                         Completion completion, RequestOptions options)
{
    SessionJob job;
    job.raw = true;
    job.rawBytes = bytes;
    job.addFraming = addFraming;
    job.priority = Priority::User;
    job.options = options;
    return enqueue(job, context, std::move(completion));
}

quint64 Session::enqueue(SessionJob &job, QObject *context, Completion completion)
{
    job.id = m_nextId.fetch_add(1);
    const quint64 id = job.id;
    if (context && completion) {
        // Registered before the job leaves: its result may come back before this returns.
        auto pending = std::make_shared<PendingCompletion>();
        pending->context = context;
        pending->function = std::move(completion);
        pending->watch = connect(
            context, &QObject::destroyed, context,
            [weak = std::weak_ptr<PendingCompletion>(pending)] {
                if (const auto alive = weak.lock()) {
                    const std::lock_guard locker(alive->mutex);
                    alive->context = nullptr;
                }
            },
            Qt::DirectConnection);
        const std::lock_guard locker(m_completions->mutex);
        m_completions->pending.emplace(id, std::move(pending));
    }
    m_worker->inbox().post(
        [worker = m_worker, job = std::move(job)]() mutable { worker->enqueue(std::move(job)); });
    return id;
}

void Session::complete(quint64 id, const SessionResult &result)
{
    std::shared_ptr<PendingCompletion> pending;
    {
        const std::lock_guard locker(m_completions->mutex);
        pending = m_completions->pending.take(id);
    }
    if (!pending)
        return;
    std::unique_lock locker(pending->mutex);
    QObject *context = pending->context;
    if (context && context->thread() != QThread::currentThread()) {
        // Posted under the lock: the context cannot finish dying until the call is queued, and
        // Qt drops a queued call with its receiver.
        CrossThreadCall::invoke(
            context, [function = std::move(pending->function), result] { function(result); });
        context = nullptr;
    }
    locker.unlock();
    QObject::disconnect(pending->watch);
    // Same thread: nothing else can destroy the context before the call (the call itself may).
    if (context)
        pending->function(result);
}

void Session::cancel(quint64 id)
{
    m_worker->inbox().post([worker = m_worker, id] { worker->cancel(id); });
}

void Session::cancelAll(const QObject *context)
{
    if (!context)
        return;
    QList<quint64> ids;
    {
        const std::lock_guard locker(m_completions->mutex);
        for (auto it = m_completions->pending.cbegin(); it != m_completions->pending.cend(); ++it) {
            // A destroyed context's slot reads null: a new object at its address is not it.
            const std::lock_guard contextLocker(it.value()->mutex);
            if (it.value()->context == context)
                ids.append(it.key());
        }
    }
    if (ids.isEmpty())
        return;
    m_worker->inbox().post([worker = m_worker, ids] {
        for (const quint64 id : ids)
            worker->cancel(id);
    });
}

void Session::setReadOnly(bool readOnly)
{
    // Atomic: effective for every request dispatched after this returns.
    m_shared->readOnly.store(readOnly);
}

bool Session::event(QEvent *event)
{
    return CrossThreadCall::deliver(this, event) || QObject::event(event);
}

bool Session::isReadOnly() const
{
    return m_shared->readOnly.load();
}

Protocol Session::protocol() const
{
    const int value = m_shared->protocol.load();
    if (value < 0)
        return m_settings.protocol == LinkSettings::ProtocolChoice::Binary ? Protocol::Binary
                                                                           : Protocol::Facon;
    return static_cast<Protocol>(value);
}

bool Session::isProtocolKnown() const
{
    return m_shared->protocol.load() >= 0;
}

LinkState Session::linkState() const
{
    return static_cast<LinkState>(m_shared->linkState.load());
}

SessionStatistics Session::statistics() const
{
    const std::lock_guard locker(m_shared->mutex);
    return m_shared->statistics;
}

void Session::resetStatistics()
{
    m_worker->inbox().post([worker = m_worker] { worker->resetStatistics(); });
}

void Session::setWatchList(const QList<WatchEntry> &entries)
{
    m_worker->inbox().post([worker = m_worker, entries] { worker->setWatchList(entries); });
}

} // namespace Fatek
