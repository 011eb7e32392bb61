#pragma once
// StatusPanel: what the operator looks at all day, at a glance (issue 16 item 1): the machine's
// state in large words and colour; the actual feed (from the live position, smoothed: the
// window's ActualSpeed) and the programmed feed with the override; the spindle on or off, its
// direction and speed; the tool in the spindle; coolant and the other outputs; the program's
// active modal codes at the line being cut (before a run: once its opening lines have run); the
// homed axes; the connection. A renderer: the main window fills a StatusView from the driver's
// snapshot and the loaded program; the panel keeps no state of its own.

#include "driver/link/machinestate.h"

#include "displayunits.h"

#include <QWidget>

#include <array>
#include <utility>
#include <vector>

class QLabel;

namespace frezka::gui {

struct StatusView
{
    driver::MachineMode mode = driver::MachineMode::Disconnected;
    double actualFeedMmPerMin = 0;
    double programmedFeedMmPerMin = -1; // < 0: no program line
    int overridePercent = 100;
    int overrideHeldPercent = 0; // what the unit runs when the link holds it down (0: none)
    bool spindleOn = false;
    int spindleDirection = 0; // as programmed: 1 M3, -1 M4, 0 unknown
    double spindleRpm = 0;
    int spindleOverridePercent = 100; // the operator's spindle override (issue 16 item 5)
    int tool = -1;                    // -1: no program
    std::vector<std::pair<QString, bool>> outputs; // caption, on
    QString modes;                                 // "G1 G17 ... M3 M8"
    int axisCount = 3;
    std::array<bool, 4> homed{};
    QString connection; // "built-in emulator", "/dev/ttyUSB0, 115200 Bd"
};

class StatusPanel : public QWidget
{
    Q_OBJECT

public:
    explicit StatusPanel(QWidget *parent = nullptr);
    void show(const StatusView &view);
    // The feeds in mm/min or in/min.
    void setUnit(LengthUnit unit);
    // The figures as shown (tests): mm/min, rpm, tool.
    double shownActualFeed() const { return m_view.actualFeedMmPerMin; }
    const StatusView &view() const { return m_view; }
    // The background colour of a state (#rrggbb).
    static QString stateColour(driver::MachineMode mode);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void render();
    LengthUnit m_unit = LengthUnit::Mm;
    QLabel *addRow(int row, QLabel **caption, const char *name);

    StatusView m_view;
    QLabel *m_state;
    QLabel *m_feedCaption, *m_feed, *m_programmedFeed;
    QLabel *m_spindleCaption, *m_spindle;
    QLabel *m_toolCaption, *m_tool;
    QLabel *m_outputsCaption, *m_outputs;
    QLabel *m_modesCaption, *m_modes;
    QLabel *m_homedCaption, *m_homed;
    QLabel *m_connectionCaption, *m_connection;
};

} // namespace frezka::gui
