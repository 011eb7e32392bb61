<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>CommissionCli</name>
    <message>
        <source>usage: frezka-cli commission --port PATH [--machine PROFILE] [--baud N] --report FILE [--profile-out FILE]
</source>
        <translation>usage: frezka-cli commission --port PATH [--machine PROFILE] [--baud N] --report FILE [--profile-out FILE]
</translation>
    </message>
    <message>
        <source>frezka-cli commission: bad option &apos;%1&apos;
</source>
        <translation>frezka-cli commission: bad option &apos;%1&apos;
</translation>
    </message>
    <message>
        <source>frezka-cli commission: --port and --report are needed
</source>
        <translation>frezka-cli commission: --port and --report are needed
</translation>
    </message>
    <message>
        <source>frezka-cli commission: cannot open %1: %2
</source>
        <translation>frezka-cli commission: cannot open %1: %2
</translation>
    </message>
    <message>
        <source>Run this step? (y = run, n = skip)</source>
        <translation>Run this step? (y = run, n = skip)</translation>
    </message>
    <message>
        <source>no terminal on standard input: nobody to confirm it; run frezka-cli commission in a terminal</source>
        <translation>no terminal on standard input: nobody to confirm it; run frezka-cli commission in a terminal</translation>
    </message>
    <message>
        <source>the port could not be opened</source>
        <translation>the port could not be opened</translation>
    </message>
    <message>
        <source>Skipped (they move or need the operator):
</source>
        <translation>Skipped (they move or need the operator):
</translation>
    </message>
    <message>
        <source>Report written to %1
</source>
        <translation>Report written to %1
</translation>
    </message>
    <message>
        <source>Updated profile written to %1
</source>
        <translation>Updated profile written to %1
</translation>
    </message>
</context>
<context>
    <name>ControllerHeader</name>
    <message>
        <source>The header &quot;%1&quot; holds &apos;%2&apos;, which the controller cannot show (it shows letters without diacritics, digits and signs). Replace it.</source>
        <translation>The header &quot;%1&quot; holds &apos;%2&apos;, which the controller cannot show (it shows letters without diacritics, digits and signs). Replace it.</translation>
    </message>
    <message>
        <source>The header &quot;%1&quot; is sent as &quot;%2&quot;: the controller has no Czech letters, so they become their base letters.</source>
        <translation>The header &quot;%1&quot; is sent as &quot;%2&quot;: the controller has no Czech letters, so they become their base letters.</translation>
    </message>
</context>
<context>
    <name>EdgeCli</name>
    <message>
        <source>usage: frezka-cli probe corner --x-direction +|- --y-direction +|- --tool-diameter MM [--reach MM] [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>usage: frezka-cli probe corner --x-direction +|- --y-direction +|- --tool-diameter MM [--reach MM] [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>usage: frezka-cli probe edge --axis x|y --direction +|- --tool-diameter MM [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>usage: frezka-cli probe edge --axis x|y --direction +|- --tool-diameter MM [--travel MM] [--feed MM/MIN] [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>--tool-diameter %1: the diameter of the tool (or the probe&apos;s ball) must be 0 mm or more.</source>
        <translation>--tool-diameter %1: the diameter of the tool (or the probe&apos;s ball) must be 0 mm or more.</translation>
    </message>
    <message>
        <source>--travel %1: how far the probe may move toward the edge must be above 0 mm.</source>
        <translation>--travel %1: how far the probe may move toward the edge must be above 0 mm.</translation>
    </message>
    <message>
        <source>--retract %1: the back-off before the slow probe must be above 0 mm.</source>
        <translation>--retract %1: the back-off before the slow probe must be above 0 mm.</translation>
    </message>
    <message>
        <source>--reach %1: the move beside an outside corner&apos;s face must be 0 mm (an inside corner) or more.</source>
        <translation>--reach %1: the move beside an outside corner&apos;s face must be 0 mm (an inside corner) or more.</translation>
    </message>
    <message>
        <source>frezka-cli probe %1: %2
</source>
        <translation>frezka-cli probe %1: %2
</translation>
    </message>
    <message>
        <source>%1 is now X %2, Y %3 (machine mm of its zero): the %4 is the work&apos;s zero, with the tool&apos;s radius of %5 mm taken into account. Give the next commands --offset %6.
</source>
        <translation>%1 is now X %2, Y %3 (machine mm of its zero): the %4 is the work&apos;s zero, with the tool&apos;s radius of %5 mm taken into account. Give the next commands --offset %6.
</translation>
    </message>
    <message>
        <source>corner</source>
        <translation>corner</translation>
    </message>
    <message>
        <source>edge</source>
        <translation>edge</translation>
    </message>
</context>
<context>
    <name>EmulatorTransport</name>
    <message>
        <source>built-in %1 emulator</source>
        <translation>built-in %1 emulator</translation>
    </message>
</context>
<context>
    <name>GrinderCli</name>
    <message>
        <source>--header: &apos;%1&apos; is longer than 16 characters</source>
        <translation>--header: &apos;%1&apos; is longer than 16 characters</translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not a baud rate</source>
        <translation>--baud: &apos;%1&apos; is not a baud rate</translation>
    </message>
    <message>
        <source>--retries: &apos;%1&apos; is not 0 to 100</source>
        <translation>--retries: &apos;%1&apos; is not 0 to 100</translation>
    </message>
    <message>
        <source>--reply-timeout-ms: &apos;%1&apos; is not 100 to 600000</source>
        <translation>--reply-timeout-ms: &apos;%1&apos; is not 100 to 600000</translation>
    </message>
    <message>
        <source>--form: &apos;%1&apos; is not 1 or 2</source>
        <translation>--form: &apos;%1&apos; is not 1 or 2</translation>
    </message>
    <message>
        <source>unknown option &apos;%1&apos;</source>
        <translation>unknown option &apos;%1&apos;</translation>
    </message>
    <message>
        <source>frezka-cli grinder: unknown action &apos;%1&apos;
</source>
        <translation>frezka-cli grinder: unknown action &apos;%1&apos;
</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>unexpected argument &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1 needs a value</source>
        <translation>%1 needs a value</translation>
    </message>
    <message>
        <source>--port PATH is required</source>
        <translation>--port PATH is required</translation>
    </message>
    <message>
        <source>%1 needs a FILE</source>
        <translation>%1 needs a FILE</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 left</source>
        <translation>%1 left</translation>
    </message>
    <message>
        <source>frezka-cli grinder: %1 failed (%2): %3
</source>
        <translation>frezka-cli grinder: %1 failed (%2): %3
</translation>
    </message>
    <message>
        <source>Repeats: %1 (NAK %2, bad checksum %3), noise bytes skipped: %4
</source>
        <translation>Repeats: %1 (NAK %2, bad checksum %3), noise bytes skipped: %4
</translation>
    </message>
    <message>
        <source>Inner blocks: %1
</source>
        <translation>Inner blocks: %1
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: cannot write %1: %2 (the data were received but not saved)
</source>
        <translation>frezka-cli grinder: cannot write %1: %2 (the data were received but not saved)
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: cannot read %1: %2
</source>
        <translation>frezka-cli grinder: cannot read %1: %2
</translation>
    </message>
    <message>
        <source>Note: TCHIN programs show &quot;no prg set&quot; once until the X axis is set up: select the program in AUT and hold RES.
</source>
        <translation>Note: TCHIN programs show &quot;no prg set&quot; once until the X axis is set up: select the program in AUT and hold RES.
</translation>
    </message>
    <message>
        <source>Z = %1 mm
</source>
        <translation>Z = %1 mm
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: --go needs FORM=1; FORM=2 only reports
</source>
        <translation>frezka-cli grinder: --go needs FORM=1; FORM=2 only reports
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: no FORM=2 position frame within %1 s
</source>
        <translation>frezka-cli grinder: no FORM=2 position frame within %1 s
</translation>
    </message>
    <message>
        <source>Moving to %1 mm...
</source>
        <translation>Moving to %1 mm...
</translation>
    </message>
    <message>
        <source>--go: &apos;%1&apos; is not a position from -9999.999 to 9999.999 mm (e.g. 12.5)</source>
        <translation>--go: &apos;%1&apos; is not a position from -9999.999 to 9999.999 mm (e.g. 12.5)</translation>
    </message>
    <message>
        <source>frezka-cli grinder: cannot write %1: %2; nothing was asked from the controller
</source>
        <translation>frezka-cli grinder: cannot write %1: %2; nothing was asked from the controller
</translation>
    </message>
    <message>
        <source>--header: ANC messages carry no header (ANCLOAD sent none); leave it out or choose --family k51 or hedit</source>
        <translation>--header: ANC messages carry no header (ANCLOAD sent none); leave it out or choose --family k51 or hedit</translation>
    </message>
    <message>
        <source>frezka-cli grinder: %1 is damaged: %2; nothing was sent
</source>
        <translation>frezka-cli grinder: %1 is damaged: %2; nothing was sent
</translation>
    </message>
    <message>
        <source>frezka-cli grinder: %1 holds %2 data (saved from a %2 control), not %3: is the wrong system selected? Use --family %4.
</source>
        <translation>frezka-cli grinder: %1 holds %2 data (saved from a %2 control), not %3: is the wrong system selected? Use --family %4.
</translation>
    </message>
    <message>
        <source>usage: frezka-cli grinder ping|save|load --port PATH [--family k51|anc|hedit|table]
                          [--baud N] [--header TEXT] [--retries N]
                          [--reply-timeout-ms N] [--send-anyway] [--raw] FILE
       frezka-cli grinder z --port PATH [--baud N] [--form 1|2] [--go MM]
                          [--reply-timeout-ms N]
  ping   link check (ENQ/ACK)
  save   controller -&gt; PC: write the controller&apos;s data to FILE, byte for byte, with
         its header and system (a FILE ending in .bin, or --raw: the bare data, as
         the old tools wrote)
  load   PC -&gt; controller: send FILE unchanged; the 16-character header is --header
         or the one saved in FILE or, as K51LOAD 2.20 did, the file name (Czech
         letters become their base letters); the file&apos;s length and inner blocks
         are checked first and nothing is sent when they are wrong
         --family table sends an APROXTAB table (LOA1) to a K51 set to table
         transfer (KONFIG6 = 3); a table cannot be saved
  z      Z-position link: print the table position (FORM=1 asks with Z?, FORM=2
         waits for a binary frame); --go MM moves the table and waits until reached
  --baud N               line rate (default: ANC 4800 Bd, as ANCLOAD/ANCSAVE; K51 and
                         HEDIT 9600 Bd)
  --retries N            repeats after a timeout, NAK or bad checksum (default 3)
  --reply-timeout-ms N   silence allowed before a reply (default 3000; 10000 for
                         the data after a request)
  --send-anyway          load a file whose inner blocks have a wrong checksum (only
                         if the controller itself gave it to you)
  --go MM                -9999.999 to 9999.999 mm
  --help                 this text
Exit status: 0 done, 1 transfer failed (the reason is printed), 2 usage error.
</source>
        <translation>usage: frezka-cli grinder ping|save|load --port PATH [--family k51|anc|hedit|table]
                          [--baud N] [--header TEXT] [--retries N]
                          [--reply-timeout-ms N] [--send-anyway] [--raw] FILE
       frezka-cli grinder z --port PATH [--baud N] [--form 1|2] [--go MM]
                          [--reply-timeout-ms N]
  ping   link check (ENQ/ACK)
  save   controller -&gt; PC: write the controller&apos;s data to FILE, byte for byte, with
         its header and system (a FILE ending in .bin, or --raw: the bare data, as
         the old tools wrote)
  load   PC -&gt; controller: send FILE unchanged; the 16-character header is --header
         or the one saved in FILE or, as K51LOAD 2.20 did, the file name (Czech
         letters become their base letters); the file&apos;s length and inner blocks
         are checked first and nothing is sent when they are wrong
         --family table sends an APROXTAB table (LOA1) to a K51 set to table
         transfer (KONFIG6 = 3); a table cannot be saved
  z      Z-position link: print the table position (FORM=1 asks with Z?, FORM=2
         waits for a binary frame); --go MM moves the table and waits until reached
  --baud N               line rate (default: ANC 4800 Bd, as ANCLOAD/ANCSAVE; K51 and
                         HEDIT 9600 Bd)
  --retries N            repeats after a timeout, NAK or bad checksum (default 3)
  --reply-timeout-ms N   silence allowed before a reply (default 3000; 10000 for
                         the data after a request)
  --send-anyway          load a file whose inner blocks have a wrong checksum (only
                         if the controller itself gave it to you)
  --go MM                -9999.999 to 9999.999 mm
  --help                 this text
Exit status: 0 done, 1 transfer failed (the reason is printed), 2 usage error.
</translation>
    </message>
    <message>
        <source>--family: &apos;%1&apos; is not k51, anc, hedit or table</source>
        <translation>--family: &apos;%1&apos; is not k51, anc, hedit or table</translation>
    </message>
</context>
<context>
    <name>LinkWorker</name>
    <message>
        <source>connected: %1</source>
        <translation>connected: %1</translation>
    </message>
    <message>
        <source>no serial port given</source>
        <translation>no serial port given</translation>
    </message>
    <message>
        <source>unknown connection kind</source>
        <translation>unknown connection kind</translation>
    </message>
    <message>
        <source>simulated handwheel: not connected to the built-in emulator; turn the unit&apos;s own MPG wheel</source>
        <translation>simulated handwheel: not connected to the built-in emulator; turn the unit&apos;s own MPG wheel</translation>
    </message>
    <message>
        <source>simulated handwheel: the unit ignored the turn; switch Handwheel (MPG) on, and enable the MPG in the profile&apos;s EEPROM settings</source>
        <translation>simulated handwheel: the unit ignored the turn; switch Handwheel (MPG) on, and enable the MPG in the profile&apos;s EEPROM settings</translation>
    </message>
    <message>
        <source>another unit becomes the machine only while every unit on the line is idle; wait, or stop the units, then choose again</source>
        <translation>another unit becomes the machine only while every unit on the line is idle; wait, or stop the units, then choose again</translation>
    </message>
    <message>
        <source>the units cannot share the built-in emulator&apos;s line: %1; fix line.units in the machine profile</source>
        <translation>the units cannot share the built-in emulator&apos;s line: %1; fix line.units in the machine profile</translation>
    </message>
</context>
<context>
    <name>LoadCheck</name>
    <message>
        <source>ANC</source>
        <translation>ANC</translation>
    </message>
    <message>
        <source>K51</source>
        <translation>K51</translation>
    </message>
    <message>
        <source>HEDIT</source>
        <translation>HEDIT</translation>
    </message>
    <message>
        <source>ANC program data have 21760 or 21766 bytes (0x5500 or 0x5506)</source>
        <translation>ANC program data have 21760 or 21766 bytes (0x5500 or 0x5506)</translation>
    </message>
    <message>
        <source>K51 program data have 21767 bytes (0x5507)</source>
        <translation>K51 program data have 21767 bytes (0x5507)</translation>
    </message>
    <message>
        <source>HEDIT data have 46 bytes (0x2E)</source>
        <translation>HEDIT data have 46 bytes (0x2E)</translation>
    </message>
    <message>
        <source>The file is empty; there is nothing to send.</source>
        <translation>The file is empty; there is nothing to send.</translation>
    </message>
    <message>
        <source>Sent anyway: %1 bytes, the length this controller reported.</source>
        <translation>Sent anyway: %1 bytes, the length this controller reported.</translation>
    </message>
    <message>
        <source>%1; the file has %2, so nothing was sent. Choose a file saved from this controller.</source>
        <translation>%1; the file has %2, so nothing was sent. Choose a file saved from this controller.</translation>
    </message>
    <message>
        <source>%1; the file has %2, the length of %3 data: is the wrong system selected? Nothing was sent.</source>
        <translation>%1; the file has %2, the length of %3 data: is the wrong system selected? Nothing was sent.</translation>
    </message>
    <message>
        <source>This controller reported this length: choose &quot;Send anyway&quot; to send it.</source>
        <translation>This controller reported this length: choose &quot;Send anyway&quot; to send it.</translation>
    </message>
    <message>
        <source>%1 of the %2 inner program blocks lack their AA and block number marker (%3): the file is not a program image of this system or it was changed. Nothing was sent.</source>
        <translation>%1 of the %2 inner program blocks lack their AA and block number marker (%3): the file is not a program image of this system or it was changed. Nothing was sent.</translation>
    </message>
    <message>
        <source>inner blocks with a wrong checksum: %1</source>
        <translation>inner blocks with a wrong checksum: %1</translation>
    </message>
    <message>
        <source>The file has %1. Nothing was sent. If the controller itself gave you this file, choose &quot;Send anyway&quot;: it gets the data unchanged.</source>
        <translation>The file has %1. Nothing was sent. If the controller itself gave you this file, choose &quot;Send anyway&quot;: it gets the data unchanged.</translation>
    </message>
    <message>
        <source>Sent anyway: %1.</source>
        <translation>Sent anyway: %1.</translation>
    </message>
</context>
<context>
    <name>ProbeCli</name>
    <message>
        <source>usage: frezka-cli probe z-plate --plate MM [--feed MM/MIN] [--slow-feed MM/MIN] [--depth MM] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>usage: frezka-cli probe z-plate --plate MM [--feed MM/MIN] [--slow-feed MM/MIN] [--depth MM] [--retract MM] [--port PATH|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>--plate %1: the plate&apos;s thickness must be 0 mm or more (0: the tool touches the work itself).</source>
        <translation>--plate %1: the plate&apos;s thickness must be 0 mm or more (0: the tool touches the work itself).</translation>
    </message>
    <message>
        <source>--depth %1: how far below the start the probe may go must be above 0 mm.</source>
        <translation>--depth %1: how far below the start the probe may go must be above 0 mm.</translation>
    </message>
    <message>
        <source>--retract %1: the back-off above the plate must be above 0 mm.</source>
        <translation>--retract %1: the back-off above the plate must be above 0 mm.</translation>
    </message>
    <message>
        <source>--slow-feed %1: the slow probe&apos;s feed must be above 0 mm/min.</source>
        <translation>--slow-feed %1: the slow probe&apos;s feed must be above 0 mm/min.</translation>
    </message>
    <message>
        <source>frezka-cli probe z-plate: %1
</source>
        <translation>frezka-cli probe z-plate: %1
</translation>
    </message>
    <message>
        <source>The plate&apos;s top touched at machine Z %1; %2 Z is now %3 (was %4), so the work&apos;s top under the %5 mm plate is Z 0 and the tool stands at Z %6. Give the next commands --offset %7.
</source>
        <translation>The plate&apos;s top touched at machine Z %1; %2 Z is now %3 (was %4), so the work&apos;s top under the %5 mm plate is Z 0 and the tool stands at Z %6. Give the next commands --offset %7.
</translation>
    </message>
    <message>
        <source>usage: frezka-cli probe tool-length --tool N [--table FILE] [--port PATH|sim] [--surface SPEC] [--machine PROFILE]
</source>
        <translation>usage: frezka-cli probe tool-length --tool N [--table FILE] [--port PATH|sim] [--surface SPEC] [--machine PROFILE]
</translation>
    </message>
    <message>
        <source>frezka-cli probe tool-length: %1
</source>
        <translation>frezka-cli probe tool-length: %1
</translation>
    </message>
    <message>
        <source>Tool %1 is %2 mm long (tripped at machine Z %3). The profile names no tool table: set tools.tableFile to keep it, or apply it with G43.1 Z%2.
</source>
        <translation>Tool %1 is %2 mm long (tripped at machine Z %3). The profile names no tool table: set tools.tableFile to keep it, or apply it with G43.1 Z%2.
</translation>
    </message>
    <message>
        <source>Tool %1 is %2 mm long (tripped at machine Z %3); written to %4.
</source>
        <translation>Tool %1 is %2 mm long (tripped at machine Z %3); written to %4.
</translation>
    </message>
    <message>
        <source>frezka-cli probe: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0], warp:Z0,DZDX,DZDY,AMP,PERIOD or block:X0,Y0,X1,Y1,TOP (machine mm)
</source>
        <translation>frezka-cli probe: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0], warp:Z0,DZDX,DZDY,AMP,PERIOD or block:X0,Y0,X1,Y1,TOP (machine mm)
</translation>
    </message>
</context>
<context>
    <name>ProbeFollow</name>
    <message>
        <source>%1: the probe move that ran does not end where the machine stopped when the program is interpreted again; it cannot go on from the probe&apos;s result.</source>
        <translation>%1: the probe move that ran does not end where the machine stopped when the program is interpreted again; it cannot go on from the probe&apos;s result.</translation>
    </message>
    <message>
        <source>the program could not be interpreted again</source>
        <translation>the program could not be interpreted again</translation>
    </message>
    <message>
        <source>%1: the program runs %2 probe moves when interpreted with the results of those run so far, fewer than the %3 the machine has run; it cannot go on from the probe&apos;s result.</source>
        <translation>%1: the program runs %2 probe moves when interpreted with the results of those run so far, fewer than the %3 the machine has run; it cannot go on from the probe&apos;s result.</translation>
    </message>
    <message>
        <source>the program could not be planned</source>
        <translation>the program could not be planned</translation>
    </message>
    <message>
        <source>Line %1: the program probes for itself: after line %2 its path depends on that probe&apos;s result, and the probes before line %1 would not run. Run the whole program.</source>
        <translation>Line %1: the program probes for itself: after line %2 its path depends on that probe&apos;s result, and the probes before line %1 would not run. Run the whole program.</translation>
    </message>
    <message>
        <source>Line %1: the program probes for itself (after this line its path depends on the probe&apos;s result): a height map cannot be applied to it. Remove the map to run the program.</source>
        <translation>Line %1: the program probes for itself (after this line its path depends on the probe&apos;s result): a height map cannot be applied to it. Remove the map to run the program.</translation>
    </message>
</context>
<context>
    <name>ProbeGridCli</name>
    <message>
        <source>usage: frezka-cli probe-grid (--area X0,Y0,X1,Y1 | --program FILE) --spacing MM --clearance MM --depth MM --feed MM/MIN --out MAP.csv [--port PATH|sim] [--surface SPEC] %1
</source>
        <translation>usage: frezka-cli probe-grid (--area X0,Y0,X1,Y1 | --program FILE) --spacing MM --clearance MM --depth MM --feed MM/MIN --out MAP.csv [--port PATH|sim] [--surface SPEC] %1
</translation>
    </message>
    <message>
        <source>frezka-cli probe-grid: --area %1: expected four numbers X0,Y0,X1,Y1 (mm), such as 0,0,80,60
</source>
        <translation>frezka-cli probe-grid: --area %1: expected four numbers X0,Y0,X1,Y1 (mm), such as 0,0,80,60
</translation>
    </message>
    <message>
        <source>%1: the program cuts nothing (no feed move or arc): give the area with --area X0,Y0,X1,Y1
</source>
        <translation>%1: the program cuts nothing (no feed move or arc): give the area with --area X0,Y0,X1,Y1
</translation>
    </message>
    <message>
        <source>frezka-cli probe-grid: %1
</source>
        <translation>frezka-cli probe-grid: %1
</translation>
    </message>
    <message>
        <source>%1 points probed, heights %2 to %3 mm from the first point (machine Z %4); the map is in %5. Set the work&apos;s Z zero on the surface at the first point (X %6, Y %7) before running with --height-map.
</source>
        <translation>%1 points probed, heights %2 to %3 mm from the first point (machine Z %4); the map is in %5. Set the work&apos;s Z zero on the surface at the first point (X %6, Y %7) before running with --height-map.
</translation>
    </message>
    <message>
        <source>frezka-cli probe-grid: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm)
</source>
        <translation>frezka-cli probe-grid: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm)
</translation>
    </message>
</context>
<context>
    <name>ProbeRunCli</name>
    <message>
        <source>could not connect to the emulator</source>
        <translation>could not connect to the emulator</translation>
    </message>
    <message>
        <source>probing did not end within a day of the emulator&apos;s time</source>
        <translation>probing did not end within a day of the emulator&apos;s time</translation>
    </message>
</context>
<context>
    <name>ProgramCli</name>
    <message>
        <source>frezka-cli: %1 needs a value
</source>
        <translation>frezka-cli: %1 needs a value
</translation>
    </message>
    <message>
        <source>frezka-cli: %1 %2: expected %3 (machine mm of the program&apos;s zero)
</source>
        <translation>frezka-cli: %1 %2: expected %3 (machine mm of the program&apos;s zero)
</translation>
    </message>
    <message>
        <source>Height map %1 applied: X %2 to %3, Y %4 to %5 mm, heights %6 to %7 mm (%8 x %9 points)
</source>
        <translation>Height map %1 applied: X %2 to %3, Y %4 to %5 mm, heights %6 to %7 mm (%8 x %9 points)
</translation>
    </message>
</context>
<context>
    <name>QSerialPort</name>
    <message>
        <source>Permission error while locking the device</source>
        <translation>Permission error while locking the device</translation>
    </message>
</context>
<context>
    <name>ReplayTransport</name>
    <message>
        <source>replay of the serial trace %1</source>
        <translation>replay of the serial trace %1</translation>
    </message>
</context>
<context>
    <name>RotaryLineCli</name>
    <message>
        <source>frezka-cli run-line: the rotary unit must be a GVE114 (only it shares its line with other units): give a GVE114 profile, --rotary-a %1:PROFILE
</source>
        <translation>frezka-cli run-line: the rotary unit must be a GVE114 (only it shares its line with other units): give a GVE114 profile, --rotary-a %1:PROFILE
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: the rotary unit&apos;s address %1 is the machine&apos;s unit&apos;s (unit.address of --machine): each unit on the line has its own address
</source>
        <translation>frezka-cli run-line: the rotary unit&apos;s address %1 is the machine&apos;s unit&apos;s (unit.address of --machine): each unit on the line has its own address
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: the rotary unit&apos;s profile has no A axis (axes.a.present is false): give a profile that sets the A axis&apos;s scale, speeds and limits, --rotary-a %1:PROFILE
</source>
        <translation>frezka-cli run-line: the rotary unit&apos;s profile has no A axis (axes.a.present is false): give a profile that sets the A axis&apos;s scale, speeds and limits, --rotary-a %1:PROFILE
</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>warning: </translation>
    </message>
    <message>
        <source>%1:%2: a probe move that turns A cannot run with A on its own unit (--rotary-a): probe without moving A
</source>
        <translation>%1:%2: a probe move that turns A cannot run with A on its own unit (--rotary-a): probe without moving A
</translation>
    </message>
    <message>
        <source>%1:%2: internal error: the program was planned without a rest around each move that turns A; please report it with the program
</source>
        <translation>%1:%2: internal error: the program was planned without a rest around each move that turns A; please report it with the program
</translation>
    </message>
</context>
<context>
    <name>RunCli</name>
    <message>
        <source><byte value="xd"/>[%1] %2% line %3 ETA %4 </source>
        <translation><byte value="xd"/>[%1] %2% line %3 ETA %4 </translation>
    </message>
    <message>
        <source>could not connect to the emulator</source>
        <translation>could not connect to the emulator</translation>
    </message>
    <message>
        <source>%1: %2
</source>
        <translation>%1: %2
</translation>
    </message>
    <message>
        <source>the job did not finish</source>
        <translation>the job did not finish</translation>
    </message>
    <message>
        <source>%1: the unit&apos;s counters differ from the planned end position
</source>
        <translation>%1: the unit&apos;s counters differ from the planned end position
</translation>
    </message>
    <message>
        <source>warning: %1
</source>
        <translation>warning: %1
</translation>
    </message>
    <message>
        <source>the scripted hold at line %1 failed %2: %3</source>
        <translation>the scripted hold at line %1 failed %2: %3</translation>
    </message>
    <message>
        <source>%1%2. Press Enter to continue.
</source>
        <translation>%1%2. Press Enter to continue.
</translation>
    </message>
    <message>
        <source>No answer on standard input: the job ends at the stop (use --continue-at-stops for an unattended run).
</source>
        <translation>No answer on standard input: the job ends at the stop (use --continue-at-stops for an unattended run).
</translation>
    </message>
    <message>
        <source>Run from line %1. %2
</source>
        <translation>Run from line %1. %2
</translation>
    </message>
    <message>
        <source>serial trace saved to %1
</source>
        <translation>serial trace saved to %1
</translation>
    </message>
    <message>
        <source>usage: frezka-cli run FILE %1 [--port PATH|sim] [--baud N] [--latency-ms N] [--faults RATE --seed N] [--clock virtual|real] [--home] [--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]] [--continue-at-stops] [--from-line N] [--trace FILE] [--surface SPEC [--cut-depth]]
</source>
        <translation>usage: frezka-cli run FILE %1 [--port PATH|sim] [--baud N] [--latency-ms N] [--faults RATE --seed N] [--clock virtual|real] [--home] [--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]] [--continue-at-stops] [--from-line N] [--trace FILE] [--surface SPEC [--cut-depth]]
</translation>
    </message>
    <message>
        <source>frezka-cli run: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm), such as plane:-5,0.001,0
</source>
        <translation>frezka-cli run: --surface %1: expected plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm), such as plane:-5,0.001,0
</translation>
    </message>
    <message>
        <source>%1:%2: the path after this probe depends on where it stops: each part is planned when the probe before it has run
</source>
        <translation>%1:%2: the path after this probe depends on where it stops: each part is planned when the probe before it has run
</translation>
    </message>
    <message>
        <source>line %1: the probe has run; the rest of the program runs as interpreted with its result
</source>
        <translation>line %1: the probe has run; the rest of the program runs as interpreted with its result
</translation>
    </message>
</context>
<context>
    <name>RunFromLine</name>
    <message>
        <source>line %1 is never reached: the program ends on line %2. Choose a line up to %2.</source>
        <translation>line %1 is never reached: the program ends on line %2. Choose a line up to %2.</translation>
    </message>
    <message>
        <source>line %1 is inside the subroutine o%2 (defined on line %3), which runs only when it is called. Choose the line that calls it, or a line outside the subroutine.</source>
        <translation>line %1 is inside the subroutine o%2 (defined on line %3), which runs only when it is called. Choose the line that calls it, or a line outside the subroutine.</translation>
    </message>
    <message>
        <source>line %1 runs only inside the subroutine o%2, called on line %3. Choose line %3, or a line outside the subroutine.</source>
        <translation>line %1 runs only inside the subroutine o%2, called on line %3. Choose line %3, or a line outside the subroutine.</translation>
    </message>
    <message>
        <source>line %1 is inside the loop o%2 that opens on line %3, so the program runs it more than once. Choose line %3, or a line after the loop.</source>
        <translation>line %1 is inside the loop o%2 that opens on line %3, so the program runs it more than once. Choose line %3, or a line after the loop.</translation>
    </message>
    <message>
        <source>line %1 is never run: the program skips it at o%2 on line %3 (a branch or a loop it does not take). Choose a line the program runs.</source>
        <translation>line %1 is never run: the program skips it at o%2 on line %3 (a branch or a loop it does not take). Choose a line the program runs.</translation>
    </message>
    <message>
        <source>%1:%2: cannot run from this line: %3</source>
        <translation>%1:%2: cannot run from this line: %3</translation>
    </message>
    <message>
        <source>no feed is in force at line %1 (no F word yet, or G93 inverse time). Choose a line after an F word in G94.</source>
        <translation>no feed is in force at line %1 (no F word yet, or G93 inverse time). Choose a line after an F word in G94.</translation>
    </message>
    <message>
        <source>tool %1 (length %2 mm)</source>
        <translation>tool %1 (length %2 mm)</translation>
    </message>
    <message>
        <source>no tool loaded by the program</source>
        <translation>no tool loaded by the program</translation>
    </message>
    <message>
        <source>Line %1: %2; the approach crosses at Z %3 (machine) and comes down at the feed to X %4 Y %5 Z %6 (machine).</source>
        <translation>Line %1: %2; the approach crosses at Z %3 (machine) and comes down at the feed to X %4 Y %5 Z %6 (machine).</translation>
    </message>
    <message>
        <source>line %1 is in a path with cutter radius compensation, turned on on line %2: where the tool runs there depends on the moves before. Choose line %2 or a line before it, or a line after G40.</source>
        <translation>line %1 is in a path with cutter radius compensation, turned on on line %2: where the tool runs there depends on the moves before. Choose line %2 or a line before it, or a line after G40.</translation>
    </message>
</context>
<context>
    <name>RunLineCli</name>
    <message>
        <source>frezka-cli run-line: cannot read --unit &apos;%1&apos;: write ADDRESS:FILE with an address 0..6, e.g. --unit 1:part.nc
</source>
        <translation>frezka-cli run-line: cannot read --unit &apos;%1&apos;: write ADDRESS:FILE with an address 0..6, e.g. --unit 1:part.nc
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: address %1 is given twice: each unit on the line has its own address
</source>
        <translation>frezka-cli run-line: address %1 is given twice: each unit on the line has its own address
</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>warning: </translation>
    </message>
    <message>
        <source>unit %1: %2
</source>
        <translation>unit %1: %2
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: %1
</source>
        <translation>frezka-cli run-line: %1
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: unit %1: a %2 answers on address 0 only; give it address 0, or use a GVE114 profile (--machine gve114)
</source>
        <translation>frezka-cli run-line: unit %1: a %2 answers on address 0 only; give it address 0, or use a GVE114 profile (--machine gve114)
