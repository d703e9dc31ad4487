#include "clirunner.h"

#include "frametext.h"
#include "modelprofile.h"
#include "plcstatus.h"
#include "simserver.h"
#include "simulatedplc.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>

#include <algorithm>
#include <array>
#include <cmath>

namespace Fatek {

namespace {

std::span<const std::uint8_t> bytesOf(const QByteArray &bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()),
            static_cast<std::size_t>(bytes.size())};
}

QString hexBytes(const Bytes &bytes)
{
    return QString::fromStdString(FrameText::toHex(bytes));
}

QString hexBytes(const QByteArray &bytes)
{
    return QString::fromStdString(FrameText::toHex(bytesOf(bytes)));
}

// Printable view of an answer: control characters as <02>, <03> ... (typed back, raw reads them).
QString asciiView(const QByteArray &bytes)
{
    return QString::fromStdString(FrameText::toAscii(bytesOf(bytes), FrameText::Controls::Hex));
}

QString addressText(const Address &address)
{
    return QString::fromStdString(address.toString());
}

QString valueHex(std::uint32_t value, const Address &address)
{
    if (isDiscrete(address.type))
        return {};
    const int digits = isDoubleWord(address.type) ? 8 : 4;
    return QStringLiteral("0x%1")
        .arg(value, digits, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

QString yesNo(bool b)
{
    return b ? QStringLiteral("yes") : QStringLiteral("no");
}

QString ms(double v)
{
    return QString::number(v, 'f', 2);
}

} // namespace

CliRunner::CliRunner(const CliOptions &options, QObject *parent)
    : QObject(parent)
    , m_options(options)
    , m_out(options.format)
{
    m_watchdog.setSingleShot(true);
    connect(&m_watchdog, &QTimer::timeout, this, [this] {
        m_out.error(QStringLiteral("No result within %1 s: the link stalled.")
                        .arg(m_watchdog.interval() / 1000.0),
                    ExitCode::Link);
        finish(ExitCode::Link);
    });
}

CliRunner::~CliRunner()
{
    // The scanner cancels through the session: drop it first.
    m_scanner.reset();
    m_session.reset();
}

bool CliRunner::startSimulator(QString *error)
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

void CliRunner::start()
{
    registerSessionMetaTypes();
    if (m_options.sim) {
        QString error;
        if (!startSimulator(&error)) {
            m_out.error(QStringLiteral("The embedded simulator could not listen: %1").arg(error),
                        ExitCode::Internal);
            finish(ExitCode::Internal);
            return;
        }
    }
    if (const QString problem = m_options.link.validate(); !problem.isEmpty()) {
        m_out.error(problem, ExitCode::Usage);
        finish(ExitCode::Usage);
        return;
    }
    m_session = std::make_unique<Session>(m_options.link);
    m_session->setReadOnly(m_options.readOnly);
    connect(m_session.get(), &Session::linkStateChanged, this, &CliRunner::onLinkState);
    m_requests.setSession(m_session.get());
    connect(m_session.get(), &Session::values, this, &CliRunner::onValues);
    armWatchdog(m_options.link.connectTimeoutMs + 2000);
    m_session->open();
}

void CliRunner::onLinkState(LinkState state, const QString &reason)
{
    if (m_done)
        return;
    if (state == LinkState::Connected) {
        if (!m_dispatched) {
            m_dispatched = true;
            dispatch();
        }
        return;
    }
    if (state == LinkState::Lost || (state == LinkState::Closed && !m_dispatched)) {
        // Requests in flight finish with LinkError and report it themselves; polling and a link
        // that never came up have nobody else to tell.
        if (!m_dispatched || m_monitoring || m_requests.pendingCount() == 0) {
            m_out.error(
                QStringLiteral("No connection to %1: %2").arg(m_options.link.toString(), reason),
                ExitCode::Link);
            finish(ExitCode::Link);
        }
    }
}

int CliRunner::requestBudgetMs() const
{
    // Every attempt may time out; an undetected protocol is probed in both protocols first.
    const int attempts = m_options.link.retries + 1;
    const bool probing = m_options.link.protocol == LinkSettings::ProtocolChoice::Auto
                         && !m_session->isProtocolKnown();
    return m_options.link.timeoutMs * attempts * (probing ? 3 : 1) + 3000;
}

void CliRunner::armWatchdog(int ms)
{
    m_watchdog.start(ms);
}

void CliRunner::submit(const Request &request, Handler handler)
{
    m_requests.submit(request, watched(std::move(handler)));
    armWatchdog(requestBudgetMs());
}

CliRunner::Handler CliRunner::watched(Handler handler)
{
    return [this, handler = std::move(handler)](const SessionResult &result) {
        if (m_requests.pendingCount() == 0)
            m_watchdog.stop();
        handler(result);
    };
}

int CliRunner::exitCodeFor(ErrorKind kind)
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

void CliRunner::failWith(const SessionResult &result)
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
        text = QString::fromStdString(result.error().message);
    m_out.error(text, code, extra);
    finish(code);
}

