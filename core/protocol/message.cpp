#include "message.h"

#include <cctype>

namespace Fatek {

bool Message::empty() const
{
    return id == MsgId::Text
           && (args.empty() || (!args.front().message && args.front().text.empty()));
}

std::string fillTemplate(std::string_view templ, const std::vector<std::string> &args)
{
    std::string out;
    out.reserve(templ.size() + 16 * args.size());
    const auto argAt = [&](char digit) -> const std::string * {
        const auto arg = static_cast<std::size_t>(digit - '1');
        return digit >= '1' && digit <= '9' && arg < args.size() ? &args[arg] : nullptr;
    };
    for (std::size_t i = 0; i < templ.size(); ++i) {
        const char c = templ[i];
        if (c == '%' && i + 1 < templ.size()) {
            if (const std::string *arg = argAt(templ[i + 1])) {
                out += *arg;
                ++i;
                continue;
            }
        }
        if (c == '{' && i + 2 < templ.size() && templ[i + 2] == ':') {
            const std::string *count = argAt(templ[i + 1]);
            const std::size_t bar = templ.find('|', i + 3);
            const std::size_t end = templ.find('}', i + 3);
            if (count && bar != std::string_view::npos && end != std::string_view::npos
                && bar < end) {
                out += *count == "1" ? templ.substr(i + 3, bar - i - 3)
                                     : templ.substr(bar + 1, end - bar - 1);
                i = end;
                continue;
            }
        }
        out += c;
    }
    return out;
}

std::string english(const Message &message)
{
    if (message.id == MsgId::Text) {
        if (message.args.empty())
            return {};
        const MessageArg &arg = message.args.front();
        return arg.message ? english(*arg.message) : arg.text;
    }
    std::vector<std::string> args;
    args.reserve(message.args.size());
    for (const MessageArg &arg : message.args)
        args.push_back(arg.message ? english(*arg.message) : arg.text);
    if (message.id == MsgId::AtPlace && args.size() == 2)
        args[1] = lowerFirst(std::move(args[1]));
    return fillTemplate(messageTemplate(message.id), args);
}

std::string lowerFirst(std::string text)
{
    const auto isUpper = [](char c) {
        return std::isupper(static_cast<unsigned char>(c)) != 0;
    };
    const auto isLower = [](char c) {
        return std::islower(static_cast<unsigned char>(c)) != 0;
    };
    if (text.size() >= 2 && isUpper(text[0]) && isLower(text[1]))
        text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
}

} // namespace Fatek
