#pragma once

// Internal to fateksession (compiled with QT_NO_KEYWORDS: PlanStep has a member named "slots").

#include "core/planner/pollplanner.h"
#include "core/protocol/address.h"
#include "sessionresult.h"
#include "sessiontypes.h"
#include "watchvalue.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QMetaType>
#include <QObject>
#include <QTimer>

#include <array>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace Fatek {

// The polling engine of a session (lives in the worker thread). Items are grouped by interval and
// station; each group is planned by PollPlanner and cycles on absolute deadlines: period
// max(interval, cycle time), no drift, never catch-up bursts. A group has one request in the queue
// at a time, so the stations of a line take turns and one-shot requests get the line between any
// two poll requests.
//
// Field faults (issue 31, issue 54): a station that leaves `demoteAfter` requests in a row
// unanswered is demoted: it rests for `demotionMs`; meanwhile its items are stale with the reason
// and the next try, and the other stations keep their rate. A resting station, and a station of
// the list that never answered yet, is not polled but probed: one small request (brief status,
// one attempt) with a short timeout of its own (probeTimeoutMs(), from the line's measured round
// trip), sent only in the line's slack before the next due poll (or delaying it by at most half
// its spare time), so a dead station never makes the other stations' items late. No answer to the
// probe: it rests (again).
//
// A batch failing with PLC error A or 2 is split until the bad element is found; only that
// element is marked, later plans keep it alone, and it is asked again only every
// refusalRecheckMs, without counting as an error.
//
// Late (issue 55): a group is expected every max(interval, its recent cycle time); its good values
// are reported late when that is overdue twice over. A line slower than the interval thus adapts
// the period once (and says so: effectiveIntervalChanged) instead of flapping good/late.
class Poller : public QObject
{
    Q_OBJECT

public:
    using SubmitFunction = std::function<void(const Request &, const RequestOptions &,
                                              std::function<void(const SessionResult &)>)>;
    static constexpr qint64 refusalRecheckMs = 60000;

    // Bounds of a probe's timeout (probeTimeoutMs()). A probe waits for slack at most
    // probePatience() past its due time, then goes anyway: a line with no slack must not keep a
    // station resting for ever.
    static constexpr int probeMinMs = 50;
    static constexpr int probeRoundTrips = 4;

    struct Policy
    {
        int demoteAfter = 3; // 0: never demote (and never probe)
        int demotionMs = 10000;
        int timeoutMs = 1000; // the link's timeout: the longest a probe may wait
        // The line's measured round trip (p99, ms; 0 while nothing was measured).
        std::function<double()> roundTripMs;
    };

    explicit Poller(SubmitFunction submit, Policy policy, QObject *parent = nullptr);

    void setProtocol(Protocol protocol);
    void setWatchList(const QList<WatchEntry> &entries);
    // Polling runs only while the link is up.
    void setLinkUp(bool up);

    // Elements remembered as refused by the PLC.
    const std::set<StationAddress> &isolated() const { return m_isolated; }

