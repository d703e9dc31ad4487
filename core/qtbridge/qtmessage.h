#pragma once

// Messages (core/protocol/message.h) at the Qt boundary: a meta-type for queued signals, and
// QString in and out of the English form.

#include "core/protocol/message.h"

#include <QMetaType>
#include <QString>

namespace Fatek {

inline QString englishText(const Message &message)
{
    return QString::fromStdString(english(message));
}

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::Message)
