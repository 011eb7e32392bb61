#pragma once
// HoldBanner: the guided step shown above the toolpath view while a job is held — a pause,
// an M0/M1/M6 operator stop, an input interrupt — and the tool-lift workflow (lift, spindle
// off, change or clean the tool, spindle on, lower, continue, optionally at a new speed).
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
    // New feed for the rest of the job, mm/min; 0 = unchanged.
    double newFeedMmPerMin() const;
    void setNewFeedMmPerMin(double feed);

signals:
    void continueRequested();
    void liftRequested(bool stopSpindle);
    // Spindle back on (if it was stopped), lower the tool, continue (or stay paused).
    void lowerRequested(double newFeedMmPerMin, bool thenContinue);
    void abortRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    Kind m_kind = Kind::None;
    int m_line = 0;
    QString m_detail;
    QLabel *m_title, *m_text, *m_feedLabel;
    QCheckBox *m_stopSpindle;
    QDoubleSpinBox *m_feed;
    QPushButton *m_continue, *m_lift, *m_lowerContinue, *m_lowerOnly, *m_abort;
};

} // namespace frezka::gui
