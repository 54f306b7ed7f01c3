#pragma once
// What corbel-cli and the editor share in their CLI11 command lines: the --version text, the
// option kinds both use (sizes WxH, bounded numbers, one of a few words, repeatable values) and
// the parse that maps CLI11's outcomes to the exit codes (0 help or version, 2 bad command line).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace corbel {

// "corbel-cli 0.1.0 (project format 1)".
std::string versionText(const std::string& program);

// --version on `command` (CLI11 does not hand it down to subcommands).
void addVersionFlag(CLI::App& command, const std::string& program);

// A window or image size; `given` tells whether the command line named it.
struct Size {
  int width = 0, height = 0;
  bool given = false;
};

// Option `name` reading WxH with whole sides in [lo, hi] into `size` (its values on entry are
// the default shown).
CLI::Option* addSize(CLI::App& command, const std::string& name, Size& size, int lo, int hi,
                     const std::string& description);

// A finite number in [lo, hi] ("nan" and "1e999" are refused, unlike CLI::Range).
CLI::Validator numberIn(double lo, double hi);
// A whole number in [lo, hi].
CLI::Validator wholeIn(long long lo, long long hi);
// One of `words` ("expected on or off, not 'yes'"). `hidden` are accepted but not shown.
CLI::Validator oneOf(const std::vector<std::string>& words, const std::vector<std::string>& hidden = {});
// "on|off": the type name of an option that takes one of `words`.
std::string choices(const std::vector<std::string>& words);

// An option that may repeat and takes exactly one value each time, so a following positional is
// never read as one of its values: --set A=1 --set B=2.
CLI::Option* addRepeated(CLI::App& command, const std::string& name, std::vector<std::string>& values,
                         const std::string& description);

// Parses the command line into the options declared on `app` (named `program`). Returns -1 when
// the program should go on; else it has printed help or the version (stdout, 0) or the fault
// ("PROGRAM: SUBCOMMAND: message" and where to find the usage, stderr, 2) and returns the code.
int parseCommandLine(CLI::App& app, int argc, const char* const* argv);

// The subcommand the command line chose: the deepest one parsed (`app` itself if none).
const CLI::App& chosenCommand(const CLI::App& app);

}  // namespace corbel