void CliRunner::interrupt()
{
    if (m_done)
        return;
    if (m_monitoring && step().command == CliCommand::Monitor) {
        m_monitoring = false;
        if (m_monitorErrors)
            m_out.note(QStringLiteral("Some elements were refused by the PLC (see above)."));
        if (const Status s = m_logger.close(); !s) {
            m_out.error(QString::fromStdString(s.error().message), ExitCode::Internal);
            return finish(ExitCode::Internal);
        }
        return finish(m_monitorErrors ? ExitCode::Plc : ExitCode::Ok);
    }
    m_out.error(QStringLiteral("Interrupted."), ExitCode::Interrupted);
    finish(ExitCode::Interrupted);
}

void CliRunner::finish(int exitCode)
{
    if (m_done)
        return;
    m_done = true;
    m_watchdog.stop();
    m_requests.forgetPending(); // results that still come are not reported
    if (m_scanner)
        m_scanner->cancel();
    if (m_session)
        m_session->setWatchList({});
    m_logger.close(); // a monitor ended by an error keeps the rows it logged
    Q_EMIT done(exitCode);
}

// {"address": ..., "station": ...}: how every JSON result names what it is about.
QJsonObject CliRunner::itemJson(const Address &address) const
{
    return {{QStringLiteral("address"), addressText(address)},
            {QStringLiteral("station"), m_options.station}};
}

QString CliRunner::stationText() const
{
    return QString::number(m_options.station);
}

const CliStep &CliRunner::step() const
{
    return m_options.steps.at(m_stepIndex);
}

void CliRunner::stepDone()
{
    if (m_done)
        return;
    if (m_stepIndex + 1 >= m_options.steps.size())
        return finish(ExitCode::Ok);
    ++m_stepIndex;
    dispatch();
}

void CliRunner::dispatch()
{
    switch (step().command) {
    case CliCommand::ShowStatus: runStatus(); break;
    case CliCommand::Run: runRunStop(true); break;
    case CliCommand::Stop: runRunStop(false); break;
    case CliCommand::Read: runRead(); break;
    case CliCommand::Write: runWrite(); break;
    case CliCommand::Control: runControl(); break;
    case CliCommand::Forced: runForced(); break;
    case CliCommand::Loopback: runLoopback(); break;
    case CliCommand::Monitor: runMonitor(); break;
    case CliCommand::Raw: runRaw(); break;
    case CliCommand::Scan: runScan(); break;
    }
}

// --- status ------------------------------------------------------------------------------------

