#pragma once
// SpeedPlot: planned speed along the program (path length on x, mm/min on y) and, while
// running, the actual speed measured from the live position. Hovering shows the source line
// at that point so the user sees where the machine slows down and why (corner, arc, short
// segments, axis limit).

#include "session/plannedspeed.h"

#include "displayunits.h"

#include <QWidget>

#include <cstdint>
#include <vector>

namespace frezka::gui {

using session::SpeedSample;

class SpeedPlot : public QWidget
{
    Q_OBJECT

public:
    explicit SpeedPlot(QWidget *parent = nullptr);
    void setPlanned(std::vector<SpeedSample> samples);
    void clearActual();
    void addActual(const SpeedSample &sample);
    void setCursorDistance(double mm);
    // The speeds and the distance in mm or inch (the samples stay in mm).
    void setUnit(LengthUnit unit);
    // The axis caption ("mm/min along the path (120 mm)"; tests).
    QString axisText() const;
    const std::vector<SpeedSample> &planned() const { return m_planned; }
    const std::vector<SpeedSample> &actual() const { return m_actual; }
    QSize sizeHint() const override { return {400, 120}; }
    // Where the top speed label (the plot's highest speed) is drawn, in widget coordinates: the
    // box its text takes, ascent to descent, never cut by the widget's edges or its own box.
    QRect topLabelRect() const;

protected:
    void paintEvent(QPaintEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;

private:
    QRectF plotRect() const;
    std::vector<SpeedSample> m_planned, m_actual;
    double m_maxDistance = 1, m_maxSpeed = 1, m_cursor = -1;
    LengthUnit m_unit = LengthUnit::Mm;
};

} // namespace frezka::gui
