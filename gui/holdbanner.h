#pragma once
// HoldBanner: the guided step shown above the toolpath view while a job is held — a pause,
// an M0/M1/M6 operator stop, an input interrupt — and the tool-lift workflow (lift, spindle
// off, change or clean the tool, jog it away and back, spindle on, lower, continue, optionally
// at a new speed). Its "Stop the spindle" box is the operator's word for the spindle and coolant
// while the job is held: ticking or unticking it asks for them off or on again at once
// (spindleHoldRequested); what the unit really drives is shown in the text (setOutputs).
// Never modal: the machine window stays usable and tests drive it by its buttons.

#include <QFrame>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace frezka::gui {

class HoldBanner : public QFrame
{
    Q_OBJECT

public:
    enum class Kind { None, Paused, OperatorStop, Interrupt, ProbeFailed, PathFault, ToolLifted };
    explicit HoldBanner(QWidget *parent = nullptr);
    // Shows the step for kind (None hides it). line = source line, detail = unit's text.
    void showHold(Kind kind, int line, const QString &detail);
    Kind kind() const { return m_kind; }
    QString text() const;
    bool stopSpindleOnLift() const;
    // The unit's spindle as the driver knows it (on, or held off for the hold) and its spin-up.
    void setOutputs(bool spindleOn, bool heldOff, double spinUpS);
    void setStopSpindle(bool on); // the box, without a request
    // New feed for the rest of the job, mm/min; 0 = unchanged.
    double newFeedMmPerMin() const;
    void setNewFeedMmPerMin(double feed);
    // A new feed needs XM (it is the override for the rest of the job): hidden on units without.
    void setNewFeedAvailable(bool available);

signals:
    void continueRequested();
    void liftRequested(bool stopSpindle);
    // The box clicked: the spindle and coolant off (true) or on again (false) while held.
    void spindleHoldRequested(bool stop);
    // Spindle back on (if it was stopped), lower the tool, continue (or stay paused).
    void lowerRequested(double newFeedMmPerMin, bool thenContinue);
    void abortRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void retranslateHold(); // the title and text of m_kind

    Kind m_kind = Kind::None;
    int m_line = 0;
    QString m_detail;
    bool m_spindleOn = false;
    bool m_heldOff = false;
    bool m_newFeed = true;
    double m_spinUpS = 0;
    QLabel *m_title, *m_text, *m_spindle, *m_feedLabel;
    QCheckBox *m_stopSpindle;
    QDoubleSpinBox *m_feed;
    QPushButton *m_continue, *m_lift, *m_lowerContinue, *m_lowerOnly, *m_abort;
};

} // namespace frezka::gui
