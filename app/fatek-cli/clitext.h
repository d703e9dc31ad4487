#pragma once

// Text helpers shared by the fatek-cli commands.

#include "core/commission/checkoutplan.h"
#include "core/protocol/address.h"
#include "core/protocol/protocolerror.h"
#include "core/protocol/request.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <span>

namespace Fatek::CliText {

QString hexBytes(const Bytes &bytes);
QString hexBytes(const QByteArray &bytes);
// Printable view of an answer: control characters as <02>, <03> ... (typed back, raw reads them).
QString asciiView(const QByteArray &bytes);
QString addressText(const Address &address);
// "0x000A" in the element's width; empty for a discrete.
QString valueHex(std::uint32_t value, const Address &address);
QString yesNo(bool b);
// Milliseconds with two decimals.
QString ms(double v);
// A core error as fatek-cli prints it.
QString error(const ProtocolError &e);
// The display formats' names, comma-separated (for usage errors).
QString formatNames();
// A checkout's point as its lines name it: "X3 (StartButton)", and its result: "X3
// (StartButton): Passed (on 09:00:01, off 09:00:02): a remark".
QString checkoutPoint(const CheckoutPoint &point);
QString checkoutResult(const CheckoutPoint &point);

// The answer to a question asked before a dangerous command (restore): --yes answers it, a
// terminal is asked on stderr and answers on stdin ("y"/"yes"); with neither, the command is
// refused (scripts must say --yes).
// Whether standard error is a terminal (progress lines are shown only there).
bool stderrIsTerminal();

enum class Confirmation { Yes, No, NoTerminal };
Confirmation confirm(const QString &question, bool assumeYes);

} // namespace Fatek::CliText
