#include "requesttracker.h"

namespace Fatek {

RequestTracker::RequestTracker(QObject *parent)
    : QObject(parent)
{
    registerSessionMetaTypes();
}

void RequestTracker::setSession(Session *session)
{
    if (m_session == session)
        return;
    forgetPending();
    disconnect(m_destroyed);
    m_session = session;
    if (session)
        m_destroyed = connect(session, &QObject::destroyed, this, [this] {
            m_session = nullptr;
            Q_EMIT sessionDestroyed();
        });
}

Session::Completion RequestTracker::track(Callback callback)
{
    ++m_pendingCount;
    return [this, generation = m_generation,
            callback = std::move(callback)](const SessionResult &result) {
        if (generation != m_generation)
            return;
        // Counted down first: the callback may submit the next request or ask what is left.
        --m_pendingCount;
        if (callback)
            callback(result);
    };
}

quint64 RequestTracker::submit(const Request &request, Callback callback, RequestOptions options,
                               Priority priority)
{
    if (!m_session)
        return 0;
    return m_session->submit(request, this, track(std::move(callback)), priority, options);
}

quint64 RequestTracker::sendRaw(const QByteArray &bytes, bool addFraming, Callback callback,
                                RequestOptions options)
{
    if (!m_session)
        return 0;
    return m_session->sendRaw(bytes, addFraming, this, track(std::move(callback)), options);
}

quint64 RequestTracker::submitChange(const Request &change, ChangeVerifier::Callback callback,
                                     RequestOptions options)
{
    if (!m_session)
        return 0;
    ++m_pendingCount;
    return ChangeVerifier::submit(
        m_session, change, this,
        [this, generation = m_generation, callback = std::move(callback)](const ChangeReport &r) {
            if (generation != m_generation)
                return;
            if (r.final)
                --m_pendingCount;
            if (callback)
                callback(r);
        },
        options);
}

void RequestTracker::forgetPending()
{
    ++m_generation;
    m_pendingCount = 0;
}

void RequestTracker::cancelPending()
{
    if (m_session)
        m_session->cancelAll(this);
    forgetPending();
}

} // namespace Fatek
