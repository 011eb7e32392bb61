#pragma once
// The two renderers behind ToolpathView: an OpenGL one (QOpenGLWidget, where a context exists)
// and a QPainter one (the offscreen platform and machines without GL). Both draw the same
// ToolpathViewModel through the same camera; input is handled by ToolpathView.

#include "toolpathviewmodel.h"

#include <QImage>
#include <QOpenGLBuffer>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLWidget>
#include <QWidget>

namespace frezka::gui {

struct OverlayLine
{
    QVector3D a;
    QVector3D b;
    QColor colour;
};

// Travel box and program bounds (drawn under the path) as coloured 3D lines.
std::vector<OverlayLine> boxLines(const ToolpathViewModel &model);
// The tool marker (drawn over the path), about 30 px tall.
std::vector<OverlayLine> toolLines(const ToolpathViewModel &model, float mmPerPixel);
// The shown height map's probed nodes as small 3D crosses (about 8 px); none when hidden.
std::vector<OverlayLine> heightMapNodeLines(const ToolpathViewModel &model, float mmPerPixel);

class SoftwareToolpathRenderer : public QWidget
{
    Q_OBJECT

public:
    explicit SoftwareToolpathRenderer(ToolpathViewModel *model, QWidget *parent = nullptr);
    // Rendered frame as an image (tests and screenshots).
    QImage renderImage(const QSize &size) const;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    ToolpathViewModel *m_model;
};

class GlToolpathRenderer : public QOpenGLWidget, protected QOpenGLFunctions
{
    Q_OBJECT

public:
    explicit GlToolpathRenderer(ToolpathViewModel *model, QWidget *parent = nullptr);
    ~GlToolpathRenderer() override;
    // True once initializeGL ran and the shaders linked.
    bool isReady() const { return m_ready; }
    // True when the GL implementation rasterizes on the CPU (llvmpipe, softpipe): the view
    // then keeps its scene as small as the QPainter view does.
    bool isSoftwareRasterizer() const { return m_softwareRasterizer; }

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    void uploadScene();
    void uploadHeightMap();
    void drawHeightMap(const QMatrix4x4 &mvp);
    void drawOverlay(const std::vector<OverlayLine> &lines);
    void drawLines(const std::vector<float> &xyz, const QColor &colour);

    ToolpathViewModel *m_model;
    QOpenGLShaderProgram m_program;
    QOpenGLShaderProgram m_meshProgram; // per-vertex colours: the height map
    QOpenGLBuffer m_vbo{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer m_overlayVbo{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer m_meshVbo{QOpenGLBuffer::VertexBuffer};
    int m_meshTriangleVertices = 0; // then the grid lines' vertices
    int m_meshLineVertices = 0;
    bool m_meshDirty = true;
    std::vector<std::pair<std::size_t, SegmentClass>> m_runs; // first segment, class
    std::size_t m_segmentCount = 0;
    bool m_sceneDirty = true;
    bool m_ready = false;
    bool m_softwareRasterizer = false;
};

// True when a QOpenGLWidget can be shown here (not offscreen/minimal, and a context can be
// created). FREZKA_SOFTWARE_VIEW=1 forces false.
bool openGlUsable();

} // namespace frezka::gui
