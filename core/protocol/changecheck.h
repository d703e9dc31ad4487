#pragma once

#include "request.h"
#include "response.h"

#include <optional>

namespace Fatek {

// How to tell, by reading, whether a change reached the PLC: after a write, RUN/STOP or forcing
// whose answer was lost (sent, not answered), the element's state is read and compared with what
// the change asked for (ChangeVerifier does the asking).
namespace ChangeCheck {

// The read whose answer shows whether `change` is in place; nothing when no read can tell (a
// program page, a broadcast, a request that changes nothing).
std::optional<Request> readBack(const Request &change);
// Whether `answer` (to readBack(change)) shows the change in place.
bool inPlace(const Request &change, const Response &answer);

} // namespace ChangeCheck

} // namespace Fatek
