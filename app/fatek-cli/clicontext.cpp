// fatek-cli: the link every command uses, the watchdog, exit codes.
#include "clicontext.h"

#include "clitext.h"
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "core/watch/symbolimport.h"

namespace Fatek {

using namespace CliText;

CliContext::CliContext(const CliOptions &options, QObject *parent)
    : QObject(parent)
    , m_options(options)
    , m_out(options.format)
{
    m_watchdog.setSingleShot(true);
    connect(&m_watchdog, &QTimer::timeout, this, [this] {
        if (m_unknownChanges > 0) {
            // Sent, unanswered, and no read-back could tell: not a failure, an open question.
            m_out.error(QStringLiteral("Outcome still unknown: the PLC did not answer the "
                                       "read-back within %1 s. Check the PLC.")
                            .arg(m_watchdog.interval() / 1000.0),
                        ExitCode::Unknown);
            return finish(ExitCode::Unknown);
        }
        m_out.error(QStringLiteral("No result within %1 s: the link stalled.")
                        .arg(m_watchdog.interval() / 1000.0),
                    ExitCode::Link);
        finish(ExitCode::Link);
    });
    // stdout failed: the program ends at once (a monitor would otherwise poll on for no reader);
    // queued, so that the command that was writing finishes its step first.
    m_out.setOnFailure([this] {
        QMetaObject::invokeMethod(
            this, [this] { finish(m_out.failureExitCode()); }, Qt::QueuedConnection);
    });
}

CliContext::~CliContext()
{
    m_session.reset();
}

bool CliContext::startSimulator(QString *error)
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_plc->setRunning(true);
    m_server = std::make_unique<SimServer>(m_plc.get());
    m_server->setStation(m_options.station == 0 ? std::uint8_t{1} : m_options.station);
    m_server->setBindAddress(QHostAddress(QHostAddress::LocalHost));
    m_server->setDemoLadder(true);
    if (!m_server->listenTcp(0, error))
        return false;
    const LinkSettings policy = m_options.link;
    m_options.link
        = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(), policy.protocol);
    m_options.link.timeoutMs = policy.timeoutMs;
    m_options.link.retries = policy.retries;
    m_options.link.autoReconnect = false;
    return true;
}

bool CliContext::applyNames()
{
    // The same import as the GUI's File > Import Names and Comments…: the items of every
    // monitor step take their address's name, which the table, CSV and data log headers show.
    const auto names = SymbolImport::fromFile(m_options.namesPath);
    if (!names) {
        m_out.error(englishText(names.error().message), ExitCode::Usage);
        finish(ExitCode::Usage);
        return false;
    }
    if (names->skipped() > 0)
        m_out.note(englishText(names->summary()));
    else if (names->imported() == 0) // an empty file, or only a header: say so, not nothing
        m_out.note(QStringLiteral("%1 names no address: the columns keep their addresses.")
                       .arg(m_options.namesPath));
    for (CliStep &s : m_options.steps) {
        for (WatchItemSpec &item : s.items) {
            if (item.name.isEmpty())
                item.name = names->symbols().name(item.address);
        }
    }
    return true;
}

void CliContext::open()
{
    registerSessionMetaTypes();
    if (m_options.offline) {
        // diff FILE FILE2: nothing to connect to.
        becomeReady();
        return;
    }
    if (m_options.sim) {
        QString error;
        if (!startSimulator(&error)) {
            m_out.error(QStringLiteral("The embedded simulator could not listen: %1").arg(error),
                        ExitCode::Internal);
            finish(ExitCode::Internal);
            return;
        }
    }
    if (const Message problem = m_options.link.validate(); !problem.empty()) {
        m_out.error(englishText(problem), ExitCode::Usage);
        finish(ExitCode::Usage);
        return;
    }
    if (!m_options.namesPath.isEmpty() && !applyNames())
        return;
    m_session = std::make_unique<Session>(m_options.link);
    m_session->setReadOnly(m_options.readOnly);
    connect(m_session.get(), &Session::linkStateChanged, this, &CliContext::onLinkState);
    m_requests.setSession(m_session.get());
    armWatchdog(m_options.link.connectTimeoutMs + 2000);
    m_session->open();
}

void CliContext::becomeReady()
{
    m_ready = true;
    Q_EMIT ready();
}

void CliContext::onLinkState(LinkState state, const Message &reason)
{
    if (m_done)
        return;
    if (state == LinkState::Connected) {
        if (!m_ready)
            becomeReady();
        return;
    }
    if (state == LinkState::Lost || (state == LinkState::Closed && !m_ready)) {
        // Requests in flight finish with LinkError and report it themselves; polling and a link
        // that never came up have nobody else to tell.
        if (!m_ready || m_polling || m_requests.pendingCount() == 0) {
            m_out.error(QStringLiteral("No connection to %1: %2")
                            .arg(m_options.link.toString(), englishText(reason)),
                        ExitCode::Link);
            finish(ExitCode::Link);
        }
    }
}

