#pragma once

#include "clioptions.h"
#include "clioutput.h"
#include "core/protocol/request.h"
#include "core/session/requesttracker.h"
#include "core/session/session.h"

#include <QJsonObject>
#include <QObject>
#include <QTimer>

#include <memory>

namespace Fatek {

class SimServer;
class SimulatedPlc;

// What every fatek-cli command shares: the options, the output, the link (or the embedded
// simulator) with its Session, the commands' requests and the watchdog that ends the program if
// the session stays silent longer than a request could possibly take, and the exit code.
class CliContext : public QObject
{
    Q_OBJECT

public:
    using Handler = RequestTracker::Callback;

    explicit CliContext(const CliOptions &options, QObject *parent = nullptr);
    ~CliContext() override;

    // Call once the event loop runs: starts the simulator (--sim), applies --names and opens the
    // link; ready() once it is up (at once without a link: diff FILE FILE2), else finished().
    void open();

    const CliOptions &options() const { return m_options; }
    CliOutput &out() { return m_out; }
    Session *session() const { return m_session.get(); }
    RequestTracker &requests() { return m_requests; }
    std::uint8_t station() const { return m_options.station; }
    QString stationText() const;
    // The link as a script names it: "tcp://192.168.1.3:500", "serial:///dev/ttyUSB0".
    QString linkName() const;
    // {"address": ..., "station": ...}: how every JSON result names what it is about.
    QJsonObject itemJson(const Address &address) const;

    // Polling (monitor): a lost link is reported even though no request of the commands waits.
    bool isPolling() const { return m_polling; }
    void setPolling(bool polling) { m_polling = polling; }

    // Submits one of the commands' requests with the watchdog armed for it.
    void submit(const Request &request, Handler handler);
    // Submits a change to the PLC (write, RUN/STOP, set/reset/enable/disable) under the one rule
    // (ChangeVerifier): not sent once its deadline (the request budget from now) passed; `done`
    // gets a successful result when the PLC carried it out (answered, or read back afterwards);
    // a refusal ends the program with its exit code; an unknown outcome is said on stderr at
    // once, read back, and ends the program with ExitCode::Unknown if the read-back cannot tell.
    void submitChange(const Request &change, Handler done);
    // The handler, after stopping the watchdog once no other request is pending.
    Handler watched(Handler handler);
    void armWatchdog(int ms);
    void stopWatchdog();
    // How long one request may take at most (every attempt timing out, protocol probing).
    int requestBudgetMs() const;

    bool isDone() const { return m_done; }
    // Ends the program with `exitCode` (once): finished() follows at once. Ok and Differ become
    // the output's failure code when stdout could not be written (CliOutput::failureExitCode).
    void finish(int exitCode);
    // Reports a failed result (stderr / JSON) and ends with its exit code.
    void failWith(const SessionResult &result);
    void failWithError(const ProtocolError &error);
    // "Interrupted." and ExitCode::Interrupted.
    void endInterrupted();
    static int exitCodeFor(ErrorKind kind);

Q_SIGNALS:
    // The link is up (or not needed): the first step may run. Once.
    void ready();
    // The program ends with this exit code: nothing is reported any more.
    void finished(int exitCode);

private:
    bool startSimulator(QString *error);
    // --names: the names of the list into the monitor items; false (and finished) when the list
    // cannot be read.
    bool applyNames();
    void onLinkState(LinkState state, const Message &reason);
    void becomeReady();

    CliOptions m_options;
    CliOutput m_out;
    // Declaration order = reverse destruction order: the session goes first, then the simulator.
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<Session> m_session;
    RequestTracker m_requests; // the commands' own requests (not the scanner's, nor the readers')
    QTimer m_watchdog;
    bool m_ready = false;
    bool m_polling = false;
    bool m_done = false;
    int m_unknownChanges = 0; // changes sent, unanswered, their read-back still going
};

} // namespace Fatek
