// Operator mode in the main window: a preference switched live, protected by a password or a
// confirmation, locked by --read-only, and enforced below the UI: a refused write, force, RUN or
// raw frame never reaches the wire (the simulator counts every byte it receives).
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"
#include "ui/connection/connection.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/mainwindow/operatormode.h"

#include <QAction>
#include <QLabel>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return *Address::parse(text);
}

struct Plc
{
    SimulatedPlc plc;
    SimServer server{&plc};
    Plc()
    {
        plc.setRunning(false); // so a RUN that slipped through would show
        server.listenTcp(0);
    }
};

SavedConnection savedFor(quint16 port)
{
    SavedConnection saved;
    saved.name = QStringLiteral("Test PLC");
    saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
    saved.settings.protocol = LinkSettings::ProtocolChoice::Facon;
    saved.settings.timeoutMs = 500;
    saved.settings.retries = 0;
    return saved;
}

// Submits `request` (or a raw frame) and waits for its one result.
SessionResult run(Session *session, const Request *request, const QByteArray &raw = {})
{
    SessionResult out;
    bool done = false;
    quint64 id = 0;
    auto connection = QObject::connect(session, &Session::finished, session,
                                       [&](quint64 finishedId, const SessionResult &result) {
                                           if (finishedId == id) {
                                               out = result;
                                               done = true;
                                           }
                                       });
    id = request ? session->submit(*request) : session->sendRaw(raw, true);
    // QTRY_VERIFY cannot return a value; the callers check the result, which stays "not done".
    if (!QTest::qWaitFor([&] { return done; }, 5000))
        qWarning("no result within 5 s");
    QObject::disconnect(connection);
    return out;
}

} // namespace

