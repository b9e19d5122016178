#pragma once

// The restart test program the collision tests of the core and the panel
// share (D-021): a slot 4 deep along Y30 from X20 to X80 with T2 (R5) in the
// demo mill's part (X0..100 Y0..60 Z-12..0 at G54); the target N0050 turns
// it towards +Y. tests/cli/cli_restart_collisions.sh writes the same blocks.
namespace mtc::test {

inline constexpr const char* kSlotRestartProgram =
    "N0010 : T2 S1500 M3\n"
    "N0020 G0 G54 X20 Y30 Z2\n"
    "N0030 G1 Z-4 F200\n"
    "N0040 X80\n"
    "N0050 X80 Y45 ;target\n"
    "N0060 G0 Z10\n"
    "N0070 M30\n";

}  // namespace mtc::test
