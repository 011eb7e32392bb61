#include "emuoptions.h"

#include "driver/emulator/surface.h"
#include "protocol/variant.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace frezka::gveemu {
namespace {

// lupdate files these tr() calls under the enclosing namespace, so that is the context.
QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::gveemu", text);
}

int axisFromLetter(QChar c)
{
    return QStringLiteral("XYZA").indexOf(c.toUpper());
}

// AXIS=POS[,+|-] -> switch; `input` < 0 means the axis' home input (IN0..IN3).
bool parseSwitch(const QString &spec, int input, emulator::PositionSwitch &sw)
{
    const auto eq = spec.indexOf(QLatin1Char('='));
    if (eq != 1)
        return false;
    const int axis = axisFromLetter(spec.at(0));
    if (axis < 0)
        return false;
    QString rest = spec.mid(2);
    int side = -1;
    if (rest.endsWith(QLatin1String(",+")) || rest.endsWith(QLatin1String(",-"))) {
        side = rest.endsWith(QLatin1Char('+')) ? 1 : -1;
        rest.chop(2);
    }
    bool ok = false;
    const qlonglong pos = rest.toLongLong(&ok);
    if (!ok)
        return false;
    sw = {input < 0 ? axis : input, axis, pos, side};
    return true;
}

bool parseRate(const QString &text, double &out)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !(v >= 0 && v <= 1))
        return false;
    out = v;
    return true;
}

// --units A:ID,... -> the units of the shared line, each a copy of `base` with its address and
// variant; address 7 for the first that has a spindle output.
bool parseUnits(const QString &spec, emulator::SimulationOptions &sim, QString &error)
{
    const emulator::UnitOptions base = sim.unit;
    std::vector<emulator::UnitOptions> units;
    bool spindleTaken = false;
    for (const QString &item : spec.split(QLatin1Char(','))) {
        const QStringList parts = item.split(QLatin1Char(':'));
        bool ok = parts.size() == 2;
        const int address = ok ? parts[0].toInt(&ok) : -1;
        const auto variant = ok ? protocol::variantFromId(parts[1].toStdString()) : std::nullopt;
        if (!ok || address < 0 || address > 6 || !variant) {
            error = tr("cannot read the unit '%1' of --units: write ADDRESS:VARIANT with an "
                       "address 0..6, e.g. 0:gve114,1:gve114")
                        .arg(item);
            return false;
        }
        for (const auto &other : units) {
            if (other.address == address) {
                error = tr("--units names address %1 twice: give each unit its own address")
                            .arg(address);
                return false;
            }
        }
        emulator::UnitOptions u = base;
        u.address = address;
        u.variant = *variant;
        u.spindleAddress = !spindleTaken && protocol::variantInfo(*variant).hasSpindleAddress7;
        spindleTaken = spindleTaken || u.spindleAddress;
        if (!base.eepromFile.empty())
            u.eepromFile = base.eepromFile + "." + std::to_string(address);
        units.push_back(std::move(u));
    }
    sim.unit = units.front();
    sim.moreUnits.assign(units.begin() + 1, units.end());
    return true;
}

// Every unit of a shared line hears the line's one speed (GVE114 manual §9.5).
bool checkLineBaud(const emulator::SimulationOptions &sim, QString &error)
{
    std::vector<emulator::UnitOptions> units{sim.unit};
    units.insert(units.end(), sim.moreUnits.begin(), sim.moreUnits.end());
    for (const auto &u : units) {
        const auto &info = protocol::variantInfo(u.variant);
        if (std::find(info.bauds.begin(), info.bauds.end(), sim.wire.baud) == info.bauds.end()) {
            error =
                tr("%1 Bd is not a baud rate of the %2")
                    .arg(sim.wire.baud)
                    .arg(QString::fromUtf8(info.displayName.data(), int(info.displayName.size())));
            return false;
        }
    }
    return true;
}

} // namespace

