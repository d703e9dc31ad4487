#include "crossthreadcall.h"

#include <QCoreApplication>

#if defined(__SANITIZE_THREAD__)
#define FATEK_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define FATEK_TSAN 1
#endif
#endif

#ifdef FATEK_TSAN
extern "C" {
void __tsan_acquire(void *addr);
void __tsan_release(void *addr);
}
#endif

namespace Fatek {

namespace {

// Everything this thread did so far happens before the other side's acquire() on `channel`.
void release([[maybe_unused]] const void *channel)
{
#ifdef FATEK_TSAN
    __tsan_release(const_cast<void *>(channel));
#endif
}

void acquire([[maybe_unused]] const void *channel)
{
#ifdef FATEK_TSAN
    __tsan_acquire(const_cast<void *>(channel));
#endif
}

// The channel of invoke()'s marks. Not the receiver's address, kept in the function: reading it
// on the receiving side would come before the acquire.
const char invokeChannel = 0;

// The function given to QMetaObject::invokeMethod by invoke(). Qt moves it into its slot object,
// the last copy the other thread reads: every construction ends with a release, so the last one
// covers that copy (and the slot object's header, written before it). The call begins with an
// acquire and ends with a release, as the slot object is shared: whichever side drops the last
// reference destroys it (the posting thread too, when the call ran first), and the destruction
// begins with an acquire.
class MarkedFunction
{
public:
    explicit MarkedFunction(std::function<void()> function)
        : m_function(std::move(function))
    {
        release(&invokeChannel);
    }
    MarkedFunction(MarkedFunction &&other) noexcept
        : m_function(std::move(other.m_function))
    {
        release(&invokeChannel);
    }
    MarkedFunction(const MarkedFunction &) = delete;
    MarkedFunction &operator=(const MarkedFunction &) = delete;
    MarkedFunction &operator=(MarkedFunction &&) = delete;
    ~MarkedFunction() { acquire(&invokeChannel); }

    void operator()()
    {
        acquire(&invokeChannel);
        if (m_function)
            m_function();
        release(&invokeChannel);
    }

private:
    std::function<void()> m_function;
};

} // namespace

CrossThreadCall::CrossThreadCall(const QObject *receiver, std::function<void()> function)
    : QEvent(eventType())
    , m_receiver(receiver)
    , m_function(std::move(function))
{}

CrossThreadCall::~CrossThreadCall()
{
    // Runs before the members (the function and what it captured) are destroyed.
    acquire(m_receiver);
}

QEvent::Type CrossThreadCall::eventType()
{
    static const auto type = static_cast<QEvent::Type>(QEvent::registerEventType());
    return type;
}

void CrossThreadCall::post(QObject *receiver, std::function<void()> function)
{
    auto *event = new CrossThreadCall(receiver, std::move(function));
    release(receiver);
    QCoreApplication::postEvent(receiver, event);
}

void CrossThreadCall::invoke(QObject *context, std::function<void()> function)
{
    QMetaObject::invokeMethod(context, MarkedFunction(std::move(function)), Qt::QueuedConnection);
}

void CrossThreadCall::threadEnds(const void *channel)
{
    release(channel);
}

void CrossThreadCall::threadEnded(const void *channel)
{
    acquire(channel);
}

bool CrossThreadCall::deliver(QObject *receiver, QEvent *event)
{
    // Before reading the event: it may be one built on the other thread.
    acquire(receiver);
    if (event->type() != eventType())
        return false;
    auto *call = static_cast<CrossThreadCall *>(event);
    if (call->m_function)
        call->m_function();
    return true;
}

} // namespace Fatek
