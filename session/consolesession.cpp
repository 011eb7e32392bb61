#include "consolesession.h"

#include "planerrortext.h"
#include "runworkflow.h"
#include "workoffsets.h"

#include "machine/planner.h"

namespace frezka::session {

ConsoleSession::ConsoleSession(RunWorkflow &workflow, WorkOffsets &offsets, QObject *parent)
    : QObject(parent)
    , m_workflow(workflow)
    , m_offsets(offsets)
{
    connect(&m_workflow, &RunWorkflow::jobStarted, this, [this] { m_ranLastJob = false; });
}

void ConsoleSession::execute(const QString &line)
{
    if (line.startsWith(QLatin1Char('!'))) {
        m_workflow.link().sendRaw(line);
        return;
    }
    const auto &st = m_workflow.state();
    if (st.mode != driver::MachineMode::Idle) {
        emit failed(tr("Manual G-code runs only while the machine is ready."));
        return;
    }
    MdiSession::Outcome result =
        m_mdi.interpret(line.toStdString(), st.positionMm, m_offsets.state());
    if (!result.ok()) {
        emit failed(gcode::formatError(tr("manual line"), result.errors.front()));
        return;
    }
    if (result.offsetsChanged)
        m_offsets.setState(result.offsets);
    emit message(tr("Manual: %1 (%2)").arg(line, m_mdi.modal().text()));
    if (result.toolpath.empty())
        return; // modes only (G91, F100, G55 ...)
    const machine::PlanResult plan = machine::plan(result.toolpath, m_workflow.profile());
    if (!plan.ok()) {
        emit failed(planErrorText(tr("manual line"), plan.errors.front()));
        return;
    }
    m_ranLastJob = true;
    emit jobStarted();
    m_workflow.link().run(plan.program);
}

} // namespace frezka::session