void CliRunner::runStatus()
{
    submit(Request::briefStatus(m_options.station), [this](const SessionResult &brief) {
        if (!brief.ok())
            return failWith(brief);
        const Bytes briefBytes = brief.response().data;
        submit(Request::detailStatus(m_options.station), [this,
                                                          briefBytes](const SessionResult &detail) {
            if (!detail.ok() && exitCodeFor(detail.errorKind()) == ExitCode::Link)
                return failWith(detail);
            const std::uint8_t status1 = briefBytes.empty() ? 0 : briefBytes.front();
            const PlcStatus s = PlcStatus::fromStatus1(status1);
            OutputBlock block;
            block.columns = {QStringLiteral("field"), QStringLiteral("value")};
            block.tableHeader = false;
            QJsonObject json;
            auto add = [&](const QString &label, const QString &key, const QJsonValue &jsonValue,
                           const QString &text) {
                block.rows << QStringList{label, text};
                json.insert(key, jsonValue);
            };
            auto flag = [&](const QString &label, const QString &key, bool value) {
                add(label, key, value, yesNo(value));
            };
            const auto proto = protocolName(m_session->protocol());
            add(QStringLiteral("station"), QStringLiteral("station"), m_options.station,
                stationText());
            add(QStringLiteral("protocol"), QStringLiteral("protocol"),
                QString::fromLatin1(proto.data(), static_cast<qsizetype>(proto.size())),
                QString::fromLatin1(proto.data(), static_cast<qsizetype>(proto.size())));
            add(QStringLiteral("mode"), QStringLiteral("mode"),
                s.running ? QStringLiteral("RUN") : QStringLiteral("STOP"),
                s.running ? QStringLiteral("RUN") : QStringLiteral("STOP"));
            add(QStringLiteral("STATUS1"), QStringLiteral("status1"), status1,
                QStringLiteral("0x%1")
                    .arg(status1, 2, 16, QLatin1Char('0'))
                    .toUpper()
                    .replace(QLatin1String("0X"), QLatin1String("0x")));
            add(QStringLiteral("status bytes"), QStringLiteral("statusBytes"), hexBytes(briefBytes),
                hexBytes(briefBytes));
            flag(QStringLiteral("running"), QStringLiteral("running"), s.running);
            flag(QStringLiteral("battery low"), QStringLiteral("batteryLow"), s.batteryLow);
            flag(QStringLiteral("ladder checksum error"), QStringLiteral("ladderChecksumError"),
                 s.ladderChecksumError);
            flag(QStringLiteral("memory pack"), QStringLiteral("memoryPack"), s.memoryPack);
            flag(QStringLiteral("watchdog error"), QStringLiteral("watchdogError"),
                 s.watchdogError);
            flag(QStringLiteral("ID set"), QStringLiteral("idSet"), s.idSet);
            flag(QStringLiteral("emergency stop"), QStringLiteral("emergencyStop"),
                 s.emergencyStop);
            if (detail.ok()) {
                const DetailStatus d = DetailStatus::decode(detail.response().data);
                QJsonObject dj;
                block.rows << QStringList{QStringLiteral("detail"),
                                          QString::fromStdString(d.summary())};
                dj.insert(QStringLiteral("summary"), QString::fromStdString(d.summary()));
                dj.insert(QStringLiteral("raw"), hexBytes(d.raw));
                auto opt8 = [&](const QString &label, const QString &key,
                                const std::optional<std::uint8_t> &v) {
                    if (!v)
                        return;
                    block.rows << QStringList{label, QString::number(*v)};
                    dj.insert(key, *v);
                };
                auto opt16 = [&](const QString &label, const QString &key,
                                 const std::optional<std::uint16_t> &v) {
                    if (!v)
                        return;
                    block.rows << QStringList{label, QString::number(*v)};
                    dj.insert(key, *v);
                };
                opt8(QStringLiteral("main unit type"), QStringLiteral("mainUnitType"),
                     d.mainUnitType);
                opt8(QStringLiteral("I/O points code"), QStringLiteral("ioPointsCode"),
                     d.ioPointsCode);
                if (d.osVersion) {
                    const std::optional<std::string> text = d.osVersionText();
                    const QString os
                        = text ? QString::fromStdString(*text)
                               : QStringLiteral("0x%1").arg(*d.osVersion, 2, 16, QLatin1Char('0'));
                    block.rows << QStringList{QStringLiteral("OS version"), os};
                    dj.insert(QStringLiteral("osVersion"), os);
                }
                opt16(QStringLiteral("program words"), QStringLiteral("ladderSize"), d.ladderSize);
                opt16(QStringLiteral("X points"), QStringLiteral("discreteInputs"),
                      d.discreteInputs);
                opt16(QStringLiteral("Y points"), QStringLiteral("discreteOutputs"),
                      d.discreteOutputs);
                opt16(QStringLiteral("analog inputs"), QStringLiteral("analogInputs"),
                      d.analogInputs);
                opt16(QStringLiteral("analog outputs"), QStringLiteral("analogOutputs"),
                      d.analogOutputs);
                opt16(QStringLiteral("M relays"), QStringLiteral("mRelays"), d.mRelays);
                opt16(QStringLiteral("S relays"), QStringLiteral("sRelays"), d.sRelays);
                opt16(QStringLiteral("L relays"), QStringLiteral("lRelays"), d.lRelays);
                opt16(QStringLiteral("R registers"), QStringLiteral("rRegisters"), d.rRegisters);
                opt16(QStringLiteral("D registers"), QStringLiteral("dRegisters"), d.dRegisters);
                opt16(QStringLiteral("timers"), QStringLiteral("timers"), d.timers);
                opt16(QStringLiteral("counters"), QStringLiteral("counters"), d.counters);
                json.insert(QStringLiteral("detail"), dj);
            } else {
                // Some PLCs refuse 53: the brief status still stands.
                block.rows << QStringList{
                    QStringLiteral("detail"),
                    QStringLiteral("unavailable (%1)").arg(detail.errorText())};
                json.insert(QStringLiteral("detailError"), detail.errorText());
            }
            block.json << json;
            m_out.print(block);
            stepDone();
        });
    });
}

