#pragma once

#include <QString>

namespace Fatek::OsUser {

// Who is logged in, for records that name a person when none was typed (the alarm journal's
// acknowledgements, a checkout's engineer): $USER, else the password database's name of the
// process's user (a service or a bare chroot may have no $USER), else $USERNAME (Windows).
// Empty when none is known.
QString name();

} // namespace Fatek::OsUser
