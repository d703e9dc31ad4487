// One vocabulary for the link options (issue 32): fatek-cli, fatek-studio and fatek-sim parse
// the same options through the same parser, so the same bad input gets the same usage error
// (exit 2) from each. And the links a script can name: --link URL, @NAME from the named links
// file, FATEK_LINK and FATEK_STATION, against a simulator that answers as station 3.
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

struct Run
{
    int code = -1;
    QString out, err;
};

} // namespace

class TestLinkOptions : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void sameErrorsEverywhere_data();
    void sameErrorsEverywhere();
    void linksByUrlNameAndEnvironment();

private:
    Run run(const QString &program, const QStringList &arguments,
            const QMap<QString, QString> &environment = {});
    QTemporaryDir m_dir;
    QMap<QString, QString> m_environment; // for every run
};

void TestLinkOptions::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("run")));
    QFile::setPermissions(m_dir.filePath(QStringLiteral("run")),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    for (const char *path : {FATEK_CLI_PATH, FATEK_STUDIO_PATH, FATEK_SIM_PATH})
        QVERIFY2(QFile::exists(QString::fromUtf8(path)), path);
}

Run TestLinkOptions::run(const QString &program, const QStringList &arguments,
                         const QMap<QString, QString> &environment)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("HOME"), m_dir.filePath(QStringLiteral("home")));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), m_dir.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("LANGUAGE"), QStringLiteral("en"));
    env.remove(QStringLiteral("FATEK_LINK"));
    env.remove(QStringLiteral("FATEK_STATION"));
    env.remove(QStringLiteral("FATEK_LINKS"));
    for (auto it = m_environment.cbegin(); it != m_environment.cend(); ++it)
        env.insert(it.key(), it.value());
    for (auto it = environment.cbegin(); it != environment.cend(); ++it)
        env.insert(it.key(), it.value());
    env.insert(QStringLiteral("XDG_RUNTIME_DIR"), m_dir.filePath(QStringLiteral("run")));
    p.setProcessEnvironment(env);
    p.start(program, arguments);
    Run r;
    // Waited for with the event loop running: the simulator of the test answers meanwhile.
    QDeadlineTimer deadline(60000);
    while (p.state() != QProcess::NotRunning && !deadline.hasExpired())
        QTest::qWait(20);
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished(5000);
        r.err = QStringLiteral("did not finish: ") + p.errorString();
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

void TestLinkOptions::sameErrorsEverywhere_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::addColumn<bool>("simToo"); // the serial line's options: fatek-sim takes them too
    auto row = [](const char *name, const QStringList &args, const char *message, bool simToo) {
        QTest::newRow(name) << args << QString::fromUtf8(message) << simToo;
    };
    const QString dev = QStringLiteral("/dev/fatek-no-such-port");
    row("bad parity",
        {QStringLiteral("--serial"), dev, QStringLiteral("--parity"), QStringLiteral("X")},
        "--parity takes N, E or O, not \"X\".", true);
    row("bad data bits",
        {QStringLiteral("--serial"), dev, QStringLiteral("--data"), QStringLiteral("9")},
        "--data takes 7 or 8, not \"9\".", true);
    row("bad stop bits",
        {QStringLiteral("--serial"), dev, QStringLiteral("--stop"), QStringLiteral("3")},
        "--stop takes 1 or 2, not \"3\".", true);
    row("bad speed",
        {QStringLiteral("--serial"), dev, QStringLiteral("--baud"), QStringLiteral("fast")},
        "--baud needs a speed like 9600, not \"fast\".", true);
    row("empty serial port", {QStringLiteral("--serial"), QString()},
        "--serial needs a port, such as /dev/ttyUSB0 or COM3.", true);
    row("empty tcp", {QStringLiteral("--tcp"), QString()},
        "--tcp needs HOST or HOST:PORT (port 1..65535; IPv6 in brackets), not \"\".", false);
    row("url in --tcp", {QStringLiteral("--tcp"), QStringLiteral("tcp://plc1:500")},
        "--tcp needs HOST or HOST:PORT, not a URL (\"tcp://plc1:500\"): write --link "
        "tcp://plc1:500.",
        false);
    row("three parts", {QStringLiteral("--tcp"), QStringLiteral("plc1:500:5")},
        "--tcp needs HOST or HOST:PORT (port 1..65535; IPv6 in brackets), not \"plc1:500:5\".",
        false);
    row("unknown scheme", {QStringLiteral("--link"), QStringLiteral("modbus://plc1")},
        "--link: Link \"modbus://plc1\": start it with tcp://, udp:// or serial://", false);
    row("unknown setting", {QStringLiteral("--link"), QStringLiteral("tcp://plc1?speed=9600")},
        "--link: Link \"tcp://plc1?speed=9600\": no setting \"speed\" (this link takes protocol, "
        "timeout, retries, station).",
        false);
    row("bad format", {QStringLiteral("--link"), QStringLiteral("serial:///dev/ttyS0?format=9X1")},
        "takes data bits, parity and stop bits such as 7E1 or 8N1, not \"9X1\".", false);
    row("two links",
        {QStringLiteral("--link"), QStringLiteral("tcp://a"), QStringLiteral("--tcp"),
         QStringLiteral("b")},
        "Give only one of --link, --tcp, --udp, --serial and ", false);
    row("serial option on tcp",
        {QStringLiteral("--link"), QStringLiteral("tcp://a"), QStringLiteral("--parity"),
         QStringLiteral("N")},
        "--baud, --parity, --data and --stop only apply to a serial link.", false);
    row("unknown name", {QStringLiteral("--link"), QStringLiteral("@line9")},
        "--link: no link named \"line9\"", false);
}

