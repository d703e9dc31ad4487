// fatek-studio started from the command line, as an operator's desktop shortcut does: the built
// executable run with QProcess (offscreen) with fatek-cli's link options and a watch-list FILE,
// against a simulator served over loopback TCP by this test. Also the usage errors (exit 2 before
// any window) and a FILE that cannot be loaded (reported, the window carries on).
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace Fatek;

namespace {

struct Run
{
    int code = -1;
    QString out;
    QString err;
};

} // namespace

class TestStudioStartup : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void help();
    void helpAndVersionWithoutDisplay_data();
    void helpAndVersionWithoutDisplay();
    void usageErrors_data();
    void usageErrors();
    void opensLinkAndWatchList();
    void unreadableWatchListKeepsRunning_data();
    void unreadableWatchListKeepsRunning();

private:
    // Starts fatek-studio and waits (running this thread's event loop, so the simulator of the
    // test answers meanwhile) until it has ended.
    // `headless`: as over SSH, no DISPLAY, no WAYLAND_DISPLAY and no QT_QPA_PLATFORM.
    Run runStudio(const QStringList &arguments, int timeoutMs = 120000, bool headless = false);
    QString writeFile(const QString &name, const QByteArray &content);

    QTemporaryDir m_dir;
};

void TestStudioStartup::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY2(QFileInfo::exists(QStringLiteral(FATEK_STUDIO_PATH)), FATEK_STUDIO_PATH);
    QDir(m_dir.path()).mkpath(QStringLiteral("home/.config"));
    QDir(m_dir.path()).mkpath(QStringLiteral("run"));
    QFile::setPermissions(m_dir.filePath(QStringLiteral("run")),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
}

Run TestStudioStartup::runStudio(const QStringList &arguments, int timeoutMs, bool headless)
{
    QProcess p;
    // The developer's own settings (recent connections, last watch list) stay out of the test.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("HOME"), m_dir.filePath(QStringLiteral("home")));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), m_dir.filePath(QStringLiteral("home/.config")));
    env.insert(QStringLiteral("XDG_RUNTIME_DIR"), m_dir.filePath(QStringLiteral("run")));
    env.insert(QStringLiteral("LANGUAGE"), QStringLiteral("en"));
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C.UTF-8"));
    if (headless) {
        for (const char *name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            env.remove(QLatin1String(name));
    }
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(FATEK_STUDIO_PATH), arguments);
    Run r;
    if (!p.waitForStarted(30000)) {
        r.err = QStringLiteral("fatek-studio did not start: ") + p.errorString();
        return r;
    }
    QDeadlineTimer deadline(timeoutMs);
    while (p.state() != QProcess::NotRunning && !deadline.hasExpired())
        QTest::qWait(50);
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished(10000);
        r.code = -3;
    } else {
        r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    }
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QString TestStudioStartup::writeFile(const QString &name, const QByteArray &content)
{
    const QString path = m_dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return {};
    f.write(content);
    return path;
}

void TestStudioStartup::help()
{
    const Run r = runStudio({QStringLiteral("--help")}, 60000);
    QCOMPARE(r.code, 0);
    for (const char *option :
         {"--link", "--tcp", "--udp", "--serial", "--baud", "--parity", "--data", "--stop",
          "--protocol", "--station", "--timeout", "--retries", "--demo", "--read-only",
          "--screenshot", "--language", "[file]"})
        QVERIFY2(r.out.contains(QLatin1String(option)), qPrintable(option + (": " + r.out)));
}

// Issue 54 item 9: over SSH (no display at all) --help and --version answered, exit 0; they
// aborted in the platform plugin (rc 134, "Could not load the Qt platform plugin").
void TestStudioStartup::helpAndVersionWithoutDisplay_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("expected");
    QTest::newRow("--help") << QStringList{QStringLiteral("--help")} << QStringLiteral("--tcp");
    QTest::newRow("-h") << QStringList{QStringLiteral("-h")} << QStringLiteral("--demo");
    QTest::newRow("--help-all") << QStringList{QStringLiteral("--help-all")}
                                << QStringLiteral("--read-only");
    QTest::newRow("--version") << QStringList{QStringLiteral("--version")}
                               << QStringLiteral("fatek-studio " FATEK_VERSION);
    QTest::newRow("--language zh_TW --help")
        << QStringList{QStringLiteral("--language"), QStringLiteral("zh_TW"),
                       QStringLiteral("--help")}
        << QStringLiteral("--serial");
}

void TestStudioStartup::helpAndVersionWithoutDisplay()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, expected);
    const Run r = runStudio(arguments, 60000, true);
    QVERIFY2(r.code == 0, qPrintable(QStringLiteral("rc %1: %2").arg(r.code).arg(r.err)));
    QVERIFY2(r.out.contains(expected), qPrintable(r.out));
}

