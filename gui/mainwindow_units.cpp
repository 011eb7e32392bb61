// MainWindow, the units on the machine's line (the profile's line.units): the Units panel, the
// other units' profiles handed to the driver before each connect, their jogs and stops.
#include "mainwindow.h"

#include "consolewidget.h"
#include "unitspanel.h"

#include "driver/link/machinecontroller.h"

#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>

namespace frezka::gui {

void MainWindow::buildUnitsDock()
{
    m_units = new UnitsPanel(this);
    m_unitsDock = new QDockWidget(this);
    m_unitsDock->setObjectName(QStringLiteral("unitsDock"));
    m_unitsDock->setWidget(m_units);
    m_unitsDock->setWindowTitle(UnitsPanel::title());
    m_unitsDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                             QDockWidget::DockWidgetClosable);
    addDockWidget(Qt::BottomDockWidgetArea, m_unitsDock);
    tabifyDockWidget(m_consoleDock, m_unitsDock);
    m_consoleDock->raise();
    m_viewMenu->insertAction(m_viewMenu->actions().value(8), m_unitsDock->toggleViewAction());

    connect(m_controller, &driver::MachineController::unitStateChanged, m_units,
            &UnitsPanel::showState);
    connect(m_controller, &driver::MachineController::unitErrorOccurred, this,
            [this](int unit, const driver::MachineError &error) {
                const QString text = driver::translatedText(error.reason, true);
                m_units->showError(unit, text);
                m_console->appendError(tr("Unit %1: %2").arg(unit).arg(text));
            });
    connect(m_units, &UnitsPanel::jogRequested, m_controller,
            [this](int unit, int axis, double distanceMm, double speedMmPerMin) {
                m_controller->executeOn(unit, driver::op::JogStep{axis, distanceMm, speedMmPerMin});
            });
    // Stop: a jog ends (H, D); a job or homing is held as the machine's Stop holds it.
    connect(m_units, &UnitsPanel::stopRequested, m_controller, [this](int unit) {
        const auto &states = m_controller->unitStates();
        const bool jogging = unit < int(states.size()) &&
                             states[std::size_t(unit)].mode == driver::MachineMode::Jogging;
        if (jogging)
            m_controller->executeOn(unit, driver::op::JogStop{});
        else
            m_controller->executeOn(unit, driver::op::Pause{});
    });
    connect(m_units, &UnitsPanel::machineChosen, m_controller,
            &driver::MachineController::chooseMachineUnit);
    connect(m_controller, &driver::MachineController::machineUnitChanged, this,
            &MainWindow::onMachineUnitChanged);
}

// The driver made another unit of the line the machine: the window takes that unit's profile,
// with the line's list in it (the units' profiles as absolute paths, the former machine's being
// the profile used so far), so that the next connect sets up the same line.
void MainWindow::onMachineUnitChanged(int unit)
{
    std::vector<UnitsPanel::Unit> units = m_units->units();
    const int former = m_units->machineIndex();
    if (unit == former) {
        showError(tr("Another unit becomes this window's machine only while every unit on the "
                     "line is idle; wait, or stop the units, then choose again."));
        return;
    }
    if (unit < 0 || unit >= int(units.size()))
        return;
    const QDir base = QFileInfo(m_profilePath).absoluteDir();
    const auto absolute = [&base](const std::string &path) {
        return path.empty() ? path
                            : QDir::cleanPath(base.absoluteFilePath(QString::fromStdString(path)))
                                  .toStdString();
    };
    const std::string chosenPath = absolute(units[std::size_t(unit)].entry.profile);
    for (int i = 0; i < int(units.size()); ++i) {
        machine::LineUnitConfig &e = units[std::size_t(i)].entry;
        if (i == unit) {
            e.role = machine::LineUnitRole::Machine;
            e.profile.clear();
        } else if (i == former) {
            e.role = machine::LineUnitRole::Auxiliary;
            e.profile = QFileInfo(m_profilePath).absoluteFilePath().toStdString();
        } else {
            e.profile = absolute(e.profile);
        }
    }
    machine::MachineConfig config = units[std::size_t(unit)].config;
    config.line.units.clear();
    for (const UnitsPanel::Unit &u : units)
        config.line.units.push_back(u.entry);
    m_units->setUnits(units, unit);
    applyProfile(config, QString::fromStdString(chosenPath));
    m_console->appendInfo(tr("This window's machine is now %1 (address %2).")
                              .arg(QString::fromStdString(units[std::size_t(unit)].entry.name))
                              .arg(units[std::size_t(unit)].entry.address));
}

bool MainWindow::prepareLine(const machine::MachineConfig &config)
{
    const machine::LineProfiles line =
        machine::loadLineProfiles(config, m_profilePath.toStdString());
    if (!line.errors.empty()) {
        QStringList problems;
        for (const machine::ConfigError &e : line.errors)
            problems << QString::fromStdString(e.message);
        showError(tr("The units on the machine's line cannot be set up; fix line.units in the "
                     "machine profile:\n%1")
                      .arg(problems.join(QLatin1Char('\n'))));
        return false;
    }
    const int machineIndex = machine::machineUnitIndex(config);
    std::vector<UnitsPanel::Unit> units;
    for (std::size_t i = 0; i < line.configs.size(); ++i) {
        machine::LineUnitConfig entry;
        if (i < config.line.units.size()) {
            entry = config.line.units[i];
        } else { // a unit alone on its line
            entry.address = config.unit.address;
            entry.variant = config.unit.variant;
            entry.name = config.name;
            entry.role = machine::LineUnitRole::Machine;
        }
        units.push_back({entry, line.configs[i]});
    }
    m_units->setUnits(units, machineIndex);
    m_controller->setLineUnits(line.configs, machineIndex);
    return true;
}

} // namespace frezka::gui
