#include "core/atomic_file.h"

#include "core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace corbel {

namespace fs = std::filesystem;

namespace {

std::string sysError(const std::string& what, const std::string& path) {
  return what + " '" + path + "': " + std::strerror(errno);
}

void fsyncDirectoryOf(const std::string& path) {
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// The mode a new file gets from open(2) under this process's umask: 0666 without the umask's
// bits. Read from /proc (umask(2) can only be read by setting it, which races with threads).
mode_t newFileMode() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Umask:", 0) == 0) return 0666 & ~static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
  return 0644;
}

// The mode of the file a save replaces (its owner chose it), else a new file's.
mode_t modeFor(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return st.st_mode & 07777;
  return newFileMode();
}

// mkstemps with the target's extension kept (OpenMesh picks its writer by extension).
int openTemp(const std::string& path, std::string& tempPath) {
  const fs::path p(path);
  const std::string ext = p.extension().string();
  fs::path dir = p.parent_path();
  std::string base = (dir.empty() ? std::string() : dir.string() + "/") + "." + p.filename().string() + ".tmp-XXXXXX";
  std::string pattern = base + ext;
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int fd = ::mkstemps(buf.data(), static_cast<int>(ext.size()));
  if (fd < 0) throw Error(sysError("cannot create a temporary file next to", path));
  tempPath = buf.data();
  return fd;
}

}  // namespace

void writeFileAtomic(const std::string& path, std::string_view data, const AtomicWriteOptions& options) {
  std::string temp;
  const int fd = openTemp(path, temp);
  auto failWith = [&](const std::string& message) {
    ::close(fd);
    ::unlink(temp.c_str());
    throw Error(message);
  };
  std::size_t written = 0;
  const std::size_t chunk = options.chunkSize ? options.chunkSize : data.size();
  while (written < data.size()) {
    const std::size_t n = std::min(chunk, data.size() - written);
    std::size_t done = 0;
    while (done < n) {
      const ssize_t w = ::write(fd, data.data() + written + done, n - done);
      if (w < 0) {
        if (errno == EINTR) continue;
        failWith(sysError("cannot write", temp));
      }
      done += static_cast<std::size_t>(w);
    }
    written += n;
    if (options.afterChunk) {
      try {
        options.afterChunk(written);
      } catch (...) {
        ::close(fd);
        ::unlink(temp.c_str());
        throw;
      }
    }
  }
  if (::fsync(fd) != 0) failWith(sysError("cannot flush", temp));
  ::fchmod(fd, modeFor(path));  // mkstemp made it 0600
  if (::close(fd) != 0) {
    ::unlink(temp.c_str());
    throw Error(sysError("cannot close", temp));
  }
  commitTempFile(temp, path);
}

std::string makeTempSibling(const std::string& path) {
  std::string temp;
  const int fd = openTemp(path, temp);
  ::close(fd);
  return temp;
}

void commitTempFile(const std::string& temp, const std::string& path) {
  {
    // Flush what another writer put there before the rename makes it visible, with the mode a
    // new file or the one it replaces would have (mkstemp made it 0600).
    const int fd = ::open(temp.c_str(), O_RDONLY);
    if (fd >= 0) {
      ::fchmod(fd, modeFor(path));
      ::fsync(fd);
      ::close(fd);
    }
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string message = sysError("cannot replace", path);
    ::unlink(temp.c_str());
    throw Error(message);
  }
  fsyncDirectoryOf(path);
}

std::string readFile(const std::string& path, std::size_t maxBytes) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error("'" + path + "': no such file");
  if (fs::is_directory(path, ec)) throw Error("'" + path + "': is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(sysError("cannot open", path));
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg()));
  if (size > maxBytes)
    throw Error("'" + path + "': file of " + std::to_string(size) + " bytes is larger than the limit of " +
                std::to_string(maxBytes));
  in.seekg(0);
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (!in) throw Error(sysError("cannot read", path));
  return text;
}

}  // namespace corbel
