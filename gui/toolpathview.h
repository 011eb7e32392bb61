#pragma once
// ToolpathView: the 3D program view with orbit (left drag), pan (right or middle drag,
// or Shift+left), zoom (wheel, at the cursor) and top/front/side/iso presets. It picks the
// OpenGL renderer when a context can be had and the QPainter renderer otherwise.

#include "toolpathviewmodel.h"

#include <QImage>
#include <QPoint>
#include <QWidget>

class QToolButton;

namespace frezka::gui {

class ToolpathView : public QWidget
{
    Q_OBJECT

public:
    enum class Backend { Auto, Software, OpenGl };
    explicit ToolpathView(QWidget *parent = nullptr, Backend backend = Backend::Auto);

    ToolpathViewModel *model() const { return m_model; }
    bool usesOpenGl() const { return m_gl; }
    // The most segments the scene for this view should hold (software draws fewer).
    std::size_t preferredMaxSegments() const;
    // The current frame as an image (screenshots, tests).
    QImage grabFrame();
    QWidget *renderer() const { return m_renderer; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    ToolpathViewModel *m_model;
    QWidget *m_renderer = nullptr;
    bool m_gl = false;
    QPoint m_lastPos;
    QToolButton *m_top, *m_front, *m_side, *m_iso, *m_fit;
};

} // namespace frezka::gui
