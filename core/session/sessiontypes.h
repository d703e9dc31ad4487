#pragma once

#include <QMetaType>
#include <QString>

namespace Fatek {

// State of a session's link, reported with a reason by Session::linkStateChanged.
enum class LinkState {
    Closed,       // not opened, or closed by the user
    Connecting,   // opening the port / connecting
    Connected,    // queries can go
    Lost,         // the link failed (reason says why); followed by Reconnecting or Closed
    Reconnecting, // waiting for the next attempt (backoff)
};
QString linkStateName(LinkState state);

// Queue a request joins. User actions go ahead of everything, polling last.
enum class Priority {
    User,       // writes, RUN/STOP, forcing, loopback, raw frames, one-off reads
    Background, // long user jobs that must not block single actions (station scan)
    Poll,       // cyclic reads of the watch list
};

// Per-request overrides of the link's policy; negative means "use the session's setting".
struct RequestOptions
{
    int timeoutMs = -1;
    int retries = -1;
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::LinkState)
Q_DECLARE_METATYPE(Fatek::Priority)
