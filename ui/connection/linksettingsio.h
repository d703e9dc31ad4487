#pragma once

#include "core/link/gatewaywatchsettings.h"
#include "core/transport/linksettings.h"

#include <QString>
#include <QVariantMap>

#include <optional>

namespace Fatek {

// A connection as the user saved it: a name, the link and the station it talks to first. With a
// gateway part it watches a gateway's connection through the broker instead (`settings` unused,
// `station` the default of new table rows).
struct SavedConnection
{
    QString name;
    LinkSettings settings;
    quint8 station = 1;
    std::optional<GatewayWatchSettings> gateway;

    // The link in the UI language (UiText).
    QString linkText() const;

    bool operator==(const SavedConnection &) const = default;
};

// LinkSettings <-> QVariantMap for QSettings (recent connections). Unknown or missing keys keep
// the defaults, so older settings files still load. A gateway part is a map under "gateway"; its
// broker password is not stored (settings files are plain text): it is asked again.
namespace LinkSettingsIo {
QVariantMap toMap(const SavedConnection &connection);
SavedConnection fromMap(const QVariantMap &map);
} // namespace LinkSettingsIo

} // namespace Fatek
