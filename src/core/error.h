#pragma once
// Errors a user can act on. Kernels and loaders throw these (or return them); the CLI prints
// what() and exits non-zero, the editor shows it and keeps the current document.
#include <stdexcept>
#include <string>

namespace corbel {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An input file's fault: `where` is a JSON path like "objects[2].box.size[1]" (empty for
// faults of the file as a whole), `reason` says what is wrong there.
struct InputError : Error {
  InputError(std::string where_, std::string reason_)
      : Error(where_.empty() ? reason_ : where_ + ": " + reason_), where(std::move(where_)), reason(std::move(reason_)) {}
  std::string where;
  std::string reason;
};

}  // namespace corbel
