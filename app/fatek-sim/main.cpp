// fatek-sim: a simulated FATEK PLC on TCP, UDP and/or a serial port, both protocols everywhere.

#include "app/common/linkarguments.h"
#include "app/common/programoptions.h"
#include "app/common/quitsignal.h"
#include "core/commission/programimage.h"
#include "core/protocol/logtext.h"
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "core/transport/linksettings.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

using namespace Fatek;

namespace {

QTextStream &out()
{
    static QTextStream stream(stdout);
    return stream;
}

QTextStream &err()
{
    static QTextStream stream(stderr);
    return stream;
}

bool parseInt(const QString &text, int min, int max, int *value)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok || v < min || v > max)
        return false;
    *value = v;
    return true;
}

bool parseRate(const QString &text, double *value)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || v < 0.0 || v > 1.0)
        return false;
    *value = v;
    return true;
}

// The serial line's settings as the other programs read them (--baud, --parity, --data, --stop).
SerialSettings serialSettings(const LinkSettings &link)
{
    SerialSettings s;
    s.portName = link.portName;
    s.baudRate = link.baudRate;
    s.dataBits = link.dataBits == 8 ? QSerialPort::Data8 : QSerialPort::Data7;
    switch (link.parity) {
    case LinkSettings::Parity::None: s.parity = QSerialPort::NoParity; break;
    case LinkSettings::Parity::Even: s.parity = QSerialPort::EvenParity; break;
    case LinkSettings::Parity::Odd: s.parity = QSerialPort::OddParity; break;
    }
    s.stopBits = link.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop;
    return s;
}

// A usage error: exit 2.
int fail(const QString &message)
{
    err() << "fatek-sim: " << message << Qt::endl;
    return 2;
}

