// Issue 48, cases 9 and 10: a restore of values is checked against the PLC's model and element
// ranges before its first write, and fatek-cli restore-values refuses an empty RANGES argument.
// Against two in-process simulators over loopback TCP, an FBs and an M series; what was written
// is counted on the wire (the simulator's request log) and read from the simulator's memory.
#include "core/commission/snapshotfile.h"
#include "core/commission/snapshotreader.h"
#include "core/commission/valuesrestorer.h"
#include "core/protocol/plcmodel.h"
#include "core/qtbridge/qtmessage.h"
#include "core/session/session.h"
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return Address::parse(text).value();
}

// One simulated PLC on a free port, its requests logged, and a session to it.
struct Plc
{
    std::unique_ptr<SimulatedPlc> plc;
    std::unique_ptr<SimServer> server;
    std::unique_ptr<Session> session;
    QStringList log;

    bool start(const ModelProfile &profile)
    {
        plc = std::make_unique<SimulatedPlc>(profile);
        server = std::make_unique<SimServer>(plc.get());
        server->setVerbose(true);
        QObject::connect(server.get(), &SimServer::logLine, server.get(),
                         [this](const QString &line) { log << line; });
        if (!server->listenTcp(0))
            return false;
        LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server->tcpPort(),
                                                  LinkSettings::ProtocolChoice::Facon);
        settings.timeoutMs = 2000;
        settings.retries = 1;
        session = std::make_unique<Session>(settings);
        session->open();
        QDeadlineTimer deadline(10000);
        while (session->linkState() != LinkState::Connected && !deadline.hasExpired())
            QTest::qWait(5);
        return session->linkState() == LinkState::Connected;
    }

    QStringList link() const
    {
        return {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(server->tcpPort()),
                QStringLiteral("--protocol"), QStringLiteral("facon")};
    }

    // Write requests that reached the simulator (45, 47, 49; decoded or refused).
    int writesOnTheWire() const
    {
        static const QRegularExpression write(QStringLiteral(" (write|command 4[579]:)"));
        int n = 0;
        for (const QString &line : log)
            n += write.match(line).hasMatch() ? 1 : 0;
        return n;
    }
};

TestUtil::ProgramRun runCli(const QStringList &arguments)
{
    return TestUtil::runProgram(QStringLiteral(FATEK_CLI_PATH), arguments);
}

} // namespace

#define RUN_IS(r, expected)                                                                        \
    QVERIFY2((r).code == (expected),                                                               \
             qPrintable(QStringLiteral("exit %1: %2 %3").arg((r).code).arg((r).err, (r).out)))

class TestRestoreCheck : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void modelsFromDetailStatus();
    void outOfRangeRefusedBeforeAnyWrite();
    void otherModelRefusedUnlessAllowed();
    void cliOutOfRangeRefusedByName();
    void cliOtherModelNeedsTheOption();
    void cliEmptyRangesIsAUsageError();

private:
    // A snapshot of `ranges` read from `from`, saved in `name`.
    QString snapshotFile(Plc &from, const char *ranges, const QString &name);
    bool restore(ValuesRestorer &restorer, const std::vector<SnapshotValue> &values,
                 const QString &model);

    Plc m_fbs;
    Plc m_m;
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestRestoreCheck::init()
{
    registerSessionMetaTypes();
    m_fbs = {};
    m_m = {};
    QVERIFY(m_fbs.start(ModelProfile::fbs()));
    QVERIFY(m_m.start(ModelProfile::mSeries()));
    m_dir = std::make_unique<QTemporaryDir>();
}

void TestRestoreCheck::cleanup()
{
    for (Plc *p : {&m_fbs, &m_m}) {
        p->session.reset();
        p->server.reset();
        p->plc.reset();
    }
    m_dir.reset();
}

QString TestRestoreCheck::snapshotFile(Plc &from, const char *ranges, const QString &name)
{
    const QString path = m_dir->filePath(name);
    const TestUtil::ProgramRun r = runCli(
        from.link() + QStringList{QStringLiteral("snapshot"), path, QString::fromLatin1(ranges)});
    if (r.code != 0)
        qWarning() << "snapshot failed:" << r.err;
    return path;
}

bool TestRestoreCheck::restore(ValuesRestorer &restorer, const std::vector<SnapshotValue> &values,
                               const QString &model)
{
    QSignalSpy done(&restorer, &ValuesRestorer::finished);
    restorer.start(1, values, model);
    return done.wait(20000);
}

