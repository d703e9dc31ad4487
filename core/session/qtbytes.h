#pragma once

// The Qt boundary of the byte path: core/protocol speaks std bytes (Bytes, spans), transports and
// the UI speak QByteArray. One pair of conversions for every layer above protocol.

#include "core/protocol/request.h"

#include <QByteArray>

#include <cstdint>
#include <span>

namespace Fatek {

inline std::span<const std::uint8_t> bytesOf(const QByteArray &bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()),
            static_cast<std::size_t>(bytes.size())};
}

inline QByteArray toQByteArray(std::span<const std::uint8_t> bytes)
{
    return QByteArray(reinterpret_cast<const char *>(bytes.data()),
                      static_cast<qsizetype>(bytes.size()));
}

} // namespace Fatek
