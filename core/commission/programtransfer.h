#pragma once

#include "core/protocol/plcstatus.h"
#include "core/protocol/protocolerror.h"
#include "core/session/requesttracker.h"
#include "programimage.h"

#include <QElapsedTimer>
#include <QMetaType>
#include <QObject>

#include <optional>
#include <string>
#include <vector>

namespace Fatek {

class Session;

// How a backup, a restore check or a restore ended.
struct ProgramTransferResult
{
    enum class Status { Ok, Failed, Cancelled };
    // What went wrong, for callers that react (a UI offering STOP, a CLI's exit code).
    enum class Problem {
        None,
        NoSession,     // no session, or it went away
        Busy,          // another transfer runs on this object
        ReadOnly,      // operator mode: a restore writes nothing
        Running,       // restore needs STOP
        NoSize,        // 53 gave no program size
        NoHeader,      // the PLC's page 0 is not a program header (backup)
        ModelMismatch, // the backup's family / capacity differ from the PLC's
        Request,       // a request failed: see errorKind
        VerifyFailed,  // pages read back differ: see pages
        Cancelled,
    };

    Status status = Status::Ok;
    Problem problem = Problem::None;
    ErrorKind errorKind = ErrorKind::Cancelled; // for Problem::Request (and ReadOnly)
    Message message;                            // the outcome, for the person
    // Restore check: pages that differ between the backup and the PLC; verification: the pages
    // that still differ after writing.
    std::vector<std::uint16_t> pages;
    int pagesDone = 0;      // pages read (backup, check) or written (restore)
    int pagesTotal = 0;     // pages of the program
    int stoppedAtPage = -1; // cancelled or failed: the page that was not done

    bool ok() const { return status == Status::Ok; }
};

// Backs up a PLC's program to a ProgramImage and restores one, over FACON 4F/50, on a Session
// through a RequestTracker: one page request at a time, never blocking; progress() after every
// page, finished() once at the end. cancel() stops between pages.
//
//   backup():        53 (program size), then 4F pages 0..N
//   checkRestore():  refused in operator mode; 40, 53, 4F pages 0..N, model check: finished()
//                    lists the pages that differ (nothing is written). In RUN only page 0 is
//                    read: a backup of another model is refused as such, then RUN is refused
//   restore():       refused in operator mode; 40, 53 and 4F page 0 (model check, then RUN
//                    refused), 50 pages 0..N, then 4F every page back and compare
class ProgramTransfer : public QObject
{
    Q_OBJECT

public:
    enum class Phase { Idle, Checking, Reading, Writing, Verifying };
    Q_ENUM(Phase)

    explicit ProgramTransfer(QObject *parent = nullptr);
    ~ProgramTransfer() override;

    void setSession(Session *session);
    Session *session() const { return m_tracker.session(); }
    void setStation(std::uint8_t station) { m_station = station; }
    std::uint8_t station() const { return m_station; }

    // Each returns false (and emits nothing) while a transfer runs.
    bool backup();
    bool checkRestore(const ProgramImage &image);
    bool restore(const ProgramImage &image);
    // Stops after the page in flight; finished() says how far it got.
    void cancel();

    bool isRunning() const { return m_phase != Phase::Idle; }
    Phase phase() const { return m_phase; }
    // The program read by the last backup or restore check.
    const ProgramImage &plcImage() const { return m_plcImage; }
    const ProgramTransferResult &lastResult() const { return m_result; }

    // The words for a phase ("Reading the program"), for progress texts.
    static Message phaseMessage(Phase phase);

Q_SIGNALS:
    void phaseChanged(Fatek::ProgramTransfer::Phase phase);
    // Pages done of the whole operation (a restore counts writing and verifying).
    void progress(int done, int total);
    void finished(const Fatek::ProgramTransferResult &result);

private:
    enum class Job { Backup, Check, Restore };

    bool start(Job job);
    void setPhase(Phase phase);
    void submit(const Request &request, RequestTracker::Callback callback);
    void readStatus();
    void readSize();
    void readPage(std::uint16_t page);
    void afterRead();
    void writePage(std::uint16_t page);
    void verifyPage(std::uint16_t page);
    void verified();
    void emitProgress();
    // The request failed: finish with the error for `page` (-1: a status request).
    void failRequest(const SessionResult &result, int page, bool writing);
    void fail(ProgramTransferResult::Problem problem, Message message,
              ErrorKind kind = ErrorKind::Cancelled);
    // true (and finished) if cancel() was asked.
    bool stopIfCancelled(int page);
    void finish(ProgramTransferResult result);

    RequestTracker m_tracker;
    std::uint8_t m_station = 1;
    Job m_job = Job::Backup;
    Phase m_phase = Phase::Idle;
    bool m_cancel = false;

    ProgramImage m_image; // restore: what is written
    ProgramImage m_plcImage;
    std::vector<ProgramPage> m_pages; // pages read so far
    std::uint16_t m_pageCount = 0;
    DetailStatus m_detail;                     // 53 of this transfer
    std::optional<std::string> m_plcModelName; // 53's model ("FBs-28MC"), when it names one
    bool m_running = false;                    // restore: 40 said RUN (refused after the checks)
    int m_done = 0;
    int m_total = 0;
    std::vector<std::uint16_t> m_badPages;
    ProgramTransferResult m_result;
};

void registerProgramTransferMetaTypes();

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::ProgramTransferResult)
