#pragma once

// The messages of the alarm journal: the ids of alarmjournalmessagelist.h, in the namespace MsgId.
// core/protocol/message.h explains the ids and their lists. Include this header where one of them
// is used; a new message of the journal goes into alarmjournalmessagelist.h.
#include "core/protocol/message.h"

namespace Fatek {

namespace MsgId {
#define FATEK_MSG FATEK_MSG_DEFINE
#ifndef Q_MOC_RUN
#include "alarmjournalmessagelist.h"
#endif
#undef FATEK_MSG
} // namespace MsgId

// Every id of alarmjournalmessagelist.h, for lookups by name and for tests.
inline constexpr const MessageDef *alarmJournalMessages[] = {
#define FATEK_MSG FATEK_MSG_ADDRESS
#ifndef Q_MOC_RUN
#include "alarmjournalmessagelist.h"
#endif
#undef FATEK_MSG
};

} // namespace Fatek