// --- run / stop ----------------------------------------------------------------------------------

void CliRunner::runRunStop(bool run)
{
    submit(Request::runStop(m_options.station, run), [this, run](const SessionResult &r) {
        if (!r.ok())
            return failWith(r);
        const QString mode = run ? QStringLiteral("RUN") : QStringLiteral("STOP");
        OutputBlock block;
        block.columns
            = {QStringLiteral("station"), QStringLiteral("command"), QStringLiteral("result")};
        block.rows << QStringList{stationText(), mode, QStringLiteral("accepted")};
        QJsonObject json;
        json.insert(QStringLiteral("station"), m_options.station);
        json.insert(QStringLiteral("command"),
                    run ? QStringLiteral("run") : QStringLiteral("stop"));
        json.insert(QStringLiteral("ok"), true);
        block.json << json;
        m_out.print(block);
        stepDone();
    });
}

// --- read / write
// ----------------------------------------------------------------------------------

void CliRunner::runRead()
{
    const Address start = step().addresses.first();
    Request request;
    if (step().mixed)
        request
            = Request::mixedRead(m_options.station, std::vector<Address>(step().addresses.begin(),
                                                                         step().addresses.end()));
    else if (isDiscrete(start.type))
        request = Request::readDiscretes(m_options.station, start, step().count);
    else
        request = Request::readRegisters(m_options.station, start, step().count);
    submit(request, [this, start](const SessionResult &r) {
        if (!r.ok())
            return failWith(r);
        const std::vector<std::uint32_t> &values = r.response().values;
        OutputBlock block;
        // Discretes have no hex view worth a column.
        const bool bitsOnly = !step().mixed && isDiscrete(start.type);
        block.columns = {QStringLiteral("address"), QStringLiteral("value"), QStringLiteral("hex")};
        if (bitsOnly)
            block.columns.removeLast();
        if (m_options.format == OutputFormat::Csv)
            block.columns
                = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("value")};
        QJsonArray all;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const Address a = step().mixed ? step().addresses.at(static_cast<qsizetype>(i))
                                           : start.advanced(static_cast<std::uint32_t>(i));
            const QString v = QString::number(values[i]);
            if (m_options.format == OutputFormat::Csv)
                block.rows << QStringList{stationText(), addressText(a), v};
            else
                block.rows << (bitsOnly ? QStringList{addressText(a), v}
                                        : QStringList{addressText(a), v, valueHex(values[i], a)});
            all.append(static_cast<qint64>(values[i]));
            if (step().mixed) {
                QJsonObject json = itemJson(a);
                json.insert(QStringLiteral("values"), QJsonArray{static_cast<qint64>(values[i])});
                block.json << json;
            }
        }
        if (!step().mixed) {
            QJsonObject json = itemJson(start);
            json.insert(QStringLiteral("values"), all);
            block.json << json;
        }
        m_out.print(block);
        stepDone();
    });
}

