#pragma once

#include "core/transport/linksettings.h"

#include <QString>
#include <QVariantMap>

namespace Fatek {

// A connection as the user saved it: a name, the link and the station it talks to first.
struct SavedConnection
{
    QString name;
    LinkSettings settings;
    quint8 station = 1;

    bool operator==(const SavedConnection &) const = default;
};

// LinkSettings <-> QVariantMap for QSettings (recent connections). Unknown or missing keys keep
// the defaults, so older settings files still load.
namespace LinkSettingsIo {
QVariantMap toMap(const SavedConnection &connection);
SavedConnection fromMap(const QVariantMap &map);
} // namespace LinkSettingsIo

} // namespace Fatek
