#include "core/planner/pollplanner.h"
#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"
#include "testutil.h"

#include <QTest>

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <set>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    auto a = Address::parse(text);
    if (!a)
        qFatal("bad test address %s", text);
    return *a;
}

std::vector<WatchItem> itemsOf(std::initializer_list<const char *> texts, std::uint8_t station = 1)
{
    std::vector<WatchItem> out;
    std::uint64_t id = 1;
    for (const char *t : texts)
        out.push_back({id++, station, addr(t)});
    return out;
}

Address addressOfSlot(const Request &r, std::uint32_t valueIndex)
{
    return r.command == Command::MixedRead ? r.addresses.at(valueIndex)
                                           : r.start.advanced(valueIndex);
}

// Every step is a valid request, its size is what queryBytes/responseBytes say, every plannable
// item has exactly one slot and that slot points at the item's own element.
void checkPlanConsistent(const Plan &plan, std::span<const WatchItem> items, Protocol protocol)
{
    std::map<std::uint64_t, int> seen;
    std::size_t total = 0;
    std::map<std::uint64_t, WatchItem> byId;
    for (const WatchItem &i : items)
        byId[i.id] = i;
    for (const PlanStep &step : plan.steps) {
        const Status valid = validateRequest(step.request, protocol);
        QVERIFY2(valid.ok(), valid.ok() ? "" : valid.error().text().c_str());
        QCOMPARE(step.wireBytes, PollPlanner::queryBytes(step.request, protocol)
                                     + PollPlanner::responseBytes(step.request, protocol));
        total += step.wireBytes;
        QVERIFY(!step.itemSlots.empty());
        for (const PlanSlot &slot : step.itemSlots) {
            QVERIFY(slot.valueIndex < step.request.expectedValueCount());
            const WatchItem &item = byId.at(slot.itemId);
            QCOMPARE(item.station, step.request.station);
            QCOMPARE(addressOfSlot(step.request, slot.valueIndex), item.address);
            ++seen[slot.itemId];
            // The slot also names the item by its position in the list.
            QVERIFY(slot.itemIndex < items.size());
            QCOMPARE(items[slot.itemIndex].id, slot.itemId);
        }
    }
    QCOMPARE(plan.wireBytes, total);
    for (const UnplannableItem &u : plan.unplannable) {
        QVERIFY(!u.reason.empty());
        QVERIFY(u.itemIndex < items.size());
        QCOMPARE(items[u.itemIndex].id, u.itemId);
        ++seen[u.itemId];
    }
    for (const WatchItem &i : items)
        QCOMPARE(seen[i.id], 1);
}

struct Optimum
{
    std::uint32_t requests = 0;
    std::size_t bytes = 0;
};

// Independent exhaustive optimum: every partition of the distinct elements into requests, each
// block read by the cheapest single valid request that covers exactly its elements (a 44/46 run
// over the block's span, or a 48 list).
Optimum exhaustiveOptimum(std::span<const WatchItem> items, Protocol protocol)
{
    std::vector<StationAddress> distinct;
    for (const WatchItem &i : items)
        distinct.push_back({i.station, i.address});
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const std::size_t n = distinct.size();
    const std::size_t full = (std::size_t{1} << n) - 1;

    std::vector<std::optional<std::size_t>> blockBytes(full + 1);
    for (std::size_t mask = 1; mask <= full; ++mask) {
        std::vector<StationAddress> block;
        for (std::size_t k = 0; k < n; ++k) {
            if (mask & (std::size_t{1} << k))
                block.push_back(distinct[k]);
        }
        std::optional<std::size_t> best;
        auto consider = [&](const Request &r) {
            if (!validateRequest(r, protocol))
                return;
            const std::size_t b
                = PollPlanner::queryBytes(r, protocol) + PollPlanner::responseBytes(r, protocol);
            if (!best || b < *best)
                best = b;
        };
        bool oneStation = true;
        bool oneChain = true;
        for (const StationAddress &e : block) {
            oneStation = oneStation && e.station == block.front().station;
            oneChain = oneChain && e.address.type == block.front().address.type
                       && e.address.number % e.address.info().step
                              == block.front().address.number % block.front().address.info().step;
        }
        if (!oneStation)
            continue;
        std::vector<Address> list;
        for (const StationAddress &e : block)
            list.push_back(e.address);
        consider(Request::mixedRead(block.front().station, list));
        if (oneChain) {
            const Address first = block.front().address;
            const std::uint32_t span
                = (block.back().address.number - first.number) / first.info().step + 1;
            consider(isDiscrete(first.type)
                         ? Request::readDiscretes(block.front().station, first, span)
                         : Request::readRegisters(block.front().station, first, span));
        }
        blockBytes[mask] = best;
    }

    // opt[mask] over sub-blocks containing the lowest element of mask.
    std::vector<std::optional<Optimum>> opt(full + 1);
    opt[0] = Optimum{};
    for (std::size_t mask = 1; mask <= full; ++mask) {
        const std::size_t low = mask & (~mask + 1);
        for (std::size_t sub = mask; sub; sub = (sub - 1) & mask) {
            if (!(sub & low) || !blockBytes[sub] || !opt[mask ^ sub])
                continue;
            const Optimum rest = *opt[mask ^ sub];
            const Optimum cand{rest.requests + 1, rest.bytes + *blockBytes[sub]};
            if (!opt[mask] || cand.requests < opt[mask]->requests
                || (cand.requests == opt[mask]->requests && cand.bytes < opt[mask]->bytes)) {
                opt[mask] = cand;
            }
        }
    }
    return *opt[full];
}

