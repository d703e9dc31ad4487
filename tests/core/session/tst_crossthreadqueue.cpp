// CrossThreadQueue: calls from other threads run on the receiver's thread, in the order posted,
// each once, also across a nested event loop, and none after the receiver is gone.
#include "core/session/crossthreadcall.h"
#include "core/session/crossthreadqueue.h"

#include <QEventLoop>
#include <QTest>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

using namespace Fatek;

namespace {

// A receiver as Session and SessionWorker are: it owns its queue and forwards its events.
class Receiver : public QObject
{
public:
    explicit Receiver(std::function<void()> batchEnded = {})
        : queue(this, std::move(batchEnded))
    {}
    bool event(QEvent *event) override
    {
        return CrossThreadCall::deliver(this, event) || QObject::event(event);
    }
    CrossThreadQueue queue;
};

} // namespace

class TestCrossThreadQueue : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void orderFromOneThread();
    void batchedAndOrderedFromSeveralThreads();
    void nestedLoopKeepsOrder();
    void receiverDestroyedByACall();
};

void TestCrossThreadQueue::orderFromOneThread()
{
    int batches = 0;
    Receiver receiver([&batches] { ++batches; });
    std::vector<int> seen;
    constexpr int count = 10000;
    std::unique_ptr<QThread> poster(QThread::create([&receiver, &seen] {
        for (int i = 0; i < count; ++i)
            receiver.queue.post([&seen, i] { seen.push_back(i); });
    }));
    poster->start();
    QVERIFY(poster->wait(10000));
    QTRY_COMPARE_WITH_TIMEOUT(int(seen.size()), count, 10000);
    for (int i = 0; i < count; ++i)
        QCOMPARE(seen[std::size_t(i)], i);
    // At least one batch; far fewer than calls when the poster ran ahead (not asserted: timing).
    QVERIFY(batches >= 1);
    QVERIFY(batches <= count);
}

void TestCrossThreadQueue::batchedAndOrderedFromSeveralThreads()
{
    Receiver receiver;
    constexpr int threads = 4;
    constexpr int count = 2000;
    std::vector<std::vector<int>> seen(threads);
    std::vector<std::unique_ptr<QThread>> posters;
    for (int t = 0; t < threads; ++t) {
        posters.emplace_back(QThread::create([&receiver, &seen, t] {
            for (int i = 0; i < count; ++i)
                receiver.queue.post([&seen, t, i] { seen[std::size_t(t)].push_back(i); });
        }));
        posters.back()->start();
    }
    for (auto &poster : posters)
        QVERIFY(poster->wait(10000));
    QTRY_VERIFY_WITH_TIMEOUT(
        std::all_of(seen.begin(), seen.end(), [](const auto &s) { return s.size() == count; }),
        10000);
    // Each poster's calls in its own order.
    for (const auto &s : seen)
        for (int i = 0; i < count; ++i)
            QCOMPARE(s[std::size_t(i)], i);
}

void TestCrossThreadQueue::nestedLoopKeepsOrder()
{
    int batches = 0;
    Receiver receiver([&batches] { ++batches; });
    std::vector<int> seen;
    std::atomic<bool> secondPosted{false};
    // Posted from this thread before the loop runs: one batch of 1, 2 (nested loop), 3.
    receiver.queue.post([&seen] { seen.push_back(1); });
    receiver.queue.post([&] {
        seen.push_back(2);
        // A call that runs a nested loop, as a slot with a dialog would. Another thread posts 4
        // meanwhile: it must come after 3, the rest of this batch.
        std::unique_ptr<QThread> poster(QThread::create([&] {
            receiver.queue.post([&seen] { seen.push_back(4); });
            secondPosted = true;
        }));
        poster->start();
        QVERIFY(poster->wait(10000));
        QEventLoop loop;
        QTimer::singleShot(50, &loop, &QEventLoop::quit);
        loop.exec();
    });
    receiver.queue.post([&seen] { seen.push_back(3); });
    QTRY_COMPARE_WITH_TIMEOUT(int(seen.size()), 4, 10000);
    QVERIFY(secondPosted);
    QCOMPARE(seen, (std::vector<int>{1, 2, 3, 4}));
    // The batch's end is reported for the outermost run only.
    QTRY_VERIFY(batches >= 1);
}

void TestCrossThreadQueue::receiverDestroyedByACall()
{
    auto *receiver = new Receiver;
    int ran = 0;
    receiver->queue.post([&ran] { ++ran; });
    receiver->queue.post([&ran, receiver] {
        ++ran;
        delete receiver; // as a receiver of Session::finished() may delete the session
    });
    receiver->queue.post([&ran] { ++ran; }); // dropped with the receiver
    QTRY_COMPARE_WITH_TIMEOUT(ran, 2, 5000);
    QTest::qWait(50);
    QCOMPARE(ran, 2);
}

QTEST_GUILESS_MAIN(TestCrossThreadQueue)
#include "tst_crossthreadqueue.moc"
