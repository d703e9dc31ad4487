// A direct link (SessionLink) end to end against the simulator over loopback TCP: items in, item
// values out (elements joined by the ItemAssembler), one write call whose outcome is the PLC's,
// operator mode refused in core, and the link's state when the PLC goes away.
#include "core/link/sessionlink.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "latestvalues.h"
#include "testutil.h"

#include <QSignalSpy>
#include <QTest>

#include <bit>
#include <optional>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int timeoutMs = 10000;

WatchItemSpec spec(const char *address, DisplayFormat format)
{
    WatchItemSpec item;
    item.address = addr(address);
    item.format = format;
    return item;
}

} // namespace

class TestLink : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }
    void itemsInValuesOutWritesOnTheWire();
};

void TestLink::itemsInValuesOutWritesOnTheWire()
{
    SimulatedPlc plc(ModelProfile::fbs());
    SimServer server(&plc);
    server.setVerbose(true); // a write is done when the simulator logged it
    QStringList simLog;
    connect(&server, &SimServer::logLine, this, [&simLog](const QString &l) { simLog << l; });
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));
    const auto writes = [&simLog] {
        return simLog.filter(QStringLiteral(" write ")).size();
    };
    QVERIFY(plc.setValue(addr("R100"), std::bit_cast<std::uint32_t>(12.5f) & 0xFFFFu));
    QVERIFY(plc.setValue(addr("R101"), std::bit_cast<std::uint32_t>(12.5f) >> 16));
    QVERIFY(plc.setValue(addr("R200"), 42));
    QVERIFY(plc.setValue(addr("Y3"), 1));

    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
    settings.timeoutMs = 500;
    SessionLink link(settings);
    QCOMPARE(link.kind(), PlcLink::Kind::Direct);
    QVERIFY(link.session());
    QVERIFY(link.takesIntervals());
    TestUtil::LatestValues latest;
    connect(&link, &PlcLink::itemValues, this,
            [&latest](const QList<WatchItemValue> &values) { latest.take(values); });
    QSignalSpy states(&link, &PlcLink::linkStateChanged);
    const std::uint64_t flow = WatchedItem::newKey();
    const std::uint64_t setpoint = WatchedItem::newKey();
    const std::uint64_t valve = WatchedItem::newKey();
    link.setItems({{flow, spec("R100", DisplayFormat::Float32), 100},
                   {setpoint, spec("R200", DisplayFormat::Signed), 100},
                   {valve, spec("Y3", DisplayFormat::Bit), 100}});
    link.open();
    QTRY_COMPARE_WITH_TIMEOUT(link.linkState(), LinkState::Connected, timeoutMs);

    // The float's two registers arrive as one item value.
    QTRY_VERIFY_WITH_TIMEOUT(latest.good(flow, std::bit_cast<std::uint32_t>(12.5f)), timeoutMs);
    QCOMPARE(latest.values.value(flow).words.size(), std::size_t(2));
    QTRY_VERIFY_WITH_TIMEOUT(latest.good(setpoint, 42) && latest.good(valve, 1), timeoutMs);

    // A write: done when the simulator logged it and its memory holds it.
    std::optional<LinkWriteResult> result;
    QObject context;
    const int before = static_cast<int>(writes());
    link.write(spec("R100", DisplayFormat::Float32), std::bit_cast<std::uint32_t>(-3.25f), &context,
               [&result](const LinkWriteResult &r) { result = r; });
    QVERIFY(!result); // never inside the call
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), timeoutMs);
    QVERIFY2(result->ok, qPrintable(englishText(result->error)));
    QCOMPARE(static_cast<int>(writes()), before + 1);
    QCOMPARE(plc.value(addr("R101")), std::optional(std::bit_cast<std::uint32_t>(-3.25f) >> 16));
    QTRY_VERIFY_WITH_TIMEOUT(latest.good(flow, std::bit_cast<std::uint32_t>(-3.25f)), timeoutMs);

    // Operator mode: refused in core, nothing on the wire.
    link.setReadOnly(true);
    result.reset();
    link.write(spec("R200", DisplayFormat::Signed), 7, &context,
               [&result](const LinkWriteResult &r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), timeoutMs);
    QVERIFY(!result->ok);
    QCOMPARE(result->error.id, MsgId::SessionReadOnly);
    QCOMPARE(static_cast<int>(writes()), before + 1);
    QCOMPARE(plc.value(addr("R200")), std::optional<std::uint32_t>(42));
    link.setReadOnly(false);

    // The PLC refuses an element it does not have: that item says so, the others stay good.
    const std::uint64_t missing = WatchedItem::newKey();
    link.setItems({{flow, spec("R100", DisplayFormat::Float32), 100},
                   {missing, spec("R5000", DisplayFormat::Signed), 100}});
    QTRY_COMPARE_WITH_TIMEOUT(latest.values.value(missing).quality, ValueQuality::Error, timeoutMs);
    QVERIFY(!latest.values.value(missing).hasValue);
    QTRY_VERIFY_WITH_TIMEOUT(latest.good(flow, std::bit_cast<std::uint32_t>(-3.25f)), timeoutMs);

    // The PLC goes away: the link says so, in its state and in its signal (which arrives queued
    // from the session's thread, after the state can already be read).
    const auto reported = [&states] {
        return states.isEmpty() ? LinkState::Closed : states.last().at(0).value<LinkState>();
    };
    QTRY_COMPARE_WITH_TIMEOUT(reported(), LinkState::Connected, timeoutMs);
    server.close();
    QTRY_VERIFY_WITH_TIMEOUT(link.linkState() != LinkState::Connected, timeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(reported() != LinkState::Connected, timeoutMs);
    link.close(CloseMode::Discard);
    QTRY_COMPARE_WITH_TIMEOUT(link.linkState(), LinkState::Closed, timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(reported(), LinkState::Closed, timeoutMs);
}

QTEST_GUILESS_MAIN(TestLink)
#include "tst_link.moc"
