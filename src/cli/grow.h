#pragma once
// corbel-cli grow: runs the growth kernel on a site file (docs/growth.md).

namespace corbel::cli {

// argv[1] is "grow". Returns the exit code (0 ok, 1 bad input, 2 bad command line); input
// faults are thrown as corbel::Error for main to report.
int grow(int argc, char** argv);

}  // namespace corbel::cli
