#include "gatewaypayload.h"

#include "core/watch/itemvalues.h"
#include "core/watch/jsonkeys.h"
#include "messagejson.h"
#include "mqttmessages.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>

#include <charconv>
#include <cmath>
#include <limits>

namespace Fatek {

namespace {

QString timeText(const QDateTime &time)
{
    if (!time.isValid())
        return {};
    return time.toUTC().toString(Qt::ISODateWithMs);
}

// The time as a JSON string ("...Z", quotes included; "" when invalid), as QJsonDocument writes
// it. One poll cycle's items share their time: formatted once.
QByteArray timeJson(const QDateTime &time)
{
    thread_local qint64 lastMs = std::numeric_limits<qint64>::min();
    thread_local QByteArray lastText;
    if (!time.isValid())
        return QByteArrayLiteral("\"\"");
    const qint64 ms = time.toMSecsSinceEpoch();
    if (ms != lastMs) {
        // ISO 8601 digits, '-', ':', '.', 'T', 'Z': nothing to escape.
        lastText = '"' + timeText(time).toLatin1() + '"';
        lastMs = ms;
    }
    return lastText;
}

template<typename Integer>
void appendNumber(QByteArray &out, Integer value)
{
    char digits[24];
    const std::to_chars_result end = std::to_chars(digits, digits + sizeof digits, value);
    out.append(digits, end.ptr - digits);
}

QDateTime timeFrom(const QJsonValue &value)
{
    return QDateTime::fromString(value.toString(), Qt::ISODateWithMs);
}

std::optional<QJsonObject> objectOf(const QByteArray &payload)
{
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(payload, &error);
    if (error.error != QJsonParseError::NoError || !document.isObject())
        return std::nullopt;
    return document.object();
}

std::optional<Address> addressFrom(const QJsonValue &value)
{
    const Result<Address> address = Address::parse(value.toString().toStdString());
    if (!address)
        return std::nullopt;
    return *address;
}

QJsonValue numericValue(const ItemValues &item, std::uint64_t raw, const QString &text)
{
    const DisplayFormat format = item.item().format;
    const int width = item.width();
    const std::uint64_t mask = width >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << width) - 1;
    // In the item's word order, as text() reads it (swapped only when the item says so).
    const std::uint64_t ordered = item.item().swapWords ? ValueFormat::swapWords(raw, width) : raw;
    const std::uint64_t value = ordered & mask;
    switch (format) {
    case DisplayFormat::Bit: return (raw & 1) != 0;
    case DisplayFormat::Ascii: return text;
    case DisplayFormat::Unsigned:
    case DisplayFormat::Hex:
    case DisplayFormat::Binary: return static_cast<double>(value);
    case DisplayFormat::Signed: {
        if (width >= 64)
            return static_cast<double>(static_cast<std::int64_t>(value));
        const std::uint64_t sign = std::uint64_t(1) << (width - 1);
        const auto signedValue
            = static_cast<std::int64_t>(value ^ sign) - static_cast<std::int64_t>(sign);
        return static_cast<double>(signedValue);
    }
    case DisplayFormat::Bcd:
    case DisplayFormat::Float32:
    case DisplayFormat::Double64: {
        bool ok = false;
        const double number = text.toDouble(&ok);
        if (!ok || !std::isfinite(number))
            return QJsonValue(QJsonValue::Null);
        return number;
    }
    }
    return QJsonValue(QJsonValue::Null);
}

// JSON text as QJsonDocument writes it: UTF-8, with quote, backslash and control characters
// escaped (lower-case hex), and a lone surrogate as \\u escape.
void appendJsonString(QByteArray &out, QStringView text)
{
    static constexpr char hex[] = "0123456789abcdef";
    out += '"';
    const char16_t *src = text.utf16();
    const char16_t *const end = src + text.size();
    while (src != end) {
        const char16_t u = *src++;
        if (u < 0x80) {
            if (u >= 0x20 && u != u'"' && u != u'\\') {
                out += static_cast<char>(u);
                continue;
            }
            out += '\\';
            switch (u) {
            case u'"': out += '"'; break;
            case u'\\': out += '\\'; break;
            case 0x8: out += 'b'; break;
            case 0xc: out += 'f'; break;
            case 0xa: out += 'n'; break;
            case 0xd: out += 'r'; break;
            case 0x9: out += 't'; break;
            default:
                out += "u00";
                out += hex[u >> 4];
                out += hex[u & 0xf];
            }
        } else if (u < 0x800) {
            out += static_cast<char>(0xc0 | (u >> 6));
            out += static_cast<char>(0x80 | (u & 0x3f));
        } else if (QChar::isHighSurrogate(u) && src != end && QChar::isLowSurrogate(*src)) {
            const char32_t code = QChar::surrogateToUcs4(u, *src++);
            out += static_cast<char>(0xf0 | (code >> 18));
            out += static_cast<char>(0x80 | ((code >> 12) & 0x3f));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (code & 0x3f));
        } else if (QChar::isSurrogate(u)) {
            out += "\\u";
            out += hex[u >> 12];
            out += hex[(u >> 8) & 0xf];
            out += hex[(u >> 4) & 0xf];
            out += hex[u & 0xf];
        } else {
            out += static_cast<char>(0xe0 | (u >> 12));
            out += static_cast<char>(0x80 | ((u >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (u & 0x3f));
        }
    }
    out += '"';
}

// The scalar kinds numericValue() gives.
void appendJsonValue(QByteArray &out, const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Bool: out += value.toBool() ? "true" : "false"; break;
    case QJsonValue::Double: {
        // An integral number in reach of 64 bits as digits, as Qt's parser reads it back (and
        // QJsonDocument writes it again): one canonical text for the same value.
        const double number = value.toDouble();
        if (!std::isfinite(number))
            out += "null";
        else if (number == std::floor(number) && number >= -9223372036854775808.0
                 && number < 9223372036854775808.0)
            appendNumber(out, static_cast<qint64>(number));
        else
            out += QByteArray::number(number, 'g', QLocale::FloatingPointShortest);
        break;
    }
    case QJsonValue::String: appendJsonString(out, value.toString()); break;
    default: out += "null"; break;
    }
}

} // namespace