Response zeroAnswer(const Request &r)
{
    Response resp;
    resp.station = r.station;
    resp.command = r.command;
    resp.values.assign(r.expectedValueCount(), 0);
    if (r.command == Command::BriefStatus)
        resp.data = {0, 0, 0};
    return resp;
}

} // namespace

class TestPollPlanner : public QObject
{
    Q_OBJECT

private Q_SLOTS: // QT_NO_KEYWORDS: PlanStep has a member named "slots"
    void sizesMatchVectors_data();
    void sizesMatchVectors();
    void sizesMatchFaconCodec();
    void sizesMatchBinaryCodec();
    void consecutiveRegistersOneRequest();
    void bridgesSmallGapsOnly();
    void limits_data();
    void limits();
    void mixedWidthsAndTypes();
    void severalStations();
    void duplicatesShareOneValue();
    void wordViewAlignment();
    void fileRegistersBinaryOnly();
    void badItemsReported();
    void deterministicOrder();
    void randomSmallListsAreOptimal_data();
    void randomSmallListsAreOptimal();
    void largeListsStayValid();
    void fastSolverMatchesReference();
    void splitIsolatesInLog2Rounds_data();
    void splitIsolatesInLog2Rounds();
    void splitSingleItemGivesNothing();
    void isolatedElementsReadAlone();
};

void TestPollPlanner::sizesMatchVectors_data()
{
    QTest::addColumn<int>("protocol");
    QTest::addColumn<int>("vectorIndex");
    QTest::addColumn<Request>("request");

    // Requests the vectors' queries encode (order as in tests/data/vectors.json).
    const auto b = static_cast<int>(Protocol::Binary);
    const auto f = static_cast<int>(Protocol::Facon);
    QTest::newRow("bin 40") << b << 0 << Request::briefStatus(1);
    QTest::newRow("bin 41 stop") << b << 2 << Request::runStop(1, false);
    QTest::newRow("bin 42") << b << 4
                            << Request::discreteControl(1, DiscreteOp::Disable, addr("X16"));
    QTest::newRow("bin 43") << b << 5 << Request::readEnableFlags(1, addr("Y10"), 7);
    QTest::newRow("bin 44") << b << 7 << Request::readDiscretes(1, addr("X50"), 6);
    QTest::newRow("bin 44 15") << b << 8 << Request::readDiscretes(1, addr("Y0"), 15);
    QTest::newRow("bin 45") << b << 9 << Request::writeDiscretes(1, addr("Y0"), {1, 0, 0, 1});
    QTest::newRow("bin 46") << b << 11 << Request::readRegisters(1, addr("R12"), 3);
    QTest::newRow("bin 47 WY") << b << 13
                               << Request::writeRegisters(1, addr("WY16"), {0xAAAA, 0x5555});
    QTest::newRow("bin 48") << b << 15
                            << Request::mixedRead(1, {addr("R1"), addr("Y9"), addr("DWM0")});
    QTest::newRow("bin 48 DR") << b << 16 << Request::mixedRead(1, {addr("DR15"), addr("D1")});
    QTest::newRow("bin 49") << b << 17
                            << Request::mixedWrite(
                                   1, {addr("Y0"), addr("Y1"), addr("WM8"), addr("DR2")},
                                   {1, 0, 0x5555, 0xFF});
    QTest::newRow("bin 4E") << b << 19 << Request::loopback(1, {'A', 'B', 'C', 'D', 'E', 'F', 'G'});
    QTest::newRow("fa 40") << f << 0 << Request::briefStatus(1);
    QTest::newRow("fa 41") << f << 1 << Request::runStop(1, true);
    QTest::newRow("fa 42") << f << 2
                           << Request::discreteControl(1, DiscreteOp::Disable, addr("X16"));
    QTest::newRow("fa 43") << f << 3 << Request::readEnableFlags(1, addr("Y10"), 7);
    QTest::newRow("fa 44") << f << 4 << Request::readDiscretes(1, addr("X50"), 6);
    QTest::newRow("fa 45") << f << 5 << Request::writeDiscretes(1, addr("Y0"), {1, 0, 0, 1});
    QTest::newRow("fa 46") << f << 6 << Request::readRegisters(1, addr("R12"), 3);
    QTest::newRow("fa 47") << f << 7 << Request::writeRegisters(1, addr("WY8"), {0xAAAA, 0x5555});
    QTest::newRow("fa 48") << f << 8
                           << Request::mixedRead(1, {addr("R1"), addr("Y9"), addr("DWM0")});
    QTest::newRow("fa 49") << f << 9
                           << Request::mixedWrite(
                                  1, {addr("Y0"), addr("Y1"), addr("WM8"), addr("DR2")},
                                  {1, 0, 0x5555, 0xFF});
    QTest::newRow("fa 4E") << f << 10 << Request::loopback(1, {'A', 'B', 'C', 'D', 'E', 'F', 'G'});
}

