#include "toolpathrenderers.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QPainter>

#include <QVector4D>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

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

std::vector<OverlayLine> heightMapNodeLines(const ToolpathViewModel &model, float mmPerPixel)
{
    std::vector<OverlayLine> out;
    const HeightMapMesh *mesh = model.shownHeightMap();
    if (!mesh)
        return out;
    const float r = 4.f * mmPerPixel;
    const QColor c = model.colours().heightMapNode;
    for (std::size_t k = 0; k < mesh->nodes.size(); ++k) {
        if (!mesh->probed[k])
            continue;
        const QVector3D p = mesh->nodes[k];
        out.push_back({p - QVector3D(r, 0, 0), p + QVector3D(r, 0, 0), c});
        out.push_back({p - QVector3D(0, r, 0), p + QVector3D(0, r, 0), c});
        out.push_back({p - QVector3D(0, 0, r), p + QVector3D(0, 0, r), c});
    }
    return out;
}

namespace {

QColor withAlpha(QColor c, int alpha)
{
    c.setAlpha(alpha);
    return c;
}

// The mean of the colours (a face's or a line's, from its corners').
QColor mixed(std::initializer_list<QColor> colours)
{
    float r = 0, g = 0, b = 0;
    for (const QColor &c : colours) {
        r += c.redF();
        g += c.greenF();
        b += c.blueF();
    }
    const float n = float(colours.size());
    return QColor::fromRgbF(r / n, g / n, b / n);
}

// The mesh's faces (semi-transparent, each triangle its corners' mean colour) and grid lines.
template<typename ToScreen>
void paintHeightMap(QPainter &p, const HeightMapMesh &mesh, const ViewColours &colours,
                    const ToScreen &toScreen)
{
    p.setPen(Qt::NoPen);
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const auto a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
        p.setBrush(withAlpha(mixed({mesh.colours[a], mesh.colours[b], mesh.colours[c]}),
                             colours.heightMapFillAlpha));
        const QPointF corners[3] = {toScreen(mesh.nodes[a]), toScreen(mesh.nodes[b]),
                                    toScreen(mesh.nodes[c])};
        p.drawPolygon(corners, 3);
    }
    p.setBrush(Qt::NoBrush);
    for (const auto &[a, b] : mesh.edges) {
        p.setPen(QPen(
            withAlpha(mixed({mesh.colours[a], mesh.colours[b]}), colours.heightMapLineAlpha), 1.0));
        p.drawLine(toScreen(mesh.nodes[a]), toScreen(mesh.nodes[b]));
    }
}

} // namespace

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
    const float mmPerPixel = m_model->camera().scaleMmPerPixel(size);
    if (const HeightMapMesh *mesh = m_model->shownHeightMap()) { // under the path
        paintHeightMap(p, *mesh, colours, toScreen);
        for (const auto &l : heightMapNodeLines(*m_model, mmPerPixel)) {
            p.setPen(QPen(l.colour, 1.0));
            p.drawLine(toScreen(l.a), toScreen(l.b));
        }
    }
    if (const auto &scene = m_model->scene(); scene && !scene->isEmpty()) {
        const std::size_t cutEnd = m_model->cutEntry() == ToolpathViewModel::kNoneCut
                                       ? 0
                                       : scene->firstSegmentAfter(m_model->cutEntry());
        const std::size_t provisional = std::max(cutEnd, m_model->firstProvisionalSegment());
        std::array<QVector<QLineF>, 6> buckets; // 4 classes + cut + provisional
        for (std::size_t i = 0; i < scene->segments.size(); ++i) {
            const auto &s = scene->segments[i];
            const std::size_t bucket = i < cutEnd ? 4 : i >= provisional ? 5 : std::size_t(s.cls);
            buckets[bucket].append(QLineF(toScreen(s.from), toScreen(s.to)));
        }
        for (std::size_t b = 0; b < buckets.size(); ++b) {
            const QColor c = b == 4   ? colours.cut
                             : b == 5 ? colours.provisional
                                      : colours.colourOf(SegmentClass(b));
            p.setPen(QPen(c, b == 4 ? 2.0 : 1.0, b == 5 ? Qt::DashLine : Qt::SolidLine));
            p.drawLines(buckets[b]);
        }
    }
    p.setRenderHint(QPainter::Antialiasing);
    for (const auto &l : toolLines(*m_model, mmPerPixel)) {
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

// The height map: each vertex its own colour (alpha included).
const char *kMeshVertexShader = R"(
attribute vec3 a_pos;
attribute vec4 a_colour;
uniform mat4 u_mvp;
varying vec4 v_colour;
void main() {
    gl_Position = u_mvp * vec4(a_pos, 1.0);
    v_colour = a_colour;
}
)";

void appendVertex(std::vector<float> &out, const QVector3D &p, const QColor &c, int alpha)
{
    out.insert(out.end(), {p.x(), p.y(), p.z(), float(c.redF()), float(c.greenF()),
                           float(c.blueF()), float(alpha) / 255.f});
}

} // namespace

GlToolpathRenderer::GlToolpathRenderer(ToolpathViewModel *model, QWidget *parent)
    : QOpenGLWidget(parent)
    , m_model(model)
{
    connect(model, &ToolpathViewModel::changed, this, qOverload<>(&QWidget::update));
    connect(model, &ToolpathViewModel::sceneChanged, this, [this] { m_sceneDirty = true; });
    connect(model, &ToolpathViewModel::heightMapChanged, this, [this] { m_meshDirty = true; });
}