</translation>
    </message>
    <message>
        <source>usage: frezka-cli run-line --unit ADDRESS:FILE[:PROFILE] [--unit ...]... %1 [--port PATH|sim] [--baud N] [--latency-ms N] [--quiet-ms N] [--timeout S]
       frezka-cli run-line --machine PROFILE --rotary-a ADDRESS[:PROFILE] [options as above] FILE
</source>
        <translation>usage: frezka-cli run-line --unit ADDRESS:FILE[:PROFILE] [--unit ...]... %1 [--port PATH|sim] [--baud N] [--latency-ms N] [--quiet-ms N] [--timeout S]
       frezka-cli run-line --machine PROFILE --rotary-a ADDRESS[:PROFILE] [options as above] FILE
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: cannot read --rotary-a &apos;%1&apos;: write the rotary unit&apos;s address 1..6, once, and optionally its profile, e.g. --rotary-a 1:rotary.json
</source>
        <translation>frezka-cli run-line: cannot read --rotary-a &apos;%1&apos;: write the rotary unit&apos;s address 1..6, once, and optionally its profile, e.g. --rotary-a 1:rotary.json
</translation>
    </message>
    <message>
        <source>frezka-cli run-line: --rotary-a runs one program on the machine&apos;s unit and the rotary unit: give the program&apos;s FILE and no --unit
</source>
        <translation>frezka-cli run-line: --rotary-a runs one program on the machine&apos;s unit and the rotary unit: give the program&apos;s FILE and no --unit
</translation>
    </message>
</context>
<context>
    <name>SerialTrace</name>
    <message>
        <source>line %1: not an entry (time in ms, then &gt;, &lt; or =, then the bytes): %2</source>
        <translation>line %1: not an entry (time in ms, then &gt;, &lt; or =, then the bytes): %2</translation>
    </message>
    <message>
        <source>line %1: the direction must be &gt; (to the unit), &lt; (from the unit) or = (an event), not &apos;%2&apos;</source>
        <translation>line %1: the direction must be &gt; (to the unit), &lt; (from the unit) or = (an event), not &apos;%2&apos;</translation>
    </message>
    <message>
        <source>line %1: a bad escape in &apos;%2&apos; (use \r, \n, \\ or \xHH)</source>
        <translation>line %1: a bad escape in &apos;%2&apos; (use \r, \n, \\ or \xHH)</translation>
    </message>
    <message>
        <source>line %1: the hex column does not match the text &apos;%2&apos;: correct it or delete it (from the &apos;|&apos; on)</source>
        <translation>line %1: the hex column does not match the text &apos;%2&apos;: correct it or delete it (from the &apos;|&apos; on)</translation>
    </message>
    <message>
        <source>line 1: not a Frezka serial trace (it must start with &apos;%1&apos;)</source>
        <translation>line 1: not a Frezka serial trace (it must start with &apos;%1&apos;)</translation>
    </message>
    <message>
        <source>trace line %1: the driver sent &apos;%2&apos; before the unit&apos;s line &apos;%3&apos; that the trace has first</source>
        <translation>trace line %1: the driver sent &apos;%2&apos; before the unit&apos;s line &apos;%3&apos; that the trace has first</translation>
    </message>
    <message>
        <source>trace line %1: expected &apos;%2&apos;, got &apos;%3&apos; (the last unit line given was trace line %4)</source>
        <translation>trace line %1: expected &apos;%2&apos;, got &apos;%3&apos; (the last unit line given was trace line %4)</translation>
    </message>
</context>
<context>
    <name>SerialTransport</name>
    <message>
        <source>%1 at %2 Bd</source>
        <translation>%1 at %2 Bd</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>cannot open %1: %2</translation>
    </message>
    <message>
        <source>cannot configure %1: %2</source>
        <translation>cannot configure %1: %2</translation>
    </message>
    <message>
        <source>write to %1: port not open</source>
        <translation>write to %1: port not open</translation>
    </message>
    <message>
        <source>short write to %1: %2 of %3 bytes (%4)</source>
        <translation>short write to %1: %2 of %3 bytes (%4)</translation>
    </message>
    <message>
        <source>%1: %2 (ignored)</source>
        <translation>%1: %2 (ignored)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>cannot open %1: permission denied. The port belongs to the group %2: join it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again.</source>
        <translation>cannot open %1: permission denied. The port belongs to the group %2: join it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again.</translation>
    </message>
</context>
<context>
    <name>TraceRecorder</name>
    <message>
        <source>cannot write the serial trace to %1: %2. Choose a folder you may write to.</source>
        <translation>cannot write the serial trace to %1: %2. Choose a folder you may write to.</translation>
    </message>
</context>
<context>
    <name>TracingTransport</name>
    <message>
        <source>serial trace saved to %1 (%2)</source>
        <translation>serial trace saved to %1 (%2)</translation>
    </message>
</context>
<context>
    <name>frezka::app</name>
    <message>
        <source>data: %1</source>
        <translation>data: %1</translation>
    </message>
    <message>
        <source>(not found)</source>
        <translation>(not found)</translation>
    </message>
</context>
<context>
    <name>frezka::cli</name>
    <message>
        <source>note: </source>
        <translation>note: </translation>
    </message>
    <message>
        <source>Check a G-code program against the machine&apos;s travel: every error, or a summary</source>
        <translation>Check a G-code program against the machine&apos;s travel: every error, or a summary</translation>
    </message>
    <message>
        <source>Transfer programs to/from ANC/K51 grinding controls; Z-position link</source>
        <translation>Transfer programs to/from ANC/K51 grinding controls; Z-position link</translation>
    </message>
    <message>
        <source>Plan a G-code program for a machine and print the unit commands</source>
        <translation>Plan a G-code program for a machine and print the unit commands</translation>
    </message>
    <message>
        <source>Run a G-code job on a GVE unit or the emulator, with progress and a JSON report</source>
        <translation>Run a G-code job on a GVE unit or the emulator, with progress and a JSON report</translation>
    </message>
    <message>
        <source>Interpret a G-code program and print its moves as JSON Lines</source>
        <translation>Interpret a G-code program and print its moves as JSON Lines</translation>
    </message>
    <message>
        <source>%1:%2: %3%4 %5 is %6 mm above the machine&apos;s travel (%4 %7 .. %8 mm)</source>
        <translation>%1:%2: %3%4 %5 is %6 mm above the machine&apos;s travel (%4 %7 .. %8 mm)</translation>
    </message>
    <message>
        <source>%1:%2: %3%4 %5 is %6 mm below the machine&apos;s travel (%4 %7 .. %8 mm)</source>
        <translation>%1:%2: %3%4 %5 is %6 mm below the machine&apos;s travel (%4 %7 .. %8 mm)</translation>
    </message>
    <message>
        <source>; the program goes %1 mm beyond it at line %2</source>
        <translation>; the program goes %1 mm beyond it at line %2</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>warning: </translation>
    </message>
    <message>
        <source>%1: the program fits the machine&apos;s travel once its work zero is set: give it with --offset G54:X,Y,Z (--offset G54:%2,%3,%4 puts it inside)
</source>
        <translation>%1: the program fits the machine&apos;s travel once its work zero is set: give it with --offset G54:X,Y,Z (--offset G54:%2,%3,%4 puts it inside)
</translation>
    </message>
    <message>
        <source>%1: the program is larger than the machine&apos;s travel
</source>
        <translation>%1: the program is larger than the machine&apos;s travel
</translation>
    </message>
    <message>
        <source>exit codes:
  0  done: the program is good (check), planned (plan), ran to its end (run)
  1  an error in the input or on the machine: a G-code error, a line beyond the machine&apos;s travel, a bad profile, a job that did not finish (on stderr, with the line)
  2  bad usage: an unknown command or option, a malformed value
</source>
        <translation>exit codes:
  0  done: the program is good (check), planned (plan), ran to its end (run)
  1  an error in the input or on the machine: a G-code error, a line beyond the machine&apos;s travel, a bad profile, a job that did not finish (on stderr, with the line)
  2  bad usage: an unknown command or option, a malformed value
</translation>
    </message>
    <message>
        <source>usage: frezka-cli COMMAND [ARGS...]

commands:
</source>
        <translation>usage: frezka-cli COMMAND [ARGS...]

commands:
</translation>
    </message>
    <message>
        <source>frezka-cli: unknown command &apos;%1&apos;
</source>
        <translation>frezka-cli: unknown command &apos;%1&apos;
</translation>
    </message>
    <message>
        <source>
work offsets: --offset G54:X,Y,Z sets where the program&apos;s zero is on the machine (machine mm; G54 .. G59.3, repeatable); --work-zero X,Y,Z is --offset G54:X,Y,Z.
operator stops: at M0, M1 and M6 frezka-cli run waits for Enter; --continue-at-stops runs on without an operator.
run from a line: frezka-cli run --from-line N starts the job at line N with the program&apos;s state there (tool, spindle, coolant, feed, modes, offsets), after a safe approach (spindle on, Z up to the safe height, X/Y across, Z down at the feed).

</source>
        <translation>
work offsets: --offset G54:X,Y,Z sets where the program&apos;s zero is on the machine (machine mm; G54 .. G59.3, repeatable); --work-zero X,Y,Z is --offset G54:X,Y,Z.
operator stops: at M0, M1 and M6 frezka-cli run waits for Enter; --continue-at-stops runs on without an operator.
run from a line: frezka-cli run --from-line N starts the job at line N with the program&apos;s state there (tool, spindle, coolant, feed, modes, offsets), after a safe approach (spindle on, Z up to the safe height, X/Y across, Z down at the feed).

</translation>
    </message>
    <message>
        <source>--version prints the version and the data folder (shipped machine profiles and sample programs).

</source>
        <translation>--version prints the version and the data folder (shipped machine profiles and sample programs).

</translation>
    </message>
    <message>
        <source>Commission a unit: identify it, check the protocol&apos;s readings, measure the link, read the EEPROM, then (in a terminal) test each axis, switch, the spindle, the outputs and homing after asking; write a report and an updated profile</source>
        <translation>Commission a unit: identify it, check the protocol&apos;s readings, measure the link, read the EEPROM, then (in a terminal) test each axis, switch, the spindle, the outputs and homing after asking; write a report and an updated profile</translation>
    </message>
    <message>
        <source>Probe a height map on the unit (G38.2 on a grid) and write its file</source>
        <translation>Probe a height map on the unit (G38.2 on a grid) and write its file</translation>
    </message>
    <message>
        <source>Run a program on each of several units sharing one serial line</source>
        <translation>Run a program on each of several units sharing one serial line</translation>
    </message>
    <message>
        <source>Probe the work&apos;s zero (Z from a touch plate, X/Y from an edge or a corner) or a tool&apos;s length on the tool sensor (fast then slow G38.2)</source>
        <translation>Probe the work&apos;s zero (Z from a touch plate, X/Y from an edge or a corner) or a tool&apos;s length on the tool sensor (fast then slow G38.2)</translation>
    </message>
    <message>
        <source>%1:%2: note: after this line the path depends on the probe&apos;s result; it is checked here as if the probe ended at its programmed end (run plans it once the probe has run)
</source>
        <translation>%1:%2: note: after this line the path depends on the probe&apos;s result; it is checked here as if the probe ended at its programmed end (run plans it once the probe has run)
</translation>
    </message>
</context>
<context>
    <name>frezka::driver</name>
    <message>
        <source>%1 is not possible now (the machine is %2)</source>
        <translation>%1 is not possible now (the machine is %2)</translation>
    </message>
    <message>
        <source>Wait until the machine is in a state that allows it, or stop what it is doing.</source>
        <translation>Wait until the machine is in a state that allows it, or stop what it is doing.</translation>
    </message>
    <message>
        <source>A job can start only when the machine is ready (it is %1)</source>
        <translation>A job can start only when the machine is ready (it is %1)</translation>
    </message>
    <message>
        <source>Wait until the machine is ready, then start the job again.</source>
        <translation>Wait until the machine is ready, then start the job again.</translation>
    </message>
    <message>
        <source>The job&apos;s progress is still being checked against the unit&apos;s counters</source>
        <translation>The job&apos;s progress is still being checked against the unit&apos;s counters</translation>
    </message>
    <message>
        <source>Wait a moment, then continue.</source>
        <translation>Wait a moment, then continue.</translation>
    </message>
    <message>
        <source>The tool is lifted and the job&apos;s queue is kept in the unit (K)</source>
        <translation>The tool is lifted and the job&apos;s queue is kept in the unit (K)</translation>
    </message>
    <message>
        <source>Lower the tool first, then abort.</source>
        <translation>Lower the tool first, then abort.</translation>
    </message>
    <message>
        <source>The machine profile homes no axis</source>
        <translation>The machine profile homes no axis</translation>
    </message>
    <message>
        <source>Set a homing order for the axes (axes.*.homing.order) in the machine profile.</source>
        <translation>Set a homing order for the axes (axes.*.homing.order) in the machine profile.</translation>
    </message>
    <message>
        <source>The machine profile does not home that axis</source>
        <translation>The machine profile does not home that axis</translation>
    </message>
    <message>
        <source>Give the axis a homing order (axes.*.homing.order) in the machine profile.</source>
        <translation>Give the axis a homing order (axes.*.homing.order) in the machine profile.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) cannot set one axis&apos;s counter (N&lt;axis&gt; needs v19), and N zeroes every counter</source>
        <translation>This unit&apos;s firmware (v%1) cannot set one axis&apos;s counter (N&lt;axis&gt; needs v19), and N zeroes every counter</translation>
    </message>
    <message>
        <source>Home all the machine&apos;s axes together, each with home position 0.</source>
        <translation>Home all the machine&apos;s axes together, each with home position 0.</translation>
    </message>
    <message>
        <source>The axis is outside its soft limits</source>
        <translation>The axis is outside its soft limits</translation>
    </message>
    <message>
        <source>Home the machine first.</source>
        <translation>Home the machine first.</translation>
    </message>
    <message>
        <source>The axis is at its soft limit</source>
        <translation>The axis is at its soft limit</translation>
    </message>
    <message>
        <source>Jog in the other direction.</source>
        <translation>Jog in the other direction.</translation>
    </message>
    <message>
        <source>This machine has no such axis</source>
        <translation>This machine has no such axis</translation>
    </message>
    <message>
        <source>Use one of the axes the machine profile has.</source>
        <translation>Use one of the axes the machine profile has.</translation>
    </message>
    <message>
        <source>This machine has no such axis or direction</source>
        <translation>This machine has no such axis or direction</translation>
    </message>
    <message>
        <source>The unit program has %1 axes</source>
        <translation>The unit program has %1 axes</translation>
    </message>
    <message>
        <source>Plan the program again for this machine.</source>
        <translation>Plan the program again for this machine.</translation>
    </message>
    <message>
        <source>The unit program has 4 axes but the %1 has 3</source>
        <translation>The unit program has 4 axes but the %1 has 3</translation>
    </message>
    <message>
        <source>The program was planned from %1 steps on axis %2 but the machine is at %3</source>
        <translation>The program was planned from %1 steps on axis %2 but the machine is at %3</translation>
    </message>
    <message>
        <source>Line %1: the plan uses VK, which this unit&apos;s firmware (v%2) lacks (it needs v19)</source>
        <translation>Line %1: the plan uses VK, which this unit&apos;s firmware (v%2) lacks (it needs v19)</translation>
    </message>
    <message>
        <source>Plan in VN (motion.speedMode &quot;vn&quot;), or set unit.firmwareVersion in the profile.</source>
        <translation>Plan in VN (motion.speedMode &quot;vn&quot;), or set unit.firmwareVersion in the profile.</translation>
    </message>
    <message>
        <source>Line %1: the command cannot be sent: %2</source>
        <translation>Line %1: the command cannot be sent: %2</translation>
    </message>
    <message>
        <source>Check the machine profile&apos;s limits and plan the program again.</source>
        <translation>Check the machine profile&apos;s limits and plan the program again.</translation>
    </message>
    <message>
        <source>Off the planned path the unit holds no queue to keep</source>
        <translation>Off the planned path the unit holds no queue to keep</translation>
    </message>
    <message>
        <source>Continue (it lifts the tool and returns to the path) or abort.</source>
        <translation>Continue (it lifts the tool and returns to the path) or abort.</translation>
    </message>
    <message>
        <source>The machine profile sets no tool lift height</source>
        <translation>The machine profile sets no tool lift height</translation>
    </message>
    <message>
        <source>Set motion.toolLiftMm in the machine profile.</source>
        <translation>Set motion.toolLiftMm in the machine profile.</translation>
    </message>
    <message>
        <source>Z is at its upper soft limit: no room to lift the tool</source>
        <translation>Z is at its upper soft limit: no room to lift the tool</translation>
    </message>
    <message>
        <source>Continue without lifting, or abort the job.</source>
        <translation>Continue without lifting, or abort the job.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) has no MPG handwheel; it needs v10</source>
        <translation>This unit&apos;s firmware (v%1) has no MPG handwheel; it needs v10</translation>
    </message>
    <message>
        <source>Jog with the buttons or the keyboard instead.</source>
        <translation>Jog with the buttons or the keyboard instead.</translation>
    </message>
    <message>
        <source>This unit has no MPG handwheel</source>
        <translation>This unit has no MPG handwheel</translation>
    </message>
    <message>
        <source>Spindle speed %1 rpm is outside 0 … %2 rpm</source>
        <translation>Spindle speed %1 rpm is outside 0 … %2 rpm</translation>
    </message>
    <message>
        <source>Enter a speed within the machine profile&apos;s range (spindle.maxRpm).</source>
        <translation>Enter a speed within the machine profile&apos;s range (spindle.maxRpm).</translation>
    </message>
    <message>
        <source>This unit has no feed override (XM)</source>
        <translation>This unit has no feed override (XM)</translation>
    </message>
    <message>
        <source>Change the feed in the program instead.</source>
        <translation>Change the feed in the program instead.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) has no XM feed override; it needs v19</source>
        <translation>This unit&apos;s firmware (v%1) has no XM feed override; it needs v19</translation>
    </message>
    <message>
        <source>The feed override cannot be set: %1</source>
        <translation>The feed override cannot be set: %1</translation>
    </message>
    <message>
        <source>Choose a value within the unit&apos;s range.</source>
        <translation>Choose a value within the unit&apos;s range.</translation>
    </message>
    <message>
        <source>Empty command</source>
        <translation>Empty command</translation>
    </message>
    <message>
        <source>Type a unit command after &apos;!&apos;.</source>
        <translation>Type a unit command after &apos;!&apos;.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be sent to the unit: %2</source>
        <translation>&apos;%1&apos; cannot be sent to the unit: %2</translation>
    </message>
    <message>
        <source>See the unit&apos;s command list (docs/gve-protocol.md).</source>
        <translation>See the unit&apos;s command list (docs/gve-protocol.md).</translation>
    </message>
    <message>
        <source>&apos;%1&apos; would disturb the running job</source>
        <translation>&apos;%1&apos; would disturb the running job</translation>
    </message>
    <message>
        <source>Send it when the job has ended.</source>
        <translation>Send it when the job has ended.</translation>
    </message>
    <message>
        <source>The new speed cannot be set: %1</source>
        <translation>The new speed cannot be set: %1</translation>
    </message>
    <message>
        <source>Enter a lower feed, or leave it unchanged.</source>
        <translation>Enter a lower feed, or leave it unchanged.</translation>
    </message>
    <message>
        <source>%1: the unit answered: %2</source>
        <translation>%1: the unit answered: %2</translation>
    </message>
    <message>
        <source>Check the machine and the connection, then try again.</source>
        <translation>Check the machine and the connection, then try again.</translation>
    </message>
    <message>
        <source>%1: the link failed: %2</source>
        <translation>%1: the link failed: %2</translation>
    </message>
    <message>
        <source>Check the cable and that the unit is on, then connect again.</source>
        <translation>Check the cable and that the unit is on, then connect again.</translation>
    </message>
    <message>
        <source>Line %1: the unit refused &apos;%2&apos; (%3)</source>
        <translation>Line %1: the unit refused &apos;%2&apos; (%3)</translation>
    </message>
    <message>
        <source>Check the machine profile against the unit (variant, firmware, limits).</source>
        <translation>Check the machine profile against the unit (variant, firmware, limits).</translation>
    </message>
    <message>
        <source>The link was lost: %1</source>
        <translation>The link was lost: %1</translation>
    </message>
    <message>
        <source>The job is kept: reconnect, then continue.</source>
        <translation>The job is kept: reconnect, then continue.</translation>
    </message>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Cannot connect: %1</translation>
    </message>
    <message>
        <source>Check the port in the settings, the cable, and that the unit is on.</source>
        <translation>Check the port in the settings, the cable, and that the unit is on.</translation>
    </message>
    <message>
        <source>The unit reports firmware &apos;%1&apos; but the machine profile is for a %2</source>
        <translation>The unit reports firmware &apos;%1&apos; but the machine profile is for a %2</translation>
    </message>
    <message>
        <source>Choose the matching machine profile.</source>
        <translation>Choose the matching machine profile.</translation>
    </message>
    <message>
        <source>The unit reports firmware v%1 but the machine profile says v%2; plans for the profile&apos;s firmware may use what this one lacks (MPG and EEPROM floats need v10; VK, VL, XM and setting one axis&apos;s counter v19)</source>
        <translation>The unit reports firmware v%1 but the machine profile says v%2; plans for the profile&apos;s firmware may use what this one lacks (MPG and EEPROM floats need v10; VK, VL, XM and setting one axis&apos;s counter v19)</translation>
    </message>
    <message>
        <source>Set unit.firmwareVersion to %1 in the machine profile.</source>
        <translation>Set unit.firmwareVersion to %1 in the machine profile.</translation>
    </message>
    <message>
        <source>Line %1: unknown unit program operation</source>
        <translation>Line %1: unknown unit program operation</translation>
    </message>
    <message>
        <source>Plan the program again.</source>
        <translation>Plan the program again.</translation>
    </message>
    <message>
        <source>Homing axis %1: the home switch was not found within the configured travel</source>
        <translation>Homing axis %1: the home switch was not found within the configured travel</translation>
    </message>
    <message>
        <source>Check the switch and its wiring, and the axis&apos;s homing travel in the profile.</source>
        <translation>Check the switch and its wiring, and the axis&apos;s homing travel in the profile.</translation>
    </message>
    <message>
        <source>Homing axis %1: %2</source>
        <translation>Homing axis %1: %2</translation>
    </message>
    <message>
        <source>Check the axis&apos;s homing settings in the machine profile.</source>
        <translation>Check the axis&apos;s homing settings in the machine profile.</translation>
    </message>
    <message>
        <source>Line %1: the probe input is already in the state the probe move waits for</source>
        <translation>Line %1: the probe input is already in the state the probe move waits for</translation>
    </message>
    <message>
        <source>Check the probe and its wiring.</source>
        <translation>Check the probe and its wiring.</translation>
    </message>
    <message>
        <source>Line %1: the probe move ended without the probe tripping</source>
        <translation>Line %1: the probe move ended without the probe tripping</translation>
    </message>
    <message>
        <source>Check the probe and the workpiece, then run the job again.</source>
        <translation>Check the probe and the workpiece, then run the job again.</translation>
    </message>
    <message>
        <source>Line %1: the probe tripped at %2 steps; the rest of the program was planned from the probe&apos;s end point</source>
        <translation>Line %1: the probe tripped at %2 steps; the rest of the program was planned from the probe&apos;s end point</translation>
    </message>
    <message>
        <source>The unit&apos;s counters match no point the job has reached; the job cannot resume exactly</source>
        <translation>The unit&apos;s counters match no point the job has reached; the job cannot resume exactly</translation>
    </message>
    <message>
        <source>Home the machine and start the job again.</source>
        <translation>Home the machine and start the job again.</translation>
    </message>
    <message>
        <source>The unit&apos;s counters match several points of the job; cannot tell how far it got</source>
        <translation>The unit&apos;s counters match several points of the job; cannot tell how far it got</translation>
    </message>
    <message>
        <source>Abort the job.</source>
        <translation>Abort the job.</translation>
    </message>
    <message>
        <source>The machine did not arrive back on the planned path after %1 attempts</source>
        <translation>The machine did not arrive back on the planned path after %1 attempts</translation>
    </message>
    <message>
        <source>Abort the job and check the machine.</source>
        <translation>Abort the job and check the machine.</translation>
    </message>
    <message>
        <source>The machine left the planned path: %1. A command was damaged on the serial line in a way its checksum cannot show</source>
        <translation>The machine left the planned path: %1. A command was damaged on the serial line in a way its checksum cannot show</translation>
    </message>
    <message>
        <source>Check the workpiece. Continue lifts the tool, returns to line %2 and runs the job on from there; or abort the job.</source>
        <translation>Check the workpiece. Continue lifts the tool, returns to line %2 and runs the job on from there; or abort the job.</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Paused</translation>
    </message>
    <message>
        <source>Continue, or lift the tool to change or clean it.</source>
        <translation>Continue, or lift the tool to change or clean it.</translation>
    </message>
    <message>
        <source>Program stop (M0) at line %1</source>
        <translation>Program stop (M0) at line %1</translation>
    </message>
    <message>
        <source>Do what the program asks, then continue.</source>
        <translation>Do what the program asks, then continue.</translation>
    </message>
    <message>
        <source>Optional stop (M1) at line %1</source>
        <translation>Optional stop (M1) at line %1</translation>
    </message>
    <message>
        <source>Tool change (M6) at line %1: change to tool %2</source>
        <translation>Tool change (M6) at line %1: change to tool %2</translation>
    </message>
    <message>
        <source>Lift the tool, change it to tool %2, lower it and continue.</source>
        <translation>Lift the tool, change it to tool %2, lower it and continue.</translation>
    </message>
    <message>
        <source>An input interrupt stopped the machine</source>
        <translation>An input interrupt stopped the machine</translation>
    </message>
    <message>
        <source>Check the machine; when it is safe, continue or abort.</source>
        <translation>Check the machine; when it is safe, continue or abort.</translation>
    </message>
    <message>
        <source>Stopped by input %1</source>
        <translation>Stopped by input %1</translation>
    </message>
    <message>
        <source>Stopped by input %1 (STOP button)</source>
        <translation>Stopped by input %1 (STOP button)</translation>
    </message>
    <message>
        <source>Tool lifted</source>
        <translation>Tool lifted</translation>
    </message>
    <message>
        <source>Change or clean the tool, then lower it.</source>
        <translation>Change or clean the tool, then lower it.</translation>
    </message>
    <message>
        <source>Tool lowered</source>
        <translation>Tool lowered</translation>
    </message>
    <message>
        <source>Continue or abort.</source>
        <translation>Continue or abort.</translation>
    </message>
    <message>
        <source>Returning to the planned path</source>
        <translation>Returning to the planned path</translation>
    </message>
    <message>
        <source>Wait until the machine is back on the path.</source>
        <translation>Wait until the machine is back on the path.</translation>
    </message>
    <message>
        <source>Link restored: checking the job&apos;s progress against the counters</source>
        <translation>Link restored: checking the job&apos;s progress against the counters</translation>
    </message>
    <message>
        <source>Wait until the check has finished, then continue.</source>
        <translation>Wait until the check has finished, then continue.</translation>
    </message>
    <message>
        <source>applying the new speed (XA)</source>
        <translation>applying the new speed (XA)</translation>
    </message>
    <message>
        <source>arming the probe input</source>
        <translation>arming the probe input</translation>
    </message>
    <message>
        <source>continuing (G)</source>
        <translation>continuing (G)</translation>
    </message>
    <message>
        <source>disarming the probe input</source>
        <translation>disarming the probe input</translation>
    </message>
    <message>
        <source>dropping the queue (D)</source>
        <translation>dropping the queue (D)</translation>
    </message>
    <message>
        <source>dropping the queue (D) off the planned path</source>
        <translation>dropping the queue (D) off the planned path</translation>
    </message>
    <message>
        <source>ending the jog (D)</source>
        <translation>ending the jog (D)</translation>
    </message>
    <message>
        <source>identifying the unit (&apos;?&apos;)</source>
        <translation>identifying the unit (&apos;?&apos;)</translation>
    </message>
    <message>
        <source>identifying the unit (&apos;Q&apos;)</source>
        <translation>identifying the unit (&apos;Q&apos;)</translation>
    </message>
    <message>
        <source>jogging</source>
        <translation>jogging</translation>
    </message>
    <message>
        <source>keeping the queue (K)</source>
        <translation>keeping the queue (K)</translation>
    </message>
    <message>
        <source>lifting the tool</source>
        <translation>lifting the tool</translation>
    </message>
    <message>
        <source>lowering the tool</source>
        <translation>lowering the tool</translation>
    </message>
    <message>
        <source>pausing (H)</source>
        <translation>pausing (H)</translation>
    </message>
    <message>
        <source>position poll</source>
        <translation>position poll</translation>
    </message>
    <message>
        <source>probe move</source>
        <translation>probe move</translation>
    </message>
    <message>
        <source>raw command</source>
        <translation>raw command</translation>
    </message>
    <message>
        <source>re-sending the job&apos;s speed settings</source>
        <translation>re-sending the job&apos;s speed settings</translation>
    </message>
    <message>
        <source>reading the EEPROM</source>
        <translation>reading the EEPROM</translation>
    </message>
    <message>
        <source>reading the final position</source>
        <translation>reading the final position</translation>
    </message>
    <message>
        <source>reading the position</source>
        <translation>reading the position</translation>
    </message>
    <message>
        <source>reading the probe input</source>
        <translation>reading the probe input</translation>
    </message>
    <message>
        <source>reading the probe position</source>
        <translation>reading the probe position</translation>
    </message>
    <message>
        <source>reading the probe result</source>
        <translation>reading the probe result</translation>
    </message>
    <message>
        <source>reading the status</source>
        <translation>reading the status</translation>
    </message>
    <message>
        <source>restoring the queue (R)</source>
        <translation>restoring the queue (R)</translation>
    </message>
    <message>
        <source>returning to the planned path</source>
        <translation>returning to the planned path</translation>
    </message>
    <message>
        <source>setting the feed override (XM)</source>
        <translation>setting the feed override (XM)</translation>
    </message>
    <message>
        <source>setting the jog speed</source>
        <translation>setting the jog speed</translation>
    </message>
    <message>
        <source>setting the new speed</source>
        <translation>setting the new speed</translation>
    </message>
    <message>
        <source>setting the speed to return to the path</source>
        <translation>setting the speed to return to the path</translation>
    </message>
    <message>
        <source>setting the spindle</source>
        <translation>setting the spindle</translation>
    </message>
    <message>
        <source>starting the spindle</source>
        <translation>starting the spindle</translation>
    </message>
    <message>
        <source>status</source>
        <translation>status</translation>
    </message>
    <message>
        <source>status poll</source>
        <translation>status poll</translation>
    </message>
    <message>
        <source>stopping (H)</source>
        <translation>stopping (H)</translation>
    </message>
    <message>
        <source>stopping (H) off the planned path</source>
        <translation>stopping (H) off the planned path</translation>
    </message>
    <message>
        <source>stopping the jog (H)</source>
        <translation>stopping the jog (H)</translation>
    </message>
    <message>
        <source>stopping the probe move (H)</source>
        <translation>stopping the probe move (H)</translation>
    </message>
    <message>
        <source>stopping the spindle</source>
        <translation>stopping the spindle</translation>
    </message>
    <message>
        <source>switching checksums</source>
        <translation>switching checksums</translation>
    </message>
    <message>
        <source>switching outputs</source>
        <translation>switching outputs</translation>
    </message>
    <message>
        <source>switching the MPG</source>
        <translation>switching the MPG</translation>
    </message>
    <message>
        <source>switching the MPG off</source>
        <translation>switching the MPG off</translation>
    </message>
    <message>
        <source>testing packets</source>
        <translation>testing packets</translation>
    </message>
    <message>
        <source>raising queued speeds (XU)</source>
        <translation>raising queued speeds (XU)</translation>
    </message>
    <message>
        <source>lowering queued speeds (XD)</source>
        <translation>lowering queued speeds (XD)</translation>
    </message>
    <message>
        <source>zeroing the counters (N)</source>
        <translation>zeroing the counters (N)</translation>
    </message>
    <message>
        <source>setting T</source>
        <translation>setting T</translation>
    </message>
    <message>
        <source>setting VN</source>
        <translation>setting VN</translation>
    </message>
    <message>
        <source>setting the interrupt mask</source>
        <translation>setting the interrupt mask</translation>
    </message>
    <message>
        <source>setting the input polarity</source>
        <translation>setting the input polarity</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Abort</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Homing</translation>
    </message>
    <message>
        <source>Jogging</source>
        <translation>Jogging</translation>
    </message>
    <message>
        <source>Stopping the jog</source>
        <translation>Stopping the jog</translation>
    </message>
    <message>
        <source>Writing the EEPROM</source>
        <translation>Writing the EEPROM</translation>
    </message>
    <message>
        <source>Lifting the tool</source>
        <translation>Lifting the tool</translation>
    </message>
    <message>
        <source>Lowering the tool</source>
        <translation>Lowering the tool</translation>
    </message>
    <message>
        <source>Switching the MPG</source>
        <translation>Switching the MPG</translation>
    </message>
    <message>
        <source>Setting the spindle</source>
        <translation>Setting the spindle</translation>
    </message>
    <message>
        <source>Switching outputs</source>
        <translation>Switching outputs</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>queue full</source>
        <translation>queue full</translation>
    </message>
    <message>
        <source>command not received completely in time</source>
        <translation>command not received completely in time</translation>
    </message>
    <message>
        <source>unknown command</source>
        <translation>unknown command</translation>
    </message>
    <message>
        <source>syntax error</source>
        <translation>syntax error</translation>
    </message>
    <message>
        <source>parameter out of range</source>
        <translation>parameter out of range</translation>
    </message>
    <message>
        <source>nothing to continue</source>
        <translation>nothing to continue</translation>
    </message>
    <message>
        <source>not allowed while a vector runs</source>
        <translation>not allowed while a vector runs</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Disconnected</translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation>Connecting</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>Idle</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Running</translation>
    </message>
    <message>
        <source>Stopping</source>
        <translation>Stopping</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Link lost</translation>
    </message>
    <message>
        <source>the link was closed</source>
        <translation>the link was closed</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>no reply</translation>
    </message>
    <message>
        <source>setup</source>
        <translation>setup</translation>
    </message>
    <message>
        <source>Jog back to where it starts, or plan it again from here.</source>
        <translation>Jog back to where it starts, or plan it again from here.</translation>
    </message>
    <message>
        <source>Check the probe and the workpiece, then plan it again from here.</source>
        <translation>Check the probe and the workpiece, then plan it again from here.</translation>
    </message>
    <message>
        <source>This unit&apos;s firmware (v%1) has no W: homing to a switch comes with IP64MPG v10</source>
        <translation>This unit&apos;s firmware (v%1) has no W: homing to a switch comes with IP64MPG v10</translation>
    </message>
    <message>
        <source>Set the position by hand (G92) or update the unit.</source>
        <translation>Set the position by hand (G92) or update the unit.</translation>
    </message>
    <message>
        <source>The spindle is starting: the job continues after its spin-up</source>
        <translation>The spindle is starting: the job continues after its spin-up</translation>
    </message>
    <message>
        <source>Wait for the spin-up; the job then goes on by itself.</source>
        <translation>Wait for the spin-up; the job then goes on by itself.</translation>
    </message>
    <message>
        <source>The jog would end at %1 mm, outside the soft limits %2 .. %3 mm</source>
        <translation>The jog would end at %1 mm, outside the soft limits %2 .. %3 mm</translation>
    </message>
    <message>
        <source>Jog a shorter distance.</source>
        <translation>Jog a shorter distance.</translation>
    </message>
    <message>
        <source>The jog is shorter than one step</source>
        <translation>The jog is shorter than one step</translation>
    </message>
    <message>
        <source>Choose a larger jog step.</source>
        <translation>Choose a larger jog step.</translation>
    </message>
    <message>
        <source>The lifted tool is still moving</source>
        <translation>The lifted tool is still moving</translation>
    </message>
    <message>
        <source>Wait until it stands, then try again.</source>
        <translation>Wait until it stands, then try again.</translation>
    </message>
    <message>
        <source>Homing axis %1: stopped before the end of its search leg (an input interrupt, or the home switch did not release within homing.backOffMm)</source>
        <translation>Homing axis %1: stopped before the end of its search leg (an input interrupt, or the home switch did not release within homing.backOffMm)</translation>
    </message>
    <message>
        <source>Check the inputs and the switch, then home again; the axis is not homed.</source>
        <translation>Check the inputs and the switch, then home again; the axis is not homed.</translation>
    </message>
    <message>
        <source>The tool did not arrive back at the lift point (%1 instead of %2)</source>
        <translation>The tool did not arrive back at the lift point (%1 instead of %2)</translation>
    </message>
    <message>
        <source>The spindle starts; the job continues after its spin-up</source>
        <translation>The spindle starts; the job continues after its spin-up</translation>
    </message>
    <message>
        <source>Keep clear of the tool.</source>
        <translation>Keep clear of the tool.</translation>
    </message>
    <message>
        <source>This unit has no axis speed limits (VL): above 100 % an axis could run over its maximum</source>
        <translation>This unit has no axis speed limits (VL): above 100 % an axis could run over its maximum</translation>
    </message>
    <message>
        <source>Raise the feed in the program instead.</source>
        <translation>Raise the feed in the program instead.</translation>
    </message>
    <message>
        <source>This unit has no XM: a new feed would change only the queued vectors</source>
        <translation>This unit has no XM: a new feed would change only the queued vectors</translation>
    </message>
    <message>
        <source>Lower the tool with the feed unchanged, then use the feed buttons (XD), which change the rest of the job.</source>
        <translation>Lower the tool with the feed unchanged, then use the feed buttons (XD), which change the rest of the job.</translation>
    </message>
    <message>
        <source>Y+ is not sent: the unit&apos;s reports come unasked, in a form the manuals do not give, and would be taken for replies</source>
        <translation>Y+ is not sent: the unit&apos;s reports come unasked, in a form the manuals do not give, and would be taken for replies</translation>
    </message>
    <message>
        <source>Use Y&amp; (the MPG on, silent); the position is read with P4/PF.</source>
        <translation>Use Y&amp; (the MPG on, silent); the position is read with P4/PF.</translation>
    </message>
    <message>
        <source>While the tool is lifted it moves by steps only</source>
        <translation>While the tool is lifted it moves by steps only</translation>
    </message>
    <message>
        <source>Choose a jog step (0.01 to 10 mm) and press the axis button; the tool returns to the lift point before it is lowered.</source>
        <translation>Choose a jog step (0.01 to 10 mm) and press the axis button; the tool returns to the lift point before it is lowered.</translation>
    </message>
    <message>
        <source>%1: %2 got no valid answer (%3%4); gave up after %5 attempts</source>
        <translation>%1: %2 got no valid answer (%3%4); gave up after %5 attempts</translation>
    </message>
    <message>
        <source>Check the cable and that the unit is on, then connect again; a job is kept and continues after the reconnect.</source>
        <translation>Check the cable and that the unit is on, then connect again; a job is kept and continues after the reconnect.</translation>
    </message>
    <message>
        <source>%1: the reply to %2 was lost and the unit&apos;s command index was unknown</source>
        <translation>%1: the reply to %2 was lost and the unit&apos;s command index was unknown</translation>
    </message>
    <message>
        <source>%1: after %2 the unit&apos;s command index is %3, expected %4 or %5</source>
        <translation>%1: after %2 the unit&apos;s command index is %3, expected %4 or %5</translation>
    </message>
    <message>
        <source>incomplete reply</source>
        <translation>incomplete reply</translation>
    </message>
    <message>
        <source>garbled reply</source>
        <translation>garbled reply</translation>
    </message>
    <message>
        <source>doubtful reply</source>
        <translation>doubtful reply</translation>
    </message>
    <message>
        <source>garbled reply to &apos;@&apos;</source>
        <translation>garbled reply to &apos;@&apos;</translation>
    </message>
    <message>
        <source>garbled repeated reply</source>
        <translation>garbled repeated reply</translation>
    </message>
    <message>
        <source>doubtful repeated reply</source>
        <translation>doubtful repeated reply</translation>
    </message>
    <message>
        <source>no reply to recovery query</source>
        <translation>no reply to recovery query</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>line %1</translation>
    </message>
    <message>
        <source>The new feed cannot be set: no speed is planned where the tool stands</source>
        <translation>The new feed cannot be set: no speed is planned where the tool stands</translation>
    </message>
    <message>
        <source>Lower the tool with the feed unchanged.</source>
        <translation>Lower the tool with the feed unchanged.</translation>
    </message>
    <message>
        <source>This unit has no output OUT%1</source>
        <translation>This unit has no output OUT%1</translation>
    </message>
    <message>
        <source>Switch one of the outputs the unit has (a GVE84 has its relay only).</source>
        <translation>Switch one of the outputs the unit has (a GVE84 has its relay only).</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: address must be 0..7</source>
        <translation>&apos;%1&apos;: address must be 0..7</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 has no address 7 (spindle)</source>
        <translation>&apos;%1&apos;: %2 has no address 7 (spindle)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a command of address 7</source>
        <translation>&apos;%1&apos;: not a command of address 7</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the spindle speed goes to address 7</source>
        <translation>&apos;%1&apos;: the spindle speed goes to address 7</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 answers on address 0 only</source>
        <translation>&apos;%1&apos;: %2 answers on address 0 only</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 components, %3 takes 3</source>
        <translation>&apos;%1&apos;: %2 components, %3 takes 3</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 components, %3 takes 3 or 4</source>
        <translation>&apos;%1&apos;: %2 components, %3 takes 3 or 4</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 %3 is outside %4..%5</source>
        <translation>&apos;%1&apos;: %2 %3 is outside %4..%5</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: value is not a finite number</source>
        <translation>&apos;%1&apos;: value is not a finite number</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: travel toward the switch must not be 0</source>
        <translation>&apos;%1&apos;: travel toward the switch must not be 0</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 has no axis %3</source>
        <translation>&apos;%1&apos;: %2 has no axis %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2 has no command %3</source>
        <translation>&apos;%1&apos;: %2 has no command %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: only C and B belong in a packet</source>
        <translation>&apos;%1&apos;: only C and B belong in a packet</translation>
    </message>
    <message>
        <source>a packet needs at least one command</source>
        <translation>a packet needs at least one command</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a unit command (it starts with &apos;!&apos; and an address 0..7)</source>
        <translation>&apos;%1&apos;: not a unit command (it starts with &apos;!&apos; and an address 0..7)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: missing or wrong checksum</source>
        <translation>&apos;%1&apos;: missing or wrong checksum</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>unknown command &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: missing number</source>
        <translation>&apos;%1&apos;: missing number</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: number out of range: %2</source>
        <translation>&apos;%1&apos;: number out of range: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a decimal number: %2</source>
        <translation>&apos;%1&apos;: not a decimal number: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a hex byte: %2</source>
        <translation>&apos;%1&apos;: not a hex byte: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: not a number: %2</source>
        <translation>&apos;%1&apos;: not a number: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: wrong number of parameters</source>
        <translation>&apos;%1&apos;: wrong number of parameters</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: W needs an axis X, Y, Z or A</source>
        <translation>&apos;%1&apos;: W needs an axis X, Y, Z or A</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: O0 needs &apos;,hh&apos;</source>
        <translation>&apos;%1&apos;: O0 needs &apos;,hh&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: unexpected parameters</source>
        <translation>&apos;%1&apos;: unexpected parameters</translation>
    </message>
    <message>
        <source>component</source>
        <translation>component</translation>
    </message>
    <message>
        <source>pause (ms)</source>
        <translation>pause (ms)</translation>
    </message>
    <message>
        <source>SHORT threshold</source>
        <translation>SHORT threshold</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>acceleration</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>speed</translation>
    </message>
    <message>
        <source>brake speed</source>
        <translation>brake speed</translation>
    </message>
    <message>
        <source>multiplier (%)</source>
        <translation>multiplier (%)</translation>
    </message>
    <message>
        <source>counter</source>
        <translation>counter</translation>
    </message>
    <message>
        <source>travel</source>
        <translation>travel</translation>
    </message>
    <message>
        <source>speed toward the switch</source>
        <translation>speed toward the switch</translation>
    </message>
    <message>
        <source>back-off travel</source>
        <translation>back-off travel</translation>
    </message>
    <message>
        <source>speed off the switch</source>
        <translation>speed off the switch</translation>
    </message>
    <message>
        <source>EEPROM address</source>
        <translation>EEPROM address</translation>
    </message>
    <message>
        <source>byte</source>
        <translation>byte</translation>
    </message>
    <message>
        <source>value</source>
        <translation>value</translation>
    </message>
    <message>
        <source>output byte</source>
        <translation>output byte</translation>
    </message>
    <message>
        <source>status number</source>
        <translation>status number</translation>
    </message>
    <message>
        <source>status byte</source>
        <translation>status byte</translation>
    </message>
    <message>
        <source>packet command count</source>
        <translation>packet command count</translation>
    </message>
    <message>
        <source>spindle (per mille)</source>
        <translation>spindle (per mille)</translation>
    </message>
    <message>
        <source>Spindle override %1 % is outside %2 … %3 %</source>
        <translation>Spindle override %1 % is outside %2 … %3 %</translation>
    </message>
    <message>
        <source>Choose a spindle override within that range.</source>
        <translation>Choose a spindle override within that range.</translation>
    </message>
    <message>
        <source>This unit switches its spindle with a relay: its speed cannot be overridden</source>
        <translation>This unit switches its spindle with a relay: its speed cannot be overridden</translation>
    </message>
    <message>
        <source>Set the speed on the spindle&apos;s drive, or use a unit with a spindle output at address 7 (GVE64, GVE114).</source>
        <translation>Set the speed on the spindle&apos;s drive, or use a unit with a spindle output at address 7 (GVE64, GVE114).</translation>
    </message>
