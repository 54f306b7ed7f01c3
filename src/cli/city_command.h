#pragma once
// corbel-cli city: a styled town from footprints or a street (docs/city.md).

namespace corbel::cli {

// argv[1] is "city". Returns the exit code (0 every building built, 1 some reported and
// skipped, 2 bad command line); faults of the inputs are thrown as corbel::Error.
int city(int argc, char** argv);

}  // namespace corbel::cli
