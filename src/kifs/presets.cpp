// Presets reproducing the looks of McGraw's figures (docs/kifs.md, "Presets"): one file each,
// assets/kifs/NAME.json, holding a KIFS spec in the project file's format (core/kifs_json.h).
#include "core/assets.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "core/kifs_json.h"
#include "kifs/kernel.h"
#include "kifs/params.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace corbel::kifs {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxPresetBytes = 1u << 20;

// A preset's name is its file's stem: letters, digits, '-' and '_', so a name cannot leave
// the folder.
bool plainName(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

std::string readText(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw Error(file.string() + ": no such file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot read the preset file");
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  if (text.size() > kMaxPresetBytes) throw Error(file.string() + ": a preset file holds at most 1 MiB");
  return text;
}

}  // namespace

std::string presetDir() { return (fs::path(assetsDir()) / "kifs").string(); }

std::vector<std::string> presetNames() {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(presetDir(), ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json" && plainName(it->path().stem().string()))
      out.push_back(it->path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

KifsParams loadPreset(const std::string& file) {
  const std::string text = readText(file);
  try {
    // The root is named "kifs", so type faults and the kernel's value faults read alike:
    // "kifs.mass.shell: ...".
    const nlohmann::json json = parseJsonText(text);
    const JsonReader root(json, "kifs");
    std::vector<std::string> unknown;
    const KifsSpec spec = kifsFromJson(root, unknown);
    // In a preset an unknown key is a typo that would silently fall back to a default.
    if (!unknown.empty()) {
      const std::string& u = unknown.front();  // "kifs.mass.wings: unknown key kept"
      throw Error(u.substr(0, u.rfind(": ")) + ": unknown key (a preset may hold only the keys of a KIFS spec)");
    }
    return paramsOf(spec);
  } catch (const Error& e) {
    throw Error(file + ": " + e.what());
  }
}

KifsParams preset(const std::string& name) {
  const std::vector<std::string> names = presetNames();
  if (!plainName(name) || std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw Error("no KIFS preset named '" + name + "' in " + presetDir() + " (presets: " +
                (list.empty() ? "none" : list) + ")");
  }
  return loadPreset((fs::path(presetDir()) / (name + ".json")).string());
}

}  // namespace corbel::kifs
