#pragma once

// The messages of core/history: the ids of historymessagelist.h, in the namespace MsgId.
// core/protocol/message.h explains the ids and their lists. Include this header where one of them
// is used; a new message of this library goes into historymessagelist.h.
#include "core/protocol/message.h"

namespace Fatek {

namespace MsgId {
#define FATEK_MSG FATEK_MSG_DEFINE
#ifndef Q_MOC_RUN
#include "historymessagelist.h"
#endif
#undef FATEK_MSG
} // namespace MsgId

// Every id of historymessagelist.h, for lookups by name and for tests.
inline constexpr const MessageDef *historyMessages[] = {
#define FATEK_MSG FATEK_MSG_ADDRESS
#ifndef Q_MOC_RUN
#include "historymessagelist.h"
#endif
#undef FATEK_MSG
};

} // namespace Fatek
