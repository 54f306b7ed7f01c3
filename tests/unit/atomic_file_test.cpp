// atomic_file.h: replacement semantics, permissions, failures without leftovers, and a writer
// killed mid-way (a forked child) leaving the previous file byte-for-byte.
#include "core/atomic_file.h"

#include "core/error.h"
#include "core/project_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

namespace {

using corbel::test::readText;
using corbel::test::TempDir;
using corbel::test::writeText;

mode_t modeOf(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return st.st_mode & 07777;
}

// A payload whose every byte depends on its position (catches reordered or torn chunks).
std::string payload(std::size_t bytes, unsigned seed) {
  std::string s(bytes, '\0');
  unsigned x = seed * 2654435761u + 1;
  for (std::size_t i = 0; i < bytes; ++i) {
    x = x * 1664525u + 1013904223u;
    s[i] = static_cast<char>('a' + (x >> 24) % 26);
  }
  return s;
}

TEST(AtomicFile, CreatesAndReplacesContent) {
  TempDir dir;
  const std::string path = dir.file("out.txt");
  corbel::writeFileAtomic(path, "first version, rather long\n");
  EXPECT_EQ(readText(path), "first version, rather long\n");
  corbel::writeFileAtomic(path, "short");
  EXPECT_EQ(readText(path), "short");  // no tail of the longer old content
  corbel::writeFileAtomic(path, "");
  EXPECT_EQ(readText(path), "");
  EXPECT_TRUE(std::filesystem::exists(path));
  const std::string big = payload(1 << 20, 1);
  corbel::writeFileAtomic(path, big);
  EXPECT_EQ(readText(path), big);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, BinaryContentIsKeptExactly) {
  TempDir dir;
  std::string data;
  for (int i = 0; i < 256; ++i) data.push_back(static_cast<char>(i));
  data += std::string("\0\0\r\n", 4);
  corbel::writeFileAtomic(dir.file("bin"), data);
  EXPECT_EQ(readText(dir.file("bin")), data);
}

TEST(AtomicFile, RelativePathInTheWorkingFolder) {
  TempDir dir;
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  EXPECT_NO_THROW(corbel::writeFileAtomic("plain.txt", "here"));
  std::filesystem::current_path(previous);
  EXPECT_EQ(readText(dir.file("plain.txt")), "here");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plain.txt"});
}

TEST(AtomicFile, KeepsTheReplacedFilesPermissions) {
  TempDir dir;
  const std::string path = dir.file("script.sh");
  writeText(path, "old");
  ASSERT_EQ(::chmod(path.c_str(), 0751), 0);
  corbel::writeFileAtomic(path, "new");
  EXPECT_EQ(readText(path), "new");
  EXPECT_EQ(modeOf(path), 0751u);
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  corbel::writeFileAtomic(path, "newer");
  EXPECT_EQ(modeOf(path), 0600u);
}

// A new file gets what open(2) would give it under the umask, not mkstemp's private 0600:
// for the writer's files and for those written through a temporary sibling (glb, tiles).
TEST(AtomicFile, ANewFileFollowsTheUmask) {
  TempDir dir;
  for (const mode_t mask : {mode_t(022), mode_t(002), mode_t(077)}) {
    const mode_t old = ::umask(mask);
    const std::string a = dir.file("fresh" + std::to_string(mask) + ".txt");
    corbel::writeFileAtomic(a, "x");
    EXPECT_EQ(modeOf(a), 0666u & ~mask);
    const std::string b = dir.file("sibling" + std::to_string(mask) + ".bin");
    const std::string temp = corbel::makeTempSibling(b);
    writeText(temp, "y");
    corbel::commitTempFile(temp, b);
    EXPECT_EQ(modeOf(b), 0666u & ~mask);
    ::umask(old);
  }
}

TEST(AtomicFile, MissingFolderFailsClearlyWithoutLeftovers) {
  TempDir dir;
  const std::string path = dir.file("nowhere/out.txt");
  try {
    corbel::writeFileAtomic(path, "data");
    FAIL() << "wrote into a missing folder";
  } catch (const corbel::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, FailedRenameRemovesTheTemporaryFile) {
  TempDir dir;
  // The target is a non-empty folder: the temporary file is written, the rename fails.
  std::filesystem::create_directory(dir.file("target"));
  writeText(dir.file("target/inside"), "keep");
  try {
    corbel::writeFileAtomic(dir.file("target"), "data");
    FAIL() << "replaced a folder";
  } catch (const corbel::Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot replace"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"target"});
  EXPECT_EQ(readText(dir.file("target/inside")), "keep");
}

TEST(AtomicFile, AfterChunkSeesCumulativeSizes) {
  TempDir dir;
  std::vector<std::size_t> calls;
  corbel::AtomicWriteOptions options;
  options.chunkSize = 3;
  options.afterChunk = [&](std::size_t written) { calls.push_back(written); };
  corbel::writeFileAtomic(dir.file("a"), "0123456789", options);
  EXPECT_EQ(calls, (std::vector<std::size_t>{3, 6, 9, 10}));
  EXPECT_EQ(readText(dir.file("a")), "0123456789");

  calls.clear();
  options.chunkSize = 0;  // one chunk
  corbel::writeFileAtomic(dir.file("b"), "0123456789", options);
  EXPECT_EQ(calls, (std::vector<std::size_t>{10}));

  calls.clear();
  corbel::writeFileAtomic(dir.file("c"), "", options);
  EXPECT_TRUE(calls.empty());
}

TEST(AtomicFile, ExceptionFromAfterChunkLeavesTheOldFile) {
  TempDir dir;
  const std::string path = dir.file("doc.txt");
  writeText(path, "previous");
  corbel::AtomicWriteOptions options;
  options.chunkSize = 4;
  options.afterChunk = [](std::size_t) { throw std::runtime_error("stop"); };
  EXPECT_THROW(corbel::writeFileAtomic(path, "replacement", options), std::runtime_error);
  EXPECT_EQ(readText(path), "previous");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"doc.txt"});  // the temporary file is removed
}

// The child writes `data` over `path` and SIGKILLs itself after the first chunk.
void killedWriter(const std::string& path, const std::string& data) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    corbel::AtomicWriteOptions options;
    options.chunkSize = 64 * 1024;
    options.afterChunk = [](std::size_t) { ::raise(SIGKILL); };
    try {
      corbel::writeFileAtomic(path, data, options);
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(4);  // the write finished: the kill did not happen
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(AtomicFile, WriterKilledMidWayLeavesThePreviousFile) {
  TempDir dir;
  const std::string path = dir.file("project.corbel");
  const std::string previous = payload(300 * 1000, 7);
  writeText(path, previous);
  killedWriter(path, payload(8 << 20, 8));
  EXPECT_EQ(readText(path), previous);
  // Whatever the killed writer left is a hidden temporary sibling, never the target.
  for (const std::string& name : dir.entries())
    if (name != "project.corbel") {
      EXPECT_EQ(name.rfind(".project.corbel.tmp-", 0), 0u) << name;
    }
  // And the next save succeeds.
  corbel::writeFileAtomic(path, "after");
  EXPECT_EQ(readText(path), "after");
}

TEST(AtomicFile, SaveProjectKilledAtAnyMomentLeavesAWholeFile) {
  // A child saves two large documents in turn, forever; it is killed after a varying delay.
  // The file must always hold exactly one of the complete serialisations.
  TempDir dir;
  const std::string path = dir.file("village.corbel");
  corbel::Document a, b;
  for (int i = 0; i < 4000; ++i) {
    corbel::DocObject o;
    o.id = static_cast<corbel::ObjectId>(i + 1);
    o.name = "House " + std::to_string(i);
    o.spec = corbel::BoxSpec{};
    a.objects.push_back(o);
    corbel::BoxSpec spec;
    spec.size = corbel::Vec3(1, 2, 3 + i);
    o.name = "Another house with a longer name " + std::to_string(i);
    o.spec = spec;
    b.objects.push_back(o);
  }
  const std::string textA = corbel::serializeProject(a), textB = corbel::serializeProject(b);
  ASSERT_NE(textA.size(), textB.size());
  corbel::saveProject(a, path);
  for (int round = 0; round < 6; ++round) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      for (int k = 0;; ++k) {
        try {
          corbel::saveProject(k % 2 ? a : b, path);
        } catch (...) {
          ::_exit(3);
        }
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5 + 23 * round));
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status));
    const std::string now = readText(path);
    EXPECT_TRUE(now == textA || now == textB) << "round " << round << ": " << now.size() << " bytes";
  }
}

