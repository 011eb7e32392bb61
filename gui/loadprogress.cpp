#include "loadprogress.h"

#include <QEvent>
#include <QPainter>
#include <QToolButton>

#include <cmath>

namespace frezka::gui {

namespace {
constexpr int kBarWidth = 240;
constexpr int kGap = 4;
} // namespace

LoadProgress::LoadProgress(QWidget *parent)
    : QWidget(parent)
    , m_cancel(new QToolButton(this))
{
    m_cancel->setObjectName(QStringLiteral("loadCancel"));
    m_cancel->setAutoRaise(true);
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop loading this program (the program loaded before stays)"));
    connect(m_cancel, &QToolButton::clicked, this, &LoadProgress::cancelRequested);
    setFixedSize(sizeHint());
}

QSize LoadProgress::sizeHint() const
{
    const int height = std::max(fontMetrics().height() + 4, m_cancel->sizeHint().height());
    return {kBarWidth + kGap + m_cancel->sizeHint().width(), height};
}

QRect LoadProgress::barRect() const
{
    const int barHeight = fontMetrics().height() + 4;
    return {0, (height() - barHeight) / 2, width() - kGap - m_cancel->width(), barHeight};
}

void LoadProgress::setProgress(double fraction, const QString &stage)
{
    const double f = std::clamp(fraction, 0.0, 1.0);
    if (std::abs(f - m_fraction) < 0.002 && stage == m_stage)
        return;
    m_fraction = f;
    m_stage = stage;
    update(barRect());
}

void LoadProgress::resizeEvent(QResizeEvent *)
{
    const QSize button = m_cancel->sizeHint();
    m_cancel->setGeometry(width() - button.width(), (height() - button.height()) / 2,
                          button.width(), button.height());
}

void LoadProgress::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_cancel->setText(tr("Cancel"));
        m_cancel->setToolTip(tr("Stop loading this program (the program loaded before stays)"));
        setFixedSize(sizeHint());
    }
    QWidget::changeEvent(event);
}

void LoadProgress::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    const QRect r = barRect().adjusted(0, 0, -1, -1);
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
