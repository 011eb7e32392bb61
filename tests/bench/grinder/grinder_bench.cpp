// grinder_bench: how fast the grinder codec and a whole virtual-time transfer run.
// Reference: the line itself — a K51 image (0x5507 bytes) takes ~22.7 s at 9600 Bd, i.e.
// 960 B/s; the codec must be orders of magnitude faster, and a virtual-clock test of a whole
// transfer must cost milliseconds.
#include "driver/grinder/emulatortransport.h"
#include "driver/grinder/transfersession.h"

#include <chrono>
#include <cstdio>

using namespace frezka::grinder;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void benchDecode(std::size_t chunk)
{
    const Bytes wire = encodeFrame(Frame::withData(Framing::K51, Code::Save, headerFromText("B"),
                                                   generatedImage(Family::K51, kK51ImageSize)));
    const int rounds = 200;
    FrameDecoder decoder(Framing::K51);
    std::vector<DecodeEvent> events;
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < rounds; ++r) {
        for (std::size_t i = 0; i < wire.size(); i += chunk)
            decoder.feed(wire.data() + i, std::min(chunk, wire.size() - i), events);
        events.clear();
    }
    const double s = secondsSince(start);
    std::printf("decode K51 SAV (%zu B) in %5zu-byte chunks: %8.1f MB/s (%.0fx the 9600 Bd line)\n",
                wire.size(), chunk, rounds * wire.size() / s / 1e6, rounds * wire.size() / s / 960.0);
}

void benchEncode()
{
    const Frame frame = Frame::withData(Framing::K51, Code::Load, headerFromText("B"),
                                        generatedImage(Family::K51, kK51ImageSize));
    const int rounds = 2000;
    std::size_t total = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < rounds; ++r)
        total += encodeFrame(frame).size();
    const double s = secondsSince(start);
    std::printf("encode K51 LOA: %8.1f MB/s\n", total / s / 1e6);
}

void benchVirtualSave()
{
    const int rounds = 20;
    double virtualS = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < rounds; ++r) {
        VirtualClock clock;
        EmulatorTransport transport(clock, EmulatorConfig{}, 9600);
        transport.open(nullptr);
        TransferSession session(transport, clock, Family::K51);
        bool done = false;
        QObject::connect(&session, &TransferSession::finished,
                         [&](const TransferResult &) { done = true; });
        session.save();
        clock.runUntil([&] { return done; }, 600'000'000);
        virtualS += session.lastResult().elapsedUs / 1e6;
    }
    const double s = secondsSince(start);
    std::printf("K51 save at 9600 Bd on the virtual clock: %.1f ms wall for %.2f s on the wire\n",
                s / rounds * 1e3, virtualS / rounds);
}

} // namespace

int main()
{
    benchDecode(1);
    benchDecode(4096);
    benchEncode();
    benchVirtualSave();
    return 0;
}
