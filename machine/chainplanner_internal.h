#pragma once
// Internal to frezka_machine: the chain planner of one run of moves (RunPlanner), in three parts:
// chainplanner.cpp (the run, the figures derived from each move, the integer passes and the
// bound), chaincaps.cpp (the vertex caps and the plan's vertex statistics) and chainpace.cpp
// (the link's pace); and the vector arithmetic they share (docs/planner.md §3-§5).

#include "machine/chainparts.h"
#include "machine/chainplanner.h"

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace frezka::machine::detail {

double dot(const Vec4 &a, const Vec4 &b);
// v scaled to length 1 (all zero stays all zero).
Vec4 normalized(const Vec4 &v);

// The directions of one move: as the unit moves it (its step vector) and as the program meant it
// (the unrounded segment), with their lengths.
struct Directions
{
    Vec4 uStep{}; // axis mm (°) per path mm of the step vector: what the unit really does
    Vec4 uPath{}; // unit direction of the intended segment (corner geometry)
    double lengthMm = 0;
    double pathLengthMm = 0;
};

// The link time of the B, V and A commands the last plan sent before each move (RunPlanner's
// m_extraS): sums of a few commands' times, so few distinct values. Each is kept once with a
// 16-bit index a move (2 bytes a move, not 8: issue 17); past 65 535 distinct values (a bound no
// link reaches: the values follow the commands' byte counts) a double a move. Reads back exactly
// the value set (equal bits).
class ExtraTimes
{
public:
    void assign(std::size_t n)
    {
        *this = ExtraTimes{};
        m_code.assign(n, 0);
    }
    std::size_t size() const { return m_full.empty() ? m_code.size() : m_full.size(); }
    double operator[](std::size_t k) const
    {
        return m_full.empty() ? m_values[m_code[k]] : m_full[k];
    }
    void set(std::size_t k, double s)
    {
        if (!m_full.empty()) {
            m_full[k] = s;
            return;
        }
        const auto bits = std::bit_cast<std::uint64_t>(s);
        if (bits != m_lastBits) { // consecutive moves mostly repeat a value: no look-up then
            auto found = m_index.find(bits);
            if (found == m_index.end()) {
                if (m_values.size() > std::numeric_limits<std::uint16_t>::max()) {
                    widen();
                    m_full[k] = s;
                    return;
                }
                found = m_index.emplace(bits, static_cast<std::uint16_t>(m_values.size())).first;
                m_values.push_back(s);
            }
            m_lastBits = bits;
            m_lastCode = found->second;
        }
        m_code[k] = m_lastCode;
    }

private:
    void widen()
    {
        m_full.resize(m_code.size());
        for (std::size_t k = 0; k < m_code.size(); ++k)
            m_full[k] = m_values[m_code[k]];
        m_code = {};
    }

    std::vector<std::uint16_t> m_code;
    std::vector<double> m_values{0.0};                                // code 0: no command
    std::unordered_map<std::uint64_t, std::uint16_t> m_index{{0, 0}}; // a value's bits -> code
    std::uint64_t m_lastBits = 0;
    std::uint16_t m_lastCode = 0;
    std::vector<double> m_full; // past 65 535 values: each move's own
};

class RunPlanner
{
public:
    RunPlanner(const Moves &moves, const MachineConfig &config, const PlanOptions &options, bool vk)
        : m_moves(moves)
        , m_config(config)
        , m_options(options)
        , m_link(config, options)
        , m_vk(vk)
    {}

    // Plans the run (chainplanner.cpp).
    RunOutcome run();

private:
    static constexpr int kWirePasses = 5;          // plans again at most this often
    static constexpr std::size_t kFlatWindow = 8;  // capVertices: vertices either side
    static constexpr std::size_t kWidestRing = 64; // derive: the wire window's candidates

    // chainplanner.cpp
    void planOnce();
    bool sentFits(const std::vector<double> &sent) const;
    void derive();
    Directions directions(const Move &m) const;
    void deriveOne(const Move &m, const MoveModes &modes, const Directions &dir, Derived &r);
    void chain(std::size_t first, std::size_t last);
    void fullPasses(std::size_t first, std::vector<std::int32_t> &b);
    void outputVector(const Derived &r, std::int32_t brake, bool chainEnd);
    void windowedPasses(std::size_t first, std::vector<std::int32_t> &b) const;
    void bound();

    // chaincaps.cpp
    void pathCaps(std::size_t k, const Vec4 &u0, const Vec4 &u1, double chordMm, double &jd,
                  double &curv) const;
    // Per-axis speed step at the vertex after move k (a, b: the directions of moves k and k+1),
    // per unit of the scalar speed there; here, inline, for its four calls a vertex.
    double jumpPerUnit(std::size_t k, const Directions &a, const Directions &b, int i) const
    {
        return std::abs(a.uStep[i] / m_d[k].f - b.uStep[i] / m_d[k + 1].f);
    }
    void vertexGeometry(std::size_t k, const Directions &a, const Directions &b);
    double boundCap(std::size_t k) const;
    bool softStopAllowed(std::size_t k) const { return m_softStop[k]; }
    void jumpStats();
    void curveStats(std::size_t k, const Directions &a, const Directions &b, double brake);

    // chainpace.cpp
    void wirePace();
    void sharePacedSpeeds(const std::vector<bool> &lowered);
    void paceModalChanges();
    double slowStretch(std::size_t first, std::size_t last, double missingS);
    double fromRestS(double cruiseS, std::size_t first, std::size_t last) const;
    std::size_t stretchEnd(std::size_t k) const;
    double mergeCostS(std::size_t first, std::size_t k, double limitS) const;
    void mergeStretches(std::size_t first, std::size_t k);
    std::int32_t vertexCap(std::size_t k) const;
    void capVertices();
    void restart(std::size_t k);

    const Moves &m_moves;
    const MachineConfig &m_config;
    const PlanOptions &m_options;
    LinkTiming m_link;
    bool m_vk;
    std::vector<Derived> m_d;
    // What the link's pace and the modal choices of a plan change in m_d, as derive() left it:
    // each plan starts again from this (no plan changes the rest of m_d). 16 bytes a move
    // instead of a second copy of m_d (176 before issue 17): derive() leaves every wireCap
    // infinite (only the pace sets it), and twoAU follows from accel (setAccel), so neither is
    // kept; V and A fit 32 bits (the pulse rate, kMaxAccel).
    struct PaceStart
    {
        double vMm;
        std::int32_t speed;
        std::int32_t accel;
    };
    std::vector<PaceStart> m_paceStart;
    std::vector<std::uint32_t> m_slowLines; // derive(): lines below the unit's slowest speed
    FeedCap m_firstFeedCap;                 // derive(): the first move whose feed is capped
    std::size_t m_feedCapLines = 0;         // ... and how many lines are
    std::uint32_t m_lastCappedLine = 0;
    // What no plan of the run changes, derived once (derive()) instead of in each of up to six
    // plans (docs/planner.md §4, "The link's pace"): per vertex after move k, the caps that
    // follow from the directions alone (junction deviation, curvature, the axes' speed steps)
    // on the scalar speed, as the bound takes them (m_geoCap) and, where the strategy takes
    // others (grbl's own), as the plan does (m_planGeoCap, else empty); whether the vertex can be
    // passed at the unit's smallest speed (and per move its window's widest vector on the wire,
    // Derived::widestBytes); whether the program stops after each move (m_stopAfter).
    std::vector<double> m_geoCap;
    std::vector<double> m_planGeoCap;
    std::vector<bool> m_softStop;
    std::vector<bool> m_stopAfter; // Move::stopAfter: no pass reads the moves themselves
    ExtraTimes m_extraS;           // link time of the B, V, A commands before move k (last plan)
    // B cap at the end of move k, speed units: at most the unit's pulse rate (32 bits: 4 bytes a
    // move less at the plan's peak, as the chain's speeds in m_scratchUnits).
    std::vector<std::int32_t> m_capUnits;
    // Room one pass at a time uses (wirePace's and paceModalChanges' prefix sums, the caps
    // before flattening, a chain's speeds), kept from plan to plan: a run of millions of moves
    // otherwise maps, faults in and returns the same megabytes in every pass of every plan.
    std::vector<double> m_scratch;
    std::vector<std::int32_t> m_scratchUnits;
    RunOutcome m_out;
};

} // namespace frezka::machine::detail
