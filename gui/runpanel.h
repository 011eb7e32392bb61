#pragma once
// RunPanel: Check / Run / Pause / Resume / Stop / Abort / Tool lift, and progress with elapsed
// time and the ETA of the planner's model. Its buttons never take the keyboard focus, so that
// Space or Enter meant for another control can never press Run, Stop or Abort by accident;
// Esc (the main window's shortcut) is the keyboard's controlled stop.

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace frezka::gui {

enum class RunPhase { NoProgram, Ready, Running, Paused, Lifted, Finished, Homing };

class RunPanel : public QWidget
{
    Q_OBJECT

public:
    explicit RunPanel(QWidget *parent = nullptr);
    // Enables the buttons that make sense in this phase; connected = a unit answers.
    void setPhase(RunPhase phase, bool connected);
    RunPhase phase() const { return m_phase; }
    // fraction 0..1; seconds < 0 = unknown.
    void setProgress(double fraction, double elapsedS, double remainingS);
    // The figures shown (seconds; remaining < 0: unknown).
    double elapsedS() const { return m_elapsedS; }
    double remainingS() const { return m_remainingS; }
    static QString formatDuration(double seconds);

signals:
    void checkRequested();
    void runRequested();
    void pauseRequested();
    void resumeRequested();
    void stopRequested();
    void abortRequested();
    void toolLiftRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    RunPhase m_phase = RunPhase::NoProgram;
    QPushButton *m_check, *m_run, *m_pause, *m_resume, *m_stop, *m_abort, *m_lift;
    QProgressBar *m_progress;
    QLabel *m_elapsed, *m_eta;
    double m_elapsedS = 0, m_remainingS = -1;
};

} // namespace frezka::gui
