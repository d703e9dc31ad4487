#include "gatewayconfigreader.h"

#include "gatewaymessages.h"

#include <QDir>
#include <QStringList>

#include <cmath>
#include <limits>

namespace Fatek::GatewayConfigRead {

Message at(Message place, Message error)
{
    return msg<MsgId::AtPlace>(std::move(place), std::move(error));
}

QString resolve(const QString &baseDirectory, const QString &file)
{
    return QDir(baseDirectory).absoluteFilePath(file);
}

} // namespace Fatek::GatewayConfigRead
