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
    <name>frezka::gcode</name>
    <message>
        <source>Cannot read the file %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check that the file exists and is readable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unexpected character &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove it or put it inside a comment ( ).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment is not closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add &apos;)&apos; at the end of the comment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment inside a comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the first comment before opening another one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A number is expected after %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write a number, a #parameter or an [expression] after the letter.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use an integer value here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Word %1 appears twice in one block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep one of them or split the block into two lines.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Word %1 is not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the word; Frezka does not use it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis %1 is not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frezka machines have the axes X, Y, Z and A.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file ended without M2, M30 or %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End the program with M2 or M30 (or enclose it in % lines).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program starts with % but has no closing %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a line with % at the end of the program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line is too long (%1 characters)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Split the line; at most 65535 characters are allowed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown G code %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the number; see the list of supported codes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove it or post-process the program without it (see the supported codes).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown M code %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 conflicts with another code of the same group in this block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use one code of each modal group per block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Too many M codes in one block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use at most four M codes per block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Word %1 is not used by any code in this block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the word or add the code that uses it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis words are given with G80</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G80 cancels the motion mode; give the axis words with G0 or G1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis words are given but no motion mode is active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add G0, G1, G2 or G3 to the block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 and a motion code both use the axis words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put them on separate lines.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs at least one axis word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the axis words (X, Y, Z or A).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 must not be negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use zero or a positive value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G53 needs G0 or G1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write G53 together with G0 or G1 on the same line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G53 cannot be used in G91 mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch to G90 before moving in machine coordinates.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G4 needs the dwell time P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add P with the dwell time in seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G10 %1 is not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use G10 L2 or G10 L20 to set a work offset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G10 needs P0 to P9 (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P0 is the active coordinate system, P1 to P9 are G54 to G59.3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coordinate system rotation (G10 R) is not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the R word.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 with zero feed rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set a feed rate with F before the first feed move.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 in inverse time mode (G93) needs an F word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give F on every feed move in G93, or switch to G94.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc without I, J, K or R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the centre with I/J/K or the radius with R.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc with both R and I/J/K</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use either the centre (I/J/K) or the radius (R).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not in the arc&apos;s plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G17 uses I and J, G18 uses I and K, G19 uses J and K.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is missing for an arc with absolute centre (G90.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give both centre coordinates in G90.1 mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc with zero radius %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the centre offsets I/J/K.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc end point is not on the circle: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the end point and the centre; the radii to start and end must match.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc radius is too small to reach the end point %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use a radius of at least half the distance between start and end.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc given by R ends where it starts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use I/J/K to program a full circle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc given by R has no end point in its plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the end point, or use I/J/K for a full circle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc turns P must be a positive integer (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use P1 or more, or leave P out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe move does not move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give an end point different from the current position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe move in inverse time mode (G93)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch to G94 before probing.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle %1 needs R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the retract plane R on the first block of the cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle %1 needs its depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the hole depth (Z in G17) on the first block of the cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle retract plane R is below the hole depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R must be above the bottom of the hole.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle %1 needs the dwell P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give P (seconds) on the first block of the cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle %1 needs the peck Q</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give Q (peck depth) on the first block of the cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peck depth Q must be positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use a positive Q.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle repeat L must be a positive integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use L1 or more, or leave L out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Canned cycle in inverse time mode (G93)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch to G94 before a canned cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expression is not closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the missing &apos;]&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown operator %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown function %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>See the list of functions (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, SIN, SQRT, TAN, EXISTS).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Division by zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the divisor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of a value outside its domain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the argument (e.g. SQRT of a negative number).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Negative number raised to a non-integer power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the operands of **.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter number %1 is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use parameters #1 to #5601.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter %1 is not defined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Assign it a value before reading it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter %1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System parameters are set by codes (e.g. G10 L2, G92), not by assignment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bad parameter name %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write named parameters as #&lt;name&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An expression is expected %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the value in brackets, e.g. [#1 + 2].</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Malformed O word %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write O-words as o100 if [...] or o&lt;name&gt; sub.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown O-word keyword %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, break or continue.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An O-word line has other words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put the other words on their own line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 without its opening O-word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the O numbers; they must match the opening line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is never closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the matching end line (endsub, endif, endwhile, endrepeat or while).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subroutine %1 is not defined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Define the subroutine before calling it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subroutine calls nested too deeply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check for unbounded recursion.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 outside a loop with this O number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use break and continue only inside their own loop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 outside a subroutine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use return and endsub only inside a subroutine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program executes more than %1 blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the loops; one of them may never end.</source>
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
    <name>frezka::gui</name>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>laser</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coolant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>air blow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machine cover lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool release</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tool cover open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>brake</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interrupt signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower limit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper limit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps per mm %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing speed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Relay function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT1 function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT2 function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT3 function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PWM mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STEP/DIR polarity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that starts homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interrupt enable IN0-7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interrupt enable IN14/IN15</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input polarity IN0-7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input polarity IN14/IN15</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A axis coupling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel maximum speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel brake delay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default spindle speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel step multiplier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brake release delay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 steps/mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>homing off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>standard PWM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>breakout-board signal (jumper ANA/PWM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown (0x%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STEP inverted: %1; DIR inverted: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DIR inverted: %1; STEP on %2 edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>falling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rising</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on, within the limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on, 4th position drives rotary A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on with limits, 4th position drives rotary A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IN%1 held &gt; 1 s starts homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enabled: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>active high: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slaved to X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slaved to Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slaved to Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>independent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>921 600 / 460 800 / 230 400 / 115 200 Bd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>19 200 / 38 400 / 57 600 / 115 200 Bd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>×%1 (x1 = %2 mm)</source>
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
    <message>
        <source>Profile name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum pulse rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Firmware version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checksums</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Packets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Commands per packet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps per mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invert direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Soft limit min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Soft limit max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapid speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum speed jump at a corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Order (0 = not homed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction to the switch (-1/+1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum search travel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed toward the switch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed off the switch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum back-off travel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position after homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc chord tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause between stand-alone moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool lift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spin-up wait</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT1 function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT2 function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT3 function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output switched by M7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with the unit on connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel (MPG)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel maximum speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel brake delay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handwheel step multiplier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input that starts homing (0 = off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interrupt enable IN0-7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interrupt enable IN14/IN15</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polarity IN0-7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polarity IN14/IN15</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A axis slaved to (0 none, 1 X, 2 Y, 3 Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PWM for breakout boards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invert STEP polarity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default spindle speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brake release delay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Path speed (VK)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Major axis speed (VN)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Laser</source>
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
        <source>Machine cover lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool release</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool cover open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brake</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interrupt signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On, within the limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On, 4th position drives rotary A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On with limits, 4th position drives rotary A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GVE84</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GVE64</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GVE64 PHANTOM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GVE114</source>
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
    <name>frezka::gui::UnitConfigDialog</name>
    <message>
        <source>No reply to %1 within 5 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the unit&apos;s EEPROM…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The unit already matches the profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the unit first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Writing %n setting(s) and reading them back…</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The unit refused %1 (reply %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read the value in the reply to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read-back of %1 gives %2, not the %3 written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The unit matches the profile (%n setting(s) compared).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ from the profile.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Unit configuration (EEPROM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Meaning (unit value)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read from unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write differences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
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