void CliRunner::runWrite()
{
    const Address start = step().addresses.first();
    const Request request = isDiscrete(start.type)
                                ? Request::writeDiscretes(m_options.station, start, step().values)
                                : Request::writeRegisters(m_options.station, start, step().values);
    submit(request, [this, start](const SessionResult &r) {
        if (!r.ok())
            return failWith(r);
        OutputBlock block;
        block.columns
            = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("written")};
        QJsonArray all;
        for (std::size_t i = 0; i < step().values.size(); ++i) {
            const Address a = start.advanced(static_cast<std::uint32_t>(i));
            block.rows << QStringList{stationText(), addressText(a),
                                      QString::number(step().values[i])};
            all.append(static_cast<qint64>(step().values[i]));
        }
        QJsonObject json = itemJson(start);
        json.insert(QStringLiteral("written"), all);
        block.json << json;
        m_out.print(block);
        stepDone();
    });
}

void CliRunner::runControl()
{
    const Address a = step().addresses.first();
    const auto op = static_cast<DiscreteOp>(step().controlOp);
    submit(
        Request::discreteControl(m_options.station, op, a), [this, a, op](const SessionResult &r) {
            if (!r.ok())
                return failWith(r);
            const auto name = discreteOpName(op);
            const QString action
                = QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
            OutputBlock block;
            block.columns
                = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("action")};
            block.rows << QStringList{stationText(), addressText(a), action};
            QJsonObject json = itemJson(a);
            json.insert(QStringLiteral("action"), action);
            json.insert(QStringLiteral("ok"), true);
            block.json << json;
            m_out.print(block);
            stepDone();
        });
}

void CliRunner::runForced()
{
    const Address start = step().addresses.first();
    submit(Request::readEnableFlags(m_options.station, start, step().count),
           [this, start](const SessionResult &r) {
               if (!r.ok())
                   return failWith(r);
               OutputBlock block;
               block.columns = {QStringLiteral("station"), QStringLiteral("address"),
                                QStringLiteral("forced")};
               QJsonArray all;
               const auto &values = r.response().values;
               for (std::size_t i = 0; i < values.size(); ++i) {
                   const Address a = start.advanced(static_cast<std::uint32_t>(i));
                   block.rows << QStringList{stationText(), addressText(a),
                                             m_options.format == OutputFormat::Table
                                                 ? (values[i] ? QStringLiteral("disabled (forced)")
                                                              : QStringLiteral("enabled"))
                                                 : QString::number(values[i])};
                   all.append(static_cast<qint64>(values[i]));
               }
               QJsonObject json = itemJson(start);
               json.insert(QStringLiteral("forced"), all);
               block.json << json;
               m_out.print(block);
               stepDone();
           });
}

// --- loopback
// --------------------------------------------------------------------------------------

void CliRunner::runLoopback()
{
    m_loopStats.reset();
    m_loopLastError.clear();
    loopbackNext();
}

void CliRunner::loopbackNext()
{
    // One run at a time: every run sent so far has its outcome.
    const int sent = m_loopStats.runs();
    if (sent >= m_options.loopbackCount) {
        OutputBlock block;
        block.columns = {QStringLiteral("field"), QStringLiteral("value")};
        block.tableHeader = false;
        const double min = m_loopStats.minMs();
        const double mean = m_loopStats.meanMs();
        const double max = m_loopStats.maxMs();
        const int ok = m_loopStats.successes();
        block.rows << QStringList{QStringLiteral("station"), stationText()}
                   << QStringList{QStringLiteral("sent"), QString::number(sent)}
                   << QStringList{QStringLiteral("ok"), QString::number(ok)}
                   << QStringList{QStringLiteral("mismatches"),
                                  QString::number(m_loopStats.mismatches())}
                   << QStringList{QStringLiteral("timeouts"),
                                  QString::number(m_loopStats.timeouts())}
                   << QStringList{QStringLiteral("min ms"), ms(min)}
                   << QStringList{QStringLiteral("mean ms"), ms(mean)}
                   << QStringList{QStringLiteral("max ms"), ms(max)};
        QJsonObject json;
        json.insert(QStringLiteral("station"), m_options.station);
        json.insert(QStringLiteral("sent"), sent);
        json.insert(QStringLiteral("ok"), ok);
        json.insert(QStringLiteral("mismatches"), m_loopStats.mismatches());
        json.insert(QStringLiteral("timeouts"), m_loopStats.timeouts());
        // Microsecond resolution is all a round trip measurement can claim.
        auto rounded = [](double v) {
            return std::round(v * 1000.0) / 1000.0;
        };
        json.insert(QStringLiteral("minMs"), rounded(min));
        json.insert(QStringLiteral("meanMs"), rounded(mean));
        json.insert(QStringLiteral("maxMs"), rounded(max));
        block.json << json;
        m_out.print(block);
        if (ok == sent)
            return stepDone();
        m_out.note(QStringLiteral("%1 of %2 round trips failed%3")
                       .arg(sent - ok)
                       .arg(sent)
                       .arg(m_loopLastError.isEmpty()
                                ? QString()
                                : QStringLiteral(" (last: %1)").arg(m_loopLastError)));
        return finish(ExitCode::Link);
    }
    const Bytes data(step().loopbackData.begin(), step().loopbackData.end());
    submit(Request::loopback(m_options.station, data), [this, data](const SessionResult &r) {
        if (r.ok()) {
            // The round trip on the wire (statistics are published before the result).
            const double rttMs = m_session->statistics().total.rttLastMs;
            if (r.response().data == data) {
                m_loopStats.add(LoopbackStats::Outcome::Success, rttMs);
            } else {
                m_loopStats.add(LoopbackStats::Outcome::Mismatch, rttMs);
                m_loopLastError = QStringLiteral("echo \"%1\" differs from what was sent")
                                      .arg(QString::fromLatin1(
                                          reinterpret_cast<const char *>(r.response().data.data()),
                                          static_cast<qsizetype>(r.response().data.size())));
            }
        } else if (r.errorKind() == ErrorKind::Timeout) {
            m_loopStats.add(LoopbackStats::Outcome::Timeout);
            m_loopLastError = r.errorText();
        } else {
            return failWith(r);
        }
        loopbackNext();
    });
}

