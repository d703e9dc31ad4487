// Memory snapshots (core/commission) against the in-process simulator over loopback TCP: the
// whole FBs in the fewest requests (counted by the simulator's server), files, differences,
// restore of values, operator mode; and fatek-cli's snapshot, diff and restore-values.
#include "core/commission/snapshotdiff.h"
#include "core/commission/snapshotfile.h"
#include "core/commission/snapshotreader.h"
#include "core/commission/valuesrestorer.h"
#include "core/qtbridge/qtmessage.h"
#include "core/session/session.h"
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QDeadlineTimer>
#include <QEventLoop>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <memory>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

using namespace Fatek;

namespace {

using Run = TestUtil::ProgramRun;

// fatek-cli with the event loop turning, so that the in-process simulator answers. Its standard
// input is a pipe: not a terminal.
Run runCli(const QStringList &arguments)
{
    return TestUtil::runProgram(QStringLiteral(FATEK_CLI_PATH), arguments);
}

Address addr(const char *text)
{
    return Address::parse(text).value();
}

std::vector<AddressRange> ranges(const char *text)
{
    return Snapshot::parseRanges(QString::fromLatin1(text)).value();
}

} // namespace

#define RUN_IS(r, expected)                                                                        \
    QVERIFY2((r).code == (expected),                                                               \
             qPrintable(QStringLiteral("exit %1: %2 %3").arg((r).code).arg((r).err, (r).out)))

class TestSnapshot : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void wholeFbsInFewestRequests();
    void chosenRanges();
    void filesRoundTrip_data();
    void filesRoundTrip();
    void damagedFilesRefused_data();
    void damagedFilesRefused();
    void diffOfTwoSnapshots();
    void diffLiveAfterChange();
    void writeFramesPacked();
    void restoreRoundTrip();
    void restoreRefusedInReadOnly();
    void cancel();
    void cancelOrDeleteWhilePlanning();
    void interruptedRestoreSaysHowManyWritten();

    void cliSnapshotDiffRestore();
    void cliRestoreWithoutYesNotTerminal();
    void cliRestoreInterruptedSaysHowManyWritten();
    void cliDiffOfTwoFilesOffline();
    void cliDamagedFile();

private:
    MemorySnapshot take(const std::vector<AddressRange> &r, int *requests = nullptr);
    QStringList link() const;

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<Session> m_session;
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestSnapshot::init()
{
    registerSessionMetaTypes();
    // No demo ladder: SimServer drives SimulatedPlc::scan only when it is enabled, so the memory
    // holds still and equality checks are exact.
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
    QVERIFY(m_server->listenTcp(0));
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(),
                                              LinkSettings::ProtocolChoice::Facon);
    settings.timeoutMs = 2000;
    settings.retries = 1;
    m_session = std::make_unique<Session>(settings);
    m_session->open();
    QTRY_VERIFY_WITH_TIMEOUT(m_session->linkState() == LinkState::Connected, 10000);
    m_dir = std::make_unique<QTemporaryDir>();
}

void TestSnapshot::cleanup()
{
    m_session.reset();
    m_server.reset();
    m_plc.reset();
    m_dir.reset();
}

QStringList TestSnapshot::link() const
{
    return {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(m_server->tcpPort()),
            QStringLiteral("--protocol"), QStringLiteral("facon")};
}

MemorySnapshot TestSnapshot::take(const std::vector<AddressRange> &r, int *requests)
{
    SnapshotReader reader;
    reader.setSession(m_session.get());
    QSignalSpy done(&reader, &SnapshotReader::finished);
    reader.start(1, r);
    // Planning a whole FBs (7606 items) takes ~1 ms in a release build, much longer under
    // ThreadSanitizer: a generous bound, reached only when something is wrong.
    if (!done.wait(120000) || !reader.ok()) {
        qWarning() << "snapshot failed:"
                   << (reader.ok() ? QStringLiteral("no answer")
                                   : englishText(reader.error().message));
        return {};
    }
    if (requests)
        *requests = reader.requestsTotal();
    return reader.snapshot();
}

