#pragma once
// corbel-cli simulate: the collapse simulation of a masonry model (src/sim), with frames
// rendered through OSMesa and a JSON summary.

namespace corbel::cli {

extern const char* const kSimulateUsage;

// argv[1] is "simulate". Returns the exit code: 0 success, 1 bad input, 2 bad command line.
int runSimulate(int argc, char** argv);

}  // namespace corbel::cli
