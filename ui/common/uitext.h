#pragma once

#include "core/protocol/element.h"
#include "core/protocol/message.h"
#include "core/protocol/request.h"
#include "core/session/sessiontypes.h"
#include "core/transport/linksettings.h"
#include "core/watch/valueformat.h"

#include <QCoreApplication>
#include <QString>

namespace Fatek {

// A core message (error, link reason, traffic-log note) in the UI language: its template
// translated in the context "Fatek::Message", arguments that are messages translated too,
// technical tokens (addresses, hosts, hex) as they are. Without a translation it reads in English,
// exactly as english() writes it.
QString translated(const Message &message);

// Core enums and values in the UI language.
class UiText
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::UiText)

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
    // A model text as core records it in snapshots and backups ("FBs-28MC, OS V3.1, program
    // 13184 words", "M series, ...") with its words in the UI language; model names as they are.
    static QString modelText(const QString &english);
    // Display format from a name typed in either language (the file names "unsigned" etc. too).
    static std::optional<DisplayFormat> formatFromName(const QString &name);
};

} // namespace Fatek
