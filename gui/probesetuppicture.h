#pragma once
// The picture of a probing setup in Machine › Probe work zero (issue 19 item 2): what the
// operator sets up before pressing Probe, drawn for the kind and the directions chosen. A touch
// plate is seen from the side (the work, the plate on it, the tool above, the probe's arrow
// down); an edge and a corner from above (the work hatched, the tool's circle beside it, the
// probe's arrows; for an outside corner the reach beside each face dashed; for an inside corner
// the pocket's walls around the tool).

#include <QWidget>

namespace frezka::gui {

class ProbeSetupPicture : public QWidget
{
    Q_OBJECT

public:
    enum class Kind { ZPlate, XEdge, YEdge, OutsideCorner, InsideCorner };

    explicit ProbeSetupPicture(QWidget *parent = nullptr);

    void setSetup(Kind kind, int xDirection, int yDirection);
    Kind kind() const { return m_kind; }
    QSize sizeHint() const override { return {260, 200}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    void paintPlate(class QPainter &p, const QRectF &area) const;
    void paintTop(class QPainter &p, const QRectF &area) const;

    Kind m_kind = Kind::ZPlate;
    int m_xDirection = 1, m_yDirection = 1;
};

} // namespace frezka::gui