void TestSnapshot::wholeFbsInFewestRequests()
{
    // Marks at the edges of every kind, so that a misplaced bit or word shows.
    m_plc->setValue(addr("X5"), 1);
    m_plc->setValue(addr("Y255"), 1);
    m_plc->setValue(addr("M2001"), 1);
    m_plc->setValue(addr("M1999"), 1);
    m_plc->setValue(addr("S999"), 1);
    m_plc->setValue(addr("T17"), 1);
    m_plc->setValue(addr("C255"), 1);
    m_plc->setValue(addr("RT0"), 11);
    m_plc->setValue(addr("RC255"), 22);
    m_plc->setValue(addr("R0"), 1234);
    m_plc->setValue(addr("R3839"), 0xBEEF);
    m_plc->setValue(addr("D2999"), 7);

    const quint64 framesBefore = m_server->counters().frames;
    int requests = 0;
    const MemorySnapshot s = take({}, &requests);
    const quint64 onTheWire = m_server->counters().frames - framesBefore;

    // The minimum, from the FBs profile's 53 sizes: every read request carries at most 64 words
    // (46 and 48; a 44 carries 256 discretes = 16 words' worth, less). The memory is
    //   discretes X256 + Y256 + M2002 + S1000 + T256 + C256 = 4026 bits = 251.6 words,
    //   registers RT256 + RC256 + R3840 + D3000 = 7352 words,
    // so at least ceil((4026 / 16 + 7352) / 64) = ceil(118.8) = 119 reads, plus the one 53 that
    // tells the sizes: 120 frames. Reached: discretes as 16-bit words (WX0..WX240, ...,
    // WM0..WM1984, WS0..WS976 + WS984, M2000 and M2001 alone: 252 words + 2), 115 full 46 runs
    // of 64 words and 4 mixed 48 reads for the remaining 246 words.
    QCOMPARE(onTheWire, quint64(120));
    QCOMPARE(requests, 120);
    QCOMPARE(s.values.size(), std::size_t(4026 + 7352));
    QCOMPARE(s.info.station, 1);
    QCOMPARE(s.info.protocol, QStringLiteral("FACON"));
    QVERIFY2(s.info.model.contains(QLatin1String("FBs-28MC")), qPrintable(s.info.model));
    for (const SnapshotValue &v : s.values) {
        const auto expected = m_plc->value(v.address);
        QVERIFY2(expected && *expected == v.value,
                 qPrintable(QString::fromStdString(v.address.toString())));
    }
    QCOMPARE(s.value(addr("M2001")), std::optional<std::uint32_t>(1));
    QCOMPARE(s.value(addr("S999")), std::optional<std::uint32_t>(1));
    QCOMPARE(s.value(addr("R3839")), std::optional<std::uint32_t>(0xBEEF));
}

void TestSnapshot::chosenRanges()
{
    m_plc->setValue(addr("M5"), 1);
    m_plc->setValue(addr("R7"), 77);
    int requests = 0;
    const MemorySnapshot s = take(ranges("R5..R9, M3-M6 S995..S999"), &requests);
    QCOMPARE(s.values.size(), std::size_t(14));
    QCOMPARE(s.value(addr("R7")), std::optional<std::uint32_t>(77));
    QCOMPARE(s.value(addr("M5")), std::optional<std::uint32_t>(1));
    QVERIFY(!s.value(addr("M7")));
    // 53, then one mixed read: R5..R9, WM0 and WS984 are 7 words.
    QCOMPARE(requests, 2);
}

void TestSnapshot::filesRoundTrip_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<CsvFile::LineEnd>("lineEnd");
    QTest::newRow("json") << QStringLiteral("s.json") << CsvFile::LineEnd::Lf;
    QTest::newRow("csv") << QStringLiteral("s.csv") << CsvFile::LineEnd::Lf;
    // As Excel on Windows wants it: the byte order mark and CRLF, read back the same.
    QTest::newRow("csv crlf") << QStringLiteral("crlf.csv") << CsvFile::LineEnd::CrLf;
}

