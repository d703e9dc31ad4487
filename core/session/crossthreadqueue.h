#pragma once

#include <deque>
#include <functional>
#include <mutex>
#include <vector>

class QObject;

namespace Fatek {

// Calls for one receiver's thread, handed over in batches. post() (any thread) appends a function
// and posts one CrossThreadCall only when none is on its way: a burst of hand-overs costs one
// event and one wake-up of the receiving thread instead of one each. The calls run in the order
// posted, each once, also when one of them runs a nested event loop (the nested turn goes on with
// the same batch first). The receiver owns the queue and forwards its events to
// CrossThreadCall::deliver(); calls not run when it is destroyed are dropped, as posted events
// are. What a call carries is ordered by the queue's std::mutex, which ThreadSanitizer sees.
class CrossThreadQueue
{
public:
    // `batchEnded`, if set, runs on the receiver's thread after each batch (not after one that
    // destroyed the receiver).
    explicit CrossThreadQueue(QObject *receiver, std::function<void()> batchEnded = {});
    CrossThreadQueue(const CrossThreadQueue &) = delete;
    CrossThreadQueue &operator=(const CrossThreadQueue &) = delete;

    void post(std::function<void()> function);
    // On the receiver's thread: whether a batch is running (a call of it is on the stack).
    bool isRunning() const { return m_depth > 0; }

private:
    void run(); // on the receiver's thread

    QObject *m_receiver;
    std::function<void()> m_batchEnded;
    std::mutex m_mutex;
    std::vector<std::function<void()>> m_incoming; // under m_mutex
    bool m_posted = false;                         // under m_mutex: a CrossThreadCall is on its way
    // The receiver's thread only:
    std::deque<std::function<void()>> m_running;
    int m_depth = 0;
};

} // namespace Fatek
