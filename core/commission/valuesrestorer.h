#pragma once

#include "core/session/requesttracker.h"
#include "memorysnapshot.h"
#include "snapshotdiff.h"
#include "snapshotreader.h"

#include <QObject>

#include <optional>
#include <span>
#include <vector>

namespace Fatek {

class Session;

// Restores values (a recipe): reads the PLC's detail status (53) for its model and ranges, writes
// the chosen values of a snapshot in the fewest write frames, then reads them back and reports
// exactly which elements differ. Refused up front, nothing written, when the session is read-only
// (operator mode); refused after the 53, nothing written, when the snapshot is of another model
// (unless allowed) or holds an element the PLC does not have. A PLC that does not answer the 53
// (an error code, not a link failure) is written unchecked: it refuses what it lacks itself.
// Through a RequestTracker: never blocks; progress() after each answer, finished() once.
class ValuesRestorer : public QObject
{
    Q_OBJECT

public:
    explicit ValuesRestorer(QObject *parent = nullptr);

    void setSession(Session *session);
    Session *session() const { return m_tracker.session(); }

    // Ignored while running. Refusals (no session, read-only, nothing to write) come as
    // finished() from the event loop, with nothing sent. `snapshotModel`: the snapshot's model
    // text (SnapshotInfo::model); empty or unknown: no model check, the ranges still are.
    void start(std::uint8_t station, std::vector<SnapshotValue> values,
               const QString &snapshotModel = {});
    // A snapshot of another model than the PLC's is written all the same (its elements must
    // still exist on the PLC). For the next start().
    void setAllowOtherModel(bool allow) { m_allowOtherModel = allow; }
    // Stops before the next write (a write on the wire completes); finished() with Cancelled.
    void cancel();
    bool isRunning() const { return m_running; }

    // Writes done so far plus the read-back's requests.
    int requestsDone() const;
    int requestsTotal() const;
    int writeRequestCount() const { return static_cast<int>(m_writes.size()); }
    // Values of the writes the PLC confirmed so far.
    int valuesWritten() const;

    // After finished(): written and read back equal.
    bool ok() const { return !m_error && m_mismatches.empty(); }
    // The failure (ReadOnly, a write refused, the link...), when there was one.
    const std::optional<ProtocolError> &error() const { return m_error; }
    // Read back after writing: before = the value written, after = the value read.
    const std::vector<SnapshotDifference> &mismatches() const { return m_mismatches; }
    // After finished(): refused because the snapshot is of another model (nothing written).
    bool refusedForModel() const { return m_refusedForModel; }
    // The PLC's model text from its 53 ("FBs-28MC, OS V3.1, program 13184 words"), once read.
    const QString &plcModel() const { return m_plcModel; }
    // One sentence: RestoreDone, RestoreDiffer, or the error.
    Message outcome() const;

    // The write frames for `values` (any order): runs of consecutive elements as 45 (discretes,
    // <= 256) or 47 (registers, <= 64 words); the shortest runs packed into 49 mixed writes
    // (<= 32 words) wherever that saves frames.
    static std::vector<Request> writeRequests(std::uint8_t station,
                                              std::span<const SnapshotValue> values);

Q_SIGNALS:
    void progress(int done, int total);
    void finished();

private:
    void onDetailStatus(const SessionResult &result);
    // The refusal for the PLC's model, if any (sets m_refusedForModel).
    std::optional<ProtocolError> checkModel(const DetailStatus &status);
    void submitNext();
    void onWritten(const Request &request, const ChangeReport &report);
    void verify();
    void fail(ProtocolError error);

    RequestTracker m_tracker;
    SnapshotReader m_reader;
    bool m_running = false;
    std::uint8_t m_station = 1;
    std::vector<SnapshotValue> m_values;
    QString m_snapshotModel;
    QString m_plcModel;
    bool m_allowOtherModel = false;
    bool m_refusedForModel = false;
    bool m_checked = false; // the 53 is answered
    std::vector<Request> m_writes;
    std::size_t m_nextWrite = 0;
    int m_written = 0;
    std::optional<ProtocolError> m_error;
    std::vector<SnapshotDifference> m_mismatches;
};

} // namespace Fatek
