// The alarm journal (issue 50) on the real SQLite library and files: events and states back as
// written, the upsert and removal of states, the time range's ends, the CSV export, the files it
// refuses (damaged, another program's database, a newer format, locked by the real sqlite3
// program), and a writer killed with SIGKILL that leaves every committed event readable.

#include "core/alarm/alarmengine.h"
#include "core/alarm/alarmjournal.h"
#include "core/alarm/alarmjournalwriter.h"
#include "core/alarm/alarmmessages.h"

#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using namespace Fatek;

namespace {

AlarmEvent makeEvent(qint64 timeMs, const QString &alarmId, AlarmEventType type, AlarmState state)
{
    AlarmEvent e;
    e.timeMs = timeMs;
    e.utcOffsetS = 8 * 3600;
    e.connection = QStringLiteral("line1");
    e.alarmId = alarmId;
    e.type = type;
    e.state = state;
    e.kind = AlarmKind::High;
    e.priority = AlarmPriority::High;
    e.message = QStringLiteral("Tank level high");
    e.group = QStringLiteral("Tanks");
    e.value = QStringLiteral("812");
    return e;
}

AlarmRecord record(const QString &alarmId, AlarmState state, qint64 sinceMs)
{
    AlarmRecord r;
    r.connection = QStringLiteral("line1");
    r.alarmId = alarmId;
    r.state = state;
    r.sinceMs = sinceMs;
    r.raisedMs = sinceMs;
    r.conditionActive = state == AlarmState::ActiveUnacked || state == AlarmState::ActiveAcked;
    return r;
}

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The durability test's child: appends one event per transaction and says each once committed,
// until it is killed.
int childMain(const QString &path)
{
    Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::open(path);
    if (!journal) {
        std::fprintf(stderr, "%s\n", english(journal.error().message).c_str());
        return 1;
    }
    for (int i = 1;; ++i) {
        const AlarmEvent e = makeEvent(1000 + i, QStringLiteral("a-%1").arg(i),
                                       AlarmEventType::Raised, AlarmState::ActiveUnacked);
        if (!(*journal)->append({e}, {record(e.alarmId, e.state, e.timeMs)}))
            return 1;
        std::printf("%d\n", i);
        std::fflush(stdout);
    }
}

WatchItemSpec tankLevel()
{
    WatchItemSpec spec;
    spec.address = *Address::parse("R100");
    spec.format = DisplayFormat::Unsigned;
    AlarmDefinition high;
    high.kind = AlarmKind::High;
    high.limit = 100;
    spec.alarms = {high};
    return spec;
}

WatchItemValue valueOf(std::uint64_t key, std::uint32_t raw)
{
    WatchItemValue v;
    v.key = key;
    v.words = {raw};
    v.raw = raw;
    v.hasValue = true;
    v.quality = ValueQuality::Good;
    return v;
}

const char *const ChildVariable = "FATEK_TEST_JOURNAL_CHILD";

} // namespace

