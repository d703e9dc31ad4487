// The console's stop requests (Windows: Ctrl-C, Ctrl-Break, closing the console, log-off,
// shut-down) as app/common/consolecontrol.cpp handles them. Wine delivers no console event to a
// program (docs/windows.md), so the handler is called here directly, from a thread of its own as
// the system calls it: the quit runs in the context's thread, and for close, log-off and
// shut-down the handler does not return (the system would end the process at once).

#include "app/common/consolecontrol.h"

#include <QAtomicInt>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

#include <atomic>
#include <thread>

#ifdef Q_OS_WIN
#include <windows.h>
#endif

using namespace Fatek;

Q_DECLARE_METATYPE(Fatek::ConsoleControl::Event)

class tst_ConsoleControl : public QObject
{
    Q_OBJECT

private:
    QObject context;
    int quits = 0;
    QThread *quitThread = nullptr;

private slots:
    void initTestCase()
    {
        ConsoleControl::install(&context, [this] {
            ++quits;
            quitThread = QThread::currentThread();
        });
    }

    void init()
    {
        quits = 0;
        quitThread = nullptr;
    }

    void eachEventQuitsInTheContextsThread_data()
    {
        QTest::addColumn<ConsoleControl::Event>("event");
        QTest::addColumn<bool>("holds");
        QTest::newRow("Ctrl-C") << ConsoleControl::Event::Interrupt << false;
        QTest::newRow("Ctrl-Break") << ConsoleControl::Event::Break << false;
        QTest::newRow("console closed") << ConsoleControl::Event::Close << true;
        QTest::newRow("log-off") << ConsoleControl::Event::Logoff << true;
        QTest::newRow("shut-down") << ConsoleControl::Event::Shutdown << true;
    }
    void eachEventQuitsInTheContextsThread()
    {
        QFETCH(ConsoleControl::Event, event);
        QFETCH(bool, holds);
        ConsoleControl::Then then = ConsoleControl::Then::Return;
        std::thread system([&] { then = ConsoleControl::handle(event); });
        system.join();
        QCOMPARE(then == ConsoleControl::Then::HoldUntilExit, holds);
        // Queued, not run on the system's thread.
        QCOMPARE(quits, 0);
        QTRY_COMPARE(quits, 1);
        QCOMPARE(quitThread, QThread::currentThread());
    }

#ifdef Q_OS_WIN
    // The very function SetConsoleCtrlHandler was given.
    void systemHandlerReturnsForCtrlC()
    {
        std::atomic<int> result{-1};
        std::thread system([&] { result = ConsoleControl::systemHandler(CTRL_C_EVENT); });
        system.join();
        QCOMPARE(result.load(), TRUE);
        QTRY_COMPARE(quits, 1);
    }

    void systemHandlerHoldsWhenTheConsoleCloses()
    {
        static std::atomic<bool> returned{false};
        // Detached: it sleeps until this program ends, as it would in the gateway.
        std::thread([] {
            ConsoleControl::systemHandler(CTRL_CLOSE_EVENT);
            returned = true;
        }).detach();
        QTRY_COMPARE(quits, 1);
        QTest::qWait(300);
        QVERIFY2(!returned,
                 "the handler returned: Windows would end the program before its clean stop");
    }

    void systemHandlerLeavesOtherEventsAlone()
    {
        QCOMPARE(ConsoleControl::systemHandler(0x7fff), FALSE);
    }
#endif
};

QTEST_GUILESS_MAIN(tst_ConsoleControl)
#include "tst_consolecontrol.moc"
