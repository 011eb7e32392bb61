#include "probesetuppicture.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace frezka::gui {

namespace {

const QColor kWork(176, 141, 87);   // the work piece
const QColor kPlate(120, 120, 130); // the touch plate
const QColor kTool(40, 90, 170);    // the tool
const QColor kArrow(200, 30, 30);   // the probe's move

void arrow(QPainter &p, QPointF from, QPointF to, bool dashed = false)
{
    QPen pen(kArrow, 2.5, dashed ? Qt::DashLine : Qt::SolidLine);
    p.setPen(pen);
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1 || dashed)
        return;
    const QPointF u = d / len, n(-u.y(), u.x());
    QPainterPath head;
    head.moveTo(to);
    head.lineTo(to - u * 10 + n * 5);
    head.lineTo(to - u * 10 - n * 5);
    head.closeSubpath();
    p.fillPath(head, kArrow);
}

} // namespace

ProbeSetupPicture::ProbeSetupPicture(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("probeSetupPicture"));
    setMinimumSize(220, 170);
}

void ProbeSetupPicture::setSetup(Kind kind, int xDirection, int yDirection)
{
    m_kind = kind;
    m_xDirection = xDirection < 0 ? -1 : 1;
    m_yDirection = yDirection < 0 ? -1 : 1;
    update();
}

void ProbeSetupPicture::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const QRectF area = QRectF(rect()).adjusted(10, 10, -10, -10);
    if (m_kind == Kind::ZPlate)
        paintPlate(p, area);
    else
        paintTop(p, area);
}

// From the side: the work, the plate on it, the tool above with the probe's arrow down.
void ProbeSetupPicture::paintPlate(QPainter &p, const QRectF &a) const
{
    const QRectF work(a.left(), a.bottom() - a.height() * 0.3, a.width(), a.height() * 0.3);
    p.fillRect(work, kWork);
    const QRectF plate(a.center().x() - a.width() * 0.18, work.top() - a.height() * 0.07,
                       a.width() * 0.36, a.height() * 0.07);
    p.fillRect(plate, kPlate);
    const QRectF tool(a.center().x() - a.width() * 0.05, a.top(), a.width() * 0.1,
                      a.height() * 0.35);
    p.fillRect(tool, kTool);
    arrow(p, QPointF(tool.right() + 12, tool.top() + 10),
          QPointF(tool.right() + 12, plate.top() - 2));
    p.setPen(palette().text().color());
    p.drawText(work, Qt::AlignCenter, tr("work"));
    p.drawText(plate.adjusted(plate.width() + 4, -4, plate.width() + 90, 4),
               Qt::AlignVCenter | Qt::AlignLeft, tr("plate"));
}

// From above: the work block (or the pocket's walls), the tool's circle, the probe's arrows.
void ProbeSetupPicture::paintTop(QPainter &p, const QRectF &a) const
{
    const double r = std::min(a.width(), a.height()) * 0.09; // the tool's radius
    const QPointF c = a.center();
    const double sx = m_kind == Kind::YEdge ? 1 : m_xDirection;
    const double sy = m_kind == Kind::XEdge ? 1 : -m_yDirection; // screen y grows downward
    // The corner (or the edge's point) the tool probes toward, left of / below it when +.
    const QPointF corner(c.x() + sx * a.width() * 0.12, c.y() + sy * a.height() * 0.12);
    QPointF tool(corner.x() - sx * a.width() * 0.25, corner.y() - sy * a.height() * 0.25);
    auto region = [&](double x0, double y0, double x1, double y1) {
        return QRectF(QPointF(std::min(x0, x1), std::min(y0, y1)),
                      QPointF(std::max(x0, x1), std::max(y0, y1)));
    };
    const double farX = sx > 0 ? a.right() : a.left(), farY = sy > 0 ? a.bottom() : a.top();
    const double nearX = sx > 0 ? a.left() : a.right(), nearY = sy > 0 ? a.top() : a.bottom();
    p.setPen(Qt::NoPen);
    switch (m_kind) {
    case Kind::XEdge:
        p.fillRect(region(corner.x(), a.top(), farX, a.bottom()), kWork);
        tool.setY(c.y());
        break;
    case Kind::YEdge:
        p.fillRect(region(a.left(), corner.y(), a.right(), farY), kWork);
        tool.setX(c.x());
        break;
    case Kind::OutsideCorner:
        p.fillRect(region(corner.x(), corner.y(), farX, farY), kWork);
        break;
    case Kind::InsideCorner: // material beyond both walls around the pocket
        p.fillRect(region(corner.x(), nearY, farX, farY), kWork);
        p.fillRect(region(nearX, corner.y(), farX, farY), kWork);
        tool = QPointF(corner.x() - sx * a.width() * 0.18, corner.y() - sy * a.height() * 0.18);
        break;
    case Kind::ZPlate:
        break;
    }
    p.setBrush(kTool);
    p.drawEllipse(tool, r, r);
    const bool probesX = m_kind != Kind::YEdge, probesY = m_kind != Kind::XEdge;
    if (m_kind == Kind::OutsideCorner) { // the reach beside each face, dashed
        const QPointF besideX(tool.x(), corner.y() + sy * a.height() * 0.12);
        const QPointF besideY(corner.x() + sx * a.width() * 0.12, tool.y());
        arrow(p, tool, besideX, true);
        arrow(p, besideX, QPointF(corner.x() - sx * r, besideX.y()));
        arrow(p, tool, besideY, true);
        arrow(p, besideY, QPointF(besideY.x(), corner.y() - sy * r));
    } else {
        if (probesX)
            arrow(p, tool, QPointF(corner.x() - sx * r, tool.y()));
        if (probesY)
            arrow(p, tool, QPointF(tool.x(), corner.y() - sy * r));
    }
    p.setPen(palette().text().color());
    p.drawText(region(corner.x(), corner.y(), farX, farY).adjusted(4, 4, -4, -4), Qt::AlignCenter,
               m_kind == Kind::InsideCorner ? QString() : tr("work"));
    p.drawText(QRectF(tool.x() - 40, tool.y() + r + 2, 80, 16), Qt::AlignCenter, tr("tool"));
}

} // namespace frezka::gui
