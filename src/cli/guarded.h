#pragma once
// The CLI's exit-code convention in one place: a command's body runs, a command-line fault
// (the command's own usage-error type) prints its message and gives 2, any other error prints
// "error: …" and gives 1.
#include <exception>
#include <iostream>

namespace corbel::cli {

template <class UsageFault, class Body>
int guarded(Body&& body) {
  try {
    return body();
  } catch (const UsageFault& e) {
    std::cerr << "corbel-cli: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "corbel-cli: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace corbel::cli
