// Program backup and restore (issue 18): ProgramImage files (round trip, every kind of damage
// refused), ProgramTransfer against the simulator over loopback TCP (backup, restore round trip,
// restore check, model mismatch, cancel, refusals in RUN and in operator mode), counted on the
// simulator's side of the wire.
#include "core/commission/programimage.h"
#include "core/commission/programtransfer.h"
#include "core/protocol/faconcodec.h"
#include "testutil.h"
#include "tst_tools_fixture.h"

#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;
using ToolsTest::plcPages;
using ToolsTest::Rig;

namespace {

std::vector<std::vector<std::uint32_t>> imagePages(const ProgramImage &image)
{
    std::vector<std::vector<std::uint32_t>> pages;
    for (int p = 0; p < image.pageCount(); ++p)
        pages.push_back(image.pageValues(p));
    return pages;
}

ProgramImage powerOnImage(const ModelProfile &profile)
{
    const auto image = ProgramImage::fromWords(profile.powerOnProgram());
    Q_ASSERT(image);
    return *image;
}

// A program that differs from the power-on one in pages 1, 5 and 100..102.
ProgramImage changedImage(const ModelProfile &profile)
{
    std::vector<std::uint16_t> words = profile.powerOnProgram();
    for (const std::size_t page : {1u, 5u, 100u, 101u, 102u}) {
        for (std::size_t i = 0; i < Limits::programPageWords; ++i)
            words[page * Limits::programPageWords + i] = static_cast<std::uint16_t>(page * 7 + i);
    }
    return *ProgramImage::fromWords(words);
}

QString text(const Message &message)
{
    return QString::fromStdString(english(message));
}

using Run = TestUtil::ProgramRun;

// fatek-cli with the event loop turning, so that the in-process simulator answers; its standard
// input is a pipe, never a terminal.
Run runCli(const QStringList &arguments)
{
    return TestUtil::runProgram(QStringLiteral(FATEK_CLI_PATH), arguments, 60000);
}

} // namespace

class TestProgram : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cleanup();

    void headerAndPageList();
    void fileRoundTrip();
    void damagedFilesRefused_data();
    void damagedFilesRefused();
    void answerWithoutErrorDigit();

    void backupReadsEveryPage();
    void restoreRoundTrip();
    void modelMismatchRefused();
    void cancelledRestoreSaysWhereItStopped();
    void restoreRefusedInRun();
    void mSeriesNamedInBackup();
    void restoreRefusedInOperatorMode();
    void cancelledBackup();
    void verificationNamesThePagesThatDiffer();

    void cliBackupRestoreRoundTrip();
    void cliRestoreNeedsConfirmation();
    void cliRestoreRefusals();

private:
    // Starts the rig (fbs, FACON) with the PLC in RUN or STOP.
    bool open(bool running);
    // Runs `start` on a transfer bound to the rig's session and returns its result.
    ProgramTransferResult run(ProgramTransfer &transfer, const std::function<bool()> &start);
    quint64 frames() const { return m_rig.server->counters().frames; }
    // fatek-cli's link options for the rig's simulator.
    QStringList link() const
    {
        return {QStringLiteral("--tcp"),
                QStringLiteral("127.0.0.1:%1").arg(m_rig.server->tcpPort()),
                QStringLiteral("--protocol"), QStringLiteral("facon")};
    }

    Rig m_rig;
    QTemporaryDir m_dir;
};

bool TestProgram::open(bool running)
{
    m_rig = Rig();
    if (!m_rig.start())
        return false;
    m_rig.plc->setRunning(running);
    return true;
}

