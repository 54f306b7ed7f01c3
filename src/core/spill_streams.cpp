#include "core/spill_streams.h"

#include "core/error.h"
#include "core/spill_buffer.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

namespace corbel {

SpillStreams::~SpillStreams() {
  if (fd_ >= 0) ::close(fd_);
}

void SpillStreams::append(std::size_t stream, const void* data, std::size_t bytes) {
  if (stream >= streams_.size()) streams_.resize(stream + 1);
  Stream& s = streams_[stream];
  const char* p = static_cast<const char*>(data);
  s.size += bytes;
  while (bytes > 0) {
    if (s.open.capacity() < block_) s.open.reserve(block_);
    const std::size_t n = std::min(bytes, block_ - s.open.size());
    s.open.insert(s.open.end(), p, p + n);
    p += n;
    bytes -= n;
    if (s.open.size() < block_) break;
    // A full block: to the file's end.
    if (fd_ < 0) fd_ = unnamedTempFile();
    for (std::size_t done = 0; done < block_;) {
      const ssize_t w = ::pwrite(fd_, s.open.data() + done, block_ - done, static_cast<off_t>(fileSize_ + done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) throw Error(std::string("cannot write a temporary file: ") + std::strerror(errno));
      done += static_cast<std::size_t>(w);
    }
    s.blocks.push_back(fileSize_);
    fileSize_ += block_;
    s.open.clear();
  }
}

void SpillStreams::readBlock(std::uint64_t at, char* into) const {
  for (std::size_t done = 0; done < block_;) {
    const ssize_t r = ::pread(fd_, into + done, block_ - done, static_cast<off_t>(at + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) throw Error(std::string("cannot read a temporary file back: ") + std::strerror(errno));
    done += static_cast<std::size_t>(r);
  }
}

}  // namespace corbel
