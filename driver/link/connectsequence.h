#pragma once
// ConnectSequence: the connecting activity: from an opened port to a unit ready for work.
//
// Contract: start() (the core calls it when the link opens, with nothing else queued) clears
// every axis's homed mark (a new link may mean a new or restarted unit), switches checksums on or
// off, identifies the unit and refuses a firmware of another family than the profile's (alarm),
// sets MPG off, T, VN and the interrupt masks and polarities from the profile, compares the unit's
// EEPROM with the profile (EepromSync; differences are reported, never written), tests whether the
// unit restarts a packet on a second *S, and reads the position and F. The mode is Connecting
// throughout; at the end it is Idle, or, with a job kept over a link loss, Paused while the job's
// progress is re-established from the counters. Every step is harmless to repeat, and the ones a
// damaged byte can spoil (%+, the packet test) are repeated a few times before they count as
// refused.

namespace frezka::driver {

class CoreHost;
class EepromSync;
class Job;
struct MachineState;

class ConnectSequence
{
public:
    ConnectSequence(CoreHost &host, Job &job, EepromSync &eeprom)
        : m_host(host)
        , m_job(job)
        , m_eeprom(eeprom)
    {}

    void start();
    // Position and status read, then Idle (or the kept job's check). Also the last step.
    void finish();

private:
    MachineState &state();
    void switchChecksums(int attempt);
    void setupUnit();
    void setupAfterIdentify();
    void probeDoublePacketStart();
    void packetStartTest(int attempt);

    CoreHost &m_host;
    Job &m_job;
    EepromSync &m_eeprom;
};

} // namespace frezka::driver
