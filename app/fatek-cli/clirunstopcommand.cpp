// fatek-cli run / stop.
#include "clirunstopcommand.h"

#include "clicontext.h"

namespace Fatek {

void CliRunStopCommand::run()
{
    const bool run = step().command == CliCommandKind::Run;
    m_context.submitChange(
        Request::runStop(m_context.station(), run), [this, run](const SessionResult &) {
            const QString mode = run ? QStringLiteral("RUN") : QStringLiteral("STOP");
            OutputBlock block;
            block.columns
                = {QStringLiteral("station"), QStringLiteral("command"), QStringLiteral("result")};
            block.rows << QStringList{m_context.stationText(), mode, QStringLiteral("accepted")};
            QJsonObject json;
            json.insert(QStringLiteral("station"), m_context.station());
            json.insert(QStringLiteral("command"),
                        run ? QStringLiteral("run") : QStringLiteral("stop"));
            json.insert(QStringLiteral("ok"), true);
            block.json << json;
            succeedWith(block);
        });
}

} // namespace Fatek
