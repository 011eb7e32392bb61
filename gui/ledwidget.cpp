#include "ledwidget.h"

#include <QPainter>

namespace frezka::gui {

LedWidget::LedWidget(const QString &caption, QColor onColour, QWidget *parent)
    : QWidget(parent)
    , m_caption(caption)
    , m_onColour(onColour)
{
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void LedWidget::setOn(bool on)
{
    if (on == m_on)
        return;
    m_on = on;
    update();
}

void LedWidget::setCaption(const QString &caption)
{
    m_caption = caption;
    updateGeometry();
    update();
}

QSize LedWidget::sizeHint() const
{
    const QFontMetrics fm(font());
    return {fm.height() + 4 + fm.horizontalAdvance(m_caption) + 4, fm.height() + 2};
}

void LedWidget::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const int d = fontMetrics().height() - 4;
    const QRectF lamp(2, (height() - d) / 2.0, d, d);
    p.setPen(QPen(QColor(60, 60, 60), 1));
    p.setBrush(m_on ? m_onColour : QColor(70, 70, 70));
    p.drawEllipse(lamp);
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(d + 6, 0, width() - d - 6, height()), Qt::AlignVCenter, m_caption);
}

} // namespace frezka::gui
