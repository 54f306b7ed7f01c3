#pragma once
// RGBA8 images, top row first, and PNG I/O (stb).
#include <cstdint>
#include <string>
#include <vector>

namespace corbel::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* at(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const std::uint8_t* at(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  // Rows as glReadPixels returns them (bottom row first) → top row first.
  void flipVertically();
};

// Atomic write (temporary sibling + rename). Throws corbel::Error.
void writePng(const Image& image, const std::string& path);
// Throws corbel::Error if the file is missing or not a PNG.
Image readPng(const std::string& path);
// Any image stb reads (PNG, JPEG, BMP, TGA, GIF's first frame), as RGBA. Throws corbel::Error
// naming the file and the reason when it is missing, unreadable, or wider or taller than
// `maxSide` pixels (checked before decoding).
Image readImage(const std::string& path, int maxSide = 1 << 15);

struct ImageDiff {
  int maxChannelDelta = 0;       // over all pixels and channels
  std::size_t differing = 0;     // pixels with a channel delta above the tolerance
  double differingFraction = 0;  // differing / pixel count
  Image visual;                  // red where pixels differ, dimmed expected elsewhere
};
// Compares two images of the same size (throws corbel::Error otherwise).
ImageDiff compareImages(const Image& expected, const Image& actual, int tolerance);

}  // namespace corbel::render
