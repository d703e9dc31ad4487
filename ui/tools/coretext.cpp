#include "coretext.h"

#include "core/protocol/protocolerror.h"

#include <QRegularExpression>

#include <array>

namespace Fatek {

namespace {

// Core message patterns and their translatable templates: %1.. are the captured groups, which are
// translated again (a reason inside "link lost: …" is itself a core message).
enum class Special { None, PlcError, DeviceReason, Traffic };

struct Pattern
{
    const char *regex;
    const char *text;
    Special special = Special::None;
};

constexpr const char *context = "Fatek::CoreText";

const Pattern patterns[] = {
    // Session engine.
    {R"re(^PLC error ([0-9A-F]+): (.*)$)re", nullptr, Special::PlcError},
    // Traffic log: frame summaries of the codecs ("station 1, 46 read consecutive registers: …").
    {R"re(^station (\d+), ([0-9A-F]{2}) (.*)$)re", nullptr, Special::Traffic},
    {R"re(^invalid FACON frame \((\d+) bytes\): (.*)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "invalid FACON frame (%1 bytes): %2")},
    {R"re(^bad binary frame \((\d+) bytes\): (.*)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "bad binary frame (%1 bytes): %2")},
    {R"re(^answer: OK$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: OK")},
    {R"re(^answer: OK, (\d+) data chars "(.*)"$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: OK, %1 data chars \"%2\"")},
    {R"re(^answer: OK, (\d+) data bytes: (.*)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: OK, %1 data bytes: %2")},
    {R"re(^answer: no error digit$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: no error digit")},
    {R"re(^answer: no error byte$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: no error byte")},
    {R"re(^answer: malformed "(.*)"$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: malformed \"%1\"")},
    {R"re(^answer: echo of (\d+) bytes$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "answer: echo of %1 bytes")},
    {R"re(^answer: error ([0-9A-F]+) \((.*)\)$)re", nullptr, Special::PlcError},
    {R"re(^unknown command, data "(.*)"$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "unknown command, data \"%1\"")},
    {R"re(^(\d+) chars "(.*)"$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "%1 chars \"%2\"")},
    {R"re(^STOP, or answer: no error$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "STOP, or answer: no error")},
    {R"re(^(\d+) elements((?: [A-Z]+\d+)*(?: \.\.\.)?)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "%1 elements%2")},
    {R"re(^page (\d+)$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "page %1")},
    {R"re(^page (\d+), 64 words$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "page %1, 64 words")},
    {R"re(^disable (\w+)$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "disable %1")},
    {R"re(^enable (\w+)$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "enable %1")},
    {R"re(^set (\w+)$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "set %1")},
    {R"re(^reset (\w+)$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "reset %1")},
    // Traffic log events and their notes.
    {R"re(^link lost$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "link lost")},
    {R"re(^stale bytes discarded$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "stale bytes discarded")},
    {R"re(^received outside an answer$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "received outside an answer")},
    {R"re(^unexpected bytes$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "unexpected bytes")},
    {R"re(^no query pending$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "no query pending")},
    {R"re(^echo of the query$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "echo of the query")},
    {R"re(^raw answer$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "raw answer")},
    {R"re(^raw frame$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "raw frame")},
    {R"re(^no complete frame$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "no complete frame")},
    {R"re(^more than (\d+) bytes: rest not read$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "more than %1 bytes: rest not read")},
    {R"re(^no answer within (\d+) ms$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "no answer within %1 ms")},
    {R"re(^protocol detected: (.*)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "protocol detected: %1")},
    {R"re(^(\d+) bytes, first (\d+) kept$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "%1 bytes, first %2 kept")},
    {R"re(^link lost: (.*)$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "link lost: %1")},
    {R"re(^(.*); next attempt in ([0-9.]+) s$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "%1; next attempt in %2 s")},
    {R"re(^No answer from station (\d+) within (\d+) ms \(attempt (\d+) of (\d+)\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "No answer from station %1 within %2 ms (attempt %3 of %4).")},
    {R"re(^No answer within (\d+) ms\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "No answer within %1 ms.")},
    {R"re(^Not sent: the link is not open\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Not sent: the link is not open.")},
    {R"re(^Not sent: the link is down \((\w+)\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Not sent: the link is down (%1).")},
    {R"re(^Not sent: (\d+) requests are already waiting on this link \(the PLC answers slower than requests arrive\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Not sent: %1 requests are already waiting on this link (the PLC answers "
                       "slower than requests arrive).")},
    {R"re(^Read-only mode: "(.*)" was not sent\. Leave operator mode to change the PLC\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Read-only mode: \"%1\" was not sent. Leave operator mode to change the "
                       "PLC.")},
    {R"re(^Cancelled before it was sent\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Cancelled before it was sent.")},
    {R"re(^the session was closed$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "the session was closed")},
    {R"re(^the session was closed after waiting (\d+) ms for queued writes$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "the session was closed after waiting %1 ms for queued writes")},
    {R"re(^Not sent: the link is closing\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Not sent: the link is closing.")},
    {R"re(^Not sent: (.*) did not take the frame within (\d+) ms \((\d+) of (\d+) bytes unsent\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Not sent: %1 did not take the frame within %2 ms (%3 of %4 bytes "
                       "unsent).")},
    {R"re(^(.*) does not take data$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "%1 does not take data")},
    {R"re(^closing$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "closing")},
    {R"re(^sending (\d+) queued write\(s\) first, at most (\d+) ms$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "sending %1 queued write(s) first, at most %2 ms")},
    {R"re(^closed$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "closed")},
    {R"re(^connecting$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "connecting")},
    {R"re(^connected$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "connected")},
    {R"re(^lost$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "lost")},
    {R"re(^reconnecting$)re", QT_TRANSLATE_NOOP("Fatek::CoreText", "reconnecting")},
    {R"re(^The answer carries fewer values than asked\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "The answer carries fewer values than asked.")},
    {R"re(^Protocol auto-detect: station (\d+) answered neither in FACON nor in binary \((.*)\)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Protocol auto-detect: station %1 answered neither in FACON nor in binary "
                       "(%2)")},
    {R"re(^Could not write to (.*)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Could not write to %1.")},
    // Transports (the part after the colon is Qt's own, already translated, error text).
    {R"re(^no connection to (.*) within (\d+) ms$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "no connection to %1 within %2 ms")},
    {R"re(^(.*) closed the connection$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "%1 closed the connection")},
    {R"re(^cannot open (\S+): (.*)$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "cannot open %1: %2")},
    // Addresses typed by the user.
    {R"re(^Empty address: type an element such as R12 or X0\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Empty address: type an element such as R12 or X0.")},
    {R"re(^Invalid address "(.*)": it must start with an element type such as R, X or DWM\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Invalid address \"%1\": it must start with an element type such as R, X "
                       "or DWM.")},
    {R"re(^Invalid address "(.*)": unknown element type "(.*)" \(known: (.*)\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Invalid address \"%1\": unknown element type \"%2\" (known: %3).")},
    {R"re(^Invalid address "(.*)": the element number is missing \(e\.g\. (\w+)\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Invalid address \"%1\": the element number is missing (e.g. %2).")},
    {R"re(^Invalid address "(.*)": "(.*)" is not a decimal element number\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Invalid address \"%1\": \"%2\" is not a decimal element number.")},
    {R"re(^Invalid address "(.*)": element number too large\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Invalid address \"%1\": element number too large.")},
    {R"re(^Address (\w+) is out of range: (\w+) numbers go from 0 to (\d+)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Address %1 is out of range: %2 numbers go from 0 to %3.")},
    {R"re(^Address (\w+) is not aligned: (\w+) must start at a multiple of (\d+) \(e\.g\. (\w+)\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Address %1 is not aligned: %2 must start at a multiple of %3 (e.g. %4).")},
    {R"re(^(\d+) elements from (\w+) run past (\w+), the last (\w+)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "%1 elements from %2 run past %3, the last %4.")},
    // Link settings checks.
    {R"re(^Enter the PLC's IP address or host name\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Enter the PLC's IP address or host name.")},
    {R"re(^Choose a serial port\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Choose a serial port.")},
    {R"re(^Baud rate (\d+) is out of range \(1200 to 921600\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Baud rate %1 is out of range (1200 to 921600).")},
    {R"re(^Timeout (\d+) ms is out of range \(1 to 60000 ms\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Timeout %1 ms is out of range (1 to 60000 ms).")},
    {R"re(^Retries (\d+) is out of range \(0 to 10\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Retries %1 is out of range (0 to 10).")},
    // Address ranges typed by the user (AddressRange, WatchList).
    {R"re(^Incomplete range "(.*)": write it as first\.\.last, e\.g\. R100\.\.R163\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Incomplete range \"%1\": write it as first..last, e.g. R100..R163.")},
    {R"re(^Range "(.*)" mixes (\w+) and (\w+): both ends must be the same element type\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Range \"%1\" mixes %2 and %3: both ends must be the same element type.")},
    {R"re(^Range "(.*)" runs backwards: write the lower address first \((.*)\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Range \"%1\" runs backwards: write the lower address first (%2).")},
    {R"re(^Range "(.*)" does not end on a whole element: (\w+) elements are (\d+) apart \((\w+), (\w+), \.\.\.\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Range \"%1\" does not end on a whole element: %2 elements are %3 apart "
                       "(%4, %5, ...).")},
    {R"re(^Range "(.*)" has (\d+) elements; at most (\d+) fit in one range\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Range \"%1\" has %2 elements; at most %3 fit in one range.")},
    {R"re(^No range given; write for example X0-255, Y0-255\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "No range given; write for example X0-255, Y0-255.")},
    // Bytes typed in the raw console (FrameText).
    {R"re(^\x{201C}(.+)\x{201D} is not a hex digit; type bytes like 01 46 03 52 00 0C\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "\u201c%1\u201d is not a hex digit; type bytes like 01 46 03 52 00 0C.")},
    {R"re(^Nothing to send: type the frame's bytes in hex\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Nothing to send: type the frame's bytes in hex.")},
    {R"re(^Odd number of hex digits: each byte needs two \(0C, not C\)\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Odd number of hex digits: each byte needs two (0C, not C).")},
    {R"re(^Only printable ASCII can be typed; write control characters as <STX>, <ETX> or <0D>\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText",
                       "Only printable ASCII can be typed; write control characters as <STX>, "
                       "<ETX> or <0D>.")},
    {R"re(^Nothing to send: type the frame\.$)re",
     QT_TRANSLATE_NOOP("Fatek::CoreText", "Nothing to send: type the frame.")},
    // "TCP 10.0.0.5:500: <Qt error>": device, then Qt's text.
    {R"re(^(\S+): (.*)$)re", nullptr, Special::DeviceReason},
};

QString plcCodeText(int code)
{
    switch (code) {
    case 0x0: return CoreText::tr("no error");
    case 0x2: return CoreText::tr("illegal value");
    case 0x3: return CoreText::tr("write prohibited (ROM pack)");
    case 0x4: return CoreText::tr("illegal format, or command cannot execute");
    case 0x5: return CoreText::tr("cannot RUN: ladder checksum error");
    case 0x6: return CoreText::tr("cannot RUN: PLC ID differs from ladder ID");
    case 0x7: return CoreText::tr("cannot RUN: syntax check error");
    case 0x9: return CoreText::tr("cannot RUN: function not supported");
    case 0xA: return CoreText::tr("illegal address");
    default: return CoreText::tr("unknown error code");
    }
}

const std::vector<QRegularExpression> &compiled()
{
    static const std::vector<QRegularExpression> list = [] {
        std::vector<QRegularExpression> v;
        for (const Pattern &p : patterns)
            v.emplace_back(QString::fromUtf8(p.regex));
        return v;
    }();
    return list;
}

// Puts the (translated) captures into %1..%9 in one pass: a capture containing "%2" stays text.
QString fill(const QString &templ, const QRegularExpressionMatch &m)
{
    QString out;
    out.reserve(templ.size() * 2);
    for (qsizetype i = 0; i < templ.size(); ++i) {
        const QChar c = templ.at(i);
        if (c == QLatin1Char('%') && i + 1 < templ.size() && templ.at(i + 1).isDigit()) {
            const int group = templ.at(i + 1).digitValue();
            if (group >= 1 && group <= m.lastCapturedIndex()) {
                out += CoreText::message(m.captured(group));
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

} // namespace

QString CoreText::linkState(LinkState state)
{
    switch (state) {
    case LinkState::Closed: return tr("closed");
    case LinkState::Connecting: return tr("connecting");
    case LinkState::Connected: return tr("connected");
    case LinkState::Lost: return tr("lost");
    case LinkState::Reconnecting: return tr("reconnecting");
    }
    return {};
}

QString CoreText::format(DisplayFormat format)
{
    switch (format) {
    case DisplayFormat::Bit: return tr("bit");
    case DisplayFormat::Unsigned: return tr("unsigned");
    case DisplayFormat::Signed: return tr("signed");
    case DisplayFormat::Hex: return tr("hex");
    case DisplayFormat::Binary: return tr("binary");
    case DisplayFormat::Bcd: return tr("BCD");
    case DisplayFormat::Float32: return tr("float");
    case DisplayFormat::Ascii: return tr("ASCII");
    case DisplayFormat::Double64: return tr("double");
    }
    return ValueFormat::name(format);
}

QString CoreText::elementName(ElementType type)
{
    using E = ElementType;
    switch (type) {
    case E::X: return tr("input");
    case E::Y: return tr("output relay");
    case E::M: return tr("internal relay");
    case E::S: return tr("step relay");
    case E::T: return tr("timer contact");
    case E::C: return tr("counter contact");
    case E::WX: return tr("inputs as 16-bit word");
    case E::WY: return tr("outputs as 16-bit word");
    case E::WM: return tr("internal relays as 16-bit word");
    case E::WS: return tr("step relays as 16-bit word");
    case E::WT: return tr("timer contacts as 16-bit word");
    case E::WC: return tr("counter contacts as 16-bit word");
    case E::RT: return tr("timer register");
    case E::RC: return tr("counter register");
    case E::R:
    case E::D: return tr("data register");
    case E::F: return tr("file register");
    case E::DWX: return tr("inputs as 32-bit word");
    case E::DWY: return tr("outputs as 32-bit word");
    case E::DWM: return tr("internal relays as 32-bit word");
    case E::DWS: return tr("step relays as 32-bit word");
    case E::DWT: return tr("timer contacts as 32-bit word");
    case E::DWC: return tr("counter contacts as 32-bit word");
    case E::DRT: return tr("timer register pair");
    case E::DRC: return tr("counter register pair");
    case E::DR:
    case E::DD: return tr("data register pair");
    case E::DF: return tr("file register pair");
    }
    return QString::fromStdString(std::string(elementInfo(type).name));
}

QString CoreText::commandName(Command command)
{
    switch (command) {
    case Command::BriefStatus: return tr("read brief status");
    case Command::RunStop: return tr("RUN/STOP control");
    case Command::DiscreteControl: return tr("single discrete control");
    case Command::ReadEnableFlags: return tr("read enable/disable flags");
    case Command::ReadDiscretes: return tr("read consecutive discretes");
    case Command::WriteDiscretes: return tr("write consecutive discretes");
    case Command::ReadRegisters: return tr("read consecutive registers");
    case Command::WriteRegisters: return tr("write consecutive registers");
    case Command::MixedRead: return tr("mixed read");
    case Command::MixedWrite: return tr("mixed write");
    case Command::Loopback: return tr("loopback test");
    case Command::ReadProgram: return tr("read program page");
    case Command::WriteProgram: return tr("write program page");
    case Command::DetailStatus: return tr("read detail status");
    }
    return QString::fromStdString(std::string(Fatek::commandName(command)));
}

std::optional<DisplayFormat> CoreText::formatFromName(const QString &name)
{
    if (const auto f = ValueFormat::fromName(name))
        return f;
    const QString wanted = name.trimmed();
    for (DisplayFormat f : ValueFormat::allFormats()) {
        if (format(f).compare(wanted, Qt::CaseInsensitive) == 0)
            return f;
    }
    return std::nullopt;
}

QString CoreText::protocolChoice(LinkSettings::ProtocolChoice choice)
{
    switch (choice) {
    case LinkSettings::ProtocolChoice::Facon: return QStringLiteral("FACON");
    case LinkSettings::ProtocolChoice::Binary: return tr("binary");
    case LinkSettings::ProtocolChoice::Auto: return tr("auto-detect");
    }
    return protocolChoiceName(choice);
}

QString CoreText::settings(const LinkSettings &settings)
{
    // The medium part is technical (TCP host:port, COM3 9600 7E1, RTS/CTS); only the protocol word
    // and the missing-port note are language.
    QString text = settings.toString();
    const QString suffix = QStringLiteral(", ") + protocolChoiceName(settings.protocol);
    if (text.endsWith(suffix)) {
        text.chop(suffix.size());
        //: Link settings: medium (TCP 10.0.0.5:500, COM3 9600 7E1) and protocol.
        text = tr("%1, %2").arg(text, protocolChoice(settings.protocol));
    }
    text.replace(QStringLiteral("(no port)"), tr("(no port)"));
    return text;
}

QString CoreText::message(const QString &text)
{
    if (text.isEmpty())
        return text;
    const auto &regexes = compiled();
    for (std::size_t i = 0; i < std::size(patterns); ++i) {
        const QRegularExpressionMatch m = regexes[i].match(text);
        if (!m.hasMatch())
            continue;
        if (patterns[i].special == Special::PlcError) {
            // "PLC error A: illegal address R70000": the code's text, then what it was about.
            bool ok = false;
            const int code = m.captured(1).toInt(&ok, 16);
            if (!ok)
                return text;
            const QString english = QString::fromStdString(std::string(plcErrorText(code)));
            QString rest = m.captured(2);
            QString subject;
            if (rest.startsWith(english)) {
                subject = rest.mid(english.size()).trimmed();
                if (subject.startsWith(QLatin1Char(':')))
                    subject = subject.mid(1).trimmed();
            }
            QString out = text.startsWith(QLatin1String("answer: "))
                              ? tr("answer: error %1 (%2)").arg(m.captured(1), plcCodeText(code))
                              : tr("PLC error %1: %2").arg(m.captured(1), plcCodeText(code));
            if (!subject.isEmpty())
                out = tr("%1 %2").arg(out, message(subject));
            return out;
        }
        if (patterns[i].special == Special::Traffic) {
            // "station 1, 46 read consecutive registers: 4 x R0": the command's name from its
            // code, the rest as another core text ("answer: OK", "4 chars …") or tokens.
            bool ok = false;
            const int code = m.captured(2).toInt(&ok, 16);
            QString rest = m.captured(3);
            if (ok && isKnownCommand(static_cast<std::uint8_t>(code))) {
                const auto command = static_cast<Command>(code);
                const QString english
                    = QString::fromStdString(std::string(Fatek::commandName(command)));
                if (rest.startsWith(english)) {
                    QString detail = rest.mid(english.size());
                    rest = commandName(command);
                    if (detail.startsWith(QLatin1String(": ")))
                        rest = tr("%1: %2").arg(rest, message(detail.mid(2)));
                    else if (!detail.isEmpty())
                        rest += detail;
                }
            }
            if (rest == m.captured(3))
                rest = message(rest);
            return tr("station %1, %2 %3").arg(m.captured(1), m.captured(2), rest);
        }
        if (patterns[i].special == Special::DeviceReason) {
            // Device and a reason: translate the reason only when it is a core message.
            const QString reason = message(m.captured(2));
            return reason == m.captured(2) ? text : tr("%1: %2").arg(m.captured(1), reason);
        }
        return fill(QCoreApplication::translate(context, patterns[i].text), m);
    }
    return text;
}

} // namespace Fatek
