#include "stationactivity.h"

#include "gatewaymessages.h"

#include <algorithm>

namespace Fatek {

namespace {

bool noAnswer(const Message &error)
{
    return error.id == MsgId::SessionNoAnswerFromStation
           || error.id == MsgId::SessionNoAnswerWithin;
}

} // namespace

std::vector<Message> StationActivity::item(int station, const Address &address,
                                           ValueQuality quality, const Message &error)
{
    std::vector<Message> lines;
    Station &s = m_stations[station];
    if (quality == ValueQuality::Good) {
        // Late is no news of the station either way: only a fresh answer brings it back.
        if (s.state == State::Silent || s.state == State::Demoted)
            lines.push_back(msg<MsgId::GatewayLogStationAnswers>(station));
        s.state = State::Answering;
        s.reason = {};
    } else if (quality == ValueQuality::Stale && error.id == MsgId::SessionStationDemoted) {
        if (s.state != State::Demoted)
            lines.push_back(msg<MsgId::GatewayLogStationDemoted>(station, error));
        s.state = State::Demoted;
        s.reason = error;
    } else if (quality == ValueQuality::Stale && noAnswer(error)) {
        // Once per silence: the next unanswered requests, and a demoted station's tries, are the
        // same news.
        if (s.state == State::Unknown || s.state == State::Answering) {
            lines.push_back(msg<MsgId::GatewayLogStationSilent>(station, error));
            s.state = State::Silent;
            s.reason = error;
        }
    }
    const QString key
        = QString::number(station) + u'/' + QString::fromStdString(address.toString());
    const auto known = m_itemErrors.constFind(key);
    if (quality == ValueQuality::Error) {
        if (known == m_itemErrors.cend() || *known != error) {
            lines.push_back(msg<MsgId::GatewayLogItemError>(station, address.toString(), error));
            m_itemErrors.insert(key, error);
        }
    } else if (known != m_itemErrors.cend()
               && (quality == ValueQuality::Good || quality == ValueQuality::Late)) {
        lines.push_back(msg<MsgId::GatewayLogItemReadAgain>(station, address.toString()));
        m_itemErrors.erase(known);
    }
    return lines;
}

void StationActivity::reset()
{
    m_stations.clear();
}

std::optional<Message> StationActivity::silence() const
{
    if (m_stations.empty())
        return std::nullopt;
    const bool silent = std::all_of(m_stations.cbegin(), m_stations.cend(), [](const auto &s) {
        return s.second.state == State::Silent || s.second.state == State::Demoted;
    });
    if (!silent)
        return std::nullopt;
    return m_stations.cbegin()->second.reason;
}

} // namespace Fatek
