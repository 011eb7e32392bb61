#include "toolpathview.h"

#include "toolpathrenderers.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>

namespace frezka::gui {

ToolpathView::ToolpathView(QWidget *parent, Backend backend)
    : QWidget(parent)
    , m_model(new ToolpathViewModel(this))
{
    m_gl = backend == Backend::OpenGl || (backend == Backend::Auto && openGlUsable());
    if (m_gl)
        m_renderer = new GlToolpathRenderer(m_model, this);
    else
        m_renderer = new SoftwareToolpathRenderer(m_model, this);
    m_renderer->setObjectName(QStringLiteral("toolpathRenderer"));
    m_renderer->installEventFilter(this);
    m_renderer->setMouseTracking(false);
    m_renderer->setMinimumSize(200, 150);

    auto *bar = new QHBoxLayout;
    bar->setContentsMargins(0, 0, 0, 0);
    auto button = [&](ViewPreset preset, const char *name) {
        auto *b = new QToolButton(this);
        b->setObjectName(QLatin1String(name));
        connect(b, &QToolButton::clicked, this, [this, preset] { m_model->setPreset(preset); });
        bar->addWidget(b);
        return b;
    };
    m_top = button(ViewPreset::Top, "viewTop");
    m_front = button(ViewPreset::Front, "viewFront");
    m_side = button(ViewPreset::Side, "viewSide");
    m_iso = button(ViewPreset::Iso, "viewIso");
    m_fit = new QToolButton(this);
    m_fit->setObjectName(QStringLiteral("viewFit"));
    connect(m_fit, &QToolButton::clicked, m_model, &ToolpathViewModel::fitAll);
    bar->addWidget(m_fit);
    bar->addStretch();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(bar);
    layout->addWidget(m_renderer, 1);
    retranslate();
}

std::size_t ToolpathView::preferredMaxSegments() const
{
    if (m_gl && !static_cast<GlToolpathRenderer *>(m_renderer)->isSoftwareRasterizer())
        return 600'000;
    return 100'000; // QPainter, or GL rasterized on the CPU: keep every frame well below 100 ms
}

QImage ToolpathView::grabFrame()
{
    if (m_gl)
        return static_cast<GlToolpathRenderer *>(m_renderer)->grabFramebuffer();
    return static_cast<SoftwareToolpathRenderer *>(m_renderer)->renderImage(m_renderer->size());
}

bool ToolpathView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_renderer)
        return QWidget::eventFilter(watched, event);
    auto &cam = m_model->camera();
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        m_lastPos = static_cast<QMouseEvent *>(event)->position().toPoint();
        return true;
    }
    case QEvent::MouseMove: {
        auto *me = static_cast<QMouseEvent *>(event);
        const QPoint pos = me->position().toPoint();
        const QPoint d = pos - m_lastPos;
        m_lastPos = pos;
        const bool panning =
            (me->buttons() & (Qt::RightButton | Qt::MiddleButton)) ||
            ((me->buttons() & Qt::LeftButton) && (me->modifiers() & Qt::ShiftModifier));
        if (panning)
            cam.pan(float(d.x()), float(d.y()), m_renderer->size());
        else if (me->buttons() & Qt::LeftButton)
            cam.orbit(float(d.x()), float(d.y()));
        else
            return false;
        m_model->notifyCameraChanged();
        return true;
    }
    case QEvent::Wheel: {
        auto *we = static_cast<QWheelEvent *>(event);
        cam.zoom(float(we->angleDelta().y()) / 120.f, we->position(), m_renderer->size());
        m_model->notifyCameraChanged();
        return true;
    }
    default:
        return false;
    }
}

void ToolpathView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ToolpathView::retranslate()
{
    m_top->setText(tr("Top"));
    m_front->setText(tr("Front"));
    m_side->setText(tr("Side"));
    m_iso->setText(tr("Iso"));
    m_fit->setText(tr("Fit"));
    m_fit->setToolTip(tr("Show the whole program"));
    m_renderer->setToolTip(
        tr("Left drag: orbit · right/middle drag or Shift+left: pan · wheel: zoom"));
}

} // namespace frezka::gui