void TestSnapshot::filesRoundTrip()
{
    QFETCH(QString, name);
    QFETCH(CsvFile::LineEnd, lineEnd);
    m_plc->setValue(addr("R1"), 65535);
    m_plc->setValue(addr("Y3"), 1);
    MemorySnapshot s = take(ranges("R0..R3 Y0..Y7 DR10"));
    QCOMPARE(s.values.size(), std::size_t(13));
    s.info.taken = QDateTime(QDate(2026, 11, 25), QTime(19, 55, 0), Qt::UTC);
    s.info.model = QStringLiteral("FBs-28MC, with \"quotes\", and commas");
    const QString path = m_dir->filePath(name);
    QVERIFY(!SnapshotFile::saveToFile(s, path, lineEnd));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray data = file.readAll();
    if (name.endsWith(QLatin1String(".csv"))) {
        QVERIFY2(data.startsWith("\xEF\xBB\xBF# fatek-studio-snapshot 1"),
                 data.left(40).constData());
        QCOMPARE(data.count("\r\n"), lineEnd == CsvFile::LineEnd::CrLf ? data.count('\n') : 0);
    } else {
        QVERIFY(data.startsWith('{')); // JSON has no mark
    }
    const SnapshotFile::Loaded back = SnapshotFile::loadFromFile(path);
    QVERIFY2(back.ok(), qPrintable(englishText(back.error.message)));
    QCOMPARE(*back.snapshot, s);
}

void TestSnapshot::damagedFilesRefused_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("value");
    QTest::addColumn<QString>("text");
    using K = SnapshotFile::Error::Kind;
    const QByteArray head = "{\"format\": \"fatek-studio-snapshot\", \"version\": 1,\n";
    QTest::newRow("json syntax")
        << "a.json" << QByteArray(head + "\"values\": [\n{\"address\": \"R0\" \"value\": 1}]}")
        << int(K::Syntax) << 3 << 0 << "line 3, column";
    QTest::newRow("json other file")
        << "a.json" << QByteArray("{\"format\": \"fatek-studio-watchlist\", \"version\": 1}")
        << int(K::NotSnapshot) << 0 << 0 << "not a memory snapshot";
    QTest::newRow("json newer")
        << "a.json"
        << QByteArray("{\"format\": \"fatek-studio-snapshot\", \"version\": 2, \"values\": []}")
        << int(K::Version) << 0 << 0 << "version 2 is not supported";
    QTest::newRow("json bad address")
        << "a.json"
        << QByteArray(head
                      + "\"values\": [{\"address\": \"R0\", \"value\": 1}, {\"address\": "
                        "\"R0x\", \"value\": 1}]}")
        << int(K::Content) << 0 << 2 << "value 2: ";
    QTest::newRow("json out of range")
        << "a.json" << QByteArray(head + "\"values\": [{\"address\": \"Y0\", \"value\": 2}]}")
        << int(K::Content) << 0 << 1 << "2 does not fit Y0 (0..1)";
    QTest::newRow("json duplicate")
        << "a.json"
        << QByteArray(head
                      + "\"values\": [{\"address\": \"R0\", \"value\": 1}, {\"address\": "
                        "\"R0\", \"value\": 1}]}")
        << int(K::Content) << 0 << 2 << "R0 appears twice";
    QTest::newRow("json no values") << "a.json" << QByteArray(head + "\"model\": \"x\"}")
                                    << int(K::Content) << 0 << 0 << "\"values\" is missing";
    QTest::newRow("csv no header") << "a.csv" << QByteArray("# fatek-studio-snapshot 1\nR0,1\n")
                                   << int(K::Syntax) << 2 << 0 << "line 2: expected address";
    QTest::newRow("csv bad value")
        << "a.csv" << QByteArray("address,value\nR0,1\nR1,x1\n") << int(K::Content) << 3 << 0
        << "line 3: \"x1\" is not a whole number";
    QTest::newRow("csv hex differs")
        << "a.csv" << QByteArray("address,value,hex\nR0,16,0x0011\n") << int(K::Content) << 2 << 0
        << "line 2: the hex column 0x0011 differs from the value 16";
    QTest::newRow("csv too many cells")
        << "a.csv" << QByteArray("address,value\nR0,1,2\n") << int(K::Syntax) << 2 << 0 << "line 2";
    QTest::newRow("unknown extension")
        << "a.txt" << QByteArray("address,value\n") << int(K::Io) << 0 << 0 << ".json or .csv";
}

