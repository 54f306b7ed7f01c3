#pragma once
// Many byte streams appended to in any interleaving and each read back in order, through one
// temporary file (the glb writer's instance placements, a stream per instanced mesh,
// core/glb_writer.h): each stream holds one block in memory and writes it to the file when it
// is full, so that memory holds a block per stream and the blocks' places in the file (8 bytes
// a block), whatever the streams' lengths.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace corbel {

class SpillStreams {
 public:
  // Blocks of `blockBytes` (at least 1) go to a file made in the system's temporary folder
  // (TMPDIR) when the first one fills, unlinked at once.
  explicit SpillStreams(std::size_t blockBytes = 4096) : block_(blockBytes ? blockBytes : 1) {}
  ~SpillStreams();
  SpillStreams(const SpillStreams&) = delete;
  SpillStreams& operator=(const SpillStreams&) = delete;

  // Appends to stream `stream` (streams are numbered from 0 and made as they are first named).
  // Throws corbel::Error when the temporary file cannot be made or written.
  void append(std::size_t stream, const void* data, std::size_t bytes);
  std::size_t size(std::size_t stream) const { return stream < streams_.size() ? streams_[stream].size : 0; }

  // Hands the bytes of `stream` in order to `take(data, bytes)`, a block at a time. Throws
  // corbel::Error when the file cannot be read back.
  template <class Take>
  void read(std::size_t stream, Take&& take) const {
    if (stream >= streams_.size()) return;
    const Stream& s = streams_[stream];
    std::vector<char> piece(s.blocks.empty() ? 0 : block_);
    for (std::uint64_t at : s.blocks) {
      readBlock(at, piece.data());
      take(static_cast<const char*>(piece.data()), block_);
    }
    if (!s.open.empty()) take(static_cast<const char*>(s.open.data()), s.open.size());
  }

 private:
  struct Stream {
    std::vector<char> open;  // the block being filled
    std::vector<std::uint64_t> blocks;  // the full blocks' places in the file, in order
    std::size_t size = 0;
  };
  void readBlock(std::uint64_t at, char* into) const;

  std::size_t block_;
  std::vector<Stream> streams_;
  int fd_ = -1;
  std::uint64_t fileSize_ = 0;
};

}  // namespace corbel