void TestRestoreCheck::modelsFromDetailStatus()
{
    const auto fbs
        = PlcModel::fromDetailStatus(DetailStatus::decode(ModelProfile::fbs().detailStatus(1)));
    QVERIFY(fbs);
    QCOMPARE(fbs->family, PlcModel::Family::FBs);
    QVERIFY(fbs->contains(addr("R3839")));
    QVERIFY(!fbs->contains(addr("R5000")));
    QVERIFY(!fbs->contains(addr("DR3839"))); // needs R3840 too
    QCOMPARE(fbs->rangeText(ElementType::R), std::string("R0-3839"));
    QCOMPARE(fbs->rangeText(ElementType::F), std::string("no F"));
    const DetailStatus m = DetailStatus::decode(ModelProfile::mSeries().detailStatus(1));
    QCOMPARE(PlcModel::fromDetailStatus(m)->family, PlcModel::Family::M);
    QVERIFY(PlcModel::fromDetailStatus(m)->contains(addr("R65535")));
    QCOMPARE(PlcModel::modelText(m), std::string("M series, OS V3.1, program 16384 words"));
    // Model texts: as snapshots record them now, an M's 53 summary as they did before, none.
    QCOMPARE(PlcModel::familyOfText("FBs-28MC, OS V3.1, program 13184 words"),
             std::optional(PlcModel::Family::FBs));
    QCOMPARE(PlcModel::familyOfText(PlcModel::modelText(m)), std::optional(PlcModel::Family::M));
    QCOMPARE(PlcModel::familyOfText(m.summary()), std::optional(PlcModel::Family::M));
    QCOMPARE(PlcModel::familyOfText(""), std::nullopt);
    // An answer too short to hold the main-unit byte or a size: no model to check against.
    const std::vector<std::uint8_t> shortAnswer = {0x01};
    QVERIFY(!PlcModel::fromDetailStatus(DetailStatus::decode(shortAnswer)));
}

// Case 10: 16 values the FBs has and 24 it has not (R5000..R5023). Today's restore wrote the
// first write request and failed the next one with "illegal address"; now nothing goes out but
// the 53, and the message names the elements and what the PLC has.
void TestRestoreCheck::outOfRangeRefusedBeforeAnyWrite()
{
    std::vector<SnapshotValue> values;
    for (std::uint32_t n = 0; n < 16; ++n)
        values.push_back({Address{ElementType::R, n}, 100 + n});
    for (std::uint32_t n = 5000; n < 5024; ++n)
        values.push_back({Address{ElementType::R, n}, 1});
    ValuesRestorer restorer;
    restorer.setSession(m_fbs.session.get());
    m_fbs.log.clear();
    QVERIFY(restore(restorer, values, QStringLiteral("FBs-28MC, OS V3.1")));
    QVERIFY(!restorer.ok());
    QCOMPARE(restorer.error()->kind, ErrorKind::InvalidAddress);
    const QString outcome = englishText(restorer.outcome());
    QVERIFY2(outcome.contains(QLatin1String("24 values of the snapshot are not on the PLC: "
                                            "R5000-5023")),
             qPrintable(outcome));
    QVERIFY2(outcome.contains(QLatin1String("has R0-3839")), qPrintable(outcome));
    QVERIFY2(outcome.contains(QLatin1String("nothing was written")), qPrintable(outcome));
    QVERIFY2(!outcome.contains(QLatin1String("illegal")), qPrintable(outcome));
    QCOMPARE(m_fbs.writesOnTheWire(), 0);
    QCOMPARE(m_fbs.log.size(), 1); // the 53
    QCOMPARE(m_fbs.plc->value(addr("R0")), std::optional<std::uint32_t>(0));
    QCOMPARE(restorer.valuesWritten(), 0);

    // The same values without the foreign ones: written and read back.
    values.resize(16);
    QVERIFY(restore(restorer, values, QStringLiteral("FBs-28MC, OS V3.1")));
    QVERIFY2(restorer.ok(), qPrintable(englishText(restorer.outcome())));
    QCOMPARE(m_fbs.plc->value(addr("R15")), std::optional<std::uint32_t>(115));
}

// Case 10: a snapshot of an M-series PLC, written to an FBs: refused with both model names,
// nothing written; allowed explicitly, its values (all on the FBs) are written.
void TestRestoreCheck::otherModelRefusedUnlessAllowed()
{
    m_m.plc->setValue(addr("R3"), 33);
    SnapshotReader reader;
    reader.setSession(m_m.session.get());
    QSignalSpy read(&reader, &SnapshotReader::finished);
    reader.start(1, {AddressRange{addr("R0"), 10}});
    QVERIFY(read.wait(20000));
    QVERIFY(reader.ok());
    const MemorySnapshot snapshot = reader.snapshot();
    QCOMPARE(snapshot.info.model, QStringLiteral("M series, OS V3.1, program 16384 words"));

    ValuesRestorer restorer;
    restorer.setSession(m_fbs.session.get());
    m_fbs.log.clear();
    QVERIFY(restore(restorer, snapshot.values, snapshot.info.model));
    QVERIFY(!restorer.ok());
    QVERIFY(restorer.refusedForModel());
    const QString outcome = englishText(restorer.outcome());
    QVERIFY2(outcome.contains(QLatin1String("M series, OS V3.1")), qPrintable(outcome));
    QVERIFY2(outcome.contains(QLatin1String("FBs-28MC")), qPrintable(outcome));
    QCOMPARE(restorer.plcModel(), QStringLiteral("FBs-28MC, OS V3.1, program 13184 words"));
    QCOMPARE(m_fbs.writesOnTheWire(), 0);
    QCOMPARE(m_fbs.plc->value(addr("R3")), std::optional<std::uint32_t>(0));

    restorer.setAllowOtherModel(true);
    QVERIFY(restore(restorer, snapshot.values, snapshot.info.model));
    QVERIFY2(restorer.ok(), qPrintable(englishText(restorer.outcome())));
    QVERIFY(!restorer.refusedForModel());
    QCOMPARE(m_fbs.writesOnTheWire(), 1);
    QCOMPARE(m_fbs.plc->value(addr("R3")), std::optional<std::uint32_t>(33));
}

