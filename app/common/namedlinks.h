#pragma once

#include <QString>
#include <QStringList>

namespace Fatek {

// Named links for --link @NAME (and FATEK_LINK=@NAME): a small text file, one link per line,
//   line1 = serial:///dev/ttyUSB0?baud=19200&format=7E1&station=3
//   press = tcp://192.168.1.20:500
// '#' starts a comment. The file is links.conf in the user's configuration folder
// (~/.config/fatek-studio/links.conf; %LOCALAPPDATA%\fatek-studio\links.conf on Windows), or
// the file FATEK_LINKS names.
QString namedLinksPath();
// The names the file defines, in its order (for shell completion); empty without a file.
QStringList namedLinkNames();
// The URL `name` stands for; empty with `error` set when there is none, or when the file has a
// line that is not NAME = URL or a name given twice (which line, in `error`).
QString lookUpNamedLink(const QString &name, QString *error);

} // namespace Fatek
