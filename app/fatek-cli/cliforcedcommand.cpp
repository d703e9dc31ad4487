// fatek-cli forced.
#include "cliforcedcommand.h"

#include "clicontext.h"

namespace Fatek {

void CliForcedCommand::run()
{
    const Address start = step().addresses.first();
    m_context.submit(Request::readEnableFlags(m_context.station(), start, step().count),
                     [this, start](const SessionResult &r) {
                         if (!r.ok())
                             return m_context.failWith(r);
                         const bool table = options().format == OutputFormat::Table;
                         succeedWithElements(start, r.response().values, QStringLiteral("forced"),
                                             [table](std::uint32_t forced) {
                                                 if (!table)
                                                     return QString::number(forced);
                                                 return forced ? QStringLiteral("disabled (forced)")
                                                               : QStringLiteral("enabled");
                                             });
                     });
}

} // namespace Fatek
