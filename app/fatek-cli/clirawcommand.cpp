// fatek-cli raw.
#include "clirawcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/protocol/frametext.h"

namespace Fatek {

using namespace CliText;

// raw HEX|ASCII
QString CliRawCommand::parse(CliStepArgs &a)
{
    if (a.forceHex && a.forceAscii)
        return QStringLiteral("raw: give --hex or --ascii, not both.");
    QString err;
    a.step.rawBytes = parseRawText(a.positional.join(QLatin1Char(' ')), a.forceHex, a.forceAscii,
                                   &err, &a.step.rawHex);
    a.step.rawFrame = a.frameGiven;
    return err;
}

QByteArray CliRawCommand::parseRawText(const QString &text, bool forceHex, bool forceAscii,
                                       QString *error, bool *isHex)
{
    const QString t = text.trimmed();
    if (t.isEmpty()) {
        *error = QStringLiteral("raw needs the bytes to send.");
        return {};
    }
    const FrameText::Typed typed = forceHex     ? FrameText::Typed::Hex
                                   : forceAscii ? FrameText::Typed::Ascii
                                                : FrameText::Typed::Guess;
    const Result<Bytes> bytes = FrameText::parse(t.toStdString(), typed, isHex);
    if (!bytes) {
        *error
            = QStringLiteral("\"%1\": %2").arg(text, QString::fromStdString(bytes.error().text()));
        return {};
    }
    return QByteArray(reinterpret_cast<const char *>(bytes->data()),
                      static_cast<qsizetype>(bytes->size()));
}

void CliRawCommand::run()
{
    Session *session = m_context.session();
    const quint64 before = session->trafficLog()->entries().isEmpty()
                               ? 0
                               : session->trafficLog()->entries().constLast().sequence;
    RequestOptions requestOptions;
    requestOptions.station = m_context.station();
    // Under auto-detect the bytes say which framing is meant (hex: binary bytes, text: FACON
    // characters), so no status probe goes before the frame.
    if (step().rawFrame && options().link.protocol == LinkSettings::ProtocolChoice::Auto
        && !session->isProtocolKnown())
        requestOptions.framing = step().rawHex ? Protocol::Binary : Protocol::Facon;
    auto onResult = [this, session, before](const SessionResult &r) {
        if (!r.ok())
            return m_context.failWith(r);
        // What actually went out (with framing and checksum when --frame was given).
        QByteArray sent = step().rawBytes;
        for (const TrafficEntry &e : session->trafficLog()->entries(before)) {
            if (e.direction == TrafficEntry::Direction::Out)
                sent = e.bytes;
        }
        OutputBlock block;
        block.columns = {QStringLiteral("field"), QStringLiteral("value")};
        block.tableHeader = false;
        block.rows << QStringList{QStringLiteral("sent"), hexBytes(sent)}
                   << QStringList{QStringLiteral("sent text"), asciiView(sent)}
                   << QStringList{QStringLiteral("answer"), hexBytes(r.rawAnswer())}
                   << QStringList{QStringLiteral("answer text"), asciiView(r.rawAnswer())};
        QJsonObject json;
        json.insert(QStringLiteral("sent"), hexBytes(sent));
        json.insert(QStringLiteral("answer"), hexBytes(r.rawAnswer()));
        json.insert(QStringLiteral("answerText"), asciiView(r.rawAnswer()));
        block.json << json;
        succeedWith(block);
    };
    m_context.requests().sendRaw(step().rawBytes, step().rawFrame,
                                 m_context.watched(std::move(onResult)), requestOptions);
    m_context.armWatchdog(m_context.requestBudgetMs());
}

} // namespace Fatek
