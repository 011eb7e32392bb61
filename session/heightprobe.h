#pragma once
// HeightProbe: probing a height map on the machine (issue 19 item 3), one sequence for the CLI
// (frezka-cli probe-grid) and the GUI (the Height map dialog), over a MachineLink.
//
// The grid covers the area with nodes no further apart than the spacing asked for (its edges
// on the area's edges). The nodes are probed in serpentine order (row 0 left to right, row 1
// right to left, ...), each as one small job planned from where the machine stands:
//
//   G0 Z<clearance>   G0 X<node> Y<node>   G38.2 Z<bottom> F<feed>
//
// so the driver's probe move gives G38.2's semantics: the probe input is read before the move
// and a probe already in contact refuses to move; the unit stops where the input trips; a
// probe that reaches the bottom without tripping fails the job. The trip point's Z (machine mm)
// goes into the map, relative to the first node's (the map's reference_z_mm). After the last
// node, after a failure and after cancel() the tool goes back up to the clearance (a Z move
// alone), unless the link is gone. Every failure names the node (X, Y) and what to do. A turning
// spindle (MachineState::spindleOn) refuses to start, and one switched on while probing ends it
// before the next probe move (the tool goes back up): a probe or a tool-length sensor touched by
// a turning tool breaks.

#include "session/machinelink.h"
#include "session/workoffsets.h"

#include "gcode/heightmap.h"
#include "gcode/toolpath.h"
#include "machine/machineconfig.h"

#include <QObject>
#include <QString>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace frezka::session {

struct HeightProbeSettings
{
    double x0Mm = 0, y0Mm = 0, x1Mm = 0, y1Mm = 0; // the area, machine mm (x0 < x1, y0 < y1)
    double spacingMm = 10;                         // nodes at most this far apart
    double clearanceZMm = 0;                       // machine Z of the moves between nodes
    double bottomZMm = 0; // machine Z the probe may go down to (below the clearance)
    double feedMmPerMin = 100;
    // Fast then slow (G38.2 twice): when above 0, each point found at feedMmPerMin is probed
    // again at this feed from retractMm above its trip point; the slow trip is the result.
    double slowFeedMmPerMin = 0;
    double retractMm = 0; // the back-off before the slow probe; see also startAt()
    // startAt(): back up to the clearance at the end instead of retractMm above the trip point
    // (a tool-length sensor: the tool leaves it at the travel height).
    bool pointEndsAtClearance = false;
    // startEdge(): how far along the axis the probe may move from where the tool stands, and a
    // move along the other of X/Y before it (back after; an outside corner's second face).
    double travelMm = 0;
    double reachMm = 0;
    friend bool operator==(const HeightProbeSettings &, const HeightProbeSettings &) = default;
};

// The grid for the settings (every height 0, the probing recorded), or nullopt and *error (in
// the user's language, naming the value and what to do).
std::optional<gcode::HeightMap> heightProbeGrid(const HeightProbeSettings &settings,
                                                QString *error);
// The offsets with the active system's Z set so that the work's top is Z 0 when a touch plate
// plateMm thick on it tripped the probe at machine Z tripZMm (the plate's top is Z plateMm;
// G92 stays as it is, as G10 L20 does).
OffsetState touchPlateZero(const OffsetState &offsets, double tripZMm, double plateMm);
// The offsets with the active system's X (axis 0) or Y (axis 1) set so that an edge is at 0:
// the probe moving in direction (+1 / -1) tripped at machine tripMm, so the edge is the tool's
// radius beyond the trip point (G92 stays as it is, as G10 L20 does).
OffsetState edgeZero(const OffsetState &offsets, int axis, int direction, double tripMm,
                     double toolDiameterMm);
// The nodes (i, j) of a countX x countY grid in serpentine order.
std::vector<std::pair<int, int>> serpentineOrder(int countX, int countY);
// X0, Y0, X1, Y1 (machine mm) of the program's cuts (what a height map must cover: its feed
// moves and arcs, chorded); nullopt when it cuts nothing.
std::optional<std::array<double, 4>> cutArea(const gcode::Toolpath &path);

