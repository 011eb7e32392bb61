// WorkOffsets: nine systems plus G92, work positions, and what is kept in QSettings (including
// the six systems saved before the session layer existed).
#include "session/workoffsets.h"

#include <QCoreApplication>
#include <QSettings>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

class WorkOffsetsTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaSessionTest"));
        QCoreApplication::setApplicationName(QStringLiteral("workoffsets"));
        QSettings().clear();
    }
    QTemporaryDir m_dir;
};

TEST_F(WorkOffsetsTest, NamesOfTheNineSystems)
{
    EXPECT_EQ(workSystemName(0), QStringLiteral("G54"));
    EXPECT_EQ(workSystemName(5), QStringLiteral("G59"));
    EXPECT_EQ(workSystemName(6), QStringLiteral("G59.1"));
    EXPECT_EQ(workSystemName(8), QStringLiteral("G59.3"));
}

TEST_F(WorkOffsetsTest, ZeroAtAPositionWithG92)
{
    WorkOffsets w;
    w.select(7); // G59.2
    w.setG92({1, 2, 3, 0});
    w.setZero(-1, {100, 50, -20, 10});
    EXPECT_EQ(w.systems()[7], (Axes4{99, 48, -23, 10}));
    EXPECT_EQ(w.workPosition({100, 50, -20, 10}), (Axes4{0, 0, 0, 0}));
    EXPECT_EQ(w.workPosition({101, 50, -20, 10}), (Axes4{1, 0, 0, 0}));
    w.setZero(0, {0, 0, 0, 0}); // X only
    EXPECT_EQ(w.systems()[7], (Axes4{-1, 48, -23, 10}));
    EXPECT_EQ(w.systems()[0], (Axes4{0, 0, 0, 0}));
}

TEST_F(WorkOffsetsTest, PersistsAllNineAndG92)
{
    {
        WorkOffsets w;
        for (int i = 0; i < kWorkSystems; ++i)
            w.setSystem(i, {double(i), double(10 * i), -double(i), 0.5 * i});
        w.setG92({7, 8, 9, 1});
        w.select(8);
    }
    WorkOffsets r;
    r.load();
    EXPECT_EQ(r.active(), 8);
    EXPECT_EQ(r.g92(), (Axes4{7, 8, 9, 1}));
    for (int i = 0; i < kWorkSystems; ++i)
        EXPECT_EQ(r.systems()[std::size_t(i)],
                  (Axes4{double(i), double(10 * i), -double(i), 0.5 * i}));
    // The six first systems keep their old key and shape (24 values).
    EXPECT_EQ(QSettings().value(QStringLiteral("workOffsets")).toList().size(), 24);
}

TEST_F(WorkOffsetsTest, ReadsOffsetsSavedBeforeTheSessionLayer)
{
    QVariantList old;
    for (int i = 0; i < 24; ++i)
        old << double(i + 1);
    QSettings().setValue(QStringLiteral("workOffsets"), old);
    QSettings().setValue(QStringLiteral("activeOffset"), 5);
    WorkOffsets w;
    w.load();
    EXPECT_EQ(w.active(), 5);
    EXPECT_EQ(w.systems()[0], (Axes4{1, 2, 3, 4}));
    EXPECT_EQ(w.systems()[5], (Axes4{21, 22, 23, 24}));
    EXPECT_EQ(w.systems()[6], (Axes4{0, 0, 0, 0}));
    EXPECT_EQ(w.g92(), (Axes4{0, 0, 0, 0}));
}

} // namespace
} // namespace frezka::session