QString GatewayPayload::qualityName(ValueQuality quality)
{
    switch (quality) {
    case ValueQuality::Good: return QStringLiteral("good");
    case ValueQuality::Late: return QStringLiteral("late");
    case ValueQuality::Stale: return QStringLiteral("stale");
    case ValueQuality::Error: return QStringLiteral("error");
    }
    return QStringLiteral("error");
}

std::optional<ValueQuality> GatewayPayload::qualityFromName(const QString &name)
{
    for (ValueQuality quality :
         {ValueQuality::Good, ValueQuality::Late, ValueQuality::Stale, ValueQuality::Error}) {
        if (qualityName(quality) == name)
            return quality;
    }
    return std::nullopt;
}

QByteArray GatewayPayload::encodeItem(const ItemValues &item,
                                      const std::vector<std::uint32_t> &words, ValueQuality quality,
                                      const QDateTime &time, const Message &error)
{
    return encodeItem(encodeItemHead(item, quality, error), item, words, time);
}

QByteArray GatewayPayload::encodeItemHead(const ItemValues &item, ValueQuality quality,
                                          const Message &error)
{
    // Written as text directly, in exactly the form QJsonDocument writes (keys sorted, compact):
    // the gateway encodes one per item per change, and building a QJsonObject took most of the
    // gateway's time per message (docs/performance.md). tst_mqtt checks the bytes against Qt's.
    const WatchItemSpec &spec = item.item();
    QByteArray out;
    out.reserve(160);
    out += "{\"address\":";
    appendJsonString(out, QString::fromStdString(spec.address.toString()));
    if (quality != ValueQuality::Good && !error.empty()) {
        out += ",\"error\":";
        out += QJsonDocument(MessageJson::toJson(error)).toJson(QJsonDocument::Compact);
    }
    out += ",\"format\":";
    appendJsonString(out, ValueFormat::name(spec.format));
    out += ",\"name\":";
    appendJsonString(out, spec.name);
    out += ",\"quality\":";
    appendJsonString(out, qualityName(quality));
    out += ",\"station\":";
    appendNumber(out, spec.station);
    out += ",\"swapWords\":";
    out += spec.swapWords ? "true" : "false";
    return out;
}

