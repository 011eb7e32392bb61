// MainWindow: Machine › Height map… and Probe work zero… (issue 19) — the dialog
// (gui/heightmapdialog.h) probes on the window's machine link, and Apply / Remove load the program
// again bent to the map or as written (session::ProgramSession::setHeightMap): the preview and the
// plan show the bent path, the listing the program's own lines.

#include "mainwindow.h"

#include "consolewidget.h"
#include "heightmapdialog.h"
#include "probezerodialog.h"

#include "session/heightprobe.h"
#include "session/machinelink.h"
#include "session/programsession.h"

#include <QAction>
#include <QMenu>

namespace frezka::gui {

void MainWindow::buildHeightMapAction()
{
    m_heightMapAction = m_machineMenu->addAction(QString(), this, [this] { openHeightMap(); });
    m_heightMapAction->setObjectName(QStringLiteral("heightMap"));
    m_probeZeroAction = m_machineMenu->addAction(QString(), this, [this] { openProbeZero(); });
    m_probeZeroAction->setObjectName(QStringLiteral("probeZero"));
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

void MainWindow::applyHeightMap(const std::optional<gcode::HeightMap> &map, bool zeroAtReference)
{
    if (map && zeroAtReference) {
        session::Axes4 at = m_link->state().positionMm;
        at[2] = map->probing().referenceZMm;
        m_offsets->setZero(2, at);
    }
    m_program->setHeightMap(map);
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
