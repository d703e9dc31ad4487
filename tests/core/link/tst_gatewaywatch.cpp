// A gateway connection watched through a real mosquitto (GatewayWatch): item values straight from
// the gateway's item payloads, quality when the gateway or the broker goes away, writes through
// /set and /reply. The gateway side is a protocol peer (TestUtil::GatewayPeer) on the same broker.
#include "core/link/gatewaywatch.h"
#include "core/mqtt/mqttmessages.h"
#include "core/session/session.h"
#include "gatewaypeer.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QSignalSpy>
#include <QTest>

#include <cstring>
#include <optional>

using namespace Fatek;
using TestUtil::addr;
using TestUtil::floatBits;
using LinkStatus = GatewayPayload::LinkStatus;

namespace {

const QString prefix = QStringLiteral("plant/fatek");
const QString line = QStringLiteral("line1");
constexpr int timeoutMs = 10000;

WatchItemSpec item(const char *address, DisplayFormat format, quint8 station = 1)
{
    WatchItemSpec spec;
    spec.address = addr(address);
    spec.format = format;
    spec.station = station;
    return spec;
}

WatchedItem watched(std::uint64_t key, const char *address, quint8 station = 1,
                    DisplayFormat format = DisplayFormat::Signed)
{
    return {key, item(address, format, station), 500};
}
WatchedItem watched(std::uint64_t key, const char *address, DisplayFormat format)
{
    return watched(key, address, 1, format);
}

// A write's outcome, once it came.
struct Outcome
{
    std::optional<LinkWriteResult> result;
    PlcLink::WriteCompletion completion()
    {
        return [this](const LinkWriteResult &r) {
            result = r;
        };
    }
};

MqttBrokerSettings settingsFor(const TestUtil::MosquittoBroker &broker)
{
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(broker.url());
    settings.reconnectMinMs = 50;
    settings.reconnectMaxMs = 200;
    return settings;
}

// The latest value of every item, as a table keeps them.
struct Values
{
    QHash<std::uint64_t, WatchItemValue> last;
    int batches = 0;

    void connect(GatewayWatch *watch)
    {
        QObject::connect(watch, &PlcLink::itemValues, [this](const QList<WatchItemValue> &values) {
            ++batches;
            for (const WatchItemValue &v : values)
                last.insert(v.key, v);
        });
    }
    // An item not reported yet has no quality (a default value would read as Error and let a
    // wait for Error pass at once).
    std::optional<ValueQuality> quality(std::uint64_t id) const
    {
        if (!last.contains(id))
            return std::nullopt;
        return last.value(id).quality;
    }
    std::uint64_t value(std::uint64_t id) const { return last.value(id).raw; }
    QString error(std::uint64_t id) const { return englishText(last.value(id).error); }
    // "3: good 7; 5: error R500 ..." for failure messages.
    QString describe() const
    {
        QStringList parts;
        for (auto it = last.cbegin(); it != last.cend(); ++it)
            parts << QStringLiteral("%1: %2 %3 %4")
                         .arg(it.key())
                         .arg(GatewayPayload::qualityName(it->quality))
                         .arg(it->raw)
                         .arg(englishText(it->error));
        return parts.join(QStringLiteral("; "));
    }
};

// A broker, a gateway peer publishing a float over R100 and a signed R200 at station 1 and a bit
// Y0 at station 2, and a watch on them.
struct Fixture
{
    TestUtil::MosquittoBroker broker;
    std::unique_ptr<TestUtil::GatewayPeer> peer;
    std::unique_ptr<GatewayWatch> watch;
    Values values;

    bool start(QString *error)
    {
        if (!broker.start(error))
            return false;
        peer = std::make_unique<TestUtil::GatewayPeer>(settingsFor(broker), prefix, line);
        peer->setItem(item("R100", DisplayFormat::Float32),
                      {floatBits(12.5f) & 0xFFFFu, floatBits(12.5f) >> 16});
        peer->setItem(item("R200", DisplayFormat::Signed), {42});
        peer->setItem(item("Y0", DisplayFormat::Bit, 2), {1});
        if (!peer->open()) {
            *error = QStringLiteral("peer does not open");
            return false;
        }
        GatewayWatchSettings settings;
        settings.broker = settingsFor(broker);
        settings.prefix = prefix;
        settings.connection = line;
        watch = std::make_unique<GatewayWatch>(settings);
        watch->setPublishedGraceMs(300);
        values.connect(watch.get());
        return true;
    }
};

} // namespace