</context>
<context>
    <name>frezka::gcode</name>
    <message>
        <source>Cannot read the file %1</source>
        <translation>Cannot read the file %1</translation>
    </message>
    <message>
        <source>Check that the file exists and is readable.</source>
        <translation>Check that the file exists and is readable.</translation>
    </message>
    <message>
        <source>Unexpected character &apos;%1&apos;</source>
        <translation>Unexpected character &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Remove it or put it inside a comment ( ).</source>
        <translation>Remove it or put it inside a comment ( ).</translation>
    </message>
    <message>
        <source>Comment is not closed</source>
        <translation>Comment is not closed</translation>
    </message>
    <message>
        <source>Add &apos;)&apos; at the end of the comment.</source>
        <translation>Add &apos;)&apos; at the end of the comment.</translation>
    </message>
    <message>
        <source>Comment inside a comment</source>
        <translation>Comment inside a comment</translation>
    </message>
    <message>
        <source>Close the first comment before opening another one.</source>
        <translation>Close the first comment before opening another one.</translation>
    </message>
    <message>
        <source>A number is expected after %1</source>
        <translation>A number is expected after %1</translation>
    </message>
    <message>
        <source>Write a number, a #parameter or an [expression] after the letter.</source>
        <translation>Write a number, a #parameter or an [expression] after the letter.</translation>
    </message>
    <message>
        <source>%1 needs a whole number</source>
        <translation>%1 needs a whole number</translation>
    </message>
    <message>
        <source>Use an integer value here.</source>
        <translation>Use an integer value here.</translation>
    </message>
    <message>
        <source>Word %1 appears twice in one block</source>
        <translation>Word %1 appears twice in one block</translation>
    </message>
    <message>
        <source>Keep one of them or split the block into two lines.</source>
        <translation>Keep one of them or split the block into two lines.</translation>
    </message>
    <message>
        <source>Word %1 is not supported</source>
        <translation>Word %1 is not supported</translation>
    </message>
    <message>
        <source>Remove the word; Frezka does not use it.</source>
        <translation>Remove the word; Frezka does not use it.</translation>
    </message>
    <message>
        <source>Axis %1 is not supported</source>
        <translation>Axis %1 is not supported</translation>
    </message>
    <message>
        <source>Frezka machines have the axes X, Y, Z and A.</source>
        <translation>Frezka machines have the axes X, Y, Z and A.</translation>
    </message>
    <message>
        <source>The file ended without M2, M30 or %</source>
        <translation>The file ended without M2, M30 or %</translation>
    </message>
    <message>
        <source>End the program with M2 or M30 (or enclose it in % lines).</source>
        <translation>End the program with M2 or M30 (or enclose it in % lines).</translation>
    </message>
    <message>
        <source>The program starts with % but has no closing %</source>
        <translation>The program starts with % but has no closing %</translation>
    </message>
    <message>
        <source>Add a line with % at the end of the program.</source>
        <translation>Add a line with % at the end of the program.</translation>
    </message>
    <message>
        <source>Line is too long (%1 characters)</source>
        <translation>Line is too long (%1 characters)</translation>
    </message>
    <message>
        <source>Split the line; at most 65535 characters are allowed.</source>
        <translation>Split the line; at most 65535 characters are allowed.</translation>
    </message>
    <message>
        <source>Unknown G code %1</source>
        <translation>Unknown G code %1</translation>
    </message>
    <message>
        <source>Check the number; see the list of supported codes.</source>
        <translation>Check the number; see the list of supported codes.</translation>
    </message>
    <message>
        <source>%1 is not supported</source>
        <translation>%1 is not supported</translation>
    </message>
    <message>
        <source>Remove it or post-process the program without it (see the supported codes).</source>
        <translation>Remove it or post-process the program without it (see the supported codes).</translation>
    </message>
    <message>
        <source>Unknown M code %1</source>
        <translation>Unknown M code %1</translation>
    </message>
    <message>
        <source>%1 conflicts with another code of the same group in this block</source>
        <translation>%1 conflicts with another code of the same group in this block</translation>
    </message>
    <message>
        <source>Use one code of each modal group per block.</source>
        <translation>Use one code of each modal group per block.</translation>
    </message>
    <message>
        <source>Too many M codes in one block</source>
        <translation>Too many M codes in one block</translation>
    </message>
    <message>
        <source>Use at most four M codes per block.</source>
        <translation>Use at most four M codes per block.</translation>
    </message>
    <message>
        <source>Word %1 is not used by any code in this block</source>
        <translation>Word %1 is not used by any code in this block</translation>
    </message>
    <message>
        <source>Remove the word or add the code that uses it.</source>
        <translation>Remove the word or add the code that uses it.</translation>
    </message>
    <message>
        <source>Axis words are given with G80</source>
        <translation>Axis words are given with G80</translation>
    </message>
    <message>
        <source>G80 cancels the motion mode; give the axis words with G0 or G1.</source>
        <translation>G80 cancels the motion mode; give the axis words with G0 or G1.</translation>
    </message>
    <message>
        <source>Axis words are given but no motion mode is active</source>
        <translation>Axis words are given but no motion mode is active</translation>
    </message>
    <message>
        <source>Add G0, G1, G2 or G3 to the block.</source>
        <translation>Add G0, G1, G2 or G3 to the block.</translation>
    </message>
    <message>
        <source>%1 and a motion code both use the axis words</source>
        <translation>%1 and a motion code both use the axis words</translation>
    </message>
    <message>
        <source>Put them on separate lines.</source>
        <translation>Put them on separate lines.</translation>
    </message>
    <message>
        <source>%1 needs at least one axis word</source>
        <translation>%1 needs at least one axis word</translation>
    </message>
    <message>
        <source>Add the axis words (X, Y, Z or A).</source>
        <translation>Add the axis words (X, Y, Z or A).</translation>
    </message>
    <message>
        <source>%1 must not be negative</source>
        <translation>%1 must not be negative</translation>
    </message>
    <message>
        <source>Use zero or a positive value.</source>
        <translation>Use zero or a positive value.</translation>
    </message>
    <message>
        <source>G53 needs G0 or G1</source>
        <translation>G53 needs G0 or G1</translation>
    </message>
    <message>
        <source>Write G53 together with G0 or G1 on the same line.</source>
        <translation>Write G53 together with G0 or G1 on the same line.</translation>
    </message>
    <message>
        <source>G53 cannot be used in G91 mode</source>
        <translation>G53 cannot be used in G91 mode</translation>
    </message>
    <message>
        <source>Switch to G90 before moving in machine coordinates.</source>
        <translation>Switch to G90 before moving in machine coordinates.</translation>
    </message>
    <message>
        <source>G4 needs the dwell time P</source>
        <translation>G4 needs the dwell time P</translation>
    </message>
    <message>
        <source>Add P with the dwell time in seconds.</source>
        <translation>Add P with the dwell time in seconds.</translation>
    </message>
    <message>
        <source>G10 %1 is not supported</source>
        <translation>G10 %1 is not supported</translation>
    </message>
    <message>
        <source>G10 needs P0 to P9 (got %1)</source>
        <translation>G10 needs P0 to P9 (got %1)</translation>
    </message>
    <message>
        <source>P0 is the active coordinate system, P1 to P9 are G54 to G59.3.</source>
        <translation>P0 is the active coordinate system, P1 to P9 are G54 to G59.3.</translation>
    </message>
    <message>
        <source>%1 with zero feed rate</source>
        <translation>%1 with zero feed rate</translation>
    </message>
    <message>
        <source>Set a feed rate with F before the first feed move.</source>
        <translation>Set a feed rate with F before the first feed move.</translation>
    </message>
    <message>
        <source>%1 in inverse time mode (G93) needs an F word</source>
        <translation>%1 in inverse time mode (G93) needs an F word</translation>
    </message>
    <message>
        <source>Give F on every feed move in G93, or switch to G94.</source>
        <translation>Give F on every feed move in G93, or switch to G94.</translation>
    </message>
    <message>
        <source>Arc without I, J, K or R</source>
        <translation>Arc without I, J, K or R</translation>
    </message>
    <message>
        <source>Give the centre with I/J/K or the radius with R.</source>
        <translation>Give the centre with I/J/K or the radius with R.</translation>
    </message>
    <message>
        <source>Arc with both R and I/J/K</source>
        <translation>Arc with both R and I/J/K</translation>
    </message>
    <message>
        <source>Use either the centre (I/J/K) or the radius (R).</source>
        <translation>Use either the centre (I/J/K) or the radius (R).</translation>
    </message>
    <message>
        <source>%1 is not in the arc&apos;s plane</source>
        <translation>%1 is not in the arc&apos;s plane</translation>
    </message>
    <message>
        <source>G17 uses I and J, G18 uses I and K, G19 uses J and K.</source>
        <translation>G17 uses I and J, G18 uses I and K, G19 uses J and K.</translation>
    </message>
    <message>
        <source>%1 is missing for an arc with absolute centre (G90.1)</source>
        <translation>%1 is missing for an arc with absolute centre (G90.1)</translation>
    </message>
    <message>
        <source>Give both centre coordinates in G90.1 mode.</source>
        <translation>Give both centre coordinates in G90.1 mode.</translation>
    </message>
    <message>
        <source>Arc with zero radius %1</source>
        <translation>Arc with zero radius %1</translation>
    </message>
    <message>
        <source>Check the centre offsets I/J/K.</source>
        <translation>Check the centre offsets I/J/K.</translation>
    </message>
    <message>
        <source>Arc end point is not on the circle: %1</source>
        <translation>Arc end point is not on the circle: %1</translation>
    </message>
    <message>
        <source>Check the end point and the centre; the radii to start and end must match.</source>
        <translation>Check the end point and the centre; the radii to start and end must match.</translation>
    </message>
    <message>
        <source>Arc radius is too small to reach the end point %1</source>
        <translation>Arc radius is too small to reach the end point %1</translation>
    </message>
    <message>
        <source>Use a radius of at least half the distance between start and end.</source>
        <translation>Use a radius of at least half the distance between start and end.</translation>
    </message>
    <message>
        <source>Arc given by R ends where it starts</source>
        <translation>Arc given by R ends where it starts</translation>
    </message>
    <message>
        <source>Use I/J/K to program a full circle.</source>
        <translation>Use I/J/K to program a full circle.</translation>
    </message>
    <message>
        <source>Arc given by R has no end point in its plane</source>
        <translation>Arc given by R has no end point in its plane</translation>
    </message>
    <message>
        <source>Give the end point, or use I/J/K for a full circle.</source>
        <translation>Give the end point, or use I/J/K for a full circle.</translation>
    </message>
    <message>
        <source>Arc turns P must be a positive integer (got %1)</source>
        <translation>Arc turns P must be a positive integer (got %1)</translation>
    </message>
    <message>
        <source>Use P1 or more, or leave P out.</source>
        <translation>Use P1 or more, or leave P out.</translation>
    </message>
    <message>
        <source>Probe move does not move</source>
        <translation>Probe move does not move</translation>
    </message>
    <message>
        <source>Give an end point different from the current position.</source>
        <translation>Give an end point different from the current position.</translation>
    </message>
    <message>
        <source>Probe move in inverse time mode (G93)</source>
        <translation>Probe move in inverse time mode (G93)</translation>
    </message>
    <message>
        <source>Switch to G94 before probing.</source>
        <translation>Switch to G94 before probing.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs R</source>
        <translation>Canned cycle %1 needs R</translation>
    </message>
    <message>
        <source>Give the retract plane R on the first block of the cycle.</source>
        <translation>Give the retract plane R on the first block of the cycle.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs its depth</source>
        <translation>Canned cycle %1 needs its depth</translation>
    </message>
    <message>
        <source>Give the hole depth (Z in G17) on the first block of the cycle.</source>
        <translation>Give the hole depth (Z in G17) on the first block of the cycle.</translation>
    </message>
    <message>
        <source>Canned cycle retract plane R is below the hole depth</source>
        <translation>Canned cycle retract plane R is below the hole depth</translation>
    </message>
    <message>
        <source>R must be above the bottom of the hole.</source>
        <translation>R must be above the bottom of the hole.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs the dwell P</source>
        <translation>Canned cycle %1 needs the dwell P</translation>
    </message>
    <message>
        <source>Give P (seconds) on the first block of the cycle.</source>
        <translation>Give P (seconds) on the first block of the cycle.</translation>
    </message>
    <message>
        <source>Canned cycle %1 needs the peck Q</source>
        <translation>Canned cycle %1 needs the peck Q</translation>
    </message>
    <message>
        <source>Give Q (peck depth) on the first block of the cycle.</source>
        <translation>Give Q (peck depth) on the first block of the cycle.</translation>
    </message>
    <message>
        <source>Peck depth Q must be positive</source>
        <translation>Peck depth Q must be positive</translation>
    </message>
    <message>
        <source>Use a positive Q.</source>
        <translation>Use a positive Q.</translation>
    </message>
    <message>
        <source>Canned cycle repeat L must be a positive integer</source>
        <translation>Canned cycle repeat L must be a positive integer</translation>
    </message>
    <message>
        <source>Use L1 or more, or leave L out.</source>
        <translation>Use L1 or more, or leave L out.</translation>
    </message>
    <message>
        <source>Canned cycle in inverse time mode (G93)</source>
        <translation>Canned cycle in inverse time mode (G93)</translation>
    </message>
    <message>
        <source>Switch to G94 before a canned cycle.</source>
        <translation>Switch to G94 before a canned cycle.</translation>
    </message>
    <message>
        <source>Expression is not closed</source>
        <translation>Expression is not closed</translation>
    </message>
    <message>
        <source>Add the missing &apos;]&apos;.</source>
        <translation>Add the missing &apos;]&apos;.</translation>
    </message>
    <message>
        <source>Unknown operator %1</source>
        <translation>Unknown operator %1</translation>
    </message>
    <message>
        <source>Use + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.</source>
        <translation>Use + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.</translation>
    </message>
    <message>
        <source>Unknown function %1</source>
        <translation>Unknown function %1</translation>
    </message>
    <message>
        <source>See the list of functions (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, SIN, SQRT, TAN, EXISTS).</source>
        <translation>See the list of functions (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, SIN, SQRT, TAN, EXISTS).</translation>
    </message>
    <message>
        <source>Division by zero</source>
        <translation>Division by zero</translation>
    </message>
    <message>
        <source>Check the divisor.</source>
        <translation>Check the divisor.</translation>
    </message>
    <message>
        <source>%1 of a value outside its domain</source>
        <translation>%1 of a value outside its domain</translation>
    </message>
    <message>
        <source>Check the argument (e.g. SQRT of a negative number).</source>
        <translation>Check the argument (e.g. SQRT of a negative number).</translation>
    </message>
    <message>
        <source>Negative number raised to a non-integer power</source>
        <translation>Negative number raised to a non-integer power</translation>
    </message>
    <message>
        <source>Check the operands of **.</source>
        <translation>Check the operands of **.</translation>
    </message>
    <message>
        <source>Parameter number %1 is out of range</source>
        <translation>Parameter number %1 is out of range</translation>
    </message>
    <message>
        <source>Use parameters #1 to #5601.</source>
        <translation>Use parameters #1 to #5601.</translation>
    </message>
    <message>
        <source>Parameter %1 is not defined</source>
        <translation>Parameter %1 is not defined</translation>
    </message>
    <message>
        <source>Assign it a value before reading it.</source>
        <translation>Assign it a value before reading it.</translation>
    </message>
    <message>
        <source>Parameter %1 is read-only</source>
        <translation>Parameter %1 is read-only</translation>
    </message>
    <message>
        <source>System parameters are set by codes (e.g. G10 L2, G92), not by assignment.</source>
        <translation>System parameters are set by codes (e.g. G10 L2, G92), not by assignment.</translation>
    </message>
    <message>
        <source>Bad parameter name %1</source>
        <translation>Bad parameter name %1</translation>
    </message>
    <message>
        <source>Write named parameters as #&lt;name&gt;.</source>
        <translation>Write named parameters as #&lt;name&gt;.</translation>
    </message>
    <message>
        <source>An expression is expected %1</source>
        <translation>An expression is expected %1</translation>
    </message>
    <message>
        <source>Write the value in brackets, e.g. [#1 + 2].</source>
        <translation>Write the value in brackets, e.g. [#1 + 2].</translation>
    </message>
    <message>
        <source>Malformed O word %1</source>
        <translation>Malformed O word %1</translation>
    </message>
    <message>
        <source>Write O-words as o100 if [...] or o&lt;name&gt; sub.</source>
        <translation>Write O-words as o100 if [...] or o&lt;name&gt; sub.</translation>
    </message>
    <message>
        <source>Unknown O-word keyword %1</source>
        <translation>Unknown O-word keyword %1</translation>
    </message>
    <message>
        <source>Use sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, break or continue.</source>
        <translation>Use sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, break or continue.</translation>
    </message>
    <message>
        <source>An O-word line has other words</source>
        <translation>An O-word line has other words</translation>
    </message>
    <message>
        <source>Put the other words on their own line.</source>
        <translation>Put the other words on their own line.</translation>
    </message>
    <message>
        <source>%1 without its opening O-word</source>
        <translation>%1 without its opening O-word</translation>
    </message>
    <message>
        <source>Check the O numbers; they must match the opening line.</source>
        <translation>Check the O numbers; they must match the opening line.</translation>
    </message>
    <message>
        <source>%1 is never closed</source>
        <translation>%1 is never closed</translation>
    </message>
    <message>
        <source>Add the matching end line (endsub, endif, endwhile, endrepeat or while).</source>
        <translation>Add the matching end line (endsub, endif, endwhile, endrepeat or while).</translation>
    </message>
    <message>
        <source>Subroutine %1 is not defined</source>
        <translation>Subroutine %1 is not defined</translation>
    </message>
    <message>
        <source>Subroutine calls nested too deeply</source>
        <translation>Subroutine calls nested too deeply</translation>
    </message>
    <message>
        <source>Check for unbounded recursion.</source>
        <translation>Check for unbounded recursion.</translation>
    </message>
    <message>
        <source>%1 outside a loop with this O number</source>
        <translation>%1 outside a loop with this O number</translation>
    </message>
    <message>
        <source>Use break and continue only inside their own loop.</source>
        <translation>Use break and continue only inside their own loop.</translation>
    </message>
    <message>
        <source>%1 outside a subroutine</source>
        <translation>%1 outside a subroutine</translation>
    </message>
    <message>
        <source>Use return and endsub only inside a subroutine.</source>
        <translation>Use return and endsub only inside a subroutine.</translation>
    </message>
    <message>
        <source>Value of %1 is out of range</source>
        <translation>Value of %1 is out of range</translation>
    </message>
    <message>
        <source>Values must be finite and below 1e12 in size; check the expression.</source>
        <translation>Values must be finite and below 1e12 in size; check the expression.</translation>
    </message>
    <message>
        <source>%1: OK, %2 lines</source>
        <translation>%1: OK, %2 lines</translation>
    </message>
    <message>
        <source>moves: %1 (rapid %2, feed %3, arc %4, probe %5), dwells: %6</source>
        <translation>moves: %1 (rapid %2, feed %3, arc %4, probe %5), dwells: %6</translation>
    </message>
    <message>
        <source>bounds (machine, mm): X %1 .. %2, Y %3 .. %4, Z %5 .. %6, A %7 .. %8</source>
        <translation>bounds (machine, mm): X %1 .. %2, Y %3 .. %4, Z %5 .. %6, A %7 .. %8</translation>
    </message>
    <message>
        <source>length: rapid %1 mm, feed %2 mm</source>
        <translation>length: rapid %1 mm, feed %2 mm</translation>
    </message>
    <message>
        <source>naive time: %1:%2:%3 (rapid %4 mm/min, no acceleration)</source>
        <translation>naive time: %1:%2:%3 (rapid %4 mm/min, no acceleration)</translation>
    </message>
    <message>
        <source>usage: frezka-cli toolpath FILE [--events]</source>
        <translation>usage: frezka-cli toolpath FILE [--events]</translation>
    </message>
    <message>
        <source>frezka-cli: cannot write the toolpath</source>
        <translation>frezka-cli: cannot write the toolpath</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n error(s)</source>
        <translation>
            <numerusform>%1: %n error</numerusform>
            <numerusform>%1: %n errors</numerusform>
        </translation>
    </message>
    <message>
        <source>usage: frezka-cli check FILE [--rapid MM_PER_MIN] %1</source>
        <translation>usage: frezka-cli check FILE [--rapid MM_PER_MIN] %1</translation>
    </message>
    <message>
        <source>F%1 was read in %2 (line %3) before this change of units: the feed moves after it run at %1 %2 (%4 %5), as in LinuxCNC, not at %1 %5 (%6 %2)</source>
        <translation>F%1 was read in %2 (line %3) before this change of units: the feed moves after it run at %1 %2 (%4 %5), as in LinuxCNC, not at %1 %5 (%6 %2)</translation>
    </message>
    <message>
        <source>LinuxCNC reads F before G20/G21, also on the same line; if %1 %5 was meant, give F again after the change of units.</source>
        <translation>LinuxCNC reads F before G20/G21, also on the same line; if %1 %5 was meant, give F again after the change of units.</translation>
    </message>
    <message>
        <source>warning: </source>
        <translation>warning: </translation>
    </message>
    <message>
        <source>note: </source>
        <translation>note: </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n more warning(s) not shown</source>
        <translation>
            <numerusform>%1: %n more warning not shown</numerusform>
            <numerusform>%1: %n more warnings not shown</numerusform>
        </translation>
    </message>
    <message>
        <source>$H is grbl&apos;s homing command, not G-code</source>
        <translation>$H is grbl&apos;s homing command, not G-code</translation>
    </message>
    <message>
        <source>%1 is a grbl system command, not G-code</source>
        <translation>%1 is a grbl system command, not G-code</translation>
    </message>
    <message>
        <source>Delete the line; grbl&apos;s $ settings and commands have no meaning here (set the machine up in Frezka&apos;s machine profile, home and jog from Frezka).</source>
        <translation>Delete the line; grbl&apos;s $ settings and commands have no meaning here (set the machine up in Frezka&apos;s machine profile, home and jog from Frezka).</translation>
    </message>
    <message>
        <source>&apos;//&apos; comments are not RS274/NGC G-code (they come from other controllers&apos; dialects, e.g. Beckhoff TwinCAT)</source>
        <translation>&apos;//&apos; comments are not RS274/NGC G-code (they come from other controllers&apos; dialects, e.g. Beckhoff TwinCAT)</translation>
    </message>
    <message>
        <source>Write the comment in parentheses ( ) or after a semicolon ;.</source>
        <translation>Write the comment in parentheses ( ) or after a semicolon ;.</translation>
    </message>
    <message>
        <source>M29 is the rigid tapping code of Fanuc-style controllers</source>
        <translation>M29 is the rigid tapping code of Fanuc-style controllers</translation>
    </message>
    <message>
        <source>Frezka has no spindle-synchronised tapping (the GVE units have no spindle encoder): tap with a floating tap holder or by hand, and post the program without M29 and G84.</source>
        <translation>Frezka has no spindle-synchronised tapping (the GVE units have no spindle encoder): tap with a floating tap holder or by hand, and post the program without M29 and G84.</translation>
    </message>
    <message>
        <source>The file ends without M2, M30 or %: the program is taken to end here, with the spindle and coolant switched off as at M2</source>
        <translation>The file ends without M2, M30 or %: the program is taken to end here, with the spindle and coolant switched off as at M2</translation>
    </message>
    <message>
        <source>Check that the file is complete (not cut short when it was copied); end the program with M2 or M30.</source>
        <translation>Check that the file is complete (not cut short when it was copied); end the program with M2 or M30.</translation>
    </message>
    <message>
        <source>G4 P%1 dwells %1 seconds (%2), as in LinuxCNC; if the post meant milliseconds (as Mach3 and UCCNC can), that is %3 s</source>
        <translation>G4 P%1 dwells %1 seconds (%2), as in LinuxCNC; if the post meant milliseconds (as Mach3 and UCCNC can), that is %3 s</translation>
    </message>
    <message>
        <source>Frezka reads P in seconds; write P%3 if %3 s was meant.</source>
        <translation>Frezka reads P in seconds; write P%3 if %3 s was meant.</translation>
    </message>
    <message>
        <source>%1 has no effect on an arc in the %2 plane and is ignored</source>
        <translation>%1 has no effect on an arc in the %2 plane and is ignored</translation>
    </message>
    <message>
        <source>Some posts (e.g. FreeCAD&apos;s grbl post) write it; LinuxCNC refuses it, and any value other than 0 is an error.</source>
        <translation>Some posts (e.g. FreeCAD&apos;s grbl post) write it; LinuxCNC refuses it, and any value other than 0 is an error.</translation>
    </message>
    <message>
        <source>Home the machine from Frezka (Home all) before starting the program, and delete this line.</source>
        <translation>Home the machine from Frezka (Home all) before starting the program, and delete this line.</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n more error(s) not shown</source>
        <translation>
            <numerusform>%1: %n more error not shown</numerusform>
            <numerusform>%1: %n more errors not shown</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot write the file %1: %2</source>
        <translation>Cannot write the file %1: %2</translation>
    </message>
    <message>
        <source>Check that the folder exists and is writable and that the disk is not full; the old file is kept unchanged.</source>
        <translation>Check that the folder exists and is writable and that the disk is not full; the old file is kept unchanged.</translation>
    </message>
    <message>
        <source>Tool table entry cannot be read at &apos;%1&apos;</source>
        <translation>Tool table entry cannot be read at &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Each line is T&lt;tool&gt; P&lt;pocket&gt; with optional X Y Z A B C U V W offsets, D diameter, I J angles and Q orientation (0-9), each letter once, then an optional ; comment, as in LinuxCNC&apos;s .tbl files. Correct the line in Machine &gt; Tool table or in a text editor.</source>
        <translation>Each line is T&lt;tool&gt; P&lt;pocket&gt; with optional X Y Z A B C U V W offsets, D diameter, I J angles and Q orientation (0-9), each letter once, then an optional ; comment, as in LinuxCNC&apos;s .tbl files. Correct the line in Machine &gt; Tool table or in a text editor.</translation>
    </message>
    <message>
        <source>Tool %1 is listed twice in the tool table</source>
        <translation>Tool %1 is listed twice in the tool table</translation>
    </message>
    <message>
        <source>Keep one line per tool number; delete or renumber the other.</source>
        <translation>Keep one line per tool number; delete or renumber the other.</translation>
    </message>
    <message>
        <source>Use G10 L2 or G10 L20 to set a work offset, G10 L1, L10 or L11 to set a tool&apos;s offsets.</source>
        <translation>Use G10 L2 or G10 L20 to set a work offset, G10 L1, L10 or L11 to set a tool&apos;s offsets.</translation>
    </message>
    <message>
        <source>Tool %1 is not in the tool table</source>
        <translation>Tool %1 is not in the tool table</translation>
    </message>
    <message>
        <source>Add the tool with its length and diameter in Machine &gt; Tool table, or correct the T, H or P number.</source>
        <translation>Add the tool with its length and diameter in Machine &gt; Tool table, or correct the T, H or P number.</translation>
    </message>
    <message>
        <source>%1 needs either H or axis words, not both or none</source>
        <translation>%1 needs either H or axis words, not both or none</translation>
    </message>
    <message>
        <source>G43.2 Hn adds tool n&apos;s offsets, G43.2 Z.. adds the given values; G43.1 takes axis words only.</source>
        <translation>G43.2 Hn adds tool n&apos;s offsets, G43.2 Z.. adds the given values; G43.1 takes axis words only.</translation>
    </message>
    <message>
        <source>%1 without offsets has no effect</source>
        <translation>%1 without offsets has no effect</translation>
    </message>
    <message>
        <source>Give the values to set, e.g. Z for the tool length and R for its radius.</source>
        <translation>Give the values to set, e.g. Z for the tool length and R for its radius.</translation>
    </message>
    <message>
        <source>%1 needs the tool number in %2</source>
        <translation>%1 needs the tool number in %2</translation>
    </message>
    <message>
        <source>Write the number of a tool of the tool table, e.g. M61 Q3 or G10 L1 P3 Z25.</source>
        <translation>Write the number of a tool of the tool table, e.g. M61 Q3 or G10 L1 P3 Z25.</translation>
    </message>
    <message>
        <source>%1 with tool %2, a lathe tool (orientation %3): the compensation of a lathe tool&apos;s nose radius is not supported</source>
        <translation>%1 with tool %2, a lathe tool (orientation %3): the compensation of a lathe tool&apos;s nose radius is not supported</translation>
    </message>
    <message>
        <source>Give a mill tool orientation 0 in Machine &gt; Tool table, or post the program again from the CAM with the compensation computed there.</source>
        <translation>Give a mill tool orientation 0 in Machine &gt; Tool table, or post the program again from the CAM with the compensation computed there.</translation>
    </message>
    <message>
        <source>%1: cutter radius compensation works only in the XY (G17) and XZ (G18) planes</source>
        <translation>%1: cutter radius compensation works only in the XY (G17) and XZ (G18) planes</translation>
    </message>
    <message>
        <source>Select G17 or G18 before turning the compensation on.</source>
        <translation>Select G17 or G18 before turning the compensation on.</translation>
    </message>
    <message>
        <source>%1 while cutter radius compensation is already on</source>
        <translation>%1 while cutter radius compensation is already on</translation>
    </message>
    <message>
        <source>Turn it off with G40 first, as LinuxCNC requires.</source>
        <translation>Turn it off with G40 first, as LinuxCNC requires.</translation>
    </message>
    <message>
        <source>%1 is not allowed while cutter radius compensation is on</source>
        <translation>%1 is not allowed while cutter radius compensation is on</translation>
    </message>
    <message>
        <source>Turn the compensation off with G40 before this block and on again after it, as LinuxCNC requires.</source>
        <translation>Turn the compensation off with G40 before this block and on again after it, as LinuxCNC requires.</translation>
    </message>
    <message>
        <source>%1 needs D, the diameter of the tool</source>
        <translation>%1 needs D, the diameter of the tool</translation>
    </message>
    <message>
        <source>Write the tool&apos;s diameter in D, e.g. %1 D6.</source>
        <translation>Write the tool&apos;s diameter in D, e.g. %1 D6.</translation>
    </message>
    <message>
        <source>The move that starts the cutter radius compensation is not longer than the tool radius (%1)</source>
        <translation>The move that starts the cutter radius compensation is not longer than the tool radius (%1)</translation>
    </message>
    <message>
        <source>Start the compensation from a point farther from the path than the tool radius, e.g. with a lead-in move from outside the part.</source>
        <translation>Start the compensation from a point farther from the path than the tool radius, e.g. with a lead-in move from outside the part.</translation>
    </message>
    <message>
        <source>The tool radius (%1) is not smaller than the radius of this arc, which the tool follows on its inside</source>
        <translation>The tool radius (%1) is not smaller than the radius of this arc, which the tool follows on its inside</translation>
    </message>
    <message>
        <source>Use a smaller tool (D), or make the arc larger than the tool.</source>
        <translation>Use a smaller tool (D), or make the arc larger than the tool.</translation>
    </message>
    <message>
        <source>The compensated tool (radius %1) cannot reach this corner without cutting into the part</source>
        <translation>The compensated tool (radius %1) cannot reach this corner without cutting into the part</translation>
    </message>
    <message>
        <source>Use a smaller tool, or change the path so that the tool fits into the inside corner (LinuxCNC refuses it too).</source>
        <translation>Use a smaller tool, or change the path so that the tool fits into the inside corner (LinuxCNC refuses it too).</translation>
    </message>
    <message>
        <source>The move just after G40 must be straight, not an arc</source>
        <translation>The move just after G40 must be straight, not an arc</translation>
    </message>
    <message>
        <source>Add a straight move (G0 or G1) after G40, before the arc.</source>
        <translation>Add a straight move (G0 or G1) after G40, before the arc.</translation>
    </message>
    <message>
        <source>%1 with tool %2, whose diameter is 0: the path is not compensated</source>
        <translation>%1 with tool %2, whose diameter is 0: the path is not compensated</translation>
    </message>
    <message>
        <source>Enter the tool&apos;s diameter in Machine &gt; Tool table; as it is, the tool follows the programmed path, off the part&apos;s contour by its radius.</source>
        <translation>Enter the tool&apos;s diameter in Machine &gt; Tool table; as it is, the tool follows the programmed path, off the part&apos;s contour by its radius.</translation>
    </message>
    <message>
        <source>Polar coordinates (@ radius, ^ angle) cannot be used here (%1)</source>
        <translation>Polar coordinates (@ radius, ^ angle) cannot be used here (%1)</translation>
    </message>
    <message>
        <source>Use @ and ^ only in the XY plane (G17), without X and Y words and without G53; at X0 Y0 give the angle ^ with an absolute radius @ (G90).</source>
        <translation>Use @ and ^ only in the XY plane (G17), without X and Y words and without G53; at X0 Y0 give the angle ^ with an absolute radius @ (G90).</translation>
    </message>
    <message>
        <source>The program has executed %1 lines and has not ended; it was stopped here</source>
        <translation>The program has executed %1 lines and has not ended; it was stopped here</translation>
    </message>
    <message>
        <source>If the program is really this long, raise the machine profile&apos;s program.maxLinesExecuted (Settings › Machine profile › Program).</source>
        <translation>If the program is really this long, raise the machine profile&apos;s program.maxLinesExecuted (Settings › Machine profile › Program).</translation>
    </message>
    <message>
        <source>The program has made %1 moves and has not ended; it was stopped here</source>
        <translation>The program has made %1 moves and has not ended; it was stopped here</translation>
    </message>
    <message>
        <source>If the program really has more moves, raise the machine profile&apos;s program.maxMoves (Settings › Machine profile › Program); a million moves take about 50 MB of memory to check, more to plan and show.</source>
        <translation>If the program really has more moves, raise the machine profile&apos;s program.maxMoves (Settings › Machine profile › Program); a million moves take about 50 MB of memory to check, more to plan and show.</translation>
    </message>
    <message>
        <source>%3 has not ended after %1 lines executed (it was stopped at line %2)</source>
        <translation>%3 has not ended after %1 lines executed (it was stopped at line %2)</translation>
    </message>
    <message>
        <source>Check what ends it (its condition, its count, the exit of a recursion); if it is meant to run this long, raise the machine profile&apos;s program.maxLinesExecuted (Settings › Machine profile › Program).</source>
        <translation>Check what ends it (its condition, its count, the exit of a recursion); if it is meant to run this long, raise the machine profile&apos;s program.maxLinesExecuted (Settings › Machine profile › Program).</translation>
    </message>
    <message>
        <source>%3 has not ended after %1 moves (it was stopped at line %2)</source>
        <translation>%3 has not ended after %1 moves (it was stopped at line %2)</translation>
    </message>
    <message>
        <source>Check what ends it (its condition, its count, the exit of a recursion); if it is meant to make more moves, raise the machine profile&apos;s program.maxMoves (Settings › Machine profile › Program).</source>
        <translation>Check what ends it (its condition, its count, the exit of a recursion); if it is meant to make more moves, raise the machine profile&apos;s program.maxMoves (Settings › Machine profile › Program).</translation>
    </message>
    <message>
        <source>The program aborts here: %1</source>
        <translation>The program aborts here: %1</translation>
    </message>
    <message>
        <source>An (abort, ...) comment ends the program, as in LinuxCNC. Change the program so that it does not reach this line.</source>
        <translation>An (abort, ...) comment ends the program, as in LinuxCNC. Change the program so that it does not reach this line.</translation>
    </message>
    <message>
        <source>%1 is not supported under a coordinate system rotation (G10 L2 R)</source>
        <translation>%1 is not supported under a coordinate system rotation (G10 L2 R)</translation>
    </message>
    <message>
        <source>Arcs outside G17 and cutter radius compensation need the rotation off: set R0 (G10 L2 P0 R0) for that part, or rotate the part in the CAM.</source>
        <translation>Arcs outside G17 and cutter radius compensation need the rotation off: set R0 (G10 L2 P0 R0) for that part, or rotate the part in the CAM.</translation>
    </message>
    <message>
        <source>%1 shares its line with other words</source>
        <translation>%1 shares its line with other words</translation>
    </message>
    <message>
        <source>Put M70, M71, M72 and M73 on a line of their own (LinuxCNC runs them in the middle of the line&apos;s other codes).</source>
        <translation>Put M70, M71, M72 and M73 on a line of their own (LinuxCNC runs them in the middle of the line&apos;s other codes).</translation>
    </message>
    <message>
        <source>%1 restores a state that was not saved at this level</source>
        <translation>%1 restores a state that was not saved at this level</translation>
    </message>
    <message>
        <source>Save the modal state with M70 (or M73) in the same subroutine, or at the top level, before M72, and do not invalidate it with M71 in between.</source>
        <translation>Save the modal state with M70 (or M73) in the same subroutine, or at the top level, before M72, and do not invalidate it with M71 in between.</translation>
    </message>
    <message>
        <source>Define it in this file with o&lt;name&gt; sub ... o&lt;name&gt; endsub, or in a file name.ngc beside the program or in a folder of the machine profile&apos;s program.subroutinePath (Settings › Machine profile › Program).</source>
        <translation>Define it in this file with o&lt;name&gt; sub ... o&lt;name&gt; endsub, or in a file name.ngc beside the program or in a folder of the machine profile&apos;s program.subroutinePath (Settings › Machine profile › Program).</translation>
    </message>
    <message>
        <source>This INI line is not [SECTION] nor NAME = VALUE: %1</source>
        <translation>This INI line is not [SECTION] nor NAME = VALUE: %1</translation>
    </message>
    <message>
        <source>Fix the line or make it a comment (starting with # or ;).</source>
        <translation>Fix the line or make it a comment (starting with # or ;).</translation>
    </message>
    <message>
        <source>%1 sub is defined inside the running subroutine %2</source>
        <translation>%1 sub is defined inside the running subroutine %2</translation>
    </message>
    <message>
        <source>Move the definition out of %2: define it before or after it (in its own file name.ngc when %2 is in a file), as LinuxCNC requires.</source>
        <translation>Move the definition out of %2: define it before or after it (in its own file name.ngc when %2 is in a file), as LinuxCNC requires.</translation>
    </message>
    <message>
        <source>Subroutine %1 is not defined yet and there is no file %2 on the subroutine path</source>
        <translation>Subroutine %1 is not defined yet and there is no file %2 on the subroutine path</translation>
    </message>
    <message>
        <source>A subroutine file holds only its own subroutine (as in LinuxCNC): put %1 in a file %2 beside the program or in a folder of the machine profile&apos;s program.subroutinePath, or define it in the program.</source>
        <translation>A subroutine file holds only its own subroutine (as in LinuxCNC): put %1 in a file %2 beside the program or in a folder of the machine profile&apos;s program.subroutinePath, or define it in the program.</translation>
    </message>
    <message>
        <source>The file %2 has no line %1 sub</source>
        <translation>The file %2 has no line %1 sub</translation>
    </message>
    <message>
        <source>A file name.ngc found for o&lt;name&gt; call must define o&lt;name&gt; sub ... o&lt;name&gt; endsub; rename the file or fix its sub line.</source>
        <translation>A file name.ngc found for o&lt;name&gt; call must define o&lt;name&gt; sub ... o&lt;name&gt; endsub; rename the file or fix its sub line.</translation>
    </message>
    <message>
        <source>%1: splines work only in the XY plane (G17)</source>
        <translation>%1: splines work only in the XY plane (G17)</translation>
    </message>
    <message>
        <source>Select G17 before the spline, as LinuxCNC requires, or re-post the curve as arcs or lines in its plane.</source>
        <translation>Select G17 before the spline, as LinuxCNC requires, or re-post the curve as arcs or lines in its plane.</translation>
    </message>
    <message>
        <source>%1 cannot move %2: a spline moves X and Y only</source>
        <translation>%1 cannot move %2: a spline moves X and Y only</translation>
    </message>
    <message>
        <source>Move Z or A in a G1 block of its own before or after the spline.</source>
        <translation>Move Z or A in a G1 block of its own before or after the spline.</translation>
    </message>
    <message>
        <source>%1 needs %2</source>
        <translation>%1 needs %2</translation>
    </message>
    <message>
        <source>G5.1 X Y I J: I J is the control point, relative to the start. G5 X Y I J P Q: I J is the first control point, relative to the start (leave both out after a G5 to continue it smoothly), P Q the second, relative to the end.</source>
        <translation>G5.1 X Y I J: I J is the control point, relative to the start. G5 X Y I J P Q: I J is the first control point, relative to the start (leave both out after a G5 to continue it smoothly), P Q the second, relative to the end.</translation>
    </message>
    <message>
        <source>A NURBS control point needs both X and Y (%1)</source>
        <translation>A NURBS control point needs both X and Y (%1)</translation>
    </message>
    <message>
        <source>Give X, Y and the weight P on every line from G5.2 to G5.3; P alone is allowed only on the G5.2 line, as the start point&apos;s weight.</source>
        <translation>Give X, Y and the weight P on every line from G5.2 to G5.3; P alone is allowed only on the G5.2 line, as the start point&apos;s weight.</translation>
    </message>
    <message>
        <source>NURBS order L%1 is not supported</source>
        <translation>NURBS order L%1 is not supported</translation>
    </message>
    <message>
        <source>Give a whole L from 3 (quadratic, also when L is left out) to 10; L4 is cubic.</source>
        <translation>Give a whole L from 3 (quadratic, also when L is left out) to 10; L4 is cubic.</translation>
    </message>
    <message>
        <source>The NURBS has %1 control points, fewer than its order L%2</source>
        <translation>The NURBS has %1 control points, fewer than its order L%2</translation>
    </message>
    <message>
        <source>Give at least as many control points (the start point counts) as the order L before G5.3, or a lower L.</source>
        <translation>Give at least as many control points (the start point counts) as the order L before G5.3, or a lower L.</translation>
    </message>
    <message>
        <source>G5.3 without G5.2 first</source>
        <translation>G5.3 without G5.2 first</translation>
    </message>
    <message>
        <source>Start the control points with G5.2 X Y P L, or remove this G5.3.</source>
        <translation>Start the control points with G5.2 X Y P L, or remove this G5.3.</translation>
    </message>
    <message>
        <source>The NURBS started on line %1 is not ended by G5.3</source>
        <translation>The NURBS started on line %1 is not ended by G5.3</translation>
    </message>
    <message>
        <source>End its control points with G5.3 before another motion or the program end (LinuxCNC would drop the curve without cutting it).</source>
        <translation>End its control points with G5.3 before another motion or the program end (LinuxCNC would drop the curve without cutting it).</translation>
    </message>
    <message>
        <source>%1 in the block of G5.3</source>
        <translation>%1 in the block of G5.3</translation>
    </message>
    <message>
        <source>Between G5.2 and G5.3 only further G5.2 control points may come; put other motions on a line of their own after G5.3.</source>
        <translation>Between G5.2 and G5.3 only further G5.2 control points may come; put other motions on a line of their own after G5.3.</translation>
    </message>
    <message>
        <source>A G5.2 NURBS in inverse time mode (G93)</source>
        <translation>A G5.2 NURBS in inverse time mode (G93)</translation>
    </message>
    <message>
        <source>Switch to G94 and give the feed with F before G5.2 (LinuxCNC does not define how long a NURBS takes in G93).</source>
        <translation>Switch to G94 and give the feed with F before G5.2 (LinuxCNC does not define how long a NURBS takes in G93).</translation>
    </message>
    <message>
        <source>A NURBS control point needs a weight P from 0.000001 to 1000000 (%1)</source>
        <translation>A NURBS control point needs a weight P from 0.000001 to 1000000 (%1)</translation>
    </message>
    <message>
        <source>Give P on every control point (P1 for an ordinary B-spline point; LinuxCNC takes -1 when it is missing).</source>
        <translation>Give P on every control point (P1 for an ordinary B-spline point; LinuxCNC takes -1 when it is missing).</translation>
    </message>
</context>
<context>
    <name>frezka::gcode::HeightMap</name>
    <message>
        <source>Height map line %1: unknown key &apos;%2&apos;. Use the keys of docs/height-map.md or make the line a plain comment without a colon.</source>
        <translation>Height map line %1: unknown key &apos;%2&apos;. Use the keys of docs/height-map.md or make the line a plain comment without a colon.</translation>
    </message>
    <message>
        <source>Height map line %1: &apos;%2&apos; is not a number. Write it as a number in millimetres, such as 10 or -0.25.</source>
        <translation>Height map line %1: &apos;%2&apos; is not a number. Write it as a number in millimetres, such as 10 or -0.25.</translation>
    </message>
    <message>
        <source>The height map lacks a grid key. Its header needs origin_x_mm, origin_y_mm, spacing_x_mm, spacing_y_mm, count_x and count_y.</source>
        <translation>The height map lacks a grid key. Its header needs origin_x_mm, origin_y_mm, spacing_x_mm, spacing_y_mm, count_x and count_y.</translation>
    </message>
    <message>
        <source>The height map&apos;s grid is not usable: the spacings must be above 0 and the counts whole numbers of at least 2 (at most a million points). Probe the grid again or correct the header.</source>
        <translation>The height map&apos;s grid is not usable: the spacings must be above 0 and the counts whole numbers of at least 2 (at most a million points). Probe the grid again or correct the header.</translation>
    </message>
    <message>
        <source>Height map line 1: not a height map of version %1 (the first line must be &apos;# frezka-height-map %1&apos;). Probe the grid again with this version of Frezka.</source>
        <translation>Height map line 1: not a height map of version %1 (the first line must be &apos;# frezka-height-map %1&apos;). Probe the grid again with this version of Frezka.</translation>
    </message>
    <message>
        <source>Height map line %1: a header line after the first row. Move it above the rows.</source>
        <translation>Height map line %1: a header line after the first row. Move it above the rows.</translation>
    </message>
    <message>
        <source>Height map line %1: expected three numbers X,Y,Z separated by commas. Correct the row or probe the grid again.</source>
        <translation>Height map line %1: expected three numbers X,Y,Z separated by commas. Correct the row or probe the grid again.</translation>
    </message>
    <message>
        <source>Height map line %1: X %2, Y %3 is not a point of the grid in the header. Correct the row or the header.</source>
        <translation>Height map line %1: X %2, Y %3 is not a point of the grid in the header. Correct the row or the header.</translation>
    </message>
    <message>
        <source>Height map line %1: the point X %2, Y %3 is given twice. Remove one of the rows.</source>
        <translation>Height map line %1: the point X %2, Y %3 is given twice. Remove one of the rows.</translation>
    </message>
    <message>
        <source>The height map has no row for X %1, Y %2. Every point of the grid needs one; probe the grid again.</source>
        <translation>The height map has no row for X %1, Y %2. Every point of the grid needs one; probe the grid again.</translation>
    </message>
    <message>
        <source>Cannot write the height map %1: %2. Choose a folder you may write to.</source>
        <translation>Cannot write the height map %1: %2. Choose a folder you may write to.</translation>
    </message>
    <message>
        <source>Cannot read the height map %1: %2. Check that the file exists and is readable.</source>
        <translation>Cannot read the height map %1: %2. Check that the file exists and is readable.</translation>
    </message>
    <message>
        <source>Line %1 cuts at X %2, Y %3, outside the height map (X %4 to %5, Y %6 to %7). Probe a grid that covers the whole program, or run it without the height map.</source>
        <translation>Line %1 cuts at X %2, Y %3, outside the height map (X %4 to %5, Y %6 to %7). Probe a grid that covers the whole program, or run it without the height map.</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::EmulatorTransport</name>
    <message>
        <source>The emulator is not open</source>
        <translation>The emulator is not open</translation>
    </message>
    <message>
        <source>emulator</source>
        <translation>emulator</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::SerialTransport</name>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>Cannot open %1: %2</translation>
    </message>
    <message>
        <source>Cannot set %1 to %2 Bd: %3</source>
        <translation>Cannot set %1 to %2 Bd: %3</translation>
    </message>
    <message>
        <source>%1 is not open</source>
        <translation>%1 is not open</translation>
    </message>
    <message>
        <source>Short write on %1: %2 of %3 bytes queued (%4)</source>
        <translation>Short write on %1: %2 of %3 bytes queued (%4)</translation>
    </message>
    <message>
        <source>Serial port %1: %2</source>
        <translation>Serial port %1: %2</translation>
    </message>
    <message>
        <source>Cannot open %1: permission denied. The port belongs to the group %2: join it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again.</source>
        <translation>Cannot open %1: permission denied. The port belongs to the group %2: join it with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again.</translation>
    </message>
    <message>
        <source>%1 (process %2)</source>
        <translation>%1 (process %2)</translation>
    </message>
    <message>
        <source>another program</source>
        <translation>another program</translation>
    </message>
    <message>
        <source>Cannot open %1: the port is in use by another program. Close it (or disconnect it), then connect again.</source>
        <translation>Cannot open %1: the port is in use by another program. Close it (or disconnect it), then connect again.</translation>
    </message>
    <message>
        <source>Cannot open %1: the port is in use by %2. Close that program (or disconnect it there), then connect again.</source>
        <translation>Cannot open %1: the port is in use by %2. Close that program (or disconnect it there), then connect again.</translation>
    </message>
    <message>
        <source>The port %1 went away: is the cable or the USB adapter unplugged? Plug it in, then connect again.</source>
        <translation>The port %1 went away: is the cable or the USB adapter unplugged? Plug it in, then connect again.</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::TransferSession</name>
    <message>
        <source>The port %1 is not open.</source>
        <translation>The port %1 is not open.</translation>
    </message>
    <message>
        <source>The data are too long for one message: %1 bytes, at most %2.</source>
        <translation>The data are too long for one message: %1 bytes, at most %2.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Cancelled.</translation>
    </message>
    <message>
        <source>&lt;- noise, %1 bytes skipped: %2</source>
        <translation>&lt;- noise, %1 bytes skipped: %2</translation>
    </message>
    <message>
        <source>Unexpected reply %1 to %2.</source>
        <translation>Unexpected reply %1 to %2.</translation>
    </message>
    <message>
        <source>The controller answered NAK to ENQ.</source>
        <translation>The controller answered NAK to ENQ.</translation>
    </message>
    <message>
        <source>The controller answered NAK to %1: is it set to program transfer (KONFIG6) with the selector in PGN?</source>
        <translation>The controller answered NAK to %1: is it set to program transfer (KONFIG6) with the selector in PGN?</translation>
    </message>
    <message>
        <source>The controller answered NAK to %1 (%2 times): it did not accept the data.</source>
        <translation>The controller answered NAK to %1 (%2 times): it did not accept the data.</translation>
    </message>
    <message>
        <source>&lt;- %1 ignored: no reply expected now</source>
        <translation>&lt;- %1 ignored: no reply expected now</translation>
    </message>
    <message>
        <source>Bad checksum in %1 from the controller: received %2, computed %3.</source>
        <translation>Bad checksum in %1 from the controller: received %2, computed %3.</translation>
    </message>
    <message>
        <source>%1 Given up after %2 repeats.</source>
        <translation>%1 Given up after %2 repeats.</translation>
    </message>
    <message>
        <source>Repeat %1 of %2: %3</source>
        <translation>Repeat %1 of %2: %3</translation>
    </message>
    <message>
        <source>The data message stopped after %1 of %2 bytes (no byte for %3 s).</source>
        <translation>The data message stopped after %1 of %2 bytes (no byte for %3 s).</translation>
    </message>
    <message>
        <source>No data from the controller within %1 s after %2.</source>
        <translation>No data from the controller within %1 s after %2.</translation>
    </message>
    <message>
        <source>No ACK to %1 within %2 s after its last byte.</source>
        <translation>No ACK to %1 within %2 s after its last byte.</translation>
    </message>
    <message>
        <source>The final ACK could not be sent within %1 s.</source>
        <translation>The final ACK could not be sent within %1 s.</translation>
    </message>
    <message>
        <source>Connected.</source>
        <translation>Connected.</translation>
    </message>
    <message>
        <source>Received %1 bytes, header &quot;%2&quot;.</source>
        <translation>Received %1 bytes, header &quot;%2&quot;.</translation>
    </message>
    <message>
        <source>Sent %1 bytes; the controller stored them.</source>
        <translation>Sent %1 bytes; the controller stored them.</translation>
    </message>
    <message>
        <source>no inner blocks (%1 bytes)</source>
        <translation>no inner blocks (%1 bytes)</translation>
    </message>
    <message>
        <source>%1 blocks, all valid</source>
        <translation>%1 blocks, all valid</translation>
    </message>
    <message>
        <source>%1 (no AA)</source>
        <translation>%1 (no AA)</translation>
    </message>
    <message>
        <source>%1 (wrong block id)</source>
        <translation>%1 (wrong block id)</translation>
    </message>
    <message>
        <source>%1 (checksum)</source>
        <translation>%1 (checksum)</translation>
    </message>
    <message>
        <source>%1 of %2 blocks invalid: %3 (the data are kept unchanged)</source>
        <translation>%1 of %2 blocks invalid: %3 (the data are kept unchanged)</translation>
    </message>
    <message>
        <source>&lt;- ACK ignored: a late answer to an earlier message</source>
        <translation>&lt;- ACK ignored: a late answer to an earlier message</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warning: %1</translation>
    </message>
    <message>
        <source>The controller may still be sending its data for about %1 s; the link check waits until then.</source>
        <translation>The controller may still be sending its data for about %1 s; the link check waits until then.</translation>
    </message>
    <message>
        <source>The controller received only part of the data and discards it; the programs it holds are unchanged.</source>
        <translation>The controller received only part of the data and discards it; the programs it holds are unchanged.</translation>
    </message>
    <message>
        <source>All data had been sent: the controller may have stored them. Check its programs.</source>
        <translation>All data had been sent: the controller may have stored them. Check its programs.</translation>
    </message>
    <message>
        <source>The controller answered NAK to %1: is the ANC set up for program transfer and not grinding?</source>
        <translation>The controller answered NAK to %1: is the ANC set up for program transfer and not grinding?</translation>
    </message>
    <message>
        <source>The controller&apos;s reply does not fit the %1 messages: is the wrong system selected (ANC or K51)? Choose the system the control is, then try again. (%2)</source>
        <translation>The controller&apos;s reply does not fit the %1 messages: is the wrong system selected (ANC or K51)? Choose the system the control is, then try again. (%2)</translation>
    </message>
    <message>
        <source>The port %1 stopped taking data: %2 bytes of %3 were not sent. Check that the cable and the USB adapter are plugged in.</source>
        <translation>The port %1 stopped taking data: %2 bytes of %3 were not sent. Check that the cable and the USB adapter are plugged in.</translation>
    </message>
    <message>
        <source>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd), the selected system (ANC) and that the ANC is not grinding.</source>
        <translation>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd), the selected system (ANC) and that the ANC is not grinding.</translation>
    </message>
    <message>
        <source>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd), the selected system (%3) and that the controller is set to transfer (KONFIG6).</source>
        <translation>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd), the selected system (%3) and that the controller is set to transfer (KONFIG6).</translation>
    </message>
    <message>
        <source>A table goes only from the PC to the controller (as APROXTAB sent it); there is nothing to receive. Choose K51 programs to receive programs.</source>
        <translation>A table goes only from the PC to the controller (as APROXTAB sent it); there is nothing to receive. Choose K51 programs to receive programs.</translation>
    </message>
    <message>
        <source>Is it set to program transfer (KONFIG6 = 2)? Set to table transfer (KONFIG6 = 3) it refuses programs.</source>
        <translation>Is it set to program transfer (KONFIG6 = 2)? Set to table transfer (KONFIG6 = 3) it refuses programs.</translation>
    </message>
    <message>
        <source>Is it set to table transfer (KONFIG6 = 3)? Only then does it take a table.</source>
        <translation>Is it set to table transfer (KONFIG6 = 3)? Only then does it take a table.</translation>
    </message>
</context>
<context>
    <name>frezka::grinder::ZLinkSession</name>
    <message>
        <source>No answer to &quot;%1&quot; within %2 s. Is the controller set to Z-position transfer (KONFIG6 = 1) with the selector in PGN?</source>
        <translation>No answer to &quot;%1&quot; within %2 s. Is the controller set to Z-position transfer (KONFIG6 = 1) with the selector in PGN?</translation>
    </message>
    <message>
        <source>The controller rejected a character of &quot;%1&quot; (%2).</source>
        <translation>The controller rejected a character of &quot;%1&quot; (%2).</translation>
    </message>
    <message>
        <source>Unreadable reply &quot;%1&quot;.</source>
        <translation>Unreadable reply &quot;%1&quot;.</translation>
    </message>
</context>
<context>
    <name>frezka::gui</name>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>spindle</source>
        <translation>spindle</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>unused</translation>
    </message>
    <message>
        <source>laser</source>
        <translation>laser</translation>
    </message>
    <message>
        <source>coolant</source>
        <translation>coolant</translation>
    </message>
    <message>
        <source>air blow</source>
        <translation>air blow</translation>
    </message>
    <message>
        <source>machine cover lock</source>
        <translation>machine cover lock</translation>
    </message>
    <message>
        <source>tool release</source>
        <translation>tool release</translation>
    </message>
    <message>
        <source>tool cover open</source>
        <translation>tool cover open</translation>
    </message>
    <message>
        <source>brake</source>
        <translation>brake</translation>
    </message>
    <message>
        <source>interrupt signal</source>
        <translation>interrupt signal</translation>
    </message>
    <message>
        <source>Lower limit %1</source>
        <translation>Lower limit %1</translation>
    </message>
    <message>
        <source>Upper limit %1</source>
        <translation>Upper limit %1</translation>
    </message>
    <message>
        <source>Steps per mm %1</source>
        <translation>Steps per mm %1</translation>
    </message>
    <message>
        <source>Homing speed %1</source>
        <translation>Homing speed %1</translation>
    </message>
    <message>
        <source>Relay function</source>
        <translation>Relay function</translation>
    </message>
    <message>
        <source>OUT1 function</source>
        <translation>OUT1 function</translation>
    </message>
    <message>
        <source>OUT2 function</source>
        <translation>OUT2 function</translation>
    </message>
    <message>
        <source>OUT3 function</source>
        <translation>OUT3 function</translation>
    </message>
    <message>
        <source>PWM mode</source>
        <translation>PWM mode</translation>
    </message>
    <message>
        <source>STEP/DIR polarity</source>
        <translation>STEP/DIR polarity</translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation>Handwheel (MPG)</translation>
    </message>
    <message>
        <source>Input that starts homing</source>
        <translation>Input that starts homing</translation>
    </message>
    <message>
        <source>Interrupt enable IN0-7</source>
        <translation>Interrupt enable IN0-7</translation>
    </message>
    <message>
        <source>Interrupt enable IN14/IN15</source>
        <translation>Interrupt enable IN14/IN15</translation>
    </message>
    <message>
        <source>Input polarity IN0-7</source>
        <translation>Input polarity IN0-7</translation>
    </message>
    <message>
        <source>Input polarity IN14/IN15</source>
        <translation>Input polarity IN14/IN15</translation>
    </message>
    <message>
        <source>A axis coupling</source>
        <translation>A axis coupling</translation>
    </message>
    <message>
        <source>Baud range</source>
        <translation>Baud range</translation>
    </message>
    <message>
        <source>Handwheel acceleration</source>
        <translation>Handwheel acceleration</translation>
    </message>
    <message>
        <source>Handwheel maximum speed</source>
        <translation>Handwheel maximum speed</translation>
    </message>
    <message>
        <source>Handwheel brake delay</source>
        <translation>Handwheel brake delay</translation>
    </message>
    <message>
        <source>Default spindle speed</source>
        <translation>Default spindle speed</translation>
    </message>
    <message>
        <source>Handwheel step multiplier</source>
        <translation>Handwheel step multiplier</translation>
    </message>
    <message>
        <source>Brake release delay</source>
        <translation>Brake release delay</translation>
    </message>
    <message>
        <source>Address 0x%1</source>
        <translation>Address 0x%1</translation>
    </message>
    <message>
        <source>%1 steps/mm</source>
        <translation>%1 steps/mm</translation>
    </message>
    <message>
        <source>homing off</source>
        <translation>homing off</translation>
    </message>
    <message>
        <source>standard PWM</source>
        <translation>standard PWM</translation>
    </message>
    <message>
        <source>breakout-board signal (jumper ANA/PWM)</source>
        <translation>breakout-board signal (jumper ANA/PWM)</translation>
    </message>
    <message>
        <source>unknown (0x%1)</source>
        <translation>unknown (0x%1)</translation>
    </message>
    <message>
        <source>STEP inverted: %1; DIR inverted: %2</source>
        <translation>STEP inverted: %1; DIR inverted: %2</translation>
    </message>
    <message>
        <source>DIR inverted: %1; STEP on %2 edge</source>
        <translation>DIR inverted: %1; STEP on %2 edge</translation>
    </message>
    <message>
        <source>falling</source>
        <translation>falling</translation>
    </message>
    <message>
        <source>rising</source>
        <translation>rising</translation>
    </message>
    <message>
        <source>on</source>
        <translation>on</translation>
    </message>
    <message>
        <source>on, within the limits</source>
        <translation>on, within the limits</translation>
    </message>
    <message>
        <source>on, 4th position drives rotary A</source>
        <translation>on, 4th position drives rotary A</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>on with limits, 4th position drives rotary A</source>
        <translation>on with limits, 4th position drives rotary A</translation>
    </message>
    <message>
        <source>IN%1 held &gt; 1 s starts homing</source>
        <translation>IN%1 held &gt; 1 s starts homing</translation>
    </message>
    <message>
        <source>enabled: %1</source>
        <translation>enabled: %1</translation>
    </message>
    <message>
        <source>active high: %1</source>
        <translation>active high: %1</translation>
    </message>
    <message>
        <source>slaved to X</source>
        <translation>slaved to X</translation>
    </message>
    <message>
        <source>slaved to Y</source>
        <translation>slaved to Y</translation>
    </message>
    <message>
        <source>slaved to Z</source>
        <translation>slaved to Z</translation>
    </message>
    <message>
        <source>independent</source>
        <translation>independent</translation>
    </message>
    <message>
        <source>921 600 / 460 800 / 230 400 / 115 200 Bd</source>
        <translation>921 600 / 460 800 / 230 400 / 115 200 Bd</translation>
    </message>
    <message>
        <source>19 200 / 38 400 / 57 600 / 115 200 Bd</source>
        <translation>19 200 / 38 400 / 57 600 / 115 200 Bd</translation>
    </message>
    <message>
        <source>×%1 (x1 = %2 mm)</source>
        <translation>×%1 (x1 = %2 mm)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::CommissionDialog</name>
    <message>
        <source>Commission this machine</source>
        <translation>Commission this machine</translation>
    </message>
    <message>
        <source>Start runs the steps that move nothing at once; each step that moves or switches something waits for Run or Skip.</source>
        <translation>Start runs the steps that move nothing at once; each step that moves or switches something waits for Run or Skip.</translation>
    </message>
    <message>
        <source>measured mm (empty: as asked)</source>
        <translation>measured mm (empty: as asked)</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Start</translation>
    </message>
    <message>
        <source>&amp;Run step</source>
        <translation>&amp;Run step</translation>
    </message>
    <message>
        <source>S&amp;kip step</source>
        <translation>S&amp;kip step</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Yes</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;No</translation>
    </message>
    <message>
        <source>&amp;OK</source>
        <translation>&amp;OK</translation>
    </message>
    <message>
        <source>Save &amp;report…</source>
        <translation>Save &amp;report…</translation>
    </message>
    <message>
        <source>Save &amp;profile…</source>
        <translation>Save &amp;profile…</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Close</translation>
    </message>
    <message>
        <source>Checking the unit (nothing moves)…</source>
        <translation>Checking the unit (nothing moves)…</translation>
    </message>
    <message>
        <source>the port could not be opened: %1</source>
        <translation>the port could not be opened: %1</translation>
    </message>
    <message>
        <source>Done. Save the report (and the updated profile, under a new name).</source>
        <translation>Done. Save the report (and the updated profile, under a new name).</translation>
    </message>
    <message>
        <source>Save the commissioning report</source>
        <translation>Save the commissioning report</translation>
    </message>
    <message>
        <source>Text (*.txt)</source>
        <translation>Text (*.txt)</translation>
    </message>
    <message>
        <source>Save the updated profile under a new name</source>
        <translation>Save the updated profile under a new name</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Machine profiles (*.json)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ConsoleWidget</name>
    <message>
        <source>Save log</source>
        <translation>Save log</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Save log…</source>
        <translation>Save log…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Send</translation>
    </message>
    <message>
        <source>G-code (e.g. G0 X10) or a raw unit command (e.g. !0PF), Enter sends</source>
        <translation>G-code (e.g. G0 X10) or a raw unit command (e.g. !0PF), Enter sends</translation>
    </message>
    <message>
        <source>Polls</source>
        <translation>Polls</translation>
    </message>
    <message>
        <source>Also show the periodic position and status polls</source>
        <translation>Also show the periodic position and status polls</translation>
    </message>
    <message>
        <source>Serial trace (*.trace)</source>
        <translation>Serial trace (*.trace)</translation>
    </message>
    <message>
        <source>Console log as shown (*.txt *.log)</source>
        <translation>Console log as shown (*.txt *.log)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::DroWidget</name>
    <message>
        <source>Work</source>
        <translation>Work</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Zero</translation>
    </message>
    <message>
        <source>Set the work zero of %1 at the current position</source>
        <translation>Set the work zero of %1 at the current position</translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation>Zero all</translation>
    </message>
    <message>
        <source>Set the work zero of every axis at the current position</source>
        <translation>Set the work zero of every axis at the current position</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>≈ modelled between position reads</source>
        <translation>≈ modelled between position reads</translation>
    </message>
    <message>
        <source>While the serial line is busy with a dense job the unit&apos;s counters are read only now and then; in between, the figures follow the driver&apos;s model of the unit along the plan, never ahead of what the unit was sent, and each read corrects them.</source>
        <translation>While the serial line is busy with a dense job the unit&apos;s counters are read only now and then; in between, the figures follow the driver&apos;s model of the unit along the plan, never ahead of what the unit was sent, and each read corrects them.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::GrinderWindow</name>
    <message>
        <source>Connect</source>
        <translation>Connect</translation>
    </message>
    <message>
        <source>Grinder transfer</source>
        <translation>Grinder transfer</translation>
    </message>
    <message>
        <source>K51 programs (K51LOAD/K51SAVE, KCOMM)</source>
        <translation>K51 programs (K51LOAD/K51SAVE, KCOMM)</translation>
    </message>
    <message>
        <source>ANC programs (ANCLOAD/ANCSAVE)</source>
        <translation>ANC programs (ANCLOAD/ANCSAVE)</translation>
    </message>
    <message>
        <source>ANC hard-chrome data (HEDIT)</source>
        <translation>ANC hard-chrome data (HEDIT)</translation>
    </message>
    <message>
        <source>Program transfer</source>
        <translation>Program transfer</translation>
    </message>
    <message>
        <source>Z position, FORM=1 (ASCII)</source>
        <translation>Z position, FORM=1 (ASCII)</translation>
    </message>
    <message>
        <source>Z position, FORM=2 (binary)</source>
        <translation>Z position, FORM=2 (binary)</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Connection</translation>
    </message>
    <message>
        <source>Control:</source>
        <translation>Control:</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Mode:</translation>
    </message>
    <message>
        <source>Z position</source>
        <translation>Z position</translation>
    </message>
    <message>
        <source>Serial monitor</source>
        <translation>Serial monitor</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Not connected.</translation>
    </message>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Cannot connect: %1</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Disconnect</translation>
    </message>
    <message>
        <source>Open: %1 at %2 Bd.</source>
        <translation>Open: %1 at %2 Bd.</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Connected</translation>
    </message>
    <message>
        <source>No connection</source>
        <translation>No connection</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>%1 — %2: %3</source>
        <translation>%1 — %2: %3</translation>
    </message>
    <message>
        <source>Disconnected during the transfer.</source>
        <translation>Disconnected during the transfer.</translation>
    </message>
    <message>
        <source>Waiting for the controller to finish its message (about %1 s)…</source>
        <translation>Waiting for the controller to finish its message (about %1 s)…</translation>
    </message>
    <message>
        <source>The data received from the controller have not been saved. Close and discard them?</source>
        <translation>The data received from the controller have not been saved. Close and discard them?</translation>
    </message>
    <message>
        <source>K51 table (APROXTAB), PC → controller only</source>
        <translation>K51 table (APROXTAB), PC → controller only</translation>
    </message>
    <message>
        <source>HEDIT data</source>
        <translation>HEDIT data</translation>
    </message>
    <message>
        <source>HEDIT editor</source>
        <translation>HEDIT editor</translation>
    </message>
</context>
<context>
    <name>frezka::gui::HardChromeEditor</name>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Decimal</source>
        <translation>Decimal</translation>
    </message>
    <message>
        <source>Hard-chrome data for parametric plunge and traverse grinding: 0x2E bytes from address 0x1100. The manual does not describe the single values, so each byte is shown as it is; what you do not edit is kept unchanged.</source>
        <translation>Hard-chrome data for parametric plunge and traverse grinding: 0x2E bytes from address 0x1100. The manual does not describe the single values, so each byte is shown as it is; what you do not edit is kept unchanged.</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Open…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Save…</translation>
    </message>
    <message>
        <source>Take received data</source>
        <translation>Take received data</translation>
    </message>
    <message>
        <source>Send to controller</source>
        <translation>Send to controller</translation>
    </message>
    <message>
        <source>Header:</source>
        <translation>Header:</translation>
    </message>
    <message>
        <source>Frezka grinder file (*.frg);;Bare data (*.bin)</source>
        <translation>Frezka grinder file (*.frg);;Bare data (*.bin)</translation>
    </message>
    <message>
        <source>Save HEDIT data</source>
        <translation>Save HEDIT data</translation>
    </message>
    <message>
        <source>Open HEDIT data</source>
        <translation>Open HEDIT data</translation>
    </message>
    <message>
        <source>Grinder files (*.frg *.bin);;All files (*)</source>
        <translation>Grinder files (*.frg *.bin);;All files (*)</translation>
    </message>
    <message>
        <source>0x%1: &quot;%2&quot; is not a byte in hex (00 to FF); the value is kept.</source>
        <translation>0x%1: &quot;%2&quot; is not a byte in hex (00 to FF); the value is kept.</translation>
    </message>
    <message>
        <source>0x%1 set to %2.</source>
        <translation>0x%1 set to %2.</translation>
    </message>
    <message>
        <source>HEDIT data have 46 bytes (0x2E); these have %1. Nothing changed.</source>
        <translation>HEDIT data have 46 bytes (0x2E); these have %1. Nothing changed.</translation>
    </message>
    <message>
        <source>46 bytes loaded.</source>
        <translation>46 bytes loaded.</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Cannot read %1: %2</translation>
    </message>
    <message>
        <source>%1 holds %2 data, not HEDIT data.</source>
        <translation>%1 holds %2 data, not HEDIT data.</translation>
    </message>
    <message>
        <source>%1 is damaged: %2</source>
        <translation>%1 is damaged: %2</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Saved to %1.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::HeightMapDialog</name>
    <message>
        <source>Save height map</source>
        <translation>Save height map</translation>
    </message>
    <message>
        <source>Height maps (*.csv)</source>
        <translation>Height maps (*.csv)</translation>
    </message>
    <message>
        <source>Load height map</source>
        <translation>Load height map</translation>
    </message>
    <message>
        <source>Height map</source>
        <translation>Height map</translation>
    </message>
    <message>
        <source>Area X from / to (mm)</source>
        <translation>Area X from / to (mm)</translation>
    </message>
    <message>
        <source>Area Y from / to (mm)</source>
        <translation>Area Y from / to (mm)</translation>
    </message>
    <message>
        <source>Spacing (mm)</source>
        <translation>Spacing (mm)</translation>
    </message>
    <message>
        <source>Clearance above Z 0 (mm)</source>
        <translation>Clearance above Z 0 (mm)</translation>
    </message>
    <message>
        <source>Probe depth below Z 0 (mm)</source>
        <translation>Probe depth below Z 0 (mm)</translation>
    </message>
    <message>
        <source>Probe feed (mm/min)</source>
        <translation>Probe feed (mm/min)</translation>
    </message>
    <message>
        <source>Area of the loaded program</source>
        <translation>Area of the loaded program</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Probe</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Save…</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Load…</translation>
    </message>
    <message>
        <source>Apply to the program</source>
        <translation>Apply to the program</translation>
    </message>
    <message>
        <source>Remove from the program</source>
        <translation>Remove from the program</translation>
    </message>
    <message>
        <source>On Apply, set the work&apos;s Z zero on the surface at the first point</source>
        <translation>On Apply, set the work&apos;s Z zero on the surface at the first point</translation>
    </message>
    <message>
        <source>Probes the grid with G38.2 at every point (the probe input IN15), back up to the clearance between the points.</source>
        <translation>Probes the grid with G38.2 at every point (the probe input IN15), back up to the clearance between the points.</translation>
    </message>
    <message>
        <source>Probing %1 points…</source>
        <translation>Probing %1 points…</translation>
    </message>
    <message>
        <source>Probed %1 of %2 points.</source>
        <translation>Probed %1 of %2 points.</translation>
    </message>
    <message>
        <source>All %1 points probed.</source>
        <translation>All %1 points probed.</translation>
    </message>
    <message>
        <source>Probing stopped after %1 of %2 points.</source>
        <translation>Probing stopped after %1 of %2 points.</translation>
    </message>
    <message>
        <source>There is no height map to save: probe or load one.</source>
        <translation>There is no height map to save: probe or load one.</translation>
    </message>
    <message>
        <source>Height map saved to %1.</source>
        <translation>Height map saved to %1.</translation>
    </message>
    <message>
        <source>Height map loaded from %1.</source>
        <translation>Height map loaded from %1.</translation>
    </message>
    <message>
        <source>%1 x %2 points, heights %3 to %4 mm from the first point (machine Z %5)</source>
        <translation>%1 x %2 points, heights %3 to %4 mm from the first point (machine Z %5)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::HoldBanner</name>
    <message>
        <source>at line %1</source>
        <translation>at line %1</translation>
    </message>
    <message>
        <source>Paused %1</source>
        <translation>Paused %1</translation>
    </message>
    <message>
        <source>Program stop %1</source>
        <translation>Program stop %1</translation>
    </message>
    <message>
        <source>%1
Do what the program asks, then press Continue.</source>
        <translation>%1
Do what the program asks, then press Continue.</translation>
    </message>
    <message>
        <source>Stopped by an input %1</source>
        <translation>Stopped by an input %1</translation>
    </message>
    <message>
        <source>%1
Check the machine; when it is safe, Continue or Abort.</source>
        <translation>%1
Check the machine; when it is safe, Continue or Abort.</translation>
    </message>
    <message>
        <source>Probe failed %1</source>
        <translation>Probe failed %1</translation>
    </message>
    <message>
        <source>%1
The probe did not touch as expected. Abort the job or Continue.</source>
        <translation>%1
The probe did not touch as expected. Abort the job or Continue.</translation>
    </message>
    <message>
        <source>Tool lifted %1</source>
        <translation>Tool lifted %1</translation>
    </message>
    <message>
        <source>Stop the spindle</source>
        <translation>Stop the spindle</translation>
    </message>
    <message>
        <source>New feed (0 = unchanged):</source>
        <translation>New feed (0 = unchanged):</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continue</translation>
    </message>
    <message>
        <source>Lift tool</source>
        <translation>Lift tool</translation>
    </message>
    <message>
        <source>Lower and continue</source>
        <translation>Lower and continue</translation>
    </message>
    <message>
        <source>Lower, stay paused</source>
        <translation>Lower, stay paused</translation>
    </message>
    <message>
        <source>Abort job</source>
        <translation>Abort job</translation>
    </message>
    <message>
        <source>Off the planned path %1</source>
        <translation>Off the planned path %1</translation>
    </message>
    <message>
        <source>The machine&apos;s position left the path that was sent: a command was damaged on the serial line in a way its checksum cannot show, and the unit ran it. The machine has stopped. Check the workpiece. Continue lifts the tool, returns to the last point verified on the path and runs the job on from there; or Abort the job.</source>
        <translation>The machine&apos;s position left the path that was sent: a command was damaged on the serial line in a way its checksum cannot show, and the unit ran it. The machine has stopped. Check the workpiece. Continue lifts the tool, returns to the last point verified on the path and runs the job on from there; or Abort the job.</translation>
    </message>
    <message>
        <source>The machine has stopped along its ramp and keeps the rest of the job. Continue, or lift the tool to change or clean it (the spindle and coolant go off for a lifted tool).</source>
        <translation>The machine has stopped along its ramp and keeps the rest of the job. Continue, or lift the tool to change or clean it (the spindle and coolant go off for a lifted tool).</translation>
    </message>
    <message>
        <source>The spindle and coolant are off for the hold. Continue switches them on again and waits %1 s for the spindle before the tool moves.</source>
        <translation>The spindle and coolant are off for the hold. Continue switches them on again and waits %1 s for the spindle before the tool moves.</translation>
    </message>
    <message>
        <source>The spindle is running.</source>
        <translation>The spindle is running.</translation>
    </message>
    <message>
        <source>The spindle is off.</source>
        <translation>The spindle is off.</translation>
    </message>
    <message>
        <source>While the job is held: the spindle and coolant off (ticked) or on again (unticked). Ticked, a pause stops them as soon as the machine stands.</source>
        <translation>While the job is held: the spindle and coolant off (ticked) or on again (unticked). Ticked, a pause stops them as soon as the machine stands.</translation>
    </message>
    <message>
        <source>The feed from here on, as the feed override for the rest of the job</source>
        <translation>The feed from here on, as the feed override for the rest of the job</translation>
    </message>
    <message>
        <source>The spindle and coolant are off. Change, measure or clean the tool; you may jog the machine away by steps. Lowering switches the spindle and coolant on again as they were, waits %1 s for the spindle to reach its speed, returns exactly to where the tool was lifted, lowers it into the work and continues. Abort ends the job here with the tool up.</source>
        <translation>The spindle and coolant are off. Change, measure or clean the tool; you may jog the machine away by steps. Lowering switches the spindle and coolant on again as they were, waits %1 s for the spindle to reach its speed, returns exactly to where the tool was lifted, lowers it into the work and continues. Abort ends the job here with the tool up.</translation>
    </message>
    <message>
        <source>A new feed entered below is the feed override for the rest of the job.</source>
        <translation>A new feed entered below is the feed override for the rest of the job.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::JogPanel</name>
    <message>
        <source>Home %1</source>
        <translation>Home %1</translation>
    </message>
    <message>
        <source>Find the home switch of %1</source>
        <translation>Find the home switch of %1</translation>
    </message>
    <message>
        <source>Home all</source>
        <translation>Home all</translation>
    </message>
    <message>
        <source>Home every axis in the order of the machine profile</source>
        <translation>Home every axis in the order of the machine profile</translation>
    </message>
    <message>
        <source>Step (mm):</source>
        <translation>Step (mm):</translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation>Continuous</translation>
    </message>
    <message>
        <source>Move while the button or key is held</source>
        <translation>Move while the button or key is held</translation>
    </message>
    <message>
        <source>Jog feed:</source>
        <translation>Jog feed:</translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation>Handwheel (MPG)</translation>
    </message>
    <message>
        <source>Keyboard: arrows jog X/Y, Page Up/Page Down jog Z</source>
        <translation>Keyboard: arrows jog X/Y, Page Up/Page Down jog Z</translation>
    </message>
    <message>
        <source>%1 not homed: soft limits off, slow jog</source>
        <translation>%1 not homed: soft limits off, slow jog</translation>
    </message>
    <message>
        <source>Before homing the counters do not say where the axes are: jogging ignores the soft limits and runs at most at the homing speed. Home the machine to have the limits and the full jog speed; a program asks for homing before it runs.</source>
        <translation>Before homing the counters do not say where the axes are: jogging ignores the soft limits and runs at most at the homing speed. Home the machine to have the limits and the full jog speed; a program asks for homing before it runs.</translation>
    </message>
    <message>
        <source>Step (in):</source>
        <translation>Step (in):</translation>
    </message>
</context>
<context>
    <name>frezka::gui::LoadProgress</name>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Stop loading this program (the program loaded before stays)</source>
        <translation>Stop loading this program (the program loaded before stays)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::MainWindow</name>
    <message>
        <source>About Frezka</source>
        <translation>About Frezka</translation>
    </message>
    <message>
        <source>&lt;b&gt;Frezka %1&lt;/b&gt;&lt;br&gt;Runs CNC mills through GVE interpolators.</source>
        <translation>&lt;b&gt;Frezka %1&lt;/b&gt;&lt;br&gt;Runs CNC mills through GVE interpolators.</translation>
    </message>
    <message>
        <source>Frezka</source>
        <translation>Frezka</translation>
    </message>
    <message>
        <source>Frezka — %1</source>
        <translation>Frezka — %1</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Program run</source>
        <translation>Program run</translation>
    </message>
    <message>
        <source>Jog and homing</source>
        <translation>Jog and homing</translation>
    </message>
    <message>
        <source>Spindle and outputs</source>
        <translation>Spindle and outputs</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Console</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Open program…</source>
        <translation>&amp;Open program…</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Open &amp;recent</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Machine</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Connect</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>&amp;Settings…</source>
        <translation>&amp;Settings…</translation>
    </message>
    <message>
        <source>&amp;Unit configuration (EEPROM)…</source>
        <translation>&amp;Unit configuration (EEPROM)…</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Reset layout</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Tools</translation>
    </message>
    <message>
        <source>&amp;Grinder transfer (ANC/K51)…</source>
        <translation>&amp;Grinder transfer (ANC/K51)…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>&amp;About Frezka</source>
        <translation>&amp;About Frezka</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>No program</translation>
    </message>
    <message>
        <source>Open program</source>
        <translation>Open program</translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.gcode *.tap *.txt);;All files (*)</source>
        <translation>G-code (*.nc *.ngc *.gcode *.tap *.txt);;All files (*)</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>Loading %1…</translation>
    </message>
    <message numerus="yes">
        <source>%1 — %n line(s)</source>
        <translation>
            <numerusform>%1 — %n line</numerusform>
            <numerusform>%1 — %n lines</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The program has %n error(s); nothing will run until they are fixed.
%1</source>
        <translation>
            <numerusform>The program has %n error; nothing will run until they are fixed.
%1</numerusform>
            <numerusform>The program has %n errors; nothing will run until they are fixed.
%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Laser</source>
        <translation>Laser</translation>
    </message>
    <message>
        <source>Cover lock</source>
        <translation>Cover lock</translation>
    </message>
    <message>
        <source>Tool release</source>
        <translation>Tool release</translation>
    </message>
    <message>
        <source>Tool cover</source>
        <translation>Tool cover</translation>
    </message>
    <message>
        <source>Program finished in %1.</source>
        <translation>Program finished in %1.</translation>
    </message>
    <message>
        <source>Program finished.</source>
        <translation>Program finished.</translation>
    </message>
    <message>
        <source>No output of this machine is set up for that function; assign one in Settings › Machine profile › Outputs.</source>
        <translation>No output of this machine is set up for that function; assign one in Settings › Machine profile › Outputs.</translation>
    </message>
    <message numerus="yes">
        <source>Check passed: %n move(s), estimated time %1, within the soft limits.</source>
        <translation>
            <numerusform>Check passed: %n move, estimated time %1, within the soft limits.</numerusform>
            <numerusform>Check passed: %n moves, estimated time %1, within the soft limits.</numerusform>
        </translation>
    </message>
    <message>
        <source>Check passed.</source>
        <translation>Check passed.</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Line %1</translation>
    </message>
    <message>
        <source>The link to the unit was lost. The job position is kept: reconnect, then Resume.</source>
        <translation>The link to the unit was lost. The job position is kept: reconnect, then Resume.</translation>
    </message>
    <message>
        <source>Unit EEPROM differs from the profile: %1 is %2 in the unit, %3 in the profile</source>
        <translation>Unit EEPROM differs from the profile: %1 is %2 in the unit, %3 in the profile</translation>
    </message>
    <message>
        <source>The unit reported a problem: %1</source>
        <translation>The unit reported a problem: %1</translation>
    </message>
    <message>
        <source>Command: %1</source>
        <translation>Command: %1</translation>
    </message>
    <message>
        <source>Reply: %1</source>
        <translation>Reply: %1</translation>
    </message>
    <message>
        <source>Program line: %1</source>
        <translation>Program line: %1</translation>
    </message>
    <message>
        <source>Open a program first.</source>
        <translation>Open a program first.</translation>
    </message>
    <message>
        <source>Jog refused: %1 would go to %2 mm, outside the soft limits %3 … %4 mm.</source>
        <translation>Jog refused: %1 would go to %2 mm, outside the soft limits %3 … %4 mm.</translation>
    </message>
    <message>
        <source>Set the work zero while the machine is ready and still.</source>
        <translation>Set the work zero while the machine is ready and still.</translation>
    </message>
    <message>
        <source>The new port is used when you connect again after the job.</source>
        <translation>The new port is used when you connect again after the job.</translation>
    </message>
    <message>
        <source>Manual line done.</source>
        <translation>Manual line done.</translation>
    </message>
    <message>
        <source>Using the port used last, %1 (the machine profile says %2).</source>
        <translation>Using the port used last, %1 (the machine profile says %2).</translation>
    </message>
    <message>
        <source>built-in emulator</source>
        <translation>built-in emulator</translation>
    </message>
    <message>
        <source>%1, %2 Bd</source>
        <translation>%1, %2 Bd</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Program comment: %1</source>
        <translation>Program comment: %1</translation>
    </message>
    <message>
        <source>State: %1 → %2</source>
        <translation>State: %1 → %2</translation>
    </message>
    <message>
        <source>The machine is not homed: its soft limits refer to nothing yet. Home all axes now and then run the program?</source>
        <translation>The machine is not homed: its soft limits refer to nothing yet. Home all axes now and then run the program?</translation>
    </message>
    <message>
        <source>Home and run</source>
        <translation>Home and run</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Coolant</translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation>Air blow</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Keyboard shortcuts</translation>
    </message>
    <message>
        <source>Run from &amp;line…</source>
        <translation>Run from &amp;line…</translation>
    </message>
    <message>
        <source>Run the &amp;whole program</source>
        <translation>Run the &amp;whole program</translation>
    </message>
    <message>
        <source>Open a program first, then choose the line to run from.</source>
        <translation>Open a program first, then choose the line to run from.</translation>
    </message>
    <message>
        <source>Line %1 is not in the program (lines 1 to %2): choose one of its lines.</source>
        <translation>Line %1 is not in the program (lines 1 to %2): choose one of its lines.</translation>
    </message>
    <message>
        <source>The machine is busy (%1): run from a line once it is ready.</source>
        <translation>The machine is busy (%1): run from a line once it is ready.</translation>
    </message>
    <message>
        <source>Run from line</source>
        <translation>Run from line</translation>
    </message>
    <message>
        <source>Start the program at line (1 to %1):</source>
        <translation>Start the program at line (1 to %1):</translation>
    </message>
    <message>
        <source>Run from line %1 is ready: the view shows the approach. Run starts it; Machine › Run the whole program goes back.</source>
        <translation>Run from line %1 is ready: the view shows the approach. Run starts it; Machine › Run the whole program goes back.</translation>
    </message>
    <message>
        <source>Re&amp;load program</source>
        <translation>Re&amp;load program</translation>
    </message>
    <message>
        <source>The program cannot be reloaded while its job runs: let it finish or abort it, then reload.</source>
        <translation>The program cannot be reloaded while its job runs: let it finish or abort it, then reload.</translation>
    </message>
    <message>
        <source>%1 has changed on disk. Reload it? Until then the listing, the preview and the job are of the version read before.</source>
        <translation>%1 has changed on disk. Reload it? Until then the listing, the preview and the job are of the version read before.</translation>
    </message>
    <message>
        <source>Reload</source>
        <translation>Reload</translation>
    </message>
    <message>
        <source>Keep the version read before</source>
        <translation>Keep the version read before</translation>
    </message>
    <message>
        <source>Work offset %1 set to X %2, Y %3, Z %4 mm.</source>
        <translation>Work offset %1 set to X %2, Y %3, Z %4 mm.</translation>
    </message>
    <message>
        <source>Program &amp;info…</source>
        <translation>Program &amp;info…</translation>
    </message>
    <message>
        <source>G20: the program is in inches</source>
        <translation>G20: the program is in inches</translation>
    </message>
    <message>
        <source>G21: the program is in mm</source>
        <translation>G21: the program is in mm</translation>
    </message>
    <message>
        <source>&amp;Tool table…</source>
        <translation>&amp;Tool table…</translation>
    </message>
    <message>
        <source>The machine profile names no tool table file: set it in Machine › Settings (Tools), e.g. tool.tbl.</source>
        <translation>The machine profile names no tool table file: set it in Machine › Settings (Tools), e.g. tool.tbl.</translation>
    </message>
    <message>
        <source>Tool table saved; programs are checked with it.</source>
        <translation>Tool table saved; programs are checked with it.</translation>
    </message>
    <message>
        <source>no comment in the tool table</source>
        <translation>no comment in the tool table</translation>
    </message>
    <message>
        <source>Tool %1: %2 (length %3 mm, diameter %4 mm)</source>
        <translation>Tool %1: %2 (length %3 mm, diameter %4 mm)</translation>
    </message>
    <message>
        <source>The program changed the tool table (G10 L1, L10 or L11): %1 saved.</source>
        <translation>The program changed the tool table (G10 L1, L10 or L11): %1 saved.</translation>
    </message>
    <message>
        <source>Loading %1 was cancelled; no program is loaded.</source>
        <translation>Loading %1 was cancelled; no program is loaded.</translation>
    </message>
    <message>
        <source>Loading %1 was cancelled; %2 stays loaded.</source>
        <translation>Loading %1 was cancelled; %2 stays loaded.</translation>
    </message>
    <message>
        <source>Save serial &amp;trace…</source>
        <translation>Save serial &amp;trace…</translation>
    </message>
    <message>
        <source>Save serial trace</source>
        <translation>Save serial trace</translation>
    </message>
    <message>
        <source>Serial traces (*.trace *.txt)</source>
        <translation>Serial traces (*.trace *.txt)</translation>
    </message>
    <message>
        <source>Serial trace saved to %1</source>
        <translation>Serial trace saved to %1</translation>
    </message>
    <message>
        <source>The serial trace is off. Set how much of it to keep in Settings › Application, then repeat what went wrong and save it again.</source>
        <translation>The serial trace is off. Set how much of it to keep in Settings › Application, then repeat what went wrong and save it again.</translation>
    </message>
    <message>
        <source>C&amp;ommission this machine…</source>
        <translation>C&amp;ommission this machine…</translation>
    </message>
    <message>
        <source>&amp;Height map…</source>
        <translation>&amp;Height map…</translation>
    </message>
    <message>
        <source>Height map applied: the program is bent to it (heights %1 to %2 mm).</source>
        <translation>Height map applied: the program is bent to it (heights %1 to %2 mm).</translation>
    </message>
    <message>
        <source>Height map removed: the program runs as written.</source>
        <translation>Height map removed: the program runs as written.</translation>
    </message>
    <message>
        <source>Tool %1 measured on the tool sensor: %2 mm long.</source>
        <translation>Tool %1 measured on the tool sensor: %2 mm long.</translation>
    </message>
    <message>
        <source>Unit %1: %2</source>
        <translation>Unit %1: %2</translation>
    </message>
    <message>
        <source>Another unit becomes this window&apos;s machine only while every unit on the line is idle; wait, or stop the units, then choose again.</source>
        <translation>Another unit becomes this window&apos;s machine only while every unit on the line is idle; wait, or stop the units, then choose again.</translation>
    </message>
    <message>
        <source>This window&apos;s machine is now %1 (address %2).</source>
        <translation>This window&apos;s machine is now %1 (address %2).</translation>
    </message>
    <message>
        <source>The units on the machine&apos;s line cannot be set up; fix line.units in the machine profile:
%1</source>
        <translation>The units on the machine&apos;s line cannot be set up; fix line.units in the machine profile:
%1</translation>
    </message>
    <message>
        <source>&amp;Probe work zero…</source>
        <translation>&amp;Probe work zero…</translation>
    </message>
    <message>
        <source>&amp;Height map</source>
        <translation>&amp;Height map</translation>
    </message>
    <message>
        <source>Show the probed or loaded height map in the toolpath view</source>
        <translation>Show the probed or loaded height map in the toolpath view</translation>
    </message>
    <message>
        <source>Height map &amp;Z scale</source>
        <translation>Height map &amp;Z scale</translation>
    </message>
    <message>
        <source>&amp;True scale</source>
        <translation>&amp;True scale</translation>
    </message>
    <message>
        <source>Heights &amp;exaggerated %1×</source>
        <translation>Heights &amp;exaggerated %1×</translation>
    </message>
    <message>
        <source>After line %1 the path depends on the probe&apos;s result: it is checked and shown as if the probe ended at its programmed end (provisional), and each part is planned once the probe before it has run.</source>
        <translation>After line %1 the path depends on the probe&apos;s result: it is checked and shown as if the probe ended at its programmed end (provisional), and each part is planned once the probe before it has run.</translation>
    </message>
    <message>
        <source>Line %1: the probe&apos;s result was followed; the rest of the program is shown and runs as interpreted with it.</source>
        <translation>Line %1: the probe&apos;s result was followed; the rest of the program is shown and runs as interpreted with it.</translation>
    </message>
    <message>
        <source>%1 X%2 Y%3 Z%4 A%5</source>
        <translation>%1 X%2 Y%3 Z%4 A%5</translation>
    </message>
    <message>
        <source>The program set work offsets (G10 L2/L20), kept: %1 (machine mm).</source>
        <translation>The program set work offsets (G10 L2/L20), kept: %1 (machine mm).</translation>
    </message>
    <message>
        <source>The port %1 is not opened: on the virtual clock (--clock virtual) only the built-in emulator runs. Choose the emulator as the port, or start Frezka without --clock virtual.</source>
        <translation>The port %1 is not opened: on the virtual clock (--clock virtual) only the built-in emulator runs. Choose the emulator as the port, or start Frezka without --clock virtual.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::OutputsPanel</name>
    <message>
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <source>Switch the spindle on or off at the speed on the right</source>
        <translation>Switch the spindle on or off at the speed on the right</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Speed:</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Coolant</translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation>Air blow</translation>
    </message>
    <message>
        <source>Feed:</source>
        <translation>Feed:</translation>
    </message>
    <message>
        <source>Feed override in percent of the programmed feed (XM)</source>
        <translation>Feed override in percent of the programmed feed (XM)</translation>
    </message>
    <message>
        <source>Raise every queued speed by 6.25 % (XU)</source>
        <translation>Raise every queued speed by 6.25 % (XU)</translation>
    </message>
    <message>
        <source>Lower every queued speed by 6.25 % (XD)</source>
        <translation>Lower every queued speed by 6.25 % (XD)</translation>
    </message>
    <message>
        <source>%1 % (runs %2 %)</source>
        <translation>%1 % (runs %2 %)</translation>
    </message>
    <message>
        <source>The serial link cannot carry the program&apos;s motion at %1 %: the unit runs %2 % until the motion ahead is slow enough, so that it never runs dry.</source>
        <translation>The serial link cannot carry the program&apos;s motion at %1 %: the unit runs %2 % until the motion ahead is slow enough, so that it never runs dry.</translation>
    </message>
    <message>
        <source>Spindle:</source>
        <translation>Spindle:</translation>
    </message>
    <message>
        <source>Spindle override in percent of the programmed speed: the turning spindle at once, and every spindle speed of the rest of the job</source>
        <translation>Spindle override in percent of the programmed speed: the turning spindle at once, and every spindle speed of the rest of the job</translation>
    </message>
    <message>
        <source>Spindle speed as programmed</source>
        <translation>Spindle speed as programmed</translation>
    </message>
</context>
<context>
    <name>frezka::gui::PlacementBar</name>
    <message>
        <source>%1 goes to %2 mm at line %3, %4 mm beyond the travel&apos;s %5 mm.</source>
        <translation>%1 goes to %2 mm at line %3, %4 mm beyond the travel&apos;s %5 mm.</translation>
    </message>
    <message>
        <source>The program leaves the machine&apos;s travel at the current work zero. %1 Its coordinates are probably relative to the stock: bring the tool to the chosen point of the stock, its tip on the stock&apos;s top (the program&apos;s Z0), and set the work zero there.</source>
        <translation>The program leaves the machine&apos;s travel at the current work zero. %1 Its coordinates are probably relative to the stock: bring the tool to the chosen point of the stock, its tip on the stock&apos;s top (the program&apos;s Z0), and set the work zero there.</translation>
    </message>
    <message>
        <source>With the work zero set here the program would sit at %1 mm: inside the travel.</source>
        <translation>With the work zero set here the program would sit at %1 mm: inside the travel.</translation>
    </message>
    <message>
        <source>With the work zero set here the program would sit at %1 mm: still outside the travel. Move to the stock first or choose another point.</source>
        <translation>With the work zero set here the program would sit at %1 mm: still outside the travel. Move to the stock first or choose another point.</translation>
    </message>
    <message>
        <source>Here is the stock&apos;s:</source>
        <translation>Here is the stock&apos;s:</translation>
    </message>
    <message>
        <source>program&apos;s X0 Y0</source>
        <translation>program&apos;s X0 Y0</translation>
    </message>
    <message>
        <source>front left corner</source>
        <translation>front left corner</translation>
    </message>
    <message>
        <source>front right corner</source>
        <translation>front right corner</translation>
    </message>
    <message>
        <source>back left corner</source>
        <translation>back left corner</translation>
    </message>
    <message>
        <source>back right corner</source>
        <translation>back right corner</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>centre</translation>
    </message>
    <message>
        <source>Set the work zero here</source>
        <translation>Set the work zero here</translation>
    </message>
    <message>
        <source>Sets the active work offset so that the chosen point of the program is at the current X/Y and the program&apos;s Z0 at the current Z</source>
        <translation>Sets the active work offset so that the chosen point of the program is at the current X/Y and the program&apos;s Z0 at the current Z</translation>
    </message>
    <message>
        <source>Shift into the travel</source>
        <translation>Shift into the travel</translation>
    </message>
    <message>
        <source>Shifts the active work offset by the least that puts the whole program inside the soft limits (as frezka-cli check suggests)</source>
        <translation>Shifts the active work offset by the least that puts the whole program inside the soft limits (as frezka-cli check suggests)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::Plan</name>
    <message>
        <source>the move leaves the machine&apos;s travel (soft limits); check the work zero and the program</source>
        <translation>the move leaves the machine&apos;s travel (soft limits); check the work zero and the program</translation>
    </message>
    <message>
        <source>the program moves an axis this machine does not have</source>
        <translation>the program moves an axis this machine does not have</translation>
    </message>
    <message>
        <source>the position is beyond the unit&apos;s step counters</source>
        <translation>the position is beyond the unit&apos;s step counters</translation>
    </message>
    <message>
        <source>a feed move has no feed rate (F)</source>
        <translation>a feed move has no feed rate (F)</translation>
    </message>
    <message>
        <source>the spindle speed (S) is above the machine&apos;s maximum</source>
        <translation>the spindle speed (S) is above the machine&apos;s maximum</translation>
    </message>
    <message>
        <source>the unit cannot do this</source>
        <translation>the unit cannot do this</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>%1:%2: %3 (%4)</source>
        <translation>%1:%2: %3 (%4)</translation>
    </message>
    <message>
        <source>the feed is above what the machine&apos;s axes can do; it runs slower than programmed</source>
        <translation>the feed is above what the machine&apos;s axes can do; it runs slower than programmed</translation>
    </message>
</context>
<context>
    <name>frezka::gui::PortSettingsRow</name>
    <message>
        <source>Serial port; a path such as /dev/pts/3 may be typed.</source>
        <translation>Serial port; a path such as /dev/pts/3 may be typed.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>even</source>
        <translation>even</translation>
    </message>
    <message>
        <source>odd</source>
        <translation>odd</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>Baud:</translation>
    </message>
    <message>
        <source>Data bits:</source>
        <translation>Data bits:</translation>
    </message>
    <message>
        <source>Parity:</source>
        <translation>Parity:</translation>
    </message>
    <message>
        <source>Stop bits:</source>
        <translation>Stop bits:</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProbeSetupPicture</name>
    <message>
        <source>work</source>
        <translation>work</translation>
    </message>
    <message>
        <source>plate</source>
        <translation>plate</translation>
    </message>
    <message>
        <source>tool</source>
        <translation>tool</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProbeZeroDialog</name>
    <message>
        <source>1. Lay the plate on the work and connect the probe&apos;s clip to the tool.
2. Jog the tool over the plate, a few mm above it.
3. Press Probe: the tool goes down until it touches (fast, then slow) and backs off; the work&apos;s top becomes Z 0.</source>
        <translation>1. Lay the plate on the work and connect the probe&apos;s clip to the tool.
2. Jog the tool over the plate, a few mm above it.
3. Press Probe: the tool goes down until it touches (fast, then slow) and backs off; the work&apos;s top becomes Z 0.</translation>
    </message>
    <message>
        <source>1. Jog the tool beside the edge, below the work&apos;s top, within the travel of it.
2. Choose the direction toward the edge and the tool&apos;s diameter.
3. Press Probe: the tool moves until it touches and comes back; the edge becomes 0 on that axis.</source>
        <translation>1. Jog the tool beside the edge, below the work&apos;s top, within the travel of it.
2. Choose the direction toward the edge and the tool&apos;s diameter.
3. Press Probe: the tool moves until it touches and comes back; the edge becomes 0 on that axis.</translation>
    </message>
    <message>
        <source>1. Jog the tool off the corner diagonally, below the work&apos;s top.
2. Set the reach: how far to move beside each face (more than the distance to the corner plus the tool&apos;s radius).
3. Press Probe: X first, then Y; the corner becomes X 0 Y 0.</source>
        <translation>1. Jog the tool off the corner diagonally, below the work&apos;s top.
2. Set the reach: how far to move beside each face (more than the distance to the corner plus the tool&apos;s radius).
3. Press Probe: X first, then Y; the corner becomes X 0 Y 0.</translation>
    </message>
    <message>
        <source>1. Jog the tool into the pocket near its corner, below the top.
2. Choose the directions toward the two walls.
3. Press Probe: X first, then Y, both from where the tool stands; the corner becomes X 0 Y 0.</source>
        <translation>1. Jog the tool into the pocket near its corner, below the top.
2. Choose the directions toward the two walls.
3. Press Probe: X first, then Y, both from where the tool stands; the corner becomes X 0 Y 0.</translation>
    </message>
    <message>
        <source>Probing…</source>
        <translation>Probing…</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;top</translation>
    </message>
    <message>
        <source>&amp;Probe</source>
        <translation>&amp;Probe</translation>
    </message>
    <message>
        <source>Nothing was set.</source>
        <translation>Nothing was set.</translation>
    </message>
    <message>
        <source>%1 is now X %2, Y %3, Z %4 (machine mm of its zero).</source>
        <translation>%1 is now X %2, Y %3, Z %4 (machine mm of its zero).</translation>
    </message>
    <message>
        <source>Probing stopped: the tool goes back to where it started. Close the dialog when it is there.</source>
        <translation>Probing stopped: the tool goes back to where it started. Close the dialog when it is there.</translation>
    </message>
    <message>
        <source>Probe work zero</source>
        <translation>Probe work zero</translation>
    </message>
    <message>
        <source>Z from a touch plate</source>
        <translation>Z from a touch plate</translation>
    </message>
    <message>
        <source>X from an edge</source>
        <translation>X from an edge</translation>
    </message>
    <message>
        <source>Y from an edge</source>
        <translation>Y from an edge</translation>
    </message>
    <message>
        <source>X and Y from an outside corner</source>
        <translation>X and Y from an outside corner</translation>
    </message>
    <message>
        <source>X and Y from an inside corner</source>
        <translation>X and Y from an inside corner</translation>
    </message>
    <message>
        <source>What to probe</source>
        <translation>What to probe</translation>
    </message>
    <message>
        <source>X direction toward the work</source>
        <translation>X direction toward the work</translation>
    </message>
    <message>
        <source>Y direction toward the work</source>
        <translation>Y direction toward the work</translation>
    </message>
    <message>
        <source>Plate thickness (mm)</source>
        <translation>Plate thickness (mm)</translation>
    </message>
    <message>
        <source>Tool diameter (mm)</source>
        <translation>Tool diameter (mm)</translation>
    </message>
    <message>
        <source>Travel at most (mm)</source>
        <translation>Travel at most (mm)</translation>
    </message>
    <message>
        <source>Reach beside each face (mm)</source>
        <translation>Reach beside each face (mm)</translation>
    </message>
    <message>
        <source>Probing feed (mm/min)</source>
        <translation>Probing feed (mm/min)</translation>
    </message>
    <message>
        <source>Back-off before the slow probe (mm)</source>
        <translation>Back-off before the slow probe (mm)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Close</translation>
    </message>
</context>
<context>
    <name>frezka::gui::Profile</name>
    <message>
        <source>Profile</source>
        <translation>Profile</translation>
    </message>
    <message>
        <source>the file cannot be read or written</source>
        <translation>the file cannot be read or written</translation>
    </message>
    <message>
        <source>the file is not valid JSON</source>
        <translation>the file is not valid JSON</translation>
    </message>
    <message>
        <source>the value has the wrong type</source>
        <translation>the value has the wrong type</translation>
    </message>
    <message>
        <source>unknown key (a typo?)</source>
        <translation>unknown key (a typo?)</translation>
    </message>
    <message>
        <source>the value is outside its range</source>
        <translation>the value is outside its range</translation>
    </message>
    <message>
        <source>the value is none of the allowed ones</source>
        <translation>the value is none of the allowed ones</translation>
    </message>
    <message>
        <source>the value contradicts another setting or the unit type</source>
        <translation>the value contradicts another setting or the unit type</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>The machine profile %1 cannot be used; the built-in GVE64 defaults are active until it is fixed:
%2</source>
        <translation>The machine profile %1 cannot be used; the built-in GVE64 defaults are active until it is fixed:
%2</translation>
    </message>
    <message>
        <source>Profile name</source>
        <translation>Profile name</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Unit type</source>
        <translation>Unit type</translation>
    </message>
    <message>
        <source>Maximum pulse rate</source>
        <translation>Maximum pulse rate</translation>
    </message>
    <message>
        <source>Firmware version</source>
        <translation>Firmware version</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Connection</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Baud rate</translation>
    </message>
    <message>
        <source>Checksums</source>
        <translation>Checksums</translation>
    </message>
    <message>
        <source>Packets</source>
        <translation>Packets</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation>Axes</translation>
    </message>
    <message>
        <source>X axis</source>
        <translation>X axis</translation>
    </message>
    <message>
        <source>Y axis</source>
        <translation>Y axis</translation>
    </message>
    <message>
        <source>Z axis</source>
        <translation>Z axis</translation>
    </message>
    <message>
        <source>A axis</source>
        <translation>A axis</translation>
    </message>
    <message>
        <source>Present</source>
        <translation>Present</translation>
    </message>
    <message>
        <source>Steps per mm</source>
        <translation>Steps per mm</translation>
    </message>
    <message>
        <source>Invert direction</source>
        <translation>Invert direction</translation>
    </message>
    <message>
        <source>Soft limit min</source>
        <translation>Soft limit min</translation>
    </message>
    <message>
        <source>Soft limit max</source>
        <translation>Soft limit max</translation>
    </message>
    <message>
        <source>Maximum speed</source>
        <translation>Maximum speed</translation>
    </message>
    <message>
        <source>Rapid speed</source>
        <translation>Rapid speed</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Acceleration</translation>
    </message>
    <message>
        <source>Maximum speed jump at a corner</source>
        <translation>Maximum speed jump at a corner</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Homing</translation>
    </message>
    <message>
        <source>Order (0 = not homed)</source>
        <translation>Order (0 = not homed)</translation>
    </message>
    <message>
        <source>Direction to the switch (-1/+1)</source>
        <translation>Direction to the switch (-1/+1)</translation>
    </message>
    <message>
        <source>Maximum search travel</source>
        <translation>Maximum search travel</translation>
    </message>
    <message>
        <source>Speed toward the switch</source>
        <translation>Speed toward the switch</translation>
    </message>
    <message>
        <source>Speed off the switch</source>
        <translation>Speed off the switch</translation>
    </message>
    <message>
        <source>Maximum back-off travel</source>
        <translation>Maximum back-off travel</translation>
    </message>
    <message>
        <source>Position after homing</source>
        <translation>Position after homing</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Motion</translation>
    </message>
    <message>
        <source>Corner deviation</source>
        <translation>Corner deviation</translation>
    </message>
    <message>
        <source>Arc chord tolerance</source>
        <translation>Arc chord tolerance</translation>
    </message>
    <message>
        <source>Pause between stand-alone moves</source>
        <translation>Pause between stand-alone moves</translation>
    </message>
    <message>
        <source>Speed mode</source>
        <translation>Speed mode</translation>
    </message>
    <message>
        <source>Tool lift</source>
        <translation>Tool lift</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <source>Spin-up wait</source>
        <translation>Spin-up wait</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>OUT1 function</source>
        <translation>OUT1 function</translation>
    </message>
    <message>
        <source>OUT2 function</source>
        <translation>OUT2 function</translation>
    </message>
    <message>
        <source>OUT3 function</source>
        <translation>OUT3 function</translation>
    </message>
    <message>
        <source>Output switched by M7</source>
        <translation>Output switched by M7</translation>
    </message>
    <message>
        <source>Unit EEPROM</source>
        <translation>Unit EEPROM</translation>
    </message>
    <message>
        <source>Compare with the unit on connect</source>
        <translation>Compare with the unit on connect</translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation>Handwheel (MPG)</translation>
    </message>
    <message>
        <source>Handwheel acceleration</source>
        <translation>Handwheel acceleration</translation>
    </message>
    <message>
        <source>Handwheel maximum speed</source>
        <translation>Handwheel maximum speed</translation>
    </message>
    <message>
        <source>Handwheel brake delay</source>
        <translation>Handwheel brake delay</translation>
    </message>
    <message>
        <source>Handwheel step multiplier</source>
        <translation>Handwheel step multiplier</translation>
    </message>
    <message>
        <source>Input that starts homing (0 = off)</source>
        <translation>Input that starts homing (0 = off)</translation>
    </message>
    <message>
        <source>Interrupt enable IN0-7</source>
        <translation>Interrupt enable IN0-7</translation>
    </message>
    <message>
        <source>Interrupt enable IN14/IN15</source>
        <translation>Interrupt enable IN14/IN15</translation>
    </message>
    <message>
        <source>Polarity IN0-7</source>
        <translation>Polarity IN0-7</translation>
    </message>
    <message>
        <source>Polarity IN14/IN15</source>
        <translation>Polarity IN14/IN15</translation>
    </message>
    <message>
        <source>A axis slaved to (0 none, 1 X, 2 Y, 3 Z)</source>
        <translation>A axis slaved to (0 none, 1 X, 2 Y, 3 Z)</translation>
    </message>
    <message>
        <source>PWM for breakout boards</source>
        <translation>PWM for breakout boards</translation>
    </message>
    <message>
        <source>Default spindle speed</source>
        <translation>Default spindle speed</translation>
    </message>
    <message>
        <source>Brake release delay</source>
        <translation>Brake release delay</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatic</translation>
    </message>
    <message>
        <source>Path speed (VK)</source>
        <translation>Path speed (VK)</translation>
    </message>
    <message>
        <source>Major axis speed (VN)</source>
        <translation>Major axis speed (VN)</translation>
    </message>
    <message>
        <source>Unused</source>
        <translation>Unused</translation>
    </message>
    <message>
        <source>Laser</source>
        <translation>Laser</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Coolant</translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation>Air blow</translation>
    </message>
    <message>
        <source>Machine cover lock</source>
        <translation>Machine cover lock</translation>
    </message>
    <message>
        <source>Tool release</source>
        <translation>Tool release</translation>
    </message>
    <message>
        <source>Tool cover open</source>
        <translation>Tool cover open</translation>
    </message>
    <message>
        <source>Brake</source>
        <translation>Brake</translation>
    </message>
    <message>
        <source>Interrupt signal</source>
        <translation>Interrupt signal</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Off</translation>
    </message>
    <message>
        <source>On</source>
        <translation>On</translation>
    </message>
    <message>
        <source>On, within the limits</source>
        <translation>On, within the limits</translation>
    </message>
    <message>
        <source>On, 4th position drives rotary A</source>
        <translation>On, 4th position drives rotary A</translation>
    </message>
    <message>
        <source>On with limits, 4th position drives rotary A</source>
        <translation>On with limits, 4th position drives rotary A</translation>
    </message>
    <message>
        <source>GVE84</source>
        <translation>GVE84</translation>
    </message>
    <message>
        <source>GVE64</source>
        <translation>GVE64</translation>
    </message>
    <message>
        <source>GVE64 PHANTOM</source>
        <translation>GVE64 PHANTOM</translation>
    </message>
    <message>
        <source>GVE114</source>
        <translation>GVE114</translation>
    </message>
    <message>
        <source>Maximum spindle speed</source>
        <translation>Maximum spindle speed</translation>
    </message>
    <message>
        <source>Adapter latency (each way)</source>
        <translation>Adapter latency (each way)</translation>
    </message>
    <message>
        <source>STEP active edge</source>
        <translation>STEP active edge</translation>
    </message>
    <message>
        <source>As the unit left the factory</source>
        <translation>As the unit left the factory</translation>
    </message>
    <message>
        <source>Falling edge</source>
        <translation>Falling edge</translation>
    </message>
    <message>
        <source>Rising edge</source>
        <translation>Rising edge</translation>
    </message>
    <message>
        <source>a key of an older profile, read into its successor or ignored</source>
        <translation>a key of an older profile, read into its successor or ignored</translation>
    </message>
    <message>
        <source>Spindle and coolant off at M0 / M1</source>
        <translation>Spindle and coolant off at M0 / M1</translation>
    </message>
    <message>
        <source>Spindle and coolant off at M6</source>
        <translation>Spindle and coolant off at M6</translation>
    </message>
    <message>
        <source>START button input (0 = none)</source>
        <translation>START button input (0 = none)</translation>
    </message>
    <message>
        <source>Allow a run before homing (with a warning)</source>
        <translation>Allow a run before homing (with a warning)</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Tools</translation>
    </message>
    <message>
        <source>Tool table file (LinuxCNC .tbl, beside the profile)</source>
        <translation>Tool table file (LinuxCNC .tbl, beside the profile)</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Lines executed at most (a program that never ends)</source>
        <translation>Lines executed at most (a program that never ends)</translation>
    </message>
    <message>
        <source>Moves at most (a program that never ends)</source>
        <translation>Moves at most (a program that never ends)</translation>
    </message>
    <message>
        <source>Subroutine folders (o&lt;name&gt; call of name.ngc; separated by :)</source>
        <translation>Subroutine folders (o&lt;name&gt; call of name.ngc; separated by :)</translation>
    </message>
    <message>
        <source>Unit address on the line (0..6)</source>
        <translation>Unit address on the line (0..6)</translation>
    </message>
    <message>
        <source>Tool length sensor</source>
        <translation>Tool length sensor</translation>
    </message>
    <message>
        <source>X (machine)</source>
        <translation>X (machine)</translation>
    </message>
    <message>
        <source>Y (machine)</source>
        <translation>Y (machine)</translation>
    </message>
    <message>
        <source>Clearance Z (machine)</source>
        <translation>Clearance Z (machine)</translation>
    </message>
    <message>
        <source>Probing feed</source>
        <translation>Probing feed</translation>
    </message>
    <message>
        <source>Slow probing feed</source>
        <translation>Slow probing feed</translation>
    </message>
    <message>
        <source>Back-off before the slow probe</source>
        <translation>Back-off before the slow probe</translation>
    </message>
    <message>
        <source>Trip Z of the reference tool (length 0)</source>
        <translation>Trip Z of the reference tool (length 0)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProfileEditor</name>
    <message>
        <source>&quot;emulator&quot; = the built-in unit emulator; or a serial port such as /dev/ttyUSB0; or a typed path such as the pty printed by gve-emu</source>
        <translation>&quot;emulator&quot; = the built-in unit emulator; or a serial port such as /dev/ttyUSB0; or a typed path such as the pty printed by gve-emu</translation>
    </message>
    <message>
        <source>General</source>
        <translation>General</translation>
    </message>
    <message>
        <source>The profile is valid.</source>
        <translation>The profile is valid.</translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) — the profile cannot be saved yet.</source>
        <translation>
            <numerusform>%n problem — the profile cannot be saved yet.</numerusform>
            <numerusform>%n problems — the profile cannot be saved yet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot load the profile %1:
%2</source>
        <translation>Cannot load the profile %1:
%2</translation>
    </message>
    <message>
        <source>The profile has problems; fix them first:
%1</source>
        <translation>The profile has problems; fix them first:
%1</translation>
    </message>
    <message>
        <source>Cannot save the profile %1: %2</source>
        <translation>Cannot save the profile %1: %2</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProgramInfoDialog</name>
    <message>
        <source>not planned</source>
        <translation>not planned</translation>
    </message>
    <message>
        <source>%1: %2 lines, %3 bytes, %4 moves, %5 mm of path, estimated time %6.</source>
        <translation>%1: %2 lines, %3 bytes, %4 moves, %5 mm of path, estimated time %6.</translation>
    </message>
    <message>
        <source>in the spindle</source>
        <translation>in the spindle</translation>
    </message>
    <message>
        <source>Program info</source>
        <translation>Program info</translation>
    </message>
    <message>
        <source>Extent (mm)</source>
        <translation>Extent (mm)</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Program min</source>
        <translation>Program min</translation>
    </message>
    <message>
        <source>Program max</source>
        <translation>Program max</translation>
    </message>
    <message>
        <source>Machine min</source>
        <translation>Machine min</translation>
    </message>
    <message>
        <source>Machine max</source>
        <translation>Machine max</translation>
    </message>
    <message>
        <source>Tools in their order</source>
        <translation>Tools in their order</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>From line</source>
        <translation>From line</translation>
    </message>
    <message>
        <source>Planned time</source>
        <translation>Planned time</translation>
    </message>
    <message>
        <source>Cut length (mm)</source>
        <translation>Cut length (mm)</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProgramListing</name>
    <message>
        <source>Run from this line (%1)…</source>
        <translation>Run from this line (%1)…</translation>
    </message>