void TestSnapshot::damagedFilesRefused()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, data);
    QFETCH(int, kind);
    QFETCH(int, line);
    QFETCH(int, value);
    QFETCH(QString, text);
    const QString path = m_dir->filePath(name);
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(data);
    f.close();
    const SnapshotFile::Loaded loaded = SnapshotFile::loadFromFile(path);
    QVERIFY(!loaded.ok());
    const QString message = englishText(loaded.error.message);
    QCOMPARE(int(loaded.error.kind), kind);
    QCOMPARE(loaded.error.line, line);
    QCOMPARE(loaded.error.valueIndex, value);
    QVERIFY2(message.contains(text), qPrintable(message));
}

void TestSnapshot::diffOfTwoSnapshots()
{
    MemorySnapshot a;
    a.values = {{addr("X0"), 0}, {addr("R0"), 1}, {addr("R1"), 0xFFFF}, {addr("R2"), 5}};
    MemorySnapshot b;
    b.values = {{addr("X0"), 1}, {addr("R0"), 1}, {addr("R1"), 3}, {addr("R3"), 9}};
    a.normalize();
    b.normalize();
    std::size_t compared = 0;
    const auto d = SnapshotDiff::compare(a, b, &compared);
    QCOMPARE(compared, std::size_t(5));
    QCOMPARE(d.size(), std::size_t(4));
    QStringList text;
    for (const SnapshotDifference &x : d)
        text << englishText(SnapshotDiff::line(x));
    QCOMPARE(text, QStringList({QStringLiteral("X0: OFF -> ON"), QStringLiteral("R1: -1 -> 3"),
                                QStringLiteral("R2: 5 -> (absent)"),
                                QStringLiteral("R3: (absent) -> 9")}));
    QCOMPARE(SnapshotDiff::hexText(addr("R1"), 0xFFFFu), QStringLiteral("0xFFFF"));
    QCOMPARE(englishText(SnapshotDiff::summary(d.size(), compared)),
             QStringLiteral("4 of 5 values differ."));
    QVERIFY(SnapshotDiff::compare(a, a).empty());
}

void TestSnapshot::diffLiveAfterChange()
{
    const MemorySnapshot before = take(ranges("R0..R99 X0..X15 M0..M31"));
    QCOMPARE(before.values.size(), std::size_t(148));
    m_plc->setValue(addr("R42"), 4242);
    m_plc->setValue(addr("X2"), 1);
    m_plc->setValue(addr("M31"), 1);
    m_plc->setValue(addr("R100"), 1); // outside the snapshot: not compared
    const MemorySnapshot live = take(ranges("R0..R99 X0..X15 M0..M31"));
    const auto d = SnapshotDiff::compare(before, live);
    QCOMPARE(d.size(), std::size_t(3));
    QCOMPARE(d[0], (SnapshotDifference{addr("X2"), 0u, 1u}));
    QCOMPARE(d[1], (SnapshotDifference{addr("M31"), 0u, 1u}));
    QCOMPARE(d[2], (SnapshotDifference{addr("R42"), 0u, 4242u}));
}

void TestSnapshot::writeFramesPacked()
{
    std::vector<SnapshotValue> v;
    for (std::uint32_t n = 0; n < 100; ++n)
        v.push_back({Address{ElementType::R, n}, n});
    // 100 consecutive registers: 64 + 36 in two 47s.
    auto frames = ValuesRestorer::writeRequests(1, v);
    QCOMPARE(frames.size(), std::size_t(2));
    QCOMPARE(frames[0].command, Command::WriteRegisters);
    QCOMPARE(frames[0].values.size(), std::size_t(64));
    // Plus 300 discretes (45s of 256 and 44) and three scattered singles (one 49).
    for (std::uint32_t n = 0; n < 300; ++n)
        v.push_back({Address{ElementType::M, n}, n % 2});
    v.push_back({addr("R500"), 5});
    v.push_back({addr("D7"), 7});
    v.push_back({addr("M9000"), 1});
    frames = ValuesRestorer::writeRequests(1, v);
    int mixed = 0;
    for (const Request &r : frames) {
        QVERIFY(validateRequest(r, Protocol::Facon));
        mixed += r.command == Command::MixedWrite;
    }
    // The minimum is 5: R0..R63 and M0..M255 fill their frames, R64..R99 (36 words) and
    // M256..M299 (44) are too long for a 49 (<= 32 words): 47, 47, 45, 45 and one 49.
    QCOMPARE(frames.size(), std::size_t(5));
    QCOMPARE(mixed, 1);
    // Short runs share one mixed write: R0..R9 D0..D3 S995..S999 (19 words) + M0..M20 (45).
    std::vector<SnapshotValue> small;
    for (std::uint32_t n = 0; n < 10; ++n)
        small.push_back({Address{ElementType::R, n}, n});
    for (std::uint32_t n = 0; n < 4; ++n)
        small.push_back({Address{ElementType::D, n}, n});
    for (std::uint32_t n = 995; n < 1000; ++n)
        small.push_back({Address{ElementType::S, n}, 1});
    for (std::uint32_t n = 0; n <= 20; ++n)
        small.push_back({Address{ElementType::M, n}, 1});
    QCOMPARE(ValuesRestorer::writeRequests(1, small).size(), std::size_t(2));
}

