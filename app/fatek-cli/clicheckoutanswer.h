#pragma once

#include "core/commission/checkoutplan.h"

#include <QString>

#include <optional>

namespace Fatek {

// What a person types at a checkout question: a key and the text after it ("r lamp dim, replace
// bulb": passed with a remark). The same keys for inputs and outputs; which ones a question takes
// is the command's business (an input has no "y", an output no "t").
struct CliCheckoutAnswer
{
    enum class Key {
        Empty,         // an empty line
        Yes,           // y, yes
        No,            // n, no (an output not seen)
        Failed,        // f, fail, failed
        Remark,        // r, remark: passed with a remark
        Deferred,      // d, defer, deferred
        NotApplicable, // na, n/a
        TestAgain,     // t, test
        Skip,          // s, skip
        Unknown,       // anything else: asked again, never taken as a result
    };

    Key key = Key::Empty;
    QString text; // what follows the key, trimmed

    static CliCheckoutAnswer parse(const QString &line);
    // The result the key records, when it records one (No is a failure).
    std::optional<CheckoutResult> result() const;
};

} // namespace Fatek
