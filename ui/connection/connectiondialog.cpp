#include "connectiondialog.h"

#include "core/transport/serialtransport.h"
#include "ui/common/uitext.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace Fatek {

namespace {

QComboBox *comboOf(const QList<QPair<QString, int>> &items, QWidget *parent)
{
    auto *combo = new QComboBox(parent);
    for (const auto &item : items)
        combo->addItem(item.first, item.second);
    return combo;
}

void selectData(QComboBox *combo, int value)
{
    const int i = combo->findData(value);
    if (i >= 0)
        combo->setCurrentIndex(i);
}

} // namespace

ConnectionDialog::ConnectionDialog(const QList<SavedConnection> &recent, QWidget *parent)
    : QDialog(parent)
    , m_recent(recent)
{
    setWindowTitle(tr("New Connection"));

    m_recentCombo = new QComboBox(this);
    m_recentCombo->addItem(tr("(new)"));
    for (const SavedConnection &c : recent)
        m_recentCombo->addItem(tr("%1 — %2").arg(c.name, c.linkText()));
    m_recentCombo->setEnabled(!recent.isEmpty());

    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("connectionNameEdit"));
    m_name->setPlaceholderText(tr("e.g. Pump station"));
    m_kind = comboOf({{tr("Serial (RS-232 / RS-485)"), int(LinkSettings::Kind::Serial)},
                      {tr("TCP"), int(LinkSettings::Kind::Tcp)},
                      {tr("UDP"), int(LinkSettings::Kind::Udp)},
                      {tr("MQTT gateway"), gatewayKind}},
                     this);
    m_kind->setObjectName(QStringLiteral("linkKindCombo"));
    m_url = new QLineEdit(this);
    m_url->setObjectName(QStringLiteral("linkUrlEdit"));
    m_url->setPlaceholderText(QStringLiteral("tcp://192.168.1.3:500"));
    // Wide enough for a typical link with its options, so the scheme and host are not scrolled
    // out of sight (the first screenshot showed only "00?protocol=facon&station=1").
    m_url->setMinimumWidth(m_url->fontMetrics().horizontalAdvance(QStringLiteral(
                               "tcp://192.168.100.100:500?protocol=facon&station=1&timeout=1000"))
                           + 16);
    m_url->setToolTip(tr("The link as fatek-cli --link takes it (tcp://HOST:PORT, udp://…, "
                         "serial:///dev/ttyUSB0?baud=19200&format=7E1): type or paste one to "
                         "fill the fields; it follows them."));

    auto *form = m_form = new QFormLayout;
    form->addRow(tr("Re&cent:"), m_recentCombo);
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&Link:"), m_kind);
    form->addRow(tr("&URL:"), m_url);

    // Each kind of link has its rows in this one form, so that every label lines up with the
    // others (a form of their own, in a stack, set its fields apart); updateKind() shows the
    // chosen kind's rows.
    // Serial rows
    m_kindRows[serialRows].first = form->rowCount();
    m_portName = new QComboBox(this);
    m_portName->setEditable(true);
    auto *refresh = new QPushButton(tr("Refresh"), this);
    auto *portRow = new QHBoxLayout;
    portRow->addWidget(m_portName, 1);
    portRow->addWidget(refresh);
    form->addRow(tr("&Port:"), portRow);
    m_baudRate = new QComboBox(this);
    m_baudRate->setEditable(true);
    for (int baud : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600})
        m_baudRate->addItem(QString::number(baud), baud);
    form->addRow(tr("&Baud rate:"), m_baudRate);
    m_dataBits = comboOf({{QStringLiteral("7"), 7}, {QStringLiteral("8"), 8}}, this);
    form->addRow(tr("&Data bits:"), m_dataBits);
    m_parity = comboOf({{tr("None"), int(LinkSettings::Parity::None)},
                        {tr("Even"), int(LinkSettings::Parity::Even)},
                        {tr("Odd"), int(LinkSettings::Parity::Odd)}},
                       this);
    form->addRow(tr("Pa&rity:"), m_parity);
    m_stopBits = comboOf({{QStringLiteral("1"), 1}, {QStringLiteral("2"), 2}}, this);
    form->addRow(tr("&Stop bits:"), m_stopBits);
    m_flowControl = comboOf({{tr("None"), int(LinkSettings::FlowControl::None)},
                             {tr("Hardware (RTS/CTS)"), int(LinkSettings::FlowControl::Hardware)},
                             {tr("Software (XON/XOFF)"), int(LinkSettings::FlowControl::Software)}},
                            this);
    form->addRow(tr("&Flow control:"), m_flowControl);

    m_kindRows[serialRows].second = form->rowCount();

    // Network rows
    m_kindRows[networkRows].first = form->rowCount();
    m_host = new QLineEdit(this);
    form->addRow(tr("&Host:"), m_host);
    m_port = new QSpinBox(this);
    m_port->setRange(1, 65535);
    form->addRow(tr("Po&rt:"), m_port);

    m_kindRows[networkRows].second = form->rowCount();

    // Gateway rows: the PLCs are watched through a fatek-gateway's topics on a broker.
    m_kindRows[gatewayRows].first = form->rowCount();
    m_brokerUrl = new QLineEdit(this);
    m_brokerUrl->setObjectName(QStringLiteral("brokerUrlEdit"));
    m_brokerUrl->setPlaceholderText(QStringLiteral("mqtt://broker:1883"));
    m_brokerUrl->setToolTip(tr("mqtt://host:port, or mqtts://host:port for TLS"));
    form->addRow(tr("&Broker:"), m_brokerUrl);
    m_prefix = new QLineEdit(this);
    m_prefix->setObjectName(QStringLiteral("gatewayPrefixEdit"));
    form->addRow(tr("Topic &prefix:"), m_prefix);
    m_gatewayName = new QLineEdit(this);
    m_gatewayName->setObjectName(QStringLiteral("gatewayNameEdit"));
    m_gatewayName->setPlaceholderText(tr("e.g. line1"));
    m_gatewayName->setToolTip(tr("The connection's name in the gateway's configuration"));
    form->addRow(tr("&Gateway connection:"), m_gatewayName);
    m_brokerUser = new QLineEdit(this);
    m_brokerUser->setObjectName(QStringLiteral("brokerUserEdit"));
    m_brokerUser->setPlaceholderText(tr("optional"));
    form->addRow(tr("&User:"), m_brokerUser);
    m_brokerPassword = new QLineEdit(this);
    m_brokerPassword->setObjectName(QStringLiteral("brokerPasswordEdit"));
    m_brokerPassword->setEchoMode(QLineEdit::Password);
    m_brokerPassword->setPlaceholderText(tr("optional; not saved"));
    form->addRow(tr("Pass&word:"), m_brokerPassword);
    // A TLS file: its path typed or picked, with a label that has a buddy (a row of a layout gets
    // none from addRow, and without one the label shows its "&" as text).
    const auto addFileRow
        = [&](const QString &label, const QString &objectName, const QString &placeholder,
              const QString &pickTitle, const QString &filter) {
              auto *edit = new QLineEdit(this);
              edit->setObjectName(objectName);
              edit->setPlaceholderText(placeholder);
              auto *browse = new QPushButton(tr("Browse…"), this);
              auto *row = new QHBoxLayout;
              row->addWidget(edit, 1);
              row->addWidget(browse);
              auto *rowLabel = new QLabel(label, this);
              rowLabel->setBuddy(edit);
              form->addRow(rowLabel, row);
              connect(browse, &QPushButton::clicked, this, [this, edit, pickTitle, filter] {
                  const QString file
                      = QFileDialog::getOpenFileName(this, pickTitle, edit->text(), filter);
                  if (!file.isEmpty())
                      edit->setText(file);
              });
              return edit;
          };
    const QString certificates = tr("Certificates (*.crt *.pem);;All files (*)");
    m_caFile = addFileRow(tr("TLS CA &file:"), QStringLiteral("brokerCaEdit"),
                          tr("optional; mqtts:// only"), tr("CA Certificate"), certificates);
    // Brokers that ask for a client certificate (require_certificate in mosquitto).
    m_certFile = addFileRow(tr("Client c&ertificate:"), QStringLiteral("brokerCertEdit"),
                            tr("optional; mqtts:// only"), tr("Client Certificate"), certificates);
    m_keyFile = addFileRow(tr("Client &key:"), QStringLiteral("brokerKeyEdit"),
                           tr("with the client certificate"), tr("Client Key"),
                           tr("Keys (*.key *.pem);;All files (*)"));

    m_kindRows[gatewayRows].second = form->rowCount();

    m_protocol = comboOf({{tr("FACON (ASCII)"), int(LinkSettings::ProtocolChoice::Facon)},
                          {tr("Binary"), int(LinkSettings::ProtocolChoice::Binary)},
                          {tr("Auto-detect"), int(LinkSettings::ProtocolChoice::Auto)}},
                         this);
    m_station = new QSpinBox(this);
    m_station->setRange(1, 254);
    m_timeout = new QSpinBox(this);
    m_timeout->setRange(20, 60000);
    m_timeout->setSingleStep(100);
    m_timeout->setSuffix(tr(" ms"));
    m_retries = new QSpinBox(this);
    m_retries->setRange(0, 10);

    form->addRow(tr("Pro&tocol:"), m_protocol);
    form->addRow(tr("St&ation:"), m_station);
    form->addRow(tr("T&imeout:"), m_timeout);
    form->addRow(tr("R&etries:"), m_retries);

    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("connectionErrorLabel"));
    m_error->setWordWrap(true);
    m_error->setVisible(false);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("C&onnect"));
    m_buttons->button(QDialogButtonBox::Ok)->setObjectName(QStringLiteral("connectButton"));

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_error);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectionDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectionDialog::reject);
    connect(refresh, &QPushButton::clicked, this, &ConnectionDialog::refreshPorts);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ConnectionDialog::updateKind);
    connect(m_url, &QLineEdit::editingFinished, this, &ConnectionDialog::takeUrl);
    for (QComboBox *combo : {m_kind, m_dataBits, m_parity, m_stopBits, m_flowControl, m_protocol})
        connect(combo, &QComboBox::currentIndexChanged, this, &ConnectionDialog::updateUrl);
    for (QComboBox *combo : {m_portName, m_baudRate})
        connect(combo, &QComboBox::currentTextChanged, this, &ConnectionDialog::updateUrl);
    for (QSpinBox *spin : {m_port, m_station, m_timeout, m_retries})
        connect(spin, &QSpinBox::valueChanged, this, &ConnectionDialog::updateUrl);
    connect(m_host, &QLineEdit::textChanged, this, &ConnectionDialog::updateUrl);
    connect(m_recentCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index > 0 && index <= m_recent.size())
            setConnection(m_recent.at(index - 1));
    });

    refreshPorts();
    SavedConnection defaults;
    defaults.name = tr("PLC");
    setConnection(defaults);
}