void TestSnapshot::restoreRoundTrip()
{
    for (std::uint32_t n = 100; n < 200; ++n)
        m_plc->setValue(Address{ElementType::R, n}, n * 3);
    m_plc->setValue(addr("M7"), 1);
    m_plc->setValue(addr("Y15"), 1);
    m_plc->setValue(addr("D9"), 999);
    const MemorySnapshot recipe = take(ranges("R100..R199 M0..M63 D0..D9 Y0..Y15"));
    QCOMPARE(recipe.values.size(), std::size_t(190));

    // The process moves on.
    m_plc->setValue(addr("R150"), 1);
    m_plc->setValue(addr("M7"), 0);
    m_plc->setValue(addr("M8"), 1);
    m_plc->setValue(addr("Y15"), 0);
    m_plc->setValue(addr("D9"), 0);
    m_plc->setValue(addr("R200"), 5); // outside the recipe: left alone

    ValuesRestorer restorer;
    restorer.setSession(m_session.get());
    QSignalSpy done(&restorer, &ValuesRestorer::finished);
    const quint64 framesBefore = m_server->counters().frames;
    restorer.start(1, recipe.select(ranges("R100..R199 M0..M63 D0..D9 Y0..Y15")));
    QVERIFY(done.wait(20000));
    QVERIFY2(restorer.ok(), qPrintable(englishText(restorer.outcome())));
    QVERIFY(restorer.mismatches().empty());
    // Writes: R100..R163 and R164..R199 (47), M0..M63 (45), and D0..D9 + Y0..Y15 (26 words) in
    // one 49. Then the read-back: 53 and its reads, all counted in requestsTotal().
    QCOMPARE(restorer.writeRequestCount(), 4);
    QCOMPARE(m_server->counters().frames - framesBefore, quint64(restorer.requestsTotal()));
    for (const SnapshotValue &v : recipe.values)
        QCOMPARE(m_plc->value(v.address), std::optional<std::uint32_t>(v.value));
    QCOMPARE(m_plc->value(addr("R200")), std::optional<std::uint32_t>(5));
    QVERIFY(englishText(restorer.outcome()).contains(QLatin1String("read back equal")));
}

void TestSnapshot::restoreRefusedInReadOnly()
{
    const MemorySnapshot recipe = take(ranges("R0..R9"));
    m_plc->setValue(addr("R3"), 33);
    m_session->setReadOnly(true);
    ValuesRestorer restorer;
    restorer.setSession(m_session.get());
    QSignalSpy done(&restorer, &ValuesRestorer::finished);
    const quint64 framesBefore = m_server->counters().frames;
    restorer.start(1, recipe.values);
    QVERIFY(done.wait(5000));
    QVERIFY(!restorer.ok());
    QVERIFY(restorer.error());
    QCOMPARE(restorer.error()->kind, ErrorKind::ReadOnly);
    QCOMPARE(restorer.writeRequestCount(), 0);
    QCOMPARE(m_server->counters().frames, framesBefore); // nothing on the wire, not even a read
    QCOMPARE(m_plc->value(addr("R3")), std::optional<std::uint32_t>(33));
}

