// Seeded random-mutation fuzzing of parseProject: 100,000 inputs derived from the examples and
// small hand-written seeds. Every input must either load into a Document that re-serialises
// and re-parses to an equal Document, or be refused with a corbel::InputError that has a
// reason. Nothing else may escape, and nothing may crash.
#include "core/error.h"
#include "core/project_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

namespace {

constexpr int kInputsPerShard = 25000;  // four shards: 100,000 inputs

std::vector<std::string> seeds() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(CORBEL_SOURCE_DIR) + "/assets/examples")) {
    if (e.path().extension() != ".corbel") continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    out.push_back(s.str());
  }
  EXPECT_FALSE(out.empty()) << "no example projects found";
  out.push_back(R"({"format": "corbel", "version": 1})");
  out.push_back(R"({"format": "corbel", "version": 1, "name": "One", "objects": [
    {"id": 1, "name": "A", "box": {"size": [1, 2, 3]}}]})");
  out.push_back(R"({"format": "corbel", "version": 1, "name": "R\u00e9p\u00e9t\u00e9 \"quoted\"", "objects": [
    {"id": 7, "name": "Row \u6f22", "visible": false,
     "box": {"origin": [-1.5, 2e3, 0.25], "size": [0.0001, 1e7, 3], "rotation": -3600, "material": "",
             "repeat": {"count": [100, 100], "spacing": [-10.5, 3]}}},
    {"id": 2147483647, "name": "Max", "box": {"size": [4, 4, 4], "material": "glass"}}]})");
  out.push_back(R"({"format": "corbel", "version": 1, "extra": {"nested": [1, [2, {"x": null}]]}, "objects": [
    {"id": 3, "name": "K", "colour": true, "box": {"size": [1, 1, 1], "height": 2,
     "repeat": {"count": [2, 3], "offset": 1}}}]})");
  out.push_back(R"({"format":"corbel","version":1,"objects":[{"id":1,"name":"a","box":{"size":[1,1,1]}},)"
                R"({"id":2,"name":"b","box":{"size":[2,2,2],"rotation":45.5}}]})");
  out.push_back(R"({"format":"corbel","version":1,"objects":[{"id":1,"name":"T","town":{)"
                R"("footprints":{"type":"FeatureCollection","features":[{"type":"Feature","id":"a",)"
                R"("geometry":{"type":"Polygon","coordinates":[[[0,0],[9,0],[9,7],[0,7],[0,0]]]}}]},)"
                R"("style":"../styles/oldtown.json","seed":3,"detail":"steps",)"
                R"("overrides":{"a":{"type":"town house","profiles":{"street":"oldtown gable","back":"x"}}}}}]})");
  return out;
}

class Mutator {
 public:
  Mutator(unsigned seed, std::vector<std::string> corpus) : rng_(seed), corpus_(std::move(corpus)) {}

  std::string next() {
    std::string s = corpus_[pick(corpus_.size())];
    // Half the inputs get a single mutation (often still a valid project), half up to four.
    const int rounds = pick(2) ? 1 : 1 + static_cast<int>(pick(4));
    for (int i = 0; i < rounds; ++i) mutate(s);
    return s;
  }

 private:
  std::size_t pick(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  std::size_t position(const std::string& s) { return pick(s.size() + 1); }

  void mutate(std::string& s) {
    switch (pick(10)) {
      case 0:
        flipByte(s);
        break;
      case 1:
        insertPunctuation(s);
        break;
      case 2:
        deleteSpan(s);
        break;
      case 3:
        truncate(s);
        break;
      case 4:
        duplicateSpan(s);
        break;
      case 5:
      case 6:
        replaceNumber(s);
        break;
      case 7:
        swapValueType(s);
        break;
      case 8:
        nest(s);
        break;
      default:
        splice(s);
        break;
    }
  }

  void flipByte(std::string& s) {
    if (s.empty()) return;
    const std::size_t i = pick(s.size());
    if (pick(2))
      s[i] = static_cast<char>(s[i] ^ (1 << pick(8)));
    else
      s[i] = static_cast<char>(pick(256));
  }

  void insertPunctuation(std::string& s) {
    static const std::string punct = "{}[],:\"\\-+.eE0123456789 \ntfn";
    const std::size_t count = 1 + pick(3);
    for (std::size_t k = 0; k < count; ++k) s.insert(position(s), 1, punct[pick(punct.size())]);
  }

  void deleteSpan(std::string& s) {
    if (s.empty()) return;
    const std::size_t at = pick(s.size());
    s.erase(at, 1 + pick(std::min<std::size_t>(40, s.size() - at)));
  }

  void truncate(std::string& s) { s.resize(pick(s.size() + 1)); }

  void duplicateSpan(std::string& s) {
    if (s.empty()) return;
    const std::size_t at = pick(s.size());
    const std::string span = s.substr(at, 1 + pick(std::min<std::size_t>(80, s.size() - at)));
    s.insert(position(s), span);
  }

  // [begin, end) of every maximal run of number characters that starts a number.
  static std::vector<std::pair<std::size_t, std::size_t>> numbers(const std::string& s) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    auto isNum = [](char c) {
      return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    };
    for (std::size_t i = 0; i < s.size();) {
      if ((s[i] >= '0' && s[i] <= '9') || s[i] == '-') {
        std::size_t j = i;
        while (j < s.size() && isNum(s[j])) ++j;
        out.emplace_back(i, j);
        i = j;
      } else {
        ++i;
      }
    }
    return out;
  }

