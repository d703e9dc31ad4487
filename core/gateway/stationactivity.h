#pragma once

#include "core/protocol/address.h"
#include "core/protocol/message.h"
#include "core/session/watchvalue.h"

#include <QHash>
#include <QString>

#include <map>
#include <optional>
#include <vector>

namespace Fatek {

// What the PLCs of one gateway connection do, for the operator's log (issue 55): a station that
// stops answering, its demotion and its return; a PLC error per item (error A: illegal address)
// once per change, never once per poll. Fed every item's state as the plant hands it over; says
// which lines to log. It also tells whether no watched station answers (the connection's status
// goes down then: no value of it is current).
class StationActivity
{
public:
    // An item's new state (every poll: only changes make lines).
    std::vector<Message> item(int station, const Address &address, ValueQuality quality,
                              const Message &error);
    // The PLC link went down or came up: every station starts unknown again (the link's own line
    // says what happened).
    void reset();
    // Whether every station with items was heard of and none answers: its reason, else nothing.
    std::optional<Message> silence() const;

private:
    enum class State { Unknown, Answering, Silent, Demoted };
    struct Station
    {
        State state = State::Unknown;
        Message reason;
    };

    std::map<int, Station> m_stations;
    // The PLC error last logged per item ("station/address"): logged again only when it changes.
    QHash<QString, Message> m_itemErrors;
};

} // namespace Fatek
