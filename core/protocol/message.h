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

// Every sentence core shows to a person, by id. The English templates (with %1..%n) are in
// messagelist.h, marked for lupdate in the context "Fatek::Message"; english() fills them in for
// logs, the CLI and tests, the UI translates them (translated(), ui/common/uitext.h).
enum class MsgId : std::uint16_t {
#define FATEK_MSG(id, argc, text) id,
#ifndef Q_MOC_RUN // moc stops at the second list file (the list means nothing to it anyway)
#include "messagelist.h"
#include "messagelistframes.h"
#include "messagelistgateway.h"
#include "messagelistmqtt.h"
#include "messagelistnames.h"
#include "messagelistprogram.h"
#include "messagelistsnapshot.h"
#endif
#undef FATEK_MSG
};

namespace MessageDetail {
inline constexpr int argCounts[] = {
#define FATEK_MSG(id, argc, text) argc,
#ifndef Q_MOC_RUN // moc stops at the second list file (the list means nothing to it anyway)
#include "messagelist.h"
#include "messagelistframes.h"
#include "messagelistgateway.h"
#include "messagelistmqtt.h"
#include "messagelistnames.h"
#include "messagelistprogram.h"
#include "messagelistsnapshot.h"
#endif
#undef FATEK_MSG
};
} // namespace MessageDetail

inline constexpr std::size_t messageIdCount = std::size(MessageDetail::argCounts);

// How many arguments (%1..%n) the template of `id` takes.
constexpr int messageArgCount(MsgId id)
{
    return MessageDetail::argCounts[static_cast<std::size_t>(id)];
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
    MsgId id = MsgId::Text;
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
template<MsgId Id, typename... Args>
Message msg(Args &&...args)
{
    static_assert(sizeof...(Args) == messageArgCount(Id),
                  "argument count differs from the message template (messagelist.h)");
    return Message{Id, {MessageArg(std::forward<Args>(args))...}};
}

// The English template of `id`, with its %1..%n.
const char *messageTemplate(MsgId id);
// The id's name in messagelist.h ("AddressEmpty"), for tests and diagnostics.
const char *messageIdName(MsgId id);
// The lupdate context of the templates.
inline constexpr const char *messageContext = "Fatek::Message";

// Puts args into %1..%9 of `templ` in one pass (an argument containing "%2" stays text).
std::string fillTemplate(std::string_view templ, const std::vector<std::string> &args);

// The message in English: the template filled with the arguments (nested ones in English too).
std::string english(const Message &message);

// "Invalid address ..." becomes "invalid address ..." after a place ("table 2, item 5: "), the
// second argument of MsgId::AtPlace. Acronyms ("BCD ...") keep their case; so does text in a
// script without case.
std::string lowerFirst(std::string text);

} // namespace Fatek
