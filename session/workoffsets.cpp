#include "workoffsets.h"

#include <QSettings>
#include <QVariantList>

#include <algorithm>

namespace frezka::session {
namespace {

const QString kFirstSix = QStringLiteral("workOffsets");
const QString kExtra = QStringLiteral("workOffsetsExtra");
const QString kG92 = QStringLiteral("g92Offset");
const QString kActive = QStringLiteral("activeOffset");

// Reads `count` values into consecutive axes of `out` starting at system `first`.
void readList(const QVariantList &list, OffsetTable &out, int first, int systems)
{
    for (int i = 0; i < systems * 4 && i < list.size(); ++i)
        out[std::size_t(first + i / 4)][std::size_t(i % 4)] = list[i].toDouble();
}

QVariantList writeList(const OffsetTable &table, int first, int systems)
{
    QVariantList list;
    for (int s = first; s < first + systems; ++s)
        for (double v : table[std::size_t(s)])
            list << v;
    return list;
}

} // namespace

Axes4 OffsetState::total() const
{
    Axes4 t{};
    for (std::size_t i = 0; i < 4; ++i)
        t[i] = systems[std::size_t(active)][i] + g92[i];
    return t;
}

Axes4 OffsetState::workPosition(const Axes4 &machineMm) const
{
    const Axes4 t = total();
    Axes4 w{};
    for (std::size_t i = 0; i < 4; ++i)
        w[i] = machineMm[i] - t[i];
    return w;
}

QString workSystemName(int index)
{
    return index < 6 ? QStringLiteral("G%1").arg(54 + index)
                     : QStringLiteral("G59.%1").arg(index - 5);
}

WorkOffsets::WorkOffsets(QObject *parent)
    : QObject(parent)
{}

void WorkOffsets::load()
{
    QSettings s;
    OffsetState next;
    readList(s.value(kFirstSix).toList(), next.systems, 0, 6);
    readList(s.value(kExtra).toList(), next.systems, 6, 3);
    const QVariantList g92 = s.value(kG92).toList();
    for (int i = 0; i < 4 && i < g92.size(); ++i)
        next.g92[std::size_t(i)] = g92[i].toDouble();
    next.active = std::clamp(s.value(kActive, 0).toInt(), 0, kWorkSystems - 1);
    m_state = next;
    emit changed();
}

void WorkOffsets::save() const
{
    QSettings s;
    s.setValue(kFirstSix, writeList(m_state.systems, 0, 6));
    s.setValue(kExtra, writeList(m_state.systems, 6, 3));
    s.setValue(kG92, QVariantList{m_state.g92[0], m_state.g92[1], m_state.g92[2], m_state.g92[3]});
    s.setValue(kActive, m_state.active);
}

void WorkOffsets::select(int index)
{
    OffsetState next = m_state;
    next.active = std::clamp(index, 0, kWorkSystems - 1);
    commit(next);
}

void WorkOffsets::setZero(int axis, const Axes4 &machineMm)
{
    OffsetState next = m_state;
    for (std::size_t i = 0; i < 4; ++i) {
        if (axis < 0 || std::size_t(axis) == i)
            next.systems[std::size_t(next.active)][i] = machineMm[i] - next.g92[i];
    }
    commit(next);
}

void WorkOffsets::setSystem(int index, const Axes4 &offsetMm)
{
    if (index < 0 || index >= kWorkSystems)
        return;
    OffsetState next = m_state;
    next.systems[std::size_t(index)] = offsetMm;
    commit(next);
}

void WorkOffsets::setG92(const Axes4 &offsetMm)
{
    OffsetState next = m_state;
    next.g92 = offsetMm;
    commit(next);
}

void WorkOffsets::setState(const OffsetState &state)
{
    OffsetState next = state;
    next.active = std::clamp(next.active, 0, kWorkSystems - 1);
    commit(next);
}

void WorkOffsets::commit(const OffsetState &next)
{
    m_state = next;
    save();
    emit changed(); // also when equal: a re-selection re-applies (re-plans) on purpose
}

} // namespace frezka::session
