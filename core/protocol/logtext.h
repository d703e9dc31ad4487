#pragma once

#include <string>
#include <string_view>

namespace Fatek {

// Text for one log line. What reaches a log may come from the network (a command's value, a
// topic, a PLC's answer): its control characters (C0, DEL, C1) and Unicode's line and paragraph
// separators are written as escapes (\n, \r, \t, \xNN, \uNNNN), so it can neither start a line
// that reads like the logger's own nor drive the terminal. Every logger writes through it.
std::string escapedForLog(std::string_view utf8);

} // namespace Fatek
