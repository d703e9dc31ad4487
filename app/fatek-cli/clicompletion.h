#pragma once

#include <QString>

namespace Fatek {

// The shell completion scripts of fatek-cli (--completion bash|zsh), made from the same command
// table, option lists and format names the parser uses, so they cannot fall behind it. Serial
// ports and the named links of links.conf are looked up by the script when it completes.
QString completionScript(const QString &shell);

} // namespace Fatek
