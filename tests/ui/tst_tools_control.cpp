// PlcControlPanel against the in-process simulator: RUN/STOP with confirmation, refusals in words,
// STATUS1 lamps and the decoded detail status.
#include "tst_tools_fixture.h"
#include "ui/tools/plccontrolpanel.h"
#include "ui/tools/statusindicator.h"

#include <QLabel>
#include <QPushButton>
#include <QTest>

using namespace Fatek;
using ToolsTest::Rig;

class TestToolsControl : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void runStopRun();
    void refusalShownInWords();
    void declinedConfirmationSendsNothing();
    void statusFlagsAsLamps();
    void detailStatusDecoded();
    void noConnection();
    void sessionDeleted();
    void operatorModeDisablesRunStop();
    void linkDownDisablesRunStop();
    void mSeriesDetailInWords();

private:
    void clickAndConfirm(const char *button);

    Rig m_rig;
    std::unique_ptr<PlcControlPanel> m_panel;
};

void TestToolsControl::init()
{
    m_rig = Rig();
    QVERIFY(m_rig.start());
    m_panel = std::make_unique<PlcControlPanel>();
    m_panel->setConfirmer(m_rig.confirmer());
    m_panel->setRefreshInterval(100);
    m_panel->setTarget(m_rig.target(1));
    m_panel->show();
}

void TestToolsControl::cleanup()
{
    m_panel.reset();
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

void TestToolsControl::clickAndConfirm(const char *button)
{
    auto *b = m_panel->findChild<QPushButton *>(QLatin1String(button));
    QVERIFY(b);
    QTRY_VERIFY_WITH_TIMEOUT(b->isEnabled(), 10000);
    b->click();
}

void TestToolsControl::runStopRun()
{
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status().has_value() && m_panel->status()->running, 10000);
    auto *mode = m_panel->findChild<QLabel *>(QStringLiteral("modeLabel"));
    QCOMPARE(mode->text(), QStringLiteral("RUN"));

    clickAndConfirm("stopButton");
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY2(m_rig.questions.last().contains(QStringLiteral("station 1")),
             qPrintable(m_rig.questions.last()));
    QVERIFY(m_rig.questions.last().contains(Rig::connectionName()));
    QVERIFY(m_rig.questions.last().contains(QStringLiteral("STOP")));
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig.plc->isRunning(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status() && !m_panel->status()->running, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(mode->text(), QStringLiteral("STOP"), 10000);
    auto *runLamp = m_panel->findChild<StatusIndicator *>(QStringLiteral("running"));
    QVERIFY(runLamp);
    QCOMPARE(runLamp->state(), StatusIndicator::State::Off);

    clickAndConfirm("runButton");
    QCOMPARE(m_rig.questions.size(), 2);
    QVERIFY(m_rig.questions.last().contains(QStringLiteral("RUN")));
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.plc->isRunning(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status() && m_panel->status()->running, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(runLamp->state(), StatusIndicator::State::On, 10000);
    QVERIFY2(m_panel->outcomeText().contains(QStringLiteral("accepted")),
             qPrintable(m_panel->outcomeText()));
}

void TestToolsControl::refusalShownInWords()
{
    m_rig.plc->setRunning(false);
    m_rig.plc->setRunRefusalCode(5);
    clickAndConfirm("runButton");
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->outcomeText().contains(
                                 QStringLiteral("PLC error 5: cannot RUN: ladder checksum error")),
                             10000);
    auto *outcome = m_panel->findChild<QLabel *>(QStringLiteral("outcomeLabel"));
    QVERIFY(outcome->property("error").toBool());
    QVERIFY(!m_rig.plc->isRunning());

    m_rig.plc->setRunRefusalCode(6);
    clickAndConfirm("runButton");
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->outcomeText().contains(QStringLiteral("PLC ID differs")),
                             10000);
    QVERIFY(!m_rig.plc->isRunning());
}

void TestToolsControl::declinedConfirmationSendsNothing()
{
    m_rig.answer = false;
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status().has_value(), 10000);
    clickAndConfirm("stopButton");
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY(m_panel->outcomeText().contains(QStringLiteral("cancelled")));
    // Give a wrongly sent STOP time to arrive: the PLC must still run.
    QTest::qWait(300);
    QVERIFY(m_rig.plc->isRunning());
}

void TestToolsControl::statusFlagsAsLamps()
{
    PlcStatus flags;
    flags.batteryLow = true;
    flags.emergencyStop = true;
    flags.idSet = true;
    m_rig.plc->setStatusFlags(flags);
    auto lamp = [this](const char *name) {
        auto *indicator = m_panel->findChild<StatusIndicator *>(QLatin1String(name));
        return indicator ? indicator->state() : StatusIndicator::State::Unknown;
    };
    QTRY_COMPARE_WITH_TIMEOUT(lamp("batteryLow"), StatusIndicator::State::On, 10000);
    QCOMPARE(lamp("emergencyStop"), StatusIndicator::State::On);
    QCOMPARE(lamp("idSet"), StatusIndicator::State::On);
    QCOMPARE(lamp("ladderChecksumError"), StatusIndicator::State::Off);
    QCOMPARE(lamp("watchdogError"), StatusIndicator::State::Off);
    QCOMPARE(lamp("memoryPack"), StatusIndicator::State::Off);

    flags = PlcStatus{};
    flags.ladderChecksumError = true;
    m_rig.plc->setStatusFlags(flags);
    QTRY_COMPARE_WITH_TIMEOUT(lamp("ladderChecksumError"), StatusIndicator::State::On, 10000);
    QCOMPARE(lamp("batteryLow"), StatusIndicator::State::Off);
}

