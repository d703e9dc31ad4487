#pragma once

#include <QEvent>

#include <functional>

class QObject;

namespace Fatek {

// A function posted to run on the thread of a receiving QObject: what a queued
// QMetaObject::invokeMethod does, plus ThreadSanitizer annotations at both ends.
//
// Qt orders a queued hand-over with its event-queue mutex, but Debian's Qt is not built with
// -fsanitize=thread, so TSan can't see that ordering and reports the data that travels (a
// request, a result) as a race. post() marks a release once the event and everything it carries
// are built, just before Qt takes it; the receiving side marks the acquire before the function
// runs and before the event is destroyed (also when it is dropped undelivered). The marks
// compile to nothing in other builds. The receiver forwards its events through deliver().
class CrossThreadCall final : public QEvent
{
public:
    ~CrossThreadCall() override;

    // Queues `function` for `receiver`'s thread; QCoreApplication owns the event from here on.
    static void post(QObject *receiver, std::function<void()> function);

    // For the receiver's event(): runs the function and returns true if `event` is a
    // CrossThreadCall, else returns false.
    static bool deliver(QObject *receiver, QEvent *event);

    // Queues `function` for the thread of any QObject (one that does not forward its events to
    // deliver()) through a queued QMetaObject::invokeMethod, with the same marks. If `context` is
    // destroyed first, Qt drops the call with it. The caller makes sure `context` is not being
    // destroyed while this runs.
    static void invoke(QObject *context, std::function<void()> function);

    // The same marks for a hand-over Qt makes without an event: a thread's end, seen by
    // QThread::wait() (Qt's threads are detached, so TSan can't see the join). Call threadEnds()
    // last thing on the ending thread and threadEnded() after wait(), with the same channel.
    static void threadEnds(const void *channel);
    static void threadEnded(const void *channel);

private:
    CrossThreadCall(const QObject *receiver, std::function<void()> function);
    static QEvent::Type eventType();

    const QObject *m_receiver;
    std::function<void()> m_function;
};

} // namespace Fatek