void ConnectionDialog::refreshPorts()
{
    const QString current = m_portName->currentText();
    m_portName->clear();
    for (const SerialPortEntry &port : SerialTransport::availablePorts()) {
        QString label = port.systemPath;
        if (!port.description.isEmpty())
            label += QStringLiteral(" — ") + port.description;
        m_portName->addItem(label, port.systemPath);
    }
    if (!current.isEmpty())
        m_portName->setCurrentText(current);
}

bool ConnectionDialog::isGateway() const
{
    return m_kind->currentData().toInt() == gatewayKind;
}

void ConnectionDialog::updateKind()
{
    const auto kind = static_cast<LinkSettings::Kind>(m_kind->currentData().toInt());
    const std::size_t shown = isGateway()                          ? gatewayRows
                              : kind == LinkSettings::Kind::Serial ? serialRows
                                                                   : networkRows;
    for (std::size_t kindRows = 0; kindRows < m_kindRows.size(); ++kindRows) {
        for (int row = m_kindRows[kindRows].first; row < m_kindRows[kindRows].second; ++row)
            m_form->setRowVisible(row, kindRows == shown);
    }
    // The gateway has its own protocol, timeout and retries per PLC link.
    for (QWidget *row : {static_cast<QWidget *>(m_url), static_cast<QWidget *>(m_protocol),
                         static_cast<QWidget *>(m_timeout), static_cast<QWidget *>(m_retries)})
        m_form->setRowVisible(row, !isGateway());
    layout()->activate();
    resize(width(), sizeHint().height());
}

