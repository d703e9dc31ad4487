// Nothing half-written may pass as saved (issue 31, part 4): every writer of core (SafeFile, and
// through it program backups, snapshots in JSON and CSV, watch lists; the data log on its own) on
// a device that refuses every byte (/dev/full, always) and on a disk that fills up half way (a
// 64 KiB tmpfs, when the test may mount one). A failure names the system's reason, leaves the old
// file as it was and no temporary file behind; a device is written, never replaced.
#include "core/commission/memorysnapshot.h"
#include "core/commission/programimage.h"
#include "core/commission/snapshotfile.h"
#include "core/qtbridge/qtmessage.h"
#include "core/sim/modelprofile.h"
#include "core/watch/datalogger.h"
#include "core/watch/safefile.h"
#include "core/watch/watchlist.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace Fatek;

namespace {

const QString fullDevice = QStringLiteral("/dev/full");
const QString noSpace = QStringLiteral("No space left on device");

bool isCharacterDevice(const QString &path)
{
    struct stat st = {};
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 && S_ISCHR(st.st_mode);
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
}

bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size()
           && f.flush();
}

// What /dev holds next to /dev/full: a temporary file left there (or renamed over it) would show.
QStringList besideFullDevice()
{
    return QDir(QStringLiteral("/dev")).entryList({QStringLiteral("full*")}, QDir::System);
}

ProgramImage bigProgram()
{
    const auto image = ProgramImage::fromWords(ModelProfile::fbs().powerOnProgram());
    Q_ASSERT(image);
    return *image;
}

MemorySnapshot bigSnapshot()
{
    MemorySnapshot s;
    for (int i = 0; i < 4000; ++i)
        s.values.push_back(
            {Address::parse("R" + std::to_string(i)).value(), static_cast<std::uint32_t>(i * 7)});
    s.normalize();
    return s;
}

WatchListFile bigWatchList()
{
    WatchTableSpec table;
    table.name = QStringLiteral("Big");
    for (int i = 0; i < 1000; ++i) {
        WatchItemSpec item;
        item.address = Address::parse("R" + std::to_string(i)).value();
        item.name = QStringLiteral("Tank level sensor %1").arg(i);
        table.items.append(item);
    }
    WatchListFile file;
    file.tables.append(table);
    return file;
}

// Every writer of core, by name: the reason it gave, empty when it wrote the file.
QString saveWith(const QString &writer, const QString &path)
{
    if (writer == QLatin1String("SafeFile"))
        return SafeFile::write(path, QByteArray(60000, 'x'));
    if (writer == QLatin1String("program backup")) {
        const auto e = bigProgram().save(path);
        return e ? QString::fromStdString(e->text()) : QString();
    }
    if (writer == QLatin1String("snapshot")) {
        const auto e = SnapshotFile::saveToFile(bigSnapshot(), path);
        return e ? englishText(e->message) : QString();
    }
    if (writer == QLatin1String("watch list")) {
        const Status s = WatchList::saveToFile(bigWatchList(), path);
        return s ? QString() : QString::fromStdString(s.error().text());
    }
    return QStringLiteral("unknown writer %1").arg(writer);
}

} // namespace

