#pragma once

#include "core/planner/pollplanner.h"
#include "core/session/requesttracker.h"
#include "memorysnapshot.h"

#include <QObject>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <thread>
#include <vector>

namespace Fatek {

class Session;

// What a snapshot reads, before it is packed into requests: the elements asked for, and the
// items the poll planner packs. Discretes are read through their 16-bit views (WX0 = X0..X15),
// 16 per word, wherever the whole word exists on the PLC; the rest are read as they are.
struct SnapshotReadItems
{
    std::set<Address> wanted;
    std::vector<WatchItem> items; // id = index
};

// Reads a memory snapshot through a RequestTracker on a Session: the 53 detail status first (the
// model for the metadata, the memory sizes for the default ranges and the discrete words), then
// the elements in the fewest requests the poll planner finds. The items are listed and planned on
// a thread of its own: a whole FBs takes milliseconds in release and far longer under
// sanitizers, too long for the GUI thread (and the session's I/O thread must not stall either).
// Never blocks; progress() after each answer, finished() once (also after cancel() or a failure).
class SnapshotReader : public QObject
{
    Q_OBJECT

public:
    explicit SnapshotReader(QObject *parent = nullptr);
    // Does not wait for a plan still being made: its result is dropped.
    ~SnapshotReader() override;

    void setSession(Session *session);
    Session *session() const { return m_tracker.session(); }

    // `ranges` empty: every element the PLC reports (Snapshot::defaultRanges). Ignored while a
    // read is running.
    void start(std::uint8_t station, std::vector<AddressRange> ranges = {});
    // Stops: queued requests are dropped, finished() comes with ErrorKind::Cancelled.
    void cancel();
    bool isRunning() const { return m_running; }

    // Requests answered and planned (the 53 included; the total is known after its answer).
    int requestsDone() const { return m_done; }
    int requestsTotal() const { return m_total; }

    // After finished(): the snapshot when ok(), else the error.
    bool ok() const { return !m_error.has_value(); }
    const MemorySnapshot &snapshot() const { return m_snapshot; }
    const ProtocolError &error() const { return *m_error; }

    // The elements and items for `ranges`; `sizes` (the 53 answer) bounds the discrete words.
    static SnapshotReadItems readItems(std::span<const AddressRange> ranges,
                                       const DetailStatus *sizes);

Q_SIGNALS:
    void progress(int done, int total);
    void finished();

private:
    struct Planned;
    struct PlanHandOff;

    void onDetailStatus(const SessionResult &result);
    // Lists and plans the items of m_ranges off this thread; onPlanned() takes the result here.
    void planInBackground(Protocol protocol, std::optional<DetailStatus> sizes);
    void onPlanned(std::uint64_t job, Planned &planned);
    void submitNext();
    void onStep(std::size_t index, const SessionResult &result);
    void fail(ProtocolError error);
    void complete();

    RequestTracker m_tracker;
    std::shared_ptr<PlanHandOff> m_handOff;
    std::thread m_planThread; // planInBackground()'s, joined by the next one and the destructor
    std::uint64_t m_job = 0;  // the plan a result must belong to (bumped by every start())
    bool m_running = false;
    std::uint8_t m_station = 1;
    std::vector<AddressRange> m_ranges;
    SnapshotReadItems m_items;
    Plan m_plan;
    std::size_t m_nextStep = 0;
    int m_inFlight = 0;
    int m_done = 0;
    int m_total = 0;
    std::map<Address, std::uint32_t> m_values;
    MemorySnapshot m_snapshot;
    std::optional<ProtocolError> m_error;
};

} // namespace Fatek