Result<GatewayWatchSettings> ConnectionDialog::gatewaySettings() const
{
    GatewayWatchSettings settings;
    const Result<MqttBrokerSettings> broker = MqttBrokerSettings::fromUrl(m_brokerUrl->text());
    if (!broker.ok())
        return broker.error();
    settings.broker = *broker;
    // The fields win over a user or password written into the URL.
    if (!m_brokerUser->text().trimmed().isEmpty())
        settings.broker.username = m_brokerUser->text().trimmed();
    if (!m_brokerPassword->text().isEmpty())
        settings.broker.password = m_brokerPassword->text();
    settings.broker.caFile = m_caFile->text().trimmed();
    settings.broker.certFile = m_certFile->text().trimmed();
    settings.broker.keyFile = m_keyFile->text().trimmed();
    settings.prefix = m_prefix->text().trimmed();
    settings.connection = m_gatewayName->text().trimmed();
    return settings;
}

void ConnectionDialog::setLinkFields(const LinkSettings &s)
{
    m_settingFields = true; // one URL update at the end, not one per field
    selectData(m_kind, int(s.kind));
    const int port = m_portName->findData(s.portName);
    if (port >= 0)
        m_portName->setCurrentIndex(port);
    else
        m_portName->setCurrentText(s.portName);
    m_baudRate->setCurrentText(QString::number(s.baudRate));
    selectData(m_dataBits, s.dataBits);
    selectData(m_parity, int(s.parity));
    selectData(m_stopBits, s.stopBits);
    selectData(m_flowControl, int(s.flowControl));
    m_host->setText(s.host);
    m_port->setValue(s.port);
    selectData(m_protocol, int(s.protocol));
    m_timeout->setValue(s.timeoutMs);
    m_retries->setValue(s.retries);
    m_settingFields = false;
    updateUrl();
}

