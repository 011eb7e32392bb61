#pragma once
// Machine › Height map (issue 19): probe a grid on the connected unit or the built-in emulator
// (session::HeightProbe, G38.2 per node), show the map as a colour map with its heights, save
// and load it (docs/height-map.md), and apply it to the loaded program or remove it (the main
// window loads the program again with the map: the preview and the plan show the bent path,
// the listing keeps the program's lines). The area, the clearance and the depth are in the
// active work system's coordinates (the window passes its offsets); the map is kept in machine
// coordinates. Non-modal; Cancel stops the probing (the job aborted, the tool back up).

#include "gcode/heightmap.h"
#include "machine/machineconfig.h"
#include "session/heightprobe.h"
#include "session/workoffsets.h"

#include <QDialog>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace frezka::session {
class MachineLink;
}

namespace frezka::gui {

class HeightMapDialog : public QDialog
{
    Q_OBJECT

public:
    HeightMapDialog(session::MachineLink &link, const machine::MachineConfig &config,
                    QWidget *parent = nullptr);
    ~HeightMapDialog() override;

    // Work coordinates = machine - workZero (the active system and G92).
    void setWorkZero(const session::Axes4 &workZeroMm);
    // The loaded program's cut area in machine mm (session::cutArea), or none.
    void setProgramArea(std::optional<std::array<double, 4>> machineArea);
    // Whether the window's program is bent to a map now (Apply / Remove enabled accordingly).
    void setApplied(bool applied);
    // Fills the area from the program's (work coordinates).
    void useProgramArea();

    // Starts probing with the values in the dialog; false (and the error shown) when it cannot.
    bool probe();
    void cancelProbe();
    bool isProbing() const;
    const std::optional<gcode::HeightMap> &map() const { return m_map; }
    void setMap(const gcode::HeightMap &map);
    // Per node of map() (j * countX + i): probed yet (all when not probing).
    std::vector<bool> probedNodes() const;
    bool saveTo(const QString &path);   // the map file; false with the error shown
    bool loadFrom(const QString &path); // reads a map file into the dialog
    QString statusText() const;
    QString errorText() const;
    QTableWidget *table() const { return m_table; }
    // Whether Apply also sets the work's Z zero on the surface at the map's first node.
    bool zeroAtReference() const;

signals:
    void applyRequested(const frezka::gcode::HeightMap &map, bool zeroAtReference);
    void removeRequested();
    // map() or probedNodes() changed: a point probed, probing started or ended, a map loaded.
    void mapChanged();
    void probingFinished(bool ok);

protected:
    void changeEvent(QEvent *event) override;

private:
    void buildForm();
    void connectButtons();
    void retranslate();
    void showMap();
    void showError(const QString &text);
    void updateButtons();
    void onPointProbed(int i, int j, int done, int total);
    void onFinished(bool ok);
    session::HeightProbeSettings settings() const;

    session::MachineLink &m_link;
    machine::MachineConfig m_config;
    std::unique_ptr<session::HeightProbe> m_probe;
    session::Axes4 m_workZero{};
    std::optional<std::array<double, 4>> m_programArea;
    std::optional<gcode::HeightMap> m_map;
    bool m_applied = false;
    std::array<QDoubleSpinBox *, 4> m_area{};
    QDoubleSpinBox *m_spacing, *m_clearance, *m_depth, *m_feed;
    std::array<QLabel *, 8> m_labels{};
    QPushButton *m_fromProgram, *m_probeButton, *m_cancel, *m_save, *m_load, *m_apply, *m_remove;
    QCheckBox *m_zeroAtReference;
    QProgressBar *m_progress;
    QLabel *m_status, *m_error, *m_range;
    QTableWidget *m_table;
};

} // namespace frezka::gui
