// MainWindow: Machine › Height map… and Probe work zero… (issue 19) — the dialog
// (gui/heightmapdialog.h) probes on the window's machine link, and Apply / Remove load the program
// again bent to the map or as written (session::ProgramSession::setHeightMap): the preview and the
// plan show the bent path, the listing the program's own lines.

#include "mainwindow.h"

#include "consolewidget.h"
#include "heightmapdialog.h"
#include "probezerodialog.h"
#include "toolpathview.h"

#include "session/heightprobe.h"
#include "session/machinelink.h"
#include "session/programsession.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QSettings>

namespace frezka::gui {

void MainWindow::buildHeightMapAction()
{
    m_heightMapAction = m_machineMenu->addAction(QString(), this, [this] { openHeightMap(); });
    m_heightMapAction->setObjectName(QStringLiteral("heightMap"));
    m_probeZeroAction = m_machineMenu->addAction(QString(), this, [this] { openProbeZero(); });
    m_probeZeroAction->setObjectName(QStringLiteral("probeZero"));
}

void MainWindow::buildHeightMapViewActions()
{
    QSettings settings;
    ToolpathViewModel *model = m_view->model();
    m_heightMapViewAction = m_viewMenu->addAction(QString());
    m_heightMapViewAction->setObjectName(QStringLiteral("viewHeightMap"));
    m_heightMapViewAction->setCheckable(true);
    m_heightMapViewAction->setChecked(
        settings.value(QStringLiteral("view/heightMap"), true).toBool());
    model->setHeightMapVisible(m_heightMapViewAction->isChecked());
    connect(m_heightMapViewAction, &QAction::toggled, this, [model](bool on) {
        model->setHeightMapVisible(on);
        QSettings().setValue(QStringLiteral("view/heightMap"), on);
    });
    m_heightMapScaleMenu = m_viewMenu->addMenu(QString());
    m_heightMapScaleMenu->setObjectName(QStringLiteral("viewHeightMapScale"));
    auto *group = new QActionGroup(this);
    const double saved = settings.value(QStringLiteral("view/heightMapZScale"), 1.0).toDouble();
    for (const double scale : {1.0, 10.0, 100.0}) {
        QAction *a = m_heightMapScaleMenu->addAction(QString());
        a->setObjectName(QStringLiteral("viewHeightMapScale%1").arg(int(scale)));
        a->setCheckable(true);
        a->setChecked(scale == saved);
        group->addAction(a);
        connect(a, &QAction::triggered, this, [model, scale] {
            model->setHeightMapZScale(scale);
            QSettings().setValue(QStringLiteral("view/heightMapZScale"), scale);
        });
        m_heightMapScaleActions.emplace_back(a, scale);
    }
    if (!group->checkedAction()) // a value from elsewhere: true scale
        m_heightMapScaleActions.front().first->setChecked(true);
    for (const auto &[action, scale] : m_heightMapScaleActions)
        if (action->isChecked())
            model->setHeightMapZScale(scale);
}

void MainWindow::retranslateHeightMapView()
{
    m_heightMapViewAction->setText(tr("&Height map"));
    m_heightMapViewAction->setToolTip(
        tr("Show the probed or loaded height map in the toolpath view"));
    m_heightMapScaleMenu->setTitle(tr("Height map &Z scale"));
    for (const auto &[action, scale] : m_heightMapScaleActions)
        action->setText(scale == 1.0 ? tr("&True scale")
                                     : tr("Heights &exaggerated %1×").arg(int(scale)));
}

void MainWindow::showHeightMapInView()
{
    ToolpathViewModel *model = m_view->model();
    if (m_heightMap && m_heightMap->map())
        model->setHeightMap(*m_heightMap->map(), m_heightMap->probedNodes());
    else if (m_program->heightMap())
        model->setHeightMap(*m_program->heightMap());
    else
        model->clearHeightMap();
}

ProbeZeroDialog *MainWindow::openProbeZero()
{
    if (!m_probeZero) {
        m_probeZero = new ProbeZeroDialog(*m_link, profile(), *m_offsets, this);
        m_probeZero->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_probeZero->show();
    m_probeZero->raise();
    return m_probeZero;
}

HeightMapDialog *MainWindow::openHeightMap(session::MachineLink *link)
{
    if (m_heightMap && link)
        delete m_heightMap; // another link: a dialog of its own
    if (!m_heightMap) {
        m_heightMap = new HeightMapDialog(link ? *link : *m_link, profile(), this);
        m_heightMap->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_heightMap, &HeightMapDialog::applyRequested, this,
                [this](const gcode::HeightMap &map, bool zero) { applyHeightMap(map, zero); });
        connect(m_heightMap, &HeightMapDialog::removeRequested, this,
                [this] { applyHeightMap(std::nullopt, false); });
        connect(m_heightMap, &HeightMapDialog::mapChanged, this, [this] { showHeightMapInView(); });
        connect(m_program, &ProgramSession::loaded, m_heightMap, [this] {
            const auto &loaded = m_program->program();
            m_heightMap->setProgramArea(loaded.ok() ? session::cutArea(*loaded.toolpath)
                                                    : std::nullopt);
        });
        if (m_program->program().ok())
            m_heightMap->setProgramArea(session::cutArea(*m_program->program().toolpath));
        if (m_program->heightMap())
            m_heightMap->setMap(*m_program->heightMap());
    }
    m_heightMap->setWorkZero(m_offsets->state().total());
    m_heightMap->setApplied(m_program->heightMap().has_value());
    m_heightMap->show();
    m_heightMap->raise();
    return m_heightMap;
}

bool MainWindow::applyHeightMapFile(const QString &path, QString *error)
{
    const std::optional<gcode::HeightMap> map = gcode::HeightMap::load(path, error);
    if (!map)
        return false;
    applyHeightMap(map, false);
    return true;
}

void MainWindow::applyHeightMap(const std::optional<gcode::HeightMap> &map, bool zeroAtReference)
{
    if (map && zeroAtReference) {
        session::Axes4 at = m_link->state().positionMm;
        at[2] = map->probing().referenceZMm;
        m_offsets->setZero(2, at);
    }
    m_program->setHeightMap(map);
    if (map)
        m_view->model()->setHeightMap(*map);
    else
        m_view->model()->clearHeightMap(); // Remove: the map goes from the view too
    if (m_heightMap) {
        m_heightMap->setWorkZero(m_offsets->state().total());
        m_heightMap->setApplied(map.has_value());
    }
    m_console->appendInfo(
        map ? tr("Height map applied: the program is bent to it (heights %1 to %2 mm).")
                  .arg(map->minZ(), 0, 'f', 3)
                  .arg(map->maxZ(), 0, 'f', 3)
            : tr("Height map removed: the program runs as written."));
    if (!m_program->program().path.isEmpty())
        m_program->reload();
}

} // namespace frezka::gui
