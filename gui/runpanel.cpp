#include "runpanel.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <cmath>

namespace frezka::gui {

RunPanel::RunPanel(QWidget *parent)
    : QWidget(parent)
{
    auto make = [this](const char *name, void (RunPanel::*signal)()) {
        auto *b = new QPushButton(this);
        b->setObjectName(QLatin1String(name));
        b->setFocusPolicy(Qt::NoFocus); // Space / Enter never press a run button
        b->setAutoDefault(false);
        connect(b, &QPushButton::clicked, this, signal);
        return b;
    };
    m_check = make("check", &RunPanel::checkRequested);
    m_run = make("run", &RunPanel::runRequested);
    m_pause = make("pause", &RunPanel::pauseRequested);
    m_resume = make("resume", &RunPanel::resumeRequested);
    m_stop = make("stop", &RunPanel::stopRequested);
    m_abort = make("abort", &RunPanel::abortRequested);
    m_lift = make("toolLift", &RunPanel::toolLiftRequested);
    m_run->setStyleSheet(QStringLiteral("QPushButton:enabled { background: #2e8b3a; color: white; "
                                        "font-weight: bold; }"));
    m_abort->setStyleSheet(QStringLiteral("QPushButton:enabled { background: #b22; color: white; "
                                          "font-weight: bold; }"));
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("runProgress"));
    m_progress->setRange(0, 1000);
    m_elapsed = new QLabel(this);
    m_eta = new QLabel(this);
    m_eta->setObjectName(QStringLiteral("eta"));
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(2, 2, 2, 2);
    grid->addWidget(m_check, 0, 0);
    grid->addWidget(m_run, 0, 1);
    grid->addWidget(m_pause, 0, 2);
    grid->addWidget(m_resume, 0, 3);
    grid->addWidget(m_lift, 1, 0);
    grid->addWidget(m_stop, 1, 1);
    grid->addWidget(m_abort, 1, 2, 1, 2);
    grid->addWidget(m_progress, 2, 0, 1, 4);
    grid->addWidget(m_elapsed, 3, 0, 1, 2);
    grid->addWidget(m_eta, 3, 2, 1, 2, Qt::AlignRight);
    setPhase(RunPhase::NoProgram, false);
    retranslate();
}

void RunPanel::setPhase(RunPhase phase, bool connected)
{
    m_phase = phase;
    const bool loaded = phase != RunPhase::NoProgram;
    m_check->setEnabled(loaded && phase != RunPhase::Running);
    m_run->setEnabled(connected && (phase == RunPhase::Ready || phase == RunPhase::Finished));
    m_pause->setEnabled(connected && phase == RunPhase::Running);
    m_resume->setEnabled(connected && (phase == RunPhase::Paused || phase == RunPhase::Lifted));
    m_lift->setEnabled(connected && phase == RunPhase::Paused);
    m_stop->setEnabled(connected && (phase == RunPhase::Running || phase == RunPhase::Paused ||
                                     phase == RunPhase::Lifted || phase == RunPhase::Homing));
    m_abort->setEnabled(connected);
}

QString RunPanel::formatDuration(double seconds)
{
    if (seconds < 0 || !std::isfinite(seconds))
        return QStringLiteral("--:--:--");
    const qint64 s = qint64(std::llround(seconds));
    return QStringLiteral("%1:%2:%3")
        .arg(s / 3600, 2, 10, QLatin1Char('0'))
        .arg((s / 60) % 60, 2, 10, QLatin1Char('0'))
        .arg(s % 60, 2, 10, QLatin1Char('0'));
}

void RunPanel::setProgress(double fraction, double elapsedS, double remainingS)
{
    m_progress->setValue(int(std::clamp(fraction, 0.0, 1.0) * 1000));
    m_elapsedS = elapsedS;
    m_remainingS = remainingS;
    m_elapsed->setText(tr("Elapsed %1").arg(formatDuration(elapsedS)));
    m_eta->setText(tr("Remaining %1").arg(formatDuration(remainingS)));
}

void RunPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void RunPanel::retranslate()
{
    m_check->setText(tr("Check"));
    m_check->setToolTip(tr("Check the program against the machine profile without moving"));
    m_run->setText(tr("Run"));
    m_run->setToolTip(tr("Run the checked program (asks for homing first on a machine not "
                         "homed). The machine's START button does the same when the profile "
                         "names its input. Space and Enter never press it."));
    m_pause->setText(tr("Pause"));
    m_pause->setToolTip(tr("Brake along the ramp and hold; Resume continues"));
    m_resume->setText(tr("Resume"));
    m_resume->setToolTip(tr("Continue the held job (the START button does the same)"));
    m_stop->setText(tr("Stop (Esc)"));
    m_stop->setToolTip(tr("Controlled stop (Esc): brake along the ramp and hold the job; the "
                          "position stays known and Resume continues it. During homing: end "
                          "homing, the axes not yet homed stay not homed."));
    m_abort->setText(tr("Abort"));
    m_abort->setToolTip(tr("Brake and drop every queued move: the job ends and cannot be "
                           "resumed; the position stays known. Also ends homing."));
    m_lift->setText(tr("Tool lift…"));
    m_lift->setToolTip(tr("Lift the tool, switch the spindle off, change or clean it, continue"));
    setProgress(double(m_progress->value()) / 1000.0, m_elapsedS, m_remainingS);
}

} // namespace frezka::gui
