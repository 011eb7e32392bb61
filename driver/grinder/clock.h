#pragma once
// Time source of the grinder sessions and the in-process emulator. RealClock runs on the Qt
// event loop; VirtualClock runs callbacks in time order when told to, so a 22 s transfer at
// 9600 Bd takes milliseconds in a test and nothing ever sleeps.

#include <QElapsedTimer>
#include <QHash>

#include <cstdint>
#include <functional>
#include <map>

class QTimer;

namespace frezka::grinder {

class Clock
{
public:
    using TimerId = std::uint64_t;
    virtual ~Clock() = default;
    // Microseconds since the clock started.
    virtual std::int64_t nowUs() const = 0;
    // Calls `callback` once, `delayUs` from now. Returns an id for cancel().
    virtual TimerId callAfter(std::int64_t delayUs, std::function<void()> callback) = 0;
    // Cancels a pending call; unknown or already run ids are ignored.
    virtual void cancel(TimerId id) = 0;
};

class RealClock : public Clock
{
public:
    RealClock();
    ~RealClock() override;
    std::int64_t nowUs() const override;
    TimerId callAfter(std::int64_t delayUs, std::function<void()> callback) override;
    void cancel(TimerId id) override;

private:
    QElapsedTimer m_elapsed;
    QHash<TimerId, QTimer *> m_timers;
    TimerId m_nextId = 1;
};

class VirtualClock : public Clock
{
public:
    std::int64_t nowUs() const override { return m_nowUs; }
    TimerId callAfter(std::int64_t delayUs, std::function<void()> callback) override;
    void cancel(TimerId id) override;

    // Runs due callbacks in order until `done()` holds, nothing is scheduled, or `limitUs` of
    // virtual time have passed. Returns done().
    bool runUntil(const std::function<bool()> &done, std::int64_t limitUs);
    // Runs everything due within the next `us` microseconds.
    void advance(std::int64_t us);
    bool idle() const { return m_queue.empty(); }

private:
    bool runNext(std::int64_t endUs);

    std::int64_t m_nowUs = 0;
    TimerId m_nextId = 1;
    // (due time, id) -> callback; the id keeps equal times in scheduling order.
    std::map<std::pair<std::int64_t, TimerId>, std::function<void()>> m_queue;
    std::map<TimerId, std::int64_t> m_due;
};

} // namespace frezka::grinder
