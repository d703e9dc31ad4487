// What fatek-cli, fatek-sim and fatek-gateway say to a script (issue 56, items 1, 3 and 10-15):
// the checkout's answers from standard input, a restore stopped while it compares, timeouts that
// name the link and count the retries in force, unknown options said alike by every program,
// named links that are refused when the file is wrong. The built programs, against fatek-sim
// children or the embedded simulator.
#include "simchild.h"
#include "testutil.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

namespace {

using Run = TestUtil::ProgramRun;

Run run(const QString &program, const QStringList &arguments, const QByteArray &input = {},
        const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
{
    return TestUtil::runProgramWith(program, arguments, input, env);
}

Run cli(const QStringList &arguments, const QByteArray &input = {})
{
    return run(QStringLiteral(FATEK_CLI_PATH), arguments, input);
}

QJsonObject checkoutFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(f.readAll()).object()
                                       : QJsonObject();
}

// The checkout file's result of each point, "untested", "passed"...
QStringList results(const QString &path)
{
    QStringList out;
    for (const QJsonValue &v : checkoutFile(path).value(QStringLiteral("points")).toArray())
        out << v.toObject().value(QStringLiteral("result")).toString();
    return out;
}

// A UDP port on loopback that nobody answers on (bound by the test, never read).
struct SilentUdp
{
    QUdpSocket socket;
    quint16 port()
    {
        if (socket.state() != QAbstractSocket::BoundState)
            socket.bind(QHostAddress::LocalHost, 0);
        return socket.localPort();
    }
};

} // namespace

class TestCliMessages : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void checkoutMissingAnswersStayUntested_data();
    void checkoutMissingAnswersStayUntested();
    void checkoutCommentKeptAsTyped();
    void restoreStoppedWhileComparing();
    void timeoutNamesLinkAndRetries();
    void monitorEndsWithoutPromisingMore();
    void unknownOptionsSaidAlike_data();
    void unknownOptionsSaidAlike();
    void qtProgramsHelp();
    void simulatorCannotListenExit1();
    void namedLinksRefuseJunkAndDuplicates();
    void emptyNamesListSaid();

private:
    QTemporaryDir m_dir;
};

void TestCliMessages::checkoutMissingAnswersStayUntested_data()
{
    QTest::addColumn<QByteArray>("answers");
    QTest::addColumn<QStringList>("expected");
    const QString u = QStringLiteral("untested");
    QTest::newRow("two answers, then the end")
        << QByteArray("y\nn\n")
        << QStringList{QStringLiteral("passed"), QStringLiteral("failed"), u, u};
    QTest::newRow("no input") << QByteArray() << QStringList{u, u, u, u};
    QTest::newRow("empty lines") << QByteArray("\n\n\n") << QStringList{u, u, u, u};
}

// Item 1: an output nobody answered for (the end of input, empty lines) stays untested, with no
// time, and a resumed run tests it.
void TestCliMessages::checkoutMissingAnswersStayUntested()
{
    QFETCH(QByteArray, answers);
    QFETCH(QStringList, expected);
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("c.json"));
    const QString report = dir.filePath(QStringLiteral("e.csv"));
    const Run r = cli({QStringLiteral("--sim"), QStringLiteral("--yes"), QStringLiteral("checkout"),
                       QStringLiteral("Y0..Y3"), QStringLiteral("--save"), file,
                       QStringLiteral("--report"), report},
                      answers);
    QCOMPARE(r.code, 6);
    QCOMPARE(results(file), expected);
    for (const QJsonValue &v : checkoutFile(file).value(QStringLiteral("points")).toArray()) {
        if (v.toObject().value(QStringLiteral("result")).toString() == QLatin1String("untested"))
            QVERIFY(!v.toObject().contains(QStringLiteral("time")));
    }
    QFile csv(report);
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(csv.readAll());
    QVERIFY2(!text.contains(QLatin1String("Y2,,Y0-3,Output,Failed")), qPrintable(text));
    // Resumed: the untested ones are asked again.
    const Run resumed
        = cli({QStringLiteral("--sim"), QStringLiteral("--yes"), QStringLiteral("checkout"), file},
              "y\ny\ny\ny\n");
    const int untested = static_cast<int>(expected.count(QStringLiteral("untested")));
    QCOMPARE(resumed.err.count(QLatin1String("is ON now")), untested);
}

// Item 3: a comment is kept as typed (case and all) in the file and the report.
void TestCliMessages::checkoutCommentKeptAsTyped()
{
    const QString file = m_dir.filePath(QStringLiteral("comment.json"));
    const QString report = m_dir.filePath(QStringLiteral("comment.csv"));
    const Run r = cli({QStringLiteral("--sim"), QStringLiteral("--yes"), QStringLiteral("checkout"),
                       QStringLiteral("Y3"), QStringLiteral("--save"), file,
                       QStringLiteral("--report"), report},
                      "n Wire loose on Y3\n");
    QCOMPARE(r.code, 6);
    const QJsonObject point
        = checkoutFile(file).value(QStringLiteral("points")).toArray().at(0).toObject();
    QCOMPARE(point.value(QStringLiteral("comment")).toString(), QStringLiteral("Wire loose on Y3"));
    QFile csv(report);
    QVERIFY(csv.open(QIODevice::ReadOnly));
    QVERIFY(csv.readAll().contains("Wire loose on Y3"));
}

