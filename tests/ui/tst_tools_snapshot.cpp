// Tools -> Memory Snapshot (SnapshotDialog) against the in-process simulator: take, compare with
// the PLC and with a file, filter, export, restore with confirmation, refused in operator mode;
// the file buttons and Close of its frame.
#include "core/commission/snapshotfile.h"
#include "tst_tools_boxes.h"
#include "tst_tools_fixture.h"
#include "ui/common/csvfilefilter.h"
#include "ui/tools/snapshotdialog.h"
#include "ui/tools/snapshotdiffmodel.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;
using ToolsTest::addr;

class TestToolsSnapshot : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void takeCompareRestore();
    void compareFilesAndExport();
    void refusedInOperatorMode();
    void otherModelAskedOutOfRangeRefused();
    void filePickersAndClose();

private:
    bool runAndWait(const std::function<void()> &action);

    ToolsTest::Rig m_rig;
    std::unique_ptr<SnapshotDialog> m_dialog;
    QTemporaryDir m_dir;
};

void TestToolsSnapshot::init()
{
    QVERIFY(m_rig.start());
    m_dialog = std::make_unique<SnapshotDialog>();
    m_dialog->setTarget(m_rig.target(1));
    m_dialog->setConfirmer(m_rig.confirmer());
    m_rig.questions.clear();
    m_rig.answer = true;
}

void TestToolsSnapshot::cleanup()
{
    m_dialog.reset();
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

bool TestToolsSnapshot::runAndWait(const std::function<void()> &action)
{
    QSignalSpy done(m_dialog.get(), &SnapshotDialog::actionFinished);
    action();
    return done.wait(10000);
}

void TestToolsSnapshot::takeCompareRestore()
{
    // As a person does it: the dialog on screen at a laptop's size, ranges typed into its fields
    // (with delays), its buttons clicked, the differences read from the table on screen.
    m_dialog->resize(900, 600);
    m_dialog->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_dialog.get()));
    auto *ranges = m_dialog->findChild<QLineEdit *>(QStringLiteral("ranges"));
    auto *filter = m_dialog->findChild<QLineEdit *>(QStringLiteral("filter"));
    auto *restoreRanges = m_dialog->findChild<QLineEdit *>(QStringLiteral("restoreRanges"));
    auto *table = m_dialog->findChild<QTableView *>(QStringLiteral("differences"));
    QVERIFY(ranges && filter && restoreRanges && table);
    auto click = [this](const char *name) {
        auto *b = m_dialog->findChild<QPushButton *>(QLatin1String(name));
        QVERIFY2(b && b->isVisible() && b->isEnabled(), name);
        QTest::mouseClick(b, Qt::LeftButton);
    };

    m_rig.plc->setValue(addr("R3"), 33);
    m_rig.plc->setValue(addr("M1"), 1);
    ranges->clear();
    QTest::keyClicks(ranges, QStringLiteral("R0..R9, M0..M15"), Qt::NoModifier, 5);
    QVERIFY(runAndWait([&] { click("takeButton"); }));
    QVERIFY2(m_dialog->snapshot().has_value(), qPrintable(m_dialog->messageText()));
    QCOMPARE(m_dialog->snapshot()->values.size(), std::size_t(26));
    QVERIFY(m_dialog->messageText().contains(QLatin1String("26 values read")));

    m_rig.plc->setValue(addr("R3"), 1);
    m_rig.plc->setValue(addr("M1"), 0);
    QVERIFY(runAndWait([&] { click("comparePlcButton"); }));
    QCOMPARE(table->model()->rowCount(), 2);
    QCOMPARE(m_dialog->differences()->data(m_dialog->differences()->index(1, 1)).toString(),
             QStringLiteral("33"));
    QTest::keyClicks(filter, QStringLiteral("R3"), Qt::NoModifier, 5);
    QCOMPARE(table->model()->rowCount(), 1);
    QCOMPARE(table->model()->index(0, 0).data().toString(), QStringLiteral("R3"));

    // Restore only R3; the question names the target.
    QTest::keyClicks(restoreRanges, QStringLiteral("R3"), Qt::NoModifier, 5);
    QVERIFY(runAndWait([&] { click("restoreButton"); }));
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY(m_rig.questions.first().contains(ToolsTest::Rig::connectionName()));
    QCOMPARE(m_rig.plc->value(addr("R3")), std::optional<std::uint32_t>(33));
    QCOMPARE(m_rig.plc->value(addr("M1")), std::optional<std::uint32_t>(0));
    QVERIFY2(m_dialog->messageText().contains(QLatin1String("read back equal")),
             qPrintable(m_dialog->messageText()));

    // Answered No: nothing written.
    m_rig.answer = false;
    restoreRanges->clear();
    click("restoreButton");
    QVERIFY2(m_rig.questions.size() == 2, qPrintable(m_dialog->messageText()));
    QCOMPARE(m_rig.plc->value(addr("M1")), std::optional<std::uint32_t>(0));
}