void TestStudioStartup::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    auto row = [](const char *name, const QString &args, const QString &message) {
        QTest::newRow(name) << args.split(QLatin1Char(' ')) << message;
    };
    row("missing value", QStringLiteral("--tcp"), QStringLiteral("Missing value after '--tcp'"));
    row("bad port", QStringLiteral("--tcp 127.0.0.1:99999"),
        QStringLiteral("--tcp needs HOST or HOST:PORT (port 1..65535; IPv6 in brackets), not "
                       "\"127.0.0.1:99999\"."));
    row("two links", QStringLiteral("--tcp plc1 --udp plc2"),
        QStringLiteral("Give only one of --link, --tcp, --udp, --serial and --demo."));
    row("demo and link", QStringLiteral("--demo --tcp 127.0.0.1"),
        QStringLiteral("Give only one of --link, --tcp, --udp, --serial and --demo."));
    row("demo and station", QStringLiteral("--demo --station 3"),
        QStringLiteral("--demo runs its own simulator"));
    row("station without link", QStringLiteral("--station 3"),
        QStringLiteral(
            "--protocol, --station, --timeout, --retries and the serial options need a link"));
    row("broadcast station", QStringLiteral("--tcp plc1 --station 0"),
        QStringLiteral("--station takes 1..254, not \"0\"."));
    row("baud without serial", QStringLiteral("--tcp plc1 --baud 9600"),
        QStringLiteral("--baud, --parity, --data and --stop only apply to a serial link."));
    row("bad parity", QStringLiteral("--serial /dev/ttyUSB0 --parity X"),
        QStringLiteral("--parity takes N, E or O, not \"X\"."));
    row("bad protocol", QStringLiteral("--tcp plc1 --protocol modbus"),
        QStringLiteral("--protocol takes facon, binary or auto, not \"modbus\"."));
    row("bad timeout", QStringLiteral("--tcp plc1 --timeout 5"),
        QStringLiteral("--timeout takes 10..60000 ms, not \"5\"."));
    row("bad retries", QStringLiteral("--tcp plc1 --retries 11"),
        QStringLiteral("--retries takes 0..10, not \"11\"."));
    row("two files", QStringLiteral("a.json b.json"),
        QStringLiteral("give at most one watch-list file"));
    row("unknown option", QStringLiteral("--bogus"), QStringLiteral("Unknown option 'bogus'"));
}

// A bad command line: exit 2 with the reason on stderr, before any window (nothing connects).
void TestStudioStartup::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const Run r = runStudio(arguments, 60000);
    QVERIFY2(r.code == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.code).arg(r.err)));
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY2(r.err.startsWith(QLatin1String("fatek-studio: ")), qPrintable(r.err));
}

// The shortcut's command line: the connection opens at start, the FILE's tables poll it, values
// arrive (the screenshot waits for them and says when none came), from station 7 of this
// simulator for exactly the listed elements.
void TestStudioStartup::opensLinkAndWatchList()
{
    SimulatedPlc plc(ModelProfile::fbs());
    QVERIFY(plc.setValue(Address::parse("R100").value(), 4321));
    QVERIFY(plc.setValue(Address::parse("D20").value(), 77));
    SimServer server(&plc);
    server.setStation(7);
    server.setVerbose(true);
    QStringList log;
    connect(&server, &SimServer::logLine, this, [&log](const QString &line) { log << line; });
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));

    const QString list
        = writeFile(QStringLiteral("line3.json"),
                    R"({"format":"fatek-studio-watchlist","version":1,"tables":[{"name":"Line 3",
            "intervalMs":200,"items":[{"address":"R100","station":7,"name":"Tank level"},
            {"address":"D20","station":7,"name":"Speed"}]}]})");
    QVERIFY(!list.isEmpty());
    const QString shot = m_dir.filePath(QStringLiteral("line3.png"));
    const Run r
        = runStudio({QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(server.tcpPort()),
                     QStringLiteral("--station"), QStringLiteral("7"),
                     QStringLiteral("--screenshot"), shot, list});
    QVERIFY2(r.code == 0, qPrintable(QStringLiteral("exit %1: %2").arg(r.code).arg(r.err)));
    QVERIFY2(!r.err.contains(QLatin1String("no values arrived")), qPrintable(r.err));
    QVERIFY(QFileInfo(shot).size() > 0);

    // Reads of the listed elements, addressed to station 7, answered.
    auto readOf = [&log](const QString &address) {
        for (const QString &line : log) {
            if (line.contains(QLatin1String("read ")) && line.contains(address)
                && line.contains(QLatin1String("(station 7) -> OK")))
                return true;
        }
        return false;
    };
    const QString joined = log.join(QLatin1Char('\n'));
    QVERIFY2(readOf(QStringLiteral("R100")), qPrintable(joined));
    QVERIFY2(readOf(QStringLiteral("D20")), qPrintable(joined));
    QVERIFY2(server.counters().otherStation == 0, qPrintable(joined));
}

void TestStudioStartup::unreadableWatchListKeepsRunning_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("content");
    QTest::newRow("missing") << QStringLiteral("missing.json") << QByteArray();
    QTest::newRow("not a watch list")
        << QStringLiteral("broken.json") << QByteArray("{\"format\":\"something else\"}");
}

// The window starts anyway (the screenshot is taken) and says which file could not be loaded.
void TestStudioStartup::unreadableWatchListKeepsRunning()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, content);
    const QString path = content.isEmpty() ? m_dir.filePath(name) : writeFile(name, content);
    const QString shot = m_dir.filePath(name + QStringLiteral(".png"));
    const Run r = runStudio({QStringLiteral("--screenshot"), shot, path});
    QVERIFY2(r.code == 0, qPrintable(QStringLiteral("exit %1: %2").arg(r.code).arg(r.err)));
    QVERIFY2(r.err.contains(QStringLiteral("%1 cannot be loaded").arg(path)), qPrintable(r.err));
    QVERIFY(QFileInfo(shot).size() > 0);
}

QTEST_GUILESS_MAIN(TestStudioStartup)
#include "tst_studio_startup.moc"
