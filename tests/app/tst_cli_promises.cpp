// fatek-cli's exit codes and files as a script relies on them (issue 56, items 2 and 4-9): the
// built program against its embedded simulator (--sim). "Cannot be written" is made for real:
// /dev/full (a device that is always full), a missing folder, a path under a regular file
// ("Not a directory"), /proc (no new files), and small tmpfs mounts, read-only or nearly full
// (the tests run as root; without the right to mount those rows are skipped). A folder of mode
// 0555 would not stop root, so none is used.
#include "testutil.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace {

using Run = TestUtil::ProgramRun;

// fatek-cli with `input` on its standard input (then closed), its standard output into `outFile`
// when given, or into a pipe whose reader is gone when `closedPipe`.
Run cli(const QStringList &arguments, const QByteArray &input = {}, const QString &outFile = {},
        bool closedPipe = false)
{
    if (outFile.isEmpty() && !closedPipe)
        return TestUtil::runProgramWith(QStringLiteral(FATEK_CLI_PATH), arguments, input);
    QProcess p;
    if (!outFile.isEmpty())
        p.setStandardOutputFile(outFile);
#ifdef Q_OS_UNIX
    int pipeEnds[2] = {-1, -1};
    if (closedPipe && ::pipe(pipeEnds) == 0) {
        ::close(pipeEnds[0]); // nobody will ever read: every write is EPIPE
        const int writeEnd = pipeEnds[1];
        p.setChildProcessModifier([writeEnd] { ::dup2(writeEnd, STDOUT_FILENO); });
    }
#endif
    p.start(QStringLiteral(FATEK_CLI_PATH), arguments);
    Run r;
    if (p.waitForStarted(10000)) {
        p.closeWriteChannel();
        if (p.waitForFinished(60000)) {
            r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
            r.err = QString::fromUtf8(p.readAllStandardError());
        } else {
            p.kill();
            p.waitForFinished();
        }
    }
#ifdef Q_OS_UNIX
    if (pipeEnds[1] >= 0)
        ::close(pipeEnds[1]);
#endif
    return r;
}

QStringList sim(const QStringList &args)
{
    return QStringList{QStringLiteral("--sim")} + args;
}

QByteArray bytesOf(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

// The places of a test's rows: a regular file "plain.txt" in `dir` (a path under it is "Not a
// directory") and, when `readOnly`, a read-only tmpfs "ro" (holding `keep` when given); an empty
// text when ready, else why not (no right to mount).
QString preparePlace(const QTemporaryDir &dir, bool readOnly, TestUtil::TmpfsMount *mount,
                     const QString &keep = {}, const QByteArray &keepBytes = {})
{
    if (!writeBytes(dir.filePath(QStringLiteral("plain.txt")), "x"))
        return QStringLiteral("cannot write in the test's folder");
    if (!readOnly)
        return {};
    const QString ro = dir.filePath(QStringLiteral("ro"));
    if (QString problem = mount->mount(ro, 64); !problem.isEmpty())
        return problem;
    if (!keep.isEmpty())
        writeBytes(QDir(ro).filePath(keep), keepBytes);
    return mount->makeReadOnly();
}

const QString fullDevice = QStringLiteral("/dev/full");

} // namespace

class TestCliPromises : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void reportCheckedBeforeForcing_data();
    void reportCheckedBeforeForcing();
    void reportOnFailingDeviceNotLost();
    void checkoutSaysNoRuntimeDirWarning();
    void diffLostOutputIsNotDifferences();
    void monitorLogPlaceExit1_data();
    void monitorLogPlaceExit1();
    void monitorLogDropsCutRow();
    void monitorLogOnFullDiskWholeRows();
    void snapshotToDevice();
    void snapshotReadOnlyMediumSaysWhy();
    void writeSplitsLikeRead();

private:
    QTemporaryDir m_dir;
};

void TestCliPromises::reportCheckedBeforeForcing_data()
{
    QTest::addColumn<QString>("report");
    QTest::addColumn<QString>("reason");
    QTest::addColumn<bool>("readOnlyMount");
    QTest::newRow("missing folder")
        << QStringLiteral("nodir/r.pdf") << QStringLiteral("No such file or directory") << false;
    QTest::newRow("under a regular file")
        << QStringLiteral("plain.txt/r.csv") << QStringLiteral("Not a directory") << false;
    QTest::newRow("read-only medium")
        << QStringLiteral("ro/r.csv") << QStringLiteral("Read-only file system") << true;
}

