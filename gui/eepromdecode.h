#pragma once
// Decoding of the unit's EEPROM settings per variant (docs/gve-protocol.md §12), in words:
// output functions, STEP/DIR polarity, A-axis coupling, PWM mode, brake delay, baud range,
// MPG, homing input and speeds, input enables and polarities.

#include "machine/machineconfig.h"

#include <QString>

namespace frezka::gui {

// Caption of an EEPROM address for a variant ("Steps per mm X").
QString eepromLabel(protocol::Variant variant, std::uint8_t address);
// The meaning of a value at an address ("OUT1: coolant", "DIR X inverted, ...").
QString eepromMeaning(protocol::Variant variant, std::uint8_t address, double value);
// The value as the unit shows it: bytes in hex, floats and integers in decimal.
QString eepromValueText(machine::EepromKind kind, double value);
// Command texts (without "!0") that read / write an entry.
QString eepromReadCommand(const machine::EepromEntry &entry);
QString eepromWriteCommand(const machine::EepromEntry &entry);
// Whether two values are the same setting (floats with a relative tolerance of 1e-4).
bool eepromSame(machine::EepromKind kind, double a, double b);

} // namespace frezka::gui
