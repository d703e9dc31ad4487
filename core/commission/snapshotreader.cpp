#include "snapshotreader.h"

#include "commissionmessages.h"
#include "core/protocol/plcmodel.h"
#include "core/session/crossthreadcall.h"
#include "core/session/session.h"

#include <QTimer>

#include <algorithm>
#include <mutex>
#include <thread>

namespace Fatek {

namespace {

// Requests kept queued in the session at once: enough to keep the link busy, few enough that
// other tools' requests on the same session are not held behind a whole snapshot.
constexpr int window = 4;

// Adds the items that read discretes [first, last] of `type`: whole 16-bit words (WX0 =
// X0..X15) where the word exists (`size`: points of the kind on the PLC), single discretes for
// what is left.
void addDiscretes(ElementType type, std::uint32_t first, std::uint32_t last, std::uint32_t size,
                  std::vector<Address> &out)
{
    const ElementType word
        = static_cast<ElementType>(static_cast<int>(ElementType::WX)
                                   + (static_cast<int>(type) - static_cast<int>(ElementType::X)));
    const std::uint32_t step = elementInfo(word).step;           // 16
    const std::uint32_t alignment = elementInfo(word).alignment; // 8
    std::uint32_t k = first - first % alignment;
    while (k <= last && k + step <= size) {
        out.push_back(Address{word, k});
        k += step;
    }
    if (k > last)
        return;
    const std::uint32_t tail = std::max(k, first);
    // One aligned word still covering the whole tail (S992..S999 of 1000 points: WS984).
    if (size >= step) {
        std::uint32_t w = std::min(tail, size - step);
        w -= w % alignment;
        if (w + step - 1 >= last && w <= tail) {
            out.push_back(Address{word, w});
            return;
        }
    }
    for (std::uint32_t n = tail; n <= last; ++n)
        out.push_back(Address{type, n});
}

} // namespace

// What the planning thread hands back.
struct SnapshotReader::Planned
{
    SnapshotReadItems items;
    Plan plan;
};

// The way back from a planning thread. `reader` is cleared, under `mutex`, by the reader's
// destructor, so a planning thread never reaches a dead reader: it posts while holding `mutex`,
// and a call posted before the destruction goes with the object (as Session's completions).
struct SnapshotReader::PlanHandOff
{
    std::mutex mutex;
    SnapshotReader *reader = nullptr;
};

SnapshotReader::SnapshotReader(QObject *parent)
    : QObject(parent)
    , m_handOff(std::make_shared<PlanHandOff>())
{
    m_handOff->reader = this;
}

SnapshotReader::~SnapshotReader()
{
    {
        const std::lock_guard locker(m_handOff->mutex);
        m_handOff->reader = nullptr;
    }
    // A plan still being made ends on its own (milliseconds); nothing outlives the reader.
    if (m_planThread.joinable())
        m_planThread.join();
}

void SnapshotReader::setSession(Session *session)
{
    if (m_running)
        cancel();
    m_tracker.setSession(session);
}

SnapshotReadItems SnapshotReader::readItems(std::span<const AddressRange> ranges,
                                            const DetailStatus *sizes)
{
    SnapshotReadItems r;
    std::vector<Address> reads;
    for (const AddressRange &range : ranges) {
        const Address last = range.last();
        for (std::uint32_t i = 0; i < range.count; ++i)
            r.wanted.insert(range.start.advanced(i));
        if (!isDiscrete(range.start.type)) {
            for (std::uint32_t i = 0; i < range.count; ++i)
                reads.push_back(range.start.advanced(i));
            continue;
        }
        std::uint32_t size = last.number + 1;
        if (sizes) {
            if (const auto count = sizes->discreteCount(range.start.type))
                size = *count;
        }
        if (last.number >= size) // asked beyond what the PLC reports: let the PLC answer
            size = last.number + 1;
        addDiscretes(range.start.type, range.start.number, last.number, size, reads);
    }
    std::sort(reads.begin(), reads.end());
    reads.erase(std::unique(reads.begin(), reads.end()), reads.end());
    r.items.reserve(reads.size());
    for (const Address &a : reads)
        r.items.push_back(WatchItem{r.items.size(), 1, a});
    return r;
}

void SnapshotReader::start(std::uint8_t station, std::vector<AddressRange> ranges)
{
    if (m_running) {
        // The running one goes on; this call is answered at once.
        return;
    }
    m_running = true;
    ++m_job; // a plan of an earlier read that comes now is not this one's
    m_station = station;
    m_ranges = std::move(ranges);
    m_items = {};
    m_plan = {};
    m_nextStep = 0;
    m_inFlight = 0;
    m_done = 0;
    m_total = 1;
    m_values.clear();
    m_snapshot = {};
    m_error.reset();
    Session *s = m_tracker.session();
    if (!s) {
        // Answered from the event loop, as every other outcome.
        QTimer::singleShot(0, this, [this] {
            fail(makeError(ErrorKind::LinkError, msg<MsgId::SnapshotNoSession>()));
        });
        return;
    }
    m_snapshot.info.taken = QDateTime::currentDateTimeUtc();
    m_snapshot.info.link = s->settings().toString();
    m_snapshot.info.station = station;
    m_tracker.submit(Request::detailStatus(station),
                     [this](const SessionResult &r) { onDetailStatus(r); });
}

void SnapshotReader::cancel()
{
    if (!m_running)
        return;
    m_tracker.cancelPending();
    fail(makeError(ErrorKind::Cancelled, msg<MsgId::SnapshotCancelled>()));
}

void SnapshotReader::onDetailStatus(const SessionResult &result)
{
    if (!m_running)
        return;
    ++m_done;
    Session *s = m_tracker.session();
    const auto proto = protocolName(s ? s->protocol() : Protocol::Facon);
    m_snapshot.info.protocol
        = QString::fromLatin1(proto.data(), static_cast<qsizetype>(proto.size()));
    std::optional<DetailStatus> status;
    if (result.ok()) {
        status = DetailStatus::decode(result.response().data);
        m_snapshot.info.model = QString::fromStdString(PlcModel::modelText(*status));
    } else if (result.errorKind() != ErrorKind::PlcError
               && result.errorKind() != ErrorKind::Unsupported
               && result.errorKind() != ErrorKind::MalformedResponse) {
        // The link itself failed: nothing else would come through either.
        return fail(result.error());
    }
    if (m_ranges.empty()) {
        if (status)
            m_ranges = Snapshot::defaultRanges(*status);
        if (m_ranges.empty())
            return fail(makeError(ErrorKind::Unsupported,
                                  msg<MsgId::SnapshotNeedsSizes>(
                                      result.ok() ? Message(commandMessage(Command::DetailStatus))
                                                  : result.errorMessage())));
    }
    std::size_t elements = 0;
    for (const AddressRange &r : m_ranges)
        elements += r.count;
    if (elements > Snapshot::MaxValues)
        return fail(makeError(ErrorKind::LimitExceeded,
                              msg<MsgId::SnapshotTooMany>(elements, Snapshot::MaxValues)));

    planInBackground(s ? s->protocol() : Protocol::Facon, std::move(status));
}

void SnapshotReader::planInBackground(Protocol protocol, std::optional<DetailStatus> sizes)
{
    // A thread per snapshot, not the session's worker: the plan would hold up its I/O. The reader
    // owns it: the next start() and the destructor join it; the hand-over drops a result nobody
    // wants any more. The thread's start orders everything it is given (visible to
    // ThreadSanitizer, unlike a Qt thread pool's queue).
    if (m_planThread.joinable())
        m_planThread.join(); // the previous start()'s plan, cancelled: done or nearly
    m_planThread = std::thread([handOff = m_handOff, job = m_job, ranges = m_ranges,
                                sizes = std::move(sizes), station = m_station, protocol] {
        auto planned = std::make_shared<Planned>();
        planned->items = readItems(ranges, sizes ? &*sizes : nullptr);
        for (WatchItem &item : planned->items.items)
            item.station = station;
        planned->plan = PollPlanner(protocol).plan(planned->items.items);
        const std::lock_guard locker(handOff->mutex);
        if (SnapshotReader *reader = handOff->reader) {
            CrossThreadCall::invoke(reader, [reader, job, planned = std::move(planned)] {
                reader->onPlanned(job, *planned);
            });
        }
    });
}

void SnapshotReader::onPlanned(std::uint64_t job, Planned &planned)
{
    if (!m_running || job != m_job)
        return;
    if (!m_tracker.session()) // gone while planning: nothing would answer
        return fail(makeError(ErrorKind::LinkError, msg<MsgId::SnapshotNoSession>()));
    m_items = std::move(planned.items);
    m_plan = std::move(planned.plan);
    if (!m_plan.unplannable.empty()) {
        const UnplannableItem &bad = m_plan.unplannable.front();
        const Address a = m_items.items.at(bad.itemId).address;
        return fail(makeError(ErrorKind::InvalidAddress,
                              msg<MsgId::SnapshotCannotRead>(a.toString(), bad.reason)));
    }
    m_total = 1 + static_cast<int>(m_plan.steps.size());
    Q_EMIT progress(m_done, m_total);
    submitNext();
}

void SnapshotReader::submitNext()
{
    while (m_running && m_inFlight < window && m_nextStep < m_plan.steps.size()) {
        const std::size_t index = m_nextStep++;
        ++m_inFlight;
        m_tracker.submit(m_plan.steps[index].request,
                         [this, index](const SessionResult &r) { onStep(index, r); });
    }
    if (m_running && m_inFlight == 0 && m_nextStep >= m_plan.steps.size())
        complete();
}

void SnapshotReader::onStep(std::size_t index, const SessionResult &result)
{
    if (!m_running)
        return;
    --m_inFlight;
    const PlanStep &step = m_plan.steps[index];
    if (!result.ok()) {
        m_tracker.cancelPending();
        return fail(result.error());
    }
    const std::vector<std::uint32_t> &values = result.response().values;
    for (const PlanSlot &slot : step.itemSlots) {
        if (slot.valueIndex >= values.size())
            continue;
        const Address read = m_items.items.at(slot.itemId).address;
        const std::uint32_t v = values[slot.valueIndex];
        const ElementInfo &info = read.info();
        if (info.discrete) {
            // A discrete word read for its bits.
            for (std::uint32_t b = 0; b < info.step; ++b) {
                const Address bit{*info.discrete, read.number + b};
                if (m_items.wanted.count(bit))
                    m_values[bit] = (v >> b) & 1u;
            }
        }
        if (m_items.wanted.count(read))
            m_values[read] = v;
    }
    ++m_done;
    Q_EMIT progress(m_done, m_total);
    submitNext();
}

void SnapshotReader::fail(ProtocolError error)
{
    if (!m_running)
        return;
    m_running = false;
    m_error = std::move(error);
    m_tracker.forgetPending();
    Q_EMIT finished();
}

void SnapshotReader::complete()
{
    m_running = false;
    m_snapshot.values.clear();
    m_snapshot.values.reserve(m_values.size());
    for (const auto &[address, value] : m_values)
        m_snapshot.values.push_back(SnapshotValue{address, value});
    Q_EMIT finished();
}

} // namespace Fatek
