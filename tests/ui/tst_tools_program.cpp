// ProgramTransferDialog (Tools → Program Backup / Restore…) against the simulator, driven as a
// person does: the real buttons are clicked, the file and the answers come from the test.
#include "core/commission/programimage.h"
#include "testutil.h"
#include "tst_tools_boxes.h"
#include "tst_tools_fixture.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/programtransferdialog.h"

#include <QAction>
#include <QEventLoop>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace Fatek;
using ToolsTest::BoxHand;
using ToolsTest::plcPages;
using ToolsTest::Rig;

namespace {

// Turns the event loop (no sleeping) until the dialog is idle, at most 60 s.
bool waitIdle(const ProgramTransferDialog &dialog)
{
    QDeadlineTimer deadline(60000);
    QTimer tick;
    tick.start(50);
    while (dialog.isRunning() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    return !dialog.isRunning();
}

} // namespace

class TestToolsProgram : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanup();

    void openedFromTheToolsMenu();
    void backupThenRestoreByClicks();
    void restoreDeclinedWritesNothing();
    void operatorModeRefusesRestore();
    void damagedFileShown();
    void otherModelRefusedBeforeAnyQuestion();
    void restoreCutOffSaysTheProgramIsMixed();
    void runDeclinedAfterRestore();
    void runOfferedWhenStoppedAndNotWritten_data();
    void runOfferedWhenStoppedAndNotWritten();

private:
    void open(bool running);
    QPushButton *button(const char *name) const
    {
        return m_dialog->findChild<QPushButton *>(QLatin1String(name));
    }

    Rig m_rig;
    QTemporaryDir m_dir;
    QString m_file;
    std::unique_ptr<ProgramTransferDialog> m_dialog;
};

void TestToolsProgram::open(bool running)
{
    m_rig = Rig();
    QVERIFY(m_rig.start());
    m_rig.plc->setRunning(running);
    m_file = m_dir.filePath(QStringLiteral("gui.fprog"));
    m_dialog = std::make_unique<ProgramTransferDialog>();
    m_dialog->setTarget(m_rig.target(1));
    m_dialog->setConfirmer(m_rig.confirmer());
    m_dialog->setFileChooser([this](const ToolDialogFrame::FileQuestion &) { return m_file; });
    m_dialog->show();
}

void TestToolsProgram::initTestCase()
{
    // Keep the developer's own settings out of the tests.
    TestUtil::useTestSettings(m_dir.path(), QStringLiteral("tst_tools_program"));
}

// Tools → Program Backup / Restore… opens one dialog (a second trigger raises it), aimed at the
// current connection: none here.
void TestToolsProgram::openedFromTheToolsMenu()
{
    MainWindow window;
    window.show();
    auto *action = window.findChild<QAction *>(QStringLiteral("programTransferAction"));
    QVERIFY(action);
    action->trigger();
    action->trigger();
    const auto dialogs = window.findChildren<ProgramTransferDialog *>();
    QCOMPARE(dialogs.size(), 1);
    ProgramTransferDialog *dialog = dialogs.first();
    QVERIFY(dialog->isVisible());
    QVERIFY(!dialog->findChild<QPushButton *>(QStringLiteral("backupButton"))->isEnabled());
    QVERIFY(!dialog->findChild<QPushButton *>(QStringLiteral("restoreButton"))->isEnabled());
    QVERIFY(dialog->findChild<QLabel *>(QStringLiteral("targetLabel"))
                ->text()
                .contains(QStringLiteral("No connection")));
}

void TestToolsProgram::cleanup()
{
    m_dialog.reset();
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

void TestToolsProgram::backupThenRestoreByClicks()
{
    open(true);
    const auto original = plcPages(*m_rig.plc);
    QTest::mouseClick(button("backupButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QVERIFY2(!m_dialog->messageIsError(), qPrintable(m_dialog->messageText()));
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("Backup done: 207 pages")),
             qPrintable(m_dialog->messageText()));
    auto *bar = m_dialog->findChild<QProgressBar *>(QStringLiteral("progressBar"));
    QCOMPARE(bar->value(), 207);
    QCOMPARE(bar->maximum(), 207);
    QVERIFY(ProgramImage::load(m_file).ok());

    // The program changes on the PLC; the restore asks to switch to STOP, then shows what it
    // will write, then writes and verifies, then offers RUN again (answered yes here).
    std::vector<std::uint32_t> page(64, 0x1234);
    QVERIFY(m_rig.plc->setProgramPage(3, page));
    QVERIFY(m_rig.plc->setProgramPage(4, page));
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QCOMPARE(m_rig.questions.size(), 3);
    QVERIFY2(m_rig.questions.at(0).contains(QStringLiteral("STOP")),
             qPrintable(m_rig.questions.at(0)));
    QVERIFY2(m_rig.questions.at(1).contains(QStringLiteral("2 pages differ from the PLC (3-4)")),
             qPrintable(m_rig.questions.at(1)));
    QVERIFY2(m_rig.questions.at(1).contains(QStringLiteral("207 pages")),
             qPrintable(m_rig.questions.at(1)));
    QVERIFY2(m_rig.questions.at(2).contains(QStringLiteral("to RUN now")),
             qPrintable(m_rig.questions.at(2)));
    QVERIFY2(m_rig.questions.at(2).contains(QStringLiteral("207 pages written and verified")),
             qPrintable(m_rig.questions.at(2)));
    QVERIFY(m_rig.plc->isRunning());
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("207 pages written and verified")),
             qPrintable(m_dialog->messageText()));
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("The PLC is in RUN")),
             qPrintable(m_dialog->messageText()));
    QCOMPARE(plcPages(*m_rig.plc), original);
    QCOMPARE(bar->value(), 2 * 207);
}

