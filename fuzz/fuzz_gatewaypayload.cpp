// What an MQTT peer sends the gateway or the GUI, on arbitrary bytes: item payloads, write
// commands, status and reply payloads, topics. The first byte picks the decoder. Whatever a
// decoder accepts is consistent (words within an item's reach, a station in range) and encodes back
// to what decodes the same (an item to exactly Qt's JSON text); nothing crashes or hangs on
// garbage.
#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/messagejson.h"
#include "core/watch/itemvalues.h"
#include "core/watch/watchlist.h"

#include <QJsonDocument>

#include <cstdlib>

using namespace Fatek;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray bytes(reinterpret_cast<const char *>(data + 1),
                           static_cast<qsizetype>(size - 1));
    switch (data[0] % 5) {
    case 0: {
        const auto item = GatewayPayload::decodeItem(bytes);
        if (!item)
            return 0;
        if (item->station < 0 || item->station > 255
            || item->words.size() > std::size_t(ItemValues::MaxElements))
            std::abort();
        // Encoded again (names and texts of any characters), it is exactly Qt's JSON text of
        // itself and keeps the name.
        WatchItemSpec spec;
        spec.address = item->address;
        spec.station = static_cast<quint8>(item->station);
        spec.format = item->format;
        spec.swapWords = item->swapWords;
        spec.name = item->name;
        if (!WatchList::validateEntry(spec))
            return 0;
        const ItemValues values(spec);
        if (static_cast<int>(item->words.size()) != values.elementCount())
            return 0;
        const QByteArray again = GatewayPayload::encodeItem(values, item->words, item->quality,
                                                            item->time, item->error);
        const auto back = GatewayPayload::decodeItem(again);
        if (QJsonDocument::fromJson(again).toJson(QJsonDocument::Compact) != again || !back
            || back->name != item->name || back->words != item->words)
            std::abort();
        break;
    }
    case 1: {
        Message error;
        const auto command = GatewayPayload::decodeSet(bytes, &error);
        if (!command) {
            if (error.empty())
                std::abort(); // a refusal always says why
            return 0;
        }
        Message again;
        const auto back = GatewayPayload::decodeSet(GatewayPayload::encodeSet(*command), &again);
        if (!back || back->value != command->value || back->format != command->format
            || back->id != command->id)
            std::abort();
        break;
    }
    case 2: {
        const auto status = GatewayPayload::decodeStatus(bytes);
        if (status && !GatewayPayload::decodeStatus(GatewayPayload::encodeStatus(*status)))
            std::abort();
        const auto reply = GatewayPayload::decodeReply(bytes);
        if (reply && !GatewayPayload::decodeReply(GatewayPayload::encodeReply(*reply)))
            std::abort();
        break;
    }
    case 3: {
        const QJsonDocument document = QJsonDocument::fromJson(bytes);
        if (const auto message = MessageJson::fromJson(document.object())) {
            // What was taken in writes out again and reads back equal.
            const auto back = MessageJson::fromJson(MessageJson::toJson(*message));
            if (!back || !(*back == *message))
                std::abort();
        }
        break;
    }
    default: {
        const QString topic = QString::fromUtf8(bytes);
        const auto parsed = GatewayTopics::parse(QStringLiteral("fatek"), topic);
        if (!parsed || parsed->kind != GatewayTopics::Kind::Item)
            return 0;
        // An item topic is exactly the one the scheme builds for what it names.
        if (GatewayTopics::item(QStringLiteral("fatek"), parsed->connection, parsed->station,
                                parsed->address)
            != topic)
            std::abort();
        break;
    }
    }
    return 0;
}
