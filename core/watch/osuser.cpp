#include "osuser.h"

#ifndef Q_OS_WIN
#include <pwd.h>
#include <unistd.h>
#endif

namespace Fatek::OsUser {

QString name()
{
    QString user = qEnvironmentVariable("USER");
#ifndef Q_OS_WIN
    if (user.isEmpty()) {
        if (const passwd *entry = getpwuid(geteuid()); entry && entry->pw_name)
            user = QString::fromLocal8Bit(entry->pw_name);
    }
#endif
    if (user.isEmpty())
        user = qEnvironmentVariable("USERNAME"); // Windows
    return user.trimmed();
}

} // namespace Fatek::OsUser
