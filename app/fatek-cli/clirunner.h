#pragma once

#include "clioptions.h"
#include "clioutput.h"
#include "core/commission/programtransfer.h"
#include "core/commission/snapshotdiff.h"
#include "core/commission/snapshotfile.h"
#include "core/protocol/request.h"
#include "core/session/loopbackstats.h"
#include "core/session/requesttracker.h"
#include "core/session/session.h"
#include "core/session/stationscanner.h"
#include "core/watch/datalogger.h"
#include "core/watch/itemassembler.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QSet>
#include <QTimer>

#include <functional>
#include <memory>
#include <vector>

namespace Fatek {

class SimServer;
class SimulatedPlc;
class SnapshotReader;
class ValuesRestorer;

// Runs one command: opens the link (or the embedded simulator), submits the command's requests to
// a Session and reacts to its signals; done() carries the exit code. Never blocks: a watchdog
// ends the program if the session stays silent longer than the request could possibly take.
class CliRunner : public QObject
{
    Q_OBJECT

public:
    explicit CliRunner(const CliOptions &options, QObject *parent = nullptr);
    ~CliRunner() override;

    // Call once the event loop runs (done() may follow at once).
    void start();
    // Ctrl-C / SIGTERM: a monitor ends as if its last cycle had come (exit 0, the data log
    // closed); any other command ends with ExitCode::Interrupted. Writes already accepted are
    // still sent when the session closes.
    void interrupt();

Q_SIGNALS:
    void done(int exitCode);

private:
    using Handler = RequestTracker::Callback;

    bool startSimulator(QString *error);
    // --names: the names of the list into the monitor items; false (and finished) when the list
    // cannot be read.
    bool applyNames();
    void onLinkState(LinkState state, const Message &reason);
    void onValues(const QList<WatchValue> &values);
    void dispatch();
    const CliStep &step() const;
    // The current command succeeded: run the next one or end with 0.
    void stepDone();

    void submit(const Request &request, Handler handler);
    // The handler, after stopping the watchdog once no other request is pending.
    Handler watched(Handler handler);
    void armWatchdog(int ms);
    int requestBudgetMs() const;
    void finish(int exitCode);
    // Reports a failed result (stderr / JSON) and ends with its exit code.
    void failWith(const SessionResult &result);
    static int exitCodeFor(ErrorKind kind);

    void runStatus();
    void runRunStop(bool run);
    void runRead();
    void runWrite();
    void runControl();
    void runForced();
    void runLoopback();
    void loopbackNext();
    void runMonitor();
    void runRaw();
    void runScan();
    void runBackup();
    void runRestore();
    // Restore, once the PLC's program is compared with the file: ask, then write.
    void confirmRestore(const ProgramImage &image, const ProgramTransferResult &check);
    void startTransfer();
    void showTransferProgress(int done, int total);
    // A backup, check or restore that did not succeed: its message and exit code.
    void failTransfer(const ProgramTransferResult &result);
    void runSnapshot();
    void runDiff();
    void runRestoreValues();
    // snapshot, diff, restore-values: a reader on the session, the watchdog re-armed on progress.
    SnapshotReader *snapshotReader();
    // A snapshot file, or nothing after reporting why not (exit 2).
    std::optional<MemorySnapshot> loadSnapshot(const QString &path);
    // One line (table, CSV row, JSON object) per difference.
    void printDifferences(const std::vector<SnapshotDifference> &differences, bool readBack);
    void failWithError(const ProtocolError &error);

    QString stationText() const;
    QJsonObject itemJson(const Address &address) const;

    CliOptions m_options;
    CliOutput m_out;
    // Declaration order = reverse destruction order: the session goes first, then the simulator.
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<Session> m_session;
    std::unique_ptr<StationScanner> m_scanner;
    std::unique_ptr<SnapshotReader> m_snapshotReader;
    std::unique_ptr<ValuesRestorer> m_restorer;
    RequestTracker m_requests; // the commands' own requests (not the scanner's)
    QTimer m_watchdog;
    qsizetype m_stepIndex = 0;
    bool m_dispatched = false;
    bool m_monitoring = false;
    bool m_done = false;

    // loopback (counted as the GUI's loopback dialog counts)
    LoopbackStats m_loopStats;
    QString m_loopLastError;

    // monitor
    int m_cycle = 0;
    int m_staleCycles = 0;
    bool m_monitorErrors = false;
    QSet<QString> m_reported;
    DataLogger m_logger;          // --output
    ItemAssembler m_monitorItems; // step().items (keys: their indexes), their elements joined

    // backup / restore
    std::unique_ptr<ProgramTransfer> m_program;
    bool m_progressShown = false;
    bool m_interrupted = false;
};

} // namespace Fatek
