#pragma once
// ANC / K51 controller emulator core. Pure C++: bytes in (feed), time passes (advance), bytes
// out (takeOutput). Baud pacing of the wire is the wrapper's job (EmulatorTransport in-process
// on a virtual clock, k51-emu on a pty in real time); this core models the controller only.
//
// Behaviour by KONFIG6 (K51-1 numbering; see transferModeFromKonfig6 for K51-2):
//   None      - never answers
//   ZPosition - FORM=1 ASCII (Z?, GO, E0/E1) or FORM=2 periodic binary frames
//   Programs  - ENQ -> ACK; request -> data message; data message -> ACK (or NAK if bad)
//   Table     - ENQ -> ACK; LOA1 -> ACK (stored apart); other data requests -> NAK
// Faults for tests: NAKs for the first good data messages, corrupted outgoing data messages,
// noise before every reply, silence (from the start or after some replies), a reply delay.

#include "driver/grinder/family.h"
#include "driver/grinder/framedecoder.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace frezka::grinder {

enum class TransferMode { None, ZPosition, Programs, Table };

// KONFIG6 value to mode: K51-1 0 none, 1 Z, 2 programs, 3 table; K51-2 0 none, 1 programs.
std::optional<TransferMode> transferModeFromKonfig6(int konfig6, bool k51Type2);

struct EmulatorConfig
{
    Family family = Family::K51;
    TransferMode mode = TransferMode::Programs;
    int zForm = 1;             // 1 ASCII both ways, 2 binary one way
    bool selectorInPgn = true; // FORM=1 answers only with the selector in PGN (manual §5)
    Bytes image;               // empty: a generated image of the family's size
    Header header = headerFromText("FREZKA EMU");
    int nakCount = 0;                 // answer the first N good data messages with NAK
    int corruptCount = 0;             // flip one byte in the first N data messages sent
    bool noise = false;               // send noise bytes before every reply
    int silentAfterReplies = -1;      // stop answering after N replies (0: silent; -1: never)
    std::int64_t replyDelayUs = 2000; // controller's pause before answering
    std::int64_t zStartUm = -1234;
    std::int64_t zSpeedUmPerS = 20000; // table speed for GO
    std::int64_t zPeriodUs = 100000;   // FORM=2 frame period
    int maxResends = 10;               // data resends on NAK before the controller gives up
};

// The noise pattern: holds AA followed by bytes that cannot start a message.
Bytes emulatorNoise();
// A deterministic image of `size` bytes; program images get sealed inner blocks.
Bytes generatedImage(Family family, std::size_t size);

class ControllerEmulator
{
public:
    explicit ControllerEmulator(EmulatorConfig config);

    // Bytes from the PC.
    void feed(const std::uint8_t *bytes, std::size_t size);
    void feed(const Bytes &bytes) { feed(bytes.data(), bytes.size()); }
    // Lets `us` microseconds pass (replies due, table movement, FORM=2 frames).
    void advance(std::int64_t us);
    // Bytes due to the PC so far (the wrapper paces them on the wire).
    Bytes takeOutput();
    bool hasPendingWork() const;
    // Human-readable trace lines since the last call ("rx ENQ", "tx SAV 21783 bytes", ...).
    std::vector<std::string> takeLog();

    const EmulatorConfig &config() const { return m_config; }
    const Bytes &image() const { return m_config.image; }
    const Header &header() const { return m_config.header; }
    const Bytes &table() const { return m_table; }
    std::uint8_t prenos() const { return m_prenos; }     // PRENOS: 0x00 init, 0xB1 after a load
    bool noProgramSet() const { return m_noProgramSet; } // "no prg set" pending after a load
    std::int64_t zPositionUm() const { return m_zUm; }
    int checksumErrors() const { return m_checksumErrors; }
    int naksSent() const { return m_naksSent; }
    int loadsStored() const { return m_loadsStored; }
    int tablesStored() const { return m_tablesStored; }

private:
    void onFrame(const Frame &frame);
    void onDataMessage(const Frame &frame);
    void sendData();
    void reply(const Bytes &bytes);
    void replyCode(Code code);
    void log(const std::string &line);
    void feedAscii(std::uint8_t byte);
    void asciiError();
    void moveTable(std::int64_t us);

    EmulatorConfig m_config;
    const FamilyInfo &m_info;
    FrameDecoder m_decoder;
    std::int64_t m_nowUs = 0;
    std::int64_t m_lastRxUs = 0;
    std::deque<std::pair<std::int64_t, Bytes>> m_scheduled; // due time, bytes
    Bytes m_output;
    std::vector<std::string> m_log;
    Bytes m_table;
    int m_replies = 0;
    int m_naksToSend = 0;
    int m_corruptToSend = 0;
    int m_resends = 0;
    bool m_awaitingAck = false;
    std::uint8_t m_prenos = 0x00;
    bool m_noProgramSet = false;
    int m_checksumErrors = 0;
    int m_naksSent = 0;
    int m_loadsStored = 0;
    int m_tablesStored = 0;
    // Z-position link
    std::int64_t m_zUm = 0;
    std::optional<std::int64_t> m_zTargetUm;
    std::int64_t m_zSpeedRemainderUs = 0;
    std::int64_t m_zNextFrameUs = 0;
    std::string m_ascii;     // FORM=1 message in progress
    bool m_asciiBad = false; // a bad character was already answered with E0
};

} // namespace frezka::grinder
