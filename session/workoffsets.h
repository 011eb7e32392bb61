#pragma once
// WorkOffsets: the operator's coordinate systems, one set for the whole application. It holds
// the nine work offsets G54..G59.3 (machine mm, X Y Z A), the G92 offset added to all of them,
// and which system is active; it turns machine positions into work positions (machine minus
// active offset minus G92), sets a work zero at a machine position, and persists everything in
// QSettings. The first six systems stay under the key "workOffsets" (24 values, as before the
// session layer existed, so saved offsets survive), G59.1..G59.3 under "workOffsetsExtra",
// G92 under "g92Offset", the active system under "activeOffset". changed() follows every edit.

#include <QObject>

#include <array>

namespace frezka::session {

inline constexpr int kWorkSystems = 9; // G54 G55 G56 G57 G58 G59 G59.1 G59.2 G59.3
using Axes4 = std::array<double, 4>;
using OffsetTable = std::array<Axes4, kWorkSystems>;

// The offsets as the interpreter takes them (a value: copied into each interpretation).
struct OffsetState
{
    OffsetTable systems{};
    Axes4 g92{};
    int active = 0; // 0 = G54 .. 8 = G59.3
    // The offset a program coordinate is measured from on each axis (active system + G92).
    Axes4 total() const;
    Axes4 workPosition(const Axes4 &machineMm) const;
    friend bool operator==(const OffsetState &, const OffsetState &) = default;
};

// "G54" .. "G59", "G59.1" .. "G59.3".
QString workSystemName(int index);

class WorkOffsets : public QObject
{
    Q_OBJECT

public:
    explicit WorkOffsets(QObject *parent = nullptr);

    const OffsetState &state() const { return m_state; }
    const OffsetTable &systems() const { return m_state.systems; }
    const Axes4 &g92() const { return m_state.g92; }
    int active() const { return m_state.active; }
    Axes4 workPosition(const Axes4 &machineMm) const { return m_state.workPosition(machineMm); }

    // Reads the saved offsets (missing keys leave zero) / writes them.
    void load();
    void save() const;

    void select(int index); // clamped to 0..8
    // Sets the active system so that the work position of `axis` (-1: all four) is zero at
    // the machine position (G92 stays as it is, as LinuxCNC's G10 L20 does).
    void setZero(int axis, const Axes4 &machineMm);
    void setSystem(int index, const Axes4 &offsetMm);
    void setG92(const Axes4 &offsetMm);
    // Replaces everything at once (the console's G10 / G92 read back from the interpreter).
    void setState(const OffsetState &state);

signals:
    void changed();

private:
    void commit(const OffsetState &next);

    OffsetState m_state;
};

} // namespace frezka::session