class TestGatewayWatch : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }
    void settingsValidate();
    void coveredElementsAndUnpublished();
    void staleWhileGatewayOfflineOrDown();
    void staleOnBrokerLossThenGoodAgain();
    void writeRoundTrip();
    void writeRefusedByGateway();
    void writeTimesOut();
    void readOnlyPublishesNothing();
};

void TestGatewayWatch::settingsValidate()
{
    GatewayWatchSettings settings;
    settings.connection = QStringLiteral("line1");
    QVERIFY(settings.validate().empty());
    settings.prefix = QStringLiteral("fatek/#");
    QCOMPARE(englishText(settings.validate()),
             QStringLiteral("\"fatek/#\" is not a topic prefix: levels separated by /, without + "
                            "or #."));
    settings.prefix = QStringLiteral("fatek");
    settings.connection = QStringLiteral("12");
    QVERIFY(englishText(settings.validate()).startsWith(QStringLiteral("\"12\" is not a gateway")));
}

void TestGatewayWatch::coveredElementsAndUnpublished()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    QSignalSpy states(f.watch.get(), &GatewayWatch::linkStateChanged);
    f.watch->setItems({watched(1, "R100", DisplayFormat::Float32), watched(2, "R101"),
                       watched(3, "R200"), watched(4, "Y0", 2, DisplayFormat::Bit),
                       watched(5, "R500"), watched(6, "Y0", 1, DisplayFormat::Bit),
                       watched(7, "R100", DisplayFormat::Double64), watched(8, "R100")});
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Connected, timeoutMs);
    QCOMPARE(f.watch->peerText(), QStringLiteral("TCP 127.0.0.1:500, FACON"));
    // The float's payload as it is: its two words joined, R100 the low word.
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(1), std::optional(ValueQuality::Good), timeoutMs);
    QCOMPARE(f.values.value(1), std::uint64_t(floatBits(12.5f)));
    QCOMPARE(f.values.last.value(1).words,
             (std::vector<std::uint32_t>{floatBits(12.5f) & 0xFFFFu, floatBits(12.5f) >> 16}));
    QVERIFY(f.values.last.value(1).hasValue);
    QVERIFY(f.values.last.value(1).time.isValid());
    QTRY_COMPARE_WITH_TIMEOUT(f.values.value(3), 42u, timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(4), std::optional(ValueQuality::Good), timeoutMs);
    QCOMPARE(f.values.value(4), 1u);
    // The same address in a format over fewer elements takes the first of them.
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(8), std::optional(ValueQuality::Good), timeoutMs);
    QCOMPARE(f.values.value(8), std::uint64_t(floatBits(12.5f) & 0xFFFFu));
    // Not published (another address, or the same one at another station): an error that says so.
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(5), std::optional(ValueQuality::Error), timeoutMs);
    QCOMPARE(f.values.error(5),
             QStringLiteral("R500 (station 1) is not published by the gateway line1."));
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(6), std::optional(ValueQuality::Error), timeoutMs);
    // R101 is the float's high word, but the gateway publishes no item there.
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(2), std::optional(ValueQuality::Error), timeoutMs);
    QCOMPARE(f.values.error(2),
             QStringLiteral("R101 (station 1) is not published by the gateway line1."));
    // A double over R100 needs R102 and R103, which the float's payload does not carry.
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(7), std::optional(ValueQuality::Error), timeoutMs);
    QCOMPARE(f.values.error(7),
             QStringLiteral("R102 (station 1) is not published by the gateway line1."));
    QVERIFY(!f.values.last.value(7).hasValue);

    // A new value of one item reports that item, not the whole list.
    const int before = f.values.batches;
    f.values.last.clear();
    f.peer->setItem(item("R200", DisplayFormat::Signed), {7});
    QTRY_COMPARE_WITH_TIMEOUT(f.values.value(3), 7u, timeoutMs);
    QVERIFY2(f.values.last.size() == 1, qPrintable(f.values.describe()));
    QVERIFY(f.values.batches > before);

    // The gateway's own quality and error pass through (its PLC refused the element).
    f.peer->setItem(item("R200", DisplayFormat::Signed), {7}, ValueQuality::Error,
                    Message::text("PLC error 2"));
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Error), timeoutMs);
    QCOMPARE(f.values.error(3), QStringLiteral("PLC error 2"));

    // An item the gateway never read (no words): stale with the gateway's reason, no value, and
    // not "not published".
    f.peer->setItem(item("R200", DisplayFormat::Signed), {}, ValueQuality::Stale,
                    Message::text("link down"));
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Stale), timeoutMs);
    QVERIFY(!f.values.last.value(3).hasValue);
    QCOMPARE(f.values.error(3), QStringLiteral("link down"));
}