// Item 2: a report that cannot be written is refused before anything is forced (exit 1), not
// after the whole checkout.
void TestCliPromises::reportCheckedBeforeForcing()
{
    QFETCH(QString, report);
    QFETCH(QString, reason);
    QFETCH(bool, readOnlyMount);
    QTemporaryDir dir;
    TestUtil::TmpfsMount mount;
    if (const QString problem = preparePlace(dir, readOnlyMount, &mount); !problem.isEmpty())
        QSKIP(qPrintable(problem));
    const QString path = dir.filePath(report);
    const Run r = cli(sim({QStringLiteral("--yes"), QStringLiteral("checkout"),
                           QStringLiteral("Y0..Y1"), QStringLiteral("--report"), path}),
                      "y\ny\n");
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(reason) && r.err.contains(QLatin1String("Nothing was forced")),
             qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String("is ON now")), qPrintable(r.err));
}

// Items 2 and 8: --report onto a device (a link named *.csv, and /dev/full itself) is accepted;
// when the device fails at the end the report comes on standard output, not lost.
void TestCliPromises::reportOnFailingDeviceNotLost()
{
    if (!QFileInfo(fullDevice).exists())
        QSKIP("no /dev/full here");
    const QString link = m_dir.filePath(QStringLiteral("report-link.csv"));
    QVERIFY(QFile::link(fullDevice, link));
    for (const QString &report : {link, fullDevice}) {
        const Run r = cli(sim({QStringLiteral("--yes"), QStringLiteral("checkout"),
                               QStringLiteral("Y0..Y1"), QStringLiteral("--report"), report}),
                          "y\nn\n");
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QLatin1String("No space left on device")), qPrintable(r.err));
        QVERIFY2(r.out.contains(QLatin1String("Y0,")) && r.out.contains(QLatin1String("Passed"))
                     && r.out.contains(QLatin1String("Y1,"))
                     && r.out.contains(QLatin1String("Failed")),
                 qPrintable(r.out + r.err));
    }
}

// Item 4: a checkout in an environment without XDG_RUNTIME_DIR (cron, a service) prints only
// fatek-cli's own lines and the questions.
void TestCliPromises::checkoutSaysNoRuntimeDirWarning()
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("XDG_RUNTIME_DIR"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(FATEK_CLI_PATH),
            sim({QStringLiteral("--yes"), QStringLiteral("checkout"), QStringLiteral("Y0")}));
    QVERIFY(p.waitForStarted(10000));
    p.write("y\n");
    p.closeWriteChannel();
    QVERIFY(p.waitForFinished(60000));
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QCOMPARE(p.exitCode(), 0);
    QVERIFY2(!err.contains(QLatin1String("XDG_RUNTIME_DIR")), qPrintable(err));
    QVERIFY2(!err.contains(QLatin1String("QStandardPaths")), qPrintable(err));
}

// Item 5: diff's differences that no reader got are not "differences found" (6): a closed pipe
// is 141, a full device 1, as the exit code table says.
void TestCliPromises::diffLostOutputIsNotDifferences()
{
    const QString a = m_dir.filePath(QStringLiteral("a.json"));
    const QString b = m_dir.filePath(QStringLiteral("b.json"));
    QCOMPARE(cli(sim({QStringLiteral("snapshot"), a, QStringLiteral("R100..R101")})).code, 0);
    QJsonObject o = QJsonDocument::fromJson(bytesOf(a)).object();
    QJsonArray values = o.value(QStringLiteral("values")).toArray();
    QJsonObject first = values.at(0).toObject();
    first.insert(QStringLiteral("value"), first.value(QStringLiteral("value")).toInt() + 7);
    values.replace(0, first);
    o.insert(QStringLiteral("values"), values);
    QVERIFY(writeBytes(b, QJsonDocument(o).toJson()));
    const QStringList diff{QStringLiteral("diff"), a, b};
    QCOMPARE(cli(diff).code, 6); // the differences, read
#ifdef Q_OS_UNIX
    const Run closed = cli(diff, {}, {}, true);
    QCOMPARE(closed.code, 141);
#endif
    if (QFileInfo(fullDevice).exists()) {
        const Run full = cli(diff, {}, fullDevice);
        QCOMPARE(full.code, 1);
        QVERIFY2(full.err.contains(QLatin1String("Cannot write the output: No space left")),
                 qPrintable(full.err));
    }
}

