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
    disconnect(m_connection);
    m_pending.clear();
    m_session = session;
    if (session)
        m_connection = connect(session, &Session::finished, this, &RequestTracker::onFinished);
}

quint64 RequestTracker::submit(const Request &request, Callback callback, RequestOptions options,
                               Priority priority)
{
    if (!m_session)
        return 0;
    const quint64 id = m_session->submit(request, priority, options);
    m_pending.insert(id, std::move(callback));
    return id;
}

quint64 RequestTracker::sendRaw(const QByteArray &bytes, bool addFraming, Callback callback,
                                RequestOptions options)
{
    if (!m_session)
        return 0;
    const quint64 id = m_session->sendRaw(bytes, addFraming, options);
    m_pending.insert(id, std::move(callback));
    return id;
}

void RequestTracker::forgetPending()
{
    m_pending.clear();
}

void RequestTracker::onFinished(quint64 id, const SessionResult &result)
{
    const auto it = m_pending.find(id);
    if (it == m_pending.end())
        return; // another tool's request, or one we stopped caring about
    const Callback callback = it.value();
    m_pending.erase(it);
    if (callback)
        callback(result);
}

} // namespace Fatek