class TestAlarmJournal : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }

    std::unique_ptr<AlarmJournal> openOk(const QString &file)
    {
        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::open(file);
        if (!journal)
            qWarning("%s", english(journal.error().message).c_str());
        return journal ? std::move(journal).value() : nullptr;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void eventsAndStatesComeBack()
    {
        const QString file = path("sub/folder/round.db");
        QList<AlarmEvent> events{
            makeEvent(1000, QStringLiteral("1-R100-high"), AlarmEventType::Raised,
                      AlarmState::ActiveUnacked),
            makeEvent(2000, QStringLiteral("1-R100-high"), AlarmEventType::Acknowledged,
                      AlarmState::ActiveAcked),
            makeEvent(3000, QStringLiteral("1-M5-on"), AlarmEventType::Shelved,
                      AlarmState::Shelved),
        };
        events[1].user = QStringLiteral("王小明");
        events[1].comment = QStringLiteral("checked, \"valve\" closed\nsecond line");
        events[1].value.clear();
        events[2].kind = AlarmKind::On;
        events[2].priority = AlarmPriority::Critical;
        events[2].shelvedUntilMs = 3600000;
        events[2].utcOffsetS = -(3 * 3600 + 1800);
        const QList<AlarmRecord> records{
            record(QStringLiteral("1-R100-high"), AlarmState::ActiveAcked, 2000),
            record(QStringLiteral("1-M5-on"), AlarmState::Shelved, 3000),
        };
        {
            auto journal = openOk(file);
            QVERIFY(journal);
            QVERIFY(journal->append(events, records));
        }
        Result<std::unique_ptr<AlarmJournal>> reopened = AlarmJournal::openReadOnly(file);
        QVERIFY(reopened);
        Result<QList<AlarmEvent>> back = (*reopened)->events(0, 10000);
        QVERIFY(back);
        QCOMPARE(*back, events);
        Result<QList<AlarmRecord>> states = (*reopened)->states(QStringLiteral("line1"));
        QVERIFY(states);
        // Ordered by connection and alarm id.
        QCOMPARE(*states, (QList<AlarmRecord>{records[1], records[0]}));
        QCOMPARE((*reopened)->states(QStringLiteral("line2"))->size(), 0);
        // Read only means read only.
        QVERIFY(!(*reopened)->append(events, {}));
    }

    void statesAreReplacedAndNormalRemoved()
    {
        auto journal = openOk(path("states.db"));
        QVERIFY(journal);
        const QString id = QStringLiteral("1-R100-high");
        AlarmRecord other = record(id, AlarmState::ActiveUnacked, 10);
        other.connection = QStringLiteral("line2");
        QVERIFY(journal->append({}, {record(id, AlarmState::ActiveUnacked, 100), other}));
        QCOMPARE(journal->states()->size(), 2);
        QVERIFY(journal->append({}, {record(id, AlarmState::ActiveAcked, 200)}));
        QCOMPARE(*journal->states(QStringLiteral("line1")),
                 QList<AlarmRecord>{record(id, AlarmState::ActiveAcked, 200)});
        // Normal: nothing left to bring back, for this connection only.
        QVERIFY(journal->append({}, {record(id, AlarmState::Normal, 300)}));
        QCOMPARE(journal->states(QStringLiteral("line1"))->size(), 0);
        QCOMPARE(*journal->states(), QList<AlarmRecord>{other});
        // In one batch, the last record of an alarm wins; a Normal one for a missing alarm is no
        // error.
        QVERIFY(journal->append({}, {record(QStringLiteral("x"), AlarmState::Normal, 1)}));
    }

    void timeRangeIncludesFromExcludesTo()
    {
        auto journal = openOk(path("range.db"));
        QVERIFY(journal);
        QList<AlarmEvent> events;
        for (qint64 t : {1000, 2000, 2000, 3000}) {
            events.append(makeEvent(t, QStringLiteral("a%1").arg(events.size()),
                                    AlarmEventType::Raised, AlarmState::ActiveUnacked));
        }
        events[3].connection = QStringLiteral("line2");
        QVERIFY(journal->append(events, {}));
        QCOMPARE(*journal->events(2000, 3000), (QList<AlarmEvent>{events[1], events[2]}));
        QCOMPARE(*journal->events(0, 2000), QList<AlarmEvent>{events[0]});
        QCOMPARE(*journal->events(1001, 1999), QList<AlarmEvent>{});
        QCOMPARE(*journal->events(0, 3001, QStringLiteral("line2")), QList<AlarmEvent>{events[3]});
        QCOMPARE(journal->events(0, 3001, QStringLiteral("line1"))->size(), 3);
        QCOMPARE(journal->events(3001, 1000)->size(), 0);
    }

    void csvText()
    {
        AlarmEvent raised = makeEvent(Q_INT64_C(1796635411253), QStringLiteral("1-R100-high"),
                                      AlarmEventType::Raised, AlarmState::ActiveUnacked);
        AlarmEvent shelved = raised;
        shelved.type = AlarmEventType::Shelved;
        shelved.state = AlarmState::Shelved;
        shelved.utcOffsetS = -(3 * 3600 + 1800);
        shelved.value.clear();
        shelved.user = QStringLiteral("ops");
        shelved.comment = QStringLiteral("pump, \"B\" out");
        shelved.shelvedUntilMs = Q_INT64_C(1796639011253);
        AlarmEvent utc = raised;
        utc.utcOffsetS = 0;
        utc.message = QStringLiteral("two\nlines");
        const QByteArray expected
            = "time,connection,alarm,kind,event,state,priority,group,message,value,user,comment,"
              "shelved until\n"
              "2026-12-07T17:23:31.253+08:00,line1,1-R100-high,high,raised,activeUnacked,high,"
              "Tanks,Tank level high,812,,,\n"
              "2026-12-07T05:53:31.253-03:30,line1,1-R100-high,high,shelved,shelved,high,Tanks,"
              "Tank level high,,ops,\"pump, \"\"B\"\" out\",2026-12-07T06:53:31.253-03:30\n"
              "2026-12-07T09:23:31.253+00:00,line1,1-R100-high,high,raised,activeUnacked,high,"
              "Tanks,\"two\nlines\",812,,,\n";
        QCOMPARE(AlarmJournal::toCsv({raised, shelved, utc}), expected);
        // As a file: the byte order mark (Excel on Windows reads UTF-8 then), CRLF when asked,
        // the line end inside the quoted message too, never "\r\r\n".
        QCOMPARE(AlarmJournal::toCsvFile({raised, shelved, utc}, CsvFile::LineEnd::Lf),
                 QByteArray("\xEF\xBB\xBF") + expected);
        QByteArray crlf = expected;
        crlf.replace("\n", "\r\n");
        QCOMPARE(AlarmJournal::toCsvFile({raised, shelved, utc}, CsvFile::LineEnd::CrLf),
                 QByteArray("\xEF\xBB\xBF") + crlf);
        QCOMPARE(AlarmJournal::toCsv({}),
                 QByteArray("time,connection,alarm,kind,event,state,priority,group,message,value,"
                            "user,comment,shelved until\n"));
    }

    void damagedFileIsRefusedWithSqlitesReason()
    {
        const QString file = path("damaged.db");
        QByteArray garbage;
        for (int i = 0; i < 8192; ++i)
            garbage.append(static_cast<char>((i * 7919) % 251));
        {
            QFile out(file);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(garbage);
        }
        for (bool readOnly : {false, true}) {
            Result<std::unique_ptr<AlarmJournal>> journal
                = readOnly ? AlarmJournal::openReadOnly(file) : AlarmJournal::open(file);
            QVERIFY(!journal);
            QVERIFY(journal.error().message.id == MessageId(MsgId::JournalOpenFailed));
            const QString text = QString::fromStdString(english(journal.error().message));
            QVERIFY2(text.contains(QLatin1String("file is not a database")), qPrintable(text));
            QVERIFY2(text.contains(QLatin1String("damaged.db")), qPrintable(text));
        }
        QCOMPARE(fileBytes(file), garbage);
    }

    void anotherProgramsDatabaseIsLeftAlone()
    {
        const QString file = path("other.db");
        QProcess cli;
        cli.start(
            QStringLiteral("sqlite3"),
            {file, QStringLiteral("CREATE TABLE events (a); INSERT INTO events VALUES (1);")});
        QVERIFY(cli.waitForFinished());
        QCOMPARE(cli.exitCode(), 0);
        const QByteArray before = fileBytes(file);
        QVERIFY(!before.isEmpty());
        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::open(file);
        QVERIFY(!journal);
        QVERIFY(journal.error().message.id == MessageId(MsgId::JournalNotJournal));
        QVERIFY(!AlarmJournal::openReadOnly(file));
        // Not switched to WAL, nothing added.
        QCOMPARE(fileBytes(file), before);
        QVERIFY(!QFile::exists(file + QLatin1String("-wal")));
    }

    void newerFormatIsRefused()
    {
        const QString file = path("newer.db");
        QVERIFY(openOk(file));
        QProcess cli;
        cli.start(QStringLiteral("sqlite3"), {file, QStringLiteral("PRAGMA user_version=7;")});
        QVERIFY(cli.waitForFinished());
        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::open(file);
        QVERIFY(!journal);
        QVERIFY(journal.error().message.id == MessageId(MsgId::JournalNewer));
        QCOMPARE(QString::fromStdString(english(journal.error().message)),
                 QStringLiteral("The alarm journal %1 has format 7, newer than this program reads "
                                "(1); it was left as it is.")
                     .arg(QDir::toNativeSeparators(file)));
    }

    void missingFileToRead()
    {
        Result<std::unique_ptr<AlarmJournal>> journal
            = AlarmJournal::openReadOnly(path("nothing-here.db"));
        QVERIFY(!journal);
        QVERIFY(journal.error().message.id == MessageId(MsgId::JournalMissing));
        QVERIFY(!QFile::exists(path("nothing-here.db")));
    }

    void lockedByAnotherProgram()
    {
        const QString file = path("locked.db");
        auto early = openOk(file);
        QVERIFY(early);
        // The real sqlite3 program holds the write lock until its input ends.
        QProcess cli;
        cli.start(QStringLiteral("sqlite3"), {file});
        QVERIFY(cli.waitForStarted());
        cli.write("BEGIN EXCLUSIVE;\nSELECT 'held';\n");
        QByteArray said;
        QTRY_VERIFY2_WITH_TIMEOUT((said += cli.readAllStandardOutput()).contains("held"),
                                  cli.readAllStandardError().constData(), 10000);

        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::open(file);
        QVERIFY(!journal);
        QVERIFY(journal.error().message.id == MessageId(MsgId::JournalLocked));
        const AlarmEvent e
            = makeEvent(1, QStringLiteral("a"), AlarmEventType::Raised, AlarmState::ActiveUnacked);
        Status appended = early->append({e}, {});
        QVERIFY(!appended);
        QVERIFY(appended.error().message.id == MessageId(MsgId::JournalLocked));
        // Readers never wait for the writer (WAL).
        Result<std::unique_ptr<AlarmJournal>> reader = AlarmJournal::openReadOnly(file);
        QVERIFY(reader);
        QVERIFY((*reader)->events(0, 10));

        cli.closeWriteChannel();
        QVERIFY(cli.waitForFinished());
        QVERIFY(early->append({e}, {}));
        QCOMPARE(*early->events(0, 10), QList<AlarmEvent>{e});
    }

    void killedWriterLeavesEveryCommittedEvent()
    {
        const QString file = path("killed.db");
        QProcess child;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QLatin1String(ChildVariable), file);
        child.setProcessEnvironment(env);
        child.start(QCoreApplication::applicationFilePath(), {});
        QVERIFY(child.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += child.readAllStandardOutput()).count('\n') >= 40, 30000);
        // SIGKILL (TerminateProcess on Windows): no clean exit, as a power cut.
        child.kill();
        QVERIFY(child.waitForFinished());
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);
        said += child.readAllStandardOutput();
        const QList<QByteArray> lines = said.trimmed().split('\n');
        const int committed = lines.last().toInt();
        QVERIFY(committed >= 40);

        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::openReadOnly(file);
        QVERIFY(journal);
        Result<QList<AlarmEvent>> events = (*journal)->events(0, Q_INT64_C(1) << 40);
        QVERIFY(events);
        // Every event it said was committed, in order; at most one more it had no time to say.
        QVERIFY2(events->size() >= committed && events->size() <= committed + 1,
                 qPrintable(
                     QStringLiteral("%1 events, %2 committed").arg(events->size()).arg(committed)));
        for (int i = 0; i < committed; ++i)
            QCOMPARE(events->at(i).alarmId, QStringLiteral("a-%1").arg(i + 1));
        QCOMPARE((*journal)->states()->size(), events->size());
        // And it opens for writing again (the log it left is taken in).
        journal = AlarmJournal::open(file);
        QVERIFY(journal);
    }

    // The writer's thread with a real engine: the raise journaled and queried back, the state
    // back after a restart without a second raise.
    void writerRecordsAndRestores()
    {
        const QString file = path("writer.db");
        const WatchItemSpec spec = tankLevel();
        const QString id = Alarms::alarmId(spec, AlarmKind::High);
        qint64 now = 1000000;
        {
            AlarmEngine engine(QStringLiteral("line1"));
            engine.setClock([&now] { return now; });
            // The engine's keys: the block after this one (WatchedItem::newKeys).
            const std::uint64_t key = WatchedItem::newKey() + 1;
            engine.setItems({WatchedItem{0, spec, 100}});
            AlarmJournalWriter writer(file);
            QSignalSpy failed(&writer, &AlarmJournalWriter::failed);
            writer.attach(&engine);
            // Held until the journal's states are in, then evaluated.
            engine.plantValues({valueOf(key, 150)});
            QTRY_COMPARE(engine.status(id)->state, AlarmState::ActiveUnacked);
            bool answered = false;
            QList<AlarmEvent> got;
            writer.query(0, now + 1, QStringLiteral("line1"), this,
                         [&](const Result<QList<AlarmEvent>> &events) {
                             answered = true;
                             QVERIFY(QThread::currentThread() == thread());
                             QVERIFY(events);
                             got = *events;
                         });
            QTRY_VERIFY(answered);
            QCOMPARE(got.size(), 1);
            QCOMPARE(got[0].type, AlarmEventType::Raised);
            QCOMPARE(got[0].alarmId, id);
            QVERIFY(failed.isEmpty());
            // Acknowledged just before the end: the destructor writes it.
            QVERIFY(engine.acknowledge(id, QStringLiteral("ops"), QStringLiteral("seen")));
        }
        {
            AlarmEngine engine(QStringLiteral("line1"));
            engine.setClock([&now] { return now; });
            engine.setItems({WatchedItem{0, spec, 100}});
            QSignalSpy events(&engine, &AlarmEngine::alarmEvent);
            AlarmJournalWriter writer(file);
            writer.attach(&engine);
            QTRY_COMPARE(engine.status(id)->state, AlarmState::ActiveAcked);
            QVERIFY(events.isEmpty());
        }
        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::openReadOnly(file);
        QVERIFY(journal);
        const QList<AlarmEvent> events = *(*journal)->events(0, now + 1);
        QCOMPARE(events.size(), 2);
        QCOMPARE(events[1].type, AlarmEventType::Acknowledged);
        QCOMPARE(events[1].user, QStringLiteral("ops"));
    }

    void writerReportsAFileItCannotOpen()
    {
        AlarmEngine engine(QStringLiteral("line1"));
        const std::uint64_t key = WatchedItem::newKey() + 1;
        engine.setItems({WatchedItem{0, tankLevel(), 100}});
        AlarmJournalWriter writer(QStringLiteral("/proc/version/alarms.db"));
        QSignalSpy failed(&writer, &AlarmJournalWriter::failed);
        writer.attach(&engine);
        QVERIFY(failed.wait(5000));
        QVERIFY(failed.at(0).at(0).value<Message>().id == MessageId(MsgId::JournalOpenFailed));
        // The hold ends anyway: the alarms are evaluated without the journal's states.
        const QString id = Alarms::alarmId(tankLevel(), AlarmKind::High);
        engine.plantValues({valueOf(key, 150)});
        QTRY_COMPARE(engine.status(id)->state, AlarmState::ActiveUnacked);
    }
};

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsSet(ChildVariable))
        return childMain(qEnvironmentVariable(ChildVariable));
    QCoreApplication app(argc, argv);
    TestAlarmJournal test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_alarmjournal.moc"
