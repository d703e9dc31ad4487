#include "uitext.h"

#include "core/qtbridge/messagetext.h"

#include <QRegularExpression>

namespace Fatek {

QString translated(const Message &message)
{
    return translatedText(message, [](const char *templ) {
        return QCoreApplication::translate(messageContext, templ);
    });
}

QString UiText::modelText(const QString &english)
{
    // The parts DetailStatus::summary() and PlcModel::modelText() write, joined by ", ".
    static const QRegularExpression os(QStringLiteral("^OS (V\\S+)$"));
    static const QRegularExpression program(QStringLiteral("^program (\\d+) words$"));
    static const QRegularExpression points(QStringLiteral("^(\\d+) I/O points$"));
    static const QRegularExpression unitType(QStringLiteral("^main unit type (\\d+)$"));
    QStringList parts = english.split(QStringLiteral(", "));
    for (QString &part : parts) {
        if (const auto m = os.match(part); m.hasMatch())
            part = tr("OS %1").arg(m.captured(1));
        else if (const auto p = program.match(part); p.hasMatch())
            part = tr("program %1 words").arg(p.captured(1));
        else if (const auto n = points.match(part); n.hasMatch())
            part = tr("%1 I/O points").arg(n.captured(1));
        else if (const auto t = unitType.match(part); t.hasMatch())
            part = tr("main unit type %1").arg(t.captured(1));
        else if (part == QLatin1String("M series"))
            part = tr("M series");
    }
    return parts.join(tr(", ", "between the parts of a model text"));
}

QString UiText::linkState(LinkState state)
{
    return translated(linkStateMessage(state));
}

QString UiText::format(DisplayFormat format)
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

QString UiText::elementName(ElementType type)
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

QString UiText::commandName(Command command)
{
    return translated(commandMessage(command));
}

std::optional<DisplayFormat> UiText::formatFromName(const QString &name)
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

QString UiText::protocolChoice(LinkSettings::ProtocolChoice choice)
{
    switch (choice) {
    case LinkSettings::ProtocolChoice::Facon: return QStringLiteral("FACON");
    case LinkSettings::ProtocolChoice::Binary: return tr("binary");
    case LinkSettings::ProtocolChoice::Auto: return tr("auto-detect");
    }
    return protocolChoiceName(choice);
}

QString UiText::settings(const LinkSettings &settings)
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

} // namespace Fatek
