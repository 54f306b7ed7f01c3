#include "core/app_state.h"

#include "core/atomic_file.h"
#include "core/json_reader.h"
#include "core/project_io.h"

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <filesystem>

namespace corbel {

namespace fs = std::filesystem;

std::string defaultStateDir() {
  if (const char* d = std::getenv("CORBEL_STATE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return std::string(x) + "/corbel";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.local/state/corbel";
  return ".corbel-state";
}

Recovery::Recovery(std::string dir) : dir_(std::move(dir)) {}

std::string Recovery::documentPath() const { return dir_ + "/recovery.corbel"; }

void Recovery::write(const Document& doc, const std::string& originalPath) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  const std::time_t now = std::time(nullptr);
  char stamp[64] = {};
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  nlohmann::json meta = {{"original", originalPath}, {"saved_at", stamp}};
  // Document first, then the note that points at it: a crash between the two leaves an older
  // note, never a note without its document.
  saveProject(doc, documentPath());
  writeFileAtomic(dir_ + "/recovery.json", meta.dump(2, ' ', false, nlohmann::json::error_handler_t::replace));
}

std::optional<RecoveredWork> Recovery::find(std::string* problem) const {
  std::error_code ec;
  if (!fs::exists(documentPath(), ec)) return std::nullopt;
  try {
    RecoveredWork w;
    w.document = loadProject(documentPath()).document;
    try {
      const nlohmann::json meta = parseJsonText(readFile(dir_ + "/recovery.json", 1 << 20));
      JsonReader r(meta, "recovery.json");
      w.originalPath = r.at("original").string(4096);
      w.savedAt = r.at("saved_at").string(64);
    } catch (const Error&) {
      // The document alone is still worth offering.
    }
    return w;
  } catch (const Error& e) {
    if (problem) *problem = e.what();
    return std::nullopt;
  }
}

void Recovery::discard() {
  std::error_code ec;
  fs::remove(documentPath(), ec);
  fs::remove(dir_ + "/recovery.json", ec);
}

RecentFiles::RecentFiles(std::string file, std::size_t capacity) : file_(std::move(file)), capacity_(capacity) {
  try {
    const nlohmann::json j = parseJsonText(readFile(file_, 1 << 20));
    if (j.is_array())
      for (const auto& p : j)
        if (p.is_string() && paths_.size() < capacity_) paths_.push_back(p.get<std::string>());
  } catch (const Error&) {
    // No list yet, or a damaged one: start empty.
  }
}

void RecentFiles::add(const std::string& path) {
  std::error_code ec;
  const std::string abs = fs::absolute(path, ec).lexically_normal().string();
  remove(abs);
  paths_.insert(paths_.begin(), abs);
  if (paths_.size() > capacity_) paths_.resize(capacity_);
  save();
}

void RecentFiles::remove(const std::string& path) {
  paths_.erase(std::remove(paths_.begin(), paths_.end(), path), paths_.end());
  save();
}

void RecentFiles::save() const {
  try {
    std::error_code ec;
    fs::create_directories(fs::path(file_).parent_path(), ec);
    writeFileAtomic(file_, nlohmann::json(paths_).dump(2, ' ', false, nlohmann::json::error_handler_t::replace));
  } catch (const Error&) {
    // A read-only home must not stop the editor; the list is a convenience.
  }
}

}  // namespace corbel
