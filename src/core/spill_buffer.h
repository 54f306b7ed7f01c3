#pragma once
// Bytes appended in order and read back once, held in memory while small and in an unnamed
// temporary file beyond that (the glb writer's buffer views and JSON arrays, core/glb_writer.h),
// so that a writer fed a whole town holds a bounded amount of it in memory.
#include <cstddef>
#include <cstdio>
#include <ostream>
#include <string_view>
#include <vector>

namespace corbel {

// A new file in the system's temporary folder (TMPDIR), unlinked at once, open for reading and
// writing: its descriptor, for the caller to close. Throws corbel::Error when it cannot be made.
int unnamedTempFile();

class SpillBuffer {
 public:
  // Up to `memoryBytes` are held in memory; the rest goes to a file made in the system's
  // temporary folder (TMPDIR) and unlinked at once, so that nothing is left behind whatever
  // way the program ends.
  explicit SpillBuffer(std::size_t memoryBytes = std::size_t{1} << 16) : limit_(memoryBytes) {}
  ~SpillBuffer();
  SpillBuffer(const SpillBuffer&) = delete;
  SpillBuffer& operator=(const SpillBuffer&) = delete;

  // Throws corbel::Error when the temporary file cannot be made or written.
  void append(const void* data, std::size_t bytes);
  void append(std::string_view s) { append(s.data(), s.size()); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // Hands the bytes in order to `take(data, bytes)` in pieces of at most 1 MiB. Throws
  // corbel::Error when the file cannot be read back.
  template <class Take>
  void read(Take&& take) const {
    if (!file_) {
      if (!memory_.empty()) take(memory_.data(), memory_.size());
      return;
    }
    rewindForReading();
    std::vector<char> piece(std::size_t{1} << 20);
    for (std::size_t left = size_; left > 0;) {
      const std::size_t n = readPiece(piece.data(), std::min(left, piece.size()));
      take(piece.data(), n);
      left -= n;
    }
  }
  void copyTo(std::ostream& out) const {
    read([&](const char* p, std::size_t n) { out.write(p, static_cast<std::streamsize>(n)); });
  }
  std::vector<unsigned char> bytes() const;  // the whole, in memory

  void clear();  // empty again, the file (if any) closed

 private:
  void rewindForReading() const;
  std::size_t readPiece(char* into, std::size_t bytes) const;

  std::size_t limit_;
  std::size_t size_ = 0;
  std::vector<char> memory_;
  std::FILE* file_ = nullptr;
  mutable bool read_ = false;  // read since the last append: the file is not at its end
};

}  // namespace corbel
