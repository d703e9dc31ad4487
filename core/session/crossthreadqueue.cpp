#include "crossthreadqueue.h"

#include "crossthreadcall.h"

#include <QPointer>

#include <iterator>
#include <utility>

namespace Fatek {

CrossThreadQueue::CrossThreadQueue(QObject *receiver, std::function<void()> batchEnded)
    : m_receiver(receiver)
    , m_batchEnded(std::move(batchEnded))
{}

void CrossThreadQueue::post(std::function<void()> function)
{
    bool wake = false;
    {
        const std::lock_guard locker(m_mutex);
        m_incoming.push_back(std::move(function));
        wake = !std::exchange(m_posted, true);
    }
    // Outside the lock: the receiving thread may take the batch as soon as the event is queued.
    if (wake)
        CrossThreadCall::post(m_receiver, [this] { run(); });
}

void CrossThreadQueue::run()
{
    {
        const std::lock_guard locker(m_mutex);
        // Cleared before the calls run: one that runs a nested event loop may wait for a later
        // post, which must bring its own event.
        m_posted = false;
        std::move(m_incoming.begin(), m_incoming.end(), std::back_inserter(m_running));
        m_incoming.clear(); // keeps its capacity: no allocation per batch
    }
    const QPointer<QObject> receiver(m_receiver);
    ++m_depth;
    // A nested run() (from a call's nested event loop) goes on with this batch first.
    while (!m_running.empty()) {
        const std::function<void()> function = std::move(m_running.front());
        m_running.pop_front();
        function();
        if (!receiver)
            return; // the call destroyed the receiver, and this queue with it
    }
    if (--m_depth == 0 && m_batchEnded)
        m_batchEnded();
}

} // namespace Fatek
