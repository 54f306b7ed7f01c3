#pragma once
// The CLI's exit-code convention in one place: a command's body runs, a command-line fault it
// finds itself (UsageError: a range, a combination, a malformed list) prints its message and
// gives 2, any other error prints "error: …" and gives 1. CLI11's own faults are reported by
// core/command_line.h before any body runs, with the same code.
#include "core/error.h"

#include <exception>
#include <iostream>

namespace corbel::cli {

struct UsageError : Error {
  using Error::Error;
};

template <class Body>
int guarded(Body&& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    std::cerr << "corbel-cli: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "corbel-cli: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace corbel::cli