QByteArray GatewayPayload::encodeItem(const QByteArray &head, const ItemValues &item,
                                      const std::vector<std::uint32_t> &words,
                                      const QDateTime &time)
{
    // No words: never read (a dead link from the start). No value is invented for it.
    const bool read = !words.empty();
    const std::uint64_t raw = item.join(words);
    const QString text = read ? item.text(raw) : QString();
    QByteArray out;
    out.reserve(head.size() + 96 + 12 * static_cast<qsizetype>(words.size()) + 2 * text.size());
    out += head;
    out += ",\"text\":";
    if (read)
        appendJsonString(out, text);
    else
        out += "null";
    out += ",\"time\":";
    out += timeJson(time);
    out += ",\"value\":";
    appendJsonValue(out, read ? numericValue(item, raw, text) : QJsonValue(QJsonValue::Null));
    out += ",\"words\":[";
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0)
            out += ',';
        appendNumber(out, words[i]);
    }
    out += "]}";
    return out;
}

std::optional<GatewayPayload::ItemValue> GatewayPayload::decodeItem(const QByteArray &payload)
{
    const std::optional<QJsonObject> object = objectOf(payload);
    if (!object)
        return std::nullopt;
    ItemValue value;
    const std::optional<Address> address = addressFrom(object->value(QStringLiteral("address")));
    const std::optional<ValueQuality> quality
        = qualityFromName(object->value(QStringLiteral("quality")).toString());
    const std::optional<DisplayFormat> format
        = ValueFormat::fromName(object->value(QStringLiteral("format")).toString());
    const QJsonArray words = object->value(QStringLiteral("words")).toArray();
    value.station = object->value(QStringLiteral("station")).toInt(-1);
    if (!address || !quality || !format || value.station < 0 || value.station > 255
        || words.size() > ItemValues::MaxElements)
        return std::nullopt;
    value.address = *address;
    value.quality = *quality;
    value.format = *format;
    value.swapWords = object->value(QStringLiteral("swapWords")).toBool();
    value.name = object->value(QStringLiteral("name")).toString();
    value.text = object->value(QStringLiteral("text")).toString();
    value.time = timeFrom(object->value(QStringLiteral("time")));
    for (const auto &word : words) {
        const double number = word.toDouble(-1);
        if (number < 0 || number > 4294967295.0 || number != std::floor(number))
            return std::nullopt;
        value.words.push_back(static_cast<std::uint32_t>(number));
    }
    if (object->contains(QStringLiteral("error")))
        value.error = MessageJson::fromJson(object->value(QStringLiteral("error")).toObject())
                          .value_or(Message{});
    return value;
}

QString GatewayPayload::linkStatusName(LinkStatus state)
{
    switch (state) {
    case LinkStatus::Offline: return QStringLiteral("offline");
    case LinkStatus::Connecting: return QStringLiteral("connecting");
    case LinkStatus::Up: return QStringLiteral("up");
    case LinkStatus::Down: return QStringLiteral("down");
    }
    return QStringLiteral("offline");
}

