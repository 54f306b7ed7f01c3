#pragma once
// corbel-cli extrude from the extrusion tests: the first JSON line of --stats.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

namespace corbel::extrude::test {

// Runs `corbel-cli extrude SOURCE_DIR/RELATIVE --stats EXTRA` and parses its first line (the
// first building's record).
inline nlohmann::json cliExtrudeStats(const std::string& relative, const std::string& extra) {
  const std::string cmd = std::string(CORBEL_CLI) + " extrude " + CORBEL_SOURCE_DIR + "/" + relative + " --stats" + extra;
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (p && std::fgets(buf, sizeof buf, p)) out += buf;
  if (p) pclose(p);
  return nlohmann::json::parse(out.substr(0, out.find('\n')));
}

}  // namespace corbel::extrude::test