// --- monitor
// -----------------------------------------------------------------------------------------

void CliRunner::runMonitor()
{
    m_cycle = 0;
    m_staleCycles = 0;
    m_monitorErrors = false;
    m_monitoring = true;
    QList<WatchEntry> entries;
    QStringList columns{QStringLiteral("cycle"), QStringLiteral("time")};
    QList<int> widths{5, 12};
    const QList<WatchItemSpec> &items = step().items;
    m_monitorItems.clear();
    m_monitorIds.clear();
    for (qsizetype i = 0; i < items.size(); ++i) {
        const WatchItemSpec &item = items.at(i);
        // A float over R100 polls R100 and R101: one entry per element.
        const ItemValues &values = m_monitorItems.emplace_back(item);
        for (const std::uint64_t id : values.pollIds())
            m_monitorIds.insert(id, i);
        entries += values.pollEntries(m_options.intervalMs);
        columns << addressText(item.address);
        const int width = values.width();
        widths << (width == 1 ? 1 : width <= 16 ? 6 : 12);
    }
    if (!m_options.outputPath.isEmpty() && !m_logger.isOpen()) {
        // Every row reaches the disk at once: an interrupted monitor loses nothing.
        m_logger.setFlushIntervalMs(0);
        if (const Status s = m_logger.open(m_options.outputPath, items); !s) {
            m_out.error(QString::fromStdString(s.error().message), ExitCode::Usage);
            return finish(ExitCode::Usage);
        }
    }
    if (m_options.format == OutputFormat::Csv)
        m_out.line(DataLogger::headerLine(items));
    else
        m_out.beginStream(columns, widths);
    armWatchdog(m_options.intervalMs
                + requestBudgetMs() * (1 + static_cast<int>(entries.size()) / 16));
    m_session->setWatchList(entries);
}