void TestToolsSnapshot::compareFilesAndExport()
{
    m_dialog->setRanges(QStringLiteral("D0..D3"));
    QVERIFY(runAndWait([this] { m_dialog->takeSnapshot(); }));
    const QString a = m_dir.filePath(QStringLiteral("a.csv"));
    QVERIFY(m_dialog->saveSnapshot(a));
    MemorySnapshot other = *m_dialog->snapshot();
    other.values[2].value = 7;
    const QString b = m_dir.filePath(QStringLiteral("b.json"));
    QVERIFY(!SnapshotFile::saveToFile(other, b));
    QVERIFY(m_dialog->openSnapshot(a));
    QVERIFY(m_dialog->compareWithFile(b));
    QCOMPARE(m_dialog->differences()->rowCount(), 1);
    const QString csv = m_dir.filePath(QStringLiteral("diff.csv"));
    QVERIFY(m_dialog->exportDifferences(csv));
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(),
             QByteArray("\xEF\xBB\xBF"
                        "address,before,after,beforeHex,afterHex\nD2,0,7,0x0000,0x0007\n"));
    f.close();
    // The file type "CSV, Windows line ends": CRLF.
    QVERIFY(m_dialog->exportDifferences(csv, CsvFile::LineEnd::CrLf));
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(),
             QByteArray("\xEF\xBB\xBF"
                        "address,before,after,beforeHex,afterHex\r\nD2,0,7,0x0000,0x0007\r\n"));
    // A device that takes nothing: refused with the system's reason in the message line.
    if (QFileInfo(QStringLiteral("/dev/full")).exists()) {
        QVERIFY(!m_dialog->exportDifferences(QStringLiteral("/dev/full")));
        QVERIFY2(m_dialog->messageText().contains(QLatin1String("No space left on device")),
                 qPrintable(m_dialog->messageText()));
        QVERIFY(!QFileInfo(QStringLiteral("/dev/full")).isFile());
    }
    // A damaged file: refused, named in the message line.
    QFile bad(m_dir.filePath(QStringLiteral("bad.json")));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("{\"format\": 1");
    bad.close();
    QVERIFY(!m_dialog->compareWithFile(bad.fileName()));
    QVERIFY2(m_dialog->messageText().contains(QLatin1String("line 1, column")),
             qPrintable(m_dialog->messageText()));
}

void TestToolsSnapshot::refusedInOperatorMode()
{
    m_dialog->setRanges(QStringLiteral("R0..R3"));
    QVERIFY(runAndWait([this] { m_dialog->takeSnapshot(); }));
    m_rig.plc->setValue(addr("R0"), 9);
    m_rig.link->setReadOnly(true);
    const quint64 frames = m_rig.server->counters().frames;
    m_dialog->restoreValues();
    QVERIFY(m_rig.questions.isEmpty());
    QCOMPARE(m_rig.server->counters().frames, frames);
    QCOMPARE(m_rig.plc->value(addr("R0")), std::optional<std::uint32_t>(9));
    QVERIFY2(m_dialog->messageText().contains(QLatin1String("Operator mode")),
             qPrintable(m_dialog->messageText()));
}

// Issue 48 case 10 in the GUI: a snapshot of an M-series PLC opened and restored to an FBs. After
// the restore's question, the dialog asks about the other model (both named): No writes nothing,
// Yes writes. A value the FBs does not have is refused by name before anything is written. The
// questions are the real message boxes.
void TestToolsSnapshot::otherModelAskedOutOfRangeRefused()
{
    m_dialog->setConfirmer({});
    m_dialog->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_dialog.get()));
    MemorySnapshot m;
    m.info.model = QStringLiteral("M series, OS V3.1, program 16384 words");
    m.values = {{addr("R0"), 5}, {addr("R1"), 6}};
    const QString file = m_dir.filePath(QStringLiteral("m.json"));
    QVERIFY(!SnapshotFile::saveToFile(m, file));
    QVERIFY(m_dialog->openSnapshot(file));
    auto *restore = m_dialog->findChild<QPushButton *>(QStringLiteral("restoreButton"));
    QVERIFY(restore && restore->isVisible() && restore->isEnabled());

    const quint64 frames = m_rig.server->counters().frames;
    {
        ToolsTest::BoxHand hand({true, false});
        QVERIFY(runAndWait([&] { QTest::mouseClick(restore, Qt::LeftButton); }));
        QCOMPARE(hand.questions.size(), 2);
        QVERIFY2(hand.questions.at(1).contains(QLatin1String("another model")),
                 qPrintable(hand.questions.at(1)));
        QVERIFY2(hand.questions.at(1).contains(QLatin1String("M series, OS V3.1")),
                 qPrintable(hand.questions.at(1)));
        QVERIFY2(hand.questions.at(1).contains(QLatin1String("FBs-28MC")),
                 qPrintable(hand.questions.at(1)));
    }
    QCOMPARE(m_rig.server->counters().frames, frames + 1); // the 53 alone
    QCOMPARE(m_rig.plc->value(addr("R0")), std::optional<std::uint32_t>(0));
    QVERIFY2(m_dialog->messageText().contains(QLatin1String("nothing was written")),
             qPrintable(m_dialog->messageText()));
    {
        ToolsTest::BoxHand hand({true, true});
        QVERIFY(runAndWait([&] { QTest::mouseClick(restore, Qt::LeftButton); }));
        QCOMPARE(hand.questions.size(), 2);
    }
    QCOMPARE(m_rig.plc->value(addr("R1")), std::optional<std::uint32_t>(6));
    QVERIFY2(m_dialog->messageText().contains(QLatin1String("read back equal")),
             qPrintable(m_dialog->messageText()));

    // An FBs snapshot holding R5000: refused by name, nothing written.
    m.info.model = QStringLiteral("FBs-28MC, OS V3.1, program 13184 words");
    m.values = {{addr("R2"), 7}, {addr("R5000"), 1}};
    QVERIFY(!SnapshotFile::saveToFile(m, file));
    QVERIFY(m_dialog->openSnapshot(file));
    {
        ToolsTest::BoxHand hand({true});
        QVERIFY(runAndWait([&] { QTest::mouseClick(restore, Qt::LeftButton); }));
        QCOMPARE(hand.questions.size(), 1);
    }
    QCOMPARE(m_rig.plc->value(addr("R2")), std::optional<std::uint32_t>(0));
    QVERIFY2(m_dialog->messageText().contains(QLatin1String("not on the PLC: R5000")),
             qPrintable(m_dialog->messageText()));
}