void TestGatewayWatch::staleWhileGatewayOfflineOrDown()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    f.watch->setItems({watched(1, "R100", DisplayFormat::Float32), watched(3, "R200")});
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Good), timeoutMs);

    // The gateway lost its PLC: the last value stays, marked stale with the gateway's reason.
    f.peer->setStatus(LinkStatus::Down, Message::text("connection refused"));
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Stale), timeoutMs);
    QCOMPARE(f.values.value(3), 42u);
    QCOMPARE(f.values.error(3),
             QStringLiteral("The gateway line1 lost its link to the PLC: connection refused"));
    QCOMPARE(f.watch->linkState(), LinkState::Lost);
    QCOMPARE(f.values.quality(1), std::optional(ValueQuality::Stale));

    f.peer->setStatus(LinkStatus::Up);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Good), timeoutMs);
    QCOMPARE(f.watch->linkState(), LinkState::Connected);

    // The gateway stopped (its will says the same when it dies): no value looks fresh.
    f.peer->setStatus(LinkStatus::Offline);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Stale), timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.error(3), QStringLiteral("The gateway line1 is offline."),
                              timeoutMs);
    QCOMPARE(f.values.quality(1), std::optional(ValueQuality::Stale));
}

void TestGatewayWatch::staleOnBrokerLossThenGoodAgain()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    f.watch->setItems(
        {watched(1, "R100", DisplayFormat::Float32), watched(3, "R200"), watched(5, "R500")});
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Good), timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(5), std::optional(ValueQuality::Error), timeoutMs);

    f.broker.kill();
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Lost, timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Stale), timeoutMs);
    QCOMPARE(f.values.value(3), 42u);
    // The broker is named as the cause: the loss itself, or (on a slower machine, under Wine) the
    // first reconnect attempt that already failed.
    QVERIFY2(f.values.error(3).startsWith(QStringLiteral("Link to the broker"))
                 || f.values.error(3).startsWith(QStringLiteral("Cannot reach the broker")),
             qPrintable(f.values.error(3)));
    QCOMPARE(f.values.quality(1), std::optional(ValueQuality::Stale));
    QCOMPARE(f.values.quality(5), std::optional(ValueQuality::Stale));

    // The broker comes back empty (no persistence); the gateway publishes everything again.
    QVERIFY2(f.broker.start(&error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Connected, timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(3), std::optional(ValueQuality::Good), timeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(1), std::optional(ValueQuality::Good), timeoutMs);
    QCOMPARE(f.values.value(3), 42u);
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(5), std::optional(ValueQuality::Error), timeoutMs);
}

void TestGatewayWatch::writeRoundTrip()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    f.watch->setItems({watched(1, "R100", DisplayFormat::Float32)});
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.values.quality(1), std::optional(ValueQuality::Good), timeoutMs);

    QObject context;
    Outcome outcome;
    f.watch->write(item("R100", DisplayFormat::Float32), floatBits(-3.25f), &context,
                   outcome.completion());
    QCOMPARE(f.watch->unansweredWrites(), 1);
    QVERIFY(!outcome.result); // never inside the call
    QTRY_VERIFY_WITH_TIMEOUT(outcome.result.has_value(), timeoutMs);
    QVERIFY2(outcome.result->ok, qPrintable(englishText(outcome.result->error)));
    QCOMPARE(f.watch->unansweredWrites(), 0);
    QCOMPARE(f.peer->setCount(), 1);
    // The typed value travels as it is: the float's raw words and its format, no text.
    const GatewayPayload::SetCommand command = f.peer->commands().constFirst();
    QVERIFY(command.words.has_value());
    QCOMPARE(*command.words,
             (std::vector<std::uint32_t>{floatBits(-3.25f) & 0xFFFFu, floatBits(-3.25f) >> 16}));
    QVERIFY(command.value.isEmpty());
    QVERIFY(command.format == DisplayFormat::Float32);
    QVERIFY(!command.id.isEmpty());
    // The gateway's next publication carries the new value.
    QTRY_COMPARE_WITH_TIMEOUT(f.values.value(1), std::uint64_t(floatBits(-3.25f)), timeoutMs);
}

