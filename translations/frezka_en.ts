<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>LinkWorker</name>
    <message>
        <source>connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no serial port given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the built-in emulator is not available yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SerialTransport</name>
    <message>
        <source>%1 at %2 Bd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot configure %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>write to %1: port not open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>short write to %1: %2 of %3 bytes (%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 (ignored)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::grinder::EmulatorTransport</name>
    <message>
        <source>The emulator is not open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>emulator</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::grinder::SerialTransport</name>
    <message>
        <source>Cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot set %1 to %2 Bd: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Short write on %1: %2 of %3 bytes queued (%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial port %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::grinder::TransferSession</name>
    <message>
        <source>The port %1 is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file is empty; there is nothing to send.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The data are too long for one message: %1 bytes, at most %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ANC program data have 21760 or 21766 bytes (0x5500 or 0x5506); the file has %1. Choose a file saved from an ANC control.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HEDIT data have 46 bytes (0x2E); the file has %1. Choose a file saved with HEDIT.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;- noise, %1 bytes skipped: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unexpected reply %1 to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller answered NAK to ENQ.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller answered NAK to %1: is it set to program transfer (KONFIG6) with the selector in PGN?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller answered NAK to %1 (%2 times): it did not accept the data.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;- %1 ignored: no reply expected now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bad checksum in %1 from the controller: received %2, computed %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 Given up after %2 repeats.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repeat %1 of %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No answer to ENQ within %1 s. Check the cable, the line settings (%2 Bd) and that the controller is set to transfer (KONFIG6).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The data message stopped after %1 of %2 bytes (no byte for %3 s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No data from the controller within %1 s after %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No ACK to %1 within %2 s after its last byte.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The final ACK could not be sent within %1 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Received %1 bytes, header &quot;%2&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent %1 bytes; the controller stored them.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::grinder::ZLinkSession</name>
    <message>
        <source>No answer to &quot;%1&quot; within %2 s. Is the controller set to Z-position transfer (KONFIG6 = 1) with the selector in PGN?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller rejected a character of &quot;%1&quot; (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unreadable reply &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::ConsoleWidget</name>
    <message>
        <source>Save log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text files (*.txt *.log)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save log…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code (e.g. G0 X10) or a raw unit command (e.g. !0PF), Enter sends</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::DroWidget</name>
    <message>
        <source>Work</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the work zero of %1 at the current position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the work zero of every axis at the current position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::HoldBanner</name>
    <message>
        <source>at line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine has stopped along its ramp and keeps the rest of the job. Continue, or lift the tool to change or clean it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program stop %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
Do what the program asks, then press Continue.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped by an input %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
Check the machine; when it is safe, Continue or Abort.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe failed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
The probe did not touch as expected. Abort the job or Continue.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool lifted %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change or clean the tool. Then lower it: the spindle starts again if it was stopped, the tool goes back down to where it was, and the job continues — at a new feed if you enter one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New feed (0 = unchanged):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lift tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower and continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower, stay paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort job</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::JogPanel</name>
    <message>
        <source>Home %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find the home switch of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home every axis in the order of the machine profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step (mm):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move while the button or key is held</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog feed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keyboard: arrows jog X/Y, Page Up/Page Down jog Z</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::MainWindow</name>
    <message>
        <source>About Frezka</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Frezka %1&lt;/b&gt;&lt;br&gt;Runs CNC mills through GVE interpolators.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frezka</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frezka — %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog and homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle and outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Console</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Settings…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Unit configuration (EEPROM)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Grinder transfer (ANC/K51)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Frezka</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.gcode *.tap *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 — %n line(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The program has %n error(s); nothing will run until they are fixed.
%1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Laser</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cover lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool release</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool cover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jogging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool lifted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program finished in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program finished.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing runs for all axes in the profile&apos;s order (the unit driver homes the whole machine).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No output of this machine is set up for that function; assign one in Settings › Machine profile › Outputs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Check passed: %n move(s), estimated time %1, within the soft limits.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Check passed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connecting to %1 at %2 Bd…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the built-in emulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The link to the unit was lost. The job position is kept: reconnect, then Resume.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit EEPROM differs from the profile: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The unit reported a problem: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reply: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program line: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a program first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program has errors and cannot run:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine is not ready (%1); wait until it is, then Run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Planning from the current position…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog refused: %1 would go to %2 mm, outside the soft limits %3 … %4 mm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the work zero while the machine is ready and still.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual G-code runs only while the machine is ready.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>manual line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::OutputsPanel</name>
    <message>
        <source>Spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch the spindle on or off at the speed on the right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Air blow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed override in percent of the programmed feed (XM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Raise every queued speed by 6.25 % (XU)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower every queued speed by 6.25 % (XD)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::Plan</name>
    <message>
        <source>the move leaves the machine&apos;s travel (soft limits); check the work zero and the program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the program moves an axis this machine does not have</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the position is beyond the unit&apos;s step counters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a feed move has no feed rate (F)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the spindle speed (S) is above the machine&apos;s maximum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the unit cannot do this</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1:%2: %3 (%4)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::Profile</name>
    <message>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be read or written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is not valid JSON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the value has the wrong type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown key (a typo?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the value is outside its range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the value is none of the allowed ones</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the value contradicts another setting or the unit type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine profile %1 cannot be used; the built-in GVE64 defaults are active until it is fixed:
%2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProfileEditor</name>
    <message>
        <source>&quot;emulator&quot; = the built-in unit emulator; or a serial port such as /dev/ttyUSB0; or a typed path such as the pty printed by gve-emu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>General</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The profile is valid.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) — the profile cannot be saved yet.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot load the profile %1:
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The profile has problems; fix them first:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot save the profile %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::ProgramSession</name>
    <message>
        <source>Reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Indexing lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interpreting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preparing the view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Planning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This build has no G-code interpreter; the program cannot be checked.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::RunPanel</name>
    <message>
        <source>Elapsed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remaining %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the program against the machine profile without moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brake along the ramp and hold; Resume continues</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the program; the position stays known</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop at once and drop every queued move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool lift…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lift the tool, switch the spindle off, change or clean it, continue</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::SettingsDialog</name>
    <message>
        <source>Export profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Defaults of the unit type loaded; Apply or Save to use them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loaded %1; Apply to use it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The profile has problems; fix the fields marked red first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied (not yet saved).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Application</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reconnect automatically after a lost link</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::SpeedPlot</name>
    <message>
        <source>mm/min along the path (%1 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm/min at %2 mm, line %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>frezka::gui::ToolpathView</name>
    <message>
        <source>Top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Iso</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the whole program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left drag: orbit · right/middle drag or Shift+left: pan · wheel: zoom</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Frezka: runs CNC mills through GVE interpolators.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw the toolpath without OpenGL.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the window as PNG once the program has loaded, then quit (README screenshots).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code program to open.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
