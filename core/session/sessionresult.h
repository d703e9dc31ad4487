#pragma once

#include "core/protocol/response.h"
#include "core/protocol/result.h"

#include <QByteArray>
#include <QMetaType>
#include <QString>

namespace Fatek {

// What became of a request that changes the PLC (docs/reliability.md, "Changes to a PLC").
enum class ChangeOutcome {
    Done,    // the PLC answered that it carried it out
    Refused, // not carried out: refused before the wire (nothing sent), or the PLC answered no
    Unknown, // sent and not (intelligibly) answered: it may have been carried out, or still be
};

// The one answer a submitted request gets: a decoded Response or a typed error; for raw frames
// the bytes that came back (raw results carry no Response).
class SessionResult
{
public:
    SessionResult() = default; // for the meta-type system: a Cancelled error
    SessionResult(Result<Response> result, QByteArray rawAnswer = {}, bool raw = false);

    static SessionResult fromError(ProtocolError error, QByteArray rawAnswer = {},
                                   bool raw = false);
    static SessionResult fromRaw(QByteArray rawAnswer);

    bool ok() const { return m_result.ok(); }
    bool isRaw() const { return m_raw; }
    const Result<Response> &result() const { return m_result; }
    // Valid only when ok() and not raw.
    const Response &response() const { return m_result.value(); }
    const ProtocolError &error() const { return m_result.error(); }
    ErrorKind errorKind() const { return m_result.error().kind; }
    // The error sentence in English, or empty.
    QString errorText() const;
    // The error as a message (empty when ok()), for the UI's language.
    Message errorMessage() const;
    // Bytes of the answer frame(s); for raw sends everything received within the timeout.
    QByteArray rawAnswer() const { return m_rawAnswer; }
    // Attempts on the wire (0 when refused before sending).
    int attempts() const { return m_attempts; }
    // For a change (a write, RUN/STOP, forcing, a program page): done, refused, or unknown. An
    // unknown outcome is never a failure: a frame that reached the PLC may have been carried
    // out, its answer lost (ChangeVerifier reads back what it became).
    ChangeOutcome outcome() const;
    void setAttempts(int attempts) { m_attempts = attempts; }

private:
    Result<Response> m_result
        = ProtocolError{ErrorKind::Cancelled, msg<MsgId::SessionNotExecuted>(), 0};
    QByteArray m_rawAnswer;
    bool m_raw = false;
    int m_attempts = 0;
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::SessionResult)
