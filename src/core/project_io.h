#pragma once
// Project files (*.corbel): versioned JSON holding a Document. See docs/project-format.md.
#include "core/document.h"

#include <string>
#include <vector>

namespace corbel {

// The version this build writes; it reads 1 (no placements: every object where its kernel
// builds it) and 2 (per-object placement and lock).
inline constexpr int kProjectVersion = 2;
inline constexpr std::size_t kMaxProjectBytes = 64u << 20;

struct LoadedProject {
  Document document;
  std::vector<std::string> warnings;  // e.g. unknown keys that were ignored
};

// Parses project text. Throws InputError naming the JSON path of the first fault. With a
// `folder`, relative paths in the file (background images) are resolved against it.
LoadedProject parseProject(const std::string& text, const std::string& folder = {});
// Reads and parses a file, resolving relative paths against its folder; errors are prefixed
// with the file name.
LoadedProject loadProject(const std::string& path);

// Serialises deterministically (fixed key order, shortest round-trip numbers): save → load →
// save gives identical bytes. With a `folder`, absolute paths (background images) are written
// relative to it.
std::string serializeProject(const Document& doc, const std::string& folder = {});
// Atomic save (temporary file, fsync, rename); paths are written relative to the file's folder.
void saveProject(const Document& doc, const std::string& path);

}  // namespace corbel