void TestPollPlanner::sizesMatchVectors()
{
    QFETCH(int, protocol);
    QFETCH(int, vectorIndex);
    QFETCH(Request, request);
    const auto p = static_cast<Protocol>(protocol);
    const auto vectors = TestUtil::loadVectors(p == Protocol::Binary ? "binary" : "facon");
    QVERIFY(vectorIndex < vectors.size());
    const TestUtil::Vector &v = vectors.at(vectorIndex);
    QVERIFY(validateRequest(request, p).ok());
    QCOMPARE(PollPlanner::queryBytes(request, p), v.query.size());
    QCOMPARE(PollPlanner::responseBytes(request, p), v.response.size());
}

namespace {
std::vector<Request> sampleRequests(Protocol p)
{
    std::vector<Request> out = {
        Request::briefStatus(3),
        Request::runStop(1, true),
        Request::discreteControl(7, DiscreteOp::Set, addr("M1234")),
        Request::readEnableFlags(1, addr("S20"), 256),
        Request::readDiscretes(1, addr("T5"), 256),
        Request::readDiscretes(254, addr("C9999"), 1),
        Request::readRegisters(1, addr("R0"), 64),
        Request::readRegisters(1, addr("DR10"), 32),
        Request::readRegisters(1, addr("WX8"), 5),
        Request::readRegisters(1, addr("DWC16"), 3),
        Request::readRegisters(1, addr("RT100"), 7),
        Request::readRegisters(1, addr("DRC10"), 2),
        Request::readRegisters(1, addr("D65535"), 1),
        Request::writeRegisters(1, addr("DD4"), {1, 2, 3}),
        Request::writeDiscretes(1, addr("Y7"), {1, 1, 0}),
        Request::mixedRead(2, {addr("X0"), addr("WY16"), addr("DRT8"), addr("RC3"), addr("DWS0")}),
        Request::mixedWrite(2, {addr("M3"), addr("R9")}, {1, 77}),
        Request::loopback(1, {}),
    };
    if (p == Protocol::Binary) {
        out.push_back(Request::readRegisters(1, addr("F100"), 10));
        out.push_back(Request::mixedRead(1, {addr("DF2"), addr("F7")}));
    }
    return out;
}
} // namespace

void TestPollPlanner::sizesMatchFaconCodec()
{
    const FaconCodec codec;
    for (const Request &r : sampleRequests(Protocol::Facon)) {
        const auto frame = codec.encodeRequest(r);
        QVERIFY2(frame.ok(), frame.ok() ? "" : frame.error().text().c_str());
        QCOMPARE(PollPlanner::queryBytes(r, Protocol::Facon), frame->size());
        QCOMPARE(PollPlanner::responseBytes(r, Protocol::Facon),
                 codec.encodeResponse(r, zeroAnswer(r)).size());
    }
}

