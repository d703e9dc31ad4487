#pragma once

#include "checkoutplan.h"
#include "core/session/requesttracker.h"
#include "core/session/sessiontypes.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <map>
#include <optional>

namespace Fatek {

class Session;

// Runs an I/O checkout on a Session (the same for the GUI and the CLI). Lives in the caller's
// thread; every request goes through RequestTrackers, nothing blocks.
//
// - start(): reads the detail status (model, OS version, RUN/STOP) into the plan, releases the
//   outputs a previous run left forced (the file records them), reads every point once (points
//   the PLC refuses, out of its model's range, are named and nothing runs: refused()), then polls
//   the plan's inputs (packed reads of consecutive runs) and the current analog point. A poll that
//   fails is said once, and again when the points read again.
// - Inputs: a change is recorded on the current point when it is an untested input (0->1 and
//   1->0 seen: passed); a change of another input meanwhile is flagged as crossed wiring on the
//   point under test, which then fails instead of passing (a person may pass it with a remark).
//   With no input under test (current point -1, another kind, or done), each input records its
//   own changes: any order. A tested input ignores edges until retest().
// - Results by hand: record() (passed with remark and deferred need their text; an input flagged
//   for crossed wiring cannot pass clean; an analog point passes or fails only by its readings).
//   A point that has a result keeps it as an earlier attempt when it is tested again.
// - Outputs, one at a time: forceOutput() records the output as forced (saved first), then
//   disables and sets it; answerOutput() records the technician's answer and releases it at
//   once (reset, enable). Refused in operator mode, and with the PLC in RUN until
//   allowOutputsInRun(true). Nothing stays forced: released by answerOutput, stop(), the
//   destructor, and after a lost link as soon as it is back. A release that failed (a timeout:
//   the PLC may or may not have done it) is tried again every releaseRetryMs while the link is
//   up, until the PLC confirms it: the enable flag read back as enabled, or reset and enable
//   answered. Only then is the output dropped from plan().forced (and from the file).
// - Analog: recordAnalog() reads the register at one check of the scale, as found or as left;
//   every check read and within tolerance (its as-left value where there is one): passed, else
//   failed. A point without a scale is refused: no expected values, no pass.
// Every change of a point is saved at once when a file is set (CheckoutFile, through SafeFile).
class CheckoutRunner : public QObject
{
    Q_OBJECT

public:
    explicit CheckoutRunner(QObject *parent = nullptr);
    // Releases what is still forced (the requests are queued on the session, which sends them
    // before it closes).
    ~CheckoutRunner() override;

    void setSession(Session *session);
    Session *session() const { return m_actions.session(); }

    void setPlan(CheckoutPlan plan);
    const CheckoutPlan &plan() const { return m_plan; }
    // Saves after every change; empty: no file.
    void setFilePath(const QString &path) { m_filePath = path; }
    QString filePath() const { return m_filePath; }
    // The last save's failure (cleared by a good save).
    const std::optional<Message> &saveError() const { return m_saveError; }
    // Recorded with each result.
    void setEngineer(const QString &name) { m_engineer = name; }
    // After an input passes, the current point moves to the next untested input.
    void setAutoAdvance(bool on) { m_autoAdvance = on; }
    void setPollIntervalMs(int ms) { m_pollIntervalMs = ms; }
    // How long after a failed release it is tried again (the link up).
    void setReleaseRetryMs(int ms) { m_releaseRetry.setInterval(ms); }

    void start();
    // Stops polling and releases what is forced (the output under test gets no answer: it stays
    // untested). The releases go on (retried) after it.
    void stop();
    bool isRunning() const { return m_running; }
    // Running and every point read once (started() emitted): only then is anything forced.
    bool isStarted() const { return m_running && !m_starting; }
    // The PLC was in RUN at the last status read.
    bool isPlcRunning() const { return m_plcRunning; }

    // The point under test (-1: none).
    int currentPoint() const { return m_current; }
    void setCurrentPoint(int index);
    // The next untested point after the current one (wrapping), -1 when every point has a
    // result.
    void nextPoint();

    // A result by hand; `comment` (the remark, the reason) replaces the old one when not null.
    // A point that has a result already is tested again: its attempt is kept as an earlier one.
    // Refused (the reason, nothing recorded): an index out of range, untested, passed with remark
    // or deferred without its text, an input flagged for crossed wiring passed clean, an analog
    // point passed or failed by hand.
    Status record(int index, CheckoutResult result, const QString &comment = QString());
    void setComment(int index, const QString &comment);
    // Tests the point again: its latest attempt goes to the earlier ones (when it has anything),
    // and an input takes new edges.
    void retest(int index);
    // The punch list: who mends the point; closed out once its latest result is no longer a
    // failure (refused otherwise, and for a point not on the list).
    Status setPunchOwner(int index, const QString &owner);
    Status closePunch(int index, const QString &closedBy);

