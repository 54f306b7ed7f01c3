#include "core/app_state.h"

#include "core/atomic_file.h"
#include "core/json_reader.h"
#include "core/project_io.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace corbel {

namespace fs = std::filesystem;

std::string defaultStateDir() {
  if (const char* d = std::getenv("CORBEL_STATE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return std::string(x) + "/corbel";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.local/state/corbel";
  return ".corbel-state";
}

namespace {

// A slot's name for a saved document: a hash of its absolute path, so every editor that opens
// the file finds the same slot.
std::string slotOf(const std::string& originalPath) {
  std::error_code ec;
  const std::string abs = fs::absolute(originalPath, ec).lexically_normal().string();
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : abs) h = (h ^ c) * 1099511628211ull;
  char name[32];
  std::snprintf(name, sizeof name, "doc-%016llx", static_cast<unsigned long long>(h));
  return name;
}

// Opens and locks `lockPath` without waiting: the descriptor, or -1 when another process holds
// it (then *holder gets the process id written in it, when it can be read).
int tryLock(const std::string& lockPath, long* holder = nullptr) {
  const int fd = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return -1;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (holder) {
      char text[32] = {};
      if (::pread(fd, text, sizeof text - 1, 0) > 0) *holder = std::strtol(text, nullptr, 10);
    }
    ::close(fd);
    return -1;
  }
  return fd;
}

std::string stamp() {
  const std::time_t now = std::time(nullptr);
  char text[64] = {};
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  return text;
}

}  // namespace

Recovery::Recovery(std::string stateDir) : dir_(stateDir + "/recovery"), legacy_(std::move(stateDir)) {}

Recovery::~Recovery() { release(); }

std::string Recovery::path(const std::string& slot, const char* ext) const {
  if (slot == "legacy") return legacy_ + "/recovery" + ext;
  return dir_ + "/" + slot + ext;
}

std::string Recovery::documentPath() const { return slot_.empty() ? std::string() : path(slot_, ".corbel"); }

void Recovery::release() {
  if (lockFd_ < 0) return;
  std::error_code ec;
  if (!fs::exists(path(slot_, ".corbel"), ec)) fs::remove(path(slot_, ".lock"), ec);
  ::close(lockFd_);
  lockFd_ = -1;
  slot_.clear();
}

std::optional<long> Recovery::claim(const std::string& originalPath) {
  release();
  std::error_code ec;
  fs::create_directories(dir_, ec);
  static int counter = 0;
  const std::string pid = std::to_string(::getpid());
  const std::string base = originalPath.empty() ? "new-" + pid + "-" + std::to_string(++counter) : slotOf(originalPath);
  long holder = 0;
  std::optional<long> shared;
  for (const std::string& slot : {base, base + "-" + pid + "-" + std::to_string(++counter)}) {
    const int fd = tryLock(path(slot, ".lock"), &holder);
    if (fd < 0) {
      if (!originalPath.empty()) shared = holder;
      continue;
    }
    const std::string text = pid + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) < 0) {
      // The lock holds without the note; the id is only for the message of a second editor.
    }
    lockFd_ = fd;
    slot_ = slot;
    return shared;
  }
  throw Error("cannot take a recovery slot in " + dir_ + ": " + std::strerror(errno));
}

void Recovery::write(const Document& doc, const std::string& originalPath) {
  if (slot_.empty()) claim(originalPath);
  nlohmann::json meta = {{"original", originalPath}, {"saved_at", stamp()}, {"pid", ::getpid()}};
  // Document first, then the note that points at it: a crash between the two leaves an older
  // note, never a note without its document.
  saveProject(doc, path(slot_, ".corbel"));
  writeFileAtomic(path(slot_, ".json"), meta.dump(2, ' ', false, nlohmann::json::error_handler_t::replace));
}

void Recovery::discard() {
  if (slot_.empty()) return;
  std::error_code ec;
  fs::remove(path(slot_, ".corbel"), ec);
  fs::remove(path(slot_, ".json"), ec);
}

std::vector<RecoveredWork> Recovery::orphans(std::vector<std::string>* problems) const {
  std::vector<std::pair<fs::file_time_type, RecoveredWork>> found;
  std::vector<std::string> slots;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir_, ec))
    if (e.path().extension() == ".corbel") slots.push_back(e.path().stem().string());
  if (fs::exists(legacy_ + "/recovery.corbel", ec)) slots.push_back("legacy");
  for (const std::string& slot : slots) {
    if (slot == slot_) continue;
    if (slot != "legacy") {
      const int fd = tryLock(path(slot, ".lock"));
      if (fd < 0) continue;  // its editor is running
      ::close(fd);
    }
    try {
      RecoveredWork w;
      w.slot = slot;
      w.document = loadProject(path(slot, ".corbel")).document;
      try {
        const nlohmann::json meta = parseJsonText(readFile(path(slot, ".json"), 1 << 20));
        JsonReader r(meta, slot + ".json");
        w.originalPath = r.at("original").string(4096);
        w.savedAt = r.at("saved_at").string(64);
      } catch (const Error&) {
        // The document alone is still worth offering.
      }
      found.emplace_back(fs::last_write_time(path(slot, ".corbel"), ec), std::move(w));
    } catch (const Error& e) {
      if (problems) problems->push_back(e.what());
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<RecoveredWork> out;
  for (auto& [time, w] : found) out.push_back(std::move(w));
  return out;
}

void Recovery::adopt(const RecoveredWork& work) {
  if (work.slot == "legacy") {  // an older version's single file: moved into a slot of this editor's
    claim(work.originalPath);
    write(work.document, work.originalPath);
    discardOrphan(work);
    return;
  }
  const int fd = tryLock(path(work.slot, ".lock"));
  if (fd < 0) throw Error("another corbel has taken this work over (recovery slot " + work.slot + ")");
  if (!slot_.empty() && slot_ != work.slot) {
    discard();
    release();
  }
  const std::string text = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) < 0) {
  }
  lockFd_ = fd;
  slot_ = work.slot;
}

void Recovery::discardOrphan(const RecoveredWork& work) const {
  std::error_code ec;
  fs::remove(path(work.slot, ".corbel"), ec);
  fs::remove(path(work.slot, ".json"), ec);
  if (work.slot != "legacy") fs::remove(path(work.slot, ".lock"), ec);
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
