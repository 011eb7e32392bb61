#include "toolpathrenderers.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QPainter>

#include <QVector4D>

#include <array>
#include <cmath>

namespace frezka::gui {
namespace {

void addBox(std::vector<OverlayLine> &out, const SceneBounds &b, const QColor &c)
{
    if (!b.valid)
        return;
    const QVector3D lo = b.min, hi = b.max;
    const std::array<QVector3D, 8> v{{{lo.x(), lo.y(), lo.z()},
                                      {hi.x(), lo.y(), lo.z()},
                                      {hi.x(), hi.y(), lo.z()},
                                      {lo.x(), hi.y(), lo.z()},
                                      {lo.x(), lo.y(), hi.z()},
                                      {hi.x(), lo.y(), hi.z()},
                                      {hi.x(), hi.y(), hi.z()},
                                      {lo.x(), hi.y(), hi.z()}}};
    static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto &e : kEdges)
        out.push_back({v[e[0]], v[e[1]], c});
}

} // namespace

std::vector<OverlayLine> boxLines(const ToolpathViewModel &model)
{
    std::vector<OverlayLine> out;
    const auto &c = model.colours();
    addBox(out, model.travelBox(), c.travel);
    if (model.scene() && model.scene()->bounds.valid)
        addBox(out, model.scene()->bounds, model.boundsOutsideLimits() ? c.boundsBad : c.boundsOk);
    return out;
}

std::vector<OverlayLine> toolLines(const ToolpathViewModel &model, float mmPerPixel)
{
    std::vector<OverlayLine> out;
    const auto &c = model.colours();
    // Tool: a cone drawn as lines, tip at the tool position, about 30 px tall.
    const QVector3D t = model.toolPosition();
    const float h = 30.f * mmPerPixel, r = 10.f * mmPerPixel;
    const int n = 8;
    for (int i = 0; i < n; ++i) {
        const float a0 = float(i) * 6.2831853f / n, a1 = float(i + 1) * 6.2831853f / n;
        const QVector3D p0 = t + QVector3D(r * std::cos(a0), r * std::sin(a0), h);
        const QVector3D p1 = t + QVector3D(r * std::cos(a1), r * std::sin(a1), h);
        out.push_back({t, p0, c.tool});
        out.push_back({p0, p1, c.tool});
    }
    return out;
}

bool openGlUsable()
{
    if (qEnvironmentVariableIntValue("FREZKA_SOFTWARE_VIEW") != 0)
        return false;
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal"))
        return false;
    QOpenGLContext ctx;
    if (!ctx.create())
        return false;
    QOffscreenSurface surface;
    surface.setFormat(ctx.format());
    surface.create();
    if (!surface.isValid() || !ctx.makeCurrent(&surface))
        return false;
    ctx.doneCurrent();
    return true;
}

// ---- software ----

SoftwareToolpathRenderer::SoftwareToolpathRenderer(ToolpathViewModel *model, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    connect(model, &ToolpathViewModel::changed, this, qOverload<>(&QWidget::update));
}

QImage SoftwareToolpathRenderer::renderImage(const QSize &size) const
{
    QImage img(size, QImage::Format_RGB32);
    QPainter p(&img);
    p.fillRect(img.rect(), m_model->colours().background);
    const QMatrix4x4 mvp = m_model->camera().viewProjection(size);
    const float w2 = float(size.width()) / 2.f, h2 = float(size.height()) / 2.f;
    auto toScreen = [&](const QVector3D &v) {
        const QVector3D n = mvp.map(v);
        return QPointF(w2 + n.x() * w2, h2 - n.y() * h2);
    };
    const auto &colours = m_model->colours();
    for (const auto &l : boxLines(*m_model)) {
        p.setPen(QPen(l.colour, 1.0));
        p.drawLine(toScreen(l.a), toScreen(l.b));
    }
    if (const auto &scene = m_model->scene(); scene && !scene->isEmpty()) {
        const std::size_t cutEnd = m_model->cutEntry() == ToolpathViewModel::kNoneCut
                                       ? 0
                                       : scene->firstSegmentAfter(m_model->cutEntry());
        std::array<QVector<QLineF>, 5> buckets; // 4 classes + cut
        for (std::size_t i = 0; i < scene->segments.size(); ++i) {
            const auto &s = scene->segments[i];
            const std::size_t bucket = i < cutEnd ? 4 : std::size_t(s.cls);
            buckets[bucket].append(QLineF(toScreen(s.from), toScreen(s.to)));
        }
        for (std::size_t b = 0; b < buckets.size(); ++b) {
            const QColor c = b == 4 ? colours.cut : colours.colourOf(SegmentClass(b));
            p.setPen(QPen(c, b == 4 ? 2.0 : 1.0));
            p.drawLines(buckets[b]);
        }
    }
    p.setRenderHint(QPainter::Antialiasing);
    for (const auto &l : toolLines(*m_model, m_model->camera().scaleMmPerPixel(size))) {
        p.setPen(QPen(l.colour, 1.0));
        p.drawLine(toScreen(l.a), toScreen(l.b));
    }
    return img;
}

void SoftwareToolpathRenderer::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.drawImage(0, 0, renderImage(size()));
}

// ---- OpenGL ----

namespace {

const char *kVertexShader = R"(
attribute vec4 a_pos; // xyz + class
uniform mat4 u_mvp;
uniform vec4 u_colours[4];
uniform vec4 u_solid;
uniform int u_mode; // 0 = class colours, 1 = solid colour
varying vec4 v_colour;
void main() {
    gl_Position = u_mvp * vec4(a_pos.xyz, 1.0);
    if (u_mode == 1)
        v_colour = u_solid;
    else
        v_colour = u_colours[int(a_pos.w + 0.5)];
}
)";

