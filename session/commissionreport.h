#pragma once
// The commissioning report (issue 21 item 4): a readable text of everything the assistant saw:
// the unit, its firmware, the link figures, each checked reading (held / did not hold / not
// checked), the EEPROM decoded against the profile, the axes' results, every step, and the
// serial trace of the session attached at the end (docs/serial-trace.md), so that a report
// sent by a user can be replayed (gve-emu --replay).

#include "session/commission.h"

#include <QString>

namespace frezka::session {

// The report as text, in the user's language (the trace as recorded).
QString commissionReportText(const CommissionResult &result);
// Writes text (UTF-8) to path, atomically. False with the reason, translated.
bool saveCommissionText(const QString &path, const QString &text, QString *error);
// Writes the updated profile to `path`, atomically, never over `original` (the profile it was
// loaded from): the operator names a new file. False with the reason, translated.
bool saveCommissionedProfile(const machine::MachineConfig &profile, const QString &path,
                             const QString &original, QString *error);

} // namespace frezka::session
