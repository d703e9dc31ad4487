#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace Fatek {

// The lupdate marks of the message lists, defined as Qt defines them (the text itself): the
// protocol layer is plain C++, and a list may be read before any Qt header.
#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(scope, x) x
#endif

// Every sentence core shows to a person has an id: a MessageDef with its name, the number of
// arguments (%1..%n) of its English template, and the template, marked for lupdate in the context
// "Fatek::Message". Each library owns the ids it uses, in an X-macro list of its own folder
// (messagelist.h and messagelistframes.h here, core/watch/watchmessagelist.h, ...), and defines
// them in the namespace MsgId with its <library>messages.h header, which also lists them all
// (protocolMessages below, watchMessages, ...) for lookups by name and for tests. english() fills
// a template in for logs, the CLI and tests; the UI translates it (translated(),
// ui/common/uitext.h). An id is the address of its definition: never copied, never numbered.
struct MessageDef
{
    const char *name; // the id's name ("AddressEmpty"): how a message travels on the wire
    int argc;
    const char *text; // the English template

    constexpr MessageDef(const char *idName, int argCount, const char *templ)
        : name(idName)
        , argc(argCount)
        , text(templ)
    {}
    // A copy would be another id: msg<>() and comparisons take the definition itself.
    MessageDef(const MessageDef &) = delete;
    MessageDef &operator=(const MessageDef &) = delete;
};

// Which message a Message is: a MsgId::X (a MessageDef) converts to it, compares by identity.
class MessageId
{
public:
    constexpr MessageId(const MessageDef &def) noexcept
        : m_def(&def)
    {}

    constexpr const char *name() const { return m_def->name; }
    constexpr int argCount() const { return m_def->argc; }
    constexpr const char *text() const { return m_def->text; }

    friend constexpr bool operator==(MessageId a, MessageId b) { return a.m_def == b.m_def; }

private:
    const MessageDef *m_def;
};

// Defines the ids of an X-macro list in the namespace MsgId (FATEK_MSG_DEFINE) and lists their
// addresses (FATEK_MSG_ADDRESS): see the <library>messages.h headers.
#define FATEK_MSG_DEFINE(id, argc, text) inline constexpr MessageDef id{#id, argc, text};
#define FATEK_MSG_ADDRESS(id, argc, text) &MsgId::id,

namespace MsgId {
#define FATEK_MSG FATEK_MSG_DEFINE
#ifndef Q_MOC_RUN // moc stops at the second list file (the list means nothing to it anyway)
#include "messagelist.h"
#include "messagelistframes.h"
#endif
#undef FATEK_MSG
} // namespace MsgId

// The ids of the two lists above.
inline constexpr const MessageDef *protocolMessages[] = {
#define FATEK_MSG FATEK_MSG_ADDRESS
#ifndef Q_MOC_RUN
#include "messagelist.h"
#include "messagelistframes.h"
#endif
#undef FATEK_MSG
};

// How many arguments (%1..%n) the template of `id` takes.
constexpr int messageArgCount(MessageId id)
{
    return id.argCount();
}

struct Message;

// One argument of a message: a technical token shown as is (an address, a number, a host), or a
// message of its own that is translated too ("link lost: <reason>").
struct MessageArg
{
    std::string text;
    std::shared_ptr<const Message> message;

    MessageArg(std::string value)
        : text(std::move(value))
    {}
    MessageArg(std::string_view value)
        : text(value)
    {}
    MessageArg(const char *value)
        : text(value)
    {}
    template<typename T,
             typename = std::enable_if_t<
                 std::is_integral_v<T> && !std::is_same_v<T, bool> && !std::is_same_v<T, char>>>
    MessageArg(T value)
        : text(std::to_string(value))
    {}
    MessageArg(Message value);

    bool operator==(const MessageArg &other) const;
};

struct Message
{
    MessageId id = MsgId::Text;
    std::vector<MessageArg> args;

    // A text shown verbatim in every language (the empty message by default): a message from
    // outside the program (an operating-system error already in the user's language) or data.
    static Message text(std::string value) { return Message{MsgId::Text, {std::move(value)}}; }

    bool empty() const;
    bool operator==(const Message &other) const = default;
};

inline MessageArg::MessageArg(Message value)
    : message(std::make_shared<const Message>(std::move(value)))
{}

inline bool MessageArg::operator==(const MessageArg &other) const
{
    if (static_cast<bool>(message) != static_cast<bool>(other.message))
        return false;
    return message ? *message == *other.message : text == other.text;
}

// Builds a message; the number of arguments is checked against the template when compiling.
template<const MessageDef &Id, typename... Args>
Message msg(Args &&...args)
{
    static_assert(sizeof...(Args) == Id.argc,
                  "argument count differs from the message template (its message list)");
    return Message{Id, {MessageArg(std::forward<Args>(args))...}};
}

// The English template of `id`, with its %1..%n.
constexpr const char *messageTemplate(MessageId id)
{
    return id.text();
}
// The id's name in its list ("AddressEmpty"): how it travels on the wire, for tests and
// diagnostics.
constexpr const char *messageIdName(MessageId id)
{
    return id.name();
}
// The lupdate context of the templates.
inline constexpr const char *messageContext = "Fatek::Message";

// Puts args into %1..%9 of `templ` in one pass (an argument containing "%2" stays text), and
// picks the words of a count: "{2:request|requests}" is "request" when argument 2 is "1", else
// "requests" (a translation without plurals just leaves the braces out).
std::string fillTemplate(std::string_view templ, const std::vector<std::string> &args);

// The message in English: the template filled with the arguments (nested ones in English too).
std::string english(const Message &message);

// "Invalid address ..." becomes "invalid address ..." after a place ("table 2, item 5: "), the
// second argument of MsgId::AtPlace. Acronyms ("BCD ...") keep their case; so does text in a
// script without case.
std::string lowerFirst(std::string text);

} // namespace Fatek
