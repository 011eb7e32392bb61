// MainWindow: programs that probe for themselves (issue 19 item 4, docs/probing.md). The run
// workflow runs them part by part (session::ProbeFollow); the window shows the path after the
// next probe not run yet as provisional (dim, dashed), and after each probe the program as
// interpreted again with its result: preview, progress and ETA of the part that runs now.
#include "mainwindow.h"

#include "consolewidget.h"
#include "runpanel.h"
#include "speedplot.h"
#include "toolpathview.h"

#include <QStatusBar>

namespace frezka::gui {

void MainWindow::connectProbeFollow()
{
    connect(m_workflow, &session::RunWorkflow::probeFollowed, this,
            [this](std::uint32_t line, const session::ProbeFollow::Next &next) {
                m_program->showFollowed(next);
                statusBar()->showMessage(
                    tr("Line %1: the probe's result was followed; the rest of the program is "
                       "shown and runs as interpreted with it.")
                        .arg(line),
                    15000);
            });
    connect(m_program, &ProgramSession::probeFollowShown, this, &MainWindow::onProbeFollowShown);
}

// The loaded program goes to the run workflow with its ProbeFollow when it probes for itself
// (made again only when the program was loaded again), without for any other program.
void MainWindow::offerProbeFollow()
{
    const LoadedProgram &p = m_program->program();
    if (!p.runnable() || !p.followRequest) {
        m_workflow->setProbeFollow(nullptr);
        m_follow.reset();
        m_followRequest.reset();
    } else if (p.followRequest != m_followRequest) {
        m_workflow->setProbeFollow(nullptr);
        m_follow = std::make_unique<session::ProbeFollow>(*p.followRequest, profile());
        m_followRequest = p.followRequest;
        m_workflow->setProbeFollow(m_follow.get());
    }
    showProvisional();
}

void MainWindow::showProvisional()
{
    const LoadedProgram &p = m_program->program();
    m_view->model()->setProvisionalAfter(p.provisional() ? std::uint32_t(p.provisionalEntry)
                                                         : ToolpathViewModel::kNoProvisional);
}

// The program after a followed probe (or as loaded again before a new run): its view, the
// provisional part from the next probe, the planned speed and the time left of the part.
void MainWindow::onProbeFollowShown()
{
    const LoadedProgram &p = m_program->program();
    m_view->model()->setScene(sceneOf(p));
    showProvisional();
    m_plot->setPlanned(p.speed);
    m_remaining = session::RemainingTime(p.lineEndS, p.estimatedS);
    if (!m_link->state().jobActive)
        m_run->setProgress(0, 0, p.estimatedS);
    checkProgramLimits();
    updatePlacement();
    updateProgramInfo();
}

} // namespace frezka::gui
