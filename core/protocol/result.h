#pragma once

#include "protocolerror.h"

#include <cassert>
#include <utility>
#include <variant>

namespace Fatek {

// A value or a ProtocolError; the pure protocol code reports every failure this way.
template<typename T>
class Result
{
public:
    Result(T value)
        : m_data(std::in_place_index<0>, std::move(value))
    {}
    Result(ProtocolError error)
        : m_data(std::in_place_index<1>, std::move(error))
    {}

    bool ok() const { return m_data.index() == 0; }
    explicit operator bool() const { return ok(); }

    const T &value() const &
    {
        assert(ok());
        return std::get<0>(m_data);
    }
    T &value() &
    {
        assert(ok());
        return std::get<0>(m_data);
    }
    T &&value() &&
    {
        assert(ok());
        return std::get<0>(std::move(m_data));
    }
    const T &operator*() const & { return value(); }
    const T *operator->() const { return &value(); }

    const ProtocolError &error() const
    {
        assert(!ok());
        return std::get<1>(m_data);
    }

private:
    std::variant<T, ProtocolError> m_data;
};

struct Ok
{
    bool operator==(const Ok &) const = default;
};
using Status = Result<Ok>;

inline ProtocolError makeError(ErrorKind kind, Message message, int plcCode = 0)
{
    return ProtocolError{kind, std::move(message), plcCode};
}
// An error whose sentence has no message id yet: shown in English in every language.
inline ProtocolError makeError(ErrorKind kind, std::string text, int plcCode = 0)
{
    return ProtocolError{kind, Message::text(std::move(text)), plcCode};
}

} // namespace Fatek
