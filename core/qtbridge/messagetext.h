#pragma once

#include "core/protocol/message.h"

#include <QString>

#include <string>
#include <vector>

namespace Fatek {

// A message as text in some language: `translate` turns a template (English, from
// messageTemplate) into its translation (QCoreApplication's for the UI, a report's own
// QTranslator); arguments that are messages are translated the same way, plural words chosen by
// core's fillTemplate. The one path from a message to translated text.
template<typename Translate>
QString translatedText(const Message &message, const Translate &translate)
{
    const auto argText = [&translate](const MessageArg &arg) {
        return arg.message ? translatedText(*arg.message, translate)
                           : QString::fromStdString(arg.text);
    };
    if (message.id == MsgId::Text)
        return message.args.empty() ? QString() : argText(message.args.front());
    std::vector<std::string> args;
    args.reserve(message.args.size());
    for (const MessageArg &arg : message.args)
        args.push_back(argText(arg).toStdString());
    if (message.id == MsgId::AtPlace && args.size() == 2)
        args[1] = lowerFirst(std::move(args[1]));
    const QString templ = translate(messageTemplate(message.id));
    return QString::fromStdString(fillTemplate(templ.toStdString(), args));
}

} // namespace Fatek
