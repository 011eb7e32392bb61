#pragma once
// DroWidget: digital read-out — work and machine coordinates for each axis of the unit variant,
// with per-axis and all-axes "set work zero" and the active work offset (G54-G59.3).

#include "displayunits.h"

#include <QWidget>

#include <array>

class QComboBox;
class QLabel;
class QPushButton;

namespace frezka::gui {

class DroWidget : public QWidget
{
    Q_OBJECT

public:
    explicit DroWidget(QWidget *parent = nullptr);
    void setAxisCount(int count); // 3 (XYZ) or 4 (XYZA)
    int axisCount() const { return m_axisCount; }
    void setPositions(const std::array<double, 4> &machineMm, const std::array<double, 4> &workMm);
    // mm or inch for X/Y/Z (A stays in degrees); the positions shown again in it.
    void setUnit(LengthUnit unit);
    void setActiveOffset(int index); // 0 = G54 .. 8 = G59.3
    void setHomed(const std::array<bool, 4> &homed);
    // The figures are the driver's model of the unit between position reads (issue 16 item 3),
    // not its counters: said under the figures, which turn grey.
    void setModelled(bool modelled);
    bool modelledShown() const { return m_modelled; }
    // Whether the axis is shown as homed (its name in green; tests).
    bool homedShown(int axis) const;
    // Shown text of an axis (tests).
    QString workText(int axis) const;
    QString machineText(int axis) const;

signals:
    void zeroAxisRequested(int axis);
    void zeroAllRequested();
    void offsetSelected(int index);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    int m_axisCount = 4;
    LengthUnit m_unit = LengthUnit::Mm;
    std::array<double, 4> m_machineMm{}, m_workMm{}; // last shown
    std::array<QLabel *, 4> m_name{}, m_work{}, m_machine{};
    std::array<QPushButton *, 4> m_zero{};
    QPushButton *m_zeroAll;
    QComboBox *m_offset;
    QLabel *m_workHeader, *m_machineHeader, *m_offsetLabel, *m_source;
    bool m_modelled = false;
};

} // namespace frezka::gui
