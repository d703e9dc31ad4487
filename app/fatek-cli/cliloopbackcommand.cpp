// fatek-cli loopback.
#include "cliloopbackcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/session/qtbytes.h"

#include <cmath>

namespace Fatek {

using namespace CliText;

// loopback [TEXT]
QString CliLoopbackCommand::parse(CliStepArgs &a)
{
    const QString text = a.positional.isEmpty() ? QStringLiteral("FATEK-CLI")
                                                : a.positional.join(QLatin1Char(' '));
    a.step.loopbackData = text.toLatin1();
    if (a.step.loopbackData.isEmpty()
        || static_cast<std::uint32_t>(a.step.loopbackData.size()) > Limits::maxLoopback)
        return QStringLiteral("loopback TEXT must be 1..%1 characters.").arg(Limits::maxLoopback);
    return {};
}

void CliLoopbackCommand::run()
{
    m_stats.reset();
    m_lastError.clear();
    next();
}

void CliLoopbackCommand::next()
{
    // One run at a time: every run sent so far has its outcome.
    const int sent = m_stats.runs();
    if (sent >= options().loopbackCount) {
        OutputBlock block;
        block.columns = {QStringLiteral("field"), QStringLiteral("value")};
        block.tableHeader = false;
        const double min = m_stats.minMs();
        const double mean = m_stats.meanMs();
        const double max = m_stats.maxMs();
        const int ok = m_stats.successes();
        block.rows << QStringList{QStringLiteral("station"), m_context.stationText()}
                   << QStringList{QStringLiteral("sent"), QString::number(sent)}
                   << QStringList{QStringLiteral("ok"), QString::number(ok)}
                   << QStringList{QStringLiteral("mismatches"),
                                  QString::number(m_stats.mismatches())}
                   << QStringList{QStringLiteral("timeouts"), QString::number(m_stats.timeouts())}
                   << QStringList{QStringLiteral("min ms"), ms(min)}
                   << QStringList{QStringLiteral("mean ms"), ms(mean)}
                   << QStringList{QStringLiteral("max ms"), ms(max)};
        QJsonObject json;
        json.insert(QStringLiteral("station"), m_context.station());
        json.insert(QStringLiteral("sent"), sent);
        json.insert(QStringLiteral("ok"), ok);
        json.insert(QStringLiteral("mismatches"), m_stats.mismatches());
        json.insert(QStringLiteral("timeouts"), m_stats.timeouts());
        // Microsecond resolution is all a round trip measurement can claim.
        auto rounded = [](double v) {
            return std::round(v * 1000.0) / 1000.0;
        };
        json.insert(QStringLiteral("minMs"), rounded(min));
        json.insert(QStringLiteral("meanMs"), rounded(mean));
        json.insert(QStringLiteral("maxMs"), rounded(max));
        block.json << json;
        out().print(block);
        if (ok == sent)
            return succeed();
        out().note(QStringLiteral("%1 of %2 round trips failed%3")
                       .arg(sent - ok)
                       .arg(sent)
                       .arg(m_lastError.isEmpty()
                                ? QString()
                                : QStringLiteral(" (last: %1)").arg(m_lastError)));
        return m_context.finish(ExitCode::Link);
    }
    const Bytes data(step().loopbackData.begin(), step().loopbackData.end());
    m_context.submit(
        Request::loopback(m_context.station(), data), [this, data](const SessionResult &r) {
            if (r.ok()) {
                // The round trip on the wire (statistics are published before the result).
                const double rttMs = m_context.session()->statistics().total.rttLastMs;
                if (r.response().data == data) {
                    m_stats.add(LoopbackStats::Outcome::Success, rttMs);
                } else {
                    m_stats.add(LoopbackStats::Outcome::Mismatch, rttMs);
                    m_lastError = QStringLiteral("echo \"%1\" differs from what was sent")
                                      .arg(QString::fromLatin1(toQByteArray(r.response().data)));
                }
            } else if (r.errorKind() == ErrorKind::Timeout) {
                m_stats.add(LoopbackStats::Outcome::Timeout);
                m_lastError = r.errorText();
            } else {
                return m_context.failWith(r);
            }
            next();
        });
}

} // namespace Fatek
