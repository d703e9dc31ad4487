#pragma once

// The messages of core/watch that core/protocol/messagelist.h does not hold (importing names, the
// items of a gateway connection): the ids of watchmessagelist.h, in the namespace MsgId.
// core/protocol/message.h explains the ids and their lists. Include this header where one of them
// is used; a new message of this library goes into watchmessagelist.h.
#include "core/protocol/message.h"

namespace Fatek {

namespace MsgId {
#define FATEK_MSG FATEK_MSG_DEFINE
#ifndef Q_MOC_RUN
#include "watchmessagelist.h"
#endif
#undef FATEK_MSG
} // namespace MsgId

// Every id of watchmessagelist.h, for lookups by name and for tests.
inline constexpr const MessageDef *watchMessages[] = {
#define FATEK_MSG FATEK_MSG_ADDRESS
#ifndef Q_MOC_RUN
#include "watchmessagelist.h"
#endif
#undef FATEK_MSG
};

} // namespace Fatek
