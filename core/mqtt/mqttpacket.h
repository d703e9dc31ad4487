#pragma once

#include <QByteArray>

namespace Fatek::MqttPacket {

// The longest remaining length MQTT 3.1.1 can say (four length bytes).
inline constexpr qsizetype MaxRemainingLength = 268'435'455;

// Whether a QoS 0 PUBLISH of this topic and payload can be written (topic at most 65,535 bytes).
inline bool fitsPublish(const QByteArray &topic, const QByteArray &payload)
{
    return topic.size() <= 0xFFFF && 2 + topic.size() + payload.size() <= MaxRemainingLength;
}

// Appends a QoS 0 PUBLISH packet (MQTT 3.1.1, 3.3): fixed header (type 3, RETAIN flag), remaining
// length, topic (length-prefixed UTF-8), payload; a QoS 0 PUBLISH has no packet identifier. Only
// what fitsPublish() takes. Sans-I/O: MqttClient writes many of them with one send().
inline void appendPublishQos0(QByteArray &out, const QByteArray &topic, const QByteArray &payload,
                              bool retain)
{
    out += static_cast<char>(0x30 | (retain ? 0x01 : 0x00));
    auto remaining = static_cast<quint32>(2 + topic.size() + payload.size());
    do {
        auto digit = static_cast<quint8>(remaining % 128);
        remaining /= 128;
        if (remaining > 0)
            digit |= 0x80;
        out += static_cast<char>(digit);
    } while (remaining > 0);
    out += static_cast<char>((topic.size() >> 8) & 0xFF);
    out += static_cast<char>(topic.size() & 0xFF);
    out += topic;
    out += payload;
}

} // namespace Fatek::MqttPacket
