#pragma once

#include "sessionjob.h"

#include <deque>
#include <optional>
#include <vector>

namespace Fatek {

// The worker's waiting requests, one queue per priority: user before background before polls,
// first in first out within each.
class RequestQueue
{
public:
    // Requests a user or background queue holds at most; more are refused (LimitExceeded).
    static constexpr std::size_t maxQueued = 1000;

    // No room for `job` in its queue. The poll queue holds at most one cycle per group and is
    // not capped.
    bool isFull(const SessionJob &job) const;
    void pushBack(SessionJob job);
    // Ahead of its queue (a request let through after the protocol probe it waited for).
    void pushFront(SessionJob job);
    // The next request by priority; false when all queues are empty.
    bool takeNext(SessionJob &job);
    // The request `id`, taken out, if it waits.
    std::optional<SessionJob> take(quint64 id);
    // Everything, in the order it would have gone (the poll queue only with `includePolls`).
    std::vector<SessionJob> takeAll(bool includePolls);
    // What a closing link does not send: all but writes and protocol probes. `writesKept` tells
    // whether a write (or a probe a write may wait for) stays.
    std::vector<SessionJob> takeReads(bool *writesKept);
    bool isEmpty() const;
    void clear();

private:
    std::deque<SessionJob> &queueFor(Priority priority);
    const std::deque<SessionJob> &queueFor(Priority priority) const;

    std::deque<SessionJob> m_user;
    std::deque<SessionJob> m_background;
    std::deque<SessionJob> m_poll;
};

} // namespace Fatek
