// Names from the ladder project (issue 18): a comment/symbol list imported through the real
// File > Import Names and Comments… action and its file dialog fills the Name and Comment
// columns of the rows there are and of a row typed afterwards, keeps a name typed by hand, and
// shows in the trend, the data log's header and the forcing tool; it is saved with the watch list.
#include "testutil.h"
#include "ui/common/symbolnames.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/discretetablemodel.h"
#include "ui/tools/forcingpanel.h"
#include "ui/trend/trendview.h"
#include "ui/watch/watchtablemodel.h"
#include "uitestutil.h"

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;
using UiTestUtil::answerModal;

namespace {

constexpr int keyDelayMs = 20;

Address addr(const char *text)
{
    return *Address::parse(text);
}

QString u(const char *utf8)
{
    return QString::fromUtf8(utf8);
}

int rowOf(const WatchTableModel *model, const char *address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->item(r).address == addr(address))
            return r;
    }
    return -1;
}

QString cell(const WatchTableModel *model, const char *address, int column)
{
    return model->index(rowOf(model, address), column).data().toString();
}

void typeAddresses(WatchTableWidget *table, const QString &text)
{
    QLineEdit *edit = table->addressEdit();
    edit->setFocus();
    QTest::keyClicks(edit, text, Qt::NoModifier, keyDelayMs);
    QTest::keyClick(edit, Qt::Key_Return);
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// File > Import Names and Comments…, choosing `path` in its file dialog as a person would.
void importThroughMenu(MainWindow &window, const QString &path)
{
    auto *action = window.findChild<QAction *>(QStringLiteral("importNamesAction"));
    QVERIFY(action);
    QVERIFY(action->isEnabled());
    bool chosen = false;
    answerModal([action] { action->trigger(); },
                [&](QWidget *modal) {
                    auto *dialog = qobject_cast<QFileDialog *>(modal);
                    auto *name
                        = dialog ? dialog->findChild<QLineEdit *>(QStringLiteral("fileNameEdit"))
                                 : nullptr;
                    if (!name)
                        return;
                    // Types the file's path into the name field and presses Enter.
                    name->setFocus();
                    QTest::keyClicks(name, path);
                    QTest::keyClick(name, Qt::Key_Return);
                    chosen = true;
                });
    QVERIFY(chosen);
    QTRY_VERIFY(!QApplication::activeModalWidget());
}

} // namespace

