// fatek-cli checkout: the answers' keys.
#include "clicheckoutanswer.h"

#include <QRegularExpression>

namespace Fatek {

CliCheckoutAnswer CliCheckoutAnswer::parse(const QString &line)
{
    const QString trimmed = line.trimmed();
    if (trimmed.isEmpty())
        return {};
    const qsizetype blank = trimmed.indexOf(QRegularExpression(QStringLiteral("\\s")));
    const QString word = (blank < 0 ? trimmed : trimmed.left(blank)).toLower();
    const QString rest = blank < 0 ? QString() : trimmed.mid(blank).trimmed();
    const auto is = [&word](std::initializer_list<const char *> names) {
        for (const char *name : names) {
            if (word == QLatin1String(name))
                return true;
        }
        return false;
    };
    Key key = Key::Unknown;
    if (is({"y", "yes"}))
        key = Key::Yes;
    else if (is({"n", "no"}))
        key = Key::No;
    else if (is({"f", "fail", "failed"}))
        key = Key::Failed;
    else if (is({"r", "remark"}))
        key = Key::Remark;
    else if (is({"d", "defer", "deferred"}))
        key = Key::Deferred;
    else if (is({"na", "n/a"}))
        key = Key::NotApplicable;
    else if (is({"t", "test"}))
        key = Key::TestAgain;
    else if (is({"s", "skip"}))
        key = Key::Skip;
    // A sentence is not a key: "no idea" is no, "lamp dim" is not understood.
    return {key, key == Key::Unknown ? trimmed : rest};
}

std::optional<CheckoutResult> CliCheckoutAnswer::result() const
{
    switch (key) {
    case Key::Yes: return CheckoutResult::Passed;
    case Key::No:
    case Key::Failed: return CheckoutResult::Failed;
    case Key::Remark: return CheckoutResult::PassedWithRemark;
    case Key::Deferred: return CheckoutResult::Deferred;
    case Key::NotApplicable: return CheckoutResult::NotApplicable;
    default: return std::nullopt;
    }
}

} // namespace Fatek