class HeightProbe : public QObject
{
    Q_OBJECT

public:
    HeightProbe(MachineLink &link, const machine::MachineConfig &config, QObject *parent = nullptr);

    // Starts probing the grid; the link must be connected and idle. False (and error()) when
    // it cannot start; otherwise finished() follows once.
    bool start(const HeightProbeSettings &settings);
    // Probes one point (X, Y machine mm; the area and spacing of the settings unused), e.g. a
    // touch plate under the tool: map() is then a 2 x 2 grid whose node (0, 0) is the point and
    // pointZMm() its trip Z. At the end the tool goes up to retractMm above the trip point (the
    // clearance when retractMm is 0).
    bool startAt(double xMm, double yMm, const HeightProbeSettings &settings);
    // Probes an edge (issue 19 item 2): from where the tool stands, G38.2 along X (axis 0) or Y
    // (axis 1) in direction +1 or -1 at the feed, at most settings.travelMm; fast then slow as
    // above (the back-off along the axis); then back to the start along the axis. The clearance,
    // bottom, area and spacing are unused. pointZMm() is then the trip's machine coordinate on
    // the axis. A probe that reaches the travel without touching is an error, as for Z.
    bool startEdge(int axis, int direction, const HeightProbeSettings &settings);
    // Machine Z of the first point's trip (nullopt before it tripped).
    std::optional<double> pointZMm() const
    {
        return m_zMm.empty() ? std::nullopt : std::optional<double>(m_zMm.front());
    }
    // Stops the motion (the job aborted), then the tool goes up to the clearance; finished(false).
    void cancel();
    bool running() const { return m_phase != Phase::Idle; }
    // The map so far: the nodes probed have their heights (relative to the first node).
    const gcode::HeightMap &map() const { return m_map; }
    int pointsDone() const { return m_done; }
    int pointsTotal() const { return static_cast<int>(m_order.size()); }
    QString error() const { return m_error; }

signals:
    // Node (i, j) touched at machine Z zMm; done of total nodes probed.
    void pointProbed(int i, int j, double zMm, int done, int total);
    void finished(bool ok);

private:
    enum class Phase : std::uint8_t { Idle, Probing, Stopping, Retracting };

    void onState(const driver::MachineState &state);
    void onJobFinished(bool ok);
    void onError(const driver::MachineError &error);
    void settle(const driver::MachineState &state);
    bool begin(const HeightProbeSettings &settings, const gcode::HeightMap &grid, bool point);
    bool startPoint(double xMm, double yMm, const HeightProbeSettings &settings, int axis,
                    int direction);
    void probeNext();
    void probeSlow(double tripZMm);
    bool runText(const QString &text);
    void fail(const QString &why);
    void retract();
    void finish();
    static QString spindleTurningText();
    bool spindleStopsProbing();
    QString nodeText(std::size_t index) const;
    QString notTrippedText(std::size_t index) const;
    double edgeEndMm() const { return m_edgeStartMm + m_direction * m_settings.travelMm; }

    MachineLink &m_link;
    machine::MachineConfig m_config;
    HeightProbeSettings m_settings;
    gcode::HeightMap m_map;
    std::vector<std::pair<int, int>> m_order;
    std::vector<double> m_zMm; // machine Z of the nodes probed, in m_order's order
    int m_done = 0;
    bool m_slowPass = false;   // the current job is a node's slow probe
    bool m_point = false;      // startAt(): one point, the retract above its trip
    int m_axis = 2;            // the axis probed: Z, or X / Y for startEdge()
    int m_direction = -1;      // of the probe move along m_axis
    double m_edgeStartMm = 0;  // startEdge(): where the tool stood on m_axis
    double m_otherStartMm = 0; // ... and on the other of X / Y
    Phase m_phase = Phase::Idle;
    std::optional<bool> m_jobEnded; // the current job's jobFinished(ok), until settled
    bool m_jobStarted = false;      // a state showed the current job active
    bool m_waitedForError = false;  // the failed job's end waits one event for its error
    bool m_failed = false;
    QString m_error;
    QString m_lastLinkError; // the link's last error during the current job, translated
    driver::DriverCode m_lastLinkCode = driver::DriverCode::None;
};

} // namespace frezka::session
