// Request completion in core (Session::submit/sendRaw with a context, RequestTracker), against the
// simulator over loopback TCP: one call per request on every outcome, on the context's thread, and
// none once the context, the tracker's interest or the session is gone.
#include "core/session/requesttracker.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "loopbacksession.h"

#include <QHash>
#include <QPointer>
#include <QSet>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

#include <atomic>
#include <memory>
#include <mutex>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return Address::parse(text).value();
}

// Every call of the completions it hands out, by tag: the result, the thread it ran on, and
// whether finished() of the request (named with expect()) had come first.
class Calls
{
public:
    explicit Calls(Session *session)
    {
        QObject::connect(session, &Session::finished, &m_receiver,
                         [this](quint64 id, const SessionResult &) {
                             const std::lock_guard locker(m_mutex);
                             m_finished.insert(id);
                         });
    }

    Session::Completion completion(quint64 tag)
    {
        return [this, tag](const SessionResult &result) {
            const std::lock_guard locker(m_mutex);
            m_tags.append(tag);
            m_results.insert(tag, result);
            m_threads.insert(tag, QThread::currentThread());
            m_finishedFirst.insert(tag, m_finished.contains(m_ids.value(tag)));
        };
    }
    // The request id of `tag`, told before its completion can run (submitted on this thread).
    void expect(quint64 tag, quint64 id)
    {
        const std::lock_guard locker(m_mutex);
        m_ids.insert(tag, id);
    }
    bool finishedFirst(quint64 tag) const
    {
        const std::lock_guard locker(m_mutex);
        return m_finishedFirst.value(tag);
    }
    bool sawFinished(quint64 id) const
    {
        const std::lock_guard locker(m_mutex);
        return m_finished.contains(id);
    }
    int count(quint64 tag) const
    {
        const std::lock_guard locker(m_mutex);
        return static_cast<int>(m_tags.count(tag));
    }
    int total() const
    {
        const std::lock_guard locker(m_mutex);
        return static_cast<int>(m_tags.size());
    }
    SessionResult result(quint64 tag) const
    {
        const std::lock_guard locker(m_mutex);
        return m_results.value(tag);
    }
    QThread *thread(quint64 tag) const
    {
        const std::lock_guard locker(m_mutex);
        return m_threads.value(tag);
    }

private:
    QObject m_receiver;
    mutable std::mutex m_mutex;
    QList<quint64> m_tags;
    QHash<quint64, SessionResult> m_results;
    QHash<quint64, QThread *> m_threads;
    QHash<quint64, quint64> m_ids;
    QHash<quint64, bool> m_finishedFirst;
    QSet<quint64> m_finished;
};

// A thread that is stopped however the test ends.
class ScopedThread : public QThread
{
public:
    ~ScopedThread() override
    {
        quit();
        wait();
    }
};

// Waits until `done` holds (or `ms` pass), running the event loop.
template<typename Predicate>
bool waitUntil(Predicate done, int ms = 10000)
{
    QDeadlineTimer deadline(ms);
    while (!done() && !deadline.hasExpired())
        QTest::qWait(2);
    return done();
}

// A context that says when it is gone.
class Probe : public QObject
{
public:
    explicit Probe(std::shared_ptr<std::atomic<bool>> dead)
        : m_dead(std::move(dead))
    {}
    ~Probe() override { m_dead->store(true); }

private:
    std::shared_ptr<std::atomic<bool>> m_dead;
};

} // namespace

class TestRequestCompletion : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void successCalledOnce();
    void plcErrorCalledOnce();
    void timeoutCalledOnce();
    void refusedWhileDownCalledOnce();
    void closeWithQueuedRequests();
    void closeDrainsQueuedWrite();
    void cancelAndCancelAll();
    void destroyedContextNotCalled();
    void contextDeletedByACompletion();
    void callbackOnContextThread();
    void contextThreadDeletionRace();
    void destroyedSessionDropsCompletions();
    void trackerForgetsAndCancels();

private:
    std::unique_ptr<Session> openSession(int timeoutMs = 1000, int retries = 1);

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
};

void TestRequestCompletion::init()
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
}

void TestRequestCompletion::cleanup()
{
    m_server.reset();
    m_plc.reset();
}

std::unique_ptr<Session> TestRequestCompletion::openSession(int timeoutMs, int retries)
{
    return TestUtil::openLoopbackSession(m_server->tcpPort(), timeoutMs, retries);
}