void ConnectionDialog::updateUrl()
{
    if (m_settingFields || isGateway())
        return;
    const SavedConnection c = connection();
    m_url->setText(c.settings.toUrl(c.station));
    // setText leaves the cursor at the end; a longer URL then shows its tail. The start (scheme
    // and host) is what a reader needs, unless they are editing the line.
    if (!m_url->hasFocus())
        m_url->setCursorPosition(0);
}

void ConnectionDialog::takeUrl()
{
    const SavedConnection current = connection();
    const QString text = m_url->text().trimmed();
    if (isGateway() || text.isEmpty() || text == current.settings.toUrl(current.station))
        return;
    Message error;
    const std::optional<LinkSettings::Parsed> parsed
        = LinkSettings::fromUrl(text, &error, current.settings);
    if (!parsed) {
        m_error->setText(translated(error));
        m_error->setVisible(true);
        return;
    }
    m_error->setVisible(false);
    if (parsed->station)
        m_station->setValue(*parsed->station);
    setLinkFields(parsed->settings);
}

void ConnectionDialog::setConnection(const SavedConnection &c)
{
    m_name->setText(c.name);
    m_station->setValue(c.station);
    setLinkFields(c.settings);
    const GatewayWatchSettings gateway = c.gateway.value_or(GatewayWatchSettings{});
    if (c.gateway)
        selectData(m_kind, gatewayKind);
    MqttBrokerSettings urlPart = gateway.broker;
    urlPart.username.clear(); // in its own field
    m_brokerUrl->setText(c.gateway ? urlPart.toUrl() : QString());
    m_brokerUser->setText(gateway.broker.username);
    m_brokerPassword->setText(gateway.broker.password);
    m_caFile->setText(gateway.broker.caFile);
    m_certFile->setText(gateway.broker.certFile);
    m_keyFile->setText(gateway.broker.keyFile);
    m_prefix->setText(gateway.prefix);
    m_gatewayName->setText(gateway.connection);
    updateKind();
}

