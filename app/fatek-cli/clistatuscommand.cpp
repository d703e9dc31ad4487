// fatek-cli status.
#include "clistatuscommand.h"

#include "clicontext.h"
#include "clitext.h"
#include "core/protocol/plcstatus.h"

namespace Fatek {

using namespace CliText;

namespace {

// The detail status's 16-bit fields: label (table), key (JSON), field.
struct SizeField
{
    const char *label;
    const char *key;
    std::optional<std::uint16_t> DetailStatus::*field;
};

constexpr SizeField sizeFields[] = {
    {"program words", "ladderSize", &DetailStatus::ladderSize},
    {"X points", "discreteInputs", &DetailStatus::discreteInputs},
    {"Y points", "discreteOutputs", &DetailStatus::discreteOutputs},
    {"analog inputs", "analogInputs", &DetailStatus::analogInputs},
    {"analog outputs", "analogOutputs", &DetailStatus::analogOutputs},
    {"M relays", "mRelays", &DetailStatus::mRelays},
    {"S relays", "sRelays", &DetailStatus::sRelays},
    {"L relays", "lRelays", &DetailStatus::lRelays},
    {"R registers", "rRegisters", &DetailStatus::rRegisters},
    {"D registers", "dRegisters", &DetailStatus::dRegisters},
    {"timers", "timers", &DetailStatus::timers},
    {"counters", "counters", &DetailStatus::counters},
};

} // namespace

void CliStatusCommand::run()
{
    m_context.submit(Request::briefStatus(m_context.station()), [this](const SessionResult &brief) {
        if (!brief.ok())
            return m_context.failWith(brief);
        const Bytes briefBytes = brief.response().data;
        m_context.submit(Request::detailStatus(m_context.station()),
                         [this, briefBytes](const SessionResult &detail) {
                             if (!detail.ok()
                                 && CliContext::exitCodeFor(detail.errorKind()) == ExitCode::Link)
                                 return m_context.failWith(detail);
                             report(briefBytes, detail);
                         });
    });
}

void CliStatusCommand::report(const Bytes &briefBytes, const SessionResult &detail)
{
    const std::uint8_t status1 = briefBytes.empty() ? 0 : briefBytes.front();
    const PlcStatus s = PlcStatus::fromStatus1(status1);
    OutputBlock block;
    block.columns = {QStringLiteral("field"), QStringLiteral("value")};
    block.tableHeader = false;
    QJsonObject json;
    auto add = [&](const QString &label, const QString &key, const QJsonValue &jsonValue,
                   const QString &text) {
        block.rows << QStringList{label, text};
        json.insert(key, jsonValue);
    };
    auto flag = [&](const QString &label, const QString &key, bool value) {
        add(label, key, value, yesNo(value));
    };
    const auto proto = protocolName(m_context.session()->protocol());
    add(QStringLiteral("station"), QStringLiteral("station"), m_context.station(),
        m_context.stationText());
    add(QStringLiteral("protocol"), QStringLiteral("protocol"),
        QString::fromLatin1(proto.data(), static_cast<qsizetype>(proto.size())),
        QString::fromLatin1(proto.data(), static_cast<qsizetype>(proto.size())));
    add(QStringLiteral("mode"), QStringLiteral("mode"),
        s.running ? QStringLiteral("RUN") : QStringLiteral("STOP"),
        s.running ? QStringLiteral("RUN") : QStringLiteral("STOP"));
    add(QStringLiteral("STATUS1"), QStringLiteral("status1"), status1,
        QStringLiteral("0x%1")
            .arg(status1, 2, 16, QLatin1Char('0'))
            .toUpper()
            .replace(QLatin1String("0X"), QLatin1String("0x")));
    add(QStringLiteral("status bytes"), QStringLiteral("statusBytes"), hexBytes(briefBytes),
        hexBytes(briefBytes));
    flag(QStringLiteral("running"), QStringLiteral("running"), s.running);
    flag(QStringLiteral("battery low"), QStringLiteral("batteryLow"), s.batteryLow);
    flag(QStringLiteral("ladder checksum error"), QStringLiteral("ladderChecksumError"),
         s.ladderChecksumError);
    flag(QStringLiteral("memory pack"), QStringLiteral("memoryPack"), s.memoryPack);
    flag(QStringLiteral("watchdog error"), QStringLiteral("watchdogError"), s.watchdogError);
    flag(QStringLiteral("ID set"), QStringLiteral("idSet"), s.idSet);
    flag(QStringLiteral("emergency stop"), QStringLiteral("emergencyStop"), s.emergencyStop);
    if (detail.ok()) {
        const DetailStatus d = DetailStatus::decode(detail.response().data);
        QJsonObject dj;
        block.rows << QStringList{QStringLiteral("detail"), QString::fromStdString(d.summary())};
        dj.insert(QStringLiteral("summary"), QString::fromStdString(d.summary()));
        dj.insert(QStringLiteral("raw"), hexBytes(d.raw));
        // The fields this PLC reports (8 or 16 bits wide).
        auto opt = [&](const QString &label, const QString &key, const auto &v) {
            if (!v)
                return;
            block.rows << QStringList{label, QString::number(*v)};
            dj.insert(key, *v);
        };
        opt(QStringLiteral("main unit type"), QStringLiteral("mainUnitType"), d.mainUnitType);
        opt(QStringLiteral("I/O points code"), QStringLiteral("ioPointsCode"), d.ioPointsCode);
        if (d.osVersion) {
            const std::optional<std::string> text = d.osVersionText();
            const QString os
                = text ? QString::fromStdString(*text)
                       : QStringLiteral("0x%1").arg(*d.osVersion, 2, 16, QLatin1Char('0'));
            block.rows << QStringList{QStringLiteral("OS version"), os};
            dj.insert(QStringLiteral("osVersion"), os);
        }
        for (const auto &[label, key, field] : sizeFields)
            opt(QLatin1String(label), QLatin1String(key), d.*field);
        json.insert(QStringLiteral("detail"), dj);
    } else {
        // Some PLCs refuse 53: the brief status still stands.
        block.rows << QStringList{QStringLiteral("detail"),
                                  QStringLiteral("unavailable (%1)").arg(detail.errorText())};
        json.insert(QStringLiteral("detailError"), detail.errorText());
    }
    block.json << json;
    succeedWith(block);
}

} // namespace Fatek