QByteArray GatewayPayload::encodeStatus(const Status &status)
{
    QJsonObject object{{QStringLiteral("state"), linkStatusName(status.state)}};
    if (!status.link.isEmpty())
        object.insert(QStringLiteral("link"), status.link);
    if (!status.reason.empty())
        object.insert(QStringLiteral("reason"), MessageJson::toJson(status.reason));
    if (status.time.isValid())
        object.insert(QStringLiteral("time"), timeText(status.time));
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

std::optional<GatewayPayload::Status> GatewayPayload::decodeStatus(const QByteArray &payload)
{
    const std::optional<QJsonObject> object = objectOf(payload);
    if (!object)
        return std::nullopt;
    Status status;
    const QString state = object->value(QStringLiteral("state")).toString();
    bool known = false;
    for (LinkStatus candidate :
         {LinkStatus::Offline, LinkStatus::Connecting, LinkStatus::Up, LinkStatus::Down}) {
        if (linkStatusName(candidate) == state) {
            status.state = candidate;
            known = true;
        }
    }
    if (!known)
        return std::nullopt;
    status.link = object->value(QStringLiteral("link")).toString();
    status.time = timeFrom(object->value(QStringLiteral("time")));
    if (object->contains(QStringLiteral("reason")))
        status.reason = MessageJson::fromJson(object->value(QStringLiteral("reason")).toObject())
                            .value_or(Message{});
    return status;
}

std::optional<GatewayPayload::SetCommand> GatewayPayload::decodeSet(const QByteArray &payload,
                                                                    Message *error)
{
    SetCommand command;
    const QByteArray trimmed = payload.trimmed();
    if (trimmed.startsWith('{')) {
        const std::optional<QJsonObject> object = objectOf(trimmed);
        if (!object) {
            *error = msg<MsgId::GatewaySetNotJson>();
            return std::nullopt;
        }
        // {"value":1,"value":100} would write 100 without a word: which one was meant is not
        // known.
        if (std::optional<Message> twice = JsonKeys::firstDuplicate(trimmed)) {
            *error = std::move(*twice);
            return std::nullopt;
        }
        const QJsonValue value = object->value(QStringLiteral("value"));
        if (object->contains(QStringLiteral("words"))) {
            const QJsonValue words = object->value(QStringLiteral("words"));
            const QJsonArray array = words.toArray();
            std::vector<std::uint32_t> list;
            bool valid = words.isArray() && !array.isEmpty();
            for (const auto &word : array) {
                const double number = word.toDouble(-1);
                valid = valid && word.isDouble() && number >= 0 && number <= 4294967295.0
                        && number == static_cast<double>(static_cast<std::uint64_t>(number));
                if (!valid)
                    break;
                list.push_back(static_cast<std::uint32_t>(number));
            }
            if (!valid) {
                *error = msg<MsgId::GatewaySetBadWords>();
                return std::nullopt;
            }
            command.words = std::move(list);
        } else if (value.isString())
            command.value = value.toString();
        else if (value.isBool())
            command.value = value.toBool() ? QStringLiteral("ON") : QStringLiteral("OFF");
        else if (value.isDouble())
            command.value = QString::number(value.toDouble(), 'g', 17);
        else {
            *error = msg<MsgId::GatewaySetNoValue>();
            return std::nullopt;
        }
        // A key of the wrong type is named as such (issue 55: "format":5 was read as "").
        for (const char *key : {"format", "time"}) {
            const QJsonValue v = object->value(QLatin1String(key));
            if (!v.isUndefined() && !v.isString()) {
                *error = msg<MsgId::GatewaySetNotString>(key);
                return std::nullopt;
            }
        }
        if (object->contains(QStringLiteral("format"))) {
            command.format
                = ValueFormat::fromName(object->value(QStringLiteral("format")).toString());
            if (!command.format) {
                *error = msg<MsgId::GatewaySetBadFormat>(
                    object->value(QStringLiteral("format")).toString().toStdString());
                return std::nullopt;
            }
        }
        if (object->contains(QStringLiteral("swapWords"))) {
            const QJsonValue swap = object->value(QStringLiteral("swapWords"));
            if (!swap.isBool()) {
                *error = msg<MsgId::GatewaySetNotBool>("swapWords", "true", "false");
                return std::nullopt;
            }
            command.swapWords = swap.toBool();
        }
        // The reply gives the id back for the sender to match: one it could not give back as it
        // was (an object read as "") would match nothing, or every other such command.
        const QJsonValue id = object->value(QStringLiteral("id"));
        if (id.isDouble())
            command.id = QString::number(id.toDouble(), 'g', QLocale::FloatingPointShortest);
        else if (id.isString())
            command.id = id.toString();
        else if (!id.isUndefined()) {
            *error = msg<MsgId::GatewaySetBadId>();
            return std::nullopt;
        }
        if (object->contains(QStringLiteral("time"))) {
            const QString text = object->value(QStringLiteral("time")).toString();
            const QDateTime time = QDateTime::fromString(text, Qt::ISODateWithMs);
            if (!time.isValid() || time.timeSpec() == Qt::LocalTime) {
                // Without an offset the sender's clock zone is a guess: refuse to guess.
                *error = msg<MsgId::GatewaySetBadTime>(text.left(40).toStdString());
                return std::nullopt;
            }
            command.time = time;
        }
        return command;
    }
    if (trimmed.isEmpty()) {
        *error = msg<MsgId::GatewaySetNoValue>();
        return std::nullopt;
    }
    command.value = QString::fromUtf8(trimmed);
    return command;
}

QByteArray GatewayPayload::encodeSet(const SetCommand &command)
{
    QJsonObject object;
    if (command.words) {
        QJsonArray words;
        for (const std::uint32_t word : *command.words)
            words.append(static_cast<qint64>(word));
        object.insert(QStringLiteral("words"), words);
    } else {
        object.insert(QStringLiteral("value"), command.value);
    }
    if (command.format)
        object.insert(QStringLiteral("format"), ValueFormat::name(*command.format));
    if (command.swapWords)
        object.insert(QStringLiteral("swapWords"), *command.swapWords);
    if (!command.id.isEmpty())
        object.insert(QStringLiteral("id"), command.id);
    if (command.time)
        object.insert(QStringLiteral("time"), command.time->toUTC().toString(Qt::ISODateWithMs));
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

QString GatewayPayload::outcomeName(ChangeOutcome outcome)
{
    switch (outcome) {
    case ChangeOutcome::Done: return QStringLiteral("done");
    case ChangeOutcome::Refused: return QStringLiteral("refused");
    case ChangeOutcome::Unknown: return QStringLiteral("unknown");
    }
    return QStringLiteral("unknown");
}

std::optional<ChangeOutcome> GatewayPayload::outcomeFrom(const QString &name)
{
    for (ChangeOutcome o : {ChangeOutcome::Done, ChangeOutcome::Refused, ChangeOutcome::Unknown})
        if (name == outcomeName(o))
            return o;
    return std::nullopt;
}

QByteArray GatewayPayload::encodeReply(const Reply &reply)
{
    QJsonObject object{
        {QStringLiteral("id"), reply.id},
        {QStringLiteral("ok"), reply.ok},
        {QStringLiteral("station"), reply.station},
        {QStringLiteral("address"), QString::fromStdString(reply.address.toString())},
        {QStringLiteral("value"), reply.value},
        {QStringLiteral("time"), timeText(reply.time)},
    };
    if (!reply.stationLevel.isEmpty() || !reply.addressLevel.isEmpty()) {
        object.insert(QStringLiteral("station"), reply.stationLevel);
        object.insert(QStringLiteral("address"), reply.addressLevel);
    }
    object.insert(QStringLiteral("outcome"), outcomeName(reply.outcome));
    object.insert(QStringLiteral("final"), reply.final);
    if (!reply.error.empty())
        object.insert(reply.ok ? QStringLiteral("detail") : QStringLiteral("error"),
                      MessageJson::toJson(reply.error));
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

std::optional<GatewayPayload::Reply> GatewayPayload::decodeReply(const QByteArray &payload)
{
    const std::optional<QJsonObject> object = objectOf(payload);
    if (!object || !object->value(QStringLiteral("ok")).isBool())
        return std::nullopt;
    Reply reply;
    reply.id = object->value(QStringLiteral("id")).toString();
    reply.ok = object->value(QStringLiteral("ok")).toBool();
    reply.station = object->value(QStringLiteral("station")).toInt(1);
    if (const std::optional<Address> address
        = addressFrom(object->value(QStringLiteral("address"))))
        reply.address = *address;
    reply.value = object->value(QStringLiteral("value")).toString();
    reply.time = timeFrom(object->value(QStringLiteral("time")));
    // A gateway before outcomes: ok or refused, always final.
    reply.outcome = reply.ok ? ChangeOutcome::Done : ChangeOutcome::Refused;
    if (const std::optional<ChangeOutcome> outcome
        = outcomeFrom(object->value(QStringLiteral("outcome")).toString()))
        reply.outcome = *outcome;
    reply.final = object->value(QStringLiteral("final")).toBool(true);
    reply.error = MessageJson::fromJson(
                      object->value(reply.ok ? QStringLiteral("detail") : QStringLiteral("error"))
                          .toObject())
                      .value_or(Message{});
    return reply;
}

} // namespace Fatek
