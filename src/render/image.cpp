#include "render/image.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace corbel::render {

void Image::flipVertically() {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* a = &rgba[y * row];
    std::uint8_t* b = &rgba[(height - 1 - y) * row];
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
}

namespace {
void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

void writePng(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot write an empty image to '" + path + "'");
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw Error("cannot encode PNG for '" + path + "'");
  writeFileAtomic(path, bytes);
}

Image readPng(const std::string& path) { return readImage(path); }

Image readImage(const std::string& path, int maxSide) {
  int w = 0, h = 0, n = 0;
  if (stbi_info(path.c_str(), &w, &h, &n) && (w > maxSide || h > maxSide))
    throw Error("cannot read image '" + path + "': " + std::to_string(w) + " x " + std::to_string(h) +
                " pixels is larger than " + std::to_string(maxSide) + " on a side");
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) throw Error("cannot read image '" + path + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown"));
  Image img(w, h);
  std::memcpy(img.rgba.data(), data, img.rgba.size());
  stbi_image_free(data);
  return img;
}

ImageDiff compareImages(const Image& expected, const Image& actual, int tolerance) {
  if (expected.width != actual.width || expected.height != actual.height)
    throw Error("image sizes differ: expected " + std::to_string(expected.width) + "x" + std::to_string(expected.height) +
                ", got " + std::to_string(actual.width) + "x" + std::to_string(actual.height));
  ImageDiff d;
  d.visual = Image(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t* e = expected.at(x, y);
      const std::uint8_t* a = actual.at(x, y);
      int delta = 0;
      for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int(e[c]) - int(a[c])));
      d.maxChannelDelta = std::max(d.maxChannelDelta, delta);
      std::uint8_t* v = d.visual.at(x, y);
      if (delta > tolerance) {
        ++d.differing;
        v[0] = 255, v[1] = 0, v[2] = 0;
      } else {
        v[0] = e[0] / 3, v[1] = e[1] / 3, v[2] = e[2] / 3;
      }
      v[3] = 255;
    }
  }
  d.differingFraction = (expected.width > 0 && expected.height > 0) ? double(d.differing) / (double(expected.width) * expected.height) : 0.0;
  return d;
}

}  // namespace corbel::render
