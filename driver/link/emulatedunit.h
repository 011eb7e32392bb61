#pragma once
// The built-in emulator as a connection asks for it: its wire (baud, latency, faults) and its
// unit (the profile's variant, EEPROM and home switches, the probe surface). The real-time link's
// transport (transportfactory.cpp) and the window's virtual clock (session::VirtualClockLink)
// both build it from these.

#include "driver/link/emulatorport.h"
#include "driver/link/machinecontroller.h"

namespace frezka::driver {

WireOptions wireFor(const ConnectionSettings &settings);
emulator::UnitOptions emulatedUnitFor(const ConnectionSettings &settings,
                                      const machine::MachineConfig &config);

} // namespace frezka::driver