  void replaceNumber(std::string& s) {
    static const char* replacements[] = {"1e999",
                                         "-1e999",
                                         "-0",
                                         "-0.0",
                                         "0",
                                         "1",
                                         "-1",
                                         "0.5",
                                         "2.5",
                                         "1e-400",
                                         "1e308",
                                         "-1e308",
                                         "18446744073709551615",
                                         "18446744073709551616",
                                         "9223372036854775807",
                                         "9223372036854775808",
                                         "-9223372036854775809",
                                         "2147483647",
                                         "2147483648",
                                         "1000000",
                                         "10000",
                                         "10001",
                                         "100",
                                         "4.9e-324",
                                         "1.7976931348623157e308",
                                         "3600",
                                         "-3600.0001",
                                         "1e7",
                                         "10000000.000000002",
                                         "0.0001",
                                         "0.00009999",
                                         "NaN",
                                         "Infinity",
                                         "1.",
                                         ".5",
                                         "01",
                                         "1e",
                                         "--1"};
    const auto spans = numbers(s);
    if (spans.empty()) return;
    const auto [b, e] = spans[pick(spans.size())];
    s.replace(b, e - b, replacements[pick(std::size(replacements))]);
  }

  // Replaces a value (number, string, literal, or an opening bracket's whole container) with
  // a value of another type.
  void swapValueType(std::string& s) {
    static const char* values[] = {"\"text\"",
                                   "\"\"",
                                   "[]",
                                   "{}",
                                   "null",
                                   "true",
                                   "false",
                                   "0",
                                   "[1, 2, 3]",
                                   "{\"a\": 1}",
                                   "[\"x\", \"y\", \"z\"]",
                                   "-12.5",
                                   "\"\\u0000\""};
    if (s.empty()) return;
    const std::size_t start = pick(s.size());
    // Find the next value start after `start`: a colon or comma or [ followed by a value.
    std::size_t i = s.find_first_of(":,[", start);
    if (i == std::string::npos) return;
    ++i;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\n')) ++i;
    if (i >= s.size()) return;
    const std::size_t end = valueEnd(s, i);
    s.replace(i, end - i, values[pick(std::size(values))]);
  }

  // End of the JSON value starting at i (best effort on broken text).
  static std::size_t valueEnd(const std::string& s, std::size_t i) {
    if (s[i] == '"') {
      std::size_t j = i + 1;
      while (j < s.size() && s[j] != '"') j += s[j] == '\\' ? 2 : 1;
      return std::min(j + 1, s.size());
    }
    if (s[i] == '[' || s[i] == '{') {
      int depth = 0;
      bool inString = false;
      for (std::size_t j = i; j < s.size(); ++j) {
        if (inString) {
          if (s[j] == '\\')
            ++j;
          else if (s[j] == '"')
            inString = false;
        } else if (s[j] == '"') {
          inString = true;
        } else if (s[j] == '[' || s[j] == '{') {
          ++depth;
        } else if ((s[j] == ']' || s[j] == '}') && --depth == 0) {
          return j + 1;
        }
      }
      return s.size();
    }
    std::size_t j = i;
    while (j < s.size() && s[j] != ',' && s[j] != '}' && s[j] != ']' && s[j] != '\n') ++j;
    return j;
  }