const char *kFragmentShader = R"(
varying vec4 v_colour;
void main() { gl_FragColor = v_colour; }
)";

} // namespace

GlToolpathRenderer::GlToolpathRenderer(ToolpathViewModel *model, QWidget *parent)
    : QOpenGLWidget(parent)
    , m_model(model)
{
    connect(model, &ToolpathViewModel::changed, this, qOverload<>(&QWidget::update));
    connect(model, &ToolpathViewModel::sceneChanged, this, [this] { m_sceneDirty = true; });
}

GlToolpathRenderer::~GlToolpathRenderer()
{
    makeCurrent();
    m_vbo.destroy();
    m_overlayVbo.destroy();
    doneCurrent();
}

void GlToolpathRenderer::initializeGL()
{
    initializeOpenGLFunctions();
    const QByteArray renderer = reinterpret_cast<const char *>(glGetString(GL_RENDERER));
    m_softwareRasterizer = renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
                           renderer.contains("Software");
    m_ready = m_program.addShaderFromSourceCode(QOpenGLShader::Vertex, kVertexShader) &&
              m_program.addShaderFromSourceCode(QOpenGLShader::Fragment, kFragmentShader);
    m_program.bindAttributeLocation("a_pos", 0);
    m_ready = m_ready && m_program.link();
    m_vbo.create();
    m_overlayVbo.create();
    m_sceneDirty = true;
}

void GlToolpathRenderer::uploadScene()
{
    m_sceneDirty = false;
    const auto &scene = m_model->scene();
    m_segmentCount = scene ? scene->segments.size() : 0;
    std::vector<float> built;
    const std::vector<float> *data = scene ? &scene->glVertices : &built;
    if (scene && scene->glVertices.size() != m_segmentCount * 8) {
        // Not prepared by the loader (e.g. a scene built by hand): build it here.
        built.reserve(m_segmentCount * 8);
        for (const auto &s : scene->segments) {
            const float c = float(s.cls);
            built.insert(built.end(),
                         {s.from.x(), s.from.y(), s.from.z(), c, s.to.x(), s.to.y(), s.to.z(), c});
        }
        data = &built;
    }
    m_vbo.bind();
    m_vbo.allocate(data->data(), int(data->size() * sizeof(float)));
    m_vbo.release();
}

void GlToolpathRenderer::drawLines(const std::vector<float> &xyz, const QColor &colour)
{
    m_overlayVbo.bind();
    m_overlayVbo.allocate(xyz.data(), int(xyz.size() * sizeof(float)));
    m_program.setUniformValue("u_mode", 1);
    m_program.setUniformValue("u_solid", colour);
    m_program.enableAttributeArray(0);
    m_program.setAttributeBuffer(0, GL_FLOAT, 0, 4);
    glDrawArrays(GL_LINES, 0, GLsizei(xyz.size() / 4));
    m_overlayVbo.release();
}

void GlToolpathRenderer::paintGL()
{
    const QColor bg = m_model->colours().background;
    glClearColor(bg.redF(), bg.greenF(), bg.blueF(), 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_ready)
        return;
    if (m_sceneDirty)
        uploadScene();
    const qreal dpr = devicePixelRatioF();
    const QSize vp(int(width() * dpr), int(height() * dpr));
    glViewport(0, 0, vp.width(), vp.height());
    m_program.bind();
    m_program.setUniformValue("u_mvp", m_model->camera().viewProjection(size()));
    const auto &c = m_model->colours();
    const QVector4D cols[4] = {
        {float(c.rapid.redF()), float(c.rapid.greenF()), float(c.rapid.blueF()), 1.f},
        {float(c.feed.redF()), float(c.feed.greenF()), float(c.feed.blueF()), 1.f},
        {float(c.arc.redF()), float(c.arc.greenF()), float(c.arc.blueF()), 1.f},
        {float(c.probe.redF()), float(c.probe.greenF()), float(c.probe.blueF()), 1.f}};
    m_program.setUniformValueArray("u_colours", cols, 4);
    drawOverlay(boxLines(*m_model));
    if (m_segmentCount > 0) {
        const auto &scene = m_model->scene();
        const std::size_t cutEnd = m_model->cutEntry() == ToolpathViewModel::kNoneCut
                                       ? 0
                                       : scene->firstSegmentAfter(m_model->cutEntry());
        m_vbo.bind();
        m_program.enableAttributeArray(0);
        m_program.setAttributeBuffer(0, GL_FLOAT, 0, 4);
        if (cutEnd > 0) {
            m_program.setUniformValue("u_mode", 1);
            m_program.setUniformValue("u_solid", c.cut);
            glLineWidth(2.f);
            glDrawArrays(GL_LINES, 0, GLsizei(cutEnd * 2));
            glLineWidth(1.f);
        }
        m_program.setUniformValue("u_mode", 0);
        glDrawArrays(GL_LINES, GLint(cutEnd * 2), GLsizei((m_segmentCount - cutEnd) * 2));
        m_vbo.release();
    }
    drawOverlay(toolLines(*m_model, m_model->camera().scaleMmPerPixel(size())));
    m_program.release();
}

void GlToolpathRenderer::drawOverlay(const std::vector<OverlayLine> &lines)
{
    // One colour at a time.
    std::vector<float> buf;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto &l = lines[i];
        buf.insert(buf.end(), {l.a.x(), l.a.y(), l.a.z(), 0.f, l.b.x(), l.b.y(), l.b.z(), 0.f});
        if (i + 1 == lines.size() || lines[i + 1].colour != l.colour) {
            drawLines(buf, l.colour);
            buf.clear();
        }
    }
}

} // namespace frezka::gui