</context>
<context>
    <name>frezka::gui::RunPanel</name>
    <message>
        <source>Elapsed %1</source>
        <translation>Elapsed %1</translation>
    </message>
    <message>
        <source>Remaining %1</source>
        <translation>Remaining %1</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Check</translation>
    </message>
    <message>
        <source>Check the program against the machine profile without moving</source>
        <translation>Check the program against the machine profile without moving</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Run</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Brake along the ramp and hold; Resume continues</source>
        <translation>Brake along the ramp and hold; Resume continues</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Abort</translation>
    </message>
    <message>
        <source>Tool lift…</source>
        <translation>Tool lift…</translation>
    </message>
    <message>
        <source>Lift the tool, switch the spindle off, change or clean it, continue</source>
        <translation>Lift the tool, switch the spindle off, change or clean it, continue</translation>
    </message>
    <message>
        <source>Run the checked program (asks for homing first on a machine not homed). The machine&apos;s START button does the same when the profile names its input. Space and Enter never press it.</source>
        <translation>Run the checked program (asks for homing first on a machine not homed). The machine&apos;s START button does the same when the profile names its input. Space and Enter never press it.</translation>
    </message>
    <message>
        <source>Continue the held job (the START button does the same)</source>
        <translation>Continue the held job (the START button does the same)</translation>
    </message>
    <message>
        <source>Stop (Esc)</source>
        <translation>Stop (Esc)</translation>
    </message>
    <message>
        <source>Controlled stop (Esc): brake along the ramp and hold the job; the position stays known and Resume continues it. During homing: end homing, the axes not yet homed stay not homed.</source>
        <translation>Controlled stop (Esc): brake along the ramp and hold the job; the position stays known and Resume continues it. During homing: end homing, the axes not yet homed stay not homed.</translation>
    </message>
    <message>
        <source>Brake and drop every queued move: the job ends and cannot be resumed; the position stays known. Also ends homing.</source>
        <translation>Brake and drop every queued move: the job ends and cannot be resumed; the position stays known. Also ends homing.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SerialMonitor</name>
    <message>
        <source>Hex view</source>
        <translation>Hex view</translation>
    </message>
    <message>
        <source>Hex bytes</source>
        <translation>Hex bytes</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <source>to port %1</source>
        <translation>to port %1</translation>
    </message>
    <message>
        <source>Stored message, e.g. AA 05 00 00 FF 51 (K51 ENQ) or Z? as text</source>
        <translation>Stored message, e.g. AA 05 00 00 FF 51 (K51 ENQ) or Z? as text</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <source>Capture to file…</source>
        <translation>Capture to file…</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Send</translation>
    </message>
    <message>
        <source>Message:</source>
        <translation>Message:</translation>
    </message>
    <message>
        <source>Port %1: cannot open %2: %3</source>
        <translation>Port %1: cannot open %2: %3</translation>
    </message>
    <message>
        <source>Port %1: %2</source>
        <translation>Port %1: %2</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>Port %1: watching %2 at %3 Bd.</source>
        <translation>Port %1: watching %2 at %3 Bd.</translation>
    </message>
    <message>
        <source>%1 older bytes left the view; capture to a file to keep everything.</source>
        <translation>%1 older bytes left the view; capture to a file to keep everything.</translation>
    </message>
    <message>
        <source>The message &quot;%1&quot; is not hex bytes (e.g. AA 05 00 00 FF 51).</source>
        <translation>The message &quot;%1&quot; is not hex bytes (e.g. AA 05 00 00 FF 51).</translation>
    </message>
    <message>
        <source>Port %1 is not open.</source>
        <translation>Port %1 is not open.</translation>
    </message>
    <message>
        <source>The message is empty.</source>
        <translation>The message is empty.</translation>
    </message>
    <message>
        <source>Port %1: the message could not be sent: %2</source>
        <translation>Port %1: the message could not be sent: %2</translation>
    </message>
    <message>
        <source>Capture to file</source>
        <translation>Capture to file</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
    <message>
        <source>Captured %1 lines to %2.</source>
        <translation>Captured %1 lines to %2.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SettingsDialog</name>
    <message>
        <source>Export profile</source>
        <translation>Export profile</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Machine profiles (*.json)</translation>
    </message>
    <message>
        <source>Load profile</source>
        <translation>Load profile</translation>
    </message>
    <message>
        <source>Defaults of the unit type loaded; Apply or Save to use them.</source>
        <translation>Defaults of the unit type loaded; Apply or Save to use them.</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Saved to %1.</translation>
    </message>
    <message>
        <source>Loaded %1; Apply to use it.</source>
        <translation>Loaded %1; Apply to use it.</translation>
    </message>
    <message>
        <source>The profile has problems; fix the fields marked red first.</source>
        <translation>The profile has problems; fix the fields marked red first.</translation>
    </message>
    <message>
        <source>Applied (not yet saved).</source>
        <translation>Applied (not yet saved).</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Settings</translation>
    </message>
    <message>
        <source>Machine profile</source>
        <translation>Machine profile</translation>
    </message>
    <message>
        <source>Application</source>
        <translation>Application</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Load…</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Save</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Export…</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>Defaults</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Apply</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Language</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>System language</translation>
    </message>
    <message>
        <source>Reconnect automatically after a lost link</source>
        <translation>Reconnect automatically after a lost link</translation>
    </message>
    <message>
        <source>Shortcuts</source>
        <translation>Shortcuts</translation>
    </message>
    <message>
        <source>Lengths shown in</source>
        <translation>Lengths shown in</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>millimetres (mm)</translation>
    </message>
    <message>
        <source>inches (in)</source>
        <translation>inches (in)</translation>
    </message>
    <message>
        <source>The DRO, the jog steps and feed, the status panel and the speed plot. The machine, its profile and the programs&apos; own G20/G21 are not affected.</source>
        <translation>The DRO, the jog steps and feed, the status panel and the speed plot. The machine, its profile and the programs&apos; own G20/G21 are not affected.</translation>
    </message>
    <message>
        <source>Serial trace kept in memory</source>
        <translation>Serial trace kept in memory</translation>
    </message>
    <message>
        <source> MB</source>
        <translation> MB</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>The last part of the serial line, both ways, saved with Machine › Save serial trace and by itself on an alarm into %1</source>
        <translation>The last part of the serial line, both ways, saved with Machine › Save serial trace and by itself on an alarm into %1</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ShortcutEditor</name>
    <message>
        <source>“%1” now has the key %2.</source>
        <translation>“%1” now has the key %2.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(none)</translation>
    </message>
    <message>
        <source>Every key is back to its default.</source>
        <translation>Every key is back to its default.</translation>
    </message>
    <message>
        <source>Click a key field and press the new key; it applies at once. A key that another action already has is refused.</source>
        <translation>Click a key field and press the new key; it applies at once. A key that another action already has is refused.</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Action</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Key</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Default</translation>
    </message>
    <message>
        <source>Reset to defaults</source>
        <translation>Reset to defaults</translation>
    </message>
