// fatek-cli alarms (issue 50), the real program against a fatek-sim child running its demo ladder
// (R1 a sine of amplitude 1000 over 10 s): the high alarm raised and returned, printed as text and
// JSON, ended by SIGINT with exit 0, the journal read back as CSV; and its refusals with their exit
// codes.

#include "simchild.h"
#include "testutil.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

namespace {

const char *const WatchList = R"({"format":"fatek-studio-watchlist","version":1,"tables":[
 {"name":"Main","intervalMs":100,"items":[
  {"address":"R1","format":"signed","name":"Sine","alarms":[
   {"type":"high","limit":500,"priority":"critical","message":"Sine high","group":"Demo"}]},
  {"address":"R0","format":"unsigned"}]}]}
)";

struct Run
{
    int code = -1;
    QByteArray out, err;
};

Run runCli(const QStringList &arguments)
{
    QProcess process;
    process.start(QStringLiteral(FATEK_CLI_PATH), arguments);
    Run run;
    if (!process.waitForFinished(30000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

} // namespace

class TestCliAlarms : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString write(const char *name, const QByteArray &text)
    {
        QFile file(m_dir.filePath(QLatin1String(name)));
        if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size())
            qWarning("cannot write %s", name);
        return file.fileName();
    }

    // The watch until the first "raised" and the "returned" after it, then SIGINT.
    void watchUntilReturned(const QStringList &extra, QByteArray *out)
    {
        TestUtil::SimChild sim;
        QString error;
        QVERIFY2(sim.start(QStringLiteral(FATEK_SIM_PATH), false, {QStringLiteral("--demo-ladder")},
                           &error),
                 qPrintable(error));
        QProcess cli;
        cli.start(QStringLiteral(FATEK_CLI_PATH),
                  QStringList{QStringLiteral("alarms"), write("plant.json", WatchList)} + sim.link()
                      + extra);
        QVERIFY(cli.waitForStarted());
        // The sine crosses 500 once per 10 s and stays above for about 3.3 s.
        QTRY_VERIFY_WITH_TIMEOUT((*out += cli.readAllStandardOutput()).contains("returned"), 30000);
#ifdef Q_OS_UNIX
        ::kill(static_cast<pid_t>(cli.processId()), SIGINT); // Ctrl-C
#else
        TestUtil::stopConsoleProgram(&cli); // Ctrl-Break
#endif
        QVERIFY(cli.waitForFinished(10000));
        *out += cli.readAllStandardOutput();
        QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
    }

    void watchesPrintsAndJournals()
    {
        const QString journal = m_dir.filePath(QStringLiteral("alarms.db"));
        QByteArray out;
        watchUntilReturned({QStringLiteral("--journal"), journal}, &out);
        if (QTest::currentTestFailed())
            return;
        const QList<QByteArray> lines = out.trimmed().split('\n');
        qsizetype raised = -1;
        for (qsizetype i = 0; i < lines.size() && raised < 0; ++i) {
            if (lines[i].contains(
                    "  raised  1-R1-high  activeUnacked  critical  Sine high  value "))
                raised = i;
        }
        QVERIFY2(raised >= 0, out.constData());
        QVERIFY2(raised + 1 < lines.size()
                     && lines[raised + 1].contains(
                         "  returned  1-R1-high  returnedUnacked  critical  Sine high  value "),
                 out.constData());

        // Read back: every line printed is in the journal (the watch ended by SIGINT wrote all).
        const Run csv
            = runCli({QStringLiteral("alarms"), QStringLiteral("--journal"), journal,
                      QStringLiteral("--since"), QStringLiteral("-1h"), QStringLiteral("--csv")});
        QCOMPARE(csv.code, 0);
        const QList<QByteArray> rows = csv.out.trimmed().split('\n');
        QCOMPARE(rows.value(0), QByteArray("time,connection,alarm,kind,event,state,priority,group,"
                                           "message,value,user,comment,shelved until"));
        QCOMPARE(rows.size(), lines.size() + 1);
        QVERIFY2(
            rows.value(raised + 1)
                .contains(",plant,1-R1-high,high,raised,activeUnacked,critical,Demo,Sine high,"),
            csv.out.constData());
        // The same time as printed, to the millisecond with its offset.
        QCOMPARE(rows.value(raised + 1).split(',').value(0), lines[raised].split(' ').value(0));

        const Run json = runCli({QStringLiteral("alarms"), QStringLiteral("--journal"), journal,
                                 QStringLiteral("--connection"), QStringLiteral("plant"),
                                 QStringLiteral("--json")});
        QCOMPARE(json.code, 0);
        const QJsonObject first
            = QJsonDocument::fromJson(json.out.split('\n').value(raised)).object();
        QCOMPARE(first.value(QStringLiteral("event")).toString(), QStringLiteral("raised"));
        QCOMPARE(first.value(QStringLiteral("alarm")).toString(), QStringLiteral("1-R1-high"));
        QVERIFY(first.value(QStringLiteral("value")).toString().toInt() >= 500);

        // Nothing of another connection, nothing before --since, nothing at or after --until.
        for (const QStringList &filter :
             {QStringList{QStringLiteral("--connection"), QStringLiteral("line9")},
              QStringList{QStringLiteral("--since"), QStringLiteral("2099-01-01")},
              QStringList{QStringLiteral("--until"), QStringLiteral("2000-01-01T00:00Z")}}) {
            const Run none
                = runCli(QStringList{QStringLiteral("alarms"), QStringLiteral("--journal"), journal}
                         + filter);
            QCOMPARE(none.code, 0);
            QCOMPARE(none.out, QByteArray());
        }
    }

    void refusals()
    {
        const QString noAlarms = write("plain.json",
                                       R"({"format":"fatek-studio-watchlist","version":1,
            "tables":[{"name":"Main","items":[{"address":"R0"}]}]})");
        const QString other = m_dir.filePath(QStringLiteral("other.db"));
        QProcess sqlite;
        sqlite.start(QStringLiteral("sqlite3"), {other, QStringLiteral("CREATE TABLE t (a);")});
        QVERIFY(sqlite.waitForFinished());
        const QString missing = m_dir.filePath(QStringLiteral("missing.db"));
        const struct
        {
            QStringList arguments;
            int code;
            const char *error;
        } cases[] = {
            {{QStringLiteral("alarms")}, 2, "alarms needs a watch list"},
            {{QStringLiteral("alarms"), noAlarms, QStringLiteral("--tcp"),
              QStringLiteral("127.0.0.1:1")},
             2,
             "defines no alarm"},
            {{QStringLiteral("alarms"), QStringLiteral("--journal"), missing,
              QStringLiteral("--since"), QStringLiteral("yesterday")},
             2,
             "--since: \"yesterday\" is not a time"},
            {{QStringLiteral("alarms"), QStringLiteral("--journal"), missing}, 2, "does not exist"},
            {{QStringLiteral("alarms"), QStringLiteral("--journal"), other},
             1,
             "is not an alarm journal"},
            {{QStringLiteral("alarms"), QStringLiteral("--journal"), other, QStringLiteral("--tcp"),
              QStringLiteral("127.0.0.1:1")},
             2,
             "needs no link option"},
        };
        for (const auto &c : cases) {
            const Run run = runCli(c.arguments);
            QVERIFY2(run.code == c.code && run.err.contains(c.error),
                     qPrintable(QStringLiteral("%1: exit %2, %3")
                                    .arg(c.arguments.join(QLatin1Char(' ')))
                                    .arg(run.code)
                                    .arg(QString::fromUtf8(run.err))));
        }
        QVERIFY(!QFile::exists(missing));
    }
};

QTEST_GUILESS_MAIN(TestCliAlarms)

#include "tst_cli_alarms.moc"