// Item 10: Ctrl-C while a restore still compares: "nothing was written", and no page named as
// where it stopped (the JSON said "stoppedAtPage":191 beside it).
void TestCliMessages::restoreStoppedWhileComparing()
{
#ifndef Q_OS_UNIX
    QSKIP("SIGINT: Unix");
#else
    TestUtil::SimChild simulator;
    QString error;
    QVERIFY2(simulator.start(QStringLiteral(FATEK_SIM_PATH), true, {}, &error), qPrintable(error));
    const QString backup = m_dir.filePath(QStringLiteral("program.json"));
    QCOMPARE(cli(simulator.link() + QStringList{QStringLiteral("backup"), backup}).code, 0);
    // A slow PLC: every answer 30 ms late, so the compare of every page takes seconds.
    TestUtil::SimChild slow;
    QVERIFY2(slow.start(QStringLiteral(FATEK_SIM_PATH), true,
                        {QStringLiteral("--latency"), QStringLiteral("30")}, &error),
             qPrintable(error));
    QProcess p;
    p.start(QStringLiteral(FATEK_CLI_PATH),
            slow.link()
                + QStringList{QStringLiteral("--json"), QStringLiteral("--yes"),
                              QStringLiteral("restore"), backup});
    QVERIFY(p.waitForStarted(10000));
    QTest::qWait(2000); // well into the compare (some 200 pages)
    ::kill(static_cast<pid_t>(p.processId()), SIGINT);
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 130);
    const QString out = QString::fromUtf8(p.readAllStandardOutput()).trimmed();
    const QJsonObject json
        = QJsonDocument::fromJson(out.split(QLatin1Char('\n')).last().toUtf8()).object();
    QCOMPARE(json.value(QStringLiteral("error")).toString(),
             QStringLiteral("Cancelled before anything was written."));
    QVERIFY2(!json.contains(QStringLiteral("stoppedAtPage")), qPrintable(out));
    QCOMPARE(json.value(QStringLiteral("writeStarted")).toBool(true), false);
#endif
}

// Item 11: a timeout names the link, and counts the attempts the retries in force give (2 by
// default: attempt 3 of 3), also while the protocol is still being detected.
void TestCliMessages::timeoutNamesLinkAndRetries()
{
    SilentUdp silent;
    const QString link = QStringLiteral("127.0.0.1:%1").arg(silent.port());
    const Run r = cli({QStringLiteral("--udp"), link, QStringLiteral("--timeout"),
                       QStringLiteral("100"), QStringLiteral("read"), QStringLiteral("R0")});
    QCOMPARE(r.code, 3);
    QVERIFY2(r.err.contains(QStringLiteral("udp://") + link), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("attempt 3 of 3")), qPrintable(r.err));
    const Run once
        = cli({QStringLiteral("--udp"), link, QStringLiteral("--timeout"), QStringLiteral("100"),
               QStringLiteral("--retries"), QStringLiteral("0"), QStringLiteral("--protocol"),
               QStringLiteral("facon"), QStringLiteral("read"), QStringLiteral("R0")});
    QCOMPARE(once.code, 3);
    QVERIFY2(once.err.contains(QStringLiteral("udp://") + link)
                 && once.err.contains(QLatin1String("attempt 1 of 1")),
             qPrintable(once.err));
}

// Item 11: a monitor that ends because nothing is read does not end with "polled again at ...".
void TestCliMessages::monitorEndsWithoutPromisingMore()
{
    SilentUdp silent;
    const QString link = QStringLiteral("127.0.0.1:%1").arg(silent.port());
    const Run r = cli({QStringLiteral("--udp"), link, QStringLiteral("--protocol"),
                       QStringLiteral("facon"), QStringLiteral("--timeout"), QStringLiteral("100"),
                       QStringLiteral("--retries"), QStringLiteral("0"), QStringLiteral("monitor"),
                       QStringLiteral("R0"), QStringLiteral("--interval"), QStringLiteral("100")});
    QCOMPARE(r.code, 3);
    const QStringList lines = r.err.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(!lines.isEmpty());
    QVERIFY2(lines.last().startsWith(QLatin1String("fatek-cli: Nothing read for 3 cycles")),
             qPrintable(r.err));
    QVERIFY2(!lines.last().contains(QLatin1String("polled again")), qPrintable(r.err));
}