void TestRequestCompletion::successCalledOnce()
{
    auto session = openSession();
    QCOMPARE(session->linkState(), LinkState::Connected);
    Calls calls(session.get());
    QObject context;
    const quint64 id = session->submit(Request::briefStatus(1), &context, calls.completion(1));
    QVERIFY(id != 0);
    calls.expect(1, id);
    calls.expect(2, session->sendRaw(QByteArray("0140"), true, &context, calls.completion(2)));
    QVERIFY(waitUntil([&] { return calls.total() == 2; }));
    QTest::qWait(200); // nothing more comes
    QCOMPARE(calls.count(1), 1);
    QCOMPARE(calls.count(2), 1);
    QVERIFY2(calls.result(1).ok(), qPrintable(calls.result(1).errorText()));
    QVERIFY2(calls.result(2).ok(), qPrintable(calls.result(2).errorText()));
    QVERIFY(!calls.result(2).rawAnswer().isEmpty());
    // After finished(), on the thread of the context (here the session's own).
    QVERIFY(calls.finishedFirst(1));
    QVERIFY(calls.finishedFirst(2));
    QCOMPARE(calls.thread(1), QThread::currentThread());
    QCOMPARE(calls.thread(2), QThread::currentThread());
}

void TestRequestCompletion::plcErrorCalledOnce()
{
    auto session = openSession();
    Calls calls(session.get());
    QObject context;
    session->submit(Request::readRegisters(1, addr("R3900"), 1), &context, calls.completion(1));
    QVERIFY(waitUntil([&] { return calls.total() == 1; }));
    QTest::qWait(200);
    QCOMPARE(calls.count(1), 1);
    QCOMPARE(calls.result(1).errorKind(), ErrorKind::PlcError);
    QCOMPARE(calls.result(1).error().plcCode, 0xA);
    QCOMPARE(calls.result(1).attempts(), 1);
}

void TestRequestCompletion::timeoutCalledOnce()
{
    FaultConfig faults;
    faults.dropRate = 1.0;
    m_server->setFaults(faults);
    auto session = openSession(100, 2);
    Calls calls(session.get());
    QObject context;
    session->submit(Request::briefStatus(1), &context, calls.completion(1));
    QVERIFY(waitUntil([&] { return calls.total() == 1; }));
    QTest::qWait(300); // past what a stray further attempt would take
    QCOMPARE(calls.count(1), 1);
    QCOMPARE(calls.result(1).errorKind(), ErrorKind::Timeout);
    QCOMPARE(calls.result(1).attempts(), 3);
}

void TestRequestCompletion::refusedWhileDownCalledOnce()
{
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(),
                                              LinkSettings::ProtocolChoice::Facon);
    Session session(settings); // never opened
    Calls calls(&session);
    QObject context;
    session.submit(Request::briefStatus(1), &context, calls.completion(1));
    // Not from inside submit(): the caller has returned before its completion runs.
    QCOMPARE(calls.total(), 0);
    QVERIFY(waitUntil([&] { return calls.total() == 1; }));
    QTest::qWait(100);
    QCOMPARE(calls.count(1), 1);
    QCOMPARE(calls.result(1).errorKind(), ErrorKind::LinkError);
}

void TestRequestCompletion::closeWithQueuedRequests()
{
    FaultConfig faults;
    faults.latencyMs = 50;
    m_server->setFaults(faults);
    auto session = openSession();
    Calls calls(session.get());
    QObject context;
    for (quint64 tag = 1; tag <= 5; ++tag)
        session->submit(Request::briefStatus(1), &context, calls.completion(tag));
    session->close();
    QVERIFY(waitUntil([&] { return calls.total() == 5; }));
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Closed, 5000);
    QTest::qWait(100);
    QCOMPARE(calls.total(), 5);
    for (quint64 tag = 1; tag <= 5; ++tag) {
        QCOMPARE(calls.count(tag), 1);
        QCOMPARE(calls.result(tag).errorKind(), ErrorKind::Cancelled);
    }
}

void TestRequestCompletion::closeDrainsQueuedWrite()
{
    FaultConfig faults;
    faults.latencyMs = 50;
    m_server->setFaults(faults);
    auto session = openSession();
    Calls calls(session.get());
    QObject context;
    session->submit(Request::readRegisters(1, addr("R0"), 1), &context, calls.completion(1));
    session->submit(Request::writeRegisters(1, addr("R7"), {77}), &context, calls.completion(2));
    session->close();
    QVERIFY(waitUntil([&] { return calls.total() == 2; }));
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Closed, 5000);
    QTest::qWait(100);
    QCOMPARE(calls.count(1), 1);
    QCOMPARE(calls.count(2), 1);
    QVERIFY2(calls.result(2).ok(), qPrintable(calls.result(2).errorText()));
    QCOMPARE(m_plc->value(addr("R7")), std::optional<std::uint32_t>(77));
}

