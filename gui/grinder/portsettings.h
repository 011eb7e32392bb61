#pragma once
// A row of line settings: port (a typed path is accepted: ptys are not listed), baud, data
// bits, parity, stop bits — KCOMM's "9600,n,8,1".

#include "driver/grinder/transport.h"

#include <QWidget>

class QComboBox;

namespace frezka::gui {

class PortSettingsRow : public QWidget
{
    Q_OBJECT
public:
    // With `offerEmulator` the port list starts with the in-process emulator.
    explicit PortSettingsRow(bool offerEmulator, QWidget *parent = nullptr);

    grinder::SerialSettings settings() const;
    void setSettings(const grinder::SerialSettings &settings);
    // The reserved port name of the in-process emulator.
    static QString emulatorPortName();
    void refreshPorts();

private:
    bool m_offerEmulator;
    QComboBox *m_port;
    QComboBox *m_baud;
    QComboBox *m_dataBits;
    QComboBox *m_parity;
    QComboBox *m_stopBits;
};

} // namespace frezka::gui
