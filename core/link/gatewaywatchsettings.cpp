#include "gatewaywatchsettings.h"

#include "core/mqtt/gatewaytopics.h"
#include "linkmessages.h"

namespace Fatek {

Message GatewayWatchSettings::validate() const
{
    if (!GatewayTopics::isValidPrefix(prefix))
        return msg<MsgId::GatewayPrefixInvalid>(prefix.toStdString());
    if (!GatewayTopics::isValidConnectionName(connection))
        return msg<MsgId::GatewayNameInvalid>(connection.toStdString());
    return broker.validate();
}

} // namespace Fatek
