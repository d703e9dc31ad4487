#pragma once

#include "linksettingsio.h"

#include <QDialog>

#include <array>
#include <utility>

class QComboBox;
class QDialogButtonBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace Fatek {

// Asks for a new connection: name, medium (serial with every line setting, TCP, UDP), protocol,
// station, timeout and retries; or an MQTT gateway's connection (broker URL, topic prefix, the
// gateway's connection name, user, password, TLS CA file). Recent connections prefill it.
class ConnectionDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ConnectionDialog(const QList<SavedConnection> &recent, QWidget *parent = nullptr);

    SavedConnection connection() const;
    void setConnection(const SavedConnection &connection);

    void accept() override;

    // The link combo's value for a gateway connection (the others are LinkSettings::Kind).
    static constexpr int gatewayKind = 100;

private:
    void refreshPorts();
    void updateKind();
    // The URL line follows the fields; a URL typed or pasted into it fills them.
    void updateUrl();
    void takeUrl();
    void setLinkFields(const LinkSettings &settings);
    bool isGateway() const;
    // The gateway part as typed; an error when the broker URL does not read.
    Result<GatewayWatchSettings> gatewaySettings() const;

    QList<SavedConnection> m_recent;
    QComboBox *m_recentCombo;
    QLineEdit *m_name;
    QLineEdit *m_url;
    bool m_settingFields = false;
    QComboBox *m_kind;
    QComboBox *m_portName;
    QComboBox *m_baudRate;
    QComboBox *m_dataBits;
    QComboBox *m_parity;
    QComboBox *m_stopBits;
    QComboBox *m_flowControl;
    QLineEdit *m_host;
    QSpinBox *m_port;
    QLineEdit *m_brokerUrl;
    QLineEdit *m_prefix;
    QLineEdit *m_gatewayName;
    QLineEdit *m_brokerUser;
    QLineEdit *m_brokerPassword;
    QLineEdit *m_caFile;
    QLineEdit *m_certFile;
    QLineEdit *m_keyFile;
    QFormLayout *m_form;
    // The form's rows of each kind of link: [first, end).
    enum KindRows { serialRows, networkRows, gatewayRows };
    std::array<std::pair<int, int>, 3> m_kindRows{};
    QComboBox *m_protocol;
    QSpinBox *m_station;
    QSpinBox *m_timeout;
    QSpinBox *m_retries;
    QLabel *m_error;
    QDialogButtonBox *m_buttons;
};

} // namespace Fatek
