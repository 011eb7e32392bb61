#pragma once
// Internal to frezka_machine: the planner's walk over the toolpath (Planner), in three parts:
// planner.cpp (the walk, the soft limits, the moves and their emission), planevents.cpp (the
// program's events: dwells, spindle, outputs, stops) and planstats.cpp (the estimate, the bound
// and the feed-cap warning) (docs/planner.md).

#include "machine/chainplanner.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "machine/unitprogram.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace frezka::machine {
struct ModelResult;
}

namespace frezka::machine::detail {

// v with three decimals ("12.500"), for messages; "?" when it does not fit.
std::string fmt(double v);

class Planner
{
public:
    Planner(const gcode::Toolpath &toolpath, const MachineConfig &config,
            const PlanOptions &options)
        : m_path(toolpath)
        , m_config(config)
        , m_options(options)
    {}

    // Plans the toolpath (planner.cpp).
    PlanResult run();

private:
    // planner.cpp
    bool chooseVk() const;
    void error(PlanErrorCode code, std::uint32_t line, const std::string &what);
    void warning(std::uint32_t line, const std::string &what);
    void emit(UnitOp op, std::int64_t value, std::uint32_t line, std::int32_t aux = 0);
    bool checkPoint(const gcode::Point4 &p, std::uint32_t line);
    void motion(std::size_t i);
    void addPoint(const gcode::Point4 &p, bool rapid, double feedMmPerS, std::uint32_t line);
    void probe(std::size_t i, double feed);
    void setModal(UnitOp op, std::int64_t &current, std::int64_t value, std::uint32_t line);
    void flush();
    void reserveMoves(std::size_t i);
    void reserveCommands(const RunOutcome &run);
    static constexpr std::size_t kKeptMoves = 1 << 16; // flush(): moves kept for the next run

    // planevents.cpp
    void event(std::size_t i);
    void spindle(std::uint32_t line, bool on, double rpm);
    void outputs(std::uint32_t line, std::uint8_t clearBits, std::uint8_t setBits);
    void wait(std::uint32_t line, double seconds);

    // planstats.cpp
    void finishStats();
    void feedCapWarning();
    struct RestCosts
    {
        double linkS = 0;      // the link's part of the rests, beyond the unit's T pauses
        double unitPauseS = 0; // the unit's T pauses after them (what dwells did not cover)
        double boundLinkS = 0; // linkS at its least (the bound's): F's reply alone at each stop
    };
    // The link's part of each rest; `holds`: the chains the driver holds at their start and what
    // each hold costs the link (leadInHolds), by the chain's first command.
    RestCosts restCosts(std::span<const std::pair<std::size_t, double>> holds,
                        const ModelResult &model) const;
    std::vector<std::pair<std::size_t, double>> leadInHolds(const ModelResult &model) const;
    // restCosts: the bytes of one command and its reply (the position read), the replies to F
    // and to a command (with a checksum: 3 bytes fewer without), and a packet's *S *S *E.
    static constexpr double kExchangeBytes = 20;
    // The driver's poll interval and its packets' cap where the motion is slow (CoreOptions
    // pollIntervalS, slowPacketWireS): a free start's first packet is cut to keep polls.
    static constexpr double kStatusPollS = 0.05;
    static constexpr double kSlowPacketWireS = 0.1;
    static constexpr double kFlagReplyBytes = 8; // 0,40,EC CR
    static constexpr double kOkReplyBytes = 5;   // 0,5C CR
    static constexpr double kPacketFramingBytes = 24;

    const gcode::Toolpath &m_path;
    const MachineConfig &m_config;
    const PlanOptions &m_options;
    PlanResult m_result;
    bool m_vk = false;
    gcode::Point4 m_posMm; // intended position (mm) of the last vector's end
    Steps4 m_steps{};      // absolute steps after the last collected move
    Steps4 m_emitted{};    // absolute steps after the last emitted motion command
    Moves m_moves;
    std::size_t m_reservedTo = 0; // reserveMoves: the toolpath entry its last reserve reached
    bool m_exactStop = false;
    double m_jd = 0;
    std::int64_t m_accel = -1, m_speed = -1, m_brake = -1; // modal values sent, -1 = unknown
    bool m_spindleOn = false;
    std::int64_t m_spindlePermille = 0;
    std::uint8_t m_port0 = 0xFF; // outputs, active low: all off
    double m_bound = 0;
    double m_waitS = 0;
    FeedCap m_firstFeedCap; // the first move whose feed the axes cap
    std::size_t m_feedCapLines = 0;
};

} // namespace frezka::machine::detail