void TestProgram::cleanup()
{
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

ProgramTransferResult TestProgram::run(ProgramTransfer &transfer,
                                       const std::function<bool()> &start)
{
    transfer.setSession(m_rig.session());
    QSignalSpy done(&transfer, &ProgramTransfer::finished);
    if (!start())
        return {};
    if (done.isEmpty())
        done.wait(60000);
    if (done.size() != 1) {
        ProgramTransferResult none;
        none.status = ProgramTransferResult::Status::Failed;
        none.errorKind = ErrorKind::Timeout;
        none.message = Message::text("no finished()");
        return none;
    }
    return done.first().first().value<ProgramTransferResult>();
}

void TestProgram::headerAndPageList()
{
    const ProgramHeader fbs = ModelProfile::fbs().programHeader();
    QCOMPARE(fbs.pageCount(), std::uint16_t{207});
    const std::vector<std::uint16_t> page0 = fbs.encode();
    QCOMPARE(page0[0], std::uint16_t{0x4642}); // "FB"
    QCOMPARE(page0[2], std::uint16_t{0x3380}); // 13184
    QCOMPARE(ProgramHeader::decode(std::span<const std::uint16_t>(page0)), std::optional{fbs});
    QCOMPARE(ModelProfile::mSeries().programHeader().pageCount(), std::uint16_t{257});
    QVERIFY(!ProgramHeader::decode(
        std::span<const std::uint16_t>(std::vector<std::uint16_t>(Limits::programPageWords, 0))));
    QCOMPARE(pageListText({1, 2, 3, 7, 9, 10}), std::string("1-3, 7, 9-10"));
    QCOMPARE(pageListText({}), std::string());
    QCOMPARE(pageListText({1, 3, 5, 7}, 2), std::string("1, 3, ..."));
}

void TestProgram::fileRoundTrip()
{
    ProgramImage image = changedImage(ModelProfile::fbs());
    image.setModelText(QStringLiteral("FBs-28MC, OS V3.1, program 13184 words"));
    image.setStation(7);
    image.setDate(QDateTime(QDate(2026, 11, 25), QTime(20, 0), Qt::UTC));
    const QString path = m_dir.filePath(QStringLiteral("round.fprog"));
    QVERIFY(!image.save(path));
    const ProgramImage::LoadResult loaded = ProgramImage::load(path);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().text().c_str());
    QCOMPARE(imagePages(loaded.image()), imagePages(image));
    QCOMPARE(loaded.image().header(), image.header());
    QCOMPARE(loaded.image().modelText(), image.modelText());
    QCOMPARE(loaded.image().station(), 7);
    QCOMPARE(loaded.image().date(), image.date());
    QCOMPARE(loaded.image().checksum(), image.checksum());
    QVERIFY(loaded.image().differingPages(image).empty());
    const std::vector<std::uint16_t> differ
        = image.differingPages(powerOnImage(ModelProfile::fbs()));
    QCOMPARE(differ, (std::vector<std::uint16_t>{1, 5, 100, 101, 102}));
    // CRC-32 as zlib computes it.
    QCOMPARE(crc32(QByteArrayLiteral("123456789")), std::uint32_t{0xCBF43926});
}

