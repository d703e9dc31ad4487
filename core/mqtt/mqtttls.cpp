#include "mqtttls.h"

#include "mqttbrokersettings.h"
#include "mqttmessages.h"

#include <mosquitto.h>

#ifndef _WIN32
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>

#include <memory>
#endif

namespace Fatek::MqttTls {

#ifndef _WIN32
namespace {

// OpenSSL's reason for the failure ("bad base64 decode", "no certificate or crl found", "key
// values mismatch"): the first in its queue, the cause (the later ones are the callers giving up,
// "PEM lib").
std::string lastError()
{
    const unsigned long first = ERR_get_error();
    ERR_clear_error();
    const char *reason = first != 0 ? ERR_reason_error_string(first) : nullptr;
    return reason ? reason : "not readable as PEM";
}

} // namespace
#endif

Message checkFiles(const MqttBrokerSettings &settings)
{
#ifdef _WIN32
    Q_UNUSED(settings);
    return {}; // no TLS in this build: validate() refuses TLS settings
#else
    if (!settings.tls)
        return {};
    const std::unique_ptr<SSL_CTX, decltype(&SSL_CTX_free)> ctx(SSL_CTX_new(TLS_client_method()),
                                                                &SSL_CTX_free);
    if (!ctx)
        return {};
    ERR_clear_error();
    const QByteArray ca = settings.caFile.toUtf8();
    if (!ca.isEmpty() && SSL_CTX_load_verify_locations(ctx.get(), ca.constData(), nullptr) != 1)
        return msg<MsgId::MqttTlsCaUnusable>(settings.caFile.toStdString(), lastError());
    if (settings.certFile.isEmpty())
        return {};
    const QByteArray cert = settings.certFile.toUtf8();
    const QByteArray key = settings.keyFile.toUtf8();
    if (SSL_CTX_use_certificate_chain_file(ctx.get(), cert.constData()) != 1)
        return msg<MsgId::MqttTlsCertUnusable>(settings.certFile.toStdString(), lastError());
    if (SSL_CTX_use_PrivateKey_file(ctx.get(), key.constData(), SSL_FILETYPE_PEM) != 1) {
        // OpenSSL loads the key and compares it with the certificate in one step.
        const std::string why = lastError();
        if (why.find("mismatch") != std::string::npos)
            return msg<MsgId::MqttTlsKeyMismatch>(settings.keyFile.toStdString(),
                                                  settings.certFile.toStdString());
        return msg<MsgId::MqttTlsKeyUnusable>(settings.keyFile.toStdString(), why);
    }
    if (SSL_CTX_check_private_key(ctx.get()) != 1)
        return msg<MsgId::MqttTlsKeyMismatch>(settings.keyFile.toStdString(),
                                              settings.certFile.toStdString());
    return {};
#endif
}

std::string verifyFailure(struct mosquitto *mosq)
{
#ifdef _WIN32
    Q_UNUSED(mosq);
    return {};
#else
    const auto *ssl = static_cast<const SSL *>(mosquitto_ssl_get(mosq));
    if (!ssl)
        return {};
    const long result = SSL_get_verify_result(ssl);
    // Unspecified: libmosquitto's own check refused it (the host name), and said so itself.
    if (result == X509_V_OK || result == X509_V_ERR_UNSPECIFIED)
        return {};
    return X509_verify_cert_error_string(result);
#endif
}

} // namespace Fatek::MqttTls
