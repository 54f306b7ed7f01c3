// libFuzzer entry point for the project loader (clang, -DCORBEL_LIBFUZZER=ON). The invariant
// is the one of loader_fuzz_test.cpp: an input either loads into a Document that
// re-serialises and re-parses to an equal Document, or is refused with a corbel::InputError
// that has a reason. Any other exception escapes and libFuzzer reports it as a crash.
#include "core/error.h"
#include "core/project_io.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  corbel::LoadedProject p;
  try {
    p = corbel::parseProject(text);
  } catch (const corbel::InputError& e) {
    if (e.reason.empty()) {
      std::fprintf(stderr, "InputError without a reason (where: %s)\n", e.where.c_str());
      std::abort();
    }
    return 0;
  }
  const std::string serialised = corbel::serializeProject(p.document);
  corbel::LoadedProject again;
  try {
    again = corbel::parseProject(serialised);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accepted input does not re-parse: %s\n%s\n", e.what(), serialised.c_str());
    std::abort();
  }
  if (!(again.document == p.document) || corbel::serializeProject(again.document) != serialised ||
      !again.warnings.empty()) {
    std::fprintf(stderr, "round trip changed the document:\n%s\n", serialised.c_str());
    std::abort();
  }
  return 0;
}
