#include "unitspanel.h"

#include "session/runworkflow.h"

#include "protocol/variant.h"

#include <QComboBox>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace frezka::gui {
namespace {

constexpr double kSteps[] = {0.01, 0.1, 1, 10};

QString variantName(protocol::Variant variant)
{
    const auto &info = protocol::variantInfo(variant);
    return QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()));
}

} // namespace

UnitsPanel::UnitsPanel(QWidget *parent)
    : QWidget(parent)
    , m_table(new QTableWidget(0, ColumnCount, this))
    , m_jogLabel(new QLabel(this))
    , m_unitBox(new QComboBox(this))
    , m_axisBox(new QComboBox(this))
    , m_stepBox(new QComboBox(this))
    , m_minus(new QPushButton(QStringLiteral("−"), this))
    , m_plus(new QPushButton(QStringLiteral("+"), this))
    , m_stop(new QPushButton(this))
    , m_choose(new QPushButton(this))
{
    m_table->setObjectName(QStringLiteral("unitsTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_unitBox->setObjectName(QStringLiteral("unitsJogUnit"));
    m_axisBox->setObjectName(QStringLiteral("unitsJogAxis"));
    m_stepBox->setObjectName(QStringLiteral("unitsJogStep"));
    m_minus->setObjectName(QStringLiteral("unitsJogMinus"));
    m_plus->setObjectName(QStringLiteral("unitsJogPlus"));
    m_stop->setObjectName(QStringLiteral("unitsStop"));
    m_choose->setObjectName(QStringLiteral("unitsMakeMachine"));
    connect(m_choose, &QPushButton::clicked, this, [this] {
        if (jogUnit() >= 0)
            emit machineChosen(jogUnit());
    });
    for (const char letter : machine::kAxisLetters)
        m_axisBox->addItem(QString(QLatin1Char(letter)));
    for (const double step : kSteps)
        m_stepBox->addItem(QString::number(step), step);
    m_stepBox->setCurrentIndex(2);
    connect(m_minus, &QPushButton::clicked, this, [this] { jog(-1); });
    connect(m_plus, &QPushButton::clicked, this, [this] { jog(+1); });
    connect(m_stop, &QPushButton::clicked, this, [this] {
        if (jogUnit() >= 0)
            emit stopRequested(jogUnit());
    });
    auto *controls = new QHBoxLayout;
    controls->addWidget(m_jogLabel);
    for (QWidget *w : {static_cast<QWidget *>(m_unitBox), static_cast<QWidget *>(m_axisBox),
                       static_cast<QWidget *>(m_stepBox), static_cast<QWidget *>(m_minus),
                       static_cast<QWidget *>(m_plus), static_cast<QWidget *>(m_stop),
                       static_cast<QWidget *>(m_choose)})
        controls->addWidget(w);
    controls->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_table, 1);
    layout->addLayout(controls);
    retranslate();
    updateControls();
}

void UnitsPanel::setUnits(const std::vector<Unit> &units, int machine)
{
    m_units = units;
    m_machine = machine;
    m_states.assign(units.size(), driver::MachineState{});
    m_errors.assign(units.size(), QString());
    m_table->setRowCount(int(units.size()));
    for (int row = 0; row < int(units.size()); ++row) {
        for (int c = 0; c < ColumnCount; ++c)
            m_table->setItem(row, c, new QTableWidgetItem);
        showState(row, {});
    }
    const int chosen = jogUnit();
    m_unitBox->clear();
    for (int i = 0; i < int(units.size()); ++i)
        if (i != machine)
            m_unitBox->addItem(QString::fromStdString(units[std::size_t(i)].entry.name), i);
    setJogUnit(chosen);
    retranslate();
    updateControls();
}

QString UnitsPanel::stateText(int unit) const
{
    const auto u = std::size_t(unit);
    if (!m_errors[u].isEmpty())
        return m_errors[u];
    return session::RunWorkflow::modeText(m_states[u].mode);
}

void UnitsPanel::showState(int unit, const driver::MachineState &state)
{
    if (unit < 0 || unit >= unitCount())
        return;
    const auto u = std::size_t(unit);
    if (state.mode != m_states[u].mode)
        m_errors[u].clear();
    m_states[u] = state;
    const Unit &info = m_units[u];
    auto set = [&](Column c, const QString &text) { m_table->item(unit, c)->setText(text); };
    set(Address, QString::number(info.entry.address));
    set(Name, unit == m_machine
                  ? tr("%1 (this window's machine)").arg(QString::fromStdString(info.entry.name))
                  : QString::fromStdString(info.entry.name));
    set(Type, variantName(info.entry.variant));
    QString identity = QString::fromStdString(state.firmware);
    if (!state.unitId.empty())
        identity += QStringLiteral(" · ") + QString::fromStdString(state.unitId);
    set(Identity, identity);
    set(State, stateText(unit));
    for (int a = 0; a < 4; ++a) {
        const bool present = info.config.axes[std::size_t(a)].present;
        set(Column(X + a),
            present ? QString::number(state.positionMm[std::size_t(a)], 'f', 3) : QString());
    }
    QStringList in, out;
    for (const int n : {0, 1, 2, 3, 4, 5, 6, 7, 14, 15})
        if (state.inputHigh(n))
            in << QString::number(n);
    for (int n = 0; n < 4; ++n)
        if (state.outputIsOn(n))
            out << QString::number(n);
    set(Inputs, in.isEmpty() ? tr("none high") : tr("high: %1").arg(in.join(QLatin1Char(' '))));
    set(Outputs, out.isEmpty() ? tr("all off") : tr("on: %1").arg(out.join(QLatin1Char(' '))));
    updateControls();
}

void UnitsPanel::showError(int unit, const QString &text)
{
    if (unit < 0 || unit >= unitCount())
        return;
    m_errors[std::size_t(unit)] = text;
    m_table->item(unit, State)->setText(text);
    m_table->item(unit, State)->setToolTip(text);
}

QString UnitsPanel::text(int unit, Column column) const
{
    const QTableWidgetItem *item = m_table->item(unit, column);
    return item ? item->text() : QString();
}

int UnitsPanel::jogUnit() const
{
    return m_unitBox->count() ? m_unitBox->currentData().toInt() : -1;
}

void UnitsPanel::setJogUnit(int unit)
{
    const int index = m_unitBox->findData(unit);
    if (index >= 0)
        m_unitBox->setCurrentIndex(index);
}

void UnitsPanel::setJogAxis(int axis)
{
    m_axisBox->setCurrentIndex(axis);
}

void UnitsPanel::setJogStepMm(double stepMm)
{
    const int index = m_stepBox->findData(stepMm);
    if (index >= 0)
        m_stepBox->setCurrentIndex(index);
}

// A step of the chosen unit, at half its axis's maximum speed (its own profile's).
void UnitsPanel::jog(int direction)
{
    const int unit = jogUnit();
    if (unit < 0)
        return;
    const int axis = m_axisBox->currentIndex();
    const auto &ax = m_units[std::size_t(unit)].config.axes[std::size_t(axis)];
    emit jogRequested(unit, axis, direction * m_stepBox->currentData().toDouble(),
                      ax.maxSpeedMmPerMin / 2);
}

// The jog acts on a connected unit that is idle or jogging; Stop whenever it is connected.
void UnitsPanel::updateControls()
{
    const int unit = jogUnit();
    using driver::MachineMode;
    const MachineMode mode =
        unit >= 0 ? m_states[std::size_t(unit)].mode : MachineMode::Disconnected;
    const bool canJog = mode == MachineMode::Idle || mode == MachineMode::Jogging;
    m_minus->setEnabled(canJog);
    m_plus->setEnabled(canJog);
    m_stop->setEnabled(unit >= 0 && mode != MachineMode::Disconnected &&
                       mode != MachineMode::LinkLost);
    m_choose->setEnabled(unit >= 0 && std::all_of(m_states.begin(), m_states.end(),
                                                  [](const driver::MachineState &s) {
                                                      return s.mode == MachineMode::Idle;
                                                  }));
    for (QWidget *w : {static_cast<QWidget *>(m_jogLabel), static_cast<QWidget *>(m_unitBox),
                       static_cast<QWidget *>(m_axisBox), static_cast<QWidget *>(m_stepBox),
                       static_cast<QWidget *>(m_minus), static_cast<QWidget *>(m_plus),
                       static_cast<QWidget *>(m_stop), static_cast<QWidget *>(m_choose)})
        w->setVisible(m_unitBox->count() > 0);
}

void UnitsPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QString UnitsPanel::title()
{
    return tr("Units on the line");
}

void UnitsPanel::retranslate()
{
    if (auto *dock = qobject_cast<QDockWidget *>(parentWidget()))
        dock->setWindowTitle(title());
    m_table->setHorizontalHeaderLabels(
        {tr("Address"), tr("Name"), tr("Unit"), tr("Firmware · identity"), tr("State"), tr("X mm"),
         tr("Y mm"), tr("Z mm"), tr("A °"), tr("Inputs"), tr("Outputs")});
    m_jogLabel->setText(tr("Jog another unit:"));
    m_stepBox->setToolTip(tr("Step in mm (A: degrees)"));
    m_minus->setToolTip(tr("Jog the chosen unit's axis by one step in the negative direction"));
    m_plus->setToolTip(tr("Jog the chosen unit's axis by one step in the positive direction"));
    m_stop->setText(tr("Stop"));
    m_stop->setToolTip(tr("Stop the chosen unit: its jog ends, a job or homing is held"));
    m_choose->setText(tr("Make it this window's machine"));
    m_choose->setToolTip(tr("The window then runs, jogs and shows the chosen unit with its own "
                            "profile; possible while every unit on the line is idle"));
    for (int row = 0; row < unitCount(); ++row)
        showState(row, m_states[std::size_t(row)]);
}

} // namespace frezka::gui
