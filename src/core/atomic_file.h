#pragma once
// Atomic file replacement: write a temporary file in the same folder, fsync it, rename it over
// the target, fsync the folder. A crash at any point leaves either the old or the new file.
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace corbel {

struct AtomicWriteOptions {
  std::size_t chunkSize = 1 << 16;
  // Called after each chunk is written to the temporary file (tests kill the process here).
  std::function<void(std::size_t written)> afterChunk;
};

// Throws corbel::Error naming the path and the system's reason on failure; the target is
// untouched then and the temporary file removed.
void writeFileAtomic(const std::string& path, std::string_view data, const AtomicWriteOptions& options = {});

// Reads a whole file, refusing files larger than maxBytes. Throws corbel::Error.
std::string readFile(const std::string& path, std::size_t maxBytes);

// Creates a temporary path next to `path` ("<dir>/.<name>.tmp-XXXXXX<ext>"), opened and
// closed, for writers that need a file name (OpenMesh, tinygltf). Pair with commitTempFile.
std::string makeTempSibling(const std::string& path);
void commitTempFile(const std::string& tempPath, const std::string& path);

}  // namespace corbel
