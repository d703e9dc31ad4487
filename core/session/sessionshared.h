#pragma once

#include "sessionstatistics.h"
#include "sessiontypes.h"

#include <atomic>
#include <mutex>

namespace Fatek {

// State shared between the Session front and its worker (read by any thread).
struct SessionShared
{
    std::atomic<bool> readOnly{false};
    std::atomic<int> linkState{static_cast<int>(LinkState::Closed)};
    std::atomic<int> protocol{-1}; // Protocol value, -1 while auto-detect has not decided
    // Accepted writes (write commands, RUN/STOP, raw frames) not finished yet, queued or on the
    // wire: what closing the link waits for.
    std::atomic<int> pendingWrites{0};
    std::atomic<int> closeDrainMs{3000}; // how long a close waits for them
    mutable std::mutex mutex;
    SessionStatistics statistics; // under mutex
};

} // namespace Fatek