void TestSnapshot::cancel()
{
    SnapshotReader reader;
    reader.setSession(m_session.get());
    QSignalSpy done(&reader, &SnapshotReader::finished);
    reader.start(1, {});
    reader.cancel();
    QCOMPARE(done.size(), 1);
    QVERIFY(!reader.ok());
    QCOMPARE(reader.error().kind, ErrorKind::Cancelled);
    QVERIFY(!reader.isRunning());
    // Answers still on their way are ignored: no second finished().
    QTest::qWait(50);
    QCOMPARE(done.size(), 1);

    ValuesRestorer restorer;
    restorer.setSession(m_session.get());
    QSignalSpy restored(&restorer, &ValuesRestorer::finished);
    std::vector<SnapshotValue> values;
    for (std::uint32_t n = 0; n < 1000; ++n)
        values.push_back({Address{ElementType::D, n}, 1});
    restorer.start(1, values);
    restorer.cancel();
    QCOMPARE(restored.size(), 1);
    QVERIFY(restorer.error());
    QCOMPARE(restorer.error()->kind, ErrorKind::Cancelled);
    QTest::qWait(50);
    QCOMPARE(restored.size(), 1);
    // At most the write already on the wire went through: D0..D63.
    QCOMPARE(m_plc->value(addr("D64")), std::optional<std::uint32_t>(0));
}

// A restore of values stopped half-way leaves some values new, some old: it says how many were
// written (the PLC confirmed them), and what to do.
// The items are planned on a thread of their own once the 53 is answered: a read cancelled or a
// reader deleted meanwhile ends once, and the plan that comes later is dropped.
void TestSnapshot::cancelOrDeleteWhilePlanning()
{
    // Events are handled one batch at a time, so the check comes right after the 53's answer,
    // while its plan is being made (the plan's own answer is a later event).
    auto untilDetailStatusAnswered = [](const SnapshotReader &reader) {
        QDeadlineTimer deadline(10000);
        while (reader.requestsDone() < 1 && !deadline.hasExpired())
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        return reader.requestsDone() == 1;
    };
    {
        SnapshotReader reader;
        reader.setSession(m_session.get());
        QSignalSpy done(&reader, &SnapshotReader::finished);
        reader.start(1, {});
        QVERIFY(untilDetailStatusAnswered(reader));
        reader.cancel();
        QCOMPARE(done.size(), 1);
        QCOMPARE(reader.error().kind, ErrorKind::Cancelled);
        QTest::qWait(200);
        QCOMPARE(done.size(), 1);
        QVERIFY(!reader.isRunning());
        // The reader reads again, with the plan of its new read.
        reader.start(1, {AddressRange{addr("R0"), 10}});
        QVERIFY(done.wait(20000));
        QVERIFY(reader.ok());
        QCOMPARE(reader.snapshot().values.size(), std::size_t{10});
    }
    {
        auto reader = std::make_unique<SnapshotReader>();
        reader->setSession(m_session.get());
        reader->start(1, {});
        QVERIFY(untilDetailStatusAnswered(*reader));
        reader.reset();
        QTest::qWait(200); // the plan finds nobody to hand over to
    }
    // The session still serves.
    QCOMPARE(take({AddressRange{addr("D0"), 3}}).values.size(), std::size_t{3});
}

void TestSnapshot::interruptedRestoreSaysHowManyWritten()
{
    ValuesRestorer restorer;
    restorer.setSession(m_session.get());
    QSignalSpy restored(&restorer, &ValuesRestorer::finished);
    std::vector<SnapshotValue> values;
    for (std::uint32_t n = 0; n < 1000; ++n)
        values.push_back({Address{ElementType::D, n}, 7});
    // Stopped once three writes of 64 registers are confirmed (after the 53 that checks the
    // ranges: four requests done).
    connect(&restorer, &ValuesRestorer::progress, this, [&restorer](int done) {
        if (done == 4)
            restorer.cancel();
    });
    restorer.start(1, values);
    QVERIFY(restored.wait(20000));
    QCOMPARE(restorer.valuesWritten(), 192);
    const QString outcome = englishText(restorer.outcome());
    QVERIFY2(outcome.contains(QLatin1String("192 of 1000 values had been written")),
             qPrintable(outcome));
    QVERIFY2(outcome.contains(QLatin1String("restore the same file again")), qPrintable(outcome));
    QCOMPARE(m_plc->value(addr("D191")), std::optional<std::uint32_t>(7));
    QCOMPARE(m_plc->value(addr("D999")), std::optional<std::uint32_t>(0));
}

