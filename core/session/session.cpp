#include "session.h"

#include "sessionworker.h"

#include <QMutexLocker>

namespace Fatek {

QString linkStateName(LinkState state)
{
    switch (state) {
    case LinkState::Closed: return QStringLiteral("closed");
    case LinkState::Connecting: return QStringLiteral("connecting");
    case LinkState::Connected: return QStringLiteral("connected");
    case LinkState::Lost: return QStringLiteral("lost");
    case LinkState::Reconnecting: return QStringLiteral("reconnecting");
    }
    return {};
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
}

Session::Session(const LinkSettings &settings, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_shared(std::make_shared<SessionShared>())
    , m_log(new TrafficLog(10000, this))
{
    registerSessionMetaTypes();
    m_thread.setObjectName(QStringLiteral("session %1").arg(settings.toString()));
    m_worker = new SessionWorker(settings, m_shared, m_log);
    m_worker->moveToThread(&m_thread);
    // The worker (and its sockets) is destroyed in its own thread when the thread ends.
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &SessionWorker::finished, this, &Session::finished);
    connect(m_worker, &SessionWorker::linkStateChanged, this, &Session::linkStateChanged);
    connect(m_worker, &SessionWorker::statisticsChanged, this, &Session::statisticsChanged);
    connect(m_worker, &SessionWorker::protocolDetected, this, &Session::protocolDetected);
    connect(m_worker, &SessionWorker::values, this, &Session::values);
    m_thread.start();
}

Session::~Session()
{
    m_thread.quit();
    m_thread.wait();
}

void Session::open()
{
    QMetaObject::invokeMethod(m_worker, &SessionWorker::open, Qt::QueuedConnection);
}

void Session::close()
{
    QMetaObject::invokeMethod(m_worker, &SessionWorker::close, Qt::QueuedConnection);
}

quint64 Session::submit(const Request &request, Priority priority, RequestOptions options)
{
    SessionJob job;
    job.id = m_nextId.fetch_add(1);
    job.request = request;
    job.priority = priority;
    job.options = options;
    const quint64 id = job.id;
    QMetaObject::invokeMethod(
        m_worker,
        [worker = m_worker, job = std::move(job)]() mutable { worker->enqueue(std::move(job)); },
        Qt::QueuedConnection);
    return id;
}

quint64 Session::sendRaw(const QByteArray &bytes, bool addFraming, RequestOptions options)
{
    SessionJob job;
    job.id = m_nextId.fetch_add(1);
    job.raw = true;
    job.rawBytes = bytes;
    job.addFraming = addFraming;
    job.priority = Priority::User;
    job.options = options;
    const quint64 id = job.id;
    QMetaObject::invokeMethod(
        m_worker,
        [worker = m_worker, job = std::move(job)]() mutable { worker->enqueue(std::move(job)); },
        Qt::QueuedConnection);
    return id;
}

void Session::cancel(quint64 id)
{
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, id] { worker->cancel(id); }, Qt::QueuedConnection);
}

void Session::setReadOnly(bool readOnly)
{
    // Atomic: effective for every request dispatched after this returns.
    m_shared->readOnly.store(readOnly);
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
    QMutexLocker locker(&m_shared->mutex);
    return m_shared->statistics;
}

void Session::resetStatistics()
{
    QMetaObject::invokeMethod(m_worker, &SessionWorker::resetStatistics, Qt::QueuedConnection);
}

void Session::setWatchList(const QList<WatchEntry> &entries)
{
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, entries] { worker->setWatchList(entries); },
        Qt::QueuedConnection);
}

} // namespace Fatek
