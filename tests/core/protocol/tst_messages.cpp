// Core messages (every library's list: core/protocol/messagelist.h, core/watch/watchmessagelist.h,
// ...; docs/architecture.md): every id has an English template whose placeholders
// are the %1..%n its argument count promises (the count msg<>() checks when compiling), both
// shipped translations (the .qm files the program embeds) carry it with the same placeholders,
// and the Chinese one is Chinese. english() and the UI's translated() fill them in alike.
#include "ui/common/uitext.h"

#include "core/alarm/alarmmessages.h"
#include "core/commission/commissionmessages.h"
#include "core/gateway/gatewaymessages.h"
#include "core/history/historymessages.h"
#include "core/link/linkmessages.h"
#include "core/mqtt/mqttmessages.h"
#include "core/protocol/message.h"
#include "core/protocol/protocolerror.h"
#include "core/protocol/request.h"
#include "core/watch/watchmessages.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QSet>
#include <QTest>
#include <QTranslator>

#include <span>

using namespace Fatek;

namespace {

// Templates whose Chinese text is rightly the same as the English one: joins of two parts.
const QList<MessageId> sameInChinese = {MsgId::Spaced};

// The ids of every library's list (a name twice would not compile here: one namespace MsgId).
QList<MessageId> allIds()
{
    QList<MessageId> ids;
    for (const auto &list : {std::span<const MessageDef *const>(protocolMessages),
                             std::span<const MessageDef *const>(watchMessages),
                             std::span<const MessageDef *const>(commissionMessages),
                             std::span<const MessageDef *const>(mqttMessages),
                             std::span<const MessageDef *const>(linkMessages),
                             std::span<const MessageDef *const>(gatewayMessages),
                             std::span<const MessageDef *const>(alarmMessages),
                             std::span<const MessageDef *const>(historyMessages)}) {
        for (const MessageDef *def : list)
            ids.append(*def);
    }
    return ids;
}

QString templateOf(MessageId id)
{
    return QString::fromUtf8(messageTemplate(id));
}

// The placeholder numbers a text uses, e.g. {1, 2} for "%1: %2".
QSet<int> placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%(\\d)"));
    QSet<int> found;
    for (const QRegularExpressionMatch &m : re.globalMatch(text))
        found.insert(m.captured(1).toInt());
    return found;
}

QSet<int> expected(MessageId id)
{
    QSet<int> numbers;
    for (int i = 1; i <= messageArgCount(id); ++i)
        numbers.insert(i);
    return numbers;
}

// A message of `id` with distinct token arguments ("<1>", "<2>", ...).
Message sample(MessageId id)
{
    Message m{id, {}};
    for (int i = 1; i <= messageArgCount(id); ++i)
        m.args.emplace_back("<" + std::to_string(i) + ">");
    return m;
}

bool hasHan(const QString &text)
{
    for (const QChar c : text) {
        if (c.script() == QChar::Script_Han)
            return true;
    }
    return false;
}

} // namespace