class TestSafeFile : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    void writers()
    {
        QTest::addColumn<QString>("writer");
        QTest::addColumn<QString>("name");
        QTest::newRow("SafeFile") << QStringLiteral("SafeFile") << QStringLiteral("f.bin");
        QTest::newRow("program backup")
            << QStringLiteral("program backup") << QStringLiteral("b.fprog");
        QTest::newRow("snapshot json") << QStringLiteral("snapshot") << QStringLiteral("s.json");
        QTest::newRow("snapshot csv") << QStringLiteral("snapshot") << QStringLiteral("s.csv");
        QTest::newRow("watch list") << QStringLiteral("watch list") << QStringLiteral("w.json");
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // The writers work at all (what the failures below are measured against): a new file is
    // written, an old one replaced, no temporary file stays.
    void writesAndReplaces_data() { writers(); }
    void writesAndReplaces()
    {
        QFETCH(QString, writer);
        QFETCH(QString, name);
        QTemporaryDir dir(m_dir.filePath(QStringLiteral("ok-XXXXXX")));
        const QString path = dir.filePath(name);
        QVERIFY(writeAll(path, "old"));
        const QString reason = saveWith(writer, path);
        QVERIFY2(reason.isEmpty(), qPrintable(reason));
        QVERIFY(QFileInfo(path).size() > 20000);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{name});
    }

    // /dev/full takes no byte: each writer says why, and /dev/full stays the device it was (a
    // temporary file renamed over it would replace the device node, as root). Reached directly
    // and through a link named as the writer wants (a snapshot's name says its format).
    void fullDeviceIsWrittenNotReplaced_data() { writers(); }
    void fullDeviceIsWrittenNotReplaced()
    {
        QFETCH(QString, writer);
        QFETCH(QString, name);
        if (!isCharacterDevice(fullDevice))
            QSKIP("/dev/full is not a character device here");
        QTest::failOnWarning(QRegularExpression(QStringLiteral(".*")));
        const QStringList before = besideFullDevice();
        if (writer != QLatin1String("snapshot")) {
            const QString direct = saveWith(writer, fullDevice);
            QVERIFY2(direct.contains(noSpace), qPrintable(direct));
            QVERIFY(isCharacterDevice(fullDevice));
        }
        QTemporaryDir dir(m_dir.filePath(QStringLiteral("link-XXXXXX")));
        const QString link = dir.filePath(name);
        QVERIFY(QFile::link(fullDevice, link));
        const QString reason = saveWith(writer, link);
        QVERIFY2(reason.contains(noSpace), qPrintable(reason));
        QVERIFY(isCharacterDevice(fullDevice));
        QCOMPARE(besideFullDevice(), before);
        // The link is still the link (not replaced by a file either).
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::System), QStringList{name});
    }

    void dataLogOnFullDevice()
    {
        if (!isCharacterDevice(fullDevice))
            QSKIP("/dev/full is not a character device here");
        QTest::failOnWarning(QRegularExpression(QStringLiteral(".*")));
        WatchItemSpec item;
        item.address = Address::parse("R0").value();
        DataLogger log;
        const Status s = log.open(fullDevice, {item});
        QVERIFY(!s);
        const QString text = QString::fromStdString(s.error().text());
        QVERIFY2(text.contains(noSpace) && text.contains(fullDevice), qPrintable(text));
        QVERIFY(log.writeFailed());
        QVERIFY(isCharacterDevice(fullDevice));
    }

    // A disk that fills up half way (the report: 24 KB of 55 KB written, then "saved"): each
    // writer fails with the system's reason, the old file is as it was, no temporary file stays;
    // the data log says so at the row that did not fit and at every later one.
    void fullDisk_data() { writers(); }
    void fullDisk()
    {
        QFETCH(QString, writer);
        QFETCH(QString, name);
        const QString mountPoint = m_dir.filePath(QStringLiteral("small-") + name);
        QVERIFY(QDir().mkpath(mountPoint));
        QProcess mount;
        mount.start(QStringLiteral("mount"),
                    {QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                     QStringLiteral("size=64k"), QStringLiteral("tmpfs"), mountPoint});
        if (!mount.waitForFinished(10000) || mount.exitStatus() != QProcess::NormalExit
            || mount.exitCode() != 0)
            QSKIP(qPrintable(
                QStringLiteral("Cannot mount a 64 KiB tmpfs (needs root and the right "
                               "to mount in this container): %1")
                    .arg(QString::fromLocal8Bit(mount.readAllStandardError()).trimmed())));
        const auto unmount = qScopeGuard(
            [&mountPoint] { QProcess::execute(QStringLiteral("umount"), {mountPoint}); });
        const QDir dir(mountPoint);
        QVERIFY(writeAll(dir.filePath(QStringLiteral("filler")), QByteArray(40000, '\0')));
        const QString path = dir.filePath(name);
        const QByteArray old = "the old file, which a failed save must not touch\n";
        QVERIFY(writeAll(path, old));
        const QStringList files = dir.entryList(QDir::Files);

        const QString reason = saveWith(writer, path);
        QVERIFY2(reason.contains(noSpace), qPrintable(reason));
        QCOMPARE(readAll(path), old);
        QCOMPARE(dir.entryList(QDir::Files), files);
        // What fits is still written: the failure was the disk, not the writer.
        QVERIFY(SafeFile::write(path, "new").isEmpty());
        QCOMPARE(readAll(path), QByteArray("new"));
    }

    void dataLogOnFullDisk()
    {
        const QString mountPoint = m_dir.filePath(QStringLiteral("small-log"));
        QVERIFY(QDir().mkpath(mountPoint));
        if (QProcess::execute(QStringLiteral("mount"),
                              {QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                               QStringLiteral("size=64k"), QStringLiteral("tmpfs"), mountPoint})
            != 0)
            QSKIP("Cannot mount a 64 KiB tmpfs (needs root and the right to mount in this "
                  "container)");
        const auto unmount = qScopeGuard(
            [&mountPoint] { QProcess::execute(QStringLiteral("umount"), {mountPoint}); });
        QVERIFY(
            writeAll(QDir(mountPoint).filePath(QStringLiteral("filler")), QByteArray(40000, '\0')));
        WatchItemSpec item;
        item.address = Address::parse("R0").value();
        DataLogger log;
        log.setFlushIntervalMs(0);
        const QString path = QDir(mountPoint).filePath(QStringLiteral("log.csv"));
        QVERIFY(log.open(path, {item}));
        const QDateTime time = QDateTime::currentDateTime();
        int written = 0;
        Status s = Ok{};
        while (written < 10000
               && (s = log.writeRow(time, {{12345, DataLogger::Quality::Good, {}}})))
            ++written;
        QVERIFY2(!s, "10000 rows fitted on a 64 KiB disk");
        QVERIFY(written > 100); // rows went in until the disk was full
        const QString text = QString::fromStdString(s.error().text());
        QVERIFY2(text.contains(noSpace) && text.contains(QStringLiteral("Logging stopped")),
                 qPrintable(text));
        // Said again, not silently dropped, by every later row and by close().
        const Status later = log.writeRow(time, {{1, DataLogger::Quality::Good, {}}});
        QVERIFY(!later);
        QCOMPARE(QString::fromStdString(later.error().text()), text);
        QVERIFY(!log.close());
        // The rows written before the disk was full are kept.
        const QList<QByteArray> lines = readAll(path).split('\n');
        QVERIFY(lines.size() > 100);
        QCOMPARE(lines.first(), QByteArray("\xEF\xBB\xBFtimestamp,R0,status"));
    }
};

QTEST_GUILESS_MAIN(TestSafeFile)
#include "tst_safefile.moc"
