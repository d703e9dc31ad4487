#pragma once

#include "core/transport/linksettings.h"

#include <QCommandLineOption>
#include <QList>
#include <QString>
#include <QStringList>

#include <cstdint>

class QCommandLineParser;

namespace Fatek {

// The link options all four programs share: --link URL|@NAME, --tcp HOST[:PORT],
// --udp HOST[:PORT], --serial DEV with --baud --parity --data --stop, --protocol
// facon|binary|auto, --station N, --timeout MS and --retries N. The one place that turns their
// text into LinkSettings (and the one place their usage errors are worded), whichever
// command-line parser collected the text. A link URL is read by LinkSettings::fromUrl; a name
// (@line1) is looked up in the named links file (namedlinks.h).
struct LinkArguments
{
    QString link, tcp, udp, serial;
    QString baud, parity, data, stop;
    QString protocol, station, timeout, retries;
    QStringList media; // the media options given, in order ("link", "tcp", ...), each time

    // The names of the options above (without "--"); each takes a value.
    static const QStringList &names();
    // Takes `value` for the option `name` (without "--"); false if `name` is not a link option.
    bool set(const QString &name, const QString &value);
    // The same options for a QCommandLineParser (help texts included), and their values from it.
    static QList<QCommandLineOption> commandLineOptions();
    static LinkArguments fromParser(const QCommandLineParser &parser);

    // Whether any link option (a medium, or one of the settings that apply to one) was given.
    bool any() const;
};

// How a program wants the link options checked.
struct LinkArgumentRules
{
    // Another way to get a link the program offers instead ("--sim", "--demo"); empty if none.
    QString alternative;
    bool alternativeGiven = false;
    // Without a link (and without the alternative): a usage error, or simply no link.
    bool linkRequired = true;
    // fatek-cli may send to station 0 (broadcast); a window watching values may not.
    int minStation = 0;
    LinkSettings::ProtocolChoice defaultProtocol = LinkSettings::ProtocolChoice::Auto;
    // Scripts: without a link option, FATEK_LINK (a URL or @NAME) is the link, and without
    // --station, FATEK_STATION the station.
    bool environment = false;
};

struct LinkArgumentsResult
{
    bool hasLink = false; // a medium was given (not the alternative, not nothing)
    LinkSettings link;    // the medium's settings (factory defaults, autoReconnect on) + options
    std::uint8_t station = 1;
    bool protocolGiven = false;
    bool timeoutGiven = false;
    QString error; // the usage error; the rest is meaningless when set
};

// Checks the link options against `rules` and builds the settings; `error` says what is wrong.
LinkArgumentsResult resolveLinkArguments(const LinkArguments &arguments,
                                         const LinkArgumentRules &rules);

// A decimal integer in [min, max] (surrounding blanks allowed); false otherwise.
bool parseIntInRange(const QString &text, qint64 min, qint64 max, qint64 *out);

} // namespace Fatek
