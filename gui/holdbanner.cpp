#include "holdbanner.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace frezka::gui {

HoldBanner::HoldBanner(QWidget *parent)
    : QFrame(parent)
{
    setObjectName(QStringLiteral("holdBanner"));
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet(QStringLiteral("#holdBanner { background: #fff3c4; color: black; }"
                                 "#holdBanner QLabel { color: black; }"));
    m_title = new QLabel(this);
    QFont f = m_title->font();
    f.setBold(true);
    f.setPointSizeF(f.pointSizeF() * 1.2);
    m_title->setFont(f);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("holdText"));
    m_text->setWordWrap(true);
    m_spindle = new QLabel(this);
    m_spindle->setObjectName(QStringLiteral("holdSpindle"));
    m_spindle->setWordWrap(true);
    m_stopSpindle = new QCheckBox(this);
    m_stopSpindle->setFocusPolicy(Qt::NoFocus); // it switches the spindle while held
    m_stopSpindle->setObjectName(QStringLiteral("holdStopSpindle"));
    m_stopSpindle->setChecked(true);
    connect(m_stopSpindle, &QCheckBox::clicked, this, &HoldBanner::spindleHoldRequested);
    m_feedLabel = new QLabel(this);
    m_feed = new QDoubleSpinBox(this);
    m_feed->setObjectName(QStringLiteral("holdNewFeed"));
    m_feed->setRange(0, 100000);
    m_feed->setDecimals(0);
    m_feed->setSuffix(QStringLiteral(" mm/min"));
    auto button = [this](const char *name) {
        auto *b = new QPushButton(this);
        b->setObjectName(QLatin1String(name));
        b->setFocusPolicy(Qt::NoFocus); // no key continues or aborts through the focus
        return b;
    };
    m_continue = button("holdContinue");
    m_lift = button("holdLift");
    m_lowerContinue = button("holdLowerContinue");
    m_lowerOnly = button("holdLowerOnly");
    m_abort = button("holdAbort");
    connect(m_continue, &QPushButton::clicked, this, &HoldBanner::continueRequested);
    connect(m_lift, &QPushButton::clicked, this,
            [this] { emit liftRequested(m_stopSpindle->isChecked()); });
    connect(m_lowerContinue, &QPushButton::clicked, this,
            [this] { emit lowerRequested(m_feed->value(), true); });
    connect(m_lowerOnly, &QPushButton::clicked, this,
            [this] { emit lowerRequested(m_feed->value(), false); });
    connect(m_abort, &QPushButton::clicked, this, &HoldBanner::abortRequested);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_stopSpindle);
    buttons->addWidget(m_feedLabel);
    buttons->addWidget(m_feed);
    buttons->addStretch();
    for (auto *b : {m_continue, m_lift, m_lowerContinue, m_lowerOnly, m_abort})
        buttons->addWidget(b);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(8, 6, 8, 6);
    layout->addWidget(m_title);
    layout->addWidget(m_text);
    layout->addWidget(m_spindle);
    layout->addLayout(buttons);
    showHold(Kind::None, 0, QString());
}

void HoldBanner::showHold(Kind kind, int line, const QString &detail)
{
    m_kind = kind;
    m_line = line;
    m_detail = detail;
    setVisible(kind != Kind::None);
    const bool lifted = kind == Kind::ToolLifted;
    const bool held = kind != Kind::None && !lifted;
    m_continue->setVisible(held);
    m_lift->setVisible(held && kind != Kind::PathFault); // Continue lifts the tool itself
    m_stopSpindle->setVisible(held && kind != Kind::PathFault);
    m_lowerContinue->setVisible(lifted);
    m_lowerOnly->setVisible(lifted);
    m_feedLabel->setVisible(lifted && m_newFeed);
    m_feed->setVisible(lifted && m_newFeed);
    retranslate();
}

QString HoldBanner::text() const
{
    return m_title->text() + QLatin1Char('\n') + m_text->text();
}

bool HoldBanner::stopSpindleOnLift() const
{
    return m_stopSpindle->isChecked();
}

void HoldBanner::setOutputs(bool spindleOn, bool heldOff, double spinUpS)
{
    if (spindleOn == m_spindleOn && heldOff == m_heldOff && spinUpS == m_spinUpS)
        return;
    m_spindleOn = spindleOn;
    m_heldOff = heldOff;
    m_spinUpS = spinUpS;
    retranslate();
}