void TestProgram::damagedFilesRefused_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("mention");
    using Kind = ProgramFileError::Kind;
    const QByteArray good = changedImage(ModelProfile::fbs()).toJson();
    const QJsonObject o = QJsonDocument::fromJson(good).object();
    auto edited = [&o](const std::function<void(QJsonObject &)> &edit) {
        QJsonObject copy = o;
        edit(copy);
        return QJsonDocument(copy).toJson();
    };
    QTest::newRow("not JSON") << QByteArrayLiteral("hello") << int(Kind::NotJson)
                              << QStringLiteral("JSON");
    QTest::newRow("truncated") << good.left(good.size() / 2) << int(Kind::NotJson)
                               << QStringLiteral("JSON");
    QTest::newRow("watch list") << QByteArrayLiteral("{\"format\": \"fatek-watchlist\"}")
                                << int(Kind::WrongFormat) << QStringLiteral("fatek-watchlist");
    QTest::newRow("newer version")
        << edited([](QJsonObject &c) { c.insert(QStringLiteral("version"), 9); })
        << int(Kind::Version) << QStringLiteral("version 9");
    QTest::newRow("page missing") << edited([](QJsonObject &c) {
        QJsonArray pages = c.value(QStringLiteral("pages")).toArray();
        pages.removeLast();
        c.insert(QStringLiteral("pages"), pages);
    }) << int(Kind::PageCount) << QStringLiteral("206 pages");
    QTest::newRow("no crc") << edited([](QJsonObject &c) { c.remove(QStringLiteral("crc32")); })
                            << int(Kind::Field) << QStringLiteral("crc32");
    QTest::newRow("word changed") << edited([](QJsonObject &c) {
        QJsonArray pages = c.value(QStringLiteral("pages")).toArray();
        QString page = pages.at(3).toString();
        page.replace(0, 4, QStringLiteral("BEEF"));
        pages.replace(3, page);
        c.insert(QStringLiteral("pages"), pages);
    }) << int(Kind::Checksum) << QStringLiteral("checksum");
    QTest::newRow("short page") << edited([](QJsonObject &c) {
        QJsonArray pages = c.value(QStringLiteral("pages")).toArray();
        pages.replace(4, pages.at(4).toString().left(200));
        c.insert(QStringLiteral("pages"), pages);
    }) << int(Kind::BadPage) << QStringLiteral("page 4");
    // A file whose page 0 is no header, with a checksum that fits its words.
    ProgramImage noHeader = changedImage(ModelProfile::fbs());
    const QJsonObject n = QJsonDocument::fromJson(noHeader.toJson()).object();
    QJsonObject bad = n;
    QJsonArray pages = bad.value(QStringLiteral("pages")).toArray();
    pages.replace(0, QString(256, QLatin1Char('0')));
    bad.insert(QStringLiteral("pages"), pages);
    QByteArray words;
    for (const QJsonValue &p : std::as_const(pages))
        words += QByteArray::fromHex(p.toString().toLatin1());
    bad.insert(QStringLiteral("crc32"),
               QStringLiteral("%1").arg(crc32(words), 8, 16, QLatin1Char('0')).toUpper());
    QTest::newRow("no header") << QJsonDocument(bad).toJson() << int(Kind::BadHeader)
                               << QStringLiteral("header");
}