void TestPollPlanner::sizesMatchBinaryCodec()
{
    const BinaryCodec codec;
    for (const Request &r : sampleRequests(Protocol::Binary)) {
        const auto frame = codec.encodeRequest(r);
        QVERIFY2(frame.ok(), frame.ok() ? "" : frame.error().text().c_str());
        QCOMPARE(PollPlanner::queryBytes(r, Protocol::Binary), frame->size());
        QCOMPARE(PollPlanner::responseBytes(r, Protocol::Binary),
                 codec.encodeResponse(r, zeroAnswer(r)).size());
    }
}

void TestPollPlanner::consecutiveRegistersOneRequest()
{
    const auto items = itemsOf({"R12", "R13", "R14"});
    const Plan plan = PollPlanner(Protocol::Facon).plan(items);
    checkPlanConsistent(plan, items, Protocol::Facon);
    QCOMPARE(plan.requestCount(), std::size_t{1});
    QCOMPARE(plan.steps[0].request, Request::readRegisters(1, addr("R12"), 3));
    // The vector frames: 16 + 21 bytes.
    QCOMPARE(plan.wireBytes, std::size_t{16 + 21});
}

void TestPollPlanner::bridgesSmallGapsOnly()
{
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        // Small gap: one run R0..R5 (reading R2..R4 costs less than a 48 address list).
        auto items = itemsOf({"R0", "R1", "R5"});
        Plan plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(exhaustiveOptimum(items, p).bytes, plan.wireBytes);

        // Large gap: one request still (48), not a 61-register run.
        items = itemsOf({"R0", "R60"});
        plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(plan.steps[0].request.command, Command::MixedRead);
        QCOMPARE(exhaustiveOptimum(items, p).bytes, plan.wireBytes);

        // Discretes: 1 byte per point, so bridging 30 points beats two more addresses.
        items = itemsOf({"X0", "X30", "R7"});
        plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(exhaustiveOptimum(items, p).bytes, plan.wireBytes);
    }
}

void TestPollPlanner::limits_data()
{
    QTest::addColumn<QString>("symbol");
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("step");
    QTest::addColumn<int>("requests");
    QTest::newRow("256 discretes") << "X" << 256 << 1 << 1;
    QTest::newRow("257 discretes") << "X" << 257 << 1 << 2;
    QTest::newRow("64 R") << "R" << 64 << 1 << 1;
    QTest::newRow("65 R") << "R" << 65 << 1 << 2;
    QTest::newRow("32 DR") << "DR" << 32 << 2 << 1;
    QTest::newRow("33 DR") << "DR" << 33 << 2 << 2;
    QTest::newRow("64 WM") << "WM" << 64 << 16 << 1;
    QTest::newRow("65 WM") << "WM" << 65 << 16 << 2;
    QTest::newRow("600 M") << "M" << 600 << 1 << 3;
    QTest::newRow("200 R") << "R" << 200 << 1 << 4;
}

void TestPollPlanner::limits()
{
    QFETCH(QString, symbol);
    QFETCH(int, count);
    QFETCH(int, step);
    QFETCH(int, requests);
    const auto type = elementTypeFromSymbol(symbol.toStdString());
    QVERIFY(type);
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        std::vector<WatchItem> items;
        for (int k = 0; k < count; ++k)
            items.push_back({static_cast<std::uint64_t>(k), 1,
                             Address{*type, static_cast<std::uint32_t>(k * step)}});
        const Plan plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), static_cast<std::size_t>(requests));
        // Dense lists are read as runs, never as address lists.
        for (const PlanStep &s : plan.steps)
            QVERIFY(s.request.command != Command::MixedRead);
    }
}

void TestPollPlanner::mixedWidthsAndTypes()
{
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        // 40 scattered DR (80 words) + 10 scattered R: 90 words -> 2 mixed reads.
        std::vector<WatchItem> items;
        std::uint64_t id = 1;
        for (std::uint32_t k = 0; k < 40; ++k)
            items.push_back({id++, 1, Address{ElementType::DR, 1000 + k * 200}});
        for (std::uint32_t k = 0; k < 10; ++k)
            items.push_back({id++, 1, Address{ElementType::R, 30000 + k * 500}});
        Plan plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{2});

        // The vector's mix: R1, Y9, DWM0 -> one 48.
        items = itemsOf({"R1", "Y9", "DWM0"});
        plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(plan.steps[0].request,
                 Request::mixedRead(1, {addr("Y9"), addr("R1"), addr("DWM0")}));

        // 100 consecutive M + 20 scattered R: the M run (more than 64 points) is one 44 and the
        // registers one 48: 2 requests, where a pure 48 packing needs 2 as well but far more bytes.
        items.clear();
        for (std::uint32_t k = 0; k < 100; ++k)
            items.push_back({id++, 1, Address{ElementType::M, k}});
        for (std::uint32_t k = 0; k < 20; ++k)
            items.push_back({id++, 1, Address{ElementType::R, k * 100}});
        plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{2});
        QCOMPARE(plan.steps[0].request, Request::readDiscretes(1, addr("M0"), 100));
        QCOMPARE(plan.steps[1].request.command, Command::MixedRead);
    }
}

