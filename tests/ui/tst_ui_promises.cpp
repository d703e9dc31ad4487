// Dialogs that keep their promise (issue 34), through the main window against a simulated FBs over
// loopback TCP, driven as a person does: an empty Ranges field snapshots every element, the
// program dialog's count and time left, a raw frame refused before the wire, and a red write
// failure once the link is back.
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "runningfbs.h"
#include "testutil.h"
#include "ui/common/messageline.h"
#include "ui/connection/connection.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/programtransferdialog.h"
#include "ui/tools/snapshotdialog.h"
#include "ui/watch/watchtablemodel.h"
#include "uitestutil.h"

#include <QAbstractItemView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
constexpr int keyDelayMs = 50;

using Plc = RunningFbs;

} // namespace

class TestUiPromises : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    Connection *m_connection = nullptr;

    bool open(quint16 port, bool readOnly = false)
    {
        m_window = std::make_unique<MainWindow>(readOnly);
        m_window->setConfirmHandler([](QWidget *, const QString &) { return true; });
        m_window->resize(1366, 700);
        m_window->show();
        if (!QTest::qWaitForWindowExposed(m_window.get()))
            return false;
        SavedConnection saved;
        saved.name = QStringLiteral("Bench PLC");
        saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
        saved.settings.timeoutMs = 300;
        saved.settings.retries = 1;
        saved.settings.reconnectMinMs = 200;
        saved.settings.reconnectMaxMs = 400;
        m_connection = m_window->openConnection(saved, false);
        return QTest::qWaitFor([this] { return m_connection->linkState() == LinkState::Connected; },
                               longWait);
    }

    // Through the window system, as a real double-click arrives.
    static void doubleClick(QAbstractItemView *view, const QModelIndex &index)
    {
        QWidget *top = view->window();
        const QPoint pos = view->viewport()->mapTo(top, view->visualRect(index).center());
        QTest::mouseMove(top->windowHandle(), pos, 300);
        QTest::mouseDClick(top->windowHandle(), Qt::LeftButton, {}, pos);
    }

    // The program dialog of the window, with the file and the answers given by the test.
    ProgramTransferDialog *programDialog()
    {
        auto *dialog
            = qobject_cast<ProgramTransferDialog *>(m_window->openTool(QStringLiteral("program")));
        if (!dialog)
            return nullptr;
        const QString file = m_dir.filePath(QStringLiteral("line.fprog"));
        dialog->setFileChooser([file](const ToolDialogFrame::FileQuestion &) { return file; });
        dialog->setConfirmer([](const QString &) { return true; });
        return dialog;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        TestUtil::useTestSettings(m_dir.path(), QStringLiteral("tst_ui_promises"));
    }

    void cleanup()
    {
        m_window.reset();
        m_connection = nullptr;
    }

    // Ranges left empty: every element the PLC reports, as fatek-cli snapshot without RANGES.
    void snapshotOfEmptyRangesReadsEverything()
    {
        Plc plc;
        QVERIFY(open(plc.port));
        auto *dialog
            = qobject_cast<SnapshotDialog *>(m_window->openTool(QStringLiteral("snapshot")));
        QVERIFY(dialog);
        auto *ranges = dialog->findChild<QLineEdit *>(QStringLiteral("ranges"));
        QVERIFY(ranges);
        QTest::mouseClick(ranges, Qt::LeftButton);
        QCOMPARE(ranges->text(), QString());
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("takeButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy() && dialog->snapshot().has_value(), longWait);
        QVERIFY2(dialog->snapshot()->values.size() == 11378, qPrintable(dialog->messageText()));
    }

    // A restore of 207 pages counts "writing 207, verifying 207", never 414 pages; the time left
    // goes when it ends, is cancelled or fails.
    void programCountsAndTimeLeft()
    {
        Plc plc;
        plc.plc.setRunning(false);
        QVERIFY(open(plc.port));
        ProgramTransferDialog *dialog = programDialog();
        QVERIFY(dialog);
        auto *label = dialog->findChild<QLabel *>(QStringLiteral("progressLabel"));
        auto *bar = dialog->findChild<QProgressBar *>(QStringLiteral("progressBar"));
        QVERIFY(label && bar);
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("backupButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), 60000);
        QVERIFY2(!label->text().contains(QStringLiteral("left")), qPrintable(label->text()));

        QStringList seen;
        QTimer watch;
        connect(&watch, &QTimer::timeout, this, [&] {
            if (seen.isEmpty() || seen.constLast() != label->text())
                seen << label->text();
        });
        watch.start(10);
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("restoreButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), 60000);
        watch.stop();
        for (const QString &text : std::as_const(seen))
            QVERIFY2(!text.contains(QStringLiteral("414")), qPrintable(text));
        QCOMPARE(label->text(), QStringLiteral("Writing 207 of 207 pages, verifying 207 of 207"));

        // Cancelled while it writes: the count stays, the time left goes.
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("restoreButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(label->text().startsWith(QStringLiteral("Writing "))
                                     && label->text().contains(QStringLiteral("left")),
                                 longWait);
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("cancelButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), longWait);
        QVERIFY2(!label->text().contains(QStringLiteral("left")), qPrintable(label->text()));
        QVERIFY2(label->text().startsWith(QStringLiteral("Writing ")), qPrintable(label->text()));

        // Failed: the simulator goes away while it writes.
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("restoreButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(label->text().startsWith(QStringLiteral("Writing "))
                                     && label->text().contains(QStringLiteral("left")),
                                 longWait);
        plc.server.close();
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), longWait);
        QVERIFY(dialog->messageIsError());
        QVERIFY2(!label->text().contains(QStringLiteral("left")), qPrintable(label->text()));
    }

    // Operator mode refuses a raw frame before the wire: it is not shown as sent.
    void refusedRawFrameIsNotShownAsSent()
    {
        Plc plc;
        QVERIFY(open(plc.port, true));
        QWidget *console = m_window->openTool(QStringLiteral("console"));
        QVERIFY(console);
        QLabel *result = UiTestUtil::sendRawFrame(console, QStringLiteral("30 31 34 31 31"));
        QVERIFY(result);
        auto *send = console->findChild<QPushButton *>(QStringLiteral("sendButton"));
        QTRY_VERIFY_WITH_TIMEOUT(send->isEnabled(), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(!result->text().contains(QStringLiteral("waiting")), longWait);
        QVERIFY2(!result->text().contains(QStringLiteral("Sent")), qPrintable(result->text()));
        QVERIFY2(result->text().startsWith(QStringLiteral("Not sent: <STX>01411")),
                 qPrintable(result->text()));
    }

    // A write that failed while the link was down: once the link is back the message is no
    // longer red, and it says the value was not written.
    void writeFailureClearsWhenTheLinkIsBack()
    {
        Plc plc;
        QVERIFY(open(plc.port));
        WatchTableWidget *table = m_window->currentWatchTable();
        QVERIFY(table);
        QTest::mouseClick(table->addressEdit(), Qt::LeftButton);
        QTest::keyClicks(table->addressEdit(), QStringLiteral("R100"), {}, keyDelayMs);
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->rowCount() == 1 && model->hasValue(0), longWait);
        auto *line = table->findChild<MessageLine *>(QStringLiteral("messageLabel"));
        QVERIFY(line);

        const quint16 port = plc.port;
        plc.server.close();
        QTRY_VERIFY_WITH_TIMEOUT(m_connection->linkState() != LinkState::Connected, longWait);
        doubleClick(table->view(), table->viewIndex(model->index(0, WatchTableModel::ValueColumn)));
        QTRY_VERIFY(table->view()->viewport()->findChild<QLineEdit *>());
        QLineEdit *editor = table->view()->viewport()->findChild<QLineEdit *>();
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("7"), {}, keyDelayMs);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(line->isError(), longWait);
        QVERIFY2(line->text().contains(QStringLiteral("failed")), qPrintable(line->text()));

        QVERIFY(plc.server.listenTcp(port));
        QTRY_VERIFY_WITH_TIMEOUT(m_connection->linkState() == LinkState::Connected, longWait);
        QTRY_VERIFY_WITH_TIMEOUT(!line->isError(), 2000);
        QVERIFY2(line->text().contains(QStringLiteral("R100 (station 1) = 7 was not written")),
                 qPrintable(line->text()));
    }
};

QTEST_MAIN(TestUiPromises)
#include "tst_ui_promises.moc"
