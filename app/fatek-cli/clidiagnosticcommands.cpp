// fatek-cli link diagnostics: loopback, raw frames, station scan.
#include "clirunner.h"

#include "clitext.h"
#include "core/protocol/plcstatus.h"
#include "core/session/qtbytes.h"

#include <cmath>

namespace Fatek {

using namespace CliText;

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
                                      .arg(QString::fromLatin1(toQByteArray(r.response().data)));
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