int CliContext::requestBudgetMs() const
{
    // Every attempt may time out; an undetected protocol is probed in both protocols first.
    const int attempts = m_options.link.retries + 1;
    const bool probing = m_options.link.protocol == LinkSettings::ProtocolChoice::Auto
                         && !m_session->isProtocolKnown();
    return m_options.link.timeoutMs * attempts * (probing ? 3 : 1) + 3000;
}

void CliContext::armWatchdog(int ms)
{
    m_watchdog.start(ms);
}

void CliContext::stopWatchdog()
{
    m_watchdog.stop();
}

void CliContext::submit(const Request &request, Handler handler)
{
    m_requests.submit(request, watched(std::move(handler)));
    armWatchdog(requestBudgetMs());
}

void CliContext::submitChange(const Request &change, Handler done)
{
    RequestOptions options;
    options.deadline.setRemainingTime(requestBudgetMs());
    m_requests.submitChange(
        change,
        [this, done = std::move(done)](const ChangeReport &report) {
            if (m_done)
                return;
            if (!report.final) {
                // Not a failure: say so now, and wait for the read-back's word.
                ++m_unknownChanges;
                m_out.note(englishText(report.message));
                armWatchdog(requestBudgetMs() + m_options.link.timeoutMs);
                return;
            }
            if (report.result.outcome() == ChangeOutcome::Unknown)
                --m_unknownChanges;
            if (m_requests.pendingCount() == 0)
                m_watchdog.stop();
            switch (report.outcome) {
            case ChangeOutcome::Done:
                if (!report.message.empty())
                    m_out.note(englishText(report.message));
                return done(report.result.ok() ? report.result
                                               : SessionResult(Result<Response>(Response{})));
            case ChangeOutcome::Refused:
                if (report.result.ok() || report.result.outcome() == ChangeOutcome::Unknown) {
                    // Read back: not in place.
                    m_out.error(englishText(report.message), ExitCode::Link);
                    return finish(ExitCode::Link);
                }
                return failWith(report.result);
            case ChangeOutcome::Unknown:
                m_out.error(englishText(report.message), ExitCode::Unknown);
                return finish(ExitCode::Unknown);
            }
        },
        options);
    armWatchdog(requestBudgetMs());
}

CliContext::Handler CliContext::watched(Handler handler)
{
    return [this, handler = std::move(handler)](const SessionResult &result) {
        if (m_requests.pendingCount() == 0)
            m_watchdog.stop();
        handler(result);
    };
}

int CliContext::exitCodeFor(ErrorKind kind)
{
    switch (kind) {
    case ErrorKind::PlcError: return ExitCode::Plc;
    case ErrorKind::ReadOnly: return ExitCode::ReadOnly;
    case ErrorKind::InvalidAddress:
    case ErrorKind::LimitExceeded:
    case ErrorKind::InvalidRequest:
    case ErrorKind::Unsupported: return ExitCode::Usage;
    default: return ExitCode::Link;
    }
}

void CliContext::failWith(const SessionResult &result)
{
    const int code = exitCodeFor(result.errorKind());
    QJsonObject extra;
    extra.insert(
        QStringLiteral("kind"),
        QString::fromLatin1(errorKindName(result.errorKind()).data(),
                            static_cast<qsizetype>(errorKindName(result.errorKind()).size())));
    if (result.errorKind() == ErrorKind::PlcError)
        extra.insert(QStringLiteral("plcError"),
                     QString::number(result.error().plcCode, 16).toUpper());
    QString text = result.errorText();
    if (text.isEmpty())
        text = QString::fromStdString(result.error().text());
    // A link failure names the link: a script talking to several PLCs can tell which one.
    if (code == ExitCode::Link && m_session)
        text = QStringLiteral("%1: %2").arg(linkName(), text);
    m_out.error(text, code, extra);
    finish(code);
}

void CliContext::failWithError(const ProtocolError &error)
{
    failWith(SessionResult::fromError(error));
}

void CliContext::endInterrupted()
{
    m_out.error(QStringLiteral("Interrupted."), ExitCode::Interrupted);
    finish(ExitCode::Interrupted);
}

void CliContext::finish(int exitCode)
{
    if (m_done)
        return;
    m_done = true;
    // Whatever the command made of it, output that did not arrive is not a success, nor a
    // result to act on: diff's 6 ("differences, listed") is 141 or 1 when the list was lost.
    if ((exitCode == ExitCode::Ok || exitCode == ExitCode::Differ)
        && m_out.failure() != CliOutput::Failure::None)
        exitCode = m_out.failureExitCode();
    m_watchdog.stop();
    m_requests.forgetPending(); // results that still come are not reported
    if (m_session)
        m_session->setWatchList({});
    Q_EMIT finished(exitCode);
}

QJsonObject CliContext::itemJson(const Address &address) const
{
    return {{QStringLiteral("address"), addressText(address)},
            {QStringLiteral("station"), m_options.station}};
}

QString CliContext::linkName() const
{
    return m_options.link.toUrl().section(QLatin1Char('?'), 0, 0); // without its settings
}

QString CliContext::stationText() const
{
    return QString::number(m_options.station);
}

} // namespace Fatek