  void nest(std::string& s) {
    const std::size_t depth = 1 + (pick(4) == 0 ? pick(100000) : pick(80));
    const std::size_t at = position(s);
    std::string deep;
    const bool arrays = pick(2) == 1;
    for (std::size_t k = 0; k < depth; ++k) deep.append(arrays ? std::string_view("[") : std::string_view("{\"k\":"));
    deep.push_back(arrays ? '1' : '0');
    deep.append(depth, arrays ? ']' : '}');
    s.insert(at, deep);
  }

  void splice(std::string& s) {
    const std::string& other = corpus_[pick(corpus_.size())];
    const std::size_t a = position(s), b = pick(other.size() + 1);
    s = s.substr(0, a) + other.substr(b, pick(other.size() - b + 1));
  }

  std::mt19937 rng_;
  std::vector<std::string> corpus_;
};

std::string excerpt(const std::string& s) {
  std::string out = s.substr(0, 300);
  if (s.size() > 300) out += "... (" + std::to_string(s.size()) + " bytes)";
  return out;
}

void runShard(unsigned seed) {
  Mutator mutator(seed, seeds());
  long accepted = 0, rejected = 0;
  for (int i = 0; i < kInputsPerShard; ++i) {
    const std::string input = mutator.next();
    try {
      const corbel::LoadedProject p = corbel::parseProject(input);
      ++accepted;
      const std::string text = corbel::serializeProject(p.document);
      corbel::LoadedProject again;
      try {
        again = corbel::parseProject(text);
      } catch (const std::exception& e) {
        FAIL() << "accepted input does not re-parse after serialisation: " << e.what() << "\ninput: " << excerpt(input)
               << "\nserialised: " << excerpt(text);
      }
      if (!(again.document == p.document)) {
        // The whole input, to study it: the message shows only its start.
        std::ofstream("loader-fuzz-failure.corbel") << input;
        FAIL() << "the re-parsed document differs (whole input in loader-fuzz-failure.corbel)\ninput: " << excerpt(input)
               << "\nserialised: " << excerpt(text);
      }
      // Unknown keys are kept: the re-saved file names the same ones again, and nothing else
      // (what was ignored, like a featureless anchor's size, is not written).
      auto kept = [](const std::vector<std::string>& warnings) {
        std::vector<std::string> out;
        for (const std::string& w : warnings)
          if (w.ends_with(": unknown key kept")) out.push_back(w);
        return out;
      };
      ASSERT_EQ(again.warnings, kept(p.warnings)) << "input: " << excerpt(input);
      ASSERT_EQ(corbel::serializeProject(again.document), text) << "input: " << excerpt(input);
    } catch (const corbel::InputError& e) {
      ++rejected;
      ASSERT_FALSE(e.reason.empty()) << "input: " << excerpt(input);
      ASSERT_FALSE(std::string(e.what()).empty())
          << "where: " << nlohmann::json(e.where).dump() << " reason: " << nlohmann::json(e.reason).dump()
          << " input: " << nlohmann::json(excerpt(input)).dump();
    } catch (const std::exception& e) {
      FAIL() << "non-InputError escaped: " << typeid(e).name() << ": " << e.what() << "\ninput: " << excerpt(input);
    } catch (...) {
      FAIL() << "unknown exception escaped\ninput: " << excerpt(input);
    }
  }
  std::cout << "[fuzz] seed " << seed << ": " << kInputsPerShard << " inputs, " << accepted << " accepted, " << rejected
            << " rejected" << std::endl;
  EXPECT_EQ(accepted + rejected, kInputsPerShard);
  // The mutations must exercise both outcomes.
  EXPECT_GT(accepted, kInputsPerShard / 100);
  EXPECT_GT(rejected, kInputsPerShard / 2);
}

TEST(LoaderFuzz, Shard1) { runShard(1); }
TEST(LoaderFuzz, Shard2) { runShard(2); }
TEST(LoaderFuzz, Shard3) { runShard(3); }
TEST(LoaderFuzz, Shard4) { runShard(4); }

TEST(LoaderFuzz, SeedsThemselvesLoad) {
  for (const std::string& s : seeds()) {
    const corbel::LoadedProject p = corbel::parseProject(s);
    EXPECT_EQ(corbel::parseProject(corbel::serializeProject(p.document)).document, p.document);
  }
}

}  // namespace