SavedConnection ConnectionDialog::connection() const
{
    SavedConnection c;
    LinkSettings &s = c.settings;
    c.name = m_name->text().trimmed();
    c.station = static_cast<quint8>(m_station->value());
    s.kind = static_cast<LinkSettings::Kind>(m_kind->currentData().toInt());
    // An item picked from the list carries the system path; typed text is taken as is.
    const int portIndex = m_portName->findText(m_portName->currentText());
    s.portName = portIndex >= 0 ? m_portName->itemData(portIndex).toString()
                                : m_portName->currentText().trimmed();
    s.baudRate = m_baudRate->currentText().toInt();
    s.dataBits = m_dataBits->currentData().toInt();
    s.parity = static_cast<LinkSettings::Parity>(m_parity->currentData().toInt());
    s.stopBits = m_stopBits->currentData().toInt();
    s.flowControl = static_cast<LinkSettings::FlowControl>(m_flowControl->currentData().toInt());
    s.host = m_host->text().trimmed();
    s.port = static_cast<quint16>(m_port->value());
    s.protocol = static_cast<LinkSettings::ProtocolChoice>(m_protocol->currentData().toInt());
    s.timeoutMs = m_timeout->value();
    s.retries = m_retries->value();
    if (isGateway()) {
        const Result<GatewayWatchSettings> gateway = gatewaySettings();
        c.gateway = gateway.ok() ? *gateway : GatewayWatchSettings{};
    }
    return c;
}

void ConnectionDialog::accept()
{
    // A URL typed and not taken yet (Enter in the URL line): it wins over the fields, or stops
    // here with what is wrong with it.
    const SavedConnection fields = connection();
    if (!isGateway() && m_url->text().trimmed() != fields.settings.toUrl(fields.station)) {
        takeUrl();
        if (m_error->isVisible())
            return;
    }
    const SavedConnection c = connection();
    QString problem
        = c.name.isEmpty() ? tr("Give the connection a name.") : translated(c.settings.validate());
    if (isGateway() && !c.name.isEmpty()) {
        const Result<GatewayWatchSettings> gateway = gatewaySettings();
        problem
            = !gateway.ok() ? translated(gateway.error().message) : translated(gateway->validate());
        const MqttBrokerSettings &b = gateway.ok() ? gateway->broker : MqttBrokerSettings{};
        if (problem.isEmpty() && !b.tls
            && !(b.caFile.isEmpty() && b.certFile.isEmpty() && b.keyFile.isEmpty()))
            problem = tr("TLS files need an mqtts:// broker URL.");
    }
    if (problem.isEmpty() && c.settings.kind == LinkSettings::Kind::Serial
        && c.settings.baudRate <= 0)
        problem = tr("The baud rate must be a positive number.");
    if (!problem.isEmpty()) {
        m_error->setText(problem);
        m_error->setVisible(true);
        return;
    }
    QDialog::accept();
}

} // namespace Fatek