void TestProgram::damagedFilesRefused()
{
    QFETCH(QByteArray, content);
    QFETCH(int, kind);
    QFETCH(QString, mention);
    const QString path = m_dir.filePath(QStringLiteral("damaged.fprog"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(content);
    file.close();
    const ProgramImage::LoadResult r = ProgramImage::load(path);
    QVERIFY(!r.ok());
    const QString why = QString::fromStdString(r.error().text());
    QVERIFY2(int(r.error().kind) == kind, qPrintable(why));
    QVERIFY2(why.contains(mention), qPrintable(why));
    const ProgramImage::LoadResult missing = ProgramImage::load(m_dir.filePath("none.fprog"));
    QVERIFY(!missing.ok());
    QCOMPARE(missing.error().kind, ProgramFileError::Kind::Unreadable);
}

// The seed's 4F answer has no error digit: a page the simulator answers, with the digit taken
// out, decodes to the same words.
void TestProgram::answerWithoutErrorDigit()
{
    SimulatedPlc plc;
    FaconCodec codec;
    const Request request = Request::readProgram(1, 1);
    const Response answer = plc.execute(request);
    const Bytes withDigit = codec.encodeResponse(request, answer);
    std::string body(withDigit.begin() + 1, withDigit.end() - 3); // "014F0" + 256 hex digits
    QCOMPARE(body.substr(0, 5), std::string("014F0"));
    body.erase(4, 1);
    // Framed again (STX, LRC, ETX) by the codec's own framing.
    const Bytes withoutDigit = codec.wrap(Bytes(body.begin(), body.end()), true);
    const auto decoded = codec.decodeResponse(withoutDigit, request);
    QVERIFY(decoded.ok());
    QCOMPARE(decoded->values, plc.programPage(1));
}

void TestProgram::backupReadsEveryPage()
{
    QVERIFY(open(true)); // a backup reads: RUN is fine
    ProgramTransfer transfer;
    QSignalSpy progress(&transfer, &ProgramTransfer::progress);
    const quint64 before = frames();
    const ProgramTransferResult r = run(transfer, [&] { return transfer.backup(); });
    QVERIFY2(r.ok(), qPrintable(text(r.message)));
    QCOMPARE(transfer.plcImage().pageCount(), 207);
    QCOMPARE(imagePages(transfer.plcImage()), plcPages(*m_rig.plc));
    QCOMPARE(transfer.plcImage().header(), ModelProfile::fbs().programHeader());
    QVERIFY(transfer.plcImage().modelText().contains(QStringLiteral("13184")));
    QCOMPARE(frames() - before, quint64{1 + 207}); // 53, then every page once
    QCOMPARE(progress.last().at(0).toInt(), 207);
    QCOMPARE(progress.last().at(1).toInt(), 207);
    QCOMPARE(r.pagesDone, 207);
    QVERIFY(text(r.message).contains(QStringLiteral("207 pages")));
}

void TestProgram::restoreRoundTrip()
{
    QVERIFY(open(true));
    ProgramTransfer transfer;
    QVERIFY(run(transfer, [&] { return transfer.backup(); }).ok());
    const QString path = m_dir.filePath(QStringLiteral("backup.fprog"));
    QVERIFY(!transfer.plcImage().save(path));
    const auto backup = ProgramImage::load(path);
    QVERIFY(backup.ok());

    // Someone changes the program on the PLC; the restore check lists the changed pages and
    // writes nothing.
    const ProgramImage changed = changedImage(ModelProfile::fbs());
    QVERIFY(m_rig.plc->setProgram(changed.words()));
    m_rig.plc->setRunning(false);
    quint64 before = frames();
    ProgramTransferResult check
        = run(transfer, [&] { return transfer.checkRestore(backup.image()); });
    QVERIFY2(check.ok(), qPrintable(text(check.message)));
    QCOMPARE(check.pages, (std::vector<std::uint16_t>{1, 5, 100, 101, 102}));
    QVERIFY2(
        text(check.message).contains(QStringLiteral("5 pages differ from the PLC (1, 5, 100-102)")),
        qPrintable(text(check.message)));
    QCOMPARE(frames() - before, quint64{2 + 207}); // 40, 53, every page
    QCOMPARE(imagePages(changed), plcPages(*m_rig.plc));

    // The restore writes every page and reads every page back: the simulator holds the backup.
    QSignalSpy progress(&transfer, &ProgramTransfer::progress);
    before = frames();
    const ProgramTransferResult r = run(transfer, [&] { return transfer.restore(backup.image()); });
    QVERIFY2(r.ok(), qPrintable(text(r.message)));
    QCOMPARE(plcPages(*m_rig.plc), imagePages(backup.image()));
    QCOMPARE(frames() - before, quint64{3 + 207 + 207}); // 40, 53, page 0, writes, read-backs
    QCOMPARE(progress.last().at(0).toInt(), 2 * 207);
    QCOMPARE(progress.last().at(1).toInt(), 2 * 207);
    QCOMPARE(r.pagesDone, 207);
    QVERIFY(text(r.message).contains(QStringLiteral("207 pages written and verified")));
    // Now the check finds nothing to change.
    check = run(transfer, [&] { return transfer.checkRestore(backup.image()); });
    QVERIFY(check.ok());
    QVERIFY(check.pages.empty());
}

void TestProgram::modelMismatchRefused()
{
    QVERIFY(open(false));
    const ProgramImage mBackup = powerOnImage(ModelProfile::mSeries());
    const auto before = plcPages(*m_rig.plc);
    const quint64 framesBefore = frames();
    ProgramTransfer transfer;
    for (const bool checkOnly : {true, false}) {
        const ProgramTransferResult r = run(transfer, [&] {
            return checkOnly ? transfer.checkRestore(mBackup) : transfer.restore(mBackup);
        });
        QCOMPARE(r.status, ProgramTransferResult::Status::Failed);
        QCOMPARE(r.problem, ProgramTransferResult::Problem::ModelMismatch);
        QVERIFY2(text(r.message).contains(QStringLiteral("M series, 16384-word")),
                 qPrintable(text(r.message)));
        QVERIFY2(text(r.message).contains(QStringLiteral("nothing was written")),
                 qPrintable(text(r.message)));
    }
    QCOMPARE(plcPages(*m_rig.plc), before);
    QCOMPARE(frames() - framesBefore, quint64{2 + 2}); // 40 and 53 each time: no page at all

    // The same family with a header that says otherwise is refused after page 0.
    std::vector<std::uint16_t> words = ModelProfile::fbs().powerOnProgram();
    words[0] = 0x464D; // "FM"
    const ProgramImage wrongFamily = *ProgramImage::fromWords(words);
    const ProgramTransferResult r = run(transfer, [&] { return transfer.restore(wrongFamily); });
    QCOMPARE(r.problem, ProgramTransferResult::Problem::ModelMismatch);
    QCOMPARE(plcPages(*m_rig.plc), before);
}

void TestProgram::cancelledRestoreSaysWhereItStopped()
{
    QVERIFY(open(false));
    const auto before = plcPages(*m_rig.plc);
    const ProgramImage changed = changedImage(ModelProfile::fbs());
    ProgramTransfer transfer;
    // Cancelled as page 2 is written (3 pages done): it stops before page 3.
    connect(&transfer, &ProgramTransfer::progress, &transfer, [&transfer](int done, int) {
        if (transfer.phase() == ProgramTransfer::Phase::Writing && done == 3)
            transfer.cancel();
    });
    const ProgramTransferResult r = run(transfer, [&] { return transfer.restore(changed); });
    QCOMPARE(r.status, ProgramTransferResult::Status::Cancelled);
    QCOMPARE(r.stoppedAtPage, 3);
    QCOMPARE(r.pagesDone, 3);
    QVERIFY2(text(r.message).contains(QStringLiteral("cancelled at page 3 (3 of 207 pages")),
             qPrintable(text(r.message)));
    const auto after = plcPages(*m_rig.plc);
    for (std::size_t p = 0; p < after.size(); ++p)
        QCOMPARE(after[p], p < 3 ? changed.pageValues(int(p)) : before[p]);
}

void TestProgram::restoreRefusedInRun()
{
    QVERIFY(open(true));
    const auto before = plcPages(*m_rig.plc);
    const quint64 framesBefore = frames();
    ProgramTransfer transfer;
    const ProgramTransferResult r
        = run(transfer, [&] { return transfer.restore(changedImage(ModelProfile::fbs())); });
    QCOMPARE(r.status, ProgramTransferResult::Status::Failed);
    QCOMPARE(r.problem, ProgramTransferResult::Problem::Running);
    QVERIFY2(text(r.message).contains(QStringLiteral("STOP")), qPrintable(text(r.message)));
    // 40, 53 and page 0: the model is checked before RUN is reported (the question to STOP
    // comes only for a restore that can go ahead).
    QCOMPARE(frames() - framesBefore, quint64{3});
    QCOMPARE(plcPages(*m_rig.plc), before);
}

// The M profile's detail status names no FBs model: its backup names the M series (from the
// program header's family), never "FBs-40MC".
void TestProgram::mSeriesNamedInBackup()
{
    QVERIFY(m_rig.start(LinkSettings::ProtocolChoice::Facon, 1000, 1, ModelProfile::mSeries()));
    ProgramTransfer transfer;
    const ProgramTransferResult r = run(transfer, [&] { return transfer.backup(); });
    QVERIFY2(r.ok(), qPrintable(text(r.message)));
    const QString model = transfer.plcImage().modelText();
    QVERIFY2(model.startsWith(QStringLiteral("M series")), qPrintable(model));
    QVERIFY2(!model.contains(QStringLiteral("FBs")), qPrintable(model));
    QVERIFY2(model.contains(QStringLiteral("16384")), qPrintable(model));
}

void TestProgram::restoreRefusedInOperatorMode()
{
    QVERIFY(open(false));
    m_rig.session()->setReadOnly(true);
    const auto before = plcPages(*m_rig.plc);
    const quint64 framesBefore = frames();
    ProgramTransfer transfer;
    for (const bool checkOnly : {true, false}) {
        const ProgramImage image = changedImage(ModelProfile::fbs());
        const ProgramTransferResult r = run(transfer, [&] {
            return checkOnly ? transfer.checkRestore(image) : transfer.restore(image);
        });
        QCOMPARE(r.status, ProgramTransferResult::Status::Failed);
        QCOMPARE(r.problem, ProgramTransferResult::Problem::ReadOnly);
        QCOMPARE(r.errorKind, ErrorKind::ReadOnly);
        QVERIFY(text(r.message).contains(QStringLiteral("Operator mode")));
    }
    QCOMPARE(frames(), framesBefore); // nothing on the wire at all
    QCOMPARE(plcPages(*m_rig.plc), before);
    // A backup only reads: allowed in operator mode.
    QVERIFY(run(transfer, [&] { return transfer.backup(); }).ok());
}

void TestProgram::cancelledBackup()
{
    QVERIFY(open(true));
    ProgramTransfer transfer;
    const auto cancelAt10
        = connect(&transfer, &ProgramTransfer::progress, &transfer, [&transfer](int done, int) {
              if (done == 10)
                  transfer.cancel();
          });
    const ProgramTransferResult r = run(transfer, [&] { return transfer.backup(); });
    QCOMPARE(r.status, ProgramTransferResult::Status::Cancelled);
    QCOMPARE(r.stoppedAtPage, 10);
    QVERIFY2(text(r.message).contains(QStringLiteral("page 10 (10 of 207 pages read)")),
             qPrintable(text(r.message)));
    QVERIFY(!transfer.isRunning());
    // It can run again, to the end.
    disconnect(cancelAt10);
    QVERIFY(run(transfer, [&] { return transfer.backup(); }).ok());
    QVERIFY(transfer.lastResult().ok());
}

// A page changed on the PLC behind the transfer's back while it reads back: the restore fails and
// names exactly that page.
void TestProgram::verificationNamesThePagesThatDiffer()
{
    QVERIFY(open(false));
    const ProgramImage changed = changedImage(ModelProfile::fbs());
    ProgramTransfer transfer;
    SimulatedPlc *plc = m_rig.plc.get();
    connect(&transfer, &ProgramTransfer::progress, &transfer, [&transfer, plc](int done, int) {
        if (transfer.phase() == ProgramTransfer::Phase::Verifying && done == 207 + 10)
            plc->setProgramPage(150, std::vector<std::uint32_t>(64, 0xDEAD));
    });
    const ProgramTransferResult r = run(transfer, [&] { return transfer.restore(changed); });
    QCOMPARE(r.status, ProgramTransferResult::Status::Failed);
    QCOMPARE(r.problem, ProgramTransferResult::Problem::VerifyFailed);
    QCOMPARE(r.pages, std::vector<std::uint16_t>{150});
    QVERIFY2(text(r.message).contains(QStringLiteral("1 page on the PLC differs from the backup "
                                                     "(150)")),
             qPrintable(text(r.message)));
}

#define RUN_OK(r)                                                                                  \
    QVERIFY2((r).code == 0,                                                                        \
             qPrintable(QStringLiteral("exit %1: %2 %3").arg((r).code).arg((r).err, (r).out)))

void TestProgram::cliBackupRestoreRoundTrip()
{
    // Seen under Wine only (2026-11-27), about every second run: the PLC holds the restored
    // program and fatek-cli.exe exits 0, but its last line on stdout (the outcome) never reaches
    // the test's QProcess; the lines before it do.
    if (TestUtil::underWine())
        QSKIP("Wine loses fatek-cli.exe's last stdout line now and then (docs/windows.md)");
    QVERIFY(open(true));
    const QString file = m_dir.filePath(QStringLiteral("cli.fprog"));
    const Run backup
        = runCli(link() + QStringList{QStringLiteral("--json"), QStringLiteral("backup"), file});
    RUN_OK(backup);
    QCOMPARE(backup.json().value(QStringLiteral("pages")).toInt(), 207);
    QCOMPARE(backup.json().value(QStringLiteral("programWords")).toInt(), 13184);
    const auto saved = ProgramImage::load(file);
    QVERIFY(saved.ok());
    QCOMPARE(imagePages(saved.image()), plcPages(*m_rig.plc));

    const ProgramImage changed = changedImage(ModelProfile::fbs());
    QVERIFY(m_rig.plc->setProgram(changed.words()));
    // In RUN: refused, nothing written, the way out named.
    const Run inRun
        = runCli(link() + QStringList{QStringLiteral("--yes"), QStringLiteral("restore"), file});
    QCOMPARE(inRun.code, 4);
    QVERIFY2(inRun.err.contains(QStringLiteral("fatek-cli stop")), qPrintable(inRun.err));
    QCOMPARE(plcPages(*m_rig.plc), imagePages(changed));

    const Run restore = runCli(link()
                               + QStringList{QStringLiteral("--json"), QStringLiteral("--yes"),
                                             QStringLiteral("stop"), QStringLiteral("--then"),
                                             QStringLiteral("restore"), file});
    RUN_OK(restore);
    QVERIFY2(restore.err.contains(QStringLiteral("5 pages differ from the PLC (1, 5, 100-102)")),
             qPrintable(restore.err));
    // The last line is the outcome (the check comes first).
    const QJsonObject result
        = QJsonDocument::fromJson(restore.lines().constLast().toUtf8()).object();
    QVERIFY2(result.value(QStringLiteral("verified")).toBool(),
             qPrintable(restore.out + restore.err));
    QCOMPARE(result.value(QStringLiteral("changedPages")).toArray().size(), 5);
    QCOMPARE(plcPages(*m_rig.plc), imagePages(saved.image()));
    // The PLC stays in STOP; the output says how to start it.
    QVERIFY(!m_rig.plc->isRunning());
    QVERIFY2(restore.err.contains(QStringLiteral("--then restore FILE --then run")),
             qPrintable(restore.err));
    // Chained to RUN: started, and no such hint.
    const Run chained
        = runCli(link()
                 + QStringList{QStringLiteral("--yes"), QStringLiteral("stop"),
                               QStringLiteral("--then"), QStringLiteral("restore"), file,
                               QStringLiteral("--then"), QStringLiteral("run")});
    RUN_OK(chained);
    QVERIFY2(!chained.err.contains(QStringLiteral("stays in STOP")), qPrintable(chained.err));
    QVERIFY(m_rig.plc->isRunning());
}

void TestProgram::cliRestoreNeedsConfirmation()
{
    QVERIFY(open(false));
    const QString file = m_dir.filePath(QStringLiteral("confirm.fprog"));
    QVERIFY(!changedImage(ModelProfile::fbs()).save(file));
    const auto before = plcPages(*m_rig.plc);
    const Run r = runCli(link() + QStringList{QStringLiteral("restore"), file});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("--yes")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("Nothing was written")), qPrintable(r.err));
    // What would be written was shown first.
    QVERIFY2(r.err.contains(QStringLiteral("207 pages")), qPrintable(r.err));
    QCOMPARE(plcPages(*m_rig.plc), before);
}

