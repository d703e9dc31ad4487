// fatek-cli forced.
#include "cliforcedcommand.h"

#include "clicontext.h"
#include "clitext.h"

#include <QJsonArray>

namespace Fatek {

using namespace CliText;

void CliForcedCommand::run()
{
    const Address start = step().addresses.first();
    m_context.submit(
        Request::readEnableFlags(m_context.station(), start, step().count),
        [this, start](const SessionResult &r) {
            if (!r.ok())
                return m_context.failWith(r);
            OutputBlock block;
            block.columns
                = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("forced")};
            QJsonArray all;
            const auto &values = r.response().values;
            for (std::size_t i = 0; i < values.size(); ++i) {
                const Address a = start.advanced(static_cast<std::uint32_t>(i));
                block.rows << QStringList{m_context.stationText(), addressText(a),
                                          options().format == OutputFormat::Table
                                              ? (values[i] ? QStringLiteral("disabled (forced)")
                                                           : QStringLiteral("enabled"))
                                              : QString::number(values[i])};
                all.append(static_cast<qint64>(values[i]));
            }
            QJsonObject json = m_context.itemJson(start);
            json.insert(QStringLiteral("forced"), all);
            block.json << json;
            succeedWith(block);
        });
}

} // namespace Fatek
