#pragma once
// Runs corbel-cli (CORBEL_CLI) from the unit tests, capturing its exit code, stdout and stderr.
#include "test_support.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace corbel::test {

// `s` in single quotes for the shell.
inline std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct CliRun {
  int code = -1;
  std::string out, err;
};

// Runs corbel-cli with `args` (already quoted where needed); its output goes through files in `dir`.
inline CliRun cli(const TempDir& dir, const std::string& args) {
  const std::string outPath = dir.file(".stdout"), errPath = dir.file(".stderr");
  const std::string command = quote(CORBEL_CLI) + " " + args + " >" + quote(outPath) + " 2>" + quote(errPath);
  const int status = std::system(command.c_str());
  CliRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(outPath);
  r.err = readText(errPath);
  std::remove(outPath.c_str());
  std::remove(errPath.c_str());
  return r;
}

}  // namespace corbel::test
