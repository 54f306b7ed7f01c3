// render/image.h: readImage gives back what writePng wrote, and refuses missing, foreign and
// oversized files with the file's name in the message.
#include "render/image.h"

#include "core/error.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace {

using corbel::render::Image;

Image pattern(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = static_cast<std::uint8_t>(40 * x), p[1] = static_cast<std::uint8_t>(90 * y), p[2] = 7, p[3] = x == y ? 128 : 255;
    }
  return img;
}

TEST(Image, ReadImageGivesBackTheWrittenPixels) {
  corbel::test::TempDir dir;
  const Image img = pattern(5, 3);
  corbel::render::writePng(img, dir.file("p.png"));
  const Image back = corbel::render::readImage(dir.file("p.png"));
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, img.rgba) << "top row first, RGBA";
}

TEST(Image, ReadImageRefusesWithTheFilesName) {
  corbel::test::TempDir dir;
  auto message = [](const std::string& path, int maxSide) -> std::string {
    try {
      corbel::render::readImage(path, maxSide);
    } catch (const corbel::Error& e) {
      return e.what();
    }
    return "";
  };
  const std::string missing = dir.file("none.png");
  EXPECT_NE(message(missing, 100).find(missing), std::string::npos);
  corbel::test::writeText(dir.file("text.png"), "not an image at all");
  EXPECT_NE(message(dir.file("text.png"), 100).find("text.png"), std::string::npos);
  corbel::render::writePng(pattern(5, 3), dir.file("wide.png"));
  EXPECT_NE(message(dir.file("wide.png"), 4).find("5 x 3 pixels is larger than 4 on a side"), std::string::npos);
  EXPECT_EQ(message(dir.file("wide.png"), 5), "");
}

}  // namespace
