#include "driver/grinder/clock.h"

#include <QTimer>

namespace frezka::grinder {

RealClock::RealClock()
{
    m_elapsed.start();
}

RealClock::~RealClock()
{
    qDeleteAll(m_timers);
}

std::int64_t RealClock::nowUs() const
{
    return m_elapsed.nsecsElapsed() / 1000;
}

Clock::TimerId RealClock::callAfter(std::int64_t delayUs, std::function<void()> callback)
{
    const TimerId id = m_nextId++;
    auto *timer = new QTimer;
    timer->setSingleShot(true);
    timer->setTimerType(Qt::PreciseTimer);
    QObject::connect(timer, &QTimer::timeout, timer, [this, id, callback = std::move(callback)] {
        if (QTimer *t = m_timers.take(id))
            t->deleteLater();
        callback();
    });
    m_timers.insert(id, timer);
    timer->start(static_cast<int>(std::max<std::int64_t>(0, (delayUs + 999) / 1000)));
    return id;
}

void RealClock::cancel(TimerId id)
{
    if (QTimer *timer = m_timers.take(id)) {
        timer->stop();
        timer->deleteLater();
    }
}

Clock::TimerId VirtualClock::callAfter(std::int64_t delayUs, std::function<void()> callback)
{
    const TimerId id = m_nextId++;
    const std::int64_t due = m_nowUs + std::max<std::int64_t>(0, delayUs);
    m_queue.emplace(std::make_pair(due, id), std::move(callback));
    m_due.emplace(id, due);
    return id;
}

void VirtualClock::cancel(TimerId id)
{
    const auto it = m_due.find(id);
    if (it == m_due.end())
        return;
    m_queue.erase(std::make_pair(it->second, id));
    m_due.erase(it);
}

bool VirtualClock::runNext(std::int64_t endUs)
{
    if (m_queue.empty() || m_queue.begin()->first.first > endUs)
        return false;
    auto node = m_queue.extract(m_queue.begin());
    m_due.erase(node.key().second);
    m_nowUs = node.key().first;
    node.mapped()();
    return true;
}

bool VirtualClock::runUntil(const std::function<bool()> &done, std::int64_t limitUs)
{
    const std::int64_t end = m_nowUs + limitUs;
    while (!done() && runNext(end)) {
    }
    if (!done() && m_nowUs < end && m_queue.empty())
        return false;
    return done();
}

void VirtualClock::advance(std::int64_t us)
{
    const std::int64_t end = m_nowUs + us;
    while (runNext(end)) {
    }
    m_nowUs = end;
}

} // namespace frezka::grinder
