// The GUI on a connection of kind "MQTT gateway" (issue 20), done as a person does it at a laptop's
// window size: the connection dialog through the menu, a watch table served by the gateway's
// topics on a real mosquitto, a write typed into a cell and confirmed, operator mode. The gateway
// side is a protocol peer (TestUtil::GatewayPeer); what reached it is counted there.
#include "core/link/gatewaywatch.h"
#include "gatewaypeer.h"
#include "mosquittobroker.h"
#include "testutil.h"
#include "ui/connection/connection.h"
#include "ui/connection/connectiondialog.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/mainwindow/operatormode.h"
#include "ui/mainwindow/tooldocks.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"
#include "uitestutil.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include <cstring>
#include <utility>

using namespace Fatek;
using TestUtil::floatBits;
using UiTestUtil::answerModal;

namespace {

constexpr int longWait = 10000;
constexpr int keyDelayMs = 40; // a person typing, quickly

WatchItemSpec item(const char *address, DisplayFormat format)
{
    WatchItemSpec spec;
    spec.address = *Address::parse(address);
    spec.format = format;
    return spec;
}

// The write confirmation (No is the default): Yes, with the mouse.
void answerYes(QWidget *modal)
{
    auto *box = qobject_cast<QMessageBox *>(modal);
    if (!box || !box->button(QMessageBox::Yes)) {
        qWarning("not the write question");
        return;
    }
    QTest::mouseClick(box->button(QMessageBox::Yes), Qt::LeftButton);
}

void typeSlowly(QWidget *widget, const QString &text)
{
    QTest::keyClicks(widget, text, Qt::NoModifier, keyDelayMs);
}

// A broker and a gateway publishing line1: a float over R100 and a signed R200.
struct Gateway
{
    TestUtil::MosquittoBroker broker;
    std::unique_ptr<TestUtil::GatewayPeer> peer;

    bool start(QString *error)
    {
        if (!broker.start(error))
            return false;
        MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(broker.url());
        settings.reconnectMinMs = 50;
        settings.reconnectMaxMs = 200;
        peer = std::make_unique<TestUtil::GatewayPeer>(settings, QStringLiteral("fatek"),
                                                       QStringLiteral("line1"));
        WatchItemSpec tank = item("R100", DisplayFormat::Float32);
        tank.name = QStringLiteral("Tank level");
        peer->setItem(tank, {floatBits(12.5f) & 0xFFFFu, floatBits(12.5f) >> 16});
        peer->setItem(item("R200", DisplayFormat::Signed), {42});
        return peer->open();
    }
};

QAction *menuAction(MainWindow &window, const QString &text)
{
    for (QAction *menu : window.menuBar()->actions()) {
        if (!menu->menu())
            continue;
        for (QAction *action : menu->menu()->actions()) {
            if (action->text() == text)
                return action;
        }
    }
    return nullptr;
}

// In the connection dialog: kind MQTT gateway, the name "Line 1", the broker and the gateway
// connection "line1" typed.
void typeGatewayConnection(QWidget *dialog, const QString &brokerUrl)
{
    auto *kind = dialog->findChild<QComboBox *>(QStringLiteral("linkKindCombo"));
    kind->setFocus();
    kind->setCurrentIndex(kind->findData(ConnectionDialog::gatewayKind));
    auto *name = dialog->findChild<QLineEdit *>(QStringLiteral("connectionNameEdit"));
    name->selectAll();
    typeSlowly(name, QStringLiteral("Line 1"));
    auto *url = dialog->findChild<QLineEdit *>(QStringLiteral("brokerUrlEdit"));
    QVERIFY(url->isVisible());
    typeSlowly(url, brokerUrl);
    typeSlowly(dialog->findChild<QLineEdit *>(QStringLiteral("gatewayNameEdit")),
               QStringLiteral("line1"));
}

// File > New Connection…, kind MQTT gateway, the broker and names typed, Connect.
Connection *connectThroughDialog(MainWindow &window, const QString &brokerUrl)
{
    QAction *newConnection = menuAction(window, QStringLiteral("&New Connection…"));
    if (!newConnection)
        return nullptr;
    answerModal([&] { newConnection->trigger(); },
                [&](QWidget *dialog) {
                    typeGatewayConnection(dialog, brokerUrl);
                    typeSlowly(dialog->findChild<QLineEdit *>(QStringLiteral("brokerUserEdit")),
                               QStringLiteral("viewer"));
                    typeSlowly(dialog->findChild<QLineEdit *>(QStringLiteral("brokerPasswordEdit")),
                               QStringLiteral("s3cret"));
                    QTest::mouseClick(
                        dialog->findChild<QPushButton *>(QStringLiteral("connectButton")),
                        Qt::LeftButton);
                });
    return window.connections()->find(QStringLiteral("Line 1"));
}

// Types `text` into the value cell of `row` with the table's editor and presses Enter; the
// confirmation is answered with `answer`. Returns the question (empty when none came).
QString typeValue(WatchTableWidget *table, int row, const QString &text,
                  const std::function<void(QWidget *)> &answer)
{
    QTableView *view = table->view();
    view->setFocus();
    view->setCurrentIndex(
        table->viewIndex(table->model()->index(row, WatchTableModel::ValueColumn)));
    QTest::keyClick(view->viewport(), Qt::Key_F2);
    auto *editor = view->viewport()->findChild<QLineEdit *>();
    if (!editor)
        return QStringLiteral("no editor");
    editor->selectAll();
    typeSlowly(editor, text);
    if (!answer) {
        QTest::keyClick(editor, Qt::Key_Return);
        return {};
    }
    return answerModal([&] { QTest::keyClick(editor, Qt::Key_Return); }, answer);
}

} // namespace