TEST(ReadFile, ReadsWholeFilesWithinTheLimit) {
  TempDir dir;
  const std::string data = payload(5000, 3);
  writeText(dir.file("f"), data);
  EXPECT_EQ(corbel::readFile(dir.file("f"), 5000), data);
  try {
    corbel::readFile(dir.file("f"), 4999);
    FAIL();
  } catch (const corbel::Error& e) {
    EXPECT_NE(std::string(e.what()).find("file of 5000 bytes is larger than the limit of 4999"), std::string::npos)
        << e.what();
  }
  writeText(dir.file("empty"), "");
  EXPECT_EQ(corbel::readFile(dir.file("empty"), 10), "");
  EXPECT_THROW(corbel::readFile(dir.file("none"), 10), corbel::Error);
  EXPECT_THROW(corbel::readFile(dir.path(), 10), corbel::Error);
}

TEST(TempSibling, KeepsTheExtensionAndCommits) {
  TempDir dir;
  const std::string target = dir.file("model.ply");
  const std::string temp = corbel::makeTempSibling(target);
  EXPECT_EQ(std::filesystem::path(temp).parent_path(), std::filesystem::path(dir.path()));
  const std::string name = std::filesystem::path(temp).filename().string();
  EXPECT_EQ(name.rfind(".model.ply.tmp-", 0), 0u) << name;
  EXPECT_EQ(std::filesystem::path(temp).extension(), ".ply");
  EXPECT_TRUE(std::filesystem::exists(temp));
  writeText(temp, "ply data");
  corbel::commitTempFile(temp, target);
  EXPECT_EQ(readText(target), "ply data");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"model.ply"});
  // Two siblings of the same target never collide.
  const std::string t1 = corbel::makeTempSibling(target), t2 = corbel::makeTempSibling(target);
  EXPECT_NE(t1, t2);
  // Committing to an impossible place fails and removes the temporary file.
  EXPECT_THROW(corbel::commitTempFile(t1, dir.file("missing/model.ply")), corbel::Error);
  EXPECT_FALSE(std::filesystem::exists(t1));
  std::filesystem::remove(t2);
  EXPECT_THROW(corbel::makeTempSibling(dir.file("missing/model.ply")), corbel::Error);
}

}  // namespace