void CliRunner::onValues(const QList<WatchValue> &values)
{
    if (m_done || !m_monitoring || step().command != CliCommand::Monitor)
        return;
    ++m_cycle;
    const QList<WatchItemSpec> &items = step().items;
    // Join the elements of each item back into one value; its quality is the worst part's.
    QList<DataLogger::Cell> cells(items.size());
    QList<int> partsSeen(items.size(), 0);
    std::vector<std::array<std::uint32_t, ItemValues::MaxElements>> words(
        static_cast<std::size_t>(items.size()));
    for (DataLogger::Cell &c : cells)
        c.quality = DataLogger::Quality::Good;
    for (const WatchValue &v : values) {
        const qsizetype item = m_monitorIds.value(v.itemId, -1);
        const int part
            = item < 0 || item >= items.size()
                  ? -1
                  : m_monitorItems.at(static_cast<std::size_t>(item)).elementOf(v.itemId);
        if (part < 0)
            continue;
        DataLogger::Cell &cell = cells[item];
        ++partsSeen[item];
        words[static_cast<std::size_t>(item)][static_cast<std::size_t>(part)] = v.value;
        if (v.quality == ValueQuality::Error) {
            cell.quality = DataLogger::Quality::Error;
            cell.reason = v.error;
        } else if (v.quality == ValueQuality::Stale && cell.quality == DataLogger::Quality::Good) {
            cell.quality = DataLogger::Quality::Stale;
            cell.reason = v.error;
        }
    }
    const QDateTime now = QDateTime::currentDateTime();
    QStringList tableCells{QString::number(m_cycle), now.toString(QStringLiteral("HH:mm:ss.zzz"))};
    QJsonArray jsonValues, jsonTexts, jsonAddresses;
    bool anyGood = false;
    QString staleReason;
    for (qsizetype i = 0; i < items.size(); ++i) {
        DataLogger::Cell &cell = cells[i];
        const WatchItemSpec &item = items.at(i);
        const ItemValues &itemValues = m_monitorItems.at(static_cast<std::size_t>(i));
        cell.raw = itemValues.join(words[static_cast<std::size_t>(i)]);
        if (partsSeen.at(i) < itemValues.elementCount()
            && cell.quality == DataLogger::Quality::Good) {
            cell.quality = DataLogger::Quality::Missing;
            cell.reason = QStringLiteral("no value this cycle");
        }
        const QString name = addressText(item.address);
        jsonAddresses.append(name);
        if (cell.quality == DataLogger::Quality::Good) {
            anyGood = true;
            const QString text = DataLogger::valueText(item, cell.raw);
            tableCells << text;
            jsonValues.append(static_cast<qint64>(cell.raw));
            jsonTexts.append(text);
            continue;
        }
        tableCells << QStringLiteral("?");
        jsonValues.append(QJsonValue::Null);
        jsonTexts.append(QJsonValue::Null);
        if (cell.quality == DataLogger::Quality::Error)
            m_monitorErrors = true;
        else
            staleReason = cell.reason;
        if (!m_reported.contains(name + cell.reason)) {
            m_reported.insert(name + cell.reason);
            m_out.note(QStringLiteral("%1: %2").arg(name, cell.reason));
        }
    }
    if (m_logger.isOpen()) {
        if (const Status s = m_logger.writeRow(now, cells); !s) {
            m_out.error(QString::fromStdString(s.error().message), ExitCode::Internal);
            return finish(ExitCode::Internal);
        }
    }
    QJsonObject json;
    json.insert(QStringLiteral("cycle"), m_cycle);
    json.insert(QStringLiteral("time"), now.toString(Qt::ISODateWithMs));
    json.insert(QStringLiteral("station"), m_options.station);
    json.insert(QStringLiteral("addresses"), jsonAddresses);
    json.insert(QStringLiteral("values"), jsonValues);
    json.insert(QStringLiteral("text"), jsonTexts);
    if (m_options.format == OutputFormat::Csv)
        m_out.line(DataLogger::rowLine(now, items, cells));
    else
        m_out.streamRow(tableCells, json);

    // Nothing read for three cycles in a row: the link is gone for practical purposes.
    m_staleCycles = (!anyGood && !staleReason.isEmpty()) ? m_staleCycles + 1 : 0;
    if (m_staleCycles >= 3) {
        m_out.error(QStringLiteral("Nothing read for 3 cycles: %1").arg(staleReason),
                    ExitCode::Link);
        return finish(ExitCode::Link);
    }
    if (m_options.cycles > 0 && m_cycle >= m_options.cycles) {
        if (m_monitorErrors)
            m_out.note(QStringLiteral("Some elements were refused by the PLC (see above)."));
        if (m_monitorErrors)
            return finish(ExitCode::Plc);
        m_session->setWatchList({});
        m_monitoring = false;
        if (const Status s = m_logger.close(); !s) {
            m_out.error(QString::fromStdString(s.error().message), ExitCode::Internal);
            return finish(ExitCode::Internal);
        }
        return stepDone();
    }
    armWatchdog(m_options.intervalMs
                + requestBudgetMs() * (1 + static_cast<int>(step().addresses.size()) / 16));
}

