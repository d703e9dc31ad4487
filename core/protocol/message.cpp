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
    for (std::size_t i = 0; i < templ.size(); ++i) {
        const char c = templ[i];
        if (c == '%' && i + 1 < templ.size() && templ[i + 1] >= '1' && templ[i + 1] <= '9') {
            const auto arg = static_cast<std::size_t>(templ[i + 1] - '1');
            if (arg < args.size()) {
                out += args[arg];
                ++i;
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