void TestCliMessages::unknownOptionsSaidAlike_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("option");
    QTest::newRow("fatek-cli --frobnicate")
        << QStringLiteral(FATEK_CLI_PATH) << QStringLiteral("--frobnicate");
    QTest::newRow("fatek-cli -x") << QStringLiteral(FATEK_CLI_PATH) << QStringLiteral("-x");
    QTest::newRow("fatek-sim --frobnicate")
        << QStringLiteral(FATEK_SIM_PATH) << QStringLiteral("--frobnicate");
    QTest::newRow("fatek-sim --help-all")
        << QStringLiteral(FATEK_SIM_PATH) << QStringLiteral("--help-all");
    QTest::newRow("fatek-gateway --frobnicate")
        << QStringLiteral(FATEK_GATEWAY_PATH) << QStringLiteral("--frobnicate");
    QTest::newRow("fatek-gateway --help-all")
        << QStringLiteral(FATEK_GATEWAY_PATH) << QStringLiteral("--help-all");
}

// Item 12: every program refuses an unknown option in the same words, with exit 2.
void TestCliMessages::unknownOptionsSaidAlike()
{
    QFETCH(QString, program);
    QFETCH(QString, option);
    const Run r = run(program, {option});
    QCOMPARE(r.code, 2);
    const QString name = QFileInfo(program).fileName();
    QVERIFY2(
        r.err.startsWith(QStringLiteral("%1: Unknown option %2 (see --help).").arg(name, option)),
        qPrintable(r.err));
}

// Item 12: --help names the program, not the path it was started by, and lists no --help-all.
void TestCliMessages::qtProgramsHelp()
{
    for (const QString &program :
         {QStringLiteral(FATEK_SIM_PATH), QStringLiteral(FATEK_GATEWAY_PATH)}) {
        const QString name = QFileInfo(program).fileName();
        const QString viaPath = QFileInfo(program).absolutePath() + QStringLiteral("/../")
                                + QFileInfo(program).dir().dirName() + QLatin1Char('/') + name;
        const Run r = run(viaPath, {QStringLiteral("--help")});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("Usage: %1 ").arg(name)), qPrintable(r.out));
        QVERIFY2(!r.out.contains(QLatin1String("--help-all")), qPrintable(r.out));
        const Run v = run(program, {QStringLiteral("--version")});
        QCOMPARE(v.code, 0);
        QVERIFY2(v.out.startsWith(name + QLatin1Char(' ')), qPrintable(v.out));
    }
}

// Item 12: a simulator that cannot listen is exit 1 (docs/cli.md's table), as fatek-cli --sim.
void TestCliMessages::simulatorCannotListenExit1()
{
    QTcpServer taken;
    QVERIFY(taken.listen(QHostAddress::LocalHost, 0));
    const Run r = run(QStringLiteral(FATEK_SIM_PATH),
                      {QStringLiteral("--tcp"), QString::number(taken.serverPort())});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.startsWith(QLatin1String("fatek-sim: ")), qPrintable(r.err));
}

// Item 15: links.conf with a line that is not NAME = URL, or a name given twice: @NAME is
// refused naming the line, not resolved silently by the first match.
void TestCliMessages::namedLinksRefuseJunkAndDuplicates()
{
    const QString junk = m_dir.filePath(QStringLiteral("junk.conf"));
    const QString twice = m_dir.filePath(QStringLiteral("twice.conf"));
    QFile j(junk);
    QVERIFY(j.open(QIODevice::WriteOnly));
    j.write("# plant\npress = tcp://127.0.0.1:9\nthis line is junk\n");
    j.close();
    QFile t(twice);
    QVERIFY(t.open(QIODevice::WriteOnly));
    t.write("press = tcp://127.0.0.1:9\noven = tcp://127.0.0.1:10\npress = udp://127.0.0.1:11\n");
    t.close();
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("FATEK_LINKS"), junk);
    const QStringList args{QStringLiteral("--link"), QStringLiteral("@press"),
                           QStringLiteral("read"), QStringLiteral("R0")};
    const Run r = run(QStringLiteral(FATEK_CLI_PATH), args, {}, env);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QLatin1String("line 3")) && r.err.contains(QLatin1String("junk")),
             qPrintable(r.err));
    env.insert(QStringLiteral("FATEK_LINKS"), twice);
    const Run d = run(QStringLiteral(FATEK_CLI_PATH), args, {}, env);
    QCOMPARE(d.code, 2);
    QVERIFY2(d.err.contains(QLatin1String("line 3")) && d.err.contains(QLatin1String("again")),
             qPrintable(d.err));
}

// Item 15: monitor --names with an empty list says that it names nothing.
void TestCliMessages::emptyNamesListSaid()
{
    const QString empty = m_dir.filePath(QStringLiteral("names.csv"));
    QFile f(empty);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.close();
    const Run r
        = cli({QStringLiteral("--sim"), QStringLiteral("monitor"), QStringLiteral("R0"),
               QStringLiteral("--cycles"), QStringLiteral("1"), QStringLiteral("--names"), empty});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.err.contains(empty) && r.err.contains(QLatin1String("names no address")),
             qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestCliMessages)
#include "tst_cli_messages.moc"
