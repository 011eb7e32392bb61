// Emulator throughput. Not run by ctest: build the target and run it, figures go to stdout.
//   cmake --build build --target emulator_bench && build/tests/bench/emulator/emulator_bench
//
// 1. Unit direct (what the planner benchmark does): 10^6 continuous vectors pushed into a
//    GVE114 as fast as its queue takes them, the clock advanced event by event.
// 2. Simulation (unit + wire model, 115 200 Bd, 4 ms USB latency each way, checksums on):
//    short vectors streamed one per request, or in packets of 10 and 40, request/response.

#include "driver/emulator/simulation.h"
#include "protocol/checksum.h"

#include <chrono>
#include <cstdio>
#include <string>

using namespace frezka::emulator;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point since)
{
    return std::chrono::duration<double>(Clock::now() - since).count();
}

std::string withChecksum(const std::string &command)
{
    const std::string text = command + ",";
    return text + frezka::protocol::hexByte(frezka::protocol::checksum(text)) + "\r";
}

void unitDirect(int vectors)
{
    UnitOptions o;
    o.variant = frezka::protocol::Variant::Gve114;
    o.maxPulseRate = 500000;
    Unit unit(o);
    unit.receive("!0Y-\r!0V100000\r!0A2000\r!0B40000\r!0$10\r");
    unit.takeTransmit();
    const auto start = Clock::now();
    long long sx = 0, sy = 0;
    char cmd[64];
    for (int sent = 0; sent < vectors;) {
        const int dx = 97 + sent % 7, dy = 30 - sent % 5;
        std::snprintf(cmd, sizeof cmd, "!0C%d,%d,0\r", dx, dy);
        unit.receive(cmd);
        if (unit.takeTransmit() == "0\r") {
            ++sent;
            sx += dx;
            sy += dy;
        } else {
            unit.advance(unit.nextEventIn()); // queue full: run to the next vector end
        }
    }
    while (unit.nextEventIn() < kNever)
        unit.advance(unit.nextEventIn());
    const double wall = seconds(start);
    const Stats s = unit.stats();
    std::printf("unit direct: %d vectors in %.2f s wall = %.0f vectors/s; %.1f s of machine "
                "time; exact end position: %s; brake violations %lld, starvation stops %lld\n",
                vectors, wall, vectors / wall, unit.now(),
                unit.position()[0] == sx && unit.position()[1] == sy ? "yes" : "NO",
                static_cast<long long>(s.motion.brakeViolations),
                static_cast<long long>(s.motion.starvationStops));
}

// Streams `count` short vectors (20 steps: ~1 ms of motion each, faster than the link can
// carry them) `perPacket` at a time (1 = one command per round trip, no packet).
void simulationStream(int count, int perPacket)
{
    SimulationOptions o;
    o.unit.variant = frezka::protocol::Variant::Gve64;
    o.wire.baud = 115200;
    o.wire.latencyPcToUnitS = o.wire.latencyUnitToPcS = 0.004;
    Simulation sim(o);
    sim.unit().receive("!0Y-\r!0V20000\r!0A500\r!0B20000\r!0$10\r!0%+\r");
    sim.unit().takeTransmit();
    const auto start = Clock::now();
    int accepted = 0;
    while (accepted < count) {
        std::string bytes;
        if (perPacket > 1) {
            bytes = withChecksum("!0*S");
            for (int i = 0; i < perPacket; ++i)
                bytes += withChecksum("!0C20,3,0");
            bytes += withChecksum("!0*E" + std::to_string(perPacket));
        } else {
            bytes = withChecksum("!0C20,3,0");
        }
        sim.pcWrite(bytes);
        const std::string reply = sim.pcReadLine(1.0);
        accepted += perPacket > 1 ? std::stoi(reply.substr(reply.find(',') + 1)) : reply[0] == '0';
    }
    while (sim.nextEventIn() < kNever)
        sim.advance(sim.nextEventIn());
    const double wall = seconds(start);
    const Stats s = sim.unit().stats();
    std::printf("simulation, %2d vector(s) per request: %d vectors in %.1f s of machine time = "
                "%.0f vectors/s, %lld starvation stops; %.2f s wall\n",
                perPacket, count, sim.now(), count / sim.now(),
                static_cast<long long>(s.motion.starvationStops), wall);
}

} // namespace

int main()
{
    unitDirect(1000000);
    simulationStream(20000, 1);
    simulationStream(20000, 10);
    simulationStream(20000, 40);
    return 0;
}
