#pragma once

#include "core/protocol/request.h"
#include "core/qtbridge/qtmessage.h"

#include <QDeadlineTimer>
#include <QMetaType>
#include <QString>

#include <optional>

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
// The state's word ("lost") as a message.
Message linkStateMessage(LinkState state);

// Queue a request joins. User actions go ahead of everything, polling last.
enum class Priority {
    User,       // writes, RUN/STOP, forcing, loopback, raw frames, one-off reads
    Background, // long user jobs that must not block single actions (station scan)
    Poll,       // cyclic reads: the watch list, and the tools' routine reads (status, forced
                // marks), which are answered at once, not sent, while their station rests
};

// What closing a link does with writes already accepted.
enum class CloseMode {
    Drain,   // send them (and unsent bytes) first, for at most Session::closeDrainMs()
    Discard, // cancel them at once
};

// Per-request overrides of the link's policy; negative means "use the session's setting".
struct RequestOptions
{
    int timeoutMs = -1;
    int retries = -1;
    // Raw frames: the station they are meant for (statistics, and the station an auto-detect
    // probe asks when the framing needs the protocol); -1: unknown (a probe asks station 1).
    int station = -1;
    // Raw frames with framing: the protocol whose framing to add. Unset: the link's protocol,
    // detected first under auto-detect.
    std::optional<Protocol> framing;
    // A poll asking again for an element the PLC refused before: another refusal is expected and
    // is not counted as a PLC error (the counters are for faults).
    bool expectRefusal = false;
    // The last moment the request may be put on the wire (a first attempt or a retry); past it
    // the request finishes with ErrorKind::Expired, nothing sent. A change confirmed by a person
    // or commanded with an age limit must not reach the PLC long after: a write that waited
    // behind a dead station would land when nobody expects it any more.
    QDeadlineTimer deadline{QDeadlineTimer::Forever};
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::LinkState)
Q_DECLARE_METATYPE(Fatek::Priority)
