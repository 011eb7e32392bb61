#pragma once
// ConsoleSession: the console's lines. "!..." goes to the unit as a raw command; anything else
// is one block of G-code in the console's own modes (MdiSession: G91, G20, F ... last from line
// to line), interpreted from the machine's position with the session's work offsets (a G10,
// G92 or G5x typed here changes them), planned for the workflow's profile and run on its link
// when the machine is ready, as a small job of its own: ranLastJob() tells the front end that
// the job on the link is the console's, not the loaded program's (whose display, progress and
// cut drawing it must not touch). A line of modes only moves nothing.

#include "session/mdisession.h"

#include <QObject>

namespace frezka::session {

class RunWorkflow;
class WorkOffsets;

class ConsoleSession : public QObject
{
    Q_OBJECT

public:
    ConsoleSession(RunWorkflow &workflow, WorkOffsets &offsets, QObject *parent = nullptr);

    void execute(const QString &line);
    const ModalState &modal() const { return m_mdi.modal(); }
    void reset() { m_mdi.reset(); }
    // The last job started on the link was a console line (until the workflow starts one).
    bool ranLastJob() const { return m_ranLastJob; }

signals:
    void message(const QString &text);
    void failed(const QString &why);
    void jobStarted(); // a console line went to the link as a job

private:
    RunWorkflow &m_workflow;
    WorkOffsets &m_offsets;
    MdiSession m_mdi;
    bool m_ranLastJob = false;
};

} // namespace frezka::session
