#pragma once
// The program of the run-from-line tests (session, frezka-cli, GUI): a tool change, a work
// offset (G55 set by G10 L2), the spindle, coolant and G91 are all in force before line 18, the
// line the tests run from (G1 Y10 in G91, tool 2, S12000 M3, M8, F800, G55).

namespace frezka::test {

inline constexpr int kRunFromLine = 18;

inline constexpr char kRunFromLineProgram[] =
    "(run from line: tool change, work offset and G91 before line 18)\n" // 1
    "G21 G90 G17 G94\n"                                                  // 2
    "G10 L2 P2 X40 Y30 Z-60\n"                                           // 3
    "G55\n"                                                              // 4
    "T1 M6\n"                                                            // 5
    "S10000 M3\n"                                                        // 6
    "G0 X0 Y0 Z5\n"                                                      // 7
    "G1 Z-1 F300\n"                                                      // 8
    "G1 X20 F900\n"                                                      // 9
    "G0 Z5\n"                                                            // 10
    "T2 M6\n"                                                            // 11
    "S12000 M3\n"                                                        // 12
    "M8\n"                                                               // 13
    "G91\n"                                                              // 14
    "G0 X10 Y5\n"                                                        // 15
    "G1 Z-7 F400\n"                                                      // 16
    "G1 X15 F800\n"                                                      // 17
    "G1 Y10\n"                                                           // 18
    "G1 X-15\n"                                                          // 19
    "G90\n"                                                              // 20
    "G0 Z5\n"                                                            // 21
    "M5 M9\n"                                                            // 22
    "M2\n";                                                              // 23

} // namespace frezka::test
