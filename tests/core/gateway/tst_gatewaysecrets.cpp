// Issue 55: no password in any message. A distinctive password planted in every place a gateway
// configuration may hold one (the broker URL, refused or not, in forms QUrl cannot read; the
// broker's "password" and password file beside a refused URL; the history store's URL) never
// shows in an error, in `fatek-gateway --check`'s output, in a SIGHUP reload's log line, nor in a
// log line of the in-process Gateway.
#include "core/gateway/gateway.h"
#include "core/gateway/gatewayconfig.h"
#include "core/qtbridge/secrets.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

#include <csignal>

using namespace Fatek;

namespace {

constexpr int Wait = 10000; // QTRY timeouts: generous for a loaded 2-core machine

// Every planted password holds it, after its raw '@', '/' or space: a partly masked password
// shows it too.
const QString Secret = QStringLiteral("Secret1");

const char *const list = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":200,"items":[{"address":"R100"}]}]})json";

QString configJson(const QString &broker, const QString &history = {}, int plcPort = 1)
{
    return QStringLiteral(R"({"format":"fatek-gateway","version":1,"prefix":"fatek","readOnly":true,
      "broker":%1,%2"connections":[{"name":"line1",
      "link":{"kind":"tcp","host":"127.0.0.1","port":%3,"timeoutMs":500,"retries":0},
      "watchLists":[{"file":"line1.json"}]}]})")
        .arg(broker, history.isEmpty() ? QString() : QStringLiteral("\"history\":%1,").arg(history))
        .arg(plcPort);
}

QString urlBroker(const QString &url)
{
    return QStringLiteral(R"({"url":"%1"})").arg(url);
}

} // namespace

class TestGatewaySecrets : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void maskUrl_data();
    void maskUrl();
    void nothingShown_data();
    void nothingShown();
    void reloadLogShowsNone();
    void gatewayLogShowsNone();

private:
    bool writeFile(const QString &name, const QByteArray &content) const;

    QTemporaryDir m_dir;
};

void TestGatewaySecrets::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(writeFile(QStringLiteral("line1.json"), list));
    QVERIFY(writeFile(QStringLiteral("secret.txt"), "TopSecret1\n"));
}

bool TestGatewaySecrets::writeFile(const QString &name, const QByteArray &content) const
{
    QFile file(m_dir.filePath(name));
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(content) >= 0;
}

void TestGatewaySecrets::maskUrl_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QString>("shown");
    QTest::newRow("plain") << "mqtt://gw:TopSecret1@127.0.0.1:0"
                           << "mqtt://gw:***@127.0.0.1:0";
    QTest::newRow("raw @") << "mqtt://gw:Top@Secret1@host"
                           << "mqtt://gw:***@host";
    QTest::newRow("space") << "mqtt://gw:Top Secret1@host/x"
                           << "mqtt://gw:***@host/x";
    QTest::newRow("raw /") << "tcp://gw:Top/Secret1@host"
                           << "tcp://gw:***@host";
    QTest::newRow("no scheme") << " gw:TopSecret1@host:1883"
                               << " gw:***@host:1883";
    QTest::newRow("no user") << "mqtt://:TopSecret1@host"
                             << "mqtt://:***@host";
    QTest::newRow("user only") << "mqtts://gw@host:8883"
                               << "mqtts://gw@host:8883";
    QTest::newRow("no user info") << "mqtt://host:1883"
                                  << "mqtt://host:1883";
    QTest::newRow("parameter") << "postgresql://h/db?sslmode=require&password=TopSecret1&x=1"
                               << "postgresql://h/db?sslmode=require&password=***&x=1";
    QTest::newRow("key=value") << "host=h password='Top Secret1' dbname=db"
                               << "host=h password=*** dbname=db";
}

void TestGatewaySecrets::maskUrl()
{
    QFETCH(QString, url);
    QFETCH(QString, shown);
    QCOMPARE(Secrets::maskUrl(url), shown);
}