</context>
<context>
    <name>frezka::gui::Shortcuts</name>
    <message>
        <source>Run the program</source>
        <translation>Run the program</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message>
        <source>Stop: brake along the ramp and hold the job (resumable)</source>
        <translation>Stop: brake along the ramp and hold the job (resumable)</translation>
    </message>
    <message>
        <source>Abort: brake and drop the job</source>
        <translation>Abort: brake and drop the job</translation>
    </message>
    <message>
        <source>Tool lift</source>
        <translation>Tool lift</translation>
    </message>
    <message>
        <source>Feed override up (6.25 %)</source>
        <translation>Feed override up (6.25 %)</translation>
    </message>
    <message>
        <source>Feed override down (6.25 %)</source>
        <translation>Feed override down (6.25 %)</translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation>Feed override 100 %</translation>
    </message>
    <message>
        <source>Home all axes</source>
        <translation>Home all axes</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Keyboard shortcuts</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Action</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Key</translation>
    </message>
    <message>
        <source>LinuxCNC AXIS</source>
        <translation>LinuxCNC AXIS</translation>
    </message>
    <message>
        <source>Jog X−</source>
        <translation>Jog X−</translation>
    </message>
    <message>
        <source>Jog X+</source>
        <translation>Jog X+</translation>
    </message>
    <message>
        <source>Jog Y−</source>
        <translation>Jog Y−</translation>
    </message>
    <message>
        <source>Jog Y+</source>
        <translation>Jog Y+</translation>
    </message>
    <message>
        <source>Jog Z−</source>
        <translation>Jog Z−</translation>
    </message>
    <message>
        <source>Jog Z+</source>
        <translation>Jog Z+</translation>
    </message>
    <message>
        <source>Work zero of X here</source>
        <translation>Work zero of X here</translation>
    </message>
    <message>
        <source>Work zero of Y here</source>
        <translation>Work zero of Y here</translation>
    </message>
    <message>
        <source>Work zero of Z here</source>
        <translation>Work zero of Z here</translation>
    </message>
    <message>
        <source>Work zero of all axes here</source>
        <translation>Work zero of all axes here</translation>
    </message>
    <message>
        <source>Spindle on / off</source>
        <translation>Spindle on / off</translation>
    </message>
    <message>
        <source>Give one key (with Ctrl, Shift or Alt if you like), not a sequence of keys.</source>
        <translation>Give one key (with Ctrl, Shift or Alt if you like), not a sequence of keys.</translation>
    </message>
    <message>
        <source>%1 is already the key of “%2”. Give that action another key first, or choose a different key.</source>
        <translation>%1 is already the key of “%2”. Give that action another key first, or choose a different key.</translation>
    </message>
    <message>
        <source>Keys of the main window; change them in Settings › Shortcuts. The jog keys act while held, only when jogging is possible (not while a job runs) and not while a text field has the focus. A text field with the focus keeps the letters typed into it; no key presses a button that merely has the focus.</source>
        <translation>Keys of the main window; change them in Settings › Shortcuts. The jog keys act while held, only when jogging is possible (not while a job runs) and not while a text field has the focus. A text field with the focus keeps the letters typed into it; no key presses a button that merely has the focus.</translation>
    </message>
    <message>
        <source>File › Open program</source>
        <translation>File › Open program</translation>
    </message>
    <message>
        <source>File › Reload program</source>
        <translation>File › Reload program</translation>
    </message>
    <message>
        <source>File › Quit</source>
        <translation>File › Quit</translation>
    </message>
    <message>
        <source>%1 is the key of the menu command “%2”. Choose a different key.</source>
        <translation>%1 is the key of the menu command “%2”. Choose a different key.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SimulatedWheel</name>
    <message>
        <source>Simulated wheel:</source>
        <translation>Simulated wheel:</translation>
    </message>
    <message>
        <source>Simulates the unit&apos;s MPG handwheel on the built-in emulator: choose the axis and the step switch (x1 = 0.01 mm per detent), then turn with − / + (hold to keep turning). It moves the axis only while Handwheel (MPG) is on.</source>
        <translation>Simulates the unit&apos;s MPG handwheel on the built-in emulator: choose the axis and the step switch (x1 = 0.01 mm per detent), then turn with − / + (hold to keep turning). It moves the axis only while Handwheel (MPG) is on.</translation>
    </message>
    <message>
        <source>The wheel&apos;s axis switch (4 = the fourth axis or the spindle, as the unit&apos;s EEPROM sets it)</source>
        <translation>The wheel&apos;s axis switch (4 = the fourth axis or the spindle, as the unit&apos;s EEPROM sets it)</translation>
    </message>
    <message>
        <source>The wheel&apos;s step switch: x1 = 0.01 mm, x10 = 0.1 mm, x100 = 1 mm per detent</source>
        <translation>The wheel&apos;s step switch: x1 = 0.01 mm, x10 = 0.1 mm, x100 = 1 mm per detent</translation>
    </message>
    <message>
        <source>Turn the simulated wheel one detent back</source>
        <translation>Turn the simulated wheel one detent back</translation>
    </message>
    <message>
        <source>Turn the simulated wheel one detent forward</source>
        <translation>Turn the simulated wheel one detent forward</translation>
    </message>
