#pragma once

#include "core/transport/linksettings.h"
#include "sessionresult.h"
#include "sessiontypes.h"

#include <QByteArray>

#include <functional>
#include <optional>

namespace Fatek {

// One queued request of the session's worker, and the link's policy as it applies to it.
struct SessionJob
{
    quint64 id = 0; // 0: internal (poller, protocol probe), answered through `done`
    bool raw = false;
    Request request;
    QByteArray rawBytes;
    bool addFraming = false;
    Priority priority = Priority::User;
    RequestOptions options;
    std::optional<Protocol> probe; // protocol auto-detect probe in this protocol
    bool fromPoller = false;       // the poller's own (it keeps the stations' health itself)
    std::function<void(const SessionResult &)> done;
    int attempts = 0;
    bool pendingWrite = false; // counted in SessionShared::pendingWrites

    // Changes the PLC (a write command, RUN/STOP, a raw frame); a probe never does.
    bool isWrite() const;
    // The station it is for; 0 for a raw frame of no known station.
    quint8 station() const;
    // How long an attempt waits for its answer.
    int timeoutMs(const LinkSettings &settings) const;
    // Attempts after the first one; changes are sent once.
    int retries(const LinkSettings &settings) const;
};

} // namespace Fatek
