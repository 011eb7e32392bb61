// The words of a hold as both front ends get them (issue 14: "frezka-cli run also reports M6 as
// M0"): the driver holds at T1 M6 as a tool change naming tool 1 at its own line, at M1 as an
// optional stop, and the headless run that ends on the hold (what frezka-cli run reports) says
// so; the same hold's words in Czech when the Czech catalogue is installed.
#include "session/runworkflow.h"
#include "session/simlink.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <QCoreApplication>
#include <QTranslator>

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

using driver::DriverCode;
using driver::MachineMode;

struct Held
{
    machine::MachineConfig config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    SimLink link{config, driver::unitOptionsFor(config), driver::WireOptions{},
                 driver::CoreOptions{}};
    RunWorkflow workflow{link};

    // Runs text headless until the run ends on its first hold.
    void runToHold(const char *text)
    {
        workflow.setProfile(config);
        const gcode::Result g = gcode::interpretText(text, {});
        ASSERT_TRUE(g.ok());
        machine::PlanResult p = machine::plan(g.toolpath, config);
        ASSERT_TRUE(p.ok());
        workflow.setProgram(std::make_shared<machine::UnitProgram>(std::move(p.program)), {},
                            QStringLiteral("held.nc"));
        workflow.setEndOnHold(true);
        workflow.start(RunWorkflow::connectionFor(config), false);
        ASSERT_TRUE(link.runUntil([this] { return workflow.hasEnded(); }, 600));
        ASSERT_EQ(link.state().mode, MachineMode::Paused);
    }
};

TEST(HoldWords, ToolChangeIsNamedWithItsToolAndLine)
{
    Held h;
    h.runToHold("G21 G91\nG1 X2 F600\nG1 Y2\nT1 M6\nG1 X-2\nG1 Y-2\nM30\n");
    const auto &s = h.link.state();
    EXPECT_EQ(s.hold, driver::HoldReason::OperatorStop);
    EXPECT_EQ(s.holdMessage.code, DriverCode::HoldToolChange);
    EXPECT_EQ(s.holdLine, 4u);
    EXPECT_EQ(s.holdText, "Tool change (M6) at line 4: change to tool 1");
    const std::string said = h.workflow.error().toStdString();
    EXPECT_NE(said.find("M6"), std::string::npos) << said;
    EXPECT_NE(said.find("tool 1"), std::string::npos) << said;
    EXPECT_EQ(said.find("M0"), std::string::npos) << said;
}

TEST(HoldWords, OptionalStopIsNamedAsSuch)
{
    Held h;
    h.runToHold("G21 G91\nG1 X2 F600\nM1\nG1 X-2\nM30\n");
    EXPECT_EQ(h.link.state().holdMessage.code, DriverCode::HoldOptionalStop);
    EXPECT_EQ(h.link.state().holdLine, 3u);
    EXPECT_NE(h.workflow.error().toStdString().find("M1"), std::string::npos);
}

TEST(HoldWords, TheHoldIsWordedInCzech)
{
    int argc = 1;
    char name[] = "holdwords_test";
    char *argv[] = {name, nullptr};
    QCoreApplication app(argc, argv); // translators are installed on the application
    QTranslator cs;
    ASSERT_TRUE(cs.load(QStringLiteral(":/i18n/frezka_cs.qm")));
    QCoreApplication::installTranslator(&cs);
    Held h;
    h.runToHold("G21 G91\nG1 X2 F600\nT3 M6\nG1 X-2\nM30\n");
    const QString said = h.workflow.error();
    QCoreApplication::removeTranslator(&cs);
    EXPECT_TRUE(
        said.contains(QStringLiteral("Výměna nástroje (M6) na řádku 3: vyměňte za nástroj 3")))
        << said.toStdString();
    EXPECT_FALSE(said.contains(QStringLiteral("Tool change"))) << said.toStdString();
}

} // namespace
} // namespace frezka::session
