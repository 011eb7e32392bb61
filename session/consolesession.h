#pragma once
// ConsoleSession: the console's lines. "!..." goes to the unit as a raw command; anything else
// is one block of G-code in the console's own modes (MdiSession: G91, G20, F ... last from line
// to line), interpreted from the machine's position with the session's work offsets (a G10,
// G92 or G5x typed here changes them), planned for the workflow's profile and run on its link
// when the machine is ready. A line of modes only moves nothing.

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

signals:
    void message(const QString &text);
    void failed(const QString &why);

private:
    RunWorkflow &m_workflow;
    WorkOffsets &m_offsets;
    MdiSession m_mdi;
};

} // namespace frezka::session