void TestProgram::cliRestoreRefusals()
{
    QVERIFY(open(false));
    const auto before = plcPages(*m_rig.plc);
    // A damaged file: exit 2 before the link is used.
    const QString damaged = m_dir.filePath(QStringLiteral("damaged-cli.fprog"));
    QFile f(damaged);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(changedImage(ModelProfile::fbs()).toJson().left(5000));
    f.close();
    const quint64 framesBefore = frames();
    const Run bad
        = runCli(link() + QStringList{QStringLiteral("--yes"), QStringLiteral("restore"), damaged});
    QCOMPARE(bad.code, 2);
    QVERIFY2(bad.err.contains(QStringLiteral("JSON")), qPrintable(bad.err));
    QCOMPARE(frames(), framesBefore);
    // Another model: exit 2.
    const QString mFile = m_dir.filePath(QStringLiteral("m.fprog"));
    QVERIFY(!powerOnImage(ModelProfile::mSeries()).save(mFile));
    const Run other
        = runCli(link() + QStringList{QStringLiteral("--yes"), QStringLiteral("restore"), mFile});
    QCOMPARE(other.code, 2);
    QVERIFY2(other.err.contains(QStringLiteral("M series")), qPrintable(other.err));
    // Operator mode: exit 5, nothing on the wire.
    const QString good = m_dir.filePath(QStringLiteral("good.fprog"));
    QVERIFY(!changedImage(ModelProfile::fbs()).save(good));
    const quint64 framesRo = frames();
    const Run ro = runCli(link()
                          + QStringList{QStringLiteral("--read-only"), QStringLiteral("--yes"),
                                        QStringLiteral("restore"), good});
    QCOMPARE(ro.code, 5);
    QCOMPARE(frames(), framesRo);
    QCOMPARE(plcPages(*m_rig.plc), before);
}

QTEST_GUILESS_MAIN(TestProgram)
#include "tst_program.moc"