class TestUiGateway : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_gateway"));
    }

    // Recent connections: the gateway part round-trips without its password; older entries
    // (no "gateway" key) still load as PLC links.
    void savedGatewayConnection()
    {
        SavedConnection saved;
        saved.name = QStringLiteral("Line 1");
        saved.station = 3;
        GatewayWatchSettings gateway;
        gateway.broker = *MqttBrokerSettings::fromUrl(QStringLiteral("mqtts://op:pw@broker:8884"));
        gateway.broker.caFile = QStringLiteral("/etc/ssl/plant-ca.crt");
        gateway.prefix = QStringLiteral("plant/fatek");
        gateway.connection = QStringLiteral("line1");
        saved.gateway = gateway;
        const SavedConnection back = LinkSettingsIo::fromMap(LinkSettingsIo::toMap(saved));
        QVERIFY(back.gateway);
        QCOMPARE(back.station, 3);
        QCOMPARE(back.gateway->broker.host, QStringLiteral("broker"));
        QCOMPARE(back.gateway->broker.port, 8884);
        QVERIFY(back.gateway->broker.tls);
        QCOMPARE(back.gateway->broker.username, QStringLiteral("op"));
        QVERIFY(back.gateway->broker.password.isEmpty());
        QCOMPARE(back.gateway->broker.caFile, gateway.broker.caFile);
        QCOMPARE(back.gateway->prefix, gateway.prefix);
        QCOMPARE(back.gateway->connection, gateway.connection);
        QVERIFY(!LinkSettingsIo::toMap(saved)
                     .value(QStringLiteral("gateway"))
                     .toMap()
                     .value(QStringLiteral("broker"))
                     .toString()
                     .contains(QStringLiteral("pw")));

        QVariantMap old = LinkSettingsIo::toMap(saved);
        old.remove(QStringLiteral("gateway"));
        QVERIFY(!LinkSettingsIo::fromMap(old).gateway);
        QCOMPARE(LinkSettingsIo::fromMap(old).name, QStringLiteral("Line 1"));
    }

    void watchAndWriteThroughTheGateway()
    {
        Gateway gateway;
        QString error;
        QVERIFY2(gateway.start(&error), qPrintable(error));
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        Connection *c = connectThroughDialog(window, gateway.broker.url());
        QVERIFY(c);
        QVERIFY(c->isGateway());
        QVERIFY(!c->session());
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        auto *status = window.findChild<QLabel *>(QStringLiteral("linkStatus"));
        QVERIFY(status);
        QTRY_VERIFY2_WITH_TIMEOUT(status->text().contains(QStringLiteral("Line 1: connected")),
                                  qPrintable(status->text()), longWait);
        // Remembered without its password.
        const QList<SavedConnection> recent = window.connections()->recent();
        QVERIFY(!recent.isEmpty() && recent.first().gateway);
        QCOMPARE(recent.first().gateway->connection, QStringLiteral("line1"));
        QCOMPARE(recent.first().gateway->broker.username, QStringLiteral("viewer"));
        QVERIFY(recent.first().gateway->broker.password.isEmpty());

        // The table shows the gateway's values, quality-marked.
        WatchTableWidget *table = window.currentWatchTable();
        QCOMPARE(table->connection(), c);
        // The gateway's configuration sets the poll interval: the table's control is off.
        auto *interval = table->findChild<QSpinBox *>(QStringLiteral("intervalSpin"));
        QVERIFY(interval && interval->isVisible());
        QVERIFY(!interval->isEnabled());
        QVERIFY2(interval->toolTip().contains(QStringLiteral("gateway")),
                 qPrintable(interval->toolTip()));
        typeSlowly(table->addressEdit(), QStringLiteral("R100 R200 R500"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        WatchTableModel *model = table->model();
        QCOMPARE(model->rowCount(), 3);
        QVERIFY(model->setFormat(0, DisplayFormat::Float32, false).ok());
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(0), QStringLiteral("12.5"), longWait);
        QCOMPARE(model->quality(0), ValueQuality::Good);
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(1), QStringLiteral("42"), longWait);
        // The names of the gateway's watch list fill the rows that have none.
        const QModelIndex tankName = model->index(0, WatchTableModel::NameColumn);
        QCOMPARE(model->data(tankName).toString(), QStringLiteral("Tank level"));
        QVERIFY(model->data(tankName, Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("gateway's name")));
        QVERIFY(model->data(model->index(1, WatchTableModel::NameColumn)).toString().isEmpty());
        // The tooltip, not the quality: a row nothing was reported for yet may read as Error.
        QTRY_VERIFY_WITH_TIMEOUT(
            model->data(model->index(2, WatchTableModel::QualityColumn), Qt::ToolTipRole)
                .toString()
                .contains(QStringLiteral("not published by the gateway line1")),
            longWait);
        QCOMPARE(model->quality(2), ValueQuality::Error);
        const QString notPublished
            = model->data(model->index(2, WatchTableModel::QualityColumn), Qt::ToolTipRole)
                  .toString();
        QVERIFY2(notPublished.contains(QStringLiteral("not published by the gateway line1")),
                 qPrintable(notPublished));

        // Live: the gateway publishes a new value.
        gateway.peer->setItem(item("R200", DisplayFormat::Signed), {43});
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(1), QStringLiteral("43"), longWait);

        // A write typed into the cell, confirmed: it reaches the gateway, whose reply shows.
        const QString question = typeValue(table, 1, QStringLiteral("77"), answerYes);
        QVERIFY2(question.contains(QStringLiteral("R200")), qPrintable(question));
        QTRY_COMPARE_WITH_TIMEOUT(gateway.peer->setCount(), 1, longWait);
        // The typed value itself, not its text.
        QCOMPARE(gateway.peer->commands().constFirst().words,
                 std::optional(std::vector<std::uint32_t>{77}));
        QTRY_VERIFY2_WITH_TIMEOUT(table->message().contains(QStringLiteral("Wrote R200")),
                                  qPrintable(table->message()), longWait);
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(1), QStringLiteral("77"), longWait);

        // The gateway's refusal is shown as such.
        gateway.peer->setRefusal(Message::text("PLC answered error 2"));
        typeValue(table, 1, QStringLiteral("78"), answerYes);
        QTRY_VERIFY2_WITH_TIMEOUT(table->message().contains(QStringLiteral("PLC answered error 2")),
                                  qPrintable(table->message()), longWait);
        QCOMPARE(gateway.peer->setCount(), 2);
        QCOMPARE(model->valueText(1), QStringLiteral("77"));

        // Tools that need the PLC's own link are greyed out with the reason, and do not crash.
        QWidget *control = window.openTool(QStringLiteral("control"));
        QVERIFY(control);
        auto *dock = window.findChild<QDockWidget *>(QStringLiteral("plcControlDock"));
        QVERIFY(!dock->widget()->isEnabled());
        QCOMPARE(dock->widget()->toolTip(), ToolDocks::gatewayNotice());
        QVERIFY(!window.findChild<QAction *>(QStringLiteral("memorySnapshotAction"))->isEnabled());
        QVERIFY(!window.findChild<QAction *>(QStringLiteral("scanStationsAction"))->isEnabled());
        QVERIFY(!window.openTool(QStringLiteral("snapshot")));

        // The gateway goes offline: every value turns stale, the status bar says why.
        gateway.peer->setStatus(GatewayPayload::LinkStatus::Offline);
        QTRY_COMPARE_WITH_TIMEOUT(model->quality(1), ValueQuality::Stale, longWait);
        QCOMPARE(model->quality(0), ValueQuality::Stale);
        QTRY_VERIFY2_WITH_TIMEOUT(status->toolTip().contains(QStringLiteral("line1 is offline")),
                                  qPrintable(status->toolTip()), longWait);
    }

    // Issue 33: a broker that wants a client certificate. The dialog takes the CA, the
    // certificate and the key (a certificate without its key is refused in the dialog), the
    // values come, and the recent connection keeps the three paths.
    void clientCertificateThroughTheDialog()
    {
#ifdef Q_OS_WIN
        QSKIP("the Windows build's MQTT library has no TLS (docs/windows.md)");
#else
        TestUtil::MosquittoBroker broker;
        QString error;
        QVERIFY2(broker.startWithTls(&error), qPrintable(error + broker.log()));
        const QDir dir(broker.directory());
        const QString url = QStringLiteral("mqtts://127.0.0.1:%1").arg(broker.port());
        MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(url);
        settings.caFile = dir.filePath(QStringLiteral("ca.crt"));
        settings.certFile = dir.filePath(QStringLiteral("client.crt"));
        settings.keyFile = dir.filePath(QStringLiteral("client.key"));
        settings.reconnectMinMs = 50;
        settings.reconnectMaxMs = 200;
        TestUtil::GatewayPeer peer(settings, QStringLiteral("fatek"), QStringLiteral("line1"));
        peer.setItem(item("R200", DisplayFormat::Signed), {42});
        QVERIFY(peer.open());
        QTRY_VERIFY_WITH_TIMEOUT(peer.isConnected(), longWait);

        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QAction *newConnection = menuAction(window, QStringLiteral("&New Connection…"));
        QVERIFY(newConnection);
        QString refusal;
        answerModal(
            [&] { newConnection->trigger(); },
            [&](QWidget *dialog) {
                typeGatewayConnection(dialog, url);
                const std::pair<const char *, QString> files[]
                    = {{"brokerCaEdit", settings.caFile}, {"brokerCertEdit", settings.certFile}};
                for (const auto &[field, path] : files) {
                    auto *edit = dialog->findChild<QLineEdit *>(QLatin1String(field));
                    QVERIFY(edit && edit->isVisible());
                    typeSlowly(edit, path);
                }
                auto *connect = dialog->findChild<QPushButton *>(QStringLiteral("connectButton"));
                QTest::mouseClick(connect, Qt::LeftButton);
                // Still open, saying what is missing.
                auto *problem = dialog->findChild<QLabel *>(QStringLiteral("connectionErrorLabel"));
                QVERIFY(dialog->isVisible() && problem && problem->isVisible());
                refusal = problem->text();
                auto *key = dialog->findChild<QLineEdit *>(QStringLiteral("brokerKeyEdit"));
                QVERIFY(key && key->isVisible());
                typeSlowly(key, settings.keyFile);
                QTest::mouseClick(connect, Qt::LeftButton);
            });
        QVERIFY2(refusal.contains(QStringLiteral("key")), qPrintable(refusal));
        Connection *c = window.connections()->find(QStringLiteral("Line 1"));
        QVERIFY(c);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        typeSlowly(table->addressEdit(), QStringLiteral("R200"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(table->model()->valueText(0), QStringLiteral("42"), longWait);

        const QList<SavedConnection> recent = window.connections()->recent();
        QVERIFY(!recent.isEmpty() && recent.first().gateway);
        QCOMPARE(recent.first().gateway->broker.certFile, settings.certFile);
        QCOMPARE(recent.first().gateway->broker.keyFile, settings.keyFile);
        QCOMPARE(recent.first().gateway->broker.caFile, settings.caFile);
#endif
    }

    void operatorModeWritesNothing()
    {
        Gateway gateway;
        QString error;
        QVERIFY2(gateway.start(&error), qPrintable(error));
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        Connection *c = connectThroughDialog(window, gateway.broker.url());
        QVERIFY(c);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        auto *mode = window.findChild<OperatorMode *>();
        QVERIFY(mode);
        mode->toggleAction()->trigger();
        QVERIFY(mode->isActive());
        QVERIFY(c->isReadOnly());

        WatchTableWidget *table = window.currentWatchTable();
        typeSlowly(table->addressEdit(), QStringLiteral("R200"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(table->model()->valueText(0), QStringLiteral("42"), longWait);
        // No question in operator mode: the refusal comes at once, from core.
        typeValue(table, 0, QStringLiteral("5"), {});
        QTRY_VERIFY2_WITH_TIMEOUT(table->message().contains(QStringLiteral("Read-only mode")),
                                  qPrintable(table->message()), longWait);
        // A write after operator mode ends goes through: the refused one would have come first.
        answerModal([&] { mode->toggleAction()->trigger(); }, answerYes);
        QVERIFY(!c->isReadOnly());
        typeValue(table, 0, QStringLiteral("6"), answerYes);
        QTRY_COMPARE_WITH_TIMEOUT(gateway.peer->setCount(), 1, longWait);
        QCOMPARE(gateway.peer->commands().constFirst().words,
                 std::optional(std::vector<std::uint32_t>{6}));
    }
};

QTEST_MAIN(TestUiGateway)
#include "tst_ui_gateway.moc"