class TestUiOperatorMode : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_operatormode"));
        registerSessionMetaTypes();
    }
    void init() { QSettings().clear(); }

    void refusedNeverReachesTheWire()
    {
        Plc plc;
        QVERIFY(plc.server.tcpPort() != 0);
        MainWindow window;
        Connection *c = window.openConnection(savedFor(plc.server.tcpPort()), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, 10000);
        auto *mode = window.findChild<OperatorMode *>();
        QVERIFY(mode);
        QVERIFY(!mode->isActive());

        // Switched on from the menu: immediate, shown, and in every session.
        mode->toggleAction()->trigger();
        QVERIFY(mode->isActive());
        QVERIFY(window.isReadOnly());
        QVERIFY(window.windowTitle().contains(QStringLiteral("Operator mode")));
        auto *label = window.findChild<QLabel *>(QStringLiteral("modeLabel"));
        QVERIFY(label && !label->isHidden());
        QVERIFY(c->session()->isReadOnly());
        QVERIFY(QSettings().value(QStringLiteral("operatorMode/enabled")).toBool());

        // The tools poll status in the background, so count what the PLC was asked, not bytes.
        QStringList received;
        plc.server.setVerbose(true);
        connect(&plc.server, &SimServer::logLine, this,
                [&received](const QString &line) { received << line; });
        const quint64 before = plc.server.counters().bytesIn;
        const Request write = Request::writeRegisters(1, addr("R10"), {1234});
        const Request force = Request::discreteControl(1, DiscreteOp::Disable, addr("Y0"));
        const Request runPlc = Request::runStop(1, true);
        for (const Request *r : {&write, &force, &runPlc}) {
            const SessionResult result = run(c->session(), r);
            QCOMPARE(result.errorKind(), ErrorKind::ReadOnly);
            QCOMPARE(result.attempts(), 0);
        }
        const SessionResult raw = run(c->session(), nullptr, QByteArray("01410"));
        QCOMPARE(raw.errorKind(), ErrorKind::ReadOnly);
        QVERIFY2(raw.errorText().contains(QStringLiteral("raw frame")),
                 qPrintable(raw.errorText()));
        QTest::qWait(200);
        // Not one of them went out: whatever reached the PLC meanwhile only reads.
        static const QRegularExpression readLine(QStringLiteral("^\\[[^]]*\\] \\S+ read "));
        for (const QString &line : std::as_const(received))
            QVERIFY2(readLine.match(line).hasMatch() || line.endsWith(QStringLiteral("connected")),
                     qPrintable(line));
        QCOMPARE(plc.plc.value(addr("R10")), std::optional<std::uint32_t>(0));
        QVERIFY(!plc.plc.isRunning());
        // Reads still work in operator mode.
        const Request read = Request::readRegisters(1, addr("R10"), 1);
        QVERIFY(run(c->session(), &read).ok());
        QVERIFY(plc.server.counters().bytesIn > before);

        // A connection opened later is read-only too.
        Connection *second = window.openConnection(savedFor(plc.server.tcpPort()), false);
        QVERIFY(second->session()->isReadOnly());

        // Off without a password: needs a confirmation; cancelling keeps it on.
        int asked = 0;
        bool confirm = false;
        mode->setAsker([&](const QString &, bool password, QString *) {
            ++asked;
            return !password && confirm;
        });
        mode->toggleAction()->trigger();
        QCOMPARE(asked, 1);
        QVERIFY(mode->isActive());
        QVERIFY(mode->toggleAction()->isChecked());
        confirm = true;
        QVERIFY(mode->disable());
        QVERIFY(!window.isReadOnly());
        QVERIFY(!c->session()->isReadOnly() && !second->session()->isReadOnly());
        QVERIFY(label->isHidden());
        QVERIFY(!window.windowTitle().contains(QStringLiteral("Operator mode")));
        // Now the same write does reach the PLC.
        QVERIFY(run(c->session(), &write).ok());
        QCOMPARE(plc.plc.value(addr("R10")), std::optional<std::uint32_t>(1234));
    }

    void passwordProtectsLeaving()
    {
        MainWindow window;
        auto *mode = window.findChild<OperatorMode *>();
        QVERIFY(mode->setPassword(QStringLiteral("s3cret")));
        QVERIFY(mode->hasPassword());
        // Stored salted and hashed, never as typed.
        QVERIFY(!QSettings().allKeys().isEmpty());
        for (const QString &key : QSettings().allKeys())
            QVERIFY(!QSettings().value(key).toString().contains(QStringLiteral("s3cret")));
        QVERIFY(mode->enable());
        QVERIFY(!mode->setPassword(QString())); // an operator cannot remove it
        QString typed = QStringLiteral("guess");
        mode->setAsker([&](const QString &, bool password, QString *answer) {
            *answer = typed;
            return password;
        });
        QVERIFY(!mode->disable());
        QVERIFY(mode->isActive() && window.isReadOnly());
        typed = QStringLiteral("s3cret");
        QVERIFY(mode->disable());
        QVERIFY(!window.isReadOnly());
    }

    void preferenceSurvivesRestart()
    {
        {
            MainWindow window;
            QVERIFY(window.findChild<OperatorMode *>()->enable());
        }
        MainWindow again;
        QVERIFY(again.isReadOnly());
        QVERIFY(again.connections()->isReadOnly());
        // A damaged value reads as on, never as off.
        QSettings().setValue(QStringLiteral("operatorMode/enabled"), QStringLiteral("garbage"));
        MainWindow damaged;
        QVERIFY(damaged.isReadOnly());
    }

    void startOptionLocksTheMode()
    {
        MainWindow window(true);
        auto *mode = window.findChild<OperatorMode *>();
        QVERIFY(mode->isActive() && mode->isLocked());
        int asked = 0;
        mode->setAsker([&](const QString &, bool, QString *) { return ++asked > 0; });
        QVERIFY(!mode->disable());
        mode->toggleAction()->trigger();
        QCOMPARE(asked, 0);
        QVERIFY(window.isReadOnly() && mode->toggleAction()->isChecked());
        // The start option is not a preference: the next start without it is not read-only.
        QVERIFY(!QSettings().contains(QStringLiteral("operatorMode/enabled")));
    }
};

QTEST_MAIN(TestUiOperatorMode)
#include "tst_ui_operatormode.moc"
