// spill_buffer.h: bytes appended across the memory limit come back in order, whole and in
// pieces, as they went in (the identity is the oracle), and the temporary file leaves no name
// behind in the temporary folder.
#include "core/spill_buffer.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace {

using corbel::SpillBuffer;

std::string pattern(std::size_t n, unsigned seed) {
  std::string s(n, '\0');
  for (std::size_t i = 0; i < n; ++i) s[i] = static_cast<char>((i * 2654435761u + seed) >> 7);
  return s;
}

TEST(SpillBuffer, GivesBackWhatWasAppendedInMemoryAndSpilled) {
  corbel::test::TempDir tmp;
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  setenv("TMPDIR", tmp.path().c_str(), 1);
  for (std::size_t limit : {std::size_t{0}, std::size_t{100}, std::size_t{1} << 20}) {
    SCOPED_TRACE(limit);
    SpillBuffer b(limit);
    std::string all;
    for (unsigned k = 0; k < 40; ++k) {  // 4 MiB in all, crossing the limit
      const std::string s = pattern(k * k * 200, k);
      b.append(s);
      all += s;
    }
    EXPECT_EQ(b.size(), all.size());
    std::string back;
    std::size_t pieces = 0;
    b.read([&](const char* p, std::size_t n) {
      back.append(p, n);
      ++pieces;
    });
    EXPECT_TRUE(back == all);
    if (limit < all.size()) {
      EXPECT_GE(pieces, all.size() >> 20);  // read back a MiB at a time
    }
    const std::vector<unsigned char> bytes = b.bytes();
    EXPECT_TRUE(std::string(bytes.begin(), bytes.end()) == all);
    b.append("tail");  // appended after a reading: at the end
    const std::vector<unsigned char> more = b.bytes();
    EXPECT_TRUE(std::string(more.begin() + static_cast<long>(all.size()), more.end()) == "tail");
    EXPECT_TRUE(tmp.entries().empty());  // the file has no name
    b.clear();
    EXPECT_TRUE(b.empty());
  }
  if (before)
    setenv("TMPDIR", saved.c_str(), 1);
  else
    unsetenv("TMPDIR");
}

}  // namespace