void TestRequestCompletion::cancelAndCancelAll()
{
    FaultConfig faults;
    faults.latencyMs = 80;
    m_server->setFaults(faults);
    auto session = openSession();
    Calls calls(session.get());
    QObject mine;
    QObject other;
    // The first is on the wire (the simulator has it) and completes; the others wait in the queue.
    session->submit(Request::briefStatus(1), &mine, calls.completion(1));
    QVERIFY(waitUntil([&] { return m_server->counters().frames == 1; }));
    const quint64 second = session->submit(Request::briefStatus(1), &mine, calls.completion(2));
    session->submit(Request::briefStatus(1), &other, calls.completion(10));
    session->submit(Request::briefStatus(1), &mine, calls.completion(3));
    session->submit(Request::briefStatus(1), &mine, calls.completion(4));
    session->cancel(second);
    session->cancelAll(&mine);
    QVERIFY(waitUntil([&] { return calls.total() == 5; }));
    QTest::qWait(300);
    QCOMPARE(calls.total(), 5);
    for (const quint64 tag : {quint64(1), quint64(2), quint64(3), quint64(4), quint64(10)})
        QCOMPARE(calls.count(tag), 1);
    QVERIFY2(calls.result(1).ok(), qPrintable(calls.result(1).errorText()));
    for (const quint64 tag : {quint64(2), quint64(3), quint64(4)})
        QCOMPARE(calls.result(tag).errorKind(), ErrorKind::Cancelled);
    // Another context's request is left alone.
    QVERIFY2(calls.result(10).ok(), qPrintable(calls.result(10).errorText()));
}

void TestRequestCompletion::destroyedContextNotCalled()
{
    FaultConfig faults;
    faults.latencyMs = 50;
    m_server->setFaults(faults);
    auto session = openSession();
    Calls calls(session.get());
    auto *context = new QObject;
    QObject survivor;
    QList<quint64> ids;
    for (quint64 tag = 1; tag <= 3; ++tag)
        ids << session->submit(Request::briefStatus(1), context, calls.completion(tag));
    const quint64 last = session->submit(Request::briefStatus(1), &survivor, calls.completion(9));
    delete context;
    QVERIFY(waitUntil([&] { return calls.sawFinished(last); }));
    QTest::qWait(100);
    // The requests ran (finished() came), their completions did not.
    for (const quint64 id : std::as_const(ids))
        QVERIFY(calls.sawFinished(id));
    QCOMPARE(calls.total(), 1);
    QCOMPARE(calls.count(9), 1);
}

void TestRequestCompletion::contextDeletedByACompletion()
{
    auto session = openSession();
    Calls calls(session.get());
    QPointer<QObject> context = new QObject;
    int called = 0;
    for (int i = 0; i < 3; ++i)
        session->submit(Request::briefStatus(1), context, [&](const SessionResult &) {
            ++called;
            delete context.data(); // the tool closes on its first answer
        });
    const quint64 last = session->submit(Request::briefStatus(1), this, calls.completion(1));
    QVERIFY(waitUntil([&] { return calls.count(1) == 1; }));
    QTest::qWait(100);
    QVERIFY(context.isNull());
    QCOMPARE(called, 1);
    QVERIFY(calls.sawFinished(last));
}

void TestRequestCompletion::callbackOnContextThread()
{
    auto session = openSession();
    Calls calls(session.get());
    ScopedThread thread;
    thread.setObjectName(QStringLiteral("context thread"));
    auto *context = new QObject;
    context->moveToThread(&thread);
    connect(&thread, &QThread::finished, context, &QObject::deleteLater);
    thread.start();
    // Submitted from this thread, answered on the context's.
    for (quint64 tag = 1; tag <= 5; ++tag)
        session->submit(Request::briefStatus(1), context, calls.completion(tag));
    QVERIFY(waitUntil([&] { return calls.total() == 5; }));
    QTest::qWait(100);
    for (quint64 tag = 1; tag <= 5; ++tag) {
        QCOMPARE(calls.count(tag), 1);
        QCOMPARE(calls.thread(tag), &thread);
        QVERIFY(calls.result(tag).ok());
    }
    thread.quit();
    QVERIFY(thread.wait(5000));
}

