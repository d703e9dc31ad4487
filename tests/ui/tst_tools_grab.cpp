// Manual check aid: renders each tool, connected to the simulator, to /tmp/tools-*.png
// (QWidget::grab) so a person can look at them. Also checks each picture was produced.
#include "tst_tools_fixture.h"
#include "ui/tools/forcedpointsview.h"
#include "ui/tools/forcingpanel.h"
#include "ui/tools/loopbackdialog.h"
#include "ui/tools/plccontrolpanel.h"
#include "ui/tools/rawconsole.h"
#include "ui/tools/rawsendbar.h"

#include <QImage>
#include <QTabWidget>
#include <QTest>

using namespace Fatek;
using ToolsTest::Rig;

class TestToolsGrab : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void controlPanel();
    void forcingPanel();
    void loopbackDialog();
    void rawConsole();
    void disconnected();

private:
    static void save(QWidget *widget, const QString &name);
    Rig m_rig;
};

void TestToolsGrab::initTestCase()
{
    QVERIFY(m_rig.start());
    m_rig.server->setDemoLadder(true);
    PlcStatus flags;
    flags.batteryLow = true;
    m_rig.plc->setStatusFlags(flags);
    m_rig.plc->setDisabled(ToolsTest::addr("Y3"), true);
}

void TestToolsGrab::cleanupTestCase()
{
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

void TestToolsGrab::save(QWidget *widget, const QString &name)
{
    const QString path = QStringLiteral("/tmp/tools-%1.png").arg(name);
    const QImage image = widget->grab().toImage();
    QVERIFY(!image.isNull());
    QVERIFY(image.width() > 100 && image.height() > 100);
    QVERIFY2(image.save(path), qPrintable(path));
}

void TestToolsGrab::controlPanel()
{
    PlcControlPanel panel;
    panel.setTarget(m_rig.target(1));
    panel.resize(560, 620);
    panel.show();
    QTRY_VERIFY_WITH_TIMEOUT(panel.status().has_value() && panel.detailStatus().has_value(), 10000);
    // Show a refusal too, to see the error colour.
    panel.setConfirmer([](const QString &) { return true; });
    m_rig.plc->setRunning(false);
    m_rig.plc->setRunRefusalCode(5);
    panel.requestRun();
    QTRY_VERIFY_WITH_TIMEOUT(panel.outcomeText().contains(QStringLiteral("PLC error 5")), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(panel.status() && !panel.status()->running, 10000);
    save(&panel, QStringLiteral("control"));
    m_rig.plc->setRunRefusalCode(0);
    m_rig.plc->setRunning(true);
}

void TestToolsGrab::forcingPanel()
{
    ForcingPanel panel;
    panel.setConfirmer([](const QString &) { return true; });
    panel.setTarget(m_rig.target(1));
    panel.resize(620, 560);
    panel.show();
    panel.showRange(ElementType::Y, 0, 16);
    QTRY_VERIFY_WITH_TIMEOUT(panel.readCount() > 0, 10000);
    save(&panel, QStringLiteral("forcing"));
    panel.forcedPointsView()->setRanges(QStringLiteral("X0-255, Y0-255"));
    panel.forcedPointsView()->scan();
    QTRY_VERIFY_WITH_TIMEOUT(panel.forcedPointsView()->scanCount() > 0, 10000);
    panel.findChild<QTabWidget *>()->setCurrentWidget(panel.forcedPointsView());
    save(&panel, QStringLiteral("forced"));
}

void TestToolsGrab::loopbackDialog()
{
    LoopbackDialog dialog;
    dialog.setTarget(m_rig.target(1));
    dialog.setRepeatCount(20);
    dialog.resize(640, 480);
    dialog.show();
    dialog.start();
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 30000);
    save(&dialog, QStringLiteral("loopback"));
}

void TestToolsGrab::rawConsole()
{
    RawConsole console;
    console.setTarget(m_rig.target(1));
    console.resize(1100, 520);
    console.show();
    FaultConfig faults;
    faults.corruptRate = 0.3;
    m_rig.server->setFaults(faults);
    RawSendBar *bar = console.sendBar();
    bar->setMode(RawSendBar::Mode::Ascii);
    bar->setText(QStringLiteral("014603R00000"));
    for (int i = 0; i < 4; ++i) {
        bar->send();
        QTRY_VERIFY_WITH_TIMEOUT(!bar->isBusy(), 10000);
    }
    m_rig.server->setFaults({});
    bar->send();
    QTRY_VERIFY_WITH_TIMEOUT(!bar->isBusy(), 10000);
    QTest::qWait(200);
    save(&console, QStringLiteral("console"));
}

void TestToolsGrab::disconnected()
{
    PlcControlPanel panel;
    panel.resize(560, 620);
    panel.show();
    save(&panel, QStringLiteral("control-disconnected"));
}

QTEST_MAIN(TestToolsGrab)
#include "tst_tools_grab.moc"
