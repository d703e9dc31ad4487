#include "sessionresult.h"

namespace Fatek {

SessionResult::SessionResult(Result<Response> result, QByteArray rawAnswer, bool raw)
    : m_result(std::move(result))
    , m_rawAnswer(std::move(rawAnswer))
    , m_raw(raw)
{}

SessionResult SessionResult::fromError(ProtocolError error, QByteArray rawAnswer, bool raw)
{
    return SessionResult(Result<Response>(std::move(error)), std::move(rawAnswer), raw);
}

SessionResult SessionResult::fromRaw(QByteArray rawAnswer)
{
    return SessionResult(Result<Response>(Response{}), std::move(rawAnswer), true);
}

ChangeOutcome SessionResult::outcome() const
{
    if (m_result.ok())
        return ChangeOutcome::Done;
    // A PLC that answers with an error code did not carry it out; nothing sent, nothing done.
    if (m_attempts == 0 || m_result.error().kind == ErrorKind::PlcError)
        return ChangeOutcome::Refused;
    return ChangeOutcome::Unknown;
}

QString SessionResult::errorText() const
{
    return m_result.ok() ? QString() : QString::fromStdString(m_result.error().text());
}

Message SessionResult::errorMessage() const
{
    return m_result.ok() ? Message{} : m_result.error().message;
}

} // namespace Fatek
