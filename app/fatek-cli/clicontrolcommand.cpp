// fatek-cli set / reset / enable / disable.
#include "clicontrolcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"

namespace Fatek {

using namespace CliText;

// set|reset|enable|disable ADDR
QString CliControlCommand::parse(CliStepArgs &a)
{
    CliStep &s = a.step;
    auto address = Address::parse(a.positional.at(0).toStdString());
    if (!address)
        return CliText::error(address.error());
    if (!isDiscrete(address.value().type))
        return QStringLiteral("%1 works on discretes (X Y M S T C), not %2.")
            .arg(a.cmd(), QString::fromStdString(address.value().toString()));
    s.addresses = {address.value()};
    const DiscreteOp op = a.cmd() == QLatin1String("set")      ? DiscreteOp::Set
                          : a.cmd() == QLatin1String("reset")  ? DiscreteOp::Reset
                          : a.cmd() == QLatin1String("enable") ? DiscreteOp::Enable
                                                               : DiscreteOp::Disable;
    s.controlOp = static_cast<int>(op);
    return {};
}

void CliControlCommand::run()
{
    const Address a = step().addresses.first();
    const auto op = static_cast<DiscreteOp>(step().controlOp);
    m_context.submitChange(
        Request::discreteControl(m_context.station(), op, a), [this, a, op](const SessionResult &) {
            const auto name = discreteOpName(op);
            const QString action
                = QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
            OutputBlock block;
            block.columns
                = {QStringLiteral("station"), QStringLiteral("address"), QStringLiteral("action")};
            block.rows << QStringList{m_context.stationText(), addressText(a), action};
            QJsonObject json = m_context.itemJson(a);
            json.insert(QStringLiteral("action"), action);
            json.insert(QStringLiteral("ok"), true);
            block.json << json;
            succeedWith(block);
        });
}

} // namespace Fatek