void TestToolsControl::detailStatusDecoded()
{
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->detailStatus().has_value(), 10000);
    const ModelProfile profile = m_rig.plc->profile();
    const DetailStatus d = *m_panel->detailStatus();
    QCOMPARE(d.ladderSize.value_or(0), profile.programWords);
    QStringList texts;
    for (QLabel *label : m_panel->findChildren<QLabel *>())
        texts << label->text();
    const QString shown = texts.join(QLatin1Char('|'));
    QVERIFY2(shown.contains(QStringLiteral("%1 words").arg(profile.programWords)),
             qPrintable(shown));
    QVERIFY2(shown.contains(QStringLiteral("V3.1")), qPrintable(shown));
    // The model as printed on the unit, not "main unit MC".
    QVERIFY2(shown.contains(QStringLiteral("FBs-28MC")), qPrintable(shown));
    auto *raw = m_panel->findChild<QLabel *>(QStringLiteral("rawDetail"));
    QVERIFY(raw->text().startsWith(QStringLiteral("01 "))); // STATUS1: RUN
}

void TestToolsControl::noConnection()
{
    m_panel->setTarget(PlcTarget());
    auto *target = m_panel->findChild<QLabel *>(QStringLiteral("targetLabel"));
    QVERIFY(target->text().contains(QStringLiteral("No connection")));
    QVERIFY(!m_panel->findChild<QPushButton *>(QStringLiteral("runButton"))->isEnabled());
    QVERIFY(!m_panel->findChild<QPushButton *>(QStringLiteral("stopButton"))->isEnabled());
    QVERIFY(!m_panel->status().has_value());
    m_panel->requestStop(); // must do nothing, and not crash
    QVERIFY(m_rig.questions.isEmpty());
}

void TestToolsControl::sessionDeleted()
{
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status().has_value(), 10000);
    m_rig.link.reset();
    auto *target = m_panel->findChild<QLabel *>(QStringLiteral("targetLabel"));
    QVERIFY(target->text().contains(QStringLiteral("No connection")));
    QVERIFY(!m_panel->findChild<QPushButton *>(QStringLiteral("runButton"))->isEnabled());
    QTest::qWait(300); // the refresh timer must not touch the deleted session
    QVERIFY(!m_panel->status().has_value());
}

void TestToolsControl::operatorModeDisablesRunStop()
{
    auto *run = m_panel->findChild<QPushButton *>(QStringLiteral("runButton"));
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status().has_value() && run->isEnabled(), 10000);
    m_rig.link->setReadOnly(true);
    QTRY_VERIFY_WITH_TIMEOUT(!run->isEnabled(), 10000);
    QVERIFY(run->toolTip().contains(QStringLiteral("Read-only")));
    // Called anyway (a shortcut, a script): the session refuses and the panel says so.
    m_panel->requestRun();
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->outcomeText().contains(QStringLiteral("Read-only mode")),
                             10000);
    m_rig.link->setReadOnly(false);
    QTRY_VERIFY_WITH_TIMEOUT(run->isEnabled(), 10000);
}

// Issue 54: while the link is down RUN/STOP cannot go out: the buttons are disabled and say why.
void TestToolsControl::linkDownDisablesRunStop()
{
    auto *run = m_panel->findChild<QPushButton *>(QStringLiteral("runButton"));
    auto *stop = m_panel->findChild<QPushButton *>(QStringLiteral("stopButton"));
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->status().has_value() && run->isEnabled(), 10000);
    m_rig.server.reset(); // the PLC's end goes away
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.link->linkState() != LinkState::Connected, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(!run->isEnabled() && !stop->isEnabled(), 10000);
    QVERIFY2(run->toolTip().contains(QStringLiteral("link")), qPrintable(run->toolTip()));
}

// Issue 54: an M-series PLC reports no FBs unit type nor I/O code (255): the panel says what it
// knows (the family) and that the rest is not reported, never "type 255" or "code 255".
void TestToolsControl::mSeriesDetailInWords()
{
    m_panel->setTarget(PlcTarget());
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
    QVERIFY(m_rig.start(LinkSettings::ProtocolChoice::Facon, 1000, 1, ModelProfile::mSeries()));
    m_panel->setTarget(m_rig.target(1));
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->detailStatus().has_value(), 10000);
    QStringList texts;
    for (QLabel *label : m_panel->findChildren<QLabel *>()) {
        if (label->objectName() != QLatin1String("rawDetail"))
            texts << label->text();
    }
    const QString shown = texts.join(QLatin1Char('|'));
    QVERIFY2(!shown.contains(QStringLiteral("255")) && !shown.contains(QStringLiteral("code")),
             qPrintable(shown));
    QVERIFY2(shown.contains(QStringLiteral("M series")), qPrintable(shown));
    QVERIFY2(shown.contains(QStringLiteral("not reported")), qPrintable(shown));
}

QTEST_MAIN(TestToolsControl)
#include "tst_tools_control.moc"
