#include "plclink.h"

namespace Fatek {

void registerLinkMetaTypes()
{
    qRegisterMetaType<Fatek::WatchItemValue>();
    qRegisterMetaType<QList<Fatek::WatchItemValue>>();
}

PlcLink::PlcLink(QObject *parent)
    : QObject(parent)
{
    registerLinkMetaTypes();
}

} // namespace Fatek
