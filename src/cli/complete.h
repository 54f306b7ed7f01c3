#pragma once
// corbel-cli complete: the form completion engine (Ch. 7, docs/growth.md) from n seeds.

namespace corbel::cli {

// argv[1] is "complete". Returns the exit code (0 ok, 1 no form found, 2 bad command line).
int complete(int argc, char** argv);

}  // namespace corbel::cli
