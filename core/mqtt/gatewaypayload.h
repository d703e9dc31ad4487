#pragma once

#include "core/protocol/address.h"
#include "core/session/sessionresult.h"
#include "core/session/watchvalue.h"
#include "core/watch/valueformat.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace Fatek {

class ItemValues;

// The gateway's JSON payloads, the one place that writes and reads them (see GatewayTopics for
// where they go). Times are UTC ISO 8601 with milliseconds.
namespace GatewayPayload {

// One item's value, as published (retained) on its item topic:
//   {"station":1,"address":"R100","name":"Tank level","format":"float","swapWords":false,
//    "value":12.5,"text":"12.5","words":[0,16712],"quality":"good","time":"...Z",
//    "error":{"id":...,"args":[...],"text":"..."}}
// "words" are the elements' raw values, element 0 (the item's address) first: a reader joins them
// itself or uses "value" (a number; true/false for a bit; text for ascii; null for NaN). "error"
// only when quality is not good.
struct ItemValue
{
    int station = 1;
    Address address;
    QString name;
    DisplayFormat format = DisplayFormat::Signed;
    bool swapWords = false;
    std::vector<std::uint32_t> words;
    QString text;
    ValueQuality quality = ValueQuality::Error;
    QDateTime time;
    Message error;
};

// Builds the payload of `item` from its elements' words (join, text and value through ItemValues).
// No words: the item was never read; "text" and "value" are null and "words" is empty (a consumer's
// retained last value is never replaced by an invented 0).
QByteArray encodeItem(const ItemValues &item, const std::vector<std::uint32_t> &words,
                      ValueQuality quality, const QDateTime &time, const Message &error);
// The same in two parts: the head (address, error, format, name, quality, station, swapWords) is
// the same for every value of an item while its quality and error stay, so the gateway writes it
// once per item and only the rest per value. encodeItem(item, ...) ==
// encodeItem(encodeItemHead(item, quality, error), item, words, time).
QByteArray encodeItemHead(const ItemValues &item, ValueQuality quality, const Message &error);
QByteArray encodeItem(const QByteArray &head, const ItemValues &item,
                      const std::vector<std::uint32_t> &words, const QDateTime &time);
// nullopt for anything that is not an item payload (a reader's garbage, another program's topic).
std::optional<ItemValue> decodeItem(const QByteArray &payload);

QString qualityName(ValueQuality quality);
std::optional<ValueQuality> qualityFromName(const QString &name);

// A link's status (retained; the will publishes Offline):
//   {"state":"up","link":"TCP 127.0.0.1:500, FACON","reason":{...},"time":"...Z"}
enum class LinkStatus {
    Offline,    // the gateway is gone (will) or stopped this link
    Connecting, // the gateway runs, the PLC link is not up yet
    Up,         // the PLC link is up
    Down,       // the PLC link broke; the gateway reconnects
};
struct Status
{
    LinkStatus state = LinkStatus::Offline;
    QString link;
    Message reason;
    QDateTime time;
};
QByteArray encodeStatus(const Status &status);
std::optional<Status> decodeStatus(const QByteArray &payload);
QString linkStatusName(LinkStatus state);

// A write command on <item>/set: plain text ("12.5", "ON") or
//   {"value":"12.5","format":"float","swapWords":false,"id":"anything"}
// ("value" may be a JSON number or true/false; without "format" the gateway uses its item's), or
// the raw value itself, as the studio sends it:
//   {"words":[0,16712],"format":"float","swapWords":false,"id":"..."}
// ("words" as in an item's payload, element 0 first; it wins over "value").
struct SetCommand
{
    QString value;
    std::optional<std::vector<std::uint32_t>> words;
    std::optional<DisplayFormat> format;
    std::optional<bool> swapWords;
    QString id;
    // When the command was sent (optional): a command older than the connection's
    // commandMaxAgeSec is refused, not carried out late.
    std::optional<QDateTime> time;
};
// nullopt: the payload is neither text nor a JSON object with a value; `error` says why.
std::optional<SetCommand> decodeSet(const QByteArray &payload, Message *error);
QByteArray encodeSet(const SetCommand &command);

// The gateway's answer on <item>/reply:
//   {"id":"...","ok":true,"station":1,"address":"R100","value":"12.5","time":"...Z"}
//   {"id":"...","ok":false,...,"error":{...}}
struct Reply
{
    QString id;
    bool ok = false; // outcome == Done
    // Done, refused (nothing carried out), or unknown (sent to the PLC, not answered). An unknown
    // outcome is answered twice: final = false at once, then final = true with what the read-back
    // found (docs/gateway.md, "Writing").
    ChangeOutcome outcome = ChangeOutcome::Refused;
    bool final = true;
    int station = 1;
    Address address;
    QString value;
    Message error;
    QDateTime time;
    // A command on a topic that names no item (R99999, r100, station 01): the topic's levels as
    // they were, in place of `station` and `address`.
    QString stationLevel;
    QString addressLevel;
};
// "done", "refused", "unknown" (the replies' "outcome").
QString outcomeName(ChangeOutcome outcome);
std::optional<ChangeOutcome> outcomeFrom(const QString &name);
QByteArray encodeReply(const Reply &reply);
std::optional<Reply> decodeReply(const QByteArray &payload);

} // namespace GatewayPayload

} // namespace Fatek