void TestToolsProgram::restoreDeclinedWritesNothing()
{
    open(false);
    QVERIFY(!ProgramImage::fromWords(ModelProfile::fbs().powerOnProgram())->save(m_file));
    std::vector<std::uint32_t> page(64, 0x4321);
    QVERIFY(m_rig.plc->setProgramPage(9, page));
    const auto before = plcPages(*m_rig.plc);
    m_rig.answer = false;
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY(m_rig.questions.first().contains(QStringLiteral("(9)")));
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("nothing was written")),
             qPrintable(m_dialog->messageText()));
    QCOMPARE(plcPages(*m_rig.plc), before);
}

void TestToolsProgram::operatorModeRefusesRestore()
{
    open(false);
    QVERIFY(!ProgramImage::fromWords(ModelProfile::fbs().powerOnProgram())->save(m_file));
    std::vector<std::uint32_t> page(64, 0x4321);
    QVERIFY(m_rig.plc->setProgramPage(9, page));
    const auto before = plcPages(*m_rig.plc);
    m_rig.link->setReadOnly(true);
    m_dialog->setTarget(m_rig.target(1));
    QVERIFY(!button("restoreButton")->isEnabled());
    auto *mode = m_dialog->findChild<QLabel *>(QStringLiteral("modeLabel"));
    QVERIFY(mode->isVisible());
    QVERIFY(mode->text().contains(QStringLiteral("Operator mode")));
    // Even asked directly (the button is disabled), the restore writes nothing.
    const quint64 frames = m_rig.server->counters().frames;
    m_dialog->restore();
    QVERIFY(waitIdle(*m_dialog));
    QVERIFY(m_dialog->messageIsError());
    QVERIFY(m_dialog->messageText().contains(QStringLiteral("Operator mode")));
    QCOMPARE(m_rig.server->counters().frames, frames);
    QCOMPARE(plcPages(*m_rig.plc), before);
    QVERIFY(m_rig.questions.isEmpty());
    // A backup still works.
    QVERIFY(button("backupButton")->isEnabled());
    QTest::mouseClick(button("backupButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QVERIFY2(!m_dialog->messageIsError(), qPrintable(m_dialog->messageText()));
}

void TestToolsProgram::damagedFileShown()
{
    open(false);
    QFile f(m_file);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("{\"format\": \"fatek-program\", \"version\": 1");
    f.close();
    const auto before = plcPages(*m_rig.plc);
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QVERIFY(m_dialog->messageIsError());
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("JSON")),
             qPrintable(m_dialog->messageText()));
    QCOMPARE(plcPages(*m_rig.plc), before);
}

// An M-series PLC in RUN and a backup of an FBs: refused for the model before any question, and
// the PLC is never stopped for a restore that cannot happen.
void TestToolsProgram::otherModelRefusedBeforeAnyQuestion()
{
    m_rig = Rig();
    QVERIFY(m_rig.start(LinkSettings::ProtocolChoice::Facon, 1000, 1, ModelProfile::mSeries()));
    QVERIFY(m_rig.plc->isRunning());
    m_file = m_dir.filePath(QStringLiteral("fbs.fprog"));
    QVERIFY(!ProgramImage::fromWords(ModelProfile::fbs().powerOnProgram())->save(m_file));
    m_dialog = std::make_unique<ProgramTransferDialog>();
    m_dialog->setTarget(m_rig.target(1));
    m_dialog->setConfirmer(m_rig.confirmer());
    m_dialog->setFileChooser([this](const ToolDialogFrame::FileQuestion &) { return m_file; });
    m_dialog->show();
    const auto before = plcPages(*m_rig.plc);
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QVERIFY2(m_rig.questions.isEmpty(), qPrintable(m_rig.questions.join(QLatin1Char('|'))));
    QVERIFY(m_rig.plc->isRunning());
    QVERIFY(m_dialog->messageIsError());
    const QString message = m_dialog->messageText();
    QVERIFY2(message.contains(QStringLiteral("The backup is for a FBs series, 13184-word program")),
             qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("16384-word program")), qPrintable(message));
    QVERIFY2(!message.contains(QLatin1Char('?')), qPrintable(message));
    QCOMPARE(plcPages(*m_rig.plc), before);
}