class TestUiNames : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        TestUtil::useTestSettings(m_dir.path(), QStringLiteral("tst_ui_names"));
        // The file dialog is Qt's own on every platform, so the test can choose in it.
        QApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    }

    void importFillsRowsTrendLogAndForcing()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        WatchTableWidget *table = window.currentWatchTable();
        QVERIFY(table);
        WatchTableModel *model = table->model();
        typeAddresses(table, QStringLiteral("R12 R13 Y0"));
        QTRY_COMPARE(model->rowCount(), 3);

        // A name typed by hand before the import.
        QTableView *view = table->view();
        const QModelIndex r13Name
            = table->viewIndex(model->index(rowOf(model, "R13"), WatchTableModel::NameColumn));
        view->setCurrentIndex(r13Name);
        view->edit(r13Name);
        QTRY_VERIFY(view->viewport()->isAncestorOf(QApplication::focusWidget()));
        QWidget *editor = QApplication::focusWidget();
        QTest::keyClicks(editor, QStringLiteral("My pressure"), Qt::NoModifier, keyDelayMs);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(cell(model, "R13", WatchTableModel::NameColumn), u("My pressure"));

        // The trend and the data log, started before the import, and a chart of R12.
        QString error;
        QVERIFY2(window.trendView()->addItem(model, rowOf(model, "R12"), &error),
                 qPrintable(error));
        QCOMPARE(window.trendView()->itemName(0), u("R12"));

        // WinProladder's list, as a spreadsheet saves it: BOM, header, CRLF, a bad line.
        const QString names = m_dir.filePath(QStringLiteral("names.csv"));
        QVERIFY(writeFile(names, "\xEF\xBB\xBF"
                                 "Address,Name,Comment\r\n"
                                 "R00012,Tank level,\"cm, from the float\"\r\n"
                                 "R13,Pressure,bar\r\n"
                                 "R14,\xE6\xB6\xB2\xE4\xBD\x8D,second tank\r\n"
                                 "R99999,Nowhere,\r\n"
                                 "Y0,Pump,\r\n"));
        importThroughMenu(window, names);

        // Empty names and comments are filled; the name typed by hand stays (its comment was
        // empty, so it takes the imported one).
        QCOMPARE(cell(model, "R12", WatchTableModel::NameColumn), u("Tank level"));
        QCOMPARE(cell(model, "R12", WatchTableModel::CommentColumn), u("cm, from the float"));
        QCOMPARE(cell(model, "R13", WatchTableModel::NameColumn), u("My pressure"));
        QCOMPARE(cell(model, "R13", WatchTableModel::CommentColumn), u("bar"));
        QCOMPARE(cell(model, "Y0", WatchTableModel::NameColumn), u("Pump"));
        // The outcome, with the skipped line and why.
        const QString status = window.statusBar()->currentMessage();
        QVERIFY2(status.contains(u("Names imported: 4, lines skipped: 1 (line 5: ")),
                 qPrintable(status));
        QVERIFY2(status.contains(u("R99999")), qPrintable(status));

        // A row typed afterwards gets its name too.
        typeAddresses(table, QStringLiteral("R14"));
        QTRY_COMPARE(model->rowCount(), 4);
        QCOMPARE(cell(model, "R14", WatchTableModel::NameColumn), u("液位"));
        QCOMPARE(cell(model, "R14", WatchTableModel::CommentColumn), u("second tank"));

        // The trend follows the new name.
        QCOMPARE(window.trendView()->itemName(0), u("Tank level (R12)"));

        // The data log's header names the columns with the rows' names.
        const QString log = m_dir.filePath(QStringLiteral("log.csv"));
        QVERIFY(window.startLogging(log).ok());
        window.stopLogging();
        QFile logFile(log);
        QVERIFY(logFile.open(QIODevice::ReadOnly));
        const QByteArray header = logFile.readLine();
        QVERIFY(header.startsWith("\xEF\xBB\xBF")); // UTF-8 for Excel on Windows
        QCOMPARE(QString::fromUtf8(header.mid(3)).trimmed(),
                 u("timestamp,Tank level (R12),My pressure (R13),Pump (Y0),液位 (R14),status"));

        // The forcing tool shows the name next to the discrete.
        auto *forcing = qobject_cast<ForcingPanel *>(window.openTool(QStringLiteral("forcing")));
        QVERIFY(forcing);
        forcing->showRange(ElementType::Y, 0, 4);
        DiscreteTableModel *discretes = forcing->model();
        QCOMPARE(discretes->index(0, DiscreteTableModel::NameColumn).data().toString(), u("Pump"));
        QCOMPARE(discretes->index(1, DiscreteTableModel::NameColumn).data().toString(), QString());

        // A second list renames R12 and names Y1: rows holding the old imported name follow.
        const QString update = m_dir.filePath(QStringLiteral("update.txt"));
        QVERIFY(writeFile(update, "R12\tLevel tank 1\tcm\nY1\tHorn\t\n"));
        importThroughMenu(window, update);
        QCOMPARE(cell(model, "R12", WatchTableModel::NameColumn), u("Level tank 1"));
        QCOMPARE(cell(model, "R12", WatchTableModel::CommentColumn), u("cm"));
        QCOMPARE(cell(model, "R13", WatchTableModel::NameColumn), u("My pressure"));
        QCOMPARE(window.trendView()->itemName(0), u("Level tank 1 (R12)"));
        QCOMPARE(discretes->index(1, DiscreteTableModel::NameColumn).data().toString(), u("Horn"));
        QVERIFY2(
            window.statusBar()->currentMessage().contains(u("Names imported: 2, lines skipped: 0")),
            qPrintable(window.statusBar()->currentMessage()));

        // Saved with the watch list: a new window that opens it has the names for new rows.
        const QString list = m_dir.filePath(QStringLiteral("line.json"));
        QVERIFY(window.saveWatchList(list).ok());
        MainWindow reopened;
        QVERIFY(reopened.loadWatchList(list).ok());
        QCOMPARE(reopened.symbolNames()->table().size(), 5);
        WatchTableWidget *again = reopened.currentWatchTable();
        WatchItemSpec y1;
        y1.address = addr("Y1");
        y1.format = DisplayFormat::Bit;
        again->model()->addItems({y1});
        QCOMPARE(cell(again->model(), "Y1", WatchTableModel::NameColumn), u("Horn"));
    }

    void unreadableFileIsReported()
    {
        MainWindow window;
        const auto result = window.importNames(m_dir.filePath(QStringLiteral("missing.csv")));
        QVERIFY(!result);
        const QString status = window.statusBar()->currentMessage();
        QVERIFY2(status.contains(u("cannot be imported")), qPrintable(status));
        QVERIFY(window.symbolNames()->table().isEmpty());
    }
};

QTEST_MAIN(TestUiNames)
#include "tst_ui_names.moc"
