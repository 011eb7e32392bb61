#include "gui/grinder/portsettings.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QIntValidator>
#include <QLabel>
#include <QSerialPortInfo>

namespace frezka::gui {

PortSettingsRow::PortSettingsRow(bool offerEmulator, QWidget *parent)
    : QWidget(parent)
    , m_offerEmulator(offerEmulator)
    , m_port(new QComboBox(this))
    , m_baud(new QComboBox(this))
    , m_dataBits(new QComboBox(this))
    , m_parity(new QComboBox(this))
    , m_stopBits(new QComboBox(this))
{
    m_port->setObjectName(QStringLiteral("port"));
    m_port->setEditable(true);
    m_port->setMinimumContentsLength(14);
    m_port->setToolTip(tr("Serial port; a path such as /dev/pts/3 may be typed."));
    m_baud->setObjectName(QStringLiteral("baud"));
    m_baud->setEditable(true);
    m_baud->setValidator(new QIntValidator(50, 4000000, m_baud));
    for (int baud : {300, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200})
        m_baud->addItem(QString::number(baud));
    m_baud->setCurrentText(QStringLiteral("9600"));
    m_dataBits->addItems({QStringLiteral("8"), QStringLiteral("7")});
    m_parity->addItem(tr("none"), QChar('n'));
    m_parity->addItem(tr("even"), QChar('e'));
    m_parity->addItem(tr("odd"), QChar('o'));
    m_stopBits->addItems({QStringLiteral("1"), QStringLiteral("2")});

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Port:"), this));
    layout->addWidget(m_port, 2);
    layout->addWidget(new QLabel(tr("Baud:"), this));
    layout->addWidget(m_baud);
    layout->addWidget(new QLabel(tr("Data bits:"), this));
    layout->addWidget(m_dataBits);
    layout->addWidget(new QLabel(tr("Parity:"), this));
    layout->addWidget(m_parity);
    layout->addWidget(new QLabel(tr("Stop bits:"), this));
    layout->addWidget(m_stopBits);
    refreshPorts();
}

QString PortSettingsRow::emulatorPortName()
{
    return QStringLiteral("emulator");
}

void PortSettingsRow::refreshPorts()
{
    const QString current = m_port->currentText();
    m_port->clear();
    if (m_offerEmulator)
        m_port->addItem(emulatorPortName());
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
        m_port->addItem(info.systemLocation());
    if (!current.isEmpty())
        m_port->setCurrentText(current);
}

grinder::SerialSettings PortSettingsRow::settings() const
{
    grinder::SerialSettings s;
    s.portName = m_port->currentText().trimmed();
    s.baud = m_baud->currentText().toInt();
    s.dataBits = m_dataBits->currentText().toInt();
    s.parity = m_parity->currentData().toChar().toLatin1();
    s.stopBits = m_stopBits->currentText().toInt();
    return s;
}

void PortSettingsRow::setSettings(const grinder::SerialSettings &s)
{
    m_port->setCurrentText(s.portName);
    m_baud->setCurrentText(QString::number(s.baud));
    m_dataBits->setCurrentText(QString::number(s.dataBits));
    const int parity = m_parity->findData(QChar(s.parity));
    m_parity->setCurrentIndex(parity < 0 ? 0 : parity);
    m_stopBits->setCurrentText(QString::number(s.stopBits));
}

} // namespace frezka::gui