</context>
<context>
    <name>frezka::gui::SpeedPlot</name>
    <message>
        <source>%1 along the path (%2 %3)</source>
        <translation>%1 along the path (%2 %3)</translation>
    </message>
    <message>
        <source>%1 %2 at %3 %4, line %5</source>
        <translation>%1 %2 at %3 %4, line %5</translation>
    </message>
</context>
<context>
    <name>frezka::gui::StatusPanel</name>
    <message>
        <source>%1 % (runs %2 %)</source>
        <translation>%1 % (runs %2 %)</translation>
    </message>
    <message>
        <source>override %1</source>
        <translation>override %1</translation>
    </message>
    <message>
        <source>clockwise (M3)</source>
        <translation>clockwise (M3)</translation>
    </message>
    <message>
        <source>counter-clockwise (M4)</source>
        <translation>counter-clockwise (M4)</translation>
    </message>
    <message>
        <source>on · %1 rpm</source>
        <translation>on · %1 rpm</translation>
    </message>
    <message>
        <source>on · %1 · %2 rpm</source>
        <translation>on · %1 · %2 rpm</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>none (T0)</source>
        <translation>none (T0)</translation>
    </message>
    <message>
        <source>%1 on</source>
        <translation>%1 on</translation>
    </message>
    <message>
        <source>%1 off</source>
        <translation>%1 off</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Feed</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Modes</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>Homed</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Connection</translation>
    </message>
    <message>
        <source>%1 (override %2 %)</source>
        <translation>%1 (override %2 %)</translation>
    </message>
    <message>
        <source>programmed %1 %2 × %3</source>
        <translation>programmed %1 %2 × %3</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ToolTableDialog</name>
    <message>
        <source>Row %1: the tool number must be a whole number from 1 up.</source>
        <translation>Row %1: the tool number must be a whole number from 1 up.</translation>
    </message>
    <message>
        <source>Row %1: tool %2 is listed twice; give it another number or remove the row.</source>
        <translation>Row %1: tool %2 is listed twice; give it another number or remove the row.</translation>
    </message>
    <message>
        <source>Row %1: the pocket must be a whole number from 0 up.</source>
        <translation>Row %1: the pocket must be a whole number from 0 up.</translation>
    </message>
    <message>
        <source>Row %1: the length must be a number of mm, e.g. 42.5.</source>
        <translation>Row %1: the length must be a number of mm, e.g. 42.5.</translation>
    </message>
    <message>
        <source>Row %1: the diameter must be a number of mm, 0 or more.</source>
        <translation>Row %1: the diameter must be a number of mm, 0 or more.</translation>
    </message>
    <message>
        <source>Tool table</source>
        <translation>Tool table</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Pocket</translation>
    </message>
    <message>
        <source>Length (mm)</source>
        <translation>Length (mm)</translation>
    </message>
    <message>
        <source>Diameter (mm)</source>
        <translation>Diameter (mm)</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Comment</translation>
    </message>
    <message>
        <source>File: %1</source>
        <translation>File: %1</translation>
    </message>
    <message>
        <source>&amp;Add tool</source>
        <translation>&amp;Add tool</translation>
    </message>
    <message>
        <source>&amp;Remove tool</source>
        <translation>&amp;Remove tool</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Save</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Close</translation>
    </message>
    <message>
        <source>Select the row of the tool in the spindle, then measure it.</source>
        <translation>Select the row of the tool in the spindle, then measure it.</translation>
    </message>
    <message>
        <source>Measuring tool %1 on the tool sensor…</source>
        <translation>Measuring tool %1 on the tool sensor…</translation>
    </message>
    <message>
        <source>Tool %1 is %2 mm long (the sensor tripped at machine Z %3).</source>
        <translation>Tool %1 is %2 mm long (the sensor tripped at machine Z %3).</translation>
    </message>
    <message>
        <source>S&amp;top measuring</source>
        <translation>S&amp;top measuring</translation>
    </message>
    <message>
        <source>&amp;Measure length</source>
        <translation>&amp;Measure length</translation>
    </message>
    <message>
        <source>Probes the selected tool on the tool length sensor (fast, then slow) and writes its length into the table.</source>
        <translation>Probes the selected tool on the tool length sensor (fast, then slow) and writes its length into the table.</translation>
    </message>
    <message>
        <source>Measuring stopped: the tool goes back up to the sensor&apos;s clearance. Close the table when it is up.</source>
        <translation>Measuring stopped: the tool goes back up to the sensor&apos;s clearance. Close the table when it is up.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ToolpathView</name>
    <message>
        <source>Top</source>
        <translation>Top</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Front</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Side</translation>
    </message>
    <message>
        <source>Iso</source>
        <translation>Iso</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Fit</translation>
    </message>
    <message>
        <source>Show the whole program</source>
        <translation>Show the whole program</translation>
    </message>
    <message>
        <source>Left drag: orbit · right/middle drag or Shift+left: pan · wheel: zoom</source>
        <translation>Left drag: orbit · right/middle drag or Shift+left: pan · wheel: zoom</translation>
    </message>
</context>
<context>
    <name>frezka::gui::TransferPanel</name>
    <message>
        <source>Controller → PC</source>
        <translation>Controller → PC</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Save…</translation>
    </message>
    <message>
        <source>Choose file…</source>
        <translation>Choose file…</translation>
    </message>
    <message>
        <source>PC → Controller</source>
        <translation>PC → Controller</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Ask the controller for its programs (DEJ) and receive them.</source>
        <translation>Ask the controller for its programs (DEJ) and receive them.</translation>
    </message>
    <message>
        <source>Send the chosen file to the controller unchanged.</source>
        <translation>Send the chosen file to the controller unchanged.</translation>
    </message>
    <message>
        <source>16 characters shown on the controller</source>
        <translation>16 characters shown on the controller</translation>
    </message>
    <message>
        <source>No file chosen</source>
        <translation>No file chosen</translation>
    </message>
    <message>
        <source>Header:</source>
        <translation>Header:</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>Length:</translation>
    </message>
    <message>
        <source>Inner blocks:</source>
        <translation>Inner blocks:</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>File:</translation>
    </message>
    <message>
        <source>Messages:</source>
        <translation>Messages:</translation>
    </message>
    <message>
        <source>Receiving from the controller…</source>
        <translation>Receiving from the controller…</translation>
    </message>
    <message>
        <source>Sending %1 to the controller…</source>
        <translation>Sending %1 to the controller…</translation>
    </message>
    <message>
        <source>%1 of %2 bytes, %3 left</source>
        <translation>%1 of %2 bytes, %3 left</translation>
    </message>
    <message>
        <source>%1 bytes in %2</source>
        <translation>%1 bytes in %2</translation>
    </message>
    <message>
        <source>%1 bytes (0x%2)</source>
        <translation>%1 bytes (0x%2)</translation>
    </message>
    <message>
        <source>Received. Press Save to store the data in a file.</source>
        <translation>Received. Press Save to store the data in a file.</translation>
    </message>
    <message>
        <source>Sent; the controller confirmed the transfer.</source>
        <translation>Sent; the controller confirmed the transfer.</translation>
    </message>
    <message>
        <source>On the controller, TCHIN programs show &quot;no prg set&quot; once after a transfer: set up the X axis first — select the TCHIN program in AUT and hold RES.</source>
        <translation>On the controller, TCHIN programs show &quot;no prg set&quot; once after a transfer: set up the X axis first — select the TCHIN program in AUT and hold RES.</translation>
    </message>
    <message>
        <source>Save the controller&apos;s data</source>
        <translation>Save the controller&apos;s data</translation>
    </message>
    <message>
        <source>Choose the file to send</source>
        <translation>Choose the file to send</translation>
    </message>
    <message>
        <source>Cannot write %1: %2. The received data are kept; choose another file.</source>
        <translation>Cannot write %1: %2. The received data are kept; choose another file.</translation>
    </message>
    <message>
        <source>Saved %1 bytes to %2.</source>
        <translation>Saved %1 bytes to %2.</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Cannot read %1: %2</translation>
    </message>
    <message>
        <source>%1 bytes; inner blocks: %2</source>
        <translation>%1 bytes; inner blocks: %2</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Send anyway</translation>
    </message>
    <message>
        <source>Send a file whose inner blocks have a wrong checksum, or whose length this controller reported itself. Only for data the controller gave you.</source>
        <translation>Send a file whose inner blocks have a wrong checksum, or whose length this controller reported itself. Only for data the controller gave you.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Cancelled.</translation>
    </message>
    <message>
        <source>Cancelled: %1</source>
        <translation>Cancelled: %1</translation>
    </message>
    <message>
        <source>Receiving from the controller failed</source>
        <translation>Receiving from the controller failed</translation>
    </message>
    <message>
        <source>Sending to the controller failed</source>
        <translation>Sending to the controller failed</translation>
    </message>
    <message>
        <source>Transfer failed.</source>
        <translation>Transfer failed.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 holds %2 data (saved from a %2 control): is the wrong system selected? Choose %2 and connect again. Nothing was sent.</source>
        <translation>%1 holds %2 data (saved from a %2 control): is the wrong system selected? Choose %2 and connect again. Nothing was sent.</translation>
    </message>
    <message>
        <source>Frezka grinder file, keeps the header (*.frg);;Bare data for the old tools (*.bin)</source>
        <translation>Frezka grinder file, keeps the header (*.frg);;Bare data for the old tools (*.bin)</translation>
    </message>
    <message>
        <source>%1 is damaged: %2</source>
        <translation>%1 is damaged: %2</translation>
    </message>
    <message>
        <source>%1 bytes from the editor</source>
        <translation>%1 bytes from the editor</translation>
    </message>
    <message>
        <source>ANC messages carry no header; nothing typed here would be sent.</source>
        <translation>ANC messages carry no header; nothing typed here would be sent.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::UnitConfigDialog</name>
    <message>
        <source>No reply to %1 within 5 s.</source>
        <translation>No reply to %1 within 5 s.</translation>
    </message>
    <message>
        <source>Reading the unit&apos;s EEPROM…</source>
        <translation>Reading the unit&apos;s EEPROM…</translation>
    </message>
    <message>
        <source>The unit already matches the profile.</source>
        <translation>The unit already matches the profile.</translation>
    </message>
    <message>
        <source>Read the unit first.</source>
        <translation>Read the unit first.</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n setting(s) and reading them back…</source>
        <translation>
            <numerusform>Writing %n setting and reading them back…</numerusform>
            <numerusform>Writing %n settings and reading them back…</numerusform>
        </translation>
    </message>
    <message>
        <source>The unit refused %1 (reply %2).</source>
        <translation>The unit refused %1 (reply %2).</translation>
    </message>
    <message>
        <source>Cannot read the value in the reply to %1: %2</source>
        <translation>Cannot read the value in the reply to %1: %2</translation>
    </message>
    <message>
        <source>Read-back of %1 gives %2, not the %3 written.</source>
        <translation>Read-back of %1 gives %2, not the %3 written.</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 failed: %2</translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation>Not read yet.</translation>
    </message>
    <message numerus="yes">
        <source>The unit matches the profile (%n setting(s) compared).</source>
        <translation>
            <numerusform>The unit matches the profile (%n setting compared).</numerusform>
            <numerusform>The unit matches the profile (%n settings compared).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ from the profile.</source>
        <translation>
            <numerusform>%n setting differ from the profile.</numerusform>
            <numerusform>%n settings differ from the profile.</numerusform>
        </translation>
    </message>
    <message>
        <source>Unit configuration (EEPROM)</source>
        <translation>Unit configuration (EEPROM)</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Setting</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profile</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Meaning (unit value)</source>
        <translation>Meaning (unit value)</translation>
    </message>
    <message>
        <source>Read from unit</source>
        <translation>Read from unit</translation>
    </message>
    <message>
        <source>Write differences</source>
        <translation>Write differences</translation>
    </message>
    <message>
        <source>Write all</source>
        <translation>Write all</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>Write the unit&apos;s EEPROM</source>
        <translation>Write the unit&apos;s EEPROM</translation>
    </message>
    <message numerus="yes">
        <source>Write all %n value(s) of the profile into the unit&apos;s EEPROM?</source>
        <translation>
            <numerusform>Write %n value of the profile into the unit&apos;s EEPROM?</numerusform>
            <numerusform>Write all %n values of the profile into the unit&apos;s EEPROM?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write the %n value(s) that differ into the unit&apos;s EEPROM?</source>
        <translation>
            <numerusform>Write the %n value that differs into the unit&apos;s EEPROM?</numerusform>
            <numerusform>Write the %n values that differ into the unit&apos;s EEPROM?</numerusform>
        </translation>
    </message>
    <message>
        <source>The unit keeps them after it is switched off, and the machine moves by them from now on.</source>
        <translation>The unit keeps them after it is switched off, and the machine moves by them from now on.</translation>
    </message>
</context>
<context>
    <name>frezka::gui::UnitsPanel</name>
    <message>
        <source>%1 (this window&apos;s machine)</source>
        <translation>%1 (this window&apos;s machine)</translation>
    </message>
    <message>
        <source>none high</source>
        <translation>none high</translation>
    </message>
    <message>
        <source>high: %1</source>
        <translation>high: %1</translation>
    </message>
    <message>
        <source>all off</source>
        <translation>all off</translation>
    </message>
    <message>
        <source>on: %1</source>
        <translation>on: %1</translation>
    </message>
    <message>
        <source>Units on the line</source>
        <translation>Units on the line</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Firmware · identity</source>
        <translation>Firmware · identity</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>X mm</source>
        <translation>X mm</translation>
    </message>
    <message>
        <source>Y mm</source>
        <translation>Y mm</translation>
    </message>
    <message>
        <source>Z mm</source>
        <translation>Z mm</translation>
    </message>
    <message>
        <source>A °</source>
        <translation>A °</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Inputs</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>Jog another unit:</source>
        <translation>Jog another unit:</translation>
    </message>
    <message>
        <source>Step in mm (A: degrees)</source>
        <translation>Step in mm (A: degrees)</translation>
    </message>
    <message>
        <source>Jog the chosen unit&apos;s axis by one step in the negative direction</source>
        <translation>Jog the chosen unit&apos;s axis by one step in the negative direction</translation>
    </message>
    <message>
        <source>Jog the chosen unit&apos;s axis by one step in the positive direction</source>
        <translation>Jog the chosen unit&apos;s axis by one step in the positive direction</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Stop the chosen unit: its jog ends, a job or homing is held</source>
        <translation>Stop the chosen unit: its jog ends, a job or homing is held</translation>
    </message>
    <message>
        <source>Make it this window&apos;s machine</source>
        <translation>Make it this window&apos;s machine</translation>
    </message>
    <message>
        <source>The window then runs, jogs and shows the chosen unit with its own profile; possible while every unit on the line is idle</source>
        <translation>The window then runs, jogs and shows the chosen unit with its own profile; possible while every unit on the line is idle</translation>
    </message>
</context>
<context>
    <name>frezka::gui::ZPositionPanel</name>
    <message>
        <source>Read position (Z?)</source>
        <translation>Read position (Z?)</translation>
    </message>
    <message>
        <source>GO</source>
        <translation>GO</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Move the table to this Z position (selector in PGN).</source>
        <translation>Move the table to this Z position (selector in PGN).</translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation>Protocol:</translation>
    </message>
    <message>
        <source>Z position:</source>
        <translation>Z position:</translation>
    </message>
    <message>
        <source>Go to:</source>
        <translation>Go to:</translation>
    </message>
    <message>
        <source>not connected in a Z-position mode</source>
        <translation>not connected in a Z-position mode</translation>
    </message>
    <message>
        <source>FORM=1: ASCII both ways (Z?, GO)</source>
        <translation>FORM=1: ASCII both ways (Z?, GO)</translation>
    </message>
    <message>
        <source>FORM=2: binary frames sent by the controller</source>
        <translation>FORM=2: binary frames sent by the controller</translation>
    </message>
    <message>
        <source>%1 bytes skipped to find the frame start.</source>
        <translation>%1 bytes skipped to find the frame start.</translation>
    </message>
    <message>
        <source>Asking for the position…</source>
        <translation>Asking for the position…</translation>
    </message>
    <message>
        <source>Moving to %1 mm…</source>
        <translation>Moving to %1 mm…</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 frames received.</source>
        <translation>%1 frames received.</translation>
    </message>
    <message>
        <source>Position received at %1.</source>
        <translation>Position received at %1.</translation>
    </message>
</context>
<context>
    <name>frezka::gveemu</name>
    <message>
        <source>%1 needs a value (see --help)</source>
        <translation>%1 needs a value (see --help)</translation>
    </message>
    <message>
        <source>unknown option %1 (see --help)</source>
        <translation>unknown option %1 (see --help)</translation>
    </message>
    <message>
        <source>invalid value &apos;%1&apos; for %2 (see --help)</source>
        <translation>invalid value &apos;%1&apos; for %2 (see --help)</translation>
    </message>
    <message>
        <source>%1 Bd is not a baud rate of the %2</source>
        <translation>%1 Bd is not a baud rate of the %2</translation>
    </message>
    <message>
        <source>%1 pulses/s is not an orderable rate of the %2</source>
        <translation>%1 pulses/s is not an orderable rate of the %2</translation>
    </message>
    <message>
        <source>the %1 has no axis A</source>
        <translation>the %1 has no axis A</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a firmware string of the %2</source>
        <translation>&apos;%1&apos; is not a firmware string of the %2</translation>
    </message>
    <message>
        <source>cannot read the wheel turn &apos;%1&apos;: write AXIS STEP DETENTS, e.g. X 10 -5</source>
        <translation>cannot read the wheel turn &apos;%1&apos;: write AXIS STEP DETENTS, e.g. X 10 -5</translation>
    </message>
    <message>
        <source>cannot read the unit &apos;%1&apos; of --units: write ADDRESS:VARIANT with an address 0..6, e.g. 0:gve114,1:gve114</source>
        <translation>cannot read the unit &apos;%1&apos; of --units: write ADDRESS:VARIANT with an address 0..6, e.g. 0:gve114,1:gve114</translation>
    </message>
    <message>
        <source>--units names address %1 twice: give each unit its own address</source>
        <translation>--units names address %1 twice: give each unit its own address</translation>
    </message>
    <message>
        <source>Usage: gve-emu [options]
Serves an emulated GVE interpolator on a new pseudo-terminal in real time.
The first line printed on stdout is the terminal path to open (e.g. /dev/pts/5).
Stop it with Ctrl+C (SIGINT) or SIGTERM.

Options:
  --variant ID        gve84 | gve64 | gve64-phantom | gve114 (default gve64)
  --baud N            line speed, one of the variant&apos;s rates (default 115200)
  --max-rate N        maximum pulse rate of the unit, pulses/s (one of the
                      variant&apos;s orderable rates; default the variant&apos;s default)
  --firmware TEXT     the reply to &apos;?&apos;, e.g. &quot;IP64MPG v17 1.2.2009&quot;: an older
                      GVE64 firmware lacks MPG and EEPROM floats (v10), VK/VL/XM
                      and N&lt;axis&gt; (v19) (default the variant&apos;s)
  --bad-checksum-code N  reply code 0..7 to a command with a wrong checksum, for
                      testing a unit that differs from the adopted reading (4)
  --address N         unit address 0..6 (default 0)
  --units A:ID,...    several units on the one line, e.g. 0:gve114,1:gve114:
                      each answers only its address (0..6), all share the wire
                      and its time; address 7 (the spindle) is the first unit&apos;s
                      that has one; the other options apply to every unit
                      (--eeprom FILE keeps unit A&apos;s EEPROM in FILE.A)
  --latency MS        added delay each way, milliseconds (default 0)
  --latency-to-unit MS, --latency-to-pc MS   the same for one direction
  --seed N            seed of the fault injector (default 1)
  --corrupt P         probability per byte of a flipped bit, both ways (0..1)
  --drop P            probability per byte that it is lost, both ways
  --duplicate P       probability per byte that it arrives twice, both ways
  --lose-reply P      probability that a whole reply is lost
  --eeprom FILE       keep the EEPROM in FILE (read at start, written on EW/EFW/EUW)
  --home AXIS=POS[,+|-]   home switch of AXIS (X, Y, Z, A on IN0..IN3): it is
                      pressed at and below POS (-, default) or at and above (+)
  --limit IN:AXIS=POS[,+|-]  input IN (0..15) pressed by AXIS beyond POS, e.g.
                      --limit 6:X=200000,+ (GVE64 end switch X)
  --surface SPEC      the work&apos;s top, touched by the tool probe (IN15), in machine
                      mm: plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or
                      warp:Z0,DZDX,DZDY,AMP,PERIOD (the plane plus the sine)
  --steps-per-mm N[,N,N]  steps per mm of X, Y, Z for --surface (default 200)
  --probe-contact 0|1 the IN15 level at contact (default 0, as the shipped
                      profiles&apos; EEPROM polarity)
  --link PATH         also create a symlink PATH to the terminal
  --replay TRACE      answer as the unit recorded in TRACE did (a serial trace,
                      docs/serial-trace.md): each recorded reply when the driver
                      sends the command before it, with its timing; a command
                      that differs ends gve-emu with the trace line (exit 3)
  --com-switch N      the COM SPEED switch, 0..3 (sw1 sw2 OFF OFF .. ON ON): the
                      unit listens at its speed in the range of EEPROM 0x0D,
                      read at start; a client at another speed is not heard
                      (default: not modelled, any speed is heard)
  --analog-jumper ana|pwm  the board&apos;s ANA/PWM jumper (default ana)
  --wheel             turn the MPG handwheel from stdin, one line per turn:
                      AXIS STEP DETENTS, e.g. &quot;X 10 -5&quot; (AXIS X, Y, Z, A or 4,
                      STEP 1, 10 or 100; the unit moves by its EEPROM&apos;s MPG)
  --verbose           log every byte to stderr
  --help              this text
  --version           the version
