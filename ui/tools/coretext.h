#pragma once

#include "core/protocol/element.h"
#include "core/protocol/request.h"
#include "core/session/sessiontypes.h"
#include "core/transport/linksettings.h"
#include "core/watch/valueformat.h"

#include <QCoreApplication>
#include <QString>

namespace Fatek {

// Texts that come from core (pure C++ protocol layer, session engine, transports) in English for
// logs and the CLI, shown in the UI's language. Known core messages are recognised by pattern and
// rebuilt from translated templates; technical tokens (addresses, hosts, hex) pass through as is.
// A message no pattern knows stays in English rather than being guessed at.
class CoreText
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::CoreText)

public:
    static QString linkState(LinkState state);
    static QString format(DisplayFormat format);
    // What an element type is ("data register" for R and D), as ElementInfo::name says in English.
    static QString elementName(ElementType type);
    // A protocol command ("read consecutive registers" for 46).
    static QString commandName(Command command);
    static QString protocolChoice(LinkSettings::ProtocolChoice choice);
    // LinkSettings::toString() with its words translated ("TCP 10.0.0.5:500, auto-detect").
    static QString settings(const LinkSettings &settings);
    // A core message (error, link reason) in the UI language when it is a known one.
    static QString message(const QString &text);
    static QString message(const std::string &text)
    {
        return message(QString::fromStdString(text));
    }
    // Display format from a name typed in either language (the file names "unsigned" etc. too).
    static std::optional<DisplayFormat> formatFromName(const QString &name);
};

} // namespace Fatek
