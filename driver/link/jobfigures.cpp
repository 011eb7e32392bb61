// JobFigures: the figures of one job. See jobfigures.h.

#include "jobfigures.h"

#include <algorithm>

namespace frezka::driver {

void JobFigures::start(double now, const LinkStats &stats)
{
    m_report = {};
    m_report.startS = now;
    m_bytesAtStart = stats.bytesIn + stats.bytesOut;
    m_resentAtStart = stats.resent;
    m_recoveredAtStart = stats.recovered;
}

void JobFigures::accepted(bool motion, double now)
{
    if (motion) {
        ++m_report.vectors;
        if (m_report.firstVectorAckS < 0)
            m_report.firstVectorAckS = now;
        m_report.lastVectorAckS = now;
    }
    ++m_report.commands;
}

void JobFigures::pollStarted(double now, bool vectorsLeft)
{
    ++m_report.polls;
    if (!vectorsLeft)
        return;
    ++m_report.streamPolls;
    const double since = m_report.streamPolls > 1 ? m_report.lastStreamPollS : m_report.startS;
    m_report.maxStreamPollGapS = std::max(m_report.maxStreamPollGapS, now - since);
    if (m_report.streamPolls == 1)
        m_report.firstStreamPollS = now;
    m_report.lastStreamPollS = now;
}

void JobFigures::finish(bool ok, double now, const LinkStats &stats)
{
    m_report.finished = ok;
    m_report.endS = now;
    m_report.linkBytes = stats.bytesIn + stats.bytesOut - m_bytesAtStart;
    m_report.resent += stats.resent - m_resentAtStart;
    m_report.recovered = stats.recovered - m_recoveredAtStart;
}

} // namespace frezka::driver
