#include "driver/grinder/emulatortransport.h"
#include "driver/grinder/zlinksession.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

namespace {
struct ZRig
{
    VirtualClock clock;
    EmulatorTransport transport;
    ZLinkSession session;
    std::vector<qint64> positions;
    QStringList failures;
    int skipped = 0;

    explicit ZRig(int form)
        : transport(clock, makeConfig(form), 9600)
        , session(transport, clock, form)
    {
        transport.open(nullptr);
        QObject::connect(&session, &ZLinkSession::positionReceived,
                         [this](qint64 um) { positions.push_back(um); });
        QObject::connect(&session, &ZLinkSession::replyFailed,
                         [this](const QString &m) { failures << m; });
        QObject::connect(&session, &ZLinkSession::bytesSkipped, [this](int n) { skipped += n; });
    }
    static EmulatorConfig makeConfig(int form)
    {
        EmulatorConfig c;
        c.mode = TransferMode::ZPosition;
        c.zForm = form;
        return c;
    }
    void settle()
    {
        clock.runUntil([this] { return !session.isWaiting(); }, 600'000'000);
    }
};
} // namespace

TEST(GrinderZLink, Form1QueryAndGo)
{
    ZRig rig(1);
    ASSERT_TRUE(rig.session.query());
    EXPECT_FALSE(rig.session.query()); // one question at a time
    rig.settle();
    ASSERT_EQ(rig.positions, std::vector<qint64>{-1234});

    ASSERT_TRUE(rig.session.go(12123));
    rig.settle();
    ASSERT_EQ(rig.positions.size(), 2u);
    EXPECT_EQ(rig.positions.back(), 12123);
    EXPECT_EQ(rig.transport.emulator().zPositionUm(), 12123);
    // 13.357 mm at 20 mm/s: the answer comes when the table has arrived, not at once.
    EXPECT_GT(rig.clock.nowUs(), 600'000);
    EXPECT_TRUE(rig.failures.isEmpty());
}

TEST(GrinderZLink, Form1BadCharactersAreReportedE0ThenE1)
{
    ZRig rig(1);
    rig.transport.write("ZX");
    rig.clock.advance(100'000);
    rig.transport.write("Q");
    rig.clock.advance(100'000);
    ASSERT_EQ(rig.failures.size(), 2);
    EXPECT_TRUE(rig.failures[0].contains("(E0)")) << rig.failures[0].toStdString();
    EXPECT_TRUE(rig.failures[1].contains("(E1)")) << rig.failures[1].toStdString();
    ASSERT_TRUE(rig.session.query()); // a good message afterwards works again
    rig.settle();
    EXPECT_EQ(rig.positions, std::vector<qint64>{-1234});
}

TEST(GrinderZLink, Form1TimeoutIsReported)
{
    VirtualClock clock;
    EmulatorConfig c = ZRig::makeConfig(1);
    c.mode = TransferMode::Programs; // wrong KONFIG6: the controller does not answer Z?
    EmulatorTransport transport(clock, c, 9600);
    transport.open(nullptr);
    ZLinkSession session(transport, clock, 1);
    QStringList failures;
    QObject::connect(&session, &ZLinkSession::replyFailed,
                     [&](const QString &m) { failures << m; });
    ASSERT_TRUE(session.query());
    clock.runUntil([&] { return !session.isWaiting(); }, 10'000'000);
    ASSERT_EQ(failures.size(), 1);
    EXPECT_TRUE(failures[0].contains("No answer to \"Z?\"")) << failures[0].toStdString();
}

TEST(GrinderZLink, Form2BinaryFramesArePositions)
{
    ZRig rig(2);
    EXPECT_FALSE(rig.session.query()); // one-way: nothing is sent
    rig.clock.advance(1'000'000);
    ASSERT_GE(rig.positions.size(), 9u);
    for (qint64 um : rig.positions)
        EXPECT_EQ(um, -1234);
    EXPECT_EQ(rig.skipped, 0);
}