class TestMessages : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_english.load(QStringLiteral(":/i18n/fatekstudio_en.qm")));
        QVERIFY(m_chinese.load(QStringLiteral(":/i18n/fatekstudio_zh_TW.qm")));
    }

    void templates()
    {
        QSet<QString> names;
        for (MessageId id : allIds()) {
            const QString name = QString::fromUtf8(messageIdName(id));
            QVERIFY2(!names.contains(name), qPrintable(name));
            names.insert(name);
            const QString text = templateOf(id);
            QVERIFY2(!text.isEmpty(), qPrintable(name));
            QVERIFY2(placeholders(text) == expected(id),
                     qPrintable(name + QLatin1String(": ") + text));
            // english() puts every argument where its placeholder is, nothing else.
            QString filled = text;
            // The sample's arguments are no "1": a count's plural words.
            filled.replace(QRegularExpression(QStringLiteral("\\{\\d:[^|}]*\\|([^}]*)\\}")),
                           QStringLiteral("\\1"));
            for (int i = messageArgCount(id); i >= 1; --i)
                filled.replace(QStringLiteral("%%1").arg(i), QStringLiteral("<%1>").arg(i));
            QCOMPARE(QString::fromStdString(english(sample(id))), filled);
        }
    }

    void bothLanguages()
    {
        for (MessageId id : allIds()) {
            if (id == MsgId::Text)
                continue; // data, never translated
            const QString name = QString::fromUtf8(messageIdName(id));
            const char *source = messageTemplate(id);
            const QString english = m_english.translate(messageContext, source);
            QVERIFY2(english == templateOf(id),
                     qPrintable(name + QLatin1String(": en: ") + english));
            const QString chinese = m_chinese.translate(messageContext, source);
            QVERIFY2(!chinese.isEmpty(),
                     qPrintable(name + QLatin1String(": no zh_TW translation")));
            QVERIFY2(placeholders(chinese) == expected(id),
                     qPrintable(name + QLatin1String(": ") + chinese));
            if (!sameInChinese.contains(id)) {
                QVERIFY2(chinese != english,
                         qPrintable(name + QLatin1String(": zh_TW is the English text")));
                // Pure joins ("%1: %2") carry only punctuation; every sentence has Chinese words.
                if (!QString(english)
                         .remove(QRegularExpression(QStringLiteral("%\\d")))
                         .contains(QRegularExpression(QStringLiteral("[A-Za-z]{2,}"))))
                    continue;
                QVERIFY2(hasHan(chinese), qPrintable(name + QLatin1String(": ") + chinese));
            }
        }
    }

    void translatedFillsArguments()
    {
        QCoreApplication::installTranslator(&m_chinese);
        for (MessageId id : allIds()) {
            const Message m = sample(id);
            const QString shown = translated(m);
            for (int i = 1; i <= messageArgCount(id); ++i)
                QVERIFY2(shown.contains(QStringLiteral("<%1>").arg(i)), qPrintable(shown));
        }
        // Nested messages are translated too; tokens stay as they are.
        const Message plc = makePlcError(0xA, "R70000").message;
        QCOMPARE(QString::fromStdString(english(plc)),
                 QStringLiteral("PLC error A: illegal address R70000"));
        QCOMPARE(translated(plc), QStringLiteral("PLC 錯誤 A：不合法的位址 R70000"));
        // An argument that looks like a placeholder stays text.
        QCOMPARE(translated(msg<MsgId::LinkDoesNotTakeData>("%2")),
                 QStringLiteral("%2 不接受資料"));
        QCOMPARE(english(msg<MsgId::LinkDoesNotTakeData>("%2")),
                 std::string("%2 does not take data"));
        QCoreApplication::removeTranslator(&m_chinese);
        // Without a translation the UI shows what english() writes.
        QCOMPARE(translated(plc), QString::fromStdString(english(plc)));
        QCOMPARE(UiText::commandName(Command::ReadRegisters),
                 QStringLiteral("read consecutive registers"));
    }

    // "1 values", "in 1 requests" (issue 32): a count's words follow it, in English and in the UI.
    void pluralWords()
    {
        QCOMPARE(english(msg<MsgId::RestoreDone>(12, 1)),
                 std::string("12 values written in 1 request and read back equal."));
        QCOMPARE(english(msg<MsgId::RestoreDone>(1, 3)),
                 std::string("1 value written in 3 requests and read back equal."));
        QCOMPARE(english(msg<MsgId::DiffCount>(1, 5)), std::string("1 of 5 values differs."));
        QCOMPARE(english(msg<MsgId::DiffCount>(2, 5)), std::string("2 of 5 values differ."));
        QCOMPARE(english(msg<MsgId::DiffCount>(1, 1)), std::string("1 of 1 value differs."));
        QCOMPARE(translated(msg<MsgId::SnapshotTaken>(1, 1)),
                 QStringLiteral("1 value read in 1 request."));
        // A brace that is not a count's choice stays text.
        QCOMPARE(fillTemplate("{x} {9:a|b} {1:a", {"1"}), std::string("{x} {9:a|b} {1:a"));
        QCoreApplication::installTranslator(&m_chinese);
        const QString chinese = translated(msg<MsgId::SnapshotTaken>(1, 1));
        QCoreApplication::removeTranslator(&m_chinese);
        QVERIFY2(!chinese.contains(QLatin1Char('{')) && chinese.contains(QLatin1Char('1')),
                 qPrintable(chinese));
    }

    void watchListPlaceLowersTheSentence()
    {
        const Message m = msg<MsgId::AtPlace>(msg<MsgId::PlaceItem>(2, 5),
                                              msg<MsgId::AddressNumberTooLarge>("R99999999999"));
        QCOMPARE(english(m),
                 std::string("table 2, item 5: invalid address \"R99999999999\": element number "
                             "too large."));
        QCOMPARE(translated(m), QString::fromStdString(english(m)));
        // Acronyms keep their case.
        QCOMPARE(lowerFirst("BCD values"), std::string("BCD values"));
    }

private:
    QTranslator m_english;
    QTranslator m_chinese;
};

QTEST_GUILESS_MAIN(TestMessages)
#include "tst_messages.moc"