void TestGatewaySecrets::nothingShown_data()
{
    QTest::addColumn<QString>("broker");
    QTest::addColumn<QString>("history");
    const auto url = [](const char *name, const char *u) {
        QTest::newRow(name) << urlBroker(QString::fromUtf8(u)) << QString();
    };
    url("url, port 0", "mqtt://gw:TopSecret1@127.0.0.1:0");
    url("url, path", "mqtt://gw:TopSecret1@127.0.0.1:1883/x");
    url("url, tcp://", "tcp://gw:TopSecret1@127.0.0.1:1883");
    url("url, mqtts port 0", "mqtts://gw:TopSecret1@127.0.0.1:0");
    url("url, query", "mqtt://gw:TopSecret1@127.0.0.1?x=1");
    url("url, raw @", "mqtt://gw:Top@Secret1@127.0.0.1:0");
    url("url, raw @ usable port", "mqtt://gw:Top@Secret1@127.0.0.1:1883");
    url("url, space", "mqtt://gw:Top Secret1@127.0.0.1:0");
    url("url, raw /", "mqtt://gw:Top/Secret1@127.0.0.1:0");
    url("url, no scheme", "gw:TopSecret1@127.0.0.1:0");
    url("url, accepted", "mqtt://gw:TopSecret1@127.0.0.1:1883");
    QTest::newRow("password, refused url")
        << R"({"url":"mqtt://gw@127.0.0.1:0","password":"TopSecret1"})" << QString();
    QTest::newRow("password without user")
        << R"({"url":"mqtt://127.0.0.1","password":"TopSecret1"})" << QString();
    QTest::newRow("password file, refused url")
        << R"({"url":"mqtt://gw@127.0.0.1:0","passwordFile":"secret.txt"})" << QString();
    QTest::newRow("password file, accepted")
        << R"({"url":"mqtt://127.0.0.1","username":"gw","passwordFile":"secret.txt"})" << QString();
    const auto store = [](const char *name, const char *s) {
        QTest::newRow(name)
            << urlBroker(QStringLiteral("mqtt://127.0.0.1"))
            << QStringLiteral(R"({"recordAll":true,"store":"%1"})").arg(QString::fromUtf8(s));
    };
    store("store", "postgresql://fatek:TopSecret1@127.0.0.1/plant");
    store("store, raw @", "postgres://fatek:Top@Secret1@127.0.0.1/plant");
    store("store, raw /", "postgresql://fatek:Top/Secret1@127.0.0.1/plant");
    store("store, capitals", "POSTGRESQL://fatek:TopSecret1@127.0.0.1/plant");
    store("store, parameter", "postgresql://127.0.0.1/plant?password=TopSecret1");
}

// Loaded in process and checked by the real program: the error or the summary, never the
// password.
void TestGatewaySecrets::nothingShown()
{
    QFETCH(QString, broker);
    QFETCH(QString, history);
    const QByteArray json = configJson(broker, history).toUtf8();
    const Result<GatewayConfig> config = GatewayConfig::load(json, m_dir.path());
    if (!config) {
        const QString text = QString::fromStdString(config.error().text());
        QVERIFY2(!text.contains(Secret), qPrintable(text));
    }
    const QString path = m_dir.filePath(QStringLiteral("gateway.json"));
    QVERIFY(writeFile(QStringLiteral("gateway.json"), json));
    const TestUtil::ProgramRun run
        = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", path});
    QCOMPARE(run.code, config ? 0 : 2);
    QVERIFY2(!run.out.contains(Secret), qPrintable(run.out));
    QVERIFY2(!run.err.contains(Secret), qPrintable(run.err));
    QVERIFY2(!run.out.isEmpty() || !run.err.isEmpty(), "--check says nothing");
}