void TestGatewayWatch::writeRefusedByGateway()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Connected, timeoutMs);
    f.peer->setRefusal(msg<MsgId::GatewaySetBadFormat>("weird"));
    Outcome reply;
    f.watch->write(item("R200", DisplayFormat::Signed), 5, nullptr, reply.completion());
    QTRY_VERIFY_WITH_TIMEOUT(reply.result.has_value(), timeoutMs);
    QVERIFY(!reply.result->ok);
    // The gateway's message, with its id: shown in the reader's language.
    QCOMPARE(reply.result->error.id, MsgId::GatewaySetBadFormat);
    QCOMPARE(englishText(reply.result->error), QStringLiteral("\"weird\" is not a value format."));
    QCOMPARE(f.peer->setCount(), 1);
}

void TestGatewayWatch::writeTimesOut()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    f.watch->setReplyTimeoutMs(500);
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Connected, timeoutMs);
    f.peer->setAnswering(false);
    Outcome reply;
    f.watch->write(item("R200", DisplayFormat::Signed), 5, nullptr, reply.completion());
    QTRY_VERIFY_WITH_TIMEOUT(reply.result.has_value(), timeoutMs);
    // Sent and not answered: the gateway may still carry it out, so unknown, not failed, and
    // its final reply is still awaited.
    QVERIFY(!reply.result->ok);
    QCOMPARE(reply.result->outcome, ChangeOutcome::Unknown);
    QVERIFY(!reply.result->final);
    QCOMPARE(englishText(reply.result->error),
             QStringLiteral("No reply from the gateway line1 within 1 s."));
    QTRY_COMPARE_WITH_TIMEOUT(f.peer->setCount(), 1, timeoutMs); // it was sent, nobody answered
    QCOMPARE(f.watch->unansweredWrites(), 1);
    // Closing ends the wait: still unknown, final.
    f.watch->close();
    QTRY_VERIFY_WITH_TIMEOUT(reply.result->final, timeoutMs);
    QCOMPARE(reply.result->outcome, ChangeOutcome::Unknown);
    QVERIFY2(englishText(reply.result->error).startsWith(QStringLiteral("Outcome unknown")),
             qPrintable(englishText(reply.result->error)));
    QCOMPARE(f.watch->unansweredWrites(), 0);
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Connected, timeoutMs);

    // A context destroyed before the reply: the completion is dropped, not called.
    bool called = false;
    {
        QObject context;
        f.watch->write(item("R200", DisplayFormat::Signed), 6, &context,
                       [&](const LinkWriteResult &) { called = true; });
    }
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->unansweredWrites(), 0, timeoutMs);
    QVERIFY(!called);
}

void TestGatewayWatch::readOnlyPublishesNothing()
{
    Fixture f;
    QString error;
    QVERIFY2(f.start(&error), qPrintable(error));
    f.watch->setReadOnly(true);
    f.watch->open();
    QTRY_COMPARE_WITH_TIMEOUT(f.watch->linkState(), LinkState::Connected, timeoutMs);
    Outcome reply;
    f.watch->write(item("R200", DisplayFormat::Signed), 5, nullptr, reply.completion());
    QVERIFY(!reply.result); // never inside the call
    QTRY_VERIFY_WITH_TIMEOUT(reply.result.has_value(), timeoutMs);
    QVERIFY(!reply.result->ok);
    QCOMPARE(reply.result->error.id, MsgId::SessionReadOnly);

    // A write allowed after it goes through, so the peer would have seen the refused one first.
    f.watch->setReadOnly(false);
    reply.result.reset();
    f.watch->write(item("R200", DisplayFormat::Signed), 9, nullptr, reply.completion());
    QTRY_VERIFY_WITH_TIMEOUT(reply.result.has_value(), timeoutMs);
    QVERIFY(reply.result->ok);
    QCOMPARE(f.peer->setCount(), 1);
    QCOMPARE(f.peer->commands().constFirst().words, std::optional(std::vector<std::uint32_t>{9}));
}

QTEST_GUILESS_MAIN(TestGatewayWatch)
#include "tst_gatewaywatch.moc"
