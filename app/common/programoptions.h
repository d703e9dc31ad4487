#pragma once

#include <QCommandLineParser>
#include <QString>

namespace Fatek {

// What fatek-sim and fatek-gateway (and fatek-studio) share around QCommandLineParser, so that
// the programs answer alike: -h/--help and -v/--version only (no --help-all: Qt's own options
// are not the user's business), the usage line names the program (not the path it was started
// by), and an unknown option is refused as fatek-cli refuses it: "Unknown option --frobnicate
// (see --help)."
namespace ProgramOptions {

// Adds -h/--help and -v/--version (instead of addHelpOption/addVersionOption).
void addHelpAndVersion(QCommandLineParser &parser);
// The usage error of a failed parser.parse(), in fatek-cli's words.
QString errorText(const QCommandLineParser &parser);
// Prints --help (its usage line naming the program) or the version on stdout; exit code 0.
int printHelp(const QCommandLineParser &parser);
int printVersion();

} // namespace ProgramOptions

} // namespace Fatek