// An endpoint that cannot be served (a port taken, a serial device missing): exit 1, as fatek-cli
// --sim when its simulator cannot listen.
int cannotServe(const QString &message)
{
    err() << "fatek-sim: " << message << Qt::endl;
    return 1;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("fatek-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_TEXT));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Simulated FATEK PLC. Answers the FACON ASCII and the FATEK binary protocol "
                       "on every endpoint\n"
                       "(told apart by the first byte of each frame). Stop with Ctrl-C."));
    ProgramOptions::addHelpAndVersion(parser);
    const QCommandLineOption tcpOpt(QStringLiteral("tcp"),
                                    QStringLiteral("Listen on TCP <port> (0: any free port)."),
                                    QStringLiteral("port"));
    const QCommandLineOption udpOpt(QStringLiteral("udp"),
                                    QStringLiteral("Listen on UDP <port> (0: any free port)."),
                                    QStringLiteral("port"));
    const QCommandLineOption serialOpt(
        QStringLiteral("serial"),
        QStringLiteral("Serve on serial port <device> (e.g. /dev/pts/7, COM3)."),
        QStringLiteral("device"));
    // The serial line's settings: the link options of fatek-cli and fatek-studio, same words.
    QList<QCommandLineOption> serialLineOpts;
    for (const QCommandLineOption &option : LinkArguments::commandLineOptions()) {
        const QString name = option.names().constFirst();
        if (name == QLatin1String("baud") || name == QLatin1String("parity")
            || name == QLatin1String("data") || name == QLatin1String("stop"))
            serialLineOpts << option;
    }
    const QCommandLineOption bindOpt(
        QStringLiteral("bind"),
        QStringLiteral("Address to listen on (default 127.0.0.1; 0.0.0.0 for every interface)."),
        QStringLiteral("address"), QStringLiteral("127.0.0.1"));
    const QCommandLineOption stationOpt(QStringLiteral("station"),
                                        QStringLiteral("Station number 1..254 (default 1)."),
                                        QStringLiteral("n"), QStringLiteral("1"));
    const QCommandLineOption profileOpt(QStringLiteral("profile"),
                                        QStringLiteral("Model profile: fbs (default) or m."),
                                        QStringLiteral("name"), QStringLiteral("fbs"));
    const QCommandLineOption ladderOpt(
        QStringLiteral("demo-ladder"),
        QStringLiteral("Run the demo ladder in RUN mode (R0 counter, R1 sine, Y0 blink, DR10 ramp, "
                       "X0..X7 walking bit)."));
    const QCommandLineOption stoppedOpt(QStringLiteral("stopped"),
                                        QStringLiteral("Start in STOP instead of RUN."));
    const QCommandLineOption refuseOpt(
        QStringLiteral("refuse-run"),
        QStringLiteral("Answer RUN commands with error <code> (5, 6, 7 or 9)."),
        QStringLiteral("code"));
    const QCommandLineOption programOpt(
        QStringLiteral("program"),
        QStringLiteral("Load a program backup <file> (fatek-cli backup) into program memory; it "
                       "must be of the profile's model."),
        QStringLiteral("file"));
    const QCommandLineOption verboseOpt(QStringLiteral("verbose"),
                                        QStringLiteral("Log one line per request."));
    const QCommandLineOption latencyOpt(QStringLiteral("latency"),
                                        QStringLiteral("Fault: delay every answer by <ms>."),
                                        QStringLiteral("ms"));
    const QCommandLineOption jitterOpt(QStringLiteral("jitter"),
                                       QStringLiteral("Fault: add 0..<ms> random delay."),
                                       QStringLiteral("ms"));
    const QCommandLineOption turnaroundOpt(QStringLiteral("turnaround"),
                                           QStringLiteral("Slave turnaround delay in ms."),
                                           QStringLiteral("ms"));
    const QCommandLineOption paceOpt(QStringLiteral("pace"),
                                     QStringLiteral("Line-speed emulation: delay each answer by "
                                                    "its wire time at <baud> (10 bits per byte)."),
                                     QStringLiteral("baud"));
    const QCommandLineOption dropOpt(QStringLiteral("drop"),
                                     QStringLiteral("Fault: drop this fraction of answers (0..1)."),
                                     QStringLiteral("rate"));
    const QCommandLineOption corruptOpt(
        QStringLiteral("corrupt"),
        QStringLiteral("Fault: corrupt this fraction of answer bytes (0..1)."),
        QStringLiteral("rate"));
    const QCommandLineOption garbageOpt(
        QStringLiteral("garbage"),
        QStringLiteral("Fault: send <n> noise bytes before each answer."), QStringLiteral("n"));
    const QCommandLineOption chunkOpt(
        QStringLiteral("chunk"), QStringLiteral("Fault: split answers into pieces of <n> bytes."),
        QStringLiteral("n"));
    const QCommandLineOption chunkDelayOpt(QStringLiteral("chunk-delay"),
                                           QStringLiteral("Fault: <ms> between answer pieces."),
                                           QStringLiteral("ms"));
    const QCommandLineOption closeOpt(
        QStringLiteral("close-every"),
        QStringLiteral("Fault: close each TCP connection <s> seconds after it opens."),
        QStringLiteral("s"));
    const QCommandLineOption wrongOpt(
        QStringLiteral("wrong-station"),
        QStringLiteral("Fault: answer this fraction of requests as another station (0..1)."),
        QStringLiteral("rate"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the random faults (default 1)."),
                                     QStringLiteral("n"), QStringLiteral("1"));
    parser.addOptions({tcpOpt,        udpOpt,     serialOpt, bindOpt,    stationOpt, profileOpt,
                       ladderOpt,     stoppedOpt, refuseOpt, verboseOpt, latencyOpt, jitterOpt,
                       turnaroundOpt, paceOpt,    dropOpt,   corruptOpt, garbageOpt, chunkOpt,
                       chunkDelayOpt, closeOpt,   wrongOpt,  seedOpt,    programOpt});
    parser.addOptions(serialLineOpts);
    // Usage errors exit 2, as in the other programs (process() would exit 1).
    if (!parser.parse(QCoreApplication::arguments()))
        return fail(ProgramOptions::errorText(parser));
    if (parser.isSet(QStringLiteral("help")))
        return ProgramOptions::printHelp(parser);
    if (parser.isSet(QStringLiteral("version")))
        return ProgramOptions::printVersion();
    LinkArguments serialLine;
    for (const QString &name :
         {QStringLiteral("serial"), QStringLiteral("baud"), QStringLiteral("parity"),
          QStringLiteral("data"), QStringLiteral("stop")}) {
        if (parser.isSet(name))
            serialLine.set(name, parser.value(name));
    }
    LinkArgumentRules serialRules;
    serialRules.linkRequired = false;
    const LinkArgumentsResult serialResolved = resolveLinkArguments(serialLine, serialRules);
    if (!serialResolved.error.isEmpty())
        return fail(serialResolved.error);

    if (!parser.isSet(tcpOpt) && !parser.isSet(udpOpt) && !parser.isSet(serialOpt))
        return fail(
            QStringLiteral("nothing to serve: give --tcp, --udp and/or --serial (see --help)."));

    const auto profile = ModelProfile::byName(parser.value(profileOpt).toStdString());
    if (!profile)
        return fail(
            QStringLiteral("unknown profile \"%1\": use fbs or m.").arg(parser.value(profileOpt)));
    int station = 1;
    if (!parseInt(parser.value(stationOpt), 1, 254, &station))
        return fail(
            QStringLiteral("station must be 1..254, not \"%1\".").arg(parser.value(stationOpt)));
    const QHostAddress bind(parser.value(bindOpt));
    if (bind.isNull())
        return fail(QStringLiteral("\"%1\" is not an IP address.").arg(parser.value(bindOpt)));

    FaultConfig faults;
    struct IntKnob
    {
        const QCommandLineOption *option;
        int *value;
        int max;
    };
    const IntKnob intKnobs[] = {
        {&latencyOpt, &faults.latencyMs, 600000},
        {&jitterOpt, &faults.jitterMs, 600000},
        {&turnaroundOpt, &faults.turnaroundMs, 600000},
        {&paceOpt, &faults.baud, 10000000},
        {&garbageOpt, &faults.garbageBytes, 100000},
        {&chunkOpt, &faults.chunkSize, 100000},
        {&chunkDelayOpt, &faults.chunkDelayMs, 600000},
        {&closeOpt, &faults.closeEverySeconds, 86400},
    };
    for (const IntKnob &k : intKnobs) {
        if (parser.isSet(*k.option) && !parseInt(parser.value(*k.option), 0, k.max, k.value)) {
            return fail(QStringLiteral("--%1 needs a whole number 0..%2, not \"%3\".")
                            .arg(k.option->names().constFirst())
                            .arg(k.max)
                            .arg(parser.value(*k.option)));
        }
    }
    struct RateKnob
    {
        const QCommandLineOption *option;
        double *value;
    };
    const RateKnob rateKnobs[] = {{&dropOpt, &faults.dropRate},
                                  {&corruptOpt, &faults.corruptRate},
                                  {&wrongOpt, &faults.wrongStationRate}};
    for (const RateKnob &k : rateKnobs) {
        if (parser.isSet(*k.option) && !parseRate(parser.value(*k.option), k.value)) {
            return fail(QStringLiteral("--%1 needs a fraction 0..1, not \"%2\".")
                            .arg(k.option->names().constFirst(), parser.value(*k.option)));
        }
    }
    bool seedOk = false;
    faults.seed = parser.value(seedOpt).toUInt(&seedOk);
    if (!seedOk)
        return fail(
            QStringLiteral("--seed needs a whole number, not \"%1\".").arg(parser.value(seedOpt)));

    SimulatedPlc plc(*profile);
    plc.setRunning(!parser.isSet(stoppedOpt));
    if (parser.isSet(refuseOpt)) {
        const QString code = parser.value(refuseOpt);
        if (code != QLatin1String("5") && code != QLatin1String("6") && code != QLatin1String("7")
            && code != QLatin1String("9")) {
            return fail(QStringLiteral("--refuse-run takes 5, 6, 7 or 9, not \"%1\".").arg(code));
        }
        plc.setRunRefusalCode(static_cast<std::uint8_t>(code.toUInt()));
    }

    if (parser.isSet(programOpt)) {
        const ProgramImage::LoadResult loaded = ProgramImage::load(parser.value(programOpt));
        if (!loaded.ok())
            return fail(QString::fromStdString(loaded.error().text()));
        const ProgramHeader own = profile->programHeader();
        if (!loaded.image().header().sameModel(own) || !plc.setProgram(loaded.image().words())) {
            return fail(QStringLiteral("the program backup %1 is for a %2, the profile \"%3\" is "
                                       "a %4.")
                            .arg(parser.value(programOpt),
                                 QString::fromStdString(english(loaded.image().header().model())),
                                 QString::fromStdString(profile->name),
                                 QString::fromStdString(english(own.model()))));
        }
    }

    SimServer server(&plc);
    server.setStation(static_cast<std::uint8_t>(station));
    server.setBindAddress(bind);
    server.setFaults(faults);
    server.setVerbose(parser.isSet(verboseOpt));
    QObject::connect(&server, &SimServer::logLine, &app, [](const QString &line) {
        out() << QString::fromStdString(escapedForLog(line.toStdString())) << Qt::endl;
    });

    QString error;
    if (parser.isSet(tcpOpt)) {
        int port = 0;
        if (!parseInt(parser.value(tcpOpt), 0, 65535, &port))
            return fail(QStringLiteral("--tcp needs a port 0..65535, not \"%1\".")
                            .arg(parser.value(tcpOpt)));
        if (!server.listenTcp(static_cast<quint16>(port), &error))
            return cannotServe(error);
        out() << "listening on tcp " << bind.toString() << ':' << server.tcpPort() << Qt::endl;
    }
    if (parser.isSet(udpOpt)) {
        int port = 0;
        if (!parseInt(parser.value(udpOpt), 0, 65535, &port))
            return fail(QStringLiteral("--udp needs a port 0..65535, not \"%1\".")
                            .arg(parser.value(udpOpt)));
        if (!server.listenUdp(static_cast<quint16>(port), &error))
            return cannotServe(error);
        out() << "listening on udp " << bind.toString() << ':' << server.udpPort() << Qt::endl;
    }
    if (parser.isSet(serialOpt)) {
        const SerialSettings serial = serialSettings(serialResolved.link);
        if (!server.openSerial(serial, &error))
            return cannotServe(error);
        out() << "listening on serial " << serial.portName << Qt::endl;
    }
    server.setDemoLadder(parser.isSet(ladderOpt));
    out() << "station " << station << ", profile " << QString::fromStdString(profile->description)
          << ", " << (plc.isRunning() ? "RUN" : "STOP")
          << (server.demoLadder() ? ", demo ladder" : "")
          << (parser.isSet(programOpt) ? ", program " + parser.value(programOpt) : QString())
          << ", faults: " << faults.describe() << Qt::endl;

    onQuitSignal(&app, [] { QCoreApplication::quit(); });
    const int rc = app.exec();
    server.close();
    out() << "stopped" << Qt::endl;
    return rc;
}
