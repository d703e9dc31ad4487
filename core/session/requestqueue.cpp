#include "requestqueue.h"

#include <algorithm>

namespace Fatek {

std::deque<SessionJob> &RequestQueue::queueFor(Priority priority)
{
    switch (priority) {
    case Priority::User: return m_user;
    case Priority::Background: return m_background;
    case Priority::Poll: return m_poll;
    }
    return m_user;
}

const std::deque<SessionJob> &RequestQueue::queueFor(Priority priority) const
{
    return const_cast<RequestQueue *>(this)->queueFor(priority);
}

bool RequestQueue::isFull(const SessionJob &job) const
{
    // A caller that submits faster than the link answers must not grow memory without end.
    return job.priority != Priority::Poll && queueFor(job.priority).size() >= maxQueued;
}

void RequestQueue::pushBack(SessionJob job)
{
    std::deque<SessionJob> &queue = queueFor(job.priority);
    queue.push_back(std::move(job));
}

void RequestQueue::pushFront(SessionJob job)
{
    std::deque<SessionJob> &queue = queueFor(job.priority);
    queue.push_front(std::move(job));
}

bool RequestQueue::takeNext(SessionJob &job)
{
    for (auto *queue : {&m_user, &m_background, &m_poll}) {
        if (!queue->empty()) {
            job = std::move(queue->front());
            queue->pop_front();
            return true;
        }
    }
    return false;
}

std::optional<SessionJob> RequestQueue::take(quint64 id)
{
    for (auto *queue : {&m_user, &m_background, &m_poll}) {
        auto it = std::find_if(queue->begin(), queue->end(),
                               [id](const SessionJob &job) { return job.id == id; });
        if (it != queue->end()) {
            SessionJob job = std::move(*it);
            queue->erase(it);
            return job;
        }
    }
    return std::nullopt;
}

std::vector<SessionJob> RequestQueue::takeAll(bool includePolls)
{
    std::vector<SessionJob> jobs;
    for (auto *queue : {&m_user, &m_background, &m_poll}) {
        if (queue == &m_poll && !includePolls)
            continue;
        for (auto &job : *queue)
            jobs.push_back(std::move(job));
        queue->clear();
    }
    return jobs;
}

std::vector<SessionJob> RequestQueue::takeReads(bool *writesKept)
{
    // Probes stay: a queued write may wait for the protocol they detect.
    std::vector<SessionJob> reads;
    *writesKept = false;
    for (auto *queue : {&m_user, &m_background, &m_poll}) {
        std::deque<SessionJob> kept;
        for (auto &job : *queue) {
            if (job.isWrite() || job.probe) {
                *writesKept = true;
                kept.push_back(std::move(job));
            } else {
                reads.push_back(std::move(job));
            }
        }
        queue->swap(kept);
    }
    return reads;
}

bool RequestQueue::isEmpty() const
{
    return m_user.empty() && m_background.empty() && m_poll.empty();
}

void RequestQueue::clear()
{
    m_user.clear();
    m_background.clear();
    m_poll.clear();
}

} // namespace Fatek
