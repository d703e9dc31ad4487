#include "mqttbrokersettings.h"

#include "core/qtbridge/secrets.h"
#include "mqttmessages.h"
#include "mqtttls.h"

#include <QFileInfo>
#include <QUrl>

#include <mosquitto.h>

namespace Fatek {

Result<MqttBrokerSettings> MqttBrokerSettings::fromUrl(const QString &text)
{
    QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::MqttUrlEmpty>());
    if (!trimmed.contains(QStringLiteral("://")))
        trimmed.prepend(QStringLiteral("mqtt://"));
    // The refusals quote the text as given, its password masked: they reach --check, the log
    // and the studio's dialogs.
    const std::string shown = Secrets::maskUrl(text.trimmed()).toStdString();
    const QUrl url(trimmed, QUrl::StrictMode);
    const QString scheme = url.scheme().toLower();
    if (!url.isValid() || url.host().isEmpty() || (scheme != u"mqtt" && scheme != u"mqtts")
        || (!url.path().isEmpty() && url.path() != u"/") || url.hasQuery() || url.hasFragment())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::MqttUrlInvalid>(shown));
    MqttBrokerSettings settings;
    settings.tls = scheme == u"mqtts";
    settings.host = url.host();
    const int port = url.port(settings.tls ? 8883 : 1883);
    if (port <= 0 || port > 65535)
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::MqttUrlInvalid>(shown));
    settings.port = static_cast<quint16>(port);
    settings.username = url.userName(QUrl::FullyDecoded);
    settings.password = url.password(QUrl::FullyDecoded);
    return settings;
}

QString MqttBrokerSettings::toUrl() const
{
    QString url = tls ? QStringLiteral("mqtts://") : QStringLiteral("mqtt://");
    if (!username.isEmpty())
        url += QString::fromUtf8(QUrl::toPercentEncoding(username)) + u'@';
    const bool ipv6 = host.contains(u':');
    url += ipv6 ? u'[' + host + u']' : host;
    if (port != (tls ? 8883 : 1883))
        url += u':' + QString::number(port);
    return url;
}

bool MqttBrokerSettings::tlsAvailable()
{
    // A libmosquitto built without TLS answers every TLS setting with "not supported", before
    // it looks at its arguments; one built with TLS refuses these (no CA) as invalid.
    return mosquitto_tls_set(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr)
           != MOSQ_ERR_NOT_SUPPORTED;
}

Message MqttBrokerSettings::validate() const
{
    if (host.trimmed().isEmpty())
        return msg<MsgId::MqttUrlEmpty>();
    if (port == 0)
        return msg<MsgId::MqttUrlInvalid>(toUrl().toStdString());
    for (const QString *file : {&caFile, &certFile, &keyFile}) {
        if (!file->isEmpty() && !QFileInfo(*file).isReadable())
            return msg<MsgId::MqttTlsFileMissing>(file->toStdString());
    }
    if (certFile.isEmpty() != keyFile.isEmpty())
        return msg<MsgId::MqttTlsCertNeedsKey>();
    // Refused, not warned about: a CA file says the broker is to be checked, a client
    // certificate that the gateway is to show one; in clear text neither happens.
    if (!tls) {
        const std::pair<bool, const char *> tlsOnly[] = {{!caFile.isEmpty(), "caFile"},
                                                         {!certFile.isEmpty(), "certFile"},
                                                         {!keyFile.isEmpty(), "keyFile"},
                                                         {tlsInsecure, "tlsInsecure"}};
        for (const auto &[given, key] : tlsOnly) {
            if (given)
                return msg<MsgId::MqttTlsWithoutTls>(key);
        }
    }
    if (!password.isEmpty() && username.isEmpty())
        return msg<MsgId::MqttPasswordNeedsUser>();
    if (keepAliveSec < 5 || reconnectMinMs < 10 || reconnectMaxMs < reconnectMinMs)
        return msg<MsgId::MqttTimingInvalid>();
    if (tls && !tlsAvailable())
        return msg<MsgId::MqttTlsUnavailable>(toUrl().toStdString());
    return MqttTls::checkFiles(*this);
}

} // namespace Fatek
