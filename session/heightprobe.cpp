// HeightProbe: the grid probed node by node, each a small planned job. See heightprobe.h.

#include "heightprobe.h"

#include "session/programplanner.h"
#include "session/runworkflow.h"

#include "machine/steps.h"

#include <algorithm>
#include <cmath>

namespace frezka::session {

namespace {

constexpr int kMaxNodes = 10000; // 100 x 100: hours of probing; more is a typo in the spacing

QString mm(double v)
{
    return QString::number(v, 'f', 3);
}

// A number in a G-code word ('.' as the decimal point, enough digits for a step).
QString word(double v)
{
    return QString::number(v, 'f', 4);
}

int nodesFor(double lengthMm, double spacingMm)
{
    return std::max(2, static_cast<int>(std::ceil(lengthMm / spacingMm - 1e-9)) + 1);
}

} // namespace

std::optional<gcode::HeightMap> heightProbeGrid(const HeightProbeSettings &s, QString *error)
{
    auto bad = [&](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (!(s.x1Mm > s.x0Mm) || !(s.y1Mm > s.y0Mm))
        return bad(HeightProbe::tr("The area to probe is empty (X %1 to %2, Y %3 to %4): give "
                                   "its corners with X0 < X1 and Y0 < Y1.")
                       .arg(mm(s.x0Mm), mm(s.x1Mm), mm(s.y0Mm), mm(s.y1Mm)));
    if (!(s.spacingMm > 0))
        return bad(HeightProbe::tr("The spacing of the grid must be above 0 mm (%1 given).")
                       .arg(mm(s.spacingMm)));
    if (!(s.feedMmPerMin > 0))
        return bad(HeightProbe::tr("The probing feed must be above 0 mm/min (%1 given).")
                       .arg(mm(s.feedMmPerMin)));
    if (!(s.clearanceZMm > s.bottomZMm))
        return bad(HeightProbe::tr("The probe's lowest Z (%1) must be below the clearance "
                                   "height (%2): give a depth above 0 mm.")
                       .arg(mm(s.bottomZMm), mm(s.clearanceZMm)));
    const int nx = nodesFor(s.x1Mm - s.x0Mm, s.spacingMm);
    const int ny = nodesFor(s.y1Mm - s.y0Mm, s.spacingMm);
    if (static_cast<long long>(nx) * ny > kMaxNodes)
        return bad(HeightProbe::tr("A spacing of %1 mm gives %2 x %3 points to probe (at most "
                                   "%4): choose a larger spacing or a smaller area.")
                       .arg(mm(s.spacingMm))
                       .arg(nx)
                       .arg(ny)
                       .arg(kMaxNodes));
    gcode::HeightMap map(s.x0Mm, s.y0Mm, (s.x1Mm - s.x0Mm) / (nx - 1), (s.y1Mm - s.y0Mm) / (ny - 1),
                         nx, ny);
    gcode::HeightMapProbing probing;
    probing.feedMmPerMin = s.feedMmPerMin;
    map.setProbing(probing);
    return map;
}

OffsetState touchPlateZero(const OffsetState &offsets, double tripZMm, double plateMm)
{
    OffsetState next = offsets;
    const auto active = static_cast<std::size_t>(std::clamp(offsets.active, 0, kWorkSystems - 1));
    next.systems[active][2] = tripZMm - plateMm - offsets.g92[2];
    return next;
}

OffsetState edgeZero(const OffsetState &offsets, int axis, int direction, double tripMm,
                     double toolDiameterMm)
{
    OffsetState next = offsets;
    const auto active = static_cast<std::size_t>(std::clamp(offsets.active, 0, kWorkSystems - 1));
    const auto a = static_cast<std::size_t>(std::clamp(axis, 0, 1));
    next.systems[active][a] = tripMm + direction * toolDiameterMm / 2 - offsets.g92[a];
    return next;
}

std::vector<std::pair<int, int>> serpentineOrder(int countX, int countY)
{
    std::vector<std::pair<int, int>> order;
    for (int j = 0; j < countY; ++j)
        for (int k = 0; k < countX; ++k)
            order.emplace_back(j % 2 == 0 ? k : countX - 1 - k, j);
    return order;
}

std::optional<std::array<double, 4>> cutArea(const gcode::Toolpath &path)
{
    std::optional<std::array<double, 4>> box;
    auto add = [&](const gcode::Point4 &p) {
        if (!box)
            box = std::array<double, 4>{p.x, p.y, p.x, p.y};
        auto &b = *box;
        b = {std::min(b[0], p.x), std::min(b[1], p.y), std::max(b[2], p.x), std::max(b[3], p.y)};
    };
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path.kind(i) == gcode::MotionKind::Feed) {
            add(path.start(i));
            add(path.end(i));
        } else if (path.kind(i) == gcode::MotionKind::Arc) {
            add(path.start(i));
            for (const gcode::Point4 &p : gcode::chordArc(path.start(i), path.end(i), path.arc(i)))
                add(p);
        }
    }
    return box;
}