void TestCliPromises::monitorLogPlaceExit1_data()
{
    QTest::addColumn<QString>("log");
    QTest::addColumn<bool>("readOnlyMount");
    QTest::newRow("missing folder") << QStringLiteral("nodir/log.csv") << false;
    QTest::newRow("under a regular file") << QStringLiteral("plain.txt/log.csv") << false;
    QTest::newRow("/proc") << QStringLiteral("/proc/fatek-log.csv") << false;
    QTest::newRow("read-only medium") << QStringLiteral("ro/log.csv") << true;
}

// Item 6: monitor --output to a place that takes no file is exit 1 (a file not written), as for
// backup and snapshot; not a usage error.
void TestCliPromises::monitorLogPlaceExit1()
{
    QFETCH(QString, log);
    QFETCH(bool, readOnlyMount);
    QTemporaryDir dir;
    TestUtil::TmpfsMount mount;
    if (const QString problem = preparePlace(dir, readOnlyMount, &mount); !problem.isEmpty())
        QSKIP(qPrintable(problem));
    const QString path = log.startsWith(QLatin1Char('/')) ? log : dir.filePath(log);
    const Run r
        = cli(sim({QStringLiteral("monitor"), QStringLiteral("R0"), QStringLiteral("--cycles"),
                   QStringLiteral("2"), QStringLiteral("--interval"), QStringLiteral("100"),
                   QStringLiteral("--output"), path}));
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(path), qPrintable(r.err));
    QVERIFY(!QFileInfo(path).isFile());
}

// Item 7: a log whose last row was cut (an earlier run on a full disk) is not appended after
// half a row: the cut row goes, every row of the file is whole.
void TestCliPromises::monitorLogDropsCutRow()
{
    const QString path = m_dir.filePath(QStringLiteral("cut.csv"));
    const QByteArray header = "timestamp,R0,status\n";
    const QByteArray whole = "2026-12-02T00:52:00.000+00:00,5,ok\n";
    QVERIFY(writeBytes(path, header + whole + "2026-12-02T00:52:01."));
    const Run r
        = cli(sim({QStringLiteral("monitor"), QStringLiteral("R0"), QStringLiteral("--cycles"),
                   QStringLiteral("2"), QStringLiteral("--interval"), QStringLiteral("100"),
                   QStringLiteral("--output"), path}));
    QCOMPARE(r.code, 0);
    const QByteArray bytes = bytesOf(path);
    QVERIFY2(bytes.startsWith(header + whole), bytes.constData());
    QVERIFY2(!bytes.contains("00:52:01."), bytes.constData());
    QVERIFY(bytes.endsWith('\n'));
    const QList<QByteArray> rows = bytes.trimmed().split('\n');
    QCOMPARE(rows.size(), 4); // the header, the old row, two new ones
    for (const QByteArray &row : rows)
        QCOMPARE(row.count(','), 2);
}

// Item 7: on a disk that fills up, every row in the file is whole (the part of a row that fitted
// is taken back), and a new log that does not get its header is not left behind empty.
void TestCliPromises::monitorLogOnFullDiskWholeRows()
{
    QTemporaryDir dir;
    const QString disk = dir.filePath(QStringLiteral("small"));
    TestUtil::TmpfsMount mount;
    if (const QString problem = mount.mount(disk, 64); !problem.isEmpty())
        QSKIP(qPrintable(problem));
    // 15 of its 16 pages taken: the header and a few rows of 100 elements fit in the last.
    QVERIFY(writeBytes(QDir(disk).filePath(QStringLiteral("fill")), QByteArray(61440, 'x')));
    const QString path = QDir(disk).filePath(QStringLiteral("log.csv"));
    const Run r
        = cli(sim({QStringLiteral("monitor"), QStringLiteral("R0..R99:hex"),
                   QStringLiteral("--interval"), QStringLiteral("100"), QStringLiteral("--cycles"),
                   QStringLiteral("20"), QStringLiteral("--output"), path}));
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QLatin1String("No space left on device")), qPrintable(r.err));
    const QByteArray bytes = bytesOf(path);
    QVERIFY(bytes.startsWith("\xEF\xBB\xBFtimestamp,R0,R1,"));
    QVERIFY2(bytes.endsWith('\n'), bytes.right(80).constData());
    const QList<QByteArray> rows = bytes.trimmed().split('\n');
    QVERIFY(rows.size() >= 2);
    for (const QByteArray &row : rows)
        QCOMPARE(row.count(','), rows.first().count(','));

    // Now the disk is full: a new log gets nothing, and no empty file stays.
    // What is left after the last whole row: filled (the write is short, the disk full).
    writeBytes(QDir(disk).filePath(QStringLiteral("rest")), QByteArray(8192, 'x'));
    const QString fresh = QDir(disk).filePath(QStringLiteral("new.csv"));
    const Run second = cli(
        sim({QStringLiteral("monitor"), QStringLiteral("R0..R99:hex"), QStringLiteral("--cycles"),
             QStringLiteral("1"), QStringLiteral("--output"), fresh}));
    QCOMPARE(second.code, 1);
    QVERIFY2(second.err.contains(QLatin1String("No space left on device")), qPrintable(second.err));
    QVERIFY(!QFileInfo::exists(fresh));
}

