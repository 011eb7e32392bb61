#include "speedplot.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>

namespace frezka::gui {

SpeedPlot::SpeedPlot(QWidget *parent)
    : QWidget(parent)
{
    setMouseTracking(true);
    setMinimumHeight(80);
}

void SpeedPlot::setPlanned(std::vector<SpeedSample> samples)
{
    m_planned = decimateSpeed(samples, 4000);
    m_actual.clear();
    m_maxDistance = 1;
    m_maxSpeed = 1;
    for (const auto &s : m_planned) {
        m_maxDistance = std::max(m_maxDistance, s.distanceMm);
        m_maxSpeed = std::max(m_maxSpeed, s.speedMmPerMin);
    }
    update();
}

void SpeedPlot::clearActual()
{
    m_actual.clear();
    update();
}

void SpeedPlot::addActual(const SpeedSample &sample)
{
    m_actual.push_back(sample);
    if (m_actual.size() > 20000)
        m_actual = decimateSpeed(m_actual, 10000);
    m_maxSpeed = std::max(m_maxSpeed, sample.speedMmPerMin);
    m_maxDistance = std::max(m_maxDistance, sample.distanceMm);
    update();
}

void SpeedPlot::setUnit(LengthUnit unit)
{
    m_unit = unit;
    update();
}

QString SpeedPlot::axisText() const
{
    return tr("%1 along the path (%2 %3)")
        .arg(feedSuffix(m_unit))
        .arg(fromMm(m_maxDistance, m_unit), 0, 'f', m_unit == LengthUnit::Inch ? 1 : 0)
        .arg(lengthSuffix(m_unit));
}

void SpeedPlot::setCursorDistance(double mm)
{
    m_cursor = mm;
    update();
}

// The speed labels sit left of the plot, the top one centred on its top edge: room for the
// widest label and half a line above the plot, so that no label is cut.
QRectF SpeedPlot::plotRect() const
{
    const QFontMetrics fm = fontMetrics();
    const int left = std::max(fm.horizontalAdvance(QStringLiteral("00000")),
                              fm.horizontalAdvance(formatFeed(m_maxSpeed, m_unit))) +
                     6;
    const int top = fm.height() / 2 + 2;
    return QRectF(left, top, width() - left - 4, height() - top - fm.height() - 4);
}

QRect SpeedPlot::topLabelRect() const
{
    const QRectF r = plotRect();
    const QFontMetrics fm = fontMetrics();
    const QRect box =
        QRectF(0, r.top() - fm.height() / 2.0, r.left() - 4, fm.height()).toAlignedRect();
    return fm.boundingRect(box, Qt::AlignRight | Qt::AlignVCenter, formatFeed(m_maxSpeed, m_unit));
}

void SpeedPlot::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 32, 36));
    const QRectF r = plotRect();
    p.setPen(QColor(90, 90, 90));
    p.drawRect(r);
    p.setPen(QColor(200, 200, 200));
    p.drawText(topLabelRect(), Qt::AlignRight | Qt::AlignVCenter, formatFeed(m_maxSpeed, m_unit));
    p.drawText(QRectF(0, r.bottom() - 16, r.left() - 4, 16), Qt::AlignRight, QStringLiteral("0"));
    p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), 20), Qt::AlignLeft, axisText());
    auto map = [&](const SpeedSample &s) {
        return QPointF(r.left() + s.distanceMm / m_maxDistance * r.width(),
                       r.bottom() - s.speedMmPerMin / m_maxSpeed * r.height());
    };
    p.setRenderHint(QPainter::Antialiasing);
    auto draw = [&](const std::vector<SpeedSample> &v, const QColor &c) {
        if (v.empty())
            return;
        QPainterPath path(map(v.front()));
        for (std::size_t i = 1; i < v.size(); ++i)
            path.lineTo(map(v[i]));
        p.setPen(QPen(c, 1.2));
        p.drawPath(path);
    };
    draw(m_planned, QColor(70, 160, 255));
    draw(m_actual, QColor(255, 170, 40));
    if (m_cursor >= 0) {
        const double x = r.left() + m_cursor / m_maxDistance * r.width();
        p.setPen(QPen(QColor(255, 60, 60), 1));
        p.drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
    }
}

void SpeedPlot::mouseMoveEvent(QMouseEvent *event)
{
    const QRectF r = plotRect();
    if (m_planned.empty() || !r.contains(event->position()))
        return;
    const double d = (event->position().x() - r.left()) / r.width() * m_maxDistance;
    auto it = std::lower_bound(m_planned.begin(), m_planned.end(), d,
                               [](const SpeedSample &s, double v) { return s.distanceMm < v; });
    if (it == m_planned.end())
        --it;
    QToolTip::showText(
        event->globalPosition().toPoint(),
        tr("%1 %2 at %3 %4, line %5")
            .arg(formatFeed(it->speedMmPerMin, m_unit), feedSuffix(m_unit))
            .arg(fromMm(it->distanceMm, m_unit), 0, 'f', m_unit == LengthUnit::Inch ? 2 : 1)
            .arg(lengthSuffix(m_unit))
            .arg(it->line),
        this);
}

} // namespace frezka::gui