HeightProbe::HeightProbe(MachineLink &link, const machine::MachineConfig &config, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_config(config)
{
    connect(&m_link, &MachineLink::stateChanged, this, &HeightProbe::onState);
    connect(&m_link, &MachineLink::jobFinished, this, &HeightProbe::onJobFinished);
    connect(&m_link, &MachineLink::errorOccurred, this, &HeightProbe::onError);
}

bool HeightProbe::start(const HeightProbeSettings &settings)
{
    m_error.clear();
    std::optional<gcode::HeightMap> grid = heightProbeGrid(settings, &m_error);
    if (!grid)
        return false;
    m_axis = 2;
    return begin(settings, *grid, false);
}

bool HeightProbe::startAt(double xMm, double yMm, const HeightProbeSettings &settings)
{
    return startPoint(xMm, yMm, settings, 2, -1);
}

bool HeightProbe::startPoint(double xMm, double yMm, const HeightProbeSettings &settings, int axis,
                             int direction)
{
    m_error.clear();
    HeightProbeSettings s = settings; // the grid's checks on a 1 mm square at the point
    s.x0Mm = xMm;
    s.y0Mm = yMm;
    s.x1Mm = xMm + 1;
    s.y1Mm = yMm + 1;
    s.spacingMm = 1;
    std::optional<gcode::HeightMap> grid = heightProbeGrid(s, &m_error);
    if (!grid || running()) // begin() says why when running
        return grid && begin(s, *grid, true);
    m_axis = axis;
    m_direction = direction;
    m_edgeStartMm = m_link.state().positionMm[static_cast<std::size_t>(axis)];
    m_otherStartMm = m_link.state().positionMm[axis == 0 ? 1 : 0];
    return begin(s, *grid, true);
}

bool HeightProbe::startEdge(int axis, int direction, const HeightProbeSettings &settings)
{
    m_error.clear();
    if ((axis != 0 && axis != 1) || (direction != 1 && direction != -1)) {
        m_error = tr("An edge is probed along X or Y, in the + or - direction.");
        return false;
    }
    if (!(settings.travelMm > 0)) {
        m_error = tr("The probe's travel toward the edge must be above 0 mm (%1 given).")
                      .arg(mm(settings.travelMm));
        return false;
    }
    const driver::MachineState &at = m_link.state();
    HeightProbeSettings s = settings; // the point's checks; the bottom is unused for an edge
    s.clearanceZMm = at.positionMm[2] + 1;
    s.bottomZMm = at.positionMm[2];
    return startPoint(at.positionMm[0], at.positionMm[1], s, axis, direction);
}

bool HeightProbe::begin(const HeightProbeSettings &settings, const gcode::HeightMap &grid,
                        bool point)
{
    if (running()) {
        m_error = tr("Probing is already running.");
        return false;
    }
    if (m_link.state().mode != driver::MachineMode::Idle) {
        m_error = tr("The machine is not ready to probe (%1): connect it and wait until it is "
                     "idle, then probe again.")
                      .arg(RunWorkflow::modeText(m_link.state().mode));
        return false;
    }
    if (m_link.state().spindleOn) {
        m_error = spindleTurningText();
        return false;
    }
    if (settings.slowFeedMmPerMin > 0 && !(settings.retractMm > 0)) {
        m_error = tr("Probing fast then slow needs a retract above 0 mm (%1 given): the tool "
                     "backs off by it before the slow probe.")
                      .arg(mm(settings.retractMm));
        return false;
    }
    m_point = point;
    m_settings = settings;
    m_map = grid;
    m_order = serpentineOrder(m_map.countX(), m_map.countY());
    if (m_point)
        m_order.resize(1);
    m_zMm.clear();
    m_done = 0;
    m_failed = false;
    m_slowPass = false;
    m_jobEnded.reset();
    probeNext();
    return true;
}

void HeightProbe::cancel()
{
    if (m_phase != Phase::Probing)
        return;
    m_failed = true;
    m_error = tr("Probing cancelled after %1 of %2 points; the tool goes up to the clearance.")
                  .arg(m_done)
                  .arg(pointsTotal());
    m_phase = Phase::Stopping;
    m_jobEnded.reset();
    m_link.abort();
}

QString HeightProbe::spindleTurningText()
{
    return tr("The spindle is turning: stop it (M5 or the spindle button) before probing. A "
              "probe or a sensor touched by a turning tool breaks one of them.");
}

// Before each probe move: a spindle switched on while probing (the operator's button) ends the
// probing before the tool goes down, and the tool goes back up.
bool HeightProbe::spindleStopsProbing()
{
    if (!m_link.state().spindleOn)
        return false;
    fail(spindleTurningText());
    retract();
    return true;
}

QString HeightProbe::nodeText(std::size_t index) const
{
    const auto [i, j] = m_order[index];
    return tr("X %1, Y %2").arg(mm(m_map.nodeX(i)), mm(m_map.nodeY(j)));
}

// Up to the clearance first when below it, across, down to it when above it, then the probe:
// the tool never moves down except over the node.
void HeightProbe::probeNext()
{
    if (spindleStopsProbing())
        return;
    if (m_axis != 2) { // an edge: from where the tool stands (and the reach), along the axis
        m_phase = Phase::Probing;
        m_slowPass = false;
        QString text = QStringLiteral("G21 G90 G94\n");
        if (m_settings.reachMm != 0)
            text += QStringLiteral("G0 %1%2\n")
                        .arg(QChar(machine::kAxisLetters[m_axis == 0 ? 1 : 0]))
                        .arg(word(m_otherStartMm + m_settings.reachMm));
        text += QStringLiteral("G38.2 %1%2 F%3\n")
                    .arg(QChar(machine::kAxisLetters[std::size_t(m_axis)]))
                    .arg(word(edgeEndMm()), word(m_settings.feedMmPerMin));
        if (!runText(text)) {
            m_failed = true;
            finish();
        }
        return;
    }
    const auto [i, j] = m_order[static_cast<std::size_t>(m_done)];
    const double z = m_link.state().positionMm[2];
    const QString clearance = QStringLiteral("G0 Z%1\n").arg(word(m_settings.clearanceZMm));
    QString text = QStringLiteral("G21 G90 G94\n");
    if (z < m_settings.clearanceZMm)
        text += clearance;
    const driver::MachineState &at = m_link.state();
    const bool over =
        std::abs(at.positionMm[0] - m_map.nodeX(i)) < 0.5 / m_config.axes[0].stepsPerMm &&
        std::abs(at.positionMm[1] - m_map.nodeY(j)) < 0.5 / m_config.axes[1].stepsPerMm;
    if (!over) // a move of no length is no move (the touch plate under the tool)
        text += QStringLiteral("G0 X%1 Y%2\n").arg(word(m_map.nodeX(i)), word(m_map.nodeY(j)));
    if (z > m_settings.clearanceZMm)
        text += clearance;
    text += QStringLiteral("G38.2 Z%1 F%2\n")
                .arg(word(m_settings.bottomZMm), word(m_settings.feedMmPerMin));
    m_phase = Phase::Probing;
    m_slowPass = false;
    if (!runText(text)) {
        m_failed = true;
        finish();
    }
}

// The slow probe of the node just found: back off by the retract above the fast trip point
// (a Z move alone, never below the clearance's limit), then G38.2 at the slow feed.
void HeightProbe::probeSlow(double tripZMm)
{
    if (spindleStopsProbing())
        return;
    const QChar axis(machine::kAxisLetters[std::size_t(m_axis)]);
    const double back = tripZMm - m_direction * m_settings.retractMm;
    const double end = m_axis == 2 ? m_settings.bottomZMm : edgeEndMm();
    const QString text = QStringLiteral("G21 G90 G94\nG0 %1%2\nG38.2 %1%3 F%4\n")
                             .arg(axis)
                             .arg(word(back), word(end), word(m_settings.slowFeedMmPerMin));
    m_slowPass = true;
    if (!runText(text)) {
        m_failed = true;
        retract();
    }
}

// Interprets and plans text from the machine's position (machine coordinates: no offsets) and
// runs it; false (and m_error) when it cannot be planned.
bool HeightProbe::runText(const QString &text)
{
    InterpretRequest request;
    request.text = text.toUtf8();
    request.fileName = tr("probing");
    const driver::MachineState &s = m_link.state();
    request.startMm = s.positionMm;
    request.limits = m_config.program;
    request.splineToleranceMm = m_config.motion.chordToleranceMm;
    const InterpretOutcome interpreted = interpretProgram(request);
    PlanOutcome plan;
    if (interpreted.errors.empty() && interpreted.toolpath)
        plan = planProgram(*interpreted.toolpath, m_config, request.fileName);
    const auto &errors = interpreted.errors.empty() ? plan.errors : interpreted.errors;
    if (!plan.ok()) {
        m_error =
            tr("The move to probe at %1 cannot be planned: %2")
                .arg(nodeText(static_cast<std::size_t>(std::min<int>(m_done, pointsTotal() - 1))),
                     errors.empty() ? QString() : errors.front().text);
        return false;
    }
    m_jobEnded.reset();
    m_jobStarted = false;
    m_waitedForError = false;
    m_lastLinkError.clear();
    m_lastLinkCode = driver::DriverCode::None;
    m_link.run(*plan.program);
    return true;
}

void HeightProbe::onError(const driver::MachineError &error)
{
    m_lastLinkError = driver::translatedText(error.reason, true);
    m_lastLinkCode = error.reason.code;
    if (m_phase == Phase::Stopping && m_link.state().mode == driver::MachineMode::Idle) {
        retract(); // nothing to abort
        return;
    }
    if (m_phase != Phase::Probing && m_phase != Phase::Retracting)
        return;
    if (!m_jobEnded && !m_jobStarted) // a refused job never starts nor finishes: it failed
        m_jobEnded = false;
    if (m_jobEnded)
        settle(m_link.state());
}

void HeightProbe::onJobFinished(bool ok)
{
    if (m_phase == Phase::Stopping && m_link.state().mode == driver::MachineMode::Idle) {
        retract(); // nothing to abort
        return;
    }
    if (m_phase != Phase::Probing && m_phase != Phase::Retracting)
        return;
    m_jobEnded = ok;
    settle(m_link.state());
}

void HeightProbe::onState(const driver::MachineState &state)
{
    if (m_phase == Phase::Idle)
        return;
    if (state.jobActive)
        m_jobStarted = true;
    if (state.mode == driver::MachineMode::Disconnected ||
        state.mode == driver::MachineMode::LinkLost) {
        if (!m_failed)
            fail(tr("The link to the machine was lost while probing at %1: probe the grid "
                    "again once it is connected.")
                     .arg(nodeText(
                         static_cast<std::size_t>(std::min<int>(m_done, pointsTotal() - 1)))));
        finish();
        return;
    }
    if (m_phase == Phase::Stopping) {
        if (state.mode == driver::MachineMode::Idle)
            retract();
        return;
    }
    if (m_jobEnded)
        settle(state);
}

// The job's end once the machine stands (the state after jobFinished can lag it).
void HeightProbe::settle(const driver::MachineState &s)
{
    if (!m_jobEnded || s.mode == driver::MachineMode::Running ||
        s.mode == driver::MachineMode::Stopping || s.mode == driver::MachineMode::Connecting)
        return;
    // A job that failed: its error follows jobFinished (the driver ends the job, then fails).
    const bool errorKnown = m_lastLinkCode != driver::DriverCode::None ||
                            s.mode == driver::MachineMode::Alarm || m_waitedForError;
    if (!*m_jobEnded && !errorKnown) {
        m_waitedForError = true; // settled at the next state or error, whatever it says
        return;
    }
    m_waitedForError = false;
    const bool ok = *m_jobEnded;
    m_jobEnded.reset();
    if (m_phase == Phase::Retracting) {
        finish();
        return;
    }
    const std::size_t index = static_cast<std::size_t>(m_done);
    const auto [i, j] = m_order[index];
    // The trip point under the node (a step either way: the node's word is rounded to 0.1 um).
    auto near = [](std::int64_t a, std::int64_t b) { return std::abs(a - b) <= 1; };
    // The trip on the probed axis; on the others where the probe started (an edge probe's Z
    // is not checked: the start's Z is not a node's).
    const double reachX = m_axis == 1 ? m_settings.reachMm : 0;
    const double reachY = m_axis == 0 ? m_settings.reachMm : 0;
    const bool atNode =
        (m_axis == 0 || near(s.probeSteps[0], machine::stepsOf(m_map.nodeX(i) + reachX,
                                                               m_config.axes[0].stepsPerMm))) &&
        (m_axis == 1 || near(s.probeSteps[1], machine::stepsOf(m_map.nodeY(j) + reachY,
                                                               m_config.axes[1].stepsPerMm)));
    if (ok && s.probeTripped && atNode) {
        const auto a = static_cast<std::size_t>(m_axis);
        const double z = static_cast<double>(s.probeSteps[a]) / m_config.axes[a].stepsPerMm;
        if (m_settings.slowFeedMmPerMin > 0 && !m_slowPass) {
            probeSlow(z);
            return;
        }
        m_zMm.push_back(z);
        m_map.setZ(i, j, z - m_zMm.front());
        ++m_done;
        emit pointProbed(i, j, z, m_done, pointsTotal());
        if (m_done == pointsTotal())
            retract();
        else
            probeNext();
        return;
    }
    const auto code = m_lastLinkCode != driver::DriverCode::None ? m_lastLinkCode
                      : s.lastError                              ? s.lastError->reason.code
                                                                 : driver::DriverCode::None;
    if (code == driver::DriverCode::ProbeNotTripped)
        fail(notTrippedText(index));
    else if (code == driver::DriverCode::ProbeAlreadyTripped)
        fail(tr("The probe at %1 was already in contact before moving down: check the probe "
                "and its wiring, and that the tool is clear of the work.")
                 .arg(nodeText(index)));
    else
        fail(tr("Probing at %1 stopped: %2")
                 .arg(nodeText(index),
                      m_lastLinkError.isEmpty() ? tr("the job did not finish.") : m_lastLinkError));
    // The state delivered can still show the machine idle while the driver holds it in an
    // alarm: Abort clears either (refused when idle: then onError goes on with the retract).
    m_phase = Phase::Stopping;
    m_link.abort();
}

QString HeightProbe::notTrippedText(std::size_t index) const
{
    if (m_axis != 2)
        return tr("The probe moved from %1 %2 to %1 %3 without touching the edge: the edge is "
                  "farther than the travel, or the probe is not connected. Check the probe and "
                  "where the tool stands (beside the edge, below the work's top), or probe "
                  "again with a longer travel.")
            .arg(QChar(machine::kAxisLetters[std::size_t(m_axis)]))
            .arg(mm(m_edgeStartMm), mm(edgeEndMm()));
    return tr("The probe at %1 went down to Z %2 without touching the surface: the work is "
              "lower than the depth allows, or the probe is not connected. Check the probe "
              "and the clearance, or probe again with a larger depth.")
        .arg(nodeText(index), mm(m_settings.bottomZMm));
}

void HeightProbe::fail(const QString &why)
{
    m_failed = true;
    m_error = why;
}

// A Z move alone up to the clearance (startAt(): the retract above the trip point), when the
// tool is below it.
void HeightProbe::retract()
{
    m_phase = Phase::Retracting;
    if (m_axis != 2) { // an edge: back to the start along the axis, then the reach back
        QString text;
        const std::size_t axes[2] = {std::size_t(m_axis), std::size_t(m_axis == 0 ? 1 : 0)};
        const double starts[2] = {m_edgeStartMm, m_otherStartMm};
        for (int k = 0; k < 2; ++k) {
            const std::size_t a = axes[k];
            if (std::abs(m_link.state().positionMm[a] - starts[k]) >=
                0.5 / m_config.axes[a].stepsPerMm)
                text += QStringLiteral("G0 %1%2\n")
                            .arg(QChar(machine::kAxisLetters[a]))
                            .arg(word(starts[k]));
        }
        if (text.isEmpty() || !runText(QStringLiteral("G21 G90\n") + text))
            finish();
        return;
    }
    const double z = m_link.state().positionMm[2];
    const double tolerance = 0.5 / m_config.axes[2].stepsPerMm;
    const double top =
        m_point && m_settings.retractMm > 0 && !m_zMm.empty() && !m_settings.pointEndsAtClearance
            ? m_zMm.front() + m_settings.retractMm
            : m_settings.clearanceZMm;
    if (z >= top - tolerance || !runText(QStringLiteral("G21 G90\nG0 Z%1\n").arg(word(top))))
        finish();
}

void HeightProbe::finish()
{
    if (m_phase == Phase::Idle)
        return;
    m_phase = Phase::Idle;
    if (!m_zMm.empty()) {
        gcode::HeightMapProbing probing = m_map.probing();
        probing.referenceZMm = m_zMm.front();
        probing.clearanceMm = m_settings.clearanceZMm - probing.referenceZMm;
        probing.depthMm = probing.referenceZMm - m_settings.bottomZMm;
        m_map.setProbing(probing);
    }
    emit finished(!m_failed);
}

} // namespace frezka::session