void TestSnapshot::cliSnapshotDiffRestore()
{
    m_plc->setValue(addr("R5"), 55);
    m_plc->setValue(addr("M3"), 1);
    const QString file = m_dir->filePath(QStringLiteral("recipe.json"));
    Run r = runCli(link()
                   + QStringList{QStringLiteral("snapshot"), file, QStringLiteral("R0..R9,"),
                                 QStringLiteral("M0..M15")});
    RUN_IS(r, 0);
    const SnapshotFile::Loaded saved = SnapshotFile::loadFromFile(file);
    QVERIFY(saved.ok());
    QCOMPARE(saved.snapshot->values.size(), std::size_t(26));
    for (const SnapshotValue &v : saved.snapshot->values)
        QCOMPARE(m_plc->value(v.address), std::optional<std::uint32_t>(v.value));

    // Equal: exit 0, nothing on stdout.
    r = runCli(link() + QStringList{QStringLiteral("diff"), file});
    RUN_IS(r, 0);
    QVERIFY(r.out.isEmpty());

    m_plc->setValue(addr("R5"), 7);
    m_plc->setValue(addr("M3"), 0);
    r = runCli(link() + QStringList{QStringLiteral("diff"), file});
    RUN_IS(r, 6);
    QCOMPARE(r.lines(),
             QStringList({QStringLiteral("M3: ON -> OFF"), QStringLiteral("R5: 55 -> 7")}));
    r = runCli(link() + QStringList{QStringLiteral("diff"), file, QStringLiteral("--json")});
    RUN_IS(r, 6);
    QCOMPARE(r.lines().size(), 2);
    const QJsonObject j = QJsonDocument::fromJson(r.lines().at(1).toUtf8()).object();
    QCOMPARE(j.value(QStringLiteral("address")).toString(), QStringLiteral("R5"));
    QCOMPARE(j.value(QStringLiteral("before")).toInteger(), 55);
    QCOMPARE(j.value(QStringLiteral("after")).toInteger(), 7);

    // Operator mode: refused before anything is written.
    r = runCli(link()
               + QStringList{QStringLiteral("--read-only"), QStringLiteral("--yes"),
                             QStringLiteral("restore-values"), file});
    RUN_IS(r, 5);
    QCOMPARE(m_plc->value(addr("R5")), std::optional<std::uint32_t>(7));

    // Only R5 (a chosen subset): M3 stays as it is.
    r = runCli(link()
               + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file,
                             QStringLiteral("R5")});
    RUN_IS(r, 0);
    QCOMPARE(m_plc->value(addr("R5")), std::optional<std::uint32_t>(55));
    QCOMPARE(m_plc->value(addr("M3")), std::optional<std::uint32_t>(0));

    r = runCli(link()
               + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file});
    RUN_IS(r, 0);
    QVERIFY2(r.err.contains(QLatin1String("26 values written")), qPrintable(r.err));
    QCOMPARE(m_plc->value(addr("M3")), std::optional<std::uint32_t>(1));
}

void TestSnapshot::cliRestoreWithoutYesNotTerminal()
{
    const QString file = m_dir->filePath(QStringLiteral("recipe.csv"));
    Run r
        = runCli(link() + QStringList{QStringLiteral("snapshot"), file, QStringLiteral("R0..R9")});
    RUN_IS(r, 0);
    m_plc->setValue(addr("R0"), 1000);
    const quint64 framesBefore = m_server->counters().frames;
    r = runCli(link() + QStringList{QStringLiteral("restore-values"), file});
    RUN_IS(r, 2);
    QVERIFY2(r.err.contains(QLatin1String("--yes")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("Nothing was written")), qPrintable(r.err));
    QCOMPARE(m_server->counters().frames, framesBefore);
    QCOMPARE(m_plc->value(addr("R0")), std::optional<std::uint32_t>(1000));
}