    // Outputs. forceOutput -> outputForced(index) (ask the technician) or failed().
    void allowOutputsInRun(bool allow) { m_allowInRun = allow; }
    void forceOutput(int index);
    void answerOutput(bool seen, const QString &comment = QString());
    // The output forced and waiting for its answer (-1: none).
    int outputUnderTest() const { return m_outputUnderTest; }
    // Outputs forced and not confirmed released (also those a previous run left).
    bool hasForced() const { return !m_plan.forced.empty(); }
    // A release failed and is being tried again (outputReleased() once the PLC confirmed it).
    bool isRetryingRelease() const { return !m_releaseFailed.empty(); }

    // Analog: reads the register now and records it at check `check` (an index into the
    // point's scale.checks), as found or, after an adjustment, as left. analogRecorded() or
    // failed() follows; refused at once (the reason) when the point cannot take it.
    Status recordAnalog(int index, int check, bool asLeft = false);

Q_SIGNALS:
    // The status is read and the leftovers released: inputs are watched.
    void started();
    void pointChanged(int index);
    void currentPointChanged(int index);
    // The latest value of a polled point (inputs, the current analog point).
    void liveValue(int index, quint32 value);
    // `changed` moved while `underTest` was tested (its changedWith has it now).
    void crossedWiring(int changed, int underTest, const Fatek::Message &message);
    // A reading of recordAnalog() is in the point (pointChanged() came first).
    void analogRecorded(int index, int check);
    // The PLC refused points of the plan at start(): nothing runs (isRunning() is false).
    void refused(const Fatek::Message &message);
    // The polled points read again after a failure.
    void readAgain(const Fatek::Message &message);
    // The PLC is in RUN: nothing was forced. Ask (message); on yes allowOutputsInRun(true) and
    // forceOutput() again, on no nothing is forced (CheckoutRunNotConfirmed says so).
    void runConfirmationNeeded(int index, const Fatek::Message &question);
    void outputForced(int index);
    void outputReleased(const Fatek::Address &address);
    // Outputs a previous run (or a lost link) left forced are released.
    void leftoversReleased(const Fatek::Message &message);
    // A refusal (operator mode, busy, no link) or a failure (force, release, read). A release
    // that keeps failing is said once, when it first fails.
    void failed(const Fatek::ProtocolError &error);
    void saveFailed(const Fatek::Message &message);

private:
    void onStatus(const SessionResult &result);
    // Reads every run of points once; those the PLC refuses are named (refused()).
    void probePoints();
    void probeDone();
    void pollCycle();
    void onInputs(const Request &request, const SessionResult &result);
    void inputChanged(int index, bool on);
    void doForce(int index);
    // checkFirst: the enable flag is read first, and an output found enabled is released already
    // (a retry after a timeout, a leftover: no reset of an output its program drives again).
    void release(const Address &address, bool leftover, bool checkFirst = false);
    void releaseDone(const Address &address, bool leftover, const SessionResult &result);
    void releaseAllForced(bool leftover);
    // The forced outputs not under test and not on the wire: checked and released (link up).
    void retryReleases();
    void onLinkState(LinkState state);
    void markResult(CheckoutPoint &p, CheckoutResult result);
    // A point with a result is tested anew: its attempt goes to the earlier ones.
    static void archiveAttempt(CheckoutPoint &p);
    void analogRead(int index, int check, bool asLeft, const SessionResult &result);
    void decideAnalog(CheckoutPoint &p);
    CheckoutPoint *pointAt(int index);
    void changed(int index);
    void save();
    void fail(ProtocolError error);

    RequestTracker m_actions;
    RequestTracker m_polls;
    QMetaObject::Connection m_linkConnection;
    CheckoutPlan m_plan;
    QString m_filePath;
    std::optional<Message> m_saveError;
    QString m_engineer;
    bool m_autoAdvance = false;
    int m_pollIntervalMs = 100;
    QTimer m_pollTimer;
    int m_pollsInFlight = 0;
    std::vector<Request> m_pollRequests;
    std::map<Address, bool> m_inputs;   // last value read
    std::optional<Message> m_pollError; // said once, until the points read again
    // start()'s reading of every point: requests on the wire, and what the PLC refused.
    int m_probesInFlight = 0;
    std::vector<Address> m_refused;
    std::optional<Message> m_refusal;
    bool m_running = false;
    bool m_starting = false; // start()'s status and probe reads still on the wire
    bool m_plcRunning = false;
    bool m_allowInRun = false;
    bool m_linkLost = false;
    int m_current = -1;
    int m_outputUnderTest = -1;
    std::vector<Address> m_releasing;     // release requests on the wire
    std::vector<Address> m_releaseFailed; // failed once, said once, retried until confirmed
    QTimer m_releaseRetry;
};

} // namespace Fatek