</source>
        <translation>Usage: gve-emu [options]
Serves an emulated GVE interpolator on a new pseudo-terminal in real time.
The first line printed on stdout is the terminal path to open (e.g. /dev/pts/5).
Stop it with Ctrl+C (SIGINT) or SIGTERM.

Options:
  --variant ID        gve84 | gve64 | gve64-phantom | gve114 (default gve64)
  --baud N            line speed, one of the variant&apos;s rates (default 115200)
  --max-rate N        maximum pulse rate of the unit, pulses/s (one of the
                      variant&apos;s orderable rates; default the variant&apos;s default)
  --firmware TEXT     the reply to &apos;?&apos;, e.g. &quot;IP64MPG v17 1.2.2009&quot;: an older
                      GVE64 firmware lacks MPG and EEPROM floats (v10), VK/VL/XM
                      and N&lt;axis&gt; (v19) (default the variant&apos;s)
  --bad-checksum-code N  reply code 0..7 to a command with a wrong checksum, for
                      testing a unit that differs from the adopted reading (4)
  --address N         unit address 0..6 (default 0)
  --units A:ID,...    several units on the one line, e.g. 0:gve114,1:gve114:
                      each answers only its address (0..6), all share the wire
                      and its time; address 7 (the spindle) is the first unit&apos;s
                      that has one; the other options apply to every unit
                      (--eeprom FILE keeps unit A&apos;s EEPROM in FILE.A)
  --latency MS        added delay each way, milliseconds (default 0)
  --latency-to-unit MS, --latency-to-pc MS   the same for one direction
  --seed N            seed of the fault injector (default 1)
  --corrupt P         probability per byte of a flipped bit, both ways (0..1)
  --drop P            probability per byte that it is lost, both ways
  --duplicate P       probability per byte that it arrives twice, both ways
  --lose-reply P      probability that a whole reply is lost
  --eeprom FILE       keep the EEPROM in FILE (read at start, written on EW/EFW/EUW)
  --home AXIS=POS[,+|-]   home switch of AXIS (X, Y, Z, A on IN0..IN3): it is
                      pressed at and below POS (-, default) or at and above (+)
  --limit IN:AXIS=POS[,+|-]  input IN (0..15) pressed by AXIS beyond POS, e.g.
                      --limit 6:X=200000,+ (GVE64 end switch X)
  --surface SPEC      the work&apos;s top, touched by the tool probe (IN15), in machine
                      mm: plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or
                      warp:Z0,DZDX,DZDY,AMP,PERIOD (the plane plus the sine)
  --steps-per-mm N[,N,N]  steps per mm of X, Y, Z for --surface (default 200)
  --probe-contact 0|1 the IN15 level at contact (default 0, as the shipped
                      profiles&apos; EEPROM polarity)
  --link PATH         also create a symlink PATH to the terminal
  --replay TRACE      answer as the unit recorded in TRACE did (a serial trace,
                      docs/serial-trace.md): each recorded reply when the driver
                      sends the command before it, with its timing; a command
                      that differs ends gve-emu with the trace line (exit 3)
  --com-switch N      the COM SPEED switch, 0..3 (sw1 sw2 OFF OFF .. ON ON): the
                      unit listens at its speed in the range of EEPROM 0x0D,
                      read at start; a client at another speed is not heard
                      (default: not modelled, any speed is heard)
  --analog-jumper ana|pwm  the board&apos;s ANA/PWM jumper (default ana)
  --wheel             turn the MPG handwheel from stdin, one line per turn:
                      AXIS STEP DETENTS, e.g. &quot;X 10 -5&quot; (AXIS X, Y, Z, A or 4,
                      STEP 1, 10 or 100; the unit moves by its EEPROM&apos;s MPG)
  --verbose           log every byte to stderr
  --help              this text
  --version           the version
</translation>
    </message>
</context>
<context>
    <name>frezka::session</name>
    <message>
        <source>held</source>
        <translation>held</translation>
    </message>
    <message>
        <source>did not hold</source>
        <translation>did not hold</translation>
    </message>
    <message>
        <source>not checked</source>
        <translation>not checked</translation>
    </message>
    <message>
        <source>skipped</source>
        <translation>skipped</translation>
    </message>
    <message>
        <source>Identify the unit</source>
        <translation>Identify the unit</translation>
    </message>
    <message>
        <source>Asks the unit for its firmware (?) and its number (Q) and compares them with the profile.</source>
        <translation>Asks the unit for its firmware (?) and its number (Q) and compares them with the profile.</translation>
    </message>
    <message>
        <source>Check the protocol readings</source>
        <translation>Check the protocol readings</translation>
    </message>
    <message>
        <source>Checks the readings of the manuals that can be checked without motion: checksums, @ and &gt;, packet replies, error replies, EEPROM reads.</source>
        <translation>Checks the readings of the manuals that can be checked without motion: checksums, @ and &gt;, packet replies, error replies, EEPROM reads.</translation>
    </message>
    <message>
        <source>Measure the link</source>
        <translation>Measure the link</translation>
    </message>
    <message>
        <source>Times round trips per command class, the bytes per second and the adapter&apos;s latency, and proposes link.latencyMs.</source>
        <translation>Times round trips per command class, the bytes per second and the adapter&apos;s latency, and proposes link.latencyMs.</translation>
    </message>
    <message>
        <source>Read the EEPROM</source>
        <translation>Read the EEPROM</translation>
    </message>
    <message>
        <source>Reads the unit&apos;s EEPROM settings, decodes them and compares them with the profile (nothing is written).</source>
        <translation>Reads the unit&apos;s EEPROM settings, decodes them and compares them with the profile (nothing is written).</translation>
    </message>
    <message>
        <source>Move axis %1</source>
        <translation>Move axis %1</translation>
    </message>
    <message>
        <source>Moves axis %1 a little in + and then back in − at a low speed; you confirm the direction and enter the distance you measured, which corrects its steps per mm.</source>
        <translation>Moves axis %1 a little in + and then back in − at a low speed; you confirm the direction and enter the distance you measured, which corrects its steps per mm.</translation>
    </message>
    <message>
        <source>Test the home and limit switches</source>
        <translation>Test the home and limit switches</translation>
    </message>
    <message>
        <source>You press each switch by hand; the step watches its input.</source>
        <translation>You press each switch by hand; the step watches its input.</translation>
    </message>
    <message>
        <source>Test the STOP button</source>
        <translation>Test the STOP button</translation>
    </message>
    <message>
        <source>You press the STOP button; the step watches its input.</source>
        <translation>You press the STOP button; the step watches its input.</translation>
    </message>
    <message>
        <source>Run the spindle at two speeds</source>
        <translation>Run the spindle at two speeds</translation>
    </message>
    <message>
        <source>Switches the spindle on at a quarter and at half of its maximum speed, then off; you confirm it turned.</source>
        <translation>Switches the spindle on at a quarter and at half of its maximum speed, then off; you confirm it turned.</translation>
    </message>
    <message>
        <source>Switch the outputs</source>
        <translation>Switch the outputs</translation>
    </message>
    <message>
        <source>Switches each output the profile uses (coolant, air ...) on and off; you confirm it switched.</source>
        <translation>Switches each output the profile uses (coolant, air ...) on and off; you confirm it switched.</translation>
    </message>
    <message>
        <source>Home the machine</source>
        <translation>Home the machine</translation>
    </message>
    <message>
        <source>Homes the axes the profile homes, in its order (last, when the switches are known to work).</source>
        <translation>Homes the axes the profile homes, in its order (last, when the switches are known to work).</translation>
    </message>
    <message>
        <source>+ move: %1 steps counted</source>
        <translation>+ move: %1 steps counted</translation>
    </message>
    <message>
        <source>(the axis did not move: at its soft limit, or the driver refused it)</source>
        <translation>(the axis did not move: at its soft limit, or the driver refused it)</translation>
    </message>
    <message>
        <source>Did axis %1 move in + (by about %2 mm)?</source>
        <translation>Did axis %1 move in + (by about %2 mm)?</translation>
    </message>
    <message>
        <source>How far did axis %1 move, measured in mm? (empty: as asked)</source>
        <translation>How far did axis %1 move, measured in mm? (empty: as asked)</translation>
    </message>
    <message>
        <source>− move: %1 steps counted</source>
        <translation>− move: %1 steps counted</translation>
    </message>
    <message>
        <source>Did axis %1 move back in −?</source>
        <translation>Did axis %1 move back in −?</translation>
    </message>
    <message>
        <source>steps per mm %1 -&gt; %2</source>
        <translation>steps per mm %1 -&gt; %2</translation>
    </message>
    <message>
        <source>Press the home switch of %1 (IN%2) now.</source>
        <translation>Press the home switch of %1 (IN%2) now.</translation>
    </message>
    <message>
        <source>home %1 (IN%2): %3</source>
        <translation>home %1 (IN%2): %3</translation>
    </message>
    <message>
        <source>the profile homes no axis</source>
        <translation>the profile homes no axis</translation>
    </message>
    <message>
        <source>Press the STOP button (IN7) now.</source>
        <translation>Press the STOP button (IN7) now.</translation>
    </message>
    <message>
        <source>IN7 changed when the button was pressed</source>
        <translation>IN7 changed when the button was pressed</translation>
    </message>
    <message>
        <source>IN7 did not change within %1 s: check the button&apos;s wiring</source>
        <translation>IN7 did not change within %1 s: check the button&apos;s wiring</translation>
    </message>
    <message>
        <source>Does the spindle turn at about %1 rpm?</source>
        <translation>Does the spindle turn at about %1 rpm?</translation>
    </message>
    <message>
        <source>%1 rpm (%2 ‰): %3</source>
        <translation>%1 rpm (%2 ‰): %3</translation>
    </message>
    <message>
        <source>Did OUT%1 switch on?</source>
        <translation>Did OUT%1 switch on?</translation>
    </message>
    <message>
        <source>OUT%1: %2</source>
        <translation>OUT%1: %2</translation>
    </message>
    <message>
        <source>the profile uses no output</source>
        <translation>the profile uses no output</translation>
    </message>
    <message>
        <source>every axis the profile homes was homed</source>
        <translation>every axis the profile homes was homed</translation>
    </message>
    <message>
        <source>homing did not finish: %1</source>
        <translation>homing did not finish: %1</translation>
    </message>
    <message>
        <source>no error reported</source>
        <translation>no error reported</translation>
    </message>
    <message>
        <source>the driver could not connect: %1</source>
        <translation>the driver could not connect: %1</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>no reply</translation>
    </message>
    <message>
        <source>skipped by the operator</source>
        <translation>skipped by the operator</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>port: %1
</source>
        <translation>port: %1
</translation>
    </message>
    <message>
        <source>identified as: %1
</source>
        <translation>identified as: %1
</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>firmware: %1
</source>
        <translation>firmware: %1
</translation>
    </message>
    <message>
        <source>(no answer)</source>
        <translation>(no answer)</translation>
    </message>
    <message>
        <source>unit number: %1
</source>
        <translation>unit number: %1
</translation>
    </message>
    <message>
        <source>profile: %1 (%2, firmware v%3)
</source>
        <translation>profile: %1 (%2, firmware v%3)
</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Steps</translation>
    </message>
    <message>
        <source> (moves)</source>
        <translation> (moves)</translation>
    </message>
    <message>
        <source>Protocol readings (docs/gve-protocol.md)</source>
        <translation>Protocol readings (docs/gve-protocol.md)</translation>
    </message>
    <message>
        <source>none checked
</source>
        <translation>none checked
</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Link</translation>
    </message>
    <message>
        <source>baud: %1
</source>
        <translation>baud: %1
</translation>
    </message>
    <message>
        <source>%1 %2: %3 samples, %4 bytes each, round trip min %5 ms, median %6 ms, max %7 ms
</source>
        <translation>%1 %2: %3 samples, %4 bytes each, round trip min %5 ms, median %6 ms, max %7 ms
</translation>
    </message>
    <message>
        <source>bytes/s in packets (both ways): %1
</source>
        <translation>bytes/s in packets (both ways): %1
</translation>
    </message>
    <message>
        <source>estimated adapter latency, one way: %1 ms
</source>
        <translation>estimated adapter latency, one way: %1 ms
</translation>
    </message>
    <message>
        <source>link.latencyMs: profile %1, proposed %2
</source>
        <translation>link.latencyMs: profile %1, proposed %2
</translation>
    </message>
    <message>
        <source>EEPROM (decoded, against the profile)</source>
        <translation>EEPROM (decoded, against the profile)</translation>
    </message>
    <message>
        <source>not read
</source>
        <translation>not read
</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>0x%1 %2: unit %3, profile %4 - %5
</source>
        <translation>0x%1 %2: unit %3, profile %4 - %5
</translation>
    </message>
    <message>
        <source>same</source>
        <translation>same</translation>
    </message>
    <message>
        <source>differs</source>
        <translation>differs</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation>Axes</translation>
    </message>
    <message>
        <source>no axis was moved
</source>
        <translation>no axis was moved
</translation>
    </message>
    <message>
        <source>%1: + %2, − %3, moved %4 mm each way, steps/mm %5</source>
        <translation>%1: + %2, − %3, moved %4 mm each way, steps/mm %5</translation>
    </message>
    <message>
        <source>, measured %1 mm</source>
        <translation>, measured %1 mm</translation>
    </message>
    <message>
        <source>, proposed steps/mm %1</source>
        <translation>, proposed steps/mm %1</translation>
    </message>
    <message>
        <source>Frezka commissioning report
===========================
</source>
        <translation>Frezka commissioning report
===========================
</translation>
    </message>
    <message>
        <source>Serial trace (docs/serial-trace.md)</source>
        <translation>Serial trace (docs/serial-trace.md)</translation>
    </message>
    <message>
        <source>not recorded
</source>
        <translation>not recorded
</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <source>the updated profile would replace %1; name a new file (--profile-out)</source>
        <translation>the updated profile would replace %1; name a new file (--profile-out)</translation>
    </message>
    <message>
        <source>%+ switches checksums on and its reply already carries one (0,5C)</source>
        <translation>%+ switches checksums on and its reply already carries one (0,5C)</translation>
    </message>
    <message>
        <source>a command with a wrong checksum is answered 4 and does not advance the index (@)</source>
        <translation>a command with a wrong checksum is answered 4 and does not advance the index (@)</translation>
    </message>
    <message>
        <source>every valid command advances the index by one, @ itself does not</source>
        <translation>every valid command advances the index by one, @ itself does not</translation>
    </message>
    <message>
        <source>&gt; repeats the last reply without executing the command again</source>
        <translation>&gt; repeats the last reply without executing the command again</translation>
    </message>
    <message>
        <source>an unknown command is answered 3</source>
        <translation>an unknown command is answered 3</translation>
    </message>
    <message>
        <source>a malformed parameter is answered 4</source>
        <translation>a malformed parameter is answered 4</translation>
    </message>
    <message>
        <source>a parameter out of range is answered 5 (T99)</source>
        <translation>a parameter out of range is answered 5 (T99)</translation>
    </message>
    <message>
        <source>a LF after the CR is ignored</source>
        <translation>a LF after the CR is ignored</translation>
    </message>
    <message>
        <source>a packet is answered once, at its end, with the number of commands (0,2)</source>
        <translation>a packet is answered once, at its end, with the number of commands (0,2)</translation>
    </message>
    <message>
        <source>a packet whose command fails stops there and answers that code and the number accepted before it (5,1)</source>
        <translation>a packet whose command fails stops there and answers that code and the number accepted before it (5,1)</translation>
    </message>
    <message>
        <source>a 4-axis unit takes L with three components (A = 0); fewer than three is answered 4</source>
        <translation>a 4-axis unit takes L with three components (A = 0); fewer than three is answered 4</translation>
    </message>
    <message>
        <source>a 3-axis unit answers 4 to a vector of four components or of two</source>
        <translation>a 3-axis unit answers 4 to a vector of four components or of two</translation>
    </message>
    <message>
        <source>ERaa reads an EEPROM byte as two hex digits</source>
        <translation>ERaa reads an EEPROM byte as two hex digits</translation>
    </message>
    <message>
        <source>float and 32-bit EEPROM values travel as decimal text</source>
        <translation>float and 32-bit EEPROM values travel as decimal text</translation>
    </message>
    <message>
        <source>the unit&apos;s firmware has no EFR/EUR</source>
        <translation>the unit&apos;s firmware has no EFR/EUR</translation>
    </message>
    <message>
        <source>needs motion or a reset; not checked here</source>
        <translation>needs motion or a reset; not checked here</translation>
    </message>
    <message>
        <source>the speed mode after a reset is VN</source>
        <translation>the speed mode after a reset is VN</translation>
    </message>
    <message>
        <source>VL limits are in pulses/s</source>
        <translation>VL limits are in pulses/s</translation>
    </message>
    <message>
        <source>a home switch not found within the travel is answered 5</source>
        <translation>a home switch not found within the travel is answered 5</translation>
    </message>
    <message>
        <source>the homing step shows it</source>
        <translation>the homing step shows it</translation>
    </message>
    <message>
        <source>%1 readings held, %2 did not hold, %3 not checked.</source>
        <translation>%1 readings held, %2 did not hold, %3 not checked.</translation>
    </message>
    <message>
        <source>Send the report (README: when a unit does something unexpected).</source>
        <translation>Send the report (README: when a unit does something unexpected).</translation>
    </message>
    <message>
        <source>The unit did not answer &apos;?&apos; (%1). Check the cable, the port and the baud rate set on the unit.</source>
        <translation>The unit did not answer &apos;?&apos; (%1). Check the cable, the port and the baud rate set on the unit.</translation>
    </message>
    <message>
        <source>the firmware &apos;%1&apos; names no known unit</source>
        <translation>the firmware &apos;%1&apos; names no known unit</translation>
    </message>
    <message>
        <source>the unit is a %1, the profile is for a %2</source>
        <translation>the unit is a %1, the profile is for a %2</translation>
    </message>
    <message>
        <source>the firmware is v%1, the profile says v%2 (unit.firmwareVersion)</source>
        <translation>the firmware is v%1, the profile says v%2 (unit.firmwareVersion)</translation>
    </message>
    <message>
        <source>Firmware &apos;%1&apos;, unit number &apos;%2&apos;.</source>
        <translation>Firmware &apos;%1&apos;, unit number &apos;%2&apos;.</translation>
    </message>
    <message>
        <source>. Correct the profile (unit.variant, unit.firmwareVersion) to the unit.</source>
        <translation>. Correct the profile (unit.variant, unit.firmwareVersion) to the unit.</translation>
    </message>
    <message>
        <source>status (F)</source>
        <translation>status (F)</translation>
    </message>
    <message>
        <source>position (PF/P4)</source>
        <translation>position (PF/P4)</translation>
    </message>
    <message>
        <source>EEPROM byte (ER)</source>
        <translation>EEPROM byte (ER)</translation>
    </message>
    <message>
        <source>packet of 10 B</source>
        <translation>packet of 10 B</translation>
    </message>
    <message>
        <source>The unit did not answer the timed commands.</source>
        <translation>The unit did not answer the timed commands.</translation>
    </message>
    <message>
        <source>Adapter latency about %1 ms each way; %2 bytes/s in packets; proposed link.latencyMs = %3 (the profile had %4).</source>
        <translation>Adapter latency about %1 ms each way; %2 bytes/s in packets; proposed link.latencyMs = %3 (the profile had %4).</translation>
    </message>
    <message>
        <source>The link is slower than the profile says: the planner would pace jobs for a faster line. Save the proposed profile.</source>
        <translation>The link is slower than the profile says: the planner would pace jobs for a faster line. Save the proposed profile.</translation>
    </message>
    <message>
        <source>not on this firmware</source>
        <translation>not on this firmware</translation>
    </message>
    <message>
        <source>%1 settings read, %2 differ from the profile, %3 could not be read.</source>
        <translation>%1 settings read, %2 differ from the profile, %3 could not be read.</translation>
    </message>
    <message>
        <source>Write the profile&apos;s values with Machine › Unit configuration (EEPROM), or correct the profile.</source>
        <translation>Write the profile&apos;s values with Machine › Unit configuration (EEPROM), or correct the profile.</translation>
    </message>
    <message>
        <source>The unit was not identified.</source>
        <translation>The unit was not identified.</translation>
    </message>
    <message>
        <source>The machine profile has no tool length sensor: set its position and probing in Machine › Settings (Tools › Tool length sensor), then measure again.</source>
        <translation>The machine profile has no tool length sensor: set its position and probing in Machine › Settings (Tools › Tool length sensor), then measure again.</translation>
    </message>
</context>
<context>
    <name>frezka::session::ConsoleSession</name>
    <message>
        <source>Manual G-code runs only while the machine is ready.</source>
        <translation>Manual G-code runs only while the machine is ready.</translation>
    </message>
    <message>
        <source>manual line</source>
        <translation>manual line</translation>
    </message>
    <message>
        <source>Manual: %1 (%2)</source>
        <translation>Manual: %1 (%2)</translation>
    </message>
</context>
<context>
    <name>frezka::session::HeightProbe</name>
    <message>
        <source>The area to probe is empty (X %1 to %2, Y %3 to %4): give its corners with X0 &lt; X1 and Y0 &lt; Y1.</source>
        <translation>The area to probe is empty (X %1 to %2, Y %3 to %4): give its corners with X0 &lt; X1 and Y0 &lt; Y1.</translation>
    </message>
    <message>
        <source>The spacing of the grid must be above 0 mm (%1 given).</source>
        <translation>The spacing of the grid must be above 0 mm (%1 given).</translation>
    </message>
    <message>
        <source>The probing feed must be above 0 mm/min (%1 given).</source>
        <translation>The probing feed must be above 0 mm/min (%1 given).</translation>
    </message>
    <message>
        <source>The probe&apos;s lowest Z (%1) must be below the clearance height (%2): give a depth above 0 mm.</source>
        <translation>The probe&apos;s lowest Z (%1) must be below the clearance height (%2): give a depth above 0 mm.</translation>
    </message>
    <message>
        <source>A spacing of %1 mm gives %2 x %3 points to probe (at most %4): choose a larger spacing or a smaller area.</source>
        <translation>A spacing of %1 mm gives %2 x %3 points to probe (at most %4): choose a larger spacing or a smaller area.</translation>
    </message>
    <message>
        <source>Probing is already running.</source>
        <translation>Probing is already running.</translation>
    </message>
    <message>
        <source>The machine is not ready to probe (%1): connect it and wait until it is idle, then probe again.</source>
        <translation>The machine is not ready to probe (%1): connect it and wait until it is idle, then probe again.</translation>
    </message>
    <message>
        <source>Probing cancelled after %1 of %2 points; the tool goes up to the clearance.</source>
        <translation>Probing cancelled after %1 of %2 points; the tool goes up to the clearance.</translation>
    </message>
    <message>
        <source>X %1, Y %2</source>
        <translation>X %1, Y %2</translation>
    </message>
    <message>
        <source>probing</source>
        <translation>probing</translation>
    </message>
    <message>
        <source>The move to probe at %1 cannot be planned: %2</source>
        <translation>The move to probe at %1 cannot be planned: %2</translation>
    </message>
    <message>
        <source>The link to the machine was lost while probing at %1: probe the grid again once it is connected.</source>
        <translation>The link to the machine was lost while probing at %1: probe the grid again once it is connected.</translation>
    </message>
    <message>
        <source>The probe at %1 went down to Z %2 without touching the surface: the work is lower than the depth allows, or the probe is not connected. Check the probe and the clearance, or probe again with a larger depth.</source>
        <translation>The probe at %1 went down to Z %2 without touching the surface: the work is lower than the depth allows, or the probe is not connected. Check the probe and the clearance, or probe again with a larger depth.</translation>
    </message>
    <message>
        <source>The probe at %1 was already in contact before moving down: check the probe and its wiring, and that the tool is clear of the work.</source>
        <translation>The probe at %1 was already in contact before moving down: check the probe and its wiring, and that the tool is clear of the work.</translation>
    </message>
    <message>
        <source>Probing at %1 stopped: %2</source>
        <translation>Probing at %1 stopped: %2</translation>
    </message>
    <message>
        <source>the job did not finish.</source>
        <translation>the job did not finish.</translation>
    </message>
    <message>
        <source>Probing fast then slow needs a retract above 0 mm (%1 given): the tool backs off by it before the slow probe.</source>
        <translation>Probing fast then slow needs a retract above 0 mm (%1 given): the tool backs off by it before the slow probe.</translation>
    </message>
    <message>
        <source>An edge is probed along X or Y, in the + or - direction.</source>
        <translation>An edge is probed along X or Y, in the + or - direction.</translation>
    </message>
    <message>
        <source>The probe&apos;s travel toward the edge must be above 0 mm (%1 given).</source>
        <translation>The probe&apos;s travel toward the edge must be above 0 mm (%1 given).</translation>
    </message>
    <message>
        <source>The probe moved from %1 %2 to %1 %3 without touching the edge: the edge is farther than the travel, or the probe is not connected. Check the probe and where the tool stands (beside the edge, below the work&apos;s top), or probe again with a longer travel.</source>
        <translation>The probe moved from %1 %2 to %1 %3 without touching the edge: the edge is farther than the travel, or the probe is not connected. Check the probe and where the tool stands (beside the edge, below the work&apos;s top), or probe again with a longer travel.</translation>
    </message>
    <message>
        <source>The spindle is turning: stop it (M5 or the spindle button) before probing. A probe or a sensor touched by a turning tool breaks one of them.</source>
        <translation>The spindle is turning: stop it (M5 or the spindle button) before probing. A probe or a sensor touched by a turning tool breaks one of them.</translation>
    </message>
</context>
<context>
    <name>frezka::session::ProgramSession</name>
    <message>
        <source>Reading</source>
        <translation>Reading</translation>
    </message>
    <message>
        <source>Indexing lines</source>
        <translation>Indexing lines</translation>
    </message>
    <message>
        <source>Interpreting</source>
        <translation>Interpreting</translation>
    </message>
    <message>
        <source>Preparing the view</source>
        <translation>Preparing the view</translation>
    </message>
    <message>
        <source>Planning</source>
        <translation>Planning</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>Cannot open %1: %2</translation>
    </message>
    <message>
        <source>Line %1: after this line the path depends on the probe&apos;s result; it is shown as provisional, and each part is planned and run once the probe before it has run.</source>
        <translation>Line %1: after this line the path depends on the probe&apos;s result; it is shown as provisional, and each part is planned and run once the probe before it has run.</translation>
    </message>
</context>
<context>
    <name>frezka::session::RunWorkflow</name>
    <message>
        <source>Not connected</source>
        <translation>Not connected</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Connecting…</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Ready</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Homing</translation>
    </message>
    <message>
        <source>Jogging</source>
        <translation>Jogging</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Running</translation>
    </message>
    <message>
        <source>Stopping</source>
        <translation>Stopping</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Paused</translation>
    </message>
    <message>
        <source>Tool lifted</source>
        <translation>Tool lifted</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Link lost</translation>
    </message>
    <message>
        <source>Connecting to %1 at %2 Bd…</source>
        <translation>Connecting to %1 at %2 Bd…</translation>
    </message>
    <message>
        <source>the built-in emulator</source>
        <translation>the built-in emulator</translation>
    </message>
    <message>
        <source>Open a program first.</source>
        <translation>Open a program first.</translation>
    </message>
    <message>
        <source>The program has errors and cannot run:
%1</source>
        <translation>The program has errors and cannot run:
%1</translation>
    </message>
    <message>
        <source>The machine is not ready (%1); wait until it is, then Run.</source>
        <translation>The machine is not ready (%1); wait until it is, then Run.</translation>
    </message>
    <message>
        <source>Planning from the current position…</source>
        <translation>Planning from the current position…</translation>
    </message>
    <message>
        <source>Running %1.</source>
        <translation>Running %1.</translation>
    </message>
    <message>
        <source>the machine stopped: %1</source>
        <translation>the machine stopped: %1</translation>
    </message>
    <message>
        <source>the job stopped: %1</source>
        <translation>the job stopped: %1</translation>
    </message>
    <message>
        <source>homing did not finish</source>
        <translation>homing did not finish</translation>
    </message>
    <message>
        <source> [command %1]</source>
        <translation> [command %1]</translation>
    </message>
    <message>
        <source> [reply &apos;%1&apos;]</source>
        <translation> [reply &apos;%1&apos;]</translation>
    </message>
    <message>
        <source>the job did not finish</source>
        <translation>the job did not finish</translation>
    </message>
    <message>
        <source>The machine is not homed: home it first, then Run.</source>
        <translation>The machine is not homed: home it first, then Run.</translation>
    </message>
    <message>
        <source>Warning: the machine is not homed; the program runs from counters that were not set by homing (motion.runBeforeHoming).</source>
        <translation>Warning: the machine is not homed; the program runs from counters that were not set by homing (motion.runBeforeHoming).</translation>
    </message>
    <message>
        <source>Homing, then running the program…</source>
        <translation>Homing, then running the program…</translation>
    </message>
    <message>
        <source>Homing did not finish; the program was not started.</source>
        <translation>Homing did not finish; the program was not started.</translation>
    </message>
    <message>
        <source>START button: resuming the job.</source>
        <translation>START button: resuming the job.</translation>
    </message>
    <message>
        <source>START button: running %1.</source>
        <translation>START button: running %1.</translation>
    </message>
    <message>
        <source>START button ignored: nothing to start or resume (%1).</source>
        <translation>START button ignored: nothing to start or resume (%1).</translation>
    </message>
    <message>
        <source>%1: continuing without an operator.</source>
        <translation>%1: continuing without an operator.</translation>
    </message>
    <message>
        <source>Line %1: the probe touched at X %2 Y %3 Z %4 (machine); the rest of the program runs as interpreted with that result.</source>
        <translation>Line %1: the probe touched at X %2 Y %3 Z %4 (machine); the rest of the program runs as interpreted with that result.</translation>
    </message>
    <message>
        <source>Line %1: the probe stopped at X %2 Y %3 Z %4 (machine) without touching; the rest of the program runs as interpreted with that result.</source>
        <translation>Line %1: the probe stopped at X %2 Y %3 Z %4 (machine) without touching; the rest of the program runs as interpreted with that result.</translation>
    </message>
</context>
<context>
    <name>gve-emu</name>
    <message>
        <source>cannot create a pipe</source>
        <translation>cannot create a pipe</translation>
    </message>
    <message>
        <source>cannot create the link %1</source>
        <translation>cannot create the link %1</translation>
    </message>
    <message>
        <source>cannot create the pseudo-terminal (%1): %2</source>
        <translation>cannot create the pseudo-terminal (%1): %2</translation>
    </message>
    <message>
        <source>cannot read the trace %1: %2</source>
        <translation>cannot read the trace %1: %2</translation>
    </message>
    <message>
        <source>the trace was played to its end; further commands get no reply</source>
        <translation>the trace was played to its end; further commands get no reply</translation>
    </message>
    <message>
        <source>the wheel does nothing: the MPG is off (Y-), not enabled in the EEPROM (0x06 and its parameters) or an interrupt waits for G</source>
        <translation>the wheel does nothing: the MPG is off (Y-), not enabled in the EEPROM (0x06 and its parameters) or an interrupt waits for G</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Frezka: runs CNC mills through GVE interpolators.</source>
        <translation>Frezka: runs CNC mills through GVE interpolators.</translation>
    </message>
    <message>
        <source>Draw the toolpath without OpenGL.</source>
        <translation>Draw the toolpath without OpenGL.</translation>
    </message>
    <message>
        <source>Save the window as PNG once the program has loaded, then quit (README screenshots).</source>
        <translation>Save the window as PNG once the program has loaded, then quit (README screenshots).</translation>
    </message>
    <message>
        <source>G-code program to open.</source>
        <translation>G-code program to open.</translation>
    </message>
    <message>
        <source>User interface language: cs or en (default: the settings, else the system language).</source>
        <translation>User interface language: cs or en (default: the settings, else the system language).</translation>
    </message>
    <message>
        <source>With --screenshot: home, run the program and take the screenshot after this many seconds of running.</source>
        <translation>With --screenshot: home, run the program and take the screenshot after this many seconds of running.</translation>
    </message>
    <message>
        <source>With --screenshot: show this dock in front of the others (its object name, such as unitsDock).</source>
        <translation>With --screenshot: show this dock in front of the others (its object name, such as unitsDock).</translation>
    </message>
    <message>
        <source>Apply this height map file to the program (as Machine › Height map › Apply, the work zero left as it is).</source>
        <translation>Apply this height map file to the program (as Machine › Height map › Apply, the work zero left as it is).</translation>
    </message>
    <message>
        <source>real (default): the machine in real time; virtual: the built-in emulator on a virtual clock, as fast as the computer allows (a port is refused).</source>
        <translation>real (default): the machine in real time; virtual: the built-in emulator on a virtual clock, as fast as the computer allows (a port is refused).</translation>
    </message>
    <message>
        <source>--clock takes real or virtual, not &quot;%1&quot;.</source>
        <translation>--clock takes real or virtual, not &quot;%1&quot;.</translation>
    </message>
</context>
</TS>
