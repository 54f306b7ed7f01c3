// spill_streams.h: streams appended to in turn, in pieces that cross the blocks' edges, come
// back each in its own order as it went in (the identity is the oracle), through one temporary
// file that leaves no name behind in the temporary folder.
#include "core/spill_streams.h"

#include "core/error.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace {

using corbel::SpillStreams;

TEST(SpillStreams, GiveBackEachStreamInItsOwnOrder) {
  corbel::test::TempDir tmp;
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  setenv("TMPDIR", tmp.path().c_str(), 1);
  for (std::size_t block : {std::size_t{1}, std::size_t{7}, std::size_t{4096}, std::size_t{1} << 20}) {
    SCOPED_TRACE(block);
    SpillStreams s(block);
    std::vector<std::string> want(5);  // stream 3 is never appended to
    for (unsigned k = 0; k < 3000; ++k) {
      const std::size_t stream = (k * 7 + k / 13) % 5 == 3 ? 4 : (k * 7 + k / 13) % 5;
      std::string piece(k % 37, '\0');
      for (std::size_t i = 0; i < piece.size(); ++i) piece[i] = static_cast<char>(k * 31 + i * 17);
      s.append(stream, piece.data(), piece.size());
      want[stream] += piece;
    }
    for (std::size_t stream = 0; stream < 7; ++stream) {
      SCOPED_TRACE(stream);
      const std::string expected = stream < want.size() ? want[stream] : "";
      EXPECT_EQ(s.size(stream), expected.size());
      std::string back;
      s.read(stream, [&](const char* p, std::size_t n) {
        EXPECT_LE(n, block);
        back.append(p, n);
      });
      EXPECT_TRUE(back == expected);
    }
    s.append(0, "tail", 4);  // appended after a reading: at the stream's end
    std::string back;
    s.read(0, [&](const char* p, std::size_t n) { back.append(p, n); });
    EXPECT_TRUE(back == want[0] + "tail");
    EXPECT_TRUE(tmp.entries().empty());  // the file has no name
  }
  if (before)
    setenv("TMPDIR", saved.c_str(), 1);
  else
    unsetenv("TMPDIR");
}

TEST(SpillStreams, SaysWhyWhenThereIsNoTemporaryFolder) {
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  setenv("TMPDIR", "/proc", 1);  // no file can be made there
  SpillStreams s(4);
  s.append(0, "abc", 3);  // within the block: memory only
  try {
    s.append(0, "def", 3);
    ADD_FAILURE() << "a block was written with no temporary folder";
  } catch (const corbel::Error& e) {
    EXPECT_NE(std::string(e.what()).find("temporary"), std::string::npos) << e.what();
  }
  if (before)
    setenv("TMPDIR", saved.c_str(), 1);
  else
    unsetenv("TMPDIR");
}

}  // namespace
