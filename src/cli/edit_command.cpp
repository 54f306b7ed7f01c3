// corbel-cli edit: an edit script applied to a project without a window, line by line as the
// editor applies --script lines, then saved atomically; a bad line writes nothing.
#include "cli/guarded.h"
#include "cli/run.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/project_io.h"
#include "extrude/edit.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <sstream>

namespace corbel::cli {

int run(const EditRequest& r) {
  if (r.out.size() < 7 || r.out.compare(r.out.size() - 7, 7, ".corbel") != 0)
    throw UsageError("--out: expected a .corbel file, got '" + r.out + "'");
  LoadedProject project = loadProject(r.project);
  for (const auto& w : project.warnings) std::cerr << "corbel-cli: warning: " << r.project << ": " << w << "\n";
  Document doc = std::move(project.document);
  std::istringstream script(readFile(r.script, kMaxProjectBytes));
  std::size_t lineNo = 0, edits = 0;
  std::vector<std::string> notes;
  for (std::string line; std::getline(script, line);) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string at = r.script + ":" + std::to_string(lineNo);
    nlohmann::json op;
    try {
      op = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(at, std::string("not valid JSON: ") + e.what());
    }
    std::vector<std::string> removed;
    try {
      extrude::edit::applyEdit(doc, op, &removed);
    } catch (const InputError& e) {
      throw InputError(at + (e.where.empty() ? "" : ": " + e.where), e.reason);
    } catch (const std::exception& e) {  // a field of the wrong type, say
      throw InputError(at, e.what());
    }
    for (const std::string& n : removed) {
      std::cerr << "corbel-cli: " << at << ": " << n << "\n";
      notes.push_back(at + ": " + n);
    }
    ++edits;
  }
  saveProject(doc, r.out);
  nlohmann::ordered_json j;
  j["edits"] = edits;
  j["objects"] = doc.objects.size();
  j["removed"] = notes;
  j["out"] = r.out;
  std::cout << j.dump() << "\n";
  return 0;
}

}  // namespace corbel::cli