// The real program: a reload whose file names the broker with a refused URL logs why, without
// the password.
void TestGatewaySecrets::reloadLogShowsNone()
{
#ifdef Q_OS_UNIX
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    const QString path = m_dir.filePath(QStringLiteral("reload.json"));
    const QString url = QStringLiteral("mqtt://gw:TopSecret1@127.0.0.1:%1").arg(broker.port());
    QVERIFY(writeFile(QStringLiteral("reload.json"), configJson(urlBroker(url)).toUtf8()));
    QProcess process;
    TestUtil::startConsoleProgram(&process, QStringLiteral(FATEK_GATEWAY_PATH), {path});
    QString log;
    const auto logHas = [&](const char *text) {
        log += QString::fromUtf8(process.readAllStandardError());
        return log.contains(QLatin1StringView(text));
    };
    QTRY_VERIFY2_WITH_TIMEOUT(logHas(" connected"), qPrintable(log), Wait);
    QVERIFY(writeFile(
        QStringLiteral("reload.json"),
        configJson(urlBroker(QStringLiteral("mqtt://gw:TopSecret1@127.0.0.1:0"))).toUtf8()));
    QVERIFY(::kill(static_cast<pid_t>(process.processId()), SIGHUP) == 0);
    QTRY_VERIFY2_WITH_TIMEOUT(logHas("not reloaded"), qPrintable(log), Wait);
    TestUtil::stopConsoleProgram(&process);
    QVERIFY(process.waitForFinished(Wait));
    log += QString::fromUtf8(process.readAllStandardError());
    QVERIFY2(log.contains(QStringLiteral("is not a broker address")), qPrintable(log));
    QVERIFY2(!log.contains(Secret), qPrintable(log));
    QVERIFY2(!QString::fromUtf8(process.readAllStandardOutput()).contains(Secret), "stdout");
#else
    QSKIP("SIGHUP: Unix only");
#endif
}

// The in-process Gateway, logging in with a password from the URL and recording history: its
// log lines (started, broker connected, history) never hold the password.
void TestGatewaySecrets::gatewayLogShowsNone()
{
    SimulatedPlc plc(ModelProfile::fbs());
    SimServer server(&plc);
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));
    TestUtil::MosquittoBroker broker;
    QVERIFY2(broker.start(&error), qPrintable(error));
    // A raw '@' is refused (above): percent-encoded here.
    const QString url = QStringLiteral("mqtt://gw:Top%40Secret1@127.0.0.1:%1").arg(broker.port());
    Result<GatewayConfig> config = GatewayConfig::load(
        configJson(urlBroker(url), QStringLiteral(R"({"recordAll":true,"store":"history.db"})"),
                   server.tcpPort())
            .toUtf8(),
        m_dir.path());
    QVERIFY2(config.ok(), config.ok() ? "" : config.error().text().c_str());
    QCOMPARE(config->broker.password, QStringLiteral("Top@Secret1"));
    Gateway gateway;
    QStringList log;
    connect(&gateway, &Gateway::logEvent, this, [&log](const QString &c, const Message &event) {
        log.append(c + QStringLiteral(": ") + QString::fromStdString(english(event)));
    });
    QString failed;
    Message startError;
    QVERIFY2(gateway.start(*config, &failed, &startError),
             qPrintable(QString::fromStdString(english(startError))));
    QTRY_VERIFY2_WITH_TIMEOUT(log.join(u'\n').contains(QStringLiteral(" connected")),
                              qPrintable(log.join(u'\n')), Wait);
    bool stopped = false;
    connect(&gateway, &Gateway::stopped, this, [&stopped] { stopped = true; });
    gateway.stop();
    QTRY_VERIFY_WITH_TIMEOUT(stopped, Wait);
    const QString text = log.join(u'\n');
    QVERIFY2(text.contains(QStringLiteral("started")), qPrintable(text));
    QVERIFY2(!text.contains(Secret), qPrintable(text));
}

QTEST_GUILESS_MAIN(TestGatewaySecrets)
#include "tst_gatewaysecrets.moc"
