#pragma once
// Test rig of the session tests: a session on the in-process emulator on a virtual clock.
#include "driver/grinder/emulatortransport.h"
#include "driver/grinder/transfersession.h"

#include <gtest/gtest.h>

#include <optional>

using namespace frezka::grinder;

namespace {

constexpr std::int64_t kLimitUs = 600'000'000; // 10 min of virtual time

struct Rig
{
    VirtualClock clock;
    EmulatorTransport transport;
    TransferSession session;
    std::optional<TransferResult> result;
    std::vector<std::pair<qint64, qint64>> progress;
    QStringList trace;

    Rig(EmulatorConfig config, int baud = 9600)
        : transport(clock, config, baud)
        , session(transport, clock, config.family)
    {
        transport.open(nullptr);
        QObject::connect(&session, &TransferSession::finished,
                         [this](const TransferResult &r) { result = r; });
        QObject::connect(&session, &TransferSession::progressed,
                         [this](qint64 done, qint64 total) { progress.emplace_back(done, total); });
        QObject::connect(&session, &TransferSession::traced,
                         [this](const QString &line) { trace << line; });
    }
    TransferResult run()
    {
        clock.runUntil([this] { return result.has_value(); }, kLimitUs);
        EXPECT_TRUE(result.has_value());
        return result.value_or(TransferResult{});
    }
    TransferResult save()
    {
        result.reset();
        session.save();
        return run();
    }
    TransferResult load(const std::string &header, const Bytes &data)
    {
        result.reset();
        session.load(headerFromText(header), QByteArray(reinterpret_cast<const char *>(data.data()),
                                                        qsizetype(data.size())));
        return run();
    }
};

EmulatorConfig config(Family family)
{
    EmulatorConfig c;
    c.family = family;
    return c;
}

Bytes toBytes(const QByteArray &data)
{
    return Bytes(data.begin(), data.end());
}

inline const Family kFamilies[] = {Family::Anc, Family::K51, Family::HardChrome};

} // namespace
