#include "loadprogress.h"

#include <QPainter>

#include <cmath>

namespace frezka::gui {

LoadProgress::LoadProgress(QWidget *parent)
    : QWidget(parent)
{
    setFixedSize(sizeHint());
}

QSize LoadProgress::sizeHint() const
{
    return {240, fontMetrics().height() + 4};
}

void LoadProgress::setProgress(double fraction, const QString &stage)
{
    const double f = std::clamp(fraction, 0.0, 1.0);
    if (std::abs(f - m_fraction) < 0.002 && stage == m_stage)
        return;
    m_fraction = f;
    m_stage = stage;
    update();
}

void LoadProgress::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    const QRect r = rect().adjusted(0, 0, -1, -1);
    p.setPen(palette().color(QPalette::Mid));
    p.setBrush(palette().color(QPalette::Base));
    p.drawRect(r);
    p.fillRect(QRect(r.left() + 1, r.top() + 1, int((r.width() - 1) * m_fraction), r.height() - 1),
               palette().color(QPalette::Highlight));
    p.setPen(palette().color(QPalette::Text));
    p.drawText(r, Qt::AlignCenter,
               QStringLiteral("%1 %2 %").arg(m_stage).arg(int(std::lround(m_fraction * 100))));
}

} // namespace frezka::gui
