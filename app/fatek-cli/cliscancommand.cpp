// fatek-cli scan.
#include "cliscancommand.h"

#include "app/common/linkarguments.h"
#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"

#include <QRegularExpression>

namespace Fatek {

using namespace CliText;

// scan [FROM..TO]
QString CliScanCommand::parse(CliStepArgs &a)
{
    if (a.positional.isEmpty())
        return {};
    static const QRegularExpression range(QStringLiteral("^(\\d+)(?:\\.\\.(\\d+))?$"));
    const auto m = range.match(a.positional.at(0).trimmed());
    qint64 first = 0, last = 0;
    if (!m.hasMatch() || !parseIntInRange(m.captured(1), 1, Limits::maxStation, &first)
        || !parseIntInRange(m.captured(2).isEmpty() ? m.captured(1) : m.captured(2), 1,
                            Limits::maxStation, &last)
        || last < first)
        return QStringLiteral("scan takes a station range like 1..16 (1..254), not \"%1\".")
            .arg(a.positional.at(0));
    a.step.scanFirst = static_cast<int>(first);
    a.step.scanLast = static_cast<int>(last);
    return {};
}

void CliScanCommand::run()
{
    m_scanner = std::make_unique<StationScanner>(m_context.session());
    const int timeout = options().timeoutGiven ? options().link.timeoutMs : 100;
    const int perStation
        = timeout * (options().link.protocol == LinkSettings::ProtocolChoice::Auto ? 2 : 1) + 1000;
    connect(m_scanner.get(), &StationScanner::progress, this,
            [this, perStation](int, int) { m_context.armWatchdog(perStation + 2000); });
    connect(m_scanner.get(), &StationScanner::finished, this,
            [this](const QList<StationScanner::Hit> &hits) {
                if (m_context.isDone())
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
                    out().error(QStringLiteral("No station answered in %1..%2.")
                                    .arg(step().scanFirst)
                                    .arg(step().scanLast),
                                ExitCode::Link);
                    return m_context.finish(ExitCode::Link);
                }
                succeedWith(block);
            });
    m_context.armWatchdog(perStation + 2000);
    m_scanner->start(step().scanFirst, step().scanLast, timeout);
}

void CliScanCommand::abandon()
{
    if (m_scanner)
        m_scanner->cancel();
}

} // namespace Fatek
