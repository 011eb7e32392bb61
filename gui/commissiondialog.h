#pragma once
// CommissionDialog: Machine › Commission this machine… (issue 21 item 3). Runs the steps of the
// commissioning assistant (session/commission.h): the ones that move nothing at once, then
// each one that moves or switches something after the operator pressed Run (or Skip); the
// questions (did it move? how far?) are answered with Yes / No and a number. The list shows
// every step with its result; Save report… writes the report with the serial trace, Save
// profile… the updated profile to a new file. The main window disconnects its own link while
// the dialog has the unit and connects again when it closes.

#include "machine/machineconfig.h"
#include "session/commissionmoves.h"

#include <QDialog>

#include <memory>

class QEventLoop;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace frezka::driver {
class EmulatorTransport;
class TraceRecorder;
class Transport;
} // namespace frezka::driver
namespace frezka::emulator {
class Unit;
}

namespace frezka::gui {

class CommissionDialog : public QDialog, private session::CommissionOperator
{
    Q_OBJECT

public:
    // profilePath: the file the profile came from (never overwritten by Save profile).
    CommissionDialog(const machine::MachineConfig &profile, const QString &profilePath,
                     QWidget *parent = nullptr);
    ~CommissionDialog() override;

    const session::CommissionResult &result() const { return m_result; }
    // The built-in emulator the steps talk to when the profile's port is "emulator" (tests
    // press its inputs), else nullptr.
    emulator::Unit *emulatedUnit();
    // The report as text (with the serial trace) and the two savers behind the buttons.
    QString reportText() const;
    bool saveReport(const QString &path, QString *error) const;
    bool saveProfile(const QString &path, QString *error) const;

public slots:
    // Runs every step; returns when all are done (the dialog stays responsive meanwhile).
    void start();
    // While the steps run: every later step is skipped; afterwards the dialog closes.
    void reject() override;

signals:
    // The dialog waits for the operator: a step to run or skip, a question, a number.
    void operatorAsked();
    // Something the operator is to do now ("Press the home switch of X (IN0) now.").
    void operatorInstructed(const QString &text);
    void stepsFinished();

private:
    enum class Answer : std::uint8_t { None, Run, Skip, Yes, No, Number };
    bool confirm(const session::CommissionStep &step) override;
    bool ask(const QString &question) override;
    std::optional<double> askNumber(const QString &question) override;
    void instruct(const QString &text) override;
    Answer waitFor(const QString &prompt, std::initializer_list<QWidget *> enabled);
    void answer(Answer a);
    void connectButtons();
    void showSteps();
    void saveReportAs();
    void saveProfileAs();

    session::CommissionResult m_result;
    QString m_profilePath;
    std::unique_ptr<driver::TraceRecorder> m_recorder;
    std::unique_ptr<driver::Transport> m_transport; // the built-in emulator's, traced
    driver::EmulatorTransport *m_emulator = nullptr;
    std::string m_probeTrace;
    QListWidget *m_steps = nullptr;
    QLabel *m_prompt = nullptr;
    QLineEdit *m_number = nullptr;
    QPushButton *m_start = nullptr, *m_run = nullptr, *m_skip = nullptr, *m_yes = nullptr,
                *m_no = nullptr, *m_ok = nullptr, *m_saveReport = nullptr, *m_saveProfile = nullptr;
    Answer m_answer = Answer::None;
    QEventLoop *m_wait = nullptr;
    bool m_cancelled = false;
    bool m_running = false;
};

} // namespace frezka::gui