QString emuHelpText()
{
    return tr(
        "Usage: gve-emu [options]\n"
        "Serves an emulated GVE interpolator on a new pseudo-terminal in real time.\n"
        "The first line printed on stdout is the terminal path to open (e.g. /dev/pts/5).\n"
        "Stop it with Ctrl+C (SIGINT) or SIGTERM.\n"
        "\n"
        "Options:\n"
        "  --variant ID        gve84 | gve64 | gve64-phantom | gve114 (default gve64)\n"
        "  --baud N            line speed, one of the variant's rates (default 115200)\n"
        "  --max-rate N        maximum pulse rate of the unit, pulses/s (one of the\n"
        "                      variant's orderable rates; default the variant's default)\n"
        "  --firmware TEXT     the reply to '?', e.g. \"IP64MPG v17 1.2.2009\": an older\n"
        "                      GVE64 firmware lacks MPG and EEPROM floats (v10), VK/VL/XM\n"
        "                      and N<axis> (v19) (default the variant's)\n"
        "  --bad-checksum-code N  reply code 0..7 to a command with a wrong checksum, for\n"
        "                      testing a unit that differs from the adopted reading (4)\n"
        "  --address N         unit address 0..6 (default 0)\n"
        "  --units A:ID,...    several units on the one line, e.g. 0:gve114,1:gve114:\n"
        "                      each answers only its address (0..6), all share the wire\n"
        "                      and its time; address 7 (the spindle) is the first unit's\n"
        "                      that has one; the other options apply to every unit\n"
        "                      (--eeprom FILE keeps unit A's EEPROM in FILE.A)\n"
        "  --latency MS        added delay each way, milliseconds (default 0)\n"
        "  --latency-to-unit MS, --latency-to-pc MS   the same for one direction\n"
        "  --seed N            seed of the fault injector (default 1)\n"
        "  --corrupt P         probability per byte of a flipped bit, both ways (0..1)\n"
        "  --drop P            probability per byte that it is lost, both ways\n"
        "  --duplicate P       probability per byte that it arrives twice, both ways\n"
        "  --lose-reply P      probability that a whole reply is lost\n"
        "  --eeprom FILE       keep the EEPROM in FILE (read at start, written on EW/EFW/EUW)\n"
        "  --home AXIS=POS[,+|-]   home switch of AXIS (X, Y, Z, A on IN0..IN3): it is\n"
        "                      pressed at and below POS (-, default) or at and above (+)\n"
        "  --limit IN:AXIS=POS[,+|-]  input IN (0..15) pressed by AXIS beyond POS, e.g.\n"
        "                      --limit 6:X=200000,+ (GVE64 end switch X)\n"
        "  --surface SPEC      the work's top, touched by the tool probe (IN15), in machine\n"
        "                      mm: plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or\n"
        "                      warp:Z0,DZDX,DZDY,AMP,PERIOD (the plane plus the sine)\n"
        "  --steps-per-mm N[,N,N]  steps per mm of X, Y, Z for --surface (default 200)\n"
        "  --probe-contact 0|1 the IN15 level at contact (default 0, as the shipped\n"
        "                      profiles' EEPROM polarity)\n"
        "  --link PATH         also create a symlink PATH to the terminal\n"
        "  --replay TRACE      answer as the unit recorded in TRACE did (a serial trace,\n"
        "                      docs/serial-trace.md): each recorded reply when the driver\n"
        "                      sends the command before it, with its timing; a command\n"
        "                      that differs ends gve-emu with the trace line (exit 3)\n"
        "  --com-switch N      the COM SPEED switch, 0..3 (sw1 sw2 OFF OFF .. ON ON): the\n"
        "                      unit listens at its speed in the range of EEPROM 0x0D,\n"
        "                      read at start; a client at another speed is not heard\n"
        "                      (default: not modelled, any speed is heard)\n"
        "  --analog-jumper ana|pwm  the board's ANA/PWM jumper (default ana)\n"
        "  --wheel             turn the MPG handwheel from stdin, one line per turn:\n"
        "                      AXIS STEP DETENTS, e.g. \"X 10 -5\" (AXIS X, Y, Z, A or 4,\n"
        "                      STEP 1, 10 or 100; the unit moves by its EEPROM's MPG)\n"
        "  --verbose           log every byte to stderr\n"
        "  --help              this text\n"
        "  --version           the version\n");
}

