#pragma once
// corbel-cli kifs: renders a KIFS building preset headless (docs/kifs.md).

namespace corbel::cli {

// argv[1] is "kifs". Returns the exit code (0, 1 bad input, 2 bad command line) and reports
// errors on stderr itself.
int kifsCommand(int argc, char** argv);

// The usage lines of the command, for corbel-cli --help.
extern const char* const kKifsUsage;

}  // namespace corbel::cli
