#pragma once

#include <string>
#include <string_view>

namespace Fatek {

// Text for one log line. What reaches a log may come from the network (a command's value, a
// topic, a PLC's answer): its control characters (C0, DEL, C1) and Unicode's line and paragraph
// separators are written as escapes (\n, \r, \t, \xNN, \uNNNN), so it can neither start a line
// that reads like the logger's own nor drive the terminal; so are the bidirectional controls
// (U+202E and its kin, issue 55), which would show a line's text in another order than it has.
// Every logger writes through it.
std::string escapedForLog(std::string_view utf8);
// A field a log line shows between quotes ("%3"): its backslashes and quotes escaped (\\, \"),
// so that a value cannot close the quotes and add fields of its own (1" (id "admin"): written).
std::string quotedFieldForLog(std::string_view utf8);

} // namespace Fatek