void TestPollPlanner::severalStations()
{
    std::vector<WatchItem> items = {
        {1, 2, addr("R0")}, {2, 1, addr("R0")}, {3, 2, addr("R1")},
        {4, 1, addr("R1")}, {5, 3, addr("Y0")},
    };
    const Plan plan = PollPlanner(Protocol::Binary).plan(items);
    checkPlanConsistent(plan, items, Protocol::Binary);
    QCOMPARE(plan.requestCount(), std::size_t{3});
    QCOMPARE(plan.steps[0].request, Request::readRegisters(1, addr("R0"), 2));
    QCOMPARE(plan.steps[1].request, Request::readRegisters(2, addr("R0"), 2));
    QCOMPARE(plan.steps[2].request, Request::readDiscretes(3, addr("Y0"), 1));
}

void TestPollPlanner::duplicatesShareOneValue()
{
    std::vector<WatchItem> items = {{10, 1, addr("R5")}, {11, 1, addr("R5")}, {12, 1, addr("R6")}};
    const Plan plan = PollPlanner(Protocol::Facon).plan(items);
    checkPlanConsistent(plan, items, Protocol::Facon);
    QCOMPARE(plan.requestCount(), std::size_t{1});
    QCOMPARE(plan.steps[0].request, Request::readRegisters(1, addr("R5"), 2));
    QCOMPARE(plan.steps[0].itemSlots.size(), std::size_t{3});
}

void TestPollPlanner::wordViewAlignment()
{
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        // WY0 and WY16 are consecutive W elements: one 46 run of 2.
        auto items = itemsOf({"WY0", "WY16"});
        Plan plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(plan.steps[0].request, Request::readRegisters(1, addr("WY0"), 2));

        // WY0 and WY8 overlap and are not one run apart: a 48 list.
        items = itemsOf({"WY0", "WY8", "DWX8", "DWX40"});
        plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(plan.wireBytes, exhaustiveOptimum(items, p).bytes);

        // DR1 is not in the run DR0, DR2.
        items = itemsOf({"DR0", "DR1", "DR2", "DR4"});
        plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        QCOMPARE(plan.wireBytes, exhaustiveOptimum(items, p).bytes);
    }
}

void TestPollPlanner::fileRegistersBinaryOnly()
{
    const std::vector<WatchItem> items
        = {{1, 1, addr("F10")}, {2, 1, addr("DF4")}, {3, 1, addr("R0")}};
    const Plan binary = PollPlanner(Protocol::Binary).plan(items);
    checkPlanConsistent(binary, items, Protocol::Binary);
    QVERIFY(binary.unplannable.empty());
    QCOMPARE(binary.requestCount(), std::size_t{1});

    const Plan facon = PollPlanner(Protocol::Facon).plan(items);
    checkPlanConsistent(facon, items, Protocol::Facon);
    QCOMPARE(facon.requestCount(), std::size_t{1});
    QCOMPARE(facon.unplannable.size(), std::size_t{2});
    QCOMPARE(facon.unplannable[0].itemId, std::uint64_t{1});
    QVERIFY(QString::fromStdString(english(facon.unplannable[0].reason)).contains("FACON"));
    QCOMPARE(facon.unplannable[1].itemId, std::uint64_t{2});
}

void TestPollPlanner::badItemsReported()
{
    const std::vector<WatchItem> items = {
        {1, 0, addr("R0")},                     // broadcast: nobody answers
        {2, 255, addr("R0")},                   // no such station
        {3, 1, Address{ElementType::X, 10000}}, // out of range
        {4, 1, Address{ElementType::WY, 4}},    // misaligned W view
        {5, 1, addr("R0")},
    };
    const Plan plan = PollPlanner(Protocol::Facon).plan(items);
    checkPlanConsistent(plan, items, Protocol::Facon);
    QCOMPARE(plan.requestCount(), std::size_t{1});
    QCOMPARE(plan.unplannable.size(), std::size_t{4});
    QVERIFY(QString::fromStdString(english(plan.unplannable[0].reason)).contains("broadcast"));
}

