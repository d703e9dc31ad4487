#pragma once

#include "request.h"
#include "session.h"

#include <QHash>
#include <QObject>
#include <QPointer>

#include <functional>

namespace Fatek {

// Sends requests for one tool and calls back with each answer, on the UI thread (finished() is
// queued). Answers of a previous session are dropped when the target changes, and a session that
// is deleted under us simply stops answering: nothing ever blocks waiting for the wire.
class RequestTracker : public QObject
{
    Q_OBJECT

public:
    using Callback = std::function<void(const SessionResult &)>;

    explicit RequestTracker(QObject *parent = nullptr);

    void setSession(Session *session);
    Session *session() const { return m_session.data(); }

    // Returns the request id, or 0 when there is no session (the callback is then not called).
    quint64 submit(const Request &request, Callback callback, RequestOptions options = {},
                   Priority priority = Priority::User);
    quint64 sendRaw(const QByteArray &bytes, bool addFraming, Callback callback,
                    RequestOptions options = {});
    // Forgets the callbacks of the requests still pending (their answers are ignored).
    void forgetPending();
    int pendingCount() const { return static_cast<int>(m_pending.size()); }

private:
    void onFinished(quint64 id, const SessionResult &result);

    QPointer<Session> m_session;
    QMetaObject::Connection m_connection;
    QHash<quint64, Callback> m_pending;
};

} // namespace Fatek
