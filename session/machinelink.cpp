#include "machinelink.h"

namespace frezka::session {

MachineLink::~MachineLink() = default;

} // namespace frezka::session