void TestPollPlanner::deterministicOrder()
{
    auto items = itemsOf({"R900", "X3", "DR40", "R7", "Y100", "R8", "D5", "M70", "M71"});
    const PollPlanner planner(Protocol::Binary);
    const Plan a = planner.plan(items);
    std::reverse(items.begin(), items.end());
    const Plan b = planner.plan(items);
    QCOMPARE(a.requestCount(), b.requestCount());
    for (std::size_t k = 0; k < a.steps.size(); ++k)
        QCOMPARE(a.steps[k].request, b.steps[k].request);
}

void TestPollPlanner::randomSmallListsAreOptimal_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("FACON") << static_cast<int>(Protocol::Facon);
    QTest::newRow("binary") << static_cast<int>(Protocol::Binary);
}

void TestPollPlanner::randomSmallListsAreOptimal()
{
    QFETCH(int, protocol);
    const auto p = static_cast<Protocol>(protocol);
    std::mt19937 rng(20240611u + static_cast<unsigned>(protocol));
    struct Kind
    {
        ElementType type;
        std::uint32_t range;
        std::uint32_t multiple;
    };
    std::vector<Kind> kinds = {
        {ElementType::X, 600, 1},   {ElementType::Y, 40, 1},     {ElementType::M, 300, 1},
        {ElementType::R, 150, 1},   {ElementType::D, 30, 1},     {ElementType::DR, 150, 1},
        {ElementType::WY, 1200, 8}, {ElementType::DWM, 2400, 8}, {ElementType::RT, 70, 1},
        {ElementType::DRC, 40, 1},
    };
    if (p == Protocol::Binary) {
        kinds.push_back({ElementType::F, 100, 1});
        kinds.push_back({ElementType::DF, 100, 1});
    }
    for (int round = 0; round < 400; ++round) {
        const int n = 1 + static_cast<int>(rng() % 8);
        const std::size_t kindCount = 1 + rng() % 3; // few kinds per case so runs are likely
        std::vector<Kind> chosen;
        for (std::size_t k = 0; k < kindCount; ++k)
            chosen.push_back(kinds[rng() % kinds.size()]);
        std::vector<WatchItem> items;
        for (int k = 0; k < n; ++k) {
            const Kind &kind = chosen[rng() % chosen.size()];
            const auto number
                = static_cast<std::uint32_t>(rng() % (kind.range / kind.multiple)) * kind.multiple;
            const auto station = static_cast<std::uint8_t>(round % 5 == 0 ? 1 + rng() % 2 : 1);
            items.push_back(
                {static_cast<std::uint64_t>(k + 1), station, Address{kind.type, number}});
        }
        const Plan plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QVERIFY(plan.unplannable.empty());
        const Optimum best = exhaustiveOptimum(items, p);
        if (plan.requestCount() != best.requests || plan.wireBytes != best.bytes) {
            QString list;
            for (const WatchItem &i : items)
                list += QString(" %1:%2").arg(i.station).arg(
                    QString::fromStdString(i.address.toString()));
            qWarning("round %d:%s -> %zu requests %zu bytes, optimum %u / %zu", round,
                     qPrintable(list), plan.requestCount(), plan.wireBytes, best.requests,
                     best.bytes);
        }
        QCOMPARE(plan.requestCount(), static_cast<std::size_t>(best.requests));
        QVERIFY(plan.wireBytes * 100 <= best.bytes * 105);
        // The planner is exact for this request model, so it should even match the bytes.
        QCOMPARE(plan.wireBytes, best.bytes);
    }
}

void TestPollPlanner::largeListsStayValid()
{
    std::mt19937 rng(7u);
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        std::vector<WatchItem> items;
        for (std::uint64_t id = 1; id <= 1500; ++id) {
            const auto type = static_cast<ElementType>(rng() % 28);
            const ElementInfo &info = elementInfo(type);
            if (p == Protocol::Facon && info.faconDigits == 0)
                continue;
            const auto number
                = static_cast<std::uint32_t>(rng() % 800) / info.alignment * info.alignment;
            items.push_back({id, static_cast<std::uint8_t>(1 + rng() % 3), Address{type, number}});
        }
        const Plan plan = PollPlanner(p).plan(items);
        checkPlanConsistent(plan, items, p);
        QVERIFY(plan.unplannable.empty());
        // Lower bound: per station, ceil(distinct words / 64) if all went to 48 lists; runs can
        // only do better on dense discretes, so the plan is never above that bound.
        std::map<std::uint8_t, std::set<Address>> distinct;
        for (const WatchItem &i : items)
            distinct[i.station].insert(i.address);
        std::size_t packBound = 0;
        for (const auto &[station, set] : distinct) {
            std::size_t words = 0;
            for (const Address &a : set)
                words += static_cast<std::size_t>(a.words());
            packBound += (words + 63) / 64;
        }
        QVERIFY(plan.requestCount() <= packBound);
    }
}