// The link drops while pages are written: the PLC holds part of each program and stays in STOP;
// the message says so and what to do.
void TestToolsProgram::restoreCutOffSaysTheProgramIsMixed()
{
    open(false);
    std::vector<std::uint16_t> words = ModelProfile::fbs().powerOnProgram();
    for (std::size_t i = 64; i < words.size(); ++i)
        words[i] = static_cast<std::uint16_t>(i);
    QVERIFY(!ProgramImage::fromWords(words)->save(m_file));
    // The simulator goes away once 20 pages are written (the bar counts writing, then reading
    // back: 2 x 207).
    auto *bar = m_dialog->findChild<QProgressBar *>(QStringLiteral("progressBar"));
    bool cut = false;
    connect(bar, &QProgressBar::valueChanged, this, [&](int value) {
        if (!cut && bar->maximum() == 2 * 207 && value >= 20) {
            cut = true;
            QTimer::singleShot(0, this, [this] { m_rig.server.reset(); });
        }
    });
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QVERIFY(cut);
    QVERIFY(m_dialog->messageIsError());
    const QString message = m_dialog->messageText();
    QVERIFY2(message.contains(QStringLiteral("Writing program page")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("holds a mixed program")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("restore the same file again")), qPrintable(message));
    QVERIFY(!m_rig.plc->isRunning());
    // Only the question before writing: no RUN offered after a failure.
    QCOMPARE(m_rig.questions.size(), 1);
}

// After a restore the PLC stays in STOP unless the person says otherwise (the default is No).
void TestToolsProgram::runDeclinedAfterRestore()
{
    open(false);
    std::vector<std::uint16_t> words = ModelProfile::fbs().powerOnProgram();
    words[70] = 0x5555;
    QVERIFY(!ProgramImage::fromWords(words)->save(m_file));
    int asked = 0;
    m_dialog->setConfirmer([&asked](const QString &) { return ++asked == 1; });
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QCOMPARE(asked, 2);
    QVERIFY(!m_rig.plc->isRunning());
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("stays in STOP")),
             qPrintable(m_dialog->messageText()));
    QVERIFY(!m_dialog->messageIsError());
}

void TestToolsProgram::runOfferedWhenStoppedAndNotWritten_data()
{
    QTest::addColumn<bool>("run");
    QTest::newRow("back to RUN") << true;
    QTest::newRow("stays in STOP") << false;
}

// Issue 48 case 11: the PLC in RUN, "Switch to STOP?" Yes, then No at "Write the program?": the
// dialog stopped the PLC for nothing, so it offers RUN again and says the PLC's state. The
// questions are the real message boxes, answered by clicking their buttons.
void TestToolsProgram::runOfferedWhenStoppedAndNotWritten()
{
    QFETCH(bool, run);
    open(true);
    m_dialog->setConfirmer({});
    std::vector<std::uint16_t> words = ModelProfile::fbs().powerOnProgram();
    words[70] = 0x5555;
    QVERIFY(!ProgramImage::fromWords(words)->save(m_file));
    const auto before = plcPages(*m_rig.plc);
    BoxHand hand({true, false, run});
    QTest::mouseClick(button("restoreButton"), Qt::LeftButton);
    QVERIFY(waitIdle(*m_dialog));
    QCOMPARE(hand.questions.size(), 3);
    QVERIFY2(hand.questions.at(0).contains(QStringLiteral("Switch the PLC to STOP")),
             qPrintable(hand.questions.at(0)));
    QVERIFY2(hand.questions.at(1).contains(QStringLiteral("Write the program")),
             qPrintable(hand.questions.at(1)));
    QVERIFY2(hand.questions.at(2).contains(QStringLiteral("back to RUN")),
             qPrintable(hand.questions.at(2)));
    QCOMPARE(plcPages(*m_rig.plc), before);
    QCOMPARE(m_rig.plc->isRunning(), run);
    const QString message = m_dialog->messageText();
    QVERIFY2(message.contains(QStringLiteral("nothing was written")), qPrintable(message));
    QVERIFY2(message.contains(run ? QStringLiteral("The PLC is in RUN")
                                  : QStringLiteral("The PLC stays in STOP")),
             qPrintable(message));
    QVERIFY(!m_dialog->messageIsError());
}

QTEST_MAIN(TestToolsProgram)
#include "tst_tools_program.moc"