GlToolpathRenderer::~GlToolpathRenderer()
{
    makeCurrent();
    m_vbo.destroy();
    m_overlayVbo.destroy();
    m_meshVbo.destroy();
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
    m_ready = m_ready &&
              m_meshProgram.addShaderFromSourceCode(QOpenGLShader::Vertex, kMeshVertexShader) &&
              m_meshProgram.addShaderFromSourceCode(QOpenGLShader::Fragment, kFragmentShader);
    m_meshProgram.bindAttributeLocation("a_pos", 0);
    m_meshProgram.bindAttributeLocation("a_colour", 1);
    m_ready = m_ready && m_meshProgram.link();
    m_vbo.create();
    m_overlayVbo.create();
    m_meshVbo.create();
    m_sceneDirty = true;
    m_meshDirty = true;
}

void GlToolpathRenderer::uploadHeightMap()
{
    m_meshDirty = false;
    m_meshTriangleVertices = m_meshLineVertices = 0;
    const HeightMapMesh *mesh = m_model->shownHeightMap();
    if (!mesh)
        return;
    const ViewColours &c = m_model->colours();
    std::vector<float> data; // x, y, z, r, g, b, a: the triangles, then the grid lines
    data.reserve((mesh->triangles.size() + mesh->edges.size() * 2) * 7);
    for (std::size_t t = 0; t + 2 < mesh->triangles.size(); t += 3) {
        const auto a = mesh->triangles[t], b = mesh->triangles[t + 1], d = mesh->triangles[t + 2];
        const QColor mean = mixed({mesh->colours[a], mesh->colours[b], mesh->colours[d]});
        for (const auto k : {a, b, d})
            appendVertex(data, mesh->nodes[k], mean, c.heightMapFillAlpha);
    }
    m_meshTriangleVertices = int(data.size() / 7);
    for (const auto &[a, b] : mesh->edges) {
        const QColor mean = mixed({mesh->colours[a], mesh->colours[b]});
        appendVertex(data, mesh->nodes[a], mean, c.heightMapLineAlpha);
        appendVertex(data, mesh->nodes[b], mean, c.heightMapLineAlpha);
    }
    m_meshLineVertices = int(data.size() / 7) - m_meshTriangleVertices;
    m_meshVbo.bind();
    m_meshVbo.allocate(data.data(), int(data.size() * sizeof(float)));
    m_meshVbo.release();
}

void GlToolpathRenderer::drawHeightMap(const QMatrix4x4 &mvp)
{
    if (m_meshDirty)
        uploadHeightMap();
    if (m_meshTriangleVertices + m_meshLineVertices == 0)
        return;
    m_meshProgram.bind();
    m_meshProgram.setUniformValue("u_mvp", mvp);
    m_meshVbo.bind();
    m_meshProgram.enableAttributeArray(0);
    m_meshProgram.enableAttributeArray(1);
    m_meshProgram.setAttributeBuffer(0, GL_FLOAT, 0, 3, 7 * sizeof(float));
    m_meshProgram.setAttributeBuffer(1, GL_FLOAT, 3 * sizeof(float), 4, 7 * sizeof(float));
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArrays(GL_TRIANGLES, 0, m_meshTriangleVertices);
    glDrawArrays(GL_LINES, m_meshTriangleVertices, m_meshLineVertices);
    glDisable(GL_BLEND);
    m_meshProgram.disableAttributeArray(1);
    m_meshVbo.release();
    m_meshProgram.release();
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
    const QMatrix4x4 mvp = m_model->camera().viewProjection(size());
    drawHeightMap(mvp); // under everything but the box: the path shows through it
    m_program.bind();
    m_program.setUniformValue("u_mvp", mvp);
    const auto &c = m_model->colours();
    const QVector4D cols[4] = {
        {float(c.rapid.redF()), float(c.rapid.greenF()), float(c.rapid.blueF()), 1.f},
        {float(c.feed.redF()), float(c.feed.greenF()), float(c.feed.blueF()), 1.f},
        {float(c.arc.redF()), float(c.arc.greenF()), float(c.arc.blueF()), 1.f},
        {float(c.probe.redF()), float(c.probe.greenF()), float(c.probe.blueF()), 1.f}};
    m_program.setUniformValueArray("u_colours", cols, 4);
    drawOverlay(boxLines(*m_model));
    const float mmPerPixel = m_model->camera().scaleMmPerPixel(size());
    drawOverlay(heightMapNodeLines(*m_model, mmPerPixel));
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
        // The path after a probe not run yet: dim, in one colour.
        const std::size_t provisional =
            std::min(m_segmentCount, std::max(cutEnd, m_model->firstProvisionalSegment()));
        m_program.setUniformValue("u_mode", 0);
        glDrawArrays(GL_LINES, GLint(cutEnd * 2), GLsizei((provisional - cutEnd) * 2));
        if (provisional < m_segmentCount) {
            m_program.setUniformValue("u_mode", 1);
            m_program.setUniformValue("u_solid", c.provisional);
            glDrawArrays(GL_LINES, GLint(provisional * 2),
                         GLsizei((m_segmentCount - provisional) * 2));
        }
        m_vbo.release();
    }
    drawOverlay(toolLines(*m_model, mmPerPixel));
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
