#pragma once
// corbel-cli statics: the masonry-statics subcommands (arch, example).

namespace corbel::cli {

// argv[1] is "statics". Returns the exit code: 0 success, 1 bad input, 2 bad command line.
int runStatics(int argc, char** argv);

}  // namespace corbel::cli