void TestRequestCompletion::contextThreadDeletionRace()
{
    FaultConfig faults;
    faults.latencyMs = 5;
    m_server->setFaults(faults);
    auto session = openSession();
    ScopedThread thread;
    thread.start();
    auto dead = std::make_shared<std::atomic<bool>>(false);
    auto *context = new Probe(dead);
    context->moveToThread(&thread);
    std::atomic<int> called{0};
    std::atomic<int> calledAfterDeath{0};
    QSignalSpy finished(session.get(), &Session::finished);
    constexpr int count = 40;
    for (int i = 0; i < count; ++i)
        session->submit(Request::briefStatus(1), context, [&, dead](const SessionResult &) {
            // Runs on the context's thread, as its destructor does: the two cannot overlap.
            if (dead->load())
                ++calledAfterDeath;
            ++called;
        });
    // Gone while results are still coming in.
    QVERIFY(waitUntil([&] { return finished.count() >= count / 4; }));
    context->deleteLater();
    QVERIFY(waitUntil([&] { return finished.count() == count; }));
    QVERIFY(waitUntil([&] { return dead->load(); }));
    QTest::qWait(100);
    QCOMPARE(calledAfterDeath.load(), 0);
    QVERIFY(called.load() >= count / 4 && called.load() < count);
    thread.quit();
    QVERIFY(thread.wait(5000));
}

void TestRequestCompletion::destroyedSessionDropsCompletions()
{
    FaultConfig faults;
    faults.latencyMs = 100;
    m_server->setFaults(faults);
    auto session = openSession();
    int called = 0;
    QObject context;
    for (int i = 0; i < 3; ++i)
        session->submit(Request::briefStatus(1), &context,
                        [&called](const SessionResult &) { ++called; });
    session.reset(); // the results that come meanwhile are not signalled, nor completed
    QTest::qWait(300);
    QCOMPARE(called, 0);
}

void TestRequestCompletion::trackerForgetsAndCancels()
{
    FaultConfig faults;
    faults.latencyMs = 30;
    m_server->setFaults(faults);
    auto session = openSession();
    QSignalSpy finished(session.get(), &Session::finished);
    RequestTracker tracker;
    int called = 0;
    auto count = [&called](const SessionResult &) {
        ++called;
    };
    QCOMPARE(tracker.submit(Request::briefStatus(1), count), quint64(0)); // no session yet
    tracker.setSession(session.get());

    // Answered: counted down before the callback runs.
    int pendingSeen = -1;
    tracker.submit(Request::briefStatus(1), [&](const SessionResult &r) {
        pendingSeen = tracker.pendingCount();
        QVERIFY(r.ok());
        ++called;
    });
    QCOMPARE(tracker.pendingCount(), 1);
    QVERIFY(waitUntil([&] { return called == 1; }));
    QCOMPARE(pendingSeen, 0);

    // Forgotten: the requests run, the callbacks do not.
    called = 0;
    finished.clear();
    for (int i = 0; i < 3; ++i)
        tracker.submit(Request::briefStatus(1), count);
    QCOMPARE(tracker.pendingCount(), 3);
    tracker.forgetPending();
    QCOMPARE(tracker.pendingCount(), 0);
    QVERIFY(waitUntil([&] { return finished.count() == 3; }));
    QTest::qWait(50);
    QCOMPARE(called, 0);

    // Another target: what was asked of the old one is dropped.
    finished.clear();
    tracker.submit(Request::briefStatus(1), count);
    tracker.setSession(nullptr);
    QCOMPARE(tracker.pendingCount(), 0);
    QVERIFY(waitUntil([&] { return finished.count() == 1; }));
    QTest::qWait(50);
    QCOMPARE(called, 0);

    // Cancelled: the queued ones never reach the PLC, and nobody is called.
    tracker.setSession(session.get());
    finished.clear();
    const quint64 framesBefore = m_server->counters().frames;
    for (int i = 0; i < 10; ++i)
        tracker.submit(Request::briefStatus(1), count);
    tracker.cancelPending();
    QCOMPARE(tracker.pendingCount(), 0);
    QVERIFY(waitUntil([&] { return finished.count() == 10; }));
    QTest::qWait(50);
    QCOMPARE(called, 0);
    int cancelled = 0;
    for (const QList<QVariant> &args : std::as_const(finished)) {
        // The one already on the wire may complete normally: only a failed result has a kind.
        const auto r = args.at(1).value<SessionResult>();
        cancelled += !r.ok() && r.errorKind() == ErrorKind::Cancelled ? 1 : 0;
    }
    QVERIFY2(cancelled >= 9, qPrintable(QString::number(cancelled)));
    QVERIFY(m_server->counters().frames - framesBefore <= 1);
}

QTEST_GUILESS_MAIN(TestRequestCompletion)
#include "tst_requestcompletion.moc"
