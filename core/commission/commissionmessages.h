#pragma once

// The messages of commissioning (program backup and restore, snapshots, differences, restores of
// values): the ids of commissionmessagelist.h, in the namespace MsgId.
// core/protocol/message.h explains the ids and their lists. Include this header where one of them
// is used; a new message of this library goes into commissionmessagelist.h.
#include "core/protocol/message.h"

namespace Fatek {

namespace MsgId {
#define FATEK_MSG FATEK_MSG_DEFINE
#ifndef Q_MOC_RUN
#include "commissionmessagelist.h"
#endif
#undef FATEK_MSG
} // namespace MsgId

// Every id of commissionmessagelist.h, for lookups by name and for tests.
inline constexpr const MessageDef *commissionMessages[] = {
#define FATEK_MSG FATEK_MSG_ADDRESS
#ifndef Q_MOC_RUN
#include "commissionmessagelist.h"
#endif
#undef FATEK_MSG
};

} // namespace Fatek