// Item 8: snapshot onto a device, named without a .json (/dev/full itself), is written as the
// device it is (exit 1 and the system's reason, not a refusal of its name).
void TestCliPromises::snapshotToDevice()
{
    if (!QFileInfo(fullDevice).exists())
        QSKIP("no /dev/full here");
    const Run r = cli(sim({QStringLiteral("snapshot"), fullDevice, QStringLiteral("R0..R9")}));
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QLatin1String("No space left on device")), qPrintable(r.err));
}

// Item 8: an existing snapshot on a read-only medium: the system's reason, not Qt's "Existing
// file ... is not writable"; the file as it was.
void TestCliPromises::snapshotReadOnlyMediumSaysWhy()
{
    QTemporaryDir dir;
    const QString disk = dir.filePath(QStringLiteral("ro"));
    TestUtil::TmpfsMount mount;
    if (const QString problem
        = preparePlace(dir, true, &mount, QStringLiteral("s.json"), "yesterday\n");
        !problem.isEmpty())
        QSKIP(qPrintable(problem));
    const QString path = QDir(disk).filePath(QStringLiteral("s.json"));
    const Run r = cli(sim({QStringLiteral("snapshot"), path, QStringLiteral("R0..R9")}));
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QLatin1String("Read-only file system")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String("is not writable")), qPrintable(r.err));
    QCOMPARE(bytesOf(path), QByteArray("yesterday\n"));
}

// Item 9: write takes as many values as read reads (up to 1,024), in as many requests as it takes,
// each part said; a typed value (float) is never cut between two requests.
void TestCliPromises::writeSplitsLikeRead()
{
    QStringList values;
    for (int i = 1; i <= 65; ++i)
        values << QString::number(i);
    const Run r = cli(
        sim(QStringList{QStringLiteral("--json"), QStringLiteral("write"), QStringLiteral("R500")}
            + values
            + QStringList{QStringLiteral("--then"), QStringLiteral("read"),
                          QStringLiteral("R500..R564")}));
    QCOMPARE(r.code, 0);
    QVERIFY2(r.err.contains(QLatin1String("R500..R563 written.")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("R564 written.")), qPrintable(r.err));
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2);
    const QJsonArray read = QJsonDocument::fromJson(lines.at(1).toUtf8())
                                .object()
                                .value(QStringLiteral("values"))
                                .toArray();
    QCOMPARE(read.size(), 65);
    for (int i = 0; i < 65; ++i)
        QCOMPARE(read.at(i).toInt(), i + 1);

    // 33 floats = 66 registers: 32 floats (64 registers) and one, never half a float.
    QStringList floats;
    for (int i = 0; i < 33; ++i)
        floats << QStringLiteral("%1.5").arg(i);
    const Run f
        = cli(sim(QStringList{QStringLiteral("write"), QStringLiteral("R600:float")} + floats));
    QCOMPARE(f.code, 0);
    QVERIFY2(f.err.contains(QLatin1String("R600..R663 written."))
                 && f.err.contains(QLatin1String("R664..R665 written.")),
             qPrintable(f.err));

    // More than 1,024: refused before anything is sent.
    QStringList many;
    for (int i = 0; i < 1025; ++i)
        many << QStringLiteral("1");
    const Run tooMany = cli(sim(QStringList{QStringLiteral("write"), QStringLiteral("R0")} + many));
    QCOMPARE(tooMany.code, 2);
    QVERIFY2(tooMany.err.contains(QLatin1String("at most 1024")), qPrintable(tooMany.err));
}

QTEST_GUILESS_MAIN(TestCliPromises)
#include "tst_cli_promises.moc"
