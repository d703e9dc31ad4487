// Safe files: watch lists and settings are validated on load; a corrupt file gives an error naming
// it and is never overwritten silently (not by a failed save, not by reopening it at start, not by
// closing the window).
#include "core/watch/watchlist.h"
#include "testutil.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/watch/watchtablewidget.h"
#include "uitestutil.h"

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

const QByteArray goodList = R"({"format":"fatek-studio-watchlist","version":1,"tables":[
    {"name":"Main","items":[{"address":"R100"},{"address":"Y0"}]}]})";

} // namespace

class TestSafeFiles : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        TestUtil::useTestSettings(m_dir.path(), QStringLiteral("tst_safefiles"));
    }
    void init() { QSettings().clear(); }

    void corruptWatchListsAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");
        QTest::newRow("truncated") << goodList.left(60) << QStringLiteral("list.json");
        QTest::newRow("binary") << QByteArray("\x00\xff\x13garbage", 10)
                                << QStringLiteral("list.json");
        QTest::newRow("other format")
            << QByteArray(R"({"format":"something","version":1,"tables":[]})")
            << QStringLiteral("list.json");
        QTest::newRow("future version")
            << QByteArray(R"({"format":"fatek-studio-watchlist","version":99,"tables":[]})")
            << QStringLiteral("version");
        QTest::newRow("bad address")
            << QByteArray(R"({"format":"fatek-studio-watchlist","version":1,"tables":[
                 {"name":"T","items":[{"address":"R99999999"}]}]})")
            << QStringLiteral("item 1");
        QTest::newRow("bad interval")
            << QByteArray(R"({"format":"fatek-studio-watchlist","version":1,"tables":[
                 {"name":"T","intervalMs":-5,"items":[]}]})")
            << QStringLiteral("table 1");
    }
    void corruptWatchListsAreRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(QStringLiteral("list.json"));
        QVERIFY(writeAll(path, bytes));
        const auto loaded = WatchList::loadFromFile(path);
        QVERIFY(!loaded.ok());
        const QString message = QString::fromStdString(loaded.error().text());
        QVERIFY2(message.contains(expected), qPrintable(message));
        QCOMPARE(readAll(path), bytes);
    }

    // A list that does not validate is not written; the file on disk stays as it was.
    void failedSaveKeepsTheFile()
    {
        const QString path = m_dir.filePath(QStringLiteral("keep.json"));
        QVERIFY(writeAll(path, goodList));
        WatchListFile bad;
        WatchTableSpec table;
        table.name = QStringLiteral("T");
        table.intervalMs = 0; // below the minimum
        bad.tables.append(table);
        QVERIFY(!WatchList::saveToFile(bad, path).ok());
        QCOMPARE(readAll(path), goodList);
    }

    // The window reopens the last list at start: a corrupt one gives an error, keeps the tables,
    // and is not touched by loading, by saving elsewhere, or by closing the window.
    void corruptLastListIsNotOverwritten()
    {
        const QString path = m_dir.filePath(QStringLiteral("last.json"));
        const QByteArray corrupt = goodList.left(50);
        QVERIFY(writeAll(path, corrupt));
        QSettings().setValue(QStringLiteral("preferences/lastWatchList"), path);
        {
            MainWindow window;
            window.show();
            QVERIFY(!window.restoreLastWatchList());
            QCOMPARE(window.watchTables().size(), 1);
            // Loading it by hand fails the same way and leaves the current tables alone.
            window.currentWatchTable()->setSpec(WatchList::load(goodList).value().tables.first());
            const WatchTableSpec before = window.currentWatchTable()->spec();
            QVERIFY(!window.loadWatchList(path).ok());
            QCOMPARE(window.watchTables().size(), 1);
            QCOMPARE(window.currentWatchTable()->spec(), before);
            // The tables were changed by hand: quitting asks, and not saving leaves the file alone.
            const QString question = UiTestUtil::answerModal([&] { window.close(); },
                                                             UiTestUtil::clickButton("quitButton"));
            QVERIFY2(question.contains(QStringLiteral("not saved")), qPrintable(question));
            QTRY_VERIFY(!window.isVisible());
        }
        QCOMPARE(readAll(path), corrupt);
    }

    // Saved connections are checked when used: damaged values fall back to defaults or fail
    // LinkSettings::validate() with a technician's message, never crash.
    void corruptSavedConnections()
    {
        QVariantMap damaged;
        damaged[QStringLiteral("name")] = QStringLiteral("Damaged");
        damaged[QStringLiteral("kind")] = 9;
        damaged[QStringLiteral("port")] = QStringLiteral("not a port");
        damaged[QStringLiteral("station")] = 999;
        damaged[QStringLiteral("timeoutMs")] = -3;
        QSettings().setValue(QStringLiteral("connections/recent"),
                             QVariantList{damaged, QStringLiteral("garbage"), 17});
        ConnectionManager manager;
        const QList<SavedConnection> recent = manager.recent();
        QCOMPARE(recent.size(), 1); // entries that are not a connection at all are skipped
        const SavedConnection &c = recent.first();
        QCOMPARE(c.station, quint8(1));
        QCOMPARE(c.settings.kind, LinkSettings::Kind::Tcp);
        QCOMPARE(c.settings.port, quint16(500));
        const QString problem = englishText(c.settings.validate());
        QVERIFY2(problem.contains(QStringLiteral("Timeout")), qPrintable(problem));
        QCOMPARE(manager.unreadableRecent(), 2);

        // Saving a new connection keeps the unreadable entries as they were.
        SavedConnection added;
        added.name = QStringLiteral("New");
        added.settings = LinkSettings::tcp(QStringLiteral("10.0.0.5"));
        manager.addRecent(added);
        const QVariantList stored
            = QSettings().value(QStringLiteral("connections/recent")).toList();
        QCOMPARE(stored.size(), 4);
        QCOMPARE(stored.at(0).toMap().value(QStringLiteral("name")).toString(),
                 QStringLiteral("New"));
        QCOMPARE(stored.at(1).toMap().value(QStringLiteral("name")).toString(),
                 QStringLiteral("Damaged"));
        QCOMPARE(stored.at(2), QVariant(QStringLiteral("garbage")));
        QCOMPARE(stored.at(3), QVariant(17));
        QCOMPARE(manager.recent().size(), 2);
        QCOMPARE(manager.unreadableRecent(), 2);

        // The menu says so instead of hiding them.
        MainWindow window;
        QMenu *menu = window.findChild<QMenu *>(QStringLiteral("recentMenu"));
        QVERIFY(menu);
        QStringList texts;
        for (QAction *action : menu->actions()) {
            if (action->text().contains(QStringLiteral("could not be read"))) {
                QVERIFY(!action->isEnabled());
                texts << action->text();
            }
        }
        QCOMPARE(texts.size(), 1);
        QVERIFY2(texts.first().startsWith(QStringLiteral("2 saved connection")),
                 qPrintable(texts.first()));
    }

    // The studio's watch list save on a device that takes nothing (/dev/full): the system's
    // reason, the last list is not set to it, the device is not replaced; then a save that works
    // still works and one on a device leaves the saved file as it was.
    void watchListSaveOnFullDevice()
    {
        const QString full = QStringLiteral("/dev/full");
        if (!QFileInfo(full).exists() || QFileInfo(full).isFile())
            QSKIP("no /dev/full device here");
        MainWindow window;
        window.currentWatchTable()->setSpec(WatchList::load(goodList).value().tables.first());
        const QString path = m_dir.filePath(QStringLiteral("saved.json"));
        QVERIFY(window.saveWatchList(path).ok());
        const QByteArray saved = readAll(path);
        QVERIFY(!saved.isEmpty());
        const Status s = window.saveWatchList(full);
        QVERIFY(!s.ok());
        const QString message = QString::fromStdString(s.error().text());
        QVERIFY2(message.contains(QStringLiteral("No space left on device")), qPrintable(message));
        QCOMPARE(QSettings().value(QStringLiteral("preferences/lastWatchList")).toString(),
                 QFileInfo(path).absoluteFilePath());
        QVERIFY(!QFileInfo(full).isFile());
        QCOMPARE(readAll(path), saved);
    }
};

QTEST_MAIN(TestSafeFiles)
#include "tst_safefiles.moc"