    // The station's health, for the session's other requests to it: a station that left a
    // request unanswered is suspect (one attempt, no retries); a demoted one rests, and its
    // routine reads are not sent (`reason` says until when).
    bool isSuspect(quint8 station) const;
    bool isResting(quint8 station, Message *reason = nullptr) const;
    // What a request of someone else told about the station (an answer ends a demotion early,
    // no answer counts towards one).
    void noteAnswer(quint8 station, const SessionResult &result);
    // The timeout of a probe: probeRoundTrips x the line's round trip, at least probeMinMs, at
    // most the link's timeout (which it is while nothing was measured).
    int probeTimeoutMs() const;

Q_SIGNALS:
    void values(const QList<Fatek::WatchValue> &values);
    void cycleCompleted(double milliseconds);
    // A station was demoted (`demoted`, with the time of its next try) or answers again.
    void stationHealthChanged(quint8 station, bool demoted, const QDateTime &nextTry,
                              int unanswered);
    // The items of a group are read every `effectiveMs` instead of every `intervalMs`: the line
    // cannot go faster (said above 1.5 x the interval); back to `intervalMs` once the recent
    // cycles fit in it again. Late is counted from the effective period.
    void effectiveIntervalChanged(quint8 station, int intervalMs, int effectiveMs);

private:
    using GroupKey = std::pair<int, quint8>; // interval, station
    // Last good value of an item, for Stale reports: only what they need (16 bytes, not a whole
    // WatchValue: this is per watched item, see docs/performance.md).
    struct LastGood
    {
        std::uint32_t value = 0;
        QDateTime timestamp;
    };
    struct Group
    {
        int intervalMs = 1000;
        quint8 station = 1;
        std::vector<WatchItem> items;
        Plan plan;
        qint64 deadline = 0; // ms on m_clock
        bool inFlight = false;
        bool replan = false;
        std::deque<PlanStep> pending; // steps of this cycle not submitted yet
        int outstanding = 0;          // submitted, not finished
        qint64 cycleStart = 0;
        quint64 generation = 0;
        // Per item, by position in `items` (the plan's slots name it): arrays, not hash tables
        // by id, since this is per watched item.
        std::vector<LastGood> lastGood;
        QList<WatchValue> cycleValues; // this cycle's values, where cycleFilled says
        std::vector<bool> cycleFilled;
        qint64 lastDelivery = 0; // ms on m_clock: the last batch, or the group's start
        bool lateReported = false;
        // The last few cycle times (ms): the period the group can have on this line.
        std::array<qint64, 3> recentCycleMs{};
        std::size_t recentNext = 0;
        bool slowed = false;                     // effectiveIntervalChanged said it is slower
        bool submitting = false;                 // inside submitNext()
        std::vector<std::uint32_t> goodLastTime; // positions of the items good in the last batch
    };
    struct StationHealth
    {
        int unanswered = 0; // poll requests in a row without an answer
        bool demoted = false;
        bool heard = false;    // answered since it joined the list: polled, not probed
        qint64 until = 0;      // ms on m_clock: end of the demotion
        bool trialOut = false; // a probe of the station is out
        quint64 probe = 0;     // which probe (a result of an earlier list's probe is ignored)
    };

    void replan(Group &group);
    void reschedule();
    void onTimer();
    void startCycle(Group &group);
    void submitNext(Group &group);
    void onStepDone(GroupKey key, quint64 generation, const PlanStep &step,
                    const SessionResult &result);
    // The station's items of `steps` are stale because it is demoted.
    void markDemoted(Group &group, const std::vector<PlanStep> &steps);
    Message demotedReason(quint8 station) const;
    void reportLate(Group &group, qint64 now);
    // The period a group can keep on this line, and when its values become late.
    static qint64 recentCycle(const Group &group); // the longest of the last few cycles
    static qint64 expectedPeriod(const Group &group);
    static qint64 lateAt(const Group &group);
    void noteCycleTime(Group &group, qint64 ms);
    // Stations not polled but probed (resting, or never answered), and when a probe may go:
    // nullopt while the line has no slack for it.
    bool needsProbe(const StationHealth &health) const;
    bool isPolled(quint8 station) const;
    bool probeOut() const;
    std::optional<qint64> probeAt(const StationHealth &health, qint64 now) const;
    // How long past its due time a probe waits for slack before it goes anyway.
    qint64 probePatience(const StationHealth &health) const;
    void submitProbe(quint8 station);
    void onProbeDone(quint8 station, quint64 probe, const SessionResult &result);
    void finishCycle(Group &group);
    static void setCycleValue(Group &group, std::uint32_t index, WatchValue value);
    static std::set<StationAddress> elementsOf(const PlanStep &step);
    bool isRefusal(const PlanStep &step) const;
    static bool noAnswer(const SessionResult &result);

    SubmitFunction m_submit;
    Policy m_policy;
    std::optional<PollPlanner> m_planner;
    std::map<GroupKey, Group> m_groups;
    std::map<quint8, StationHealth> m_health;
    std::set<quint8> m_stations; // the stations of the list
    quint64 m_probes = 0;
    std::set<StationAddress> m_isolated;
    // Isolated elements: the refusal to show, and when to ask again (ms on m_clock).
    struct Refusal
    {
        Message reason;
        qint64 recheckAt = 0;
    };
    std::map<StationAddress, Refusal> m_refusals;
    bool m_linkUp = false;
    quint64 m_generation = 0;
    QElapsedTimer m_clock;
    QTimer m_timer{this}; // a child: follows the poller to its thread
};

} // namespace Fatek
