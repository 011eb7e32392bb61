#include "drowidget.h"

#include "session/workoffsets.h"

#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

namespace frezka::gui {
namespace {
constexpr char kAxes[] = "XYZA";
}

DroWidget::DroWidget(QWidget *parent)
    : QWidget(parent)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(4, 4, 4, 4);
    QFont big = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    big.setPointSizeF(big.pointSizeF() * 1.8);
    big.setBold(true);
    QFont small = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_workHeader = new QLabel(this);
    m_machineHeader = new QLabel(this);
    grid->addWidget(m_workHeader, 0, 1, Qt::AlignRight);
    grid->addWidget(m_machineHeader, 0, 2, Qt::AlignRight);
    for (int i = 0; i < 4; ++i) {
        m_name[i] = new QLabel(QString(QLatin1Char(kAxes[i])), this);
        m_name[i]->setFont(big);
        m_work[i] = new QLabel(this);
        m_work[i]->setFont(big);
        m_work[i]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_work[i]->setObjectName(QStringLiteral("droWork%1").arg(QLatin1Char(kAxes[i])));
        m_work[i]->setMinimumWidth(
            QFontMetrics(big).horizontalAdvance(QStringLiteral("-0000.000")));
        m_machine[i] = new QLabel(this);
        m_machine[i]->setFont(small);
        m_machine[i]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_machine[i]->setObjectName(QStringLiteral("droMachine%1").arg(QLatin1Char(kAxes[i])));
        m_zero[i] = new QPushButton(this);
        m_zero[i]->setObjectName(QStringLiteral("zero%1").arg(QLatin1Char(kAxes[i])));
        m_zero[i]->setFocusPolicy(Qt::NoFocus); // no key zeroes an axis through the focus
        connect(m_zero[i], &QPushButton::clicked, this, [this, i] { emit zeroAxisRequested(i); });
        grid->addWidget(m_name[i], i + 1, 0);
        grid->addWidget(m_work[i], i + 1, 1);
        grid->addWidget(m_machine[i], i + 1, 2);
        grid->addWidget(m_zero[i], i + 1, 3);
    }
    m_offsetLabel = new QLabel(this);
    m_offset = new QComboBox(this);
    m_offset->setObjectName(QStringLiteral("workOffset"));
    for (int i = 0; i < session::kWorkSystems; ++i)
        m_offset->addItem(session::workSystemName(i));
    connect(m_offset, &QComboBox::activated, this, &DroWidget::offsetSelected);
    m_zeroAll = new QPushButton(this);
    m_zeroAll->setObjectName(QStringLiteral("zeroAll"));
    m_zeroAll->setFocusPolicy(Qt::NoFocus);
    connect(m_zeroAll, &QPushButton::clicked, this, &DroWidget::zeroAllRequested);
    grid->addWidget(m_offsetLabel, 5, 0);
    grid->addWidget(m_offset, 5, 1);
    grid->addWidget(m_zeroAll, 5, 2, 1, 2);
    m_source = new QLabel(this);
    m_source->setObjectName(QStringLiteral("droSource"));
    m_source->setStyleSheet(QStringLiteral("color: #777; font-style: italic;"));
    m_source->setVisible(false);
    grid->addWidget(m_source, 6, 0, 1, 4);
    grid->setColumnStretch(1, 1);
    setPositions({}, {});
    retranslate();
}

void DroWidget::setAxisCount(int count)
{
    m_axisCount = count;
    for (int i = 0; i < 4; ++i) {
        const bool on = i < count;
        m_name[i]->setVisible(on);
        m_work[i]->setVisible(on);
        m_machine[i]->setVisible(on);
        m_zero[i]->setVisible(on);
    }
}

void DroWidget::setPositions(const std::array<double, 4> &machineMm,
                             const std::array<double, 4> &workMm)
{
    m_machineMm = machineMm;
    m_workMm = workMm;
    for (int i = 0; i < 4; ++i) {
        const LengthUnit unit = i < 3 ? m_unit : LengthUnit::Mm; // A: degrees
        m_work[i]->setText(formatLength(workMm[i], unit));
        m_machine[i]->setText(formatLength(machineMm[i], unit));
    }
}

void DroWidget::setModelled(bool modelled)
{
    if (modelled == m_modelled)
        return;
    m_modelled = modelled;
    m_source->setVisible(modelled);
    const QString grey = modelled ? QStringLiteral("color: #777;") : QString();
    for (int i = 0; i < 4; ++i) {
        m_work[i]->setStyleSheet(grey);
        m_machine[i]->setStyleSheet(grey);
    }
}

void DroWidget::setUnit(LengthUnit unit)
{
    m_unit = unit;
    retranslate();
    setPositions(m_machineMm, m_workMm);
}

void DroWidget::setActiveOffset(int index)
{
    m_offset->setCurrentIndex(index);
}

void DroWidget::setHomed(const std::array<bool, 4> &homed)
{
    for (int i = 0; i < 4; ++i)
        m_name[i]->setStyleSheet(homed[i] ? QStringLiteral("color: #2a2") : QString());
}

bool DroWidget::homedShown(int axis) const
{
    return !m_name[axis]->styleSheet().isEmpty();
}

QString DroWidget::workText(int axis) const
{
    return m_work[axis]->text();
}

QString DroWidget::machineText(int axis) const
{
    return m_machine[axis]->text();
}

void DroWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void DroWidget::retranslate()
{
    m_workHeader->setText(QStringLiteral("%1 (%2)").arg(tr("Work"), lengthSuffix(m_unit)));
    m_machineHeader->setText(QStringLiteral("%1 (%2)").arg(tr("Machine"), lengthSuffix(m_unit)));
    for (int i = 0; i < 4; ++i) {
        m_zero[i]->setText(tr("Zero"));
        m_zero[i]->setToolTip(
            tr("Set the work zero of %1 at the current position").arg(QLatin1Char(kAxes[i])));
    }
    m_zeroAll->setText(tr("Zero all"));
    m_zeroAll->setToolTip(tr("Set the work zero of every axis at the current position"));
    m_offsetLabel->setText(tr("Offset"));
    m_source->setText(tr("≈ modelled between position reads"));
    m_source->setToolTip(tr("While the serial line is busy with a dense job the unit's counters "
                            "are read only now and then; in between, the figures follow the "
                            "driver's model of the unit along the plan, never ahead of what the "
                            "unit was sent, and each read corrects them."));
}

} // namespace frezka::gui
