#pragma once
// LineSync: the sync points of the jobs of several units on one line (machine/rotarysplit.h,
// driver/link/synchold.h). Each unit's job says when it has reached a sync point; when every
// unit has reached it, all are released together (a held unit then gets its G on its next
// turn of the line). Counts, per unit, how often and how long it waited for the others.

#include "driver/link/machinecore.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace frezka::driver {

struct LineSyncUnitStats
{
    std::int64_t waits = 0; // sync points this unit reached before the last of the others
    double waitS = 0;       // time it stood there waiting for them
};

struct LineSyncStats
{
    std::int64_t released = 0; // sync points every unit passed
    std::vector<LineSyncUnitStats> units;
    std::vector<double> releasedAtS; // when each sync point was released
};

class LineSync
{
public:
    // Installs itself as each core's sync handler; the cores must outlive it.
    explicit LineSync(std::vector<MachineCore *> cores);
    ~LineSync();
    LineSync(const LineSync &) = delete;
    LineSync &operator=(const LineSync &) = delete;

    const LineSyncStats &stats() const { return m_stats; }

private:
    void reached(std::size_t unit, std::size_t index, double now);

    std::vector<MachineCore *> m_cores;
    std::vector<std::int64_t> m_reached; // per unit: the last sync point reached, -1 none
    std::vector<double> m_reachedAt;
    LineSyncStats m_stats;
};

} // namespace frezka::driver