// Ctrl-C during restore-values: not just "Interrupted.", but how many values were written.
void TestSnapshot::cliRestoreInterruptedSaysHowManyWritten()
{
#ifdef Q_OS_UNIX
    const QString file = m_dir->filePath(QStringLiteral("many.csv"));
    for (std::uint32_t n = 0; n < 1000; ++n)
        m_plc->setValue(Address{ElementType::D, n}, 5);
    Run r = runCli(link()
                   + QStringList{QStringLiteral("snapshot"), file, QStringLiteral("D0..D999")});
    RUN_IS(r, 0);
    for (std::uint32_t n = 0; n < 1000; ++n)
        m_plc->setValue(Address{ElementType::D, n}, 0);
    // Slow answers: 16 writes of 64 registers take seconds, Ctrl-C comes after the second.
    FaultConfig slow;
    slow.latencyMs = 150;
    m_server->setFaults(slow);
    const quint64 framesBefore = m_server->counters().frames;
    QProcess p;
    p.start(QStringLiteral(FATEK_CLI_PATH),
            link() + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file});
    QVERIFY(p.waitForStarted(10000));
    // The link's first query is a status (53) or a write: wait for three frames.
    QTRY_VERIFY_WITH_TIMEOUT(m_server->counters().frames >= framesBefore + 3, 20000);
    ::kill(static_cast<pid_t>(p.processId()), SIGINT);
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 10000);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QCOMPARE(p.exitCode(), 130);
    static const QRegularExpression written(
        QStringLiteral("(\\d+) of 1000 values had been written when it stopped"));
    const QRegularExpressionMatch m = written.match(err);
    QVERIFY2(m.hasMatch(), qPrintable(err));
    QVERIFY2(err.contains(QLatin1String("restore the same file again")), qPrintable(err));
    // The count is what the PLC holds: that many values from D0 on are written.
    const int count = m.captured(1).toInt();
    QVERIFY2(count >= 64 && count % 64 == 0 && count < 1000, qPrintable(err));
    QCOMPARE(m_plc->value(Address{ElementType::D, static_cast<std::uint32_t>(count - 1)}),
             std::optional<std::uint32_t>(5));
#else
    QSKIP("Unix signals");
#endif
}

void TestSnapshot::cliDiffOfTwoFilesOffline()
{
    MemorySnapshot a;
    a.values = {{addr("R0"), 1}, {addr("Y1"), 0}};
    MemorySnapshot b = a;
    const QString fa = m_dir->filePath(QStringLiteral("a.json"));
    const QString fb = m_dir->filePath(QStringLiteral("b.csv"));
    QVERIFY(!SnapshotFile::saveToFile(a, fa));
    QVERIFY(!SnapshotFile::saveToFile(b, fb));
    Run r = runCli({QStringLiteral("diff"), fa, fb}); // no link needed
    RUN_IS(r, 0);
    b.values[1].value = 1;
    QVERIFY(!SnapshotFile::saveToFile(b, fb));
    r = runCli({QStringLiteral("diff"), fa, fb});
    RUN_IS(r, 6);
    QCOMPARE(r.lines(), QStringList({QStringLiteral("Y1: OFF -> ON")}));
    r = runCli({QStringLiteral("diff"), fa, fb, QStringLiteral("--csv")});
    RUN_IS(r, 6);
    QCOMPARE(r.lines(),
             QStringList({QStringLiteral("address,before,after"), QStringLiteral("Y1,0,1")}));
}

void TestSnapshot::cliDamagedFile()
{
    const QString file = m_dir->filePath(QStringLiteral("bad.csv"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("address,value\nR0,1\nR1\n");
    f.close();
    const Run r = runCli(
        link() + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file});
    RUN_IS(r, 2);
    QVERIFY2(r.err.contains(QLatin1String("line 3")), qPrintable(r.err));
    const Run u = runCli(
        link() + QStringList{QStringLiteral("snapshot"), m_dir->filePath(QStringLiteral("x.txt"))});
    RUN_IS(u, 2);
}

QTEST_GUILESS_MAIN(TestSnapshot)
#include "tst_snapshot.moc"