void HoldBanner::setStopSpindle(bool on)
{
    m_stopSpindle->setChecked(on);
}

double HoldBanner::newFeedMmPerMin() const
{
    return m_feed->value();
}

void HoldBanner::setNewFeedAvailable(bool available)
{
    if (available == m_newFeed)
        return;
    m_newFeed = available;
    retranslate();
    m_feedLabel->setVisible(available && m_lowerOnly->isVisibleTo(this));
    m_feed->setVisible(available && m_lowerOnly->isVisibleTo(this));
    if (!available)
        m_feed->setValue(0);
}

void HoldBanner::setNewFeedMmPerMin(double feed)
{
    m_feed->setValue(feed);
}

void HoldBanner::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QFrame::changeEvent(event);
}

void HoldBanner::retranslate()
{
    retranslateHold();
    if (m_kind == Kind::None || m_kind == Kind::ToolLifted)
        m_spindle->clear();
    else if (m_heldOff)
        m_spindle->setText(tr("The spindle and coolant are off for the hold. Continue switches "
                              "them on again and waits %1 s for the spindle before the tool moves.")
                               .arg(m_spinUpS, 0, 'f', 1));
    else if (m_spindleOn)
        m_spindle->setText(tr("The spindle is running."));
    else
        m_spindle->setText(tr("The spindle is off."));
    m_stopSpindle->setText(tr("Stop the spindle"));
    m_stopSpindle->setToolTip(
        tr("While the job is held: the spindle and coolant off (ticked) or on again (unticked). "
           "Ticked, a pause stops them as soon as the machine stands."));
    m_feedLabel->setText(tr("New feed (0 = unchanged):"));
    m_feed->setToolTip(tr("The feed from here on, as the feed override for the rest of the job"));
    m_continue->setText(tr("Continue"));
    m_lift->setText(tr("Lift tool"));
    m_lowerContinue->setText(tr("Lower and continue"));
    m_lowerOnly->setText(tr("Lower, stay paused"));
    m_abort->setText(tr("Abort job"));
}

// The title and the text of the hold's kind, one case per kind.
void HoldBanner::retranslateHold()
{
    const QString where = m_line > 0 ? tr("at line %1").arg(m_line) : QString();
    switch (m_kind) {
    case Kind::None:
        break;
    case Kind::Paused:
        m_title->setText(tr("Paused %1").arg(where));
        m_text->setText(tr("The machine has stopped along its ramp and keeps the rest of the job. "
                           "Continue, or lift the tool to change or clean it (the spindle and "
                           "coolant go off for a lifted tool)."));
        break;
    case Kind::OperatorStop:
        m_title->setText(tr("Program stop %1").arg(where));
        m_text->setText(tr("%1\nDo what the program asks, then press Continue.").arg(m_detail));
        break;
    case Kind::Interrupt:
        m_title->setText(tr("Stopped by an input %1").arg(where));
        m_text->setText(
            tr("%1\nCheck the machine; when it is safe, Continue or Abort.").arg(m_detail));
        break;
    case Kind::ProbeFailed:
        m_title->setText(tr("Probe failed %1").arg(where));
        m_text->setText(tr("%1\nThe probe did not touch as expected. Abort the job or Continue.")
                            .arg(m_detail));
        break;
    case Kind::PathFault:
        m_title->setText(tr("Off the planned path %1").arg(where));
        m_text->setText(
            tr("The machine's position left the path that was sent: a command was damaged on the "
               "serial line in a way its checksum cannot show, and the unit ran it. The machine "
               "has stopped. Check the workpiece. Continue lifts the tool, returns to the last "
               "point verified on the path and runs the job on from there; or Abort the job."));
        break;
    case Kind::ToolLifted:
        m_title->setText(tr("Tool lifted %1").arg(where));
        m_text->setText(
            tr("The spindle and coolant are off. Change, measure or clean the tool; you may jog "
               "the machine away by steps. Lowering switches the spindle and coolant on again as "
               "they were, waits %1 s for the spindle to reach its speed, returns exactly to where "
               "the tool was lifted, lowers it into the work and continues. Abort ends the job "
               "here with the tool up.")
                .arg(m_spinUpS, 0, 'f', 1) +
            (m_newFeed ? QLatin1Char(' ') + tr("A new feed entered below is the feed override "
                                               "for the rest of the job.")
                       : QString()));
        break;
    }
}

} // namespace frezka::gui