// --- raw
// ------------------------------------------------------------------------------------------------

void CliRunner::runRaw()
{
    {
        const quint64 before = m_session->trafficLog()->entries().isEmpty()
                                   ? 0
                                   : m_session->trafficLog()->entries().constLast().sequence;
        RequestOptions options;
        options.station = m_options.station;
        // Under auto-detect the bytes say which framing is meant (hex: binary bytes, text: FACON
        // characters), so no status probe goes before the frame.
        if (step().rawFrame && m_options.link.protocol == LinkSettings::ProtocolChoice::Auto
            && !m_session->isProtocolKnown())
            options.framing = step().rawHex ? Protocol::Binary : Protocol::Facon;
        auto onResult = [this, before](const SessionResult &r) {
            if (!r.ok())
                return failWith(r);
            // What actually went out (with framing and checksum when --frame was given).
            QByteArray sent = step().rawBytes;
            for (const TrafficEntry &e : m_session->trafficLog()->entries(before)) {
                if (e.direction == TrafficEntry::Direction::Out)
                    sent = e.bytes;
            }
            OutputBlock block;
            block.columns = {QStringLiteral("field"), QStringLiteral("value")};
            block.tableHeader = false;
            block.rows << QStringList{QStringLiteral("sent"), hexBytes(sent)}
                       << QStringList{QStringLiteral("sent text"), asciiView(sent)}
                       << QStringList{QStringLiteral("answer"), hexBytes(r.rawAnswer())}
                       << QStringList{QStringLiteral("answer text"), asciiView(r.rawAnswer())};
            QJsonObject json;
            json.insert(QStringLiteral("sent"), hexBytes(sent));
            json.insert(QStringLiteral("answer"), hexBytes(r.rawAnswer()));
            json.insert(QStringLiteral("answerText"), asciiView(r.rawAnswer()));
            block.json << json;
            m_out.print(block);
            stepDone();
        };
        m_requests.sendRaw(step().rawBytes, step().rawFrame, watched(std::move(onResult)), options);
        armWatchdog(requestBudgetMs());
    }
}

// --- scan
// -------------------------------------------------------------------------------------------------

void CliRunner::runScan()
{
    m_scanner = std::make_unique<StationScanner>(m_session.get());
    const int timeout = m_options.timeoutGiven ? m_options.link.timeoutMs : 100;
    const int perStation
        = timeout * (m_options.link.protocol == LinkSettings::ProtocolChoice::Auto ? 2 : 1) + 1000;
    connect(m_scanner.get(), &StationScanner::progress, this,
            [this, perStation](int, int) { armWatchdog(perStation + 2000); });
    connect(m_scanner.get(), &StationScanner::finished, this,
            [this](const QList<StationScanner::Hit> &hits) {
                if (m_done)
                    return;
                OutputBlock block;
                block.columns = {QStringLiteral("station"), QStringLiteral("mode"),
                                 QStringLiteral("status bytes")};
                for (const StationScanner::Hit &hit : hits) {
                    const QString mode
                        = hit.status.running ? QStringLiteral("RUN") : QStringLiteral("STOP");
                    block.rows << QStringList{QString::number(hit.station), mode,
                                              hexBytes(hit.statusBytes)};
                    QJsonObject json;
                    json.insert(QStringLiteral("station"), hit.station);
                    json.insert(QStringLiteral("mode"), mode);
                    json.insert(QStringLiteral("running"), hit.status.running);
                    json.insert(QStringLiteral("status1"), hit.status.toStatus1());
                    json.insert(QStringLiteral("statusBytes"), hexBytes(hit.statusBytes));
                    block.json << json;
                }
                if (hits.isEmpty()) {
                    m_out.error(QStringLiteral("No station answered in %1..%2.")
                                    .arg(step().scanFirst)
                                    .arg(step().scanLast),
                                ExitCode::Link);
                    return finish(ExitCode::Link);
                }
                m_out.print(block);
                stepDone();
            });
    armWatchdog(perStation + 2000);
    m_scanner->start(step().scanFirst, step().scanLast, timeout);
}

} // namespace Fatek