// The fast solver (no search over gap-free stretches) plans the same requests and bytes as the
// full search, on random lists of ranges (gap-free stretches, some longer than a segment) mixed
// with scattered items, several stations, isolated elements.
void TestPollPlanner::fastSolverMatchesReference()
{
    std::mt19937 rng(35u);
    auto below = [&rng](std::uint32_t n) {
        return static_cast<std::uint32_t>(rng() % n);
    };
    int lists = 0;
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        std::vector<ElementType> types;
        for (const ElementInfo &info : allElements()) {
            if (p == Protocol::Binary || info.faconDigits != 0)
                types.push_back(info.type);
        }
        const PollPlanner fast(p);
        const PollPlanner reference(p, PollPlanner::Solver::Reference);
        for (int round = 0; round < 60; ++round) {
            std::vector<WatchItem> items;
            auto add = [&](std::uint8_t station, ElementType type, std::uint32_t number) {
                if (number <= elementInfo(type).maxNumber)
                    items.push_back({items.size() + 1, station, Address{type, number}});
            };
            const std::uint8_t stations = round % 3 == 0 ? 2 : 1;
            const bool scattered = round % 2 == 1;
            for (std::uint32_t r = 1 + below(4); r > 0; --r) {
                const ElementType type = types[below(static_cast<std::uint32_t>(types.size()))];
                const ElementInfo &info = elementInfo(type);
                // A few ranges span more than one 512-item segment; the search is slow on those.
                const std::uint32_t length
                    = round % 20 == 0 && r == 1 ? 500 + below(700) : 2 + below(200);
                const std::uint32_t start = below(600) / info.alignment * info.alignment;
                const auto station = static_cast<std::uint8_t>(1 + below(stations));
                for (std::uint32_t k = 0; k < length; ++k)
                    add(station, type, start + k * info.step);
                // Items near and inside the range: gaps to bridge or not, duplicates.
                for (std::uint32_t k = scattered ? below(40) : 0; k > 0; --k) {
                    const std::uint32_t offset = below(length + 300);
                    add(station, type, start + offset * info.step);
                }
            }
            std::set<StationAddress> isolated;
            if (round % 4 == 3) {
                for (int k = 0; k < 3; ++k) {
                    const WatchItem &item = items[below(static_cast<std::uint32_t>(items.size()))];
                    isolated.insert({item.station, item.address});
                }
            }
            const Plan quick = fast.plan(items, isolated);
            const Plan searched = reference.plan(items, isolated);
            checkPlanConsistent(quick, items, p);
            QVERIFY(quick.unplannable.empty());
            const QByteArray what
                = QByteArray(protocolName(p).data()) + " list " + QByteArray::number(round) + ", "
                  + QByteArray::number(static_cast<qulonglong>(items.size())) + " items";
            QVERIFY2(quick.requestCount() == searched.requestCount(), what.constData());
            QVERIFY2(quick.wireBytes == searched.wireBytes, what.constData());
            ++lists;
        }
    }
    QCOMPARE(lists, 120);
}

void TestPollPlanner::splitIsolatesInLog2Rounds_data()
{
    QTest::addColumn<int>("kind"); // 0: 48 list, 1: 46 run with gaps, 2: 44 run
    QTest::addColumn<int>("count");
    QTest::newRow("48 of 40") << 0 << 40;
    QTest::newRow("48 of 64") << 0 << 64;
    QTest::newRow("48 of 3") << 0 << 3;
    QTest::newRow("46 of 30") << 1 << 30;
    QTest::newRow("44 of 256") << 2 << 256;
    QTest::newRow("44 of 2") << 2 << 2;
}

