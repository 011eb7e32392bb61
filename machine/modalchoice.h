#pragma once
// Internal to frezka_machine: V and A per vector, shared over stretches (docs/planner.md §4-§5).

#include "machine/chainparts.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace frezka::machine::detail {

// Sets each vector's V (Derived::speed) and, where it shares a V above its own cap, the B cap
// that keeps it within its own (Derived::speedCap). Without a link (baud 0) each keeps its own.
void chooseSpeeds(std::vector<Derived> &d, const PlanOptions &options, const LinkTiming &link);
// Sets each vector's A (Derived::accel) and its braking room (Derived::twoAU). Quick vectors
// share one A while their caps lie within PlanOptions::accelTolerance, or while the time the
// lower A costs them stays below what an A command costs the link; a vector shorter than
// PlanOptions::accelWindowSteps takes its neighbours' least cap where that costs it less than
// the A change would cost the job on this link (its command, and where the unit would hold too
// little motion there, what the packets it stops cost). vertexCaps: per vertex (after move k)
// the caps its geometry sets on the scalar speed, speed units (the time a lower A costs).
void chooseAccels(std::vector<Derived> &d, const std::vector<double> &vertexCaps,
                  const PlanOptions &options, const LinkTiming &link);
// Vector j's time at V `speed` (at most `fastest`, speed units/s) and A `accel` (thousands)
// between the fastest speeds its two corners allow (vertexCaps as for chooseAccels, both Vs as d
// has them), seconds.
double vectorTimeS(const std::vector<Derived> &d, const std::vector<double> &vertexCaps,
                   std::size_t j, std::int64_t speed, std::int64_t accel, double fastest);
// Sets a vector's A (thousands of pulses/s²) and the usable 2·A·distance that follows from it.
void setAccel(Derived &r, std::int64_t accel, const PlanOptions &options);
// The A cap of vector k, thousands of pulses/s²: where it is shorter than
// PlanOptions::accelWindowSteps, the least of its neighbours' within that distance.
std::int64_t accelCap(const std::vector<Derived> &d, std::size_t k, const PlanOptions &options);
// The same within windowSteps (0: the vector's own cap).
std::int64_t accelCapWithin(const std::vector<Derived> &d, std::size_t k,
                            const PlanOptions &options, double windowSteps);
// True when vector k passes in under PlanOptions::accelKeepS at its V.
bool quick(const std::vector<Derived> &d, std::size_t k, const PlanOptions &options);

} // namespace frezka::machine::detail
