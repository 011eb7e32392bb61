#include "driver/grinder/controlleremulator.h"

#include "driver/grinder/imagecheck.h"
#include "driver/grinder/zposition.h"

namespace frezka::grinder {

std::optional<TransferMode> transferModeFromKonfig6(int konfig6, bool k51Type2)
{
    if (k51Type2) {
        if (konfig6 == 0)
            return TransferMode::None;
        if (konfig6 == 1)
            return TransferMode::Programs;
        return std::nullopt;
    }
    switch (konfig6) {
    case 0:
        return TransferMode::None;
    case 1:
        return TransferMode::ZPosition;
    case 2:
        return TransferMode::Programs;
    case 3:
        return TransferMode::Table;
    default:
        return std::nullopt;
    }
}

Bytes emulatorNoise()
{
    return {0x00, 0x13, 0xAA, 0x99, 0xFF, 0x55};
}

Bytes generatedImage(Family family, std::size_t size)
{
    Bytes image(size);
    std::uint32_t state = 0x2545F491u + static_cast<std::uint32_t>(family);
    for (std::uint8_t &byte : image) {
        state = state * 1664525u + 1013904223u;
        byte = static_cast<std::uint8_t>(state >> 24);
    }
    if (size >= kProgramImageSize)
        sealImageBlocks(image, size - kProgramImageSize);
    return image;
}

ControllerEmulator::ControllerEmulator(EmulatorConfig config)
    : m_config(std::move(config))
    , m_info(familyInfo(m_config.family))
    , m_decoder(m_info.framing)
{
    if (m_config.image.empty() && m_info.defaultSize > 0)
        m_config.image = generatedImage(m_config.family, m_info.defaultSize);
    m_naksToSend = m_config.nakCount;
    m_corruptToSend = m_config.corruptCount;
    m_zUm = m_config.zStartUm;
}

void ControllerEmulator::log(const std::string &line)
{
    m_log.push_back(line);
}

std::vector<std::string> ControllerEmulator::takeLog()
{
    std::vector<std::string> lines;
    lines.swap(m_log);
    return lines;
}

void ControllerEmulator::feed(const std::uint8_t *bytes, std::size_t size)
{
    switch (m_config.mode) {
    case TransferMode::None:
        return;
    case TransferMode::ZPosition:
        if (m_config.zForm == 1 && m_config.selectorInPgn) {
            for (std::size_t i = 0; i < size; ++i)
                feedAscii(bytes[i]);
        } else if (m_config.zForm == 1) {
            log("selector not in PGN: FORM=1 input ignored");
        }
        return; // FORM=2 is one way: input is ignored
    case TransferMode::Programs:
    case TransferMode::Table:
        break;
    }
    std::vector<DecodeEvent> events;
    if (size > 0)
        m_lastRxUs = m_nowUs;
    m_decoder.feed(bytes, size, events);
    for (const DecodeEvent &event : events) {
        switch (event.kind) {
        case DecodeEvent::Kind::Noise:
            log("rx noise " + std::to_string(event.noise.size()) + " bytes");
            break;
        case DecodeEvent::Kind::ChecksumError:
            ++m_checksumErrors;
            log("rx " + codeName(m_info.framing, std::uint8_t(event.frame.code)) +
                " with a bad checksum");
            replyCode(Code::Nak);
            break;
        case DecodeEvent::Kind::Frame:
            onFrame(event.frame);
            break;
        }
    }
}

void ControllerEmulator::onFrame(const Frame &frame)
{
    log("rx " + codeName(m_info.framing, std::uint8_t(frame.code)) +
        (frame.data.empty() ? "" : " " + std::to_string(frame.data.size()) + " bytes"));
    const bool programs = m_config.mode == TransferMode::Programs;
    if (frame.code == Code::Enq) {
        replyCode(Code::Ack);
    } else if (frame.code == Code::Ack || frame.code == Code::Nak) {
        if (!m_awaitingAck)
            return; // nothing outstanding: a stray reply changes nothing
        if (frame.code == Code::Ack) {
            m_awaitingAck = false;
        } else if (++m_resends <= m_config.maxResends) {
            sendData();
        } else {
            m_awaitingAck = false;
            log("gave up after " + std::to_string(m_config.maxResends) + " resends");
        }
    } else if (programs && frame.code == m_info.requestCode && frame.data.empty()) {
        m_resends = 0;
        sendData();
    } else if (programs && frame.code == m_info.loadCode && frame.code != Code::LoadTable &&
               frame.payloadSize() > 0) {
        onDataMessage(frame);
    } else if (m_config.mode == TransferMode::Table && frame.code == Code::LoadTable) {
        m_table = frame.data;
        m_prenos = 0xB1;
        ++m_tablesStored;
        replyCode(Code::Ack);
    } else {
        log("unsupported in this mode: NAK");
        replyCode(Code::Nak);
    }
}

void ControllerEmulator::onDataMessage(const Frame &frame)
{
    if (m_naksToSend > 0) {
        --m_naksToSend;
        log("injected NAK");
        replyCode(Code::Nak);
        return;
    }
    m_config.image = frame.data;
    if (carriesHeader(frame.framing, frame.code))
        m_config.header = frame.header;
    if (m_config.family != Family::HardChrome) {
        m_prenos = 0xB1;
        m_noProgramSet = true;
    }
    ++m_loadsStored;
    replyCode(Code::Ack);
}

void ControllerEmulator::sendData()
{
    Bytes wire = encodeFrame(
        Frame::withData(m_info.framing, m_info.saveCode, m_config.header, m_config.image));
    if (m_corruptToSend > 0 && wire.size() > 8) {
        --m_corruptToSend;
        wire[wire.size() / 2] ^= 0x5A;
        log("injected corruption");
    }
    m_awaitingAck = true;
    reply(wire);
}

void ControllerEmulator::replyCode(Code code)
{
    if (code == Code::Nak)
        ++m_naksSent;
    reply(encodeFrame(Frame::control(m_info.framing, code)));
}

void ControllerEmulator::reply(const Bytes &bytes)
{
    if (m_config.silentAfterReplies >= 0 && m_replies >= m_config.silentAfterReplies) {
        log("silent: reply withheld");
        return;
    }
    ++m_replies;
    Bytes wire = m_config.noise ? emulatorNoise() : Bytes{};
    wire.insert(wire.end(), bytes.begin(), bytes.end());
    log("tx " + std::to_string(bytes.size()) + " bytes");
    m_scheduled.emplace_back(m_nowUs + m_config.replyDelayUs, std::move(wire));
}

void ControllerEmulator::advance(std::int64_t us)
{
    m_nowUs += us;
    if (m_decoder.pendingBytes() > 0 && m_nowUs - m_lastRxUs > kControllerGapUs) {
        std::vector<DecodeEvent> dropped;
        m_decoder.reset(dropped);
        log("incomplete message dropped after a gap");
    }
    if (m_config.mode != TransferMode::ZPosition)
        return;
    if (m_config.zForm == 1) {
        moveTable(us);
    } else {
        while (m_zNextFrameUs <= m_nowUs) {
            const Bytes frame = encodeZBinary(m_zUm);
            m_output.insert(m_output.end(), frame.begin(), frame.end());
            m_zNextFrameUs += m_config.zPeriodUs;
        }
    }
}

Bytes ControllerEmulator::takeOutput()
{
    while (!m_scheduled.empty() && m_scheduled.front().first <= m_nowUs) {
        const Bytes &bytes = m_scheduled.front().second;
        m_output.insert(m_output.end(), bytes.begin(), bytes.end());
        m_scheduled.pop_front();
    }
    Bytes out;
    out.swap(m_output);
    return out;
}

bool ControllerEmulator::hasPendingWork() const
{
    return !m_scheduled.empty() || !m_output.empty() || m_zTargetUm.has_value() ||
           (m_config.mode == TransferMode::ZPosition && m_config.zForm == 2);
}

void ControllerEmulator::moveTable(std::int64_t us)
{
    if (!m_zTargetUm)
        return;
    m_zSpeedRemainderUs += us * m_config.zSpeedUmPerS;
    const std::int64_t step = m_zSpeedRemainderUs / 1000000;
    m_zSpeedRemainderUs %= 1000000;
    const std::int64_t distance = *m_zTargetUm - m_zUm;
    if ((distance < 0 ? -distance : distance) <= step) {
        m_zUm = *m_zTargetUm;
        m_zTargetUm.reset();
        m_zSpeedRemainderUs = 0;
        const std::string text = positionMessage(m_zUm);
        log("reached " + text);
        reply(Bytes(text.begin(), text.end()));
    } else {
        m_zUm += distance < 0 ? -step : step;
    }
}

void ControllerEmulator::asciiError()
{
    const std::string text = m_asciiBad ? "E1 " : "E0 ";
    m_asciiBad = true;
    m_ascii.clear();
    log("bad character: " + text);
    reply(Bytes(text.begin(), text.end()));
}

// FORM=1 receiver: "Z? " and "GO <number> ", checked character by character.
void ControllerEmulator::feedAscii(std::uint8_t byte)
{
    const char c = static_cast<char>(byte);
    const std::string &s = m_ascii;
    bool good = false;
    if (s.empty())
        good = c == 'Z' || c == 'G' || c == ' ';
    else if (s == "Z")
        good = c == '?';
    else if (s == "Z?")
        good = c == ' ';
    else if (s == "G")
        good = c == 'O';
    else if (s == "GO")
        good = c == ' ';
    else if (s.size() >= 3 && s.compare(0, 3, "GO ") == 0)
        good = c == ' ' || (c >= '0' && c <= '9') || c == '.' || c == ',' ||
               ((c == '-' || c == '+') && s.size() == 3);
    if (!good) {
        asciiError();
        return;
    }
    if (c == ' ' && s.empty())
        return;
    if (c != ' ' || s == "GO") {
        m_ascii.push_back(c);
        return;
    }
    if (s == "Z?") {
        m_ascii.clear();
        m_asciiBad = false;
        const std::string text = positionMessage(m_zUm);
        reply(Bytes(text.begin(), text.end()));
        return;
    }
    const auto target = parseMillimetres(std::string_view(s).substr(3));
    if (!target) {
        asciiError();
        return;
    }
    m_ascii.clear();
    m_asciiBad = false;
    m_zTargetUm = *target;
    log("GO " + formatMillimetres(*target));
    moveTable(0);
}

} // namespace frezka::grinder