// Case 10 from the command line: the file names the elements, exit 2, nothing written.
void TestRestoreCheck::cliOutOfRangeRefusedByName()
{
    const QString file = m_dir->filePath(QStringLiteral("mixed.csv"));
    MemorySnapshot s;
    s.info.model = QStringLiteral("FBs-28MC, OS V3.1, program 13184 words");
    for (std::uint32_t n = 0; n < 16; ++n)
        s.values.push_back({Address{ElementType::R, n}, 7});
    for (std::uint32_t n = 5000; n < 5024; ++n)
        s.values.push_back({Address{ElementType::R, n}, 1});
    QVERIFY(!SnapshotFile::saveToFile(s, file));
    m_fbs.log.clear();
    const TestUtil::ProgramRun r
        = runCli(m_fbs.link()
                 + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file});
    RUN_IS(r, 2);
    QVERIFY2(r.err.contains(QLatin1String("not on the PLC: R5000-5023")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String("illegal")), qPrintable(r.err));
    QCOMPARE(m_fbs.writesOnTheWire(), 0);
    QCOMPARE(m_fbs.plc->value(addr("R0")), std::optional<std::uint32_t>(0));
}

// Case 10 from the command line: an M's snapshot to an FBs needs --other-model.
void TestRestoreCheck::cliOtherModelNeedsTheOption()
{
    m_m.plc->setValue(addr("R3"), 33);
    const QString file = snapshotFile(m_m, "R0..R9", QStringLiteral("m.json"));
    m_fbs.log.clear();
    TestUtil::ProgramRun r
        = runCli(m_fbs.link()
                 + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file});
    RUN_IS(r, 2);
    QVERIFY2(r.err.contains(QLatin1String("M series")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("FBs-28MC")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("--other-model")), qPrintable(r.err));
    QCOMPARE(m_fbs.writesOnTheWire(), 0);
    QCOMPARE(m_fbs.plc->value(addr("R3")), std::optional<std::uint32_t>(0));

    r = runCli(m_fbs.link()
               + QStringList{QStringLiteral("--yes"), QStringLiteral("--other-model"),
                             QStringLiteral("restore-values"), file});
    RUN_IS(r, 0);
    QCOMPARE(m_fbs.writesOnTheWire(), 1);
    QCOMPARE(m_fbs.plc->value(addr("R3")), std::optional<std::uint32_t>(33));
    // The option belongs to restore-values alone.
    r = runCli(m_fbs.link()
               + QStringList{QStringLiteral("--other-model"), QStringLiteral("status")});
    RUN_IS(r, 2);
}

// Case 9: restore-values FILE "" wrote every value of the file, as if no RANGES were given.
void TestRestoreCheck::cliEmptyRangesIsAUsageError()
{
    for (std::uint32_t n = 0; n < 39; ++n)
        m_fbs.plc->setValue(Address{ElementType::D, n}, 9);
    const QString file = snapshotFile(m_fbs, "D0..D38", QStringLiteral("d.csv"));
    for (std::uint32_t n = 0; n < 39; ++n)
        m_fbs.plc->setValue(Address{ElementType::D, n}, 0);
    m_fbs.log.clear();
    for (const QString &blank : {QString(), QStringLiteral("  ")}) {
        const TestUtil::ProgramRun r = runCli(
            m_fbs.link()
            + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file, blank});
        RUN_IS(r, 2);
        QVERIFY2(r.err.contains(QLatin1String("RANGES is empty")), qPrintable(r.err));
    }
    QCOMPARE(m_fbs.writesOnTheWire(), 0);
    QCOMPARE(m_fbs.plc->value(addr("D0")), std::optional<std::uint32_t>(0));
    // Left out, RANGES means every value.
    const TestUtil::ProgramRun r
        = runCli(m_fbs.link()
                 + QStringList{QStringLiteral("--yes"), QStringLiteral("restore-values"), file});
    RUN_IS(r, 0);
    QCOMPARE(m_fbs.plc->value(addr("D38")), std::optional<std::uint32_t>(9));
}

QTEST_GUILESS_MAIN(TestRestoreCheck)
#include "tst_restorecheck.moc"