void TestPollPlanner::splitIsolatesInLog2Rounds()
{
    QFETCH(int, kind);
    QFETCH(int, count);
    const auto n = static_cast<std::uint32_t>(count);
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        const PollPlanner planner(p);
        std::vector<WatchItem> items;
        for (std::uint32_t k = 0; k < n; ++k) {
            Address a{ElementType::R, 1000 * k};
            if (kind == 1)
                a = Address{ElementType::R, 2 * k};
            else if (kind == 2)
                a = Address{ElementType::Y, k};
            items.push_back({k + 1, 1, a});
        }
        const Plan plan = planner.plan(items);
        QCOMPARE(plan.requestCount(), std::size_t{1});
        // Halves differ by at most one element: between floor(log2 n) and ceil(log2 n) rounds.
        int ceilLog2 = 0;
        while ((1u << ceilLog2) < n)
            ++ceilLog2;
        int floorLog2 = 0;
        while ((2u << floorLog2) <= n)
            ++floorLog2;
        int mostRounds = 0;
        // Try every bad position for small lists, a few for large ones.
        for (std::uint32_t bad = 0; bad < n; bad += (n > 64 ? 37 : 1)) {
            const Address badAddress = items[bad].address;
            PlanStep failing = plan.steps[0];
            int rounds = 0;
            while (true) {
                const std::vector<PlanStep> halves = planner.split(failing);
                if (halves.empty())
                    break;
                QCOMPARE(halves.size(), std::size_t{2});
                ++rounds;
                std::optional<PlanStep> next;
                std::size_t slotCount = 0;
                for (const PlanStep &h : halves) {
                    QVERIFY(validateRequest(h.request, p).ok());
                    QCOMPARE(h.wireBytes, PollPlanner::queryBytes(h.request, p)
                                              + PollPlanner::responseBytes(h.request, p));
                    slotCount += h.itemSlots.size();
                    bool holdsBad = false;
                    for (const PlanSlot &s : h.itemSlots) {
                        holdsBad = holdsBad || addressOfSlot(h.request, s.valueIndex) == badAddress;
                        QCOMPARE(items[s.itemIndex].id, s.itemId); // positions survive a split
                    }
                    if (holdsBad) {
                        QVERIFY(!next);
                        next = h;
                    }
                }
                QCOMPARE(slotCount, failing.itemSlots.size());
                QVERIFY(next);
                failing = *next;
            }
            QVERIFY(rounds >= floorLog2 && rounds <= ceilLog2);
            mostRounds = std::max(mostRounds, rounds);
            QCOMPARE(failing.itemSlots.size(), std::size_t{1});
            QCOMPARE(failing.itemSlots[0].itemId, items[bad].id);
            QCOMPARE(addressOfSlot(failing.request, failing.itemSlots[0].valueIndex), badAddress);
            QCOMPARE(failing.request.expectedValueCount(), 1u);
        }
        QCOMPARE(mostRounds, ceilLog2);
    }
}

void TestPollPlanner::splitSingleItemGivesNothing()
{
    const PollPlanner planner(Protocol::Facon);
    std::vector<WatchItem> items = {{1, 1, addr("R3")}, {2, 1, addr("R3")}};
    const Plan plan = planner.plan(items);
    QCOMPARE(plan.requestCount(), std::size_t{1});
    QVERIFY(planner.split(plan.steps[0]).empty());
    PlanStep status;
    status.request = Request::briefStatus(1);
    QVERIFY(planner.split(status).empty());
}

void TestPollPlanner::isolatedElementsReadAlone()
{
    const PollPlanner planner(Protocol::Binary);
    const auto items = itemsOf({"R0", "R1", "R2", "R3", "X5"});
    const std::set<StationAddress> isolated = {{1, addr("R2")}};
    const Plan plan = planner.plan(items, isolated);
    checkPlanConsistent(plan, items, Protocol::Binary);
    bool sawAlone = false;
    for (const PlanStep &s : plan.steps) {
        if (s.request == Request::readRegisters(1, addr("R2"), 1)) {
            sawAlone = true;
            QCOMPARE(s.itemSlots.size(), std::size_t{1});
            continue;
        }
        // No other step reads R2, not even to bridge the gap between R1 and R3.
        for (std::uint32_t k = 0; k < s.request.expectedValueCount(); ++k)
            QVERIFY(addressOfSlot(s.request, k) != addr("R2"));
    }
    QVERIFY(sawAlone);
    QCOMPARE(plan.requestCount(), std::size_t{2}); // R2 alone; R0, R1, R3, X5 share one 48
}

QTEST_GUILESS_MAIN(TestPollPlanner)
#include "tst_pollplanner.moc"
