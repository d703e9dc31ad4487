#pragma once

// What the checkout tests share (tst_checkout, tst_checkout_statuses): an FBs simulator in STOP
// with no demo ladder (only the test moves the inputs) served over loopback TCP and a session on
// it; a runner started on it; an input actuated as a technician does.
#include "core/commission/checkoutplan.h"
#include "core/commission/checkoutrunner.h"
#include "core/qtbridge/qtmessage.h"
#include "core/session/session.h"
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

struct CheckoutSim
{
    std::unique_ptr<Fatek::SimulatedPlc> plc;
    std::unique_ptr<Fatek::SimServer> server;
    std::unique_ptr<Fatek::Session> session;
    std::unique_ptr<QTemporaryDir> dir;
    quint16 port = 0;

    void open()
    {
        using namespace Fatek;
        registerSessionMetaTypes();
        plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
        plc->setRunning(false);
        server = std::make_unique<SimServer>(plc.get());
        QVERIFY(server->listenTcp(0));
        port = server->tcpPort();
        LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port,
                                                  LinkSettings::ProtocolChoice::Facon);
        settings.timeoutMs = 2000;
        settings.retries = 1;
        settings.reconnectMinMs = 100;
        settings.reconnectMaxMs = 500;
        session = std::make_unique<Session>(settings);
        session->open();
        QTRY_VERIFY_WITH_TIMEOUT(session->linkState() == LinkState::Connected, 20000);
        dir = std::make_unique<QTemporaryDir>();
    }

    void close()
    {
        session.reset();
        server.reset();
        plc.reset();
        dir.reset();
    }

    QString freeFile(const char *name) const { return dir->filePath(QLatin1String(name)); }

    // Started, and every input polled once (its baseline).
    void startRunner(Fatek::CheckoutRunner &runner, const Fatek::CheckoutPlan &plan,
                     const QString &file = {})
    {
        using namespace Fatek;
        runner.setSession(session.get());
        runner.setPlan(plan);
        runner.setFilePath(file);
        runner.setEngineer(QStringLiteral("Lin"));
        // Every failure in the test's log: a wait that times out says why.
        QObject::connect(&runner, &CheckoutRunner::failed, &runner, [](const ProtocolError &e) {
            qInfo() << "runner failed:" << englishText(e.message);
        });
        QSignalSpy started(&runner, &CheckoutRunner::started);
        QSignalSpy live(&runner, &CheckoutRunner::liveValue);
        runner.start();
        QTRY_VERIFY_WITH_TIMEOUT(started.count() == 1, 30000);
        const int inputs = static_cast<int>(plan.indexesOf(CheckoutKind::Input).size());
        if (inputs > 0)
            QTRY_VERIFY_WITH_TIMEOUT(live.count() >= inputs, 30000);
    }

    // The technician presses the switch and lets it go, each state held until the runner saw it.
    void actuate(Fatek::CheckoutRunner &runner, const char *input)
    {
        const int i = runner.plan().indexOf(TestUtil::addr(input));
        QVERIFY(i >= 0);
        const Fatek::CheckoutPoint &p = runner.plan().points[static_cast<std::size_t>(i)];
        plc->setValue(TestUtil::addr(input), 1);
        QTRY_VERIFY_WITH_TIMEOUT(p.rose.isValid(), 30000);
        plc->setValue(TestUtil::addr(input), 0);
        QTRY_VERIFY_WITH_TIMEOUT(p.fell.isValid(), 30000);
    }
};