void TestLinkOptions::sameErrorsEverywhere()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QFETCH(bool, simToo);
    struct Program
    {
        QString path, prefix;
        QStringList extra;
    };
    QList<Program> programs{
        {QStringLiteral(FATEK_CLI_PATH), QStringLiteral("fatek-cli: "), {QStringLiteral("status")}},
        {QStringLiteral(FATEK_STUDIO_PATH), QStringLiteral("fatek-studio: "), {}},
    };
    if (simToo)
        programs.append({QStringLiteral(FATEK_SIM_PATH), QStringLiteral("fatek-sim: "), {}});
    for (const Program &program : programs) {
        const Run r = run(program.path, arguments + program.extra);
        const QString what = program.prefix + r.err;
        QVERIFY2(r.code == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.code).arg(what)));
        QVERIFY2(r.err.startsWith(program.prefix), qPrintable(what));
        QVERIFY2(r.err.contains(message), qPrintable(what));
    }
}

void TestLinkOptions::linksByUrlNameAndEnvironment()
{
    SimulatedPlc plc(ModelProfile::fbs());
    QVERIFY(plc.setValue(Address::parse("R7").value(), 4242));
    SimServer server(&plc);
    server.setStation(3);
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));
    const QString url = QStringLiteral("tcp://127.0.0.1:%1?station=3&protocol=facon&timeout=500")
                            .arg(server.tcpPort());
    const QString cli = QStringLiteral(FATEK_CLI_PATH);
    const QStringList read{QStringLiteral("--json"), QStringLiteral("read"), QStringLiteral("R7")};
    auto readsValue = [](const Run &r) {
        return r.code == 0 && r.out.contains(QLatin1String("\"values\":[4242]"));
    };
    Run r = run(cli, QStringList{QStringLiteral("--link"), url} + read);
    QVERIFY2(readsValue(r), qPrintable(r.out + r.err));

    // A named link, from the file in the user's configuration folder.
    QDir(m_dir.path()).mkpath(QStringLiteral("config/fatek-studio"));
    QFile links(m_dir.filePath(QStringLiteral("config/fatek-studio/links.conf")));
    QVERIFY(links.open(QIODevice::WriteOnly | QIODevice::Text));
    links.write("# the test bench\nbench = " + url.toUtf8() + "   # station 3\nother = tcp://a\n");
    links.close();
#ifdef Q_OS_WIN
    // Windows keeps it in %LOCALAPPDATA%, which the test cannot move: name the file instead.
    m_environment.insert(QStringLiteral("FATEK_LINKS"), links.fileName());
#endif
    r = run(cli, QStringList{QStringLiteral("--link"), QStringLiteral("@bench")} + read);
    QVERIFY2(readsValue(r), qPrintable(r.out + r.err));
    r = run(cli, QStringList{QStringLiteral("--link"), QStringLiteral("@nope")} + read);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QLatin1String("(it names bench, other)")), qPrintable(r.err));

    // The environment: FATEK_LINK as a URL or a name; FATEK_STATION when --station is not given,
    // and --station over both.
    const QString plain
        = QStringLiteral("tcp://127.0.0.1:%1?protocol=facon&timeout=500").arg(server.tcpPort());
    r = run(cli, read,
            {{QStringLiteral("FATEK_LINK"), plain},
             {QStringLiteral("FATEK_STATION"), QStringLiteral("3")}});
    QVERIFY2(readsValue(r), qPrintable(r.out + r.err));
    r = run(cli, read, {{QStringLiteral("FATEK_LINK"), QStringLiteral("@bench")}});
    QVERIFY2(readsValue(r), qPrintable(r.out + r.err));
    r = run(cli, QStringList{QStringLiteral("--station"), QStringLiteral("4")} + read,
            {{QStringLiteral("FATEK_LINK"), QStringLiteral("@bench")}});
    QCOMPARE(r.code, 3); // station 4: nobody answers
    r = run(cli, read,
            {{QStringLiteral("FATEK_LINK"), plain},
             {QStringLiteral("FATEK_STATION"), QStringLiteral("x")}});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QLatin1String("FATEK_STATION takes 0..254, not \"x\".")),
             qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestLinkOptions)
#include "tst_linkoptions.moc"
