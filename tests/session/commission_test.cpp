// The commissioning assistant's steps on the in-process emulator in real time (issue 21 item
// 1): the steps that move nothing over a raw transport, then every step that moves or switches
// something with a scripted operator who answers, measures and presses the emulator's inputs.
// Asserted on what reached the wire (the serial trace) and what the emulator did (position,
// homed counters, outputs), not only on the results the assistant wrote down.

#include "session/commissionmoves.h"
#include "session/commissionreport.h"
#include "session/unitprobe.h"

#include "driver/emulator/serialtrace.h"
#include "driver/link/emulatorport.h"
#include "driver/link/emulatortransport.h"
#include "driver/link/tracerecorder.h"
#include "driver/link/tracingtransport.h"
#include "machine/steps.h"

#include <QCoreApplication>
#include <QTimer>

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

void ensureApplication()
{
    static int argc = 1;
    static char name[] = "commission_test";
    static char *argv[] = {name, nullptr};
    static QCoreApplication *app =
        QCoreApplication::instance() ? nullptr : new QCoreApplication(argc, argv);
    (void)app;
}

// Answers yes, measures 4.9 mm where 5 were asked, and presses the input it is told to.
struct ScriptedOperator : CommissionOperator
{
    driver::EmulatorTransport **unit = nullptr;
    QStringList questions;
    bool confirm(const CommissionStep &) override { return true; }
    bool ask(const QString &q) override
    {
        questions << q;
        return true;
    }
    std::optional<double> askNumber(const QString &q) override
    {
        questions << q;
        return 4.9;
    }
    void instruct(const QString &text) override
    {
        // "... (IN2) now.": press that input a moment later, as a hand would.
        const int at = static_cast<int>(text.indexOf(QLatin1String("(IN")));
        const int in = text.mid(at + 3, text.indexOf(QLatin1Char(')'), at) - at - 3).toInt();
        emulator::Unit &u = (*unit)->unit();
        const bool level = u.input(in);
        QTimer::singleShot(150, [&u, in, level] { u.setInput(in, !level); });
        QTimer::singleShot(600, [&u, in, level] { u.setInput(in, level); });
    }
};

TEST(Commission, ProbeStepsOnTheEmulatorHoldAndMoveNothing)
{
    ensureApplication();
    const auto profile = machine::defaultMachineConfig(protocol::Variant::Gve114);
    CommissionResult r = startCommission(profile, "emulator");
    driver::TraceRecorder recorder;
    auto *emu = new driver::EmulatorTransport(driver::unitOptionsFor(profile), {});
    driver::TracingTransport traced(emu, recorder, {});
    QString error;
    ASSERT_TRUE(runUnitProbe(traced, profile, 115200, r, &error)) << error.toStdString();
    EXPECT_EQ(r.step("identify")->result, StepResult::Held)
        << r.step("identify")->details.toStdString();
    EXPECT_EQ(r.step("readings")->result, StepResult::Held)
        << r.step("readings")->details.toStdString();
    EXPECT_EQ(r.step("eeprom")->result, StepResult::Held)
        << r.step("eeprom")->details.toStdString();
    EXPECT_EQ(r.variantId, "gve114");
    EXPECT_FALSE(r.eeprom.empty());
    EXPECT_EQ(r.link.classes.size(), 4u);
    for (const auto &c : r.readings)
        EXPECT_NE(c.result, StepResult::DidNotHold)
            << c.reading.toStdString() << ": " << c.details.toStdString();
    // The emulator saw one wrong checksum and nothing that moved.
    EXPECT_EQ(emu->unit().stats().checksumErrors, 1);
    EXPECT_EQ(emu->unit().position(), (std::array<std::int64_t, 4>{}));
    EXPECT_EQ(emu->unit().outputs(), 0xFF);
    const std::string trace = emulator::formatTrace(recorder.snapshot());
    EXPECT_NE(trace.find("!0%+"), std::string::npos);
    EXPECT_EQ(trace.find("!0C"), std::string::npos);
    // Every step that needs the operator is still to do.
    for (const auto &s : r.steps) {
        if (s.needsOperator) {
            EXPECT_EQ(s.result, StepResult::NotChecked) << s.id;
        }
    }
}

TEST(Commission, OperatorStepsMoveSwitchAndHome)
{
    ensureApplication();
    const auto profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
    CommissionResult r = startCommission(profile, "emulator");
    driver::EmulatorTransport *emu = nullptr;
    driver::TraceRecorder recorder;
    // Owned here, not by the driver's worker: the emulator is asked after the steps ended.
    std::unique_ptr<driver::TracingTransport> transport;
    MoveOptions options;
    options.watchSwitchS = 10;
    options.factory = [&](const driver::ConnectionSettings &, const machine::MachineConfig &c,
                          QObject *, QString *) -> driver::Transport * {
        emu = new driver::EmulatorTransport(driver::unitOptionsFor(c), {});
        transport = std::make_unique<driver::TracingTransport>(
            emu, recorder, std::vector<std::pair<std::string, std::string>>{});
        return transport.get();
    };
    ScriptedOperator op;
    op.unit = &emu;
    runOperatorSteps(QStringLiteral("emulator"), 115200, r, op, options);
    ASSERT_NE(emu, nullptr);
    for (const auto &s : r.steps) {
        if (s.needsOperator) {
            EXPECT_EQ(s.result, StepResult::Held) << s.id << ": " << s.details.toStdString();
        }
    }
    // X moved 5 mm and back: 4.9 mm measured corrects its steps per mm by 5/4.9.
    ASSERT_FALSE(r.axes.empty());
    const double spm = profile.axes[0].stepsPerMm;
    ASSERT_TRUE(r.axes[0].stepsPerMmProposed);
    EXPECT_NEAR(*r.axes[0].stepsPerMmProposed, spm * 5.0 / 4.9, 1e-6);
    EXPECT_NEAR(r.profileAfter.axes[0].stepsPerMm, spm * 5.0 / 4.9, 1e-6);
    // The wire: the jogs, the spindle at 250 and 500 per mille and off, the coolant on and off,
    // homing with W; the emulator ends homed at the profile's home positions, spindle off.
    const std::string trace = emulator::formatTrace(recorder.snapshot());
    for (const char *sent : {"!7V250", "!7V500", "!7V0", "!0WX", "!0WZ"})
        EXPECT_NE(trace.find(sent), std::string::npos) << sent;
    EXPECT_FALSE(emu->unit().spindleTurning());
    EXPECT_EQ(emu->unit().outputs() & 0x0E, 0x0E); // OUT1..OUT3 off again
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(emu->unit().position()[static_cast<std::size_t>(a)],
                  machine::stepsOf(profile.axes[static_cast<std::size_t>(a)].homing.homePositionMm,
                                   profile.axes[static_cast<std::size_t>(a)].stepsPerMm))
            << a;
    // The report says it all, and the saved profile is not the original.
    const QString report = commissionReportText(r);
    EXPECT_TRUE(report.contains(QLatin1String("proposed steps/mm"))) << report.toStdString();
}

} // namespace
} // namespace frezka::session
