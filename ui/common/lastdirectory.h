#pragma once

#include <QFileInfo>
#include <QSettings>
#include <QString>

namespace Fatek {

// The folder of the file last chosen in any file dialog of the studio (watch lists, CSV imports,
// data logs): the next dialog starts there, also after a restart.
inline QString lastDirectory()
{
    return QSettings().value(QStringLiteral("preferences/lastDirectory")).toString();
}

inline void setLastDirectory(const QString &path)
{
    QSettings().setValue(QStringLiteral("preferences/lastDirectory"),
                         QFileInfo(path).absolutePath());
}

} // namespace Fatek