// One branch per option of the usage text above, in its order: long as the list is, kept whole
// so that the usage and the parser are read side by side.
bool parseEmuOptions(const QStringList &args, EmuOptions &options, QString &error)
{
    using protocol::variantInfo;
    auto &unit = options.simulation.unit;
    auto &wire = options.simulation.wire;
    int baud = 0;
    QString units;                    // --units, applied after the options every unit shares
    unit.surface.contactHigh = false; // the shipped profiles' IN15 polarity (EEPROM ST3 bit 7)
    for (int i = 0; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (a == QLatin1String("--help") || a == QLatin1String("-h")) {
            options.help = true;
            return true;
        }
        if (a == QLatin1String("--verbose") || a == QLatin1String("--wheel")) {
            (a == QLatin1String("--wheel") ? options.wheel : options.verbose) = true;
            continue;
        }
        if (i + 1 >= args.size()) {
            error = tr("%1 needs a value (see --help)").arg(a);
            return false;
        }
        const QString v = args.at(++i);
        bool ok = true;
        if (a == QLatin1String("--variant")) {
            const auto variant = protocol::variantFromId(v.toStdString());
            ok = variant.has_value();
            if (ok)
                unit.variant = *variant;
        } else if (a == QLatin1String("--baud")) {
            baud = v.toInt(&ok);
        } else if (a == QLatin1String("--max-rate")) {
            unit.maxPulseRate = v.toInt(&ok);
        } else if (a == QLatin1String("--firmware")) {
            unit.firmware = v.toStdString();
            ok = !unit.firmware.empty();
        } else if (a == QLatin1String("--bad-checksum-code")) {
            unit.badChecksumCode = v.toInt(&ok);
            ok = ok && unit.badChecksumCode >= 0 && unit.badChecksumCode <= 7;
        } else if (a == QLatin1String("--address")) {
            unit.address = v.toInt(&ok);
            ok = ok && unit.address >= 0 && unit.address <= 6;
        } else if (a == QLatin1String("--units")) {
            units = v;
        } else if (a == QLatin1String("--latency") || a == QLatin1String("--latency-to-unit") ||
                   a == QLatin1String("--latency-to-pc")) {
            const double ms = v.toDouble(&ok);
            ok = ok && ms >= 0 && ms <= 10000;
            if (a != QLatin1String("--latency-to-pc"))
                wire.latencyPcToUnitS = ms / 1000.0;
            if (a != QLatin1String("--latency-to-unit"))
                wire.latencyUnitToPcS = ms / 1000.0;
        } else if (a == QLatin1String("--seed")) {
            wire.seed = v.toULongLong(&ok);
        } else if (a == QLatin1String("--corrupt")) {
            ok = parseRate(v, wire.pcToUnit.corruptByteRate);
            wire.unitToPc.corruptByteRate = wire.pcToUnit.corruptByteRate;
        } else if (a == QLatin1String("--drop")) {
            ok = parseRate(v, wire.pcToUnit.dropByteRate);
            wire.unitToPc.dropByteRate = wire.pcToUnit.dropByteRate;
        } else if (a == QLatin1String("--duplicate")) {
            ok = parseRate(v, wire.pcToUnit.duplicateByteRate);
            wire.unitToPc.duplicateByteRate = wire.pcToUnit.duplicateByteRate;
        } else if (a == QLatin1String("--lose-reply")) {
            ok = parseRate(v, wire.unitToPc.loseMessageRate);
        } else if (a == QLatin1String("--eeprom")) {
            unit.eepromFile = v.toStdString();
            ok = !v.isEmpty();
        } else if (a == QLatin1String("--home")) {
            emulator::PositionSwitch sw;
            ok = parseSwitch(v, -1, sw);
            if (ok)
                unit.switches.push_back(sw);
        } else if (a == QLatin1String("--limit")) {
            const auto colon = v.indexOf(QLatin1Char(':'));
            const int input = colon > 0 ? v.left(colon).toInt(&ok) : -1;
            emulator::PositionSwitch sw;
            ok = ok && input >= 0 && input <= 15 && parseSwitch(v.mid(colon + 1), input, sw);
            if (ok)
                unit.switches.push_back(sw);
        } else if (a == QLatin1String("--surface")) {
            ok = emulator::parseProbeSurface(v.toStdString(), &unit.surface);
        } else if (a == QLatin1String("--steps-per-mm")) {
            const QStringList parts = v.split(QLatin1Char(','));
            ok = parts.size() == 1 || parts.size() == 3;
            for (std::size_t k = 0; ok && k < 3; ++k) {
                const double n = parts[parts.size() == 1 ? 0 : qsizetype(k)].toDouble(&ok);
                ok = ok && n > 0;
                unit.surface.stepsPerMm[k] = n;
            }
        } else if (a == QLatin1String("--probe-contact")) {
            ok = v == QLatin1String("0") || v == QLatin1String("1");
            unit.surface.contactHigh = v == QLatin1String("1");
        } else if (a == QLatin1String("--com-switch")) {
            unit.baudSwitch = v.toInt(&ok);
            ok = ok && unit.baudSwitch >= 0 && unit.baudSwitch <= 3;
        } else if (a == QLatin1String("--analog-jumper")) {
            ok = v == QLatin1String("ana") || v == QLatin1String("pwm");
            unit.analogJumper = v == QLatin1String("pwm") ? emulator::AnalogJumper::Pwm
                                                          : emulator::AnalogJumper::Analog;
        } else if (a == QLatin1String("--link")) {
            options.linkPath = v;
        } else if (a == QLatin1String("--replay")) {
            options.replayFile = v;
        } else {
            error = tr("unknown option %1 (see --help)").arg(a);
            return false;
        }
        if (!ok) {
            error = tr("invalid value '%1' for %2 (see --help)").arg(v, a);
            return false;
        }
    }
    if (!units.isEmpty() && !parseUnits(units, options.simulation, error))
        return false;
    const auto &info = variantInfo(unit.variant);
    wire.baud = baud ? baud : info.defaultBaud;
    if (!checkLineBaud(options.simulation, error))
        return false;
    if (unit.maxPulseRate != 0 && std::find(info.maxPulseRates.begin(), info.maxPulseRates.end(),
                                            unit.maxPulseRate) == info.maxPulseRates.end()) {
        error = tr("%1 pulses/s is not an orderable rate of the %2")
                    .arg(unit.maxPulseRate)
                    .arg(QString::fromUtf8(info.displayName.data(), int(info.displayName.size())));
        return false;
    }
    const auto family =
        unit.variant == protocol::Variant::Gve64Phantom ? protocol::Variant::Gve64 : unit.variant;
    if (!unit.firmware.empty() && protocol::variantFromFirmware(unit.firmware) != family) {
        error = tr("'%1' is not a firmware string of the %2")
                    .arg(QString::fromStdString(unit.firmware))
                    .arg(QString::fromUtf8(info.displayName.data(), int(info.displayName.size())));
        return false;
    }
    for (const auto &sw : unit.switches) {
        if (sw.axis >= info.axisCount) {
            error =
                tr("the %1 has no axis A")
                    .arg(QString::fromUtf8(info.displayName.data(), int(info.displayName.size())));
            return false;
        }
    }
    return true;
}

bool parseWheelLine(const QString &line, WheelTurn &turn, QString &error)
{
    const QStringList parts = line.simplified().split(QLatin1Char(' '));
    static const QString kAxes = QStringLiteral("XYZA4");
    bool ok = parts.size() == 3 && parts[0].size() == 1 && kAxes.contains(parts[0].toUpper());
    if (ok) {
        const int axis = int(kAxes.indexOf(parts[0].toUpper()));
        turn.axisPosition = axis == 4 ? 3 : axis;
        turn.multiplier = parts[1].toInt(&ok);
        ok = ok && (turn.multiplier == 1 || turn.multiplier == 10 || turn.multiplier == 100);
    }
    if (ok)
        turn.detents = parts[2].toInt(&ok);
    if (!ok)
        error = tr("cannot read the wheel turn '%1': write AXIS STEP DETENTS, e.g. X 10 -5")
                    .arg(line.trimmed());
    return ok;
}

} // namespace frezka::gveemu
