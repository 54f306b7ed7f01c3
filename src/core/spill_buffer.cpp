#include "core/spill_buffer.h"

#include "core/error.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace corbel {

namespace {

std::string reason() { return std::strerror(errno); }

}  // namespace

int unnamedTempFile() {
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) throw Error("no folder for temporary files (TMPDIR): " + ec.message());
  std::string name = (dir / "corbel-spill-XXXXXX").string();
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw Error("cannot make a temporary file in " + dir.string() + ": " + reason());
  ::unlink(name.c_str());
  return fd;
}

namespace {

// A new file in the temporary folder, already unlinked.
std::FILE* anonymousFile() {
  const int fd = unnamedTempFile();
  std::FILE* f = ::fdopen(fd, "w+b");
  if (!f) {
    ::close(fd);
    throw Error("cannot open a temporary file: " + reason());
  }
  return f;
}

}  // namespace

SpillBuffer::~SpillBuffer() { clear(); }

void SpillBuffer::append(const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  const char* p = static_cast<const char*>(data);
  if (!file_ && memory_.size() + bytes <= limit_) {
    memory_.insert(memory_.end(), p, p + bytes);
  } else {
    if (!file_) {
      file_ = anonymousFile();
      if (!memory_.empty() && std::fwrite(memory_.data(), 1, memory_.size(), file_) != memory_.size())
        throw Error("cannot write a temporary file: " + reason());
      std::vector<char>().swap(memory_);
    }
    // Back to the end after a reading (seeking flushes the stream's buffer, so only then).
    if (read_ && std::fseek(file_, 0, SEEK_END) != 0) throw Error("cannot write a temporary file: " + reason());
    read_ = false;
    if (std::fwrite(p, 1, bytes, file_) != bytes) throw Error("cannot write a temporary file: " + reason());
  }
  size_ += bytes;
}

void SpillBuffer::rewindForReading() const {
  read_ = true;
  if (std::fflush(file_) != 0 || std::fseek(file_, 0, SEEK_SET) != 0)
    throw Error("cannot read a temporary file back: " + reason());
}

std::size_t SpillBuffer::readPiece(char* into, std::size_t bytes) const {
  if (std::fread(into, 1, bytes, file_) != bytes) throw Error("cannot read a temporary file back: " + reason());
  return bytes;
}

std::vector<unsigned char> SpillBuffer::bytes() const {
  std::vector<unsigned char> all;
  all.reserve(size_);
  read([&](const char* p, std::size_t n) { all.insert(all.end(), p, p + n); });
  return all;
}

void SpillBuffer::clear() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
  read_ = false;
  std::vector<char>().swap(memory_);
  size_ = 0;
}

}  // namespace corbel