// The file buttons ask through the dialog's frame (save or open, its title and filter); a pick
// cancelled does nothing. Closing the dialog while it reads cancels the read.
void TestToolsSnapshot::filePickersAndClose()
{
    m_dialog->setRanges(QStringLiteral("D0..D3"));
    QVERIFY(runAndWait([this] { m_dialog->takeSnapshot(); }));
    QList<ToolDialogFrame::FileQuestion> asked;
    QString answer; // empty: the person cancelled
    m_dialog->setFileChooser([&asked, &answer](const ToolDialogFrame::FileQuestion &question) {
        asked << question;
        return answer;
    });
    auto *save = m_dialog->findChild<QPushButton *>(QStringLiteral("saveButton"));
    auto *open = m_dialog->findChild<QPushButton *>(QStringLiteral("openButton"));
    QVERIFY(save && open);
    const QStringList files = QDir(m_dir.path()).entryList(QDir::Files);
    save->click();
    QCOMPARE(asked.size(), 1);
    QVERIFY(asked.last().save);
    QCOMPARE(asked.last().title, SnapshotDialog::tr("Save Snapshot"));
    // Saving offers a second type: a .csv snapshot with Windows line ends.
    QCOMPARE(asked.last().filter, SnapshotDialog::tr("Snapshots (*.json *.csv)")
                                      + QStringLiteral(";;") + CsvFileFilter::windows());
    QVERIFY(asked.last().selectedFilter);
    QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files), files); // nothing written

    answer = m_dir.filePath(QStringLiteral("picked.json"));
    save->click();
    QVERIFY(QFileInfo::exists(answer));
    QCOMPARE(m_dialog->messageText(), SnapshotDialog::tr("Saved %1.").arg(answer));
    open->click();
    QCOMPARE(asked.size(), 3);
    QVERIFY(!asked.last().save);
    QCOMPARE(asked.last().title, SnapshotDialog::tr("Open Snapshot"));
    QCOMPARE(asked.last().filter, SnapshotDialog::tr("Snapshots (*.json *.csv)"));
    QCOMPARE(m_dialog->messageText(), SnapshotDialog::tr("Opened %1.").arg(answer));

    // The Windows type chosen: the .csv snapshot has the byte order mark and CRLF, and opens.
    answer = m_dir.filePath(QStringLiteral("windows.csv"));
    m_dialog->setFileChooser([&answer](const ToolDialogFrame::FileQuestion &question) {
        if (question.selectedFilter)
            *question.selectedFilter = CsvFileFilter::windows();
        return answer;
    });
    save->click();
    QFile csv(answer);
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QByteArray data = csv.readAll();
    QVERIFY2(data.startsWith("\xEF\xBB\xBF# fatek-studio-snapshot 1\r\n"), data.constData());
    QCOMPARE(data.count('\n'), data.count("\r\n"));
    open->click();
    QCOMPARE(m_dialog->messageText(), SnapshotDialog::tr("Opened %1.").arg(answer));

    QSignalSpy finished(m_dialog.get(), &SnapshotDialog::actionFinished);
    m_dialog->takeSnapshot();
    QVERIFY(m_dialog->isBusy());
    m_dialog->reject(); // Close, Esc or the window's button
    QVERIFY(!m_dialog->isBusy());
    QCOMPARE(finished.size(), 1);
}

QTEST_MAIN(TestToolsSnapshot)
#include "tst_tools_snapshot.moc"
