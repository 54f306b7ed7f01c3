// project_io.h: round trips of random and example documents, and the exact path and reason of
// every kind of bad project file.
#include "core/project_io.h"

#include "core/error.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <random>
#include <set>

namespace {

using corbel::BoxSpec;
using corbel::DocObject;
using corbel::Document;
using corbel::InputError;
using corbel::Vec3;
using corbel::test::readText;
using corbel::test::TempDir;
using corbel::test::writeText;
namespace limits = corbel::limits;

// ---------------------------------------------------------------------------------------------
// Random documents within the limits.

class RandomDocs {
 public:
  explicit RandomDocs(unsigned seed) : rng_(seed) {}

  Document document() {
    Document d;
    d.name = text(0, 40);
    const int count = pick(0, 9);
    std::set<std::string> names;
    std::set<corbel::ObjectId> ids;
    for (int i = 0; i < count; ++i) {
      DocObject o;
      do o.id = static_cast<corbel::ObjectId>(pick(0, 2) ? pick(1, 50) : pick(1, 0x7fffffff));
      while (!ids.insert(o.id).second);
      do o.name = text(1, 30);
      while (!names.insert(o.name).second);
      o.visible = pick(0, 1) == 1;
      o.spec = box();
      d.objects.push_back(std::move(o));
    }
    return d;
  }

  BoxSpec box() {
    BoxSpec b;
    for (int k = 0; k < 3; ++k) b.origin[k] = number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
    for (int k = 0; k < 3; ++k) b.size[k] = number(limits::kMinSize, limits::kMaxCoordinate);
    b.rotation_deg = number(-3600, 3600);
    b.material = pick(0, 3) ? std::string(materials_[pick(0, 4)]) : text(0, 20);
    b.repeat_x = pick(1, 100);
    b.repeat_y = pick(1, 100);
    // |spacing| * count must stay within the coordinate limit (with room for rounding).
    const double sx = 0.999999 * limits::kMaxCoordinate / b.repeat_x,
                 sy = 0.999999 * limits::kMaxCoordinate / b.repeat_y;
    b.spacing_x = number(-sx, sx);
    b.spacing_y = number(-sy, sy);
    EXPECT_EQ(corbel::checkBoxSpec(b), std::nullopt);
    return b;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  // A double within [lo, hi] drawn from several shapes: whole numbers, short decimals, full
  // 17-digit doubles, tiny and huge magnitudes, and the bounds themselves.
  double number(double lo, double hi) {
    double v = 0;
    switch (pick(0, 6)) {
      case 0:
        v = std::round(std::uniform_real_distribution<double>(lo, hi)(rng_));
        break;
      case 1:
        v = std::round(std::uniform_real_distribution<double>(-1000, 1000)(rng_)) / 10.0;
        break;
      case 2:
        v = std::uniform_real_distribution<double>(lo, hi)(rng_);
        break;
      case 3:
        v = std::ldexp(std::uniform_real_distribution<double>(0.5, 1)(rng_), pick(-14, 23));
        break;
      case 4:
        v = pick(0, 1) ? lo : hi;
        break;
      case 5:
        v = std::nextafter(pick(0, 1) ? lo : hi, 0.0);
        break;
      default:
        v = std::uniform_real_distribution<double>(-3, 3)(rng_);
        break;
    }
    if (!(v >= lo && v <= hi)) v = std::clamp(v, lo, hi);
    return v;
  }

  // Valid UTF-8 text with quotes, backslashes, control characters and non-ASCII letters.
  std::string text(int minLength, int maxLength) {
    static const char* pieces[] = {"a", "B", "z",  " ", "\"", "\\", "/", "\n", "\t", "\x01", "\x1f", "é",
                                   "ß", "Ω", "漢", "🏠", "{",  "}",  "[", "]",  ":",  ",",    "0",    "-"};
    std::string s;
    const int n = pick(minLength, maxLength);
    for (int i = 0; i < n; ++i) s.append(std::string_view(pieces[pick(0, static_cast<int>(std::size(pieces)) - 1)]));
    // At most 40 pieces of at most 4 bytes: always within kMaxNameLength.
    if (static_cast<int>(s.size()) < minLength) s.push_back('x');
    return s;
  }

  std::mt19937 rng_;
  static constexpr const char* materials_[] = {"plaster", "stone", "brick", "glass", ""};
};

TEST(ProjectIo, RandomDocumentsRoundTrip) {
  RandomDocs gen(20240611);
  for (int i = 0; i < 300; ++i) {
    const Document d = gen.document();
    const std::string text = corbel::serializeProject(d);
    corbel::LoadedProject back;
    ASSERT_NO_THROW(back = corbel::parseProject(text)) << text;
    EXPECT_TRUE(back.warnings.empty());
    ASSERT_EQ(back.document, d) << text;
    // Bit-exact doubles (== would accept -0 for 0).
    for (std::size_t k = 0; k < d.objects.size(); ++k) {
      const auto& a = std::get<BoxSpec>(d.objects[k].spec);
      const auto& b = std::get<BoxSpec>(back.document.objects[k].spec);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(std::signbit(a.origin[c]), std::signbit(b.origin[c]));
        EXPECT_EQ(std::signbit(a.size[c]), std::signbit(b.size[c]));
      }
    }
    EXPECT_EQ(corbel::serializeProject(back.document), text);
  }
}

TEST(ProjectIo, NegativeZeroAndExtremeDoublesRoundTrip) {
  Document d;
  BoxSpec b;
  b.origin = Vec3(-0.0, 0.1 + 0.2, -limits::kMaxCoordinate);
  b.size = Vec3(limits::kMinSize, std::nextafter(limits::kMaxCoordinate, 0.0), 1.0 / 3.0);
  b.rotation_deg = -0.0;
  b.spacing_x = 5e-324;  // smallest subnormal
  d.add("Extreme", b);
  const Document back = corbel::parseProject(corbel::serializeProject(d)).document;
  const auto& r = std::get<BoxSpec>(back.objects[0].spec);
  EXPECT_EQ(back, d);
  EXPECT_TRUE(std::signbit(r.origin[0]));
  EXPECT_TRUE(std::signbit(r.rotation_deg));
  EXPECT_EQ(r.origin[1], 0.1 + 0.2);
  EXPECT_EQ(r.size[2], 1.0 / 3.0);
  EXPECT_EQ(r.spacing_x, 5e-324);
}

TEST(ProjectIo, ExamplesSaveLoadSaveIsByteIdentical) {
  const auto examples = corbel::test::exampleProjects();
  ASSERT_FALSE(examples.empty());
  TempDir dir;
  for (const std::string& path : examples) {
    SCOPED_TRACE(path);
    const corbel::LoadedProject loaded = corbel::loadProject(path);
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_FALSE(loaded.document.objects.empty());
    corbel::saveProject(loaded.document, dir.file("a.corbel"));
    const corbel::LoadedProject again = corbel::loadProject(dir.file("a.corbel"));
    EXPECT_EQ(again.document, loaded.document);
    corbel::saveProject(again.document, dir.file("b.corbel"));
    const std::string a = readText(dir.file("a.corbel")), b = readText(dir.file("b.corbel"));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, corbel::serializeProject(loaded.document, dir.path()));  // file paths relative to it
  }
}

// Every example is written by the current writer: loading it and saving it beside itself gives
// the file's own bytes. A change to the format re-saves the examples in the same commit.
TEST(ProjectIo, ExamplesAreWhatTheCurrentWriterWrites) {
  const auto examples = corbel::test::exampleProjects();
  ASSERT_FALSE(examples.empty());
  for (const std::string& path : examples) {
    SCOPED_TRACE(path);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    const std::string text = readText(path);
    EXPECT_EQ(corbel::serializeProject(corbel::parseProject(text, folder).document, folder), text)
        << "re-save the example with the current writer";
  }
}

TEST(ProjectIo, VillageExampleContents) {
  // Spot checks against the example file's text.
  const Document d = corbel::loadProject(corbel::test::sourcePath("assets/examples/village.corbel")).document;
  EXPECT_EQ(d.name, "Village");
  ASSERT_EQ(d.objects.size(), 5u);
  EXPECT_EQ(d.objects[2].name, "Terrace");
  const auto& terrace = std::get<BoxSpec>(d.objects[2].spec);
  EXPECT_EQ(terrace.origin, Vec3(-2, -16, 0));
  EXPECT_EQ(terrace.size, Vec3(6, 8, 5));
  EXPECT_EQ(terrace.rotation_deg, 8.0);
  EXPECT_EQ(terrace.repeat_x, 4);
  EXPECT_EQ(terrace.spacing_x, 7.0);
  EXPECT_EQ(std::get<BoxSpec>(d.objects[4].spec).origin[2], -0.3);
}

TEST(ProjectIo, OptionalFieldsTakeDefaults) {
  const auto p = corbel::parseProject(R"({"format": "corbel", "version": 1,
      "objects": [{"id": 3, "name": "Plain", "box": {"size": [1, 2, 3]}}]})");
  EXPECT_EQ(p.document.name, "untitled");
  ASSERT_EQ(p.document.objects.size(), 1u);
  const DocObject& o = p.document.objects[0];
  EXPECT_EQ(o.id, 3u);
  EXPECT_TRUE(o.visible);
  BoxSpec expected;
  expected.size = Vec3(1, 2, 3);
  EXPECT_EQ(std::get<BoxSpec>(o.spec), expected);
  EXPECT_TRUE(corbel::parseProject(R"({"format": "corbel", "version": 1})").document.objects.empty());
}

// ---------------------------------------------------------------------------------------------
// Errors: exact path and reason.

struct Fault {
  std::string where, reason;
};

Fault parseFault(const std::string& text) {
  try {
    corbel::parseProject(text);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), e.where.empty() ? e.reason : e.where + ": " + e.reason);
    return {e.where, e.reason};
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return {"<other>", e.what()};
  }
  ADD_FAILURE() << "accepted: " << text;
  return {"<accepted>", ""};
}

// A project with one object whose box is `box` (a JSON object body) and other fields `extra`.
std::string withBox(const std::string& box, const std::string& extra = "") {
  return R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A", )" + extra + R"("box": {)" + box +
         "}}]}";
}

#define EXPECT_FAULT(text, expectedWhere, expectedReason) \
  do {                                                    \
    const Fault f_ = parseFault(text);                    \
    EXPECT_EQ(f_.where, expectedWhere) << (text);         \
    EXPECT_EQ(f_.reason, expectedReason) << (text);       \
  } while (0)

#define EXPECT_FAULT_CONTAINS(text, expectedWhere, part)                                             \
  do {                                                                                               \
    const Fault f_ = parseFault(text);                                                               \
    EXPECT_EQ(f_.where, expectedWhere) << (text);                                                    \
    EXPECT_NE(f_.reason.find(part), std::string::npos) << "reason: " << f_.reason << "\n" << (text); \
  } while (0)

TEST(ProjectIoErrors, FileAsAWhole) {
  EXPECT_FAULT("", "", "file is empty");
  EXPECT_FAULT("   \n\t\r\n ", "", "file is empty");
  EXPECT_FAULT_CONTAINS("this is not a project", "", "not valid JSON: ");
  EXPECT_FAULT_CONTAINS("<?xml version=\"1.0\"?>", "", "line 1, column 1");
  EXPECT_FAULT("[]", "", "a project file must hold a JSON object");
  EXPECT_FAULT("\"corbel\"", "", "a project file must hold a JSON object");
  EXPECT_FAULT("42", "", "a project file must hold a JSON object");
  EXPECT_FAULT("null", "", "a project file must hold a JSON object");
}

TEST(ProjectIoErrors, EveryTruncationOfTheExampleFailsCleanly) {
  const std::string text = readText(corbel::test::sourcePath("assets/examples/village.corbel"));
  const corbel::LoadedProject full = corbel::parseProject(text);
  const std::size_t lastBrace = text.rfind('}');
  ASSERT_NE(lastBrace, std::string::npos);
  for (std::size_t n = 0; n < text.size(); ++n) {
    const std::string prefix = text.substr(0, n);
    if (n <= lastBrace) {
      // Cut before the closing brace: never a complete JSON value.
      try {
        corbel::parseProject(prefix);
        ADD_FAILURE() << "prefix of " << n << " bytes accepted";
      } catch (const InputError& e) {
        EXPECT_FALSE(e.reason.empty()) << n;
        EXPECT_EQ(e.where, "") << n;
      } catch (const std::exception& e) {
        ADD_FAILURE() << "prefix of " << n << " bytes: not an InputError: " << e.what();
      }
    } else {
      // Only trailing whitespace is missing.
      EXPECT_EQ(corbel::parseProject(prefix).document, full.document) << n;
    }
  }
}

TEST(ProjectIoErrors, HeaderFields) {
  EXPECT_FAULT(R"({"version": 1})", "format", "missing");
  EXPECT_FAULT(R"({"format": "corbel"})", "version", "missing");
  EXPECT_FAULT(R"({"format": "blender", "version": 1})", "format", R"(expected "corbel", found "blender")");
  EXPECT_FAULT(R"({"format": 1, "version": 1})", "format", "expected a string, found a number");
  EXPECT_FAULT(R"({"format": "corbel", "version": "1"})", "version", "expected an integer, found a string");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1.5})", "version", "expected an integer, found a fractional number");
  EXPECT_FAULT(R"({"format": "corbel", "version": 0})", "version", "format version must be at least 1");
  EXPECT_FAULT(R"({"format": "corbel", "version": -1})", "version", "-1 is outside [0, 1073741824]");
  const Fault future = parseFault(R"({"format": "corbel", "version": 99, "objects": "whatever"})");
  EXPECT_EQ(future.where, "version");
  EXPECT_NE(future.reason.find("newer corbel"), std::string::npos) << future.reason;
  EXPECT_NE(future.reason.find("99"), std::string::npos) << future.reason;
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "name": 7})", "name", "expected a string, found a number");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": {}})", "objects", "expected an array, found an object");
}

TEST(ProjectIoErrors, WrongTypes) {
  EXPECT_FAULT(withBox(R"("size": "10")"), "objects[0].box.size", "expected [x, y, z] numbers");
  EXPECT_FAULT(withBox(R"("size": [1, "2", 3])"), "objects[0].box.size", "expected [x, y, z] numbers");
  EXPECT_FAULT(withBox(R"("size": [1, 2])"), "objects[0].box.size", "expected [x, y, z] numbers");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "origin": {"x": 1})"), "objects[0].box.origin",
               "expected [x, y, z] numbers");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "rotation": [0])"), "objects[0].box.rotation",
               "expected a number, found an array");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "material": 3)"), "objects[0].box.material",
               "expected a string, found a number");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "repeat": [2, 2])"), "objects[0].box.repeat",
               "expected an object, found an array");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "repeat": {"count": "3"})"), "objects[0].box.repeat.count",
               "expected [a, b] integers");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "repeat": {"count": [2, 1.5]})"), "objects[0].box.repeat.count[1]",
               "expected an integer, found a fractional number");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3], "repeat": {"spacing": [1, null]})"), "objects[0].box.repeat.spacing",
               "expected [x, y] numbers");
  EXPECT_FAULT(withBox(R"("size": [1, 2, 3])", R"("visible": "yes", )"), "objects[0].visible",
               "expected true or false, found a string");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": "1", "name": "A", "box": {}}]})",
               "objects[0].id", "expected an integer, found a string");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": ["A"], "box": {}}]})",
               "objects[0].name", "expected a string, found an array");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A", "box": [1]}]})",
               "objects[0].box", "expected an object, found an array");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [7]})", "objects[0]",
               "expected an object, found a number");
}

TEST(ProjectIoErrors, MissingFields) {
  EXPECT_FAULT(withBox(R"("origin": [0, 0, 0])"), "objects[0].box.size", "missing");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"name": "A", "box": {}}]})", "objects[0].id",
               "missing");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "box": {}}]})", "objects[0].name",
               "missing");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A"}]})", "objects[0]",
               R"(no spec: expected one of "box", "extrusion", "masonry", "kifs", "growth", "unit", "town")");
}

TEST(ProjectIoErrors, NonFiniteNumbers) {
  // NaN and Infinity are not JSON.
  EXPECT_FAULT_CONTAINS(withBox(R"("size": [NaN, 1, 1])"), "", "not valid JSON: ");
  EXPECT_FAULT_CONTAINS(withBox(R"("size": [1, Infinity, 1])"), "", "not valid JSON: ");
  // 1e999 is JSON, but no double holds it.
  EXPECT_FAULT_CONTAINS(withBox(R"("size": [1e999, 1, 1])"), "objects[0].box.size[0]", "not finite");
  EXPECT_FAULT_CONTAINS(withBox(R"("size": [1, 1, 1], "rotation": -1e999)"), "objects[0].box.rotation", "not finite");
  EXPECT_FAULT_CONTAINS(withBox(R"("size": [1, 1, 1], "repeat": {"spacing": [0, 2e308]})"),
                        "objects[0].box.repeat.spacing[1]", "not finite");
}

TEST(ProjectIoErrors, Limits) {
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "repeat": {"count": [1000000, 1000000]})"),
               "objects[0].box.repeat.count[0]", "1000000 is larger than 10000");
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "repeat": {"count": [200, 100]})"), "objects[0].box.repeat.count",
               "200 x 100 boxes exceeds the limit of 10000");
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "repeat": {"count": [0, 1]})"), "objects[0].box.repeat.count[0]",
               "0 is outside [1, 10000]");
  EXPECT_FAULT(withBox(R"("size": [1, -2, 1])"), "objects[0].box.size",
               "each extent must be between 0.0001 and 1e+07 m (got -2)");
  EXPECT_FAULT(withBox(R"("size": [0, 1, 1])"), "objects[0].box.size",
               "each extent must be between 0.0001 and 1e+07 m (got 0)");
  EXPECT_FAULT(withBox(R"("size": [1, 1, 2e7])"), "objects[0].box.size",
               "each extent must be between 0.0001 and 1e+07 m (got 2e+07)");
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "origin": [0, 1e8, 0])"), "objects[0].box.origin",
               "coordinates must be finite and within 1e+07 m");
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "rotation": 4000)"), "objects[0].box.rotation",
               "must be a finite angle in degrees");
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "repeat": {"count": [100, 1], "spacing": [2e5, 0]})"),
               "objects[0].box.repeat.spacing", "must be finite and keep the copies within the coordinate limit");
  const std::string longName(limits::kMaxNameLength + 1, 'n');
  EXPECT_FAULT(withBox(R"("size": [1, 1, 1], "material": ")" + longName + "\""), "objects[0].box.material",
               "text longer than 256 bytes");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "name": ")" + longName + "\"}", "name",
               "text longer than 256 bytes");
  EXPECT_FAULT(
      R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": ")" + longName + R"(", "box": {}}]})",
      "objects[0].name", "text longer than 256 bytes");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 0, "name": "A", "box": {}}]})", "objects[0].id",
               "0 is outside [1, 2147483647]");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 2147483648, "name": "A", "box": {}}]})",
               "objects[0].id", "2147483648 is larger than 2147483647");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "", "box": {}}]})",
               "objects[0].name", "name must not be empty");
  // More objects than kMaxObjects.
  std::string many = R"({"format": "corbel", "version": 1, "objects": [)";
  for (std::size_t i = 0; i <= limits::kMaxObjects; ++i) many += i ? ",{}" : "{}";
  many += "]}";
  EXPECT_FAULT(many, "objects", "has 100001 entries, more than the limit of 100000");
}

TEST(ProjectIoErrors, DuplicatesAndNesting) {
  const std::string head = R"({"format": "corbel", "version": 1, "objects": [)";
  const std::string box = R"("box": {"size": [1, 1, 1]})";
  EXPECT_FAULT(head + R"({"id": 1, "name": "A", )" + box + R"(}, {"id": 1, "name": "B", )" + box + "}]}",
               "objects[1].id", "id 1 is used twice");
  EXPECT_FAULT(head + R"({"id": 1, "name": "A", )" + box + R"(}, {"id": 2, "name": "A", )" + box + "}]}",
               "objects[1].name", R"(name "A" is used twice)");
  const std::string deep(100000, '[');
  EXPECT_FAULT_CONTAINS(deep, "", "nesting deeper than 64 levels");
  EXPECT_FAULT_CONTAINS(R"({"format": "corbel", "version": 1, "x": )" + std::string(100000, '{'), "",
                        "nesting deeper than 64 levels");
}

TEST(ProjectIo, UnknownKeysAreWarningsWithPaths) {
  const auto p = corbel::parseProject(R"({"format": "corbel", "version": 1, "author": "me",
      "objects": [{"id": 1, "name": "A", "colour": "red",
                   "box": {"size": [1, 1, 1], "height": 3, "repeat": {"count": [1, 1], "offset": 2}}}]})");
  EXPECT_EQ(p.document.objects.size(), 1u);
  const std::set<std::string> warnings(p.warnings.begin(), p.warnings.end());
  EXPECT_EQ(warnings, (std::set<std::string>{"author: unknown key kept", "objects[0].colour: unknown key kept",
                                             "objects[0].box.height: unknown key kept",
                                             "objects[0].box.repeat.offset: unknown key kept"}));
}

// Keys this build does not know (from a newer corbel, or added by hand) are kept: each is
// warned about, and a save writes it back at the same place with the same value, even after
// edits to the object that holds it. The oracle is the input text read by nlohmann::json.
TEST(ProjectIo, UnknownKeysAreKeptAndWrittenBack) {
  const std::string text = R"({"format": "corbel", "version": 1, "author": {"name": "me", "tags": [1, 2]},
      "objects": [
        {"id": 4, "name": "A", "pose": {"at": [1, 2, 3], "turn": 90},
         "box": {"size": [1, 2, 3], "height": 3, "repeat": {"count": [1, 1], "offset": null}}},
        {"id": 7, "name": "B",
         "extrusion": {"plan": {"loops": [[[0, 0], [4, 0], [4, 3], [0, 3]]], "grid": 0.5},
                       "profiles": [{"name": "p", "points": [[0, 0], [0, 3]], "curve": "arc"}]}}],
      "z-last": "~/tilde and slash"})";
  const corbel::LoadedProject p = corbel::parseProject(text);
  const std::set<std::string> warnings(p.warnings.begin(), p.warnings.end());
  EXPECT_EQ(warnings, (std::set<std::string>{
                          "author: unknown key kept", "z-last: unknown key kept", "objects[0].pose: unknown key kept",
                          "objects[0].box.height: unknown key kept", "objects[0].box.repeat.offset: unknown key kept",
                          "objects[1].extrusion.plan.grid: unknown key kept",
                          "objects[1].extrusion.profiles[0].curve: unknown key kept"}));
  const nlohmann::json in = nlohmann::json::parse(text);
  const std::vector<std::string> pointers = {"/author",
                                             "/z-last",
                                             "/objects/0/pose",
                                             "/objects/0/box/height",
                                             "/objects/0/box/repeat/offset",
                                             "/objects/1/extrusion/plan/grid",
                                             "/objects/1/extrusion/profiles/0/curve"};
  auto expectKept = [&](const std::string& saved) {
    const nlohmann::json out = nlohmann::json::parse(saved);
    for (const std::string& at : pointers) {
      SCOPED_TRACE(at);
      const nlohmann::json::json_pointer ptr(at);
      ASSERT_TRUE(out.contains(ptr));
      EXPECT_EQ(out[ptr], in[ptr]);
    }
  };
  const std::string saved = corbel::serializeProject(p.document);
  expectKept(saved);
  // Edits to the objects that hold them keep them; the save is stable from then on.
  Document d = p.document;
  d.find(4)->name = "A2";
  std::get<BoxSpec>(d.find(4)->spec).size = Vec3(5, 5, 5);
  d.find(7)->visible = false;
  const std::string edited = corbel::serializeProject(d);
  expectKept(edited);
  const nlohmann::json e = nlohmann::json::parse(edited);
  EXPECT_EQ(e["objects"][0]["name"], "A2");
  EXPECT_EQ(e["objects"][0]["box"]["size"], nlohmann::json::parse("[5.0, 5.0, 5.0]"));
  const corbel::LoadedProject again = corbel::parseProject(edited);
  EXPECT_EQ(again.document, d);
  EXPECT_EQ(corbel::serializeProject(again.document), edited);
}

// A kept key whose place is gone (its profile deleted) is dropped, never written elsewhere
// as a known key or into another entry's place that no longer exists.
TEST(ProjectIo, AKeptKeyWhosePlaceIsGoneIsDropped) {
  const corbel::LoadedProject p = corbel::parseProject(R"({"format": "corbel", "version": 1, "objects": [
      {"id": 1, "name": "E", "extrusion": {"plan": {"loops": [[[0, 0], [4, 0], [4, 3], [0, 3]]], "profile": "p"},
       "profiles": [{"name": "p", "points": [[0, 0], [0, 3]]}, {"name": "q", "points": [[0, 0], [0, 2]], "curve": 1}]}}]})");
  Document d = p.document;
  auto& e = std::get<corbel::ExtrusionSpec>(d.objects[0].spec);
  ASSERT_EQ(e.profiles.size(), 2u);
  e.profiles.pop_back();
  const nlohmann::json out = nlohmann::json::parse(corbel::serializeProject(d));
  EXPECT_EQ(out["objects"][0]["extrusion"]["profiles"].size(), 1u);
  EXPECT_FALSE(out["objects"][0]["extrusion"]["profiles"][0].contains("curve"));
}

TEST(ProjectIo, LoadProjectReportsFileProblems) {
  TempDir dir;
  try {
    corbel::loadProject(dir.file("missing.corbel"));
    FAIL() << "missing file loaded";
  } catch (const corbel::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir.file("missing.corbel")), std::string::npos) << what;
    EXPECT_NE(what.find("no such file"), std::string::npos) << what;
  }
  try {
    corbel::loadProject(dir.path());
    FAIL() << "folder loaded";
  } catch (const corbel::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir.path()), std::string::npos) << what;
    EXPECT_NE(what.find("is a folder"), std::string::npos) << what;
  }
  // Larger than kMaxProjectBytes: refused by its size, before reading (a sparse file).
  const std::string big = dir.file("big.corbel");
  writeText(big, "{");
  std::filesystem::resize_file(big, corbel::kMaxProjectBytes + 1);
  try {
    corbel::loadProject(big);
    FAIL() << "oversized file loaded";
  } catch (const corbel::Error& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the limit"), std::string::npos) << e.what();
  }
}

TEST(ProjectIo, LoadProjectPrefixesFaultsWithTheFileName) {
  TempDir dir;
  const std::string path = dir.file("bad.corbel");
  writeText(path, withBox(R"("size": "10")"));
  try {
    corbel::loadProject(path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, path + ": objects[0].box.size");
    EXPECT_EQ(e.reason, "expected [x, y, z] numbers");
  }
  writeText(path, "");
  try {
    corbel::loadProject(path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, path);
    EXPECT_EQ(e.reason, "file is empty");
  }
}

TEST(ProjectIo, SaveProjectWritesTheSerialisation) {
  TempDir dir;
  Document d;
  d.name = "Saved";
  d.add("One", BoxSpec{});
  corbel::saveProject(d, dir.file("p.corbel"));
  EXPECT_EQ(readText(dir.file("p.corbel")), corbel::serializeProject(d));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.corbel"});  // no temporary left behind
  EXPECT_THROW(corbel::saveProject(d, dir.file("no/such/folder/p.corbel")), corbel::Error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.corbel"});
}

}  // namespace

namespace {

corbel::ExtrusionSpec sampleExtrusion() {
  corbel::ExtrusionSpec e;
  e.material = "brick";
  e.roofMaterial = "slate";
  e.baseZ = 0.5;
  e.priority = corbel::Priority::MinimiseVolume;
  corbel::Profile hip;
  hip.name = "hip";
  hip.points = {{0, 0}, {3, 3}};
  hip.tags = {"roof"};
  corbel::Profile wall;
  wall.name = "wall+gable";
  wall.points = {{0, 0}, {0, 2.5}, {0.1, 6}};
  wall.tags = {"wall", ""};
  e.profiles = {hip, wall};
  corbel::PlanLoop outer;
  outer.points = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  outer.profile = {0, 1, 0, 1};
  corbel::PlanLoop hole;
  hole.points = {{2, 2}, {2, 4}, {4, 4}, {4, 2}};
  hole.profile = {0, 0, 0, 0};
  e.loops = {outer, hole};
  corbel::PlanStep dormer;
  dormer.name = "dormer";
  dormer.anchor = {0, 0, false, 0.25, 2.5};
  dormer.width = 2;
  dormer.depth = 0.1;
  dormer.frontProfile = 1;
  dormer.sideProfile = 0;
  corbel::PlanStep bay;
  bay.anchor = {0, 2, true, 3.0, 0.0};
  bay.shape = corbel::StepShape::Bay;
  bay.cant = 0.5;
  bay.frontProfile = bay.sideProfile = 1;
  corbel::PlanStep forced;
  forced.shape = corbel::StepShape::Forced;
  forced.anchor = {0, 1, false, 0.5, 1.0};
  forced.points = {{-1, 0}, {0, 2}, {1, 0}};
  forced.frontProfile = 1;
  e.steps = {dormer, bay, forced};
  e.anchors = {{"door", {0, 0, true, 4.5, 0.0}},
               {"windows", {0, 0, false, 0.1, 1.0}, corbel::FeatureKind::Window, {1.2, 1.4, 0.12},
                {corbel::RepeatKind::Grid, 0.9, 3.5, 2.0, 2.5}},
               {"pot", {0, 1, false, 0.5, 4.0}, corbel::FeatureKind::ChimneyPot, {0.3, 0.6, 0.25},
                {corbel::RepeatKind::Row, 0.7, 0.0, 0.5, 3.0}}};
  e.steps[0].repeat = {corbel::RepeatKind::Row, 0.75, 0.0, 2.5, 3.0};
  e.offsets = {{2.5, {{1, -0.3, -100, 1, 0}}, 0}};
  return e;
}

std::string withExtrusion(const std::string& body) {
  return R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A", "extrusion": {)" + body + "}}]}";
}

}  // namespace

// Extrusion specs survive save → load exactly; a uniform plan is written with one "profile".
TEST(ProjectIo, ExtrusionSpecsRoundTrip) {
  Document d;
  d.add("house", sampleExtrusion());
  corbel::ExtrusionSpec uniform = sampleExtrusion();
  for (auto& l : uniform.loops) l.profile.assign(l.points.size(), 1);
  d.add("uniform", uniform);
  const std::string text = corbel::serializeProject(d);
  const corbel::LoadedProject back = corbel::parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document), text);
  EXPECT_NE(text.find(R"("profile": "wall+gable")"), std::string::npos);
  EXPECT_NE(text.find(R"("edge_profiles")"), std::string::npos);
}

// Features and repeats: written only when present, so files without them load unchanged; a
// feature named without a size gets its kind's size.
TEST(ProjectIo, MeshAnchorFeaturesAndRepeats) {
  const std::string profiles = R"("profiles": [{"name": "hip", "points": [[0, 0], [1, 1]]}])";
  const std::string plan = R"(, "plan": {"loops": [[[0, 0], [10, 0], [10, 6]]]})";
  const auto loaded = corbel::parseProject(withExtrusion(profiles + plan + R"(, "anchors": [
      {"loop": 0, "edge": 0, "fraction": 0.5, "name": "plain"},
      {"loop": 0, "edge": 0, "fraction": 0.1, "height": 1, "name": "w", "feature": "window",
       "repeat": {"kind": "row", "along": 0.9, "spacing": 2}}])"));
  EXPECT_TRUE(loaded.warnings.empty());
  const auto& e = std::get<corbel::ExtrusionSpec>(loaded.document.objects[0].spec);
  ASSERT_EQ(e.anchors.size(), 2u);
  EXPECT_EQ(e.anchors[0].feature, corbel::FeatureKind::None);
  EXPECT_EQ(e.anchors[0].repeat.kind, corbel::RepeatKind::None);
  EXPECT_EQ(e.anchors[1].feature, corbel::FeatureKind::Window);
  EXPECT_EQ(e.anchors[1].size, corbel::defaultFeatureSize(corbel::FeatureKind::Window));
  EXPECT_EQ(e.anchors[1].repeat, (corbel::Repeat{corbel::RepeatKind::Row, 0.9, 0.0, 2.0, 3.0}));
  const std::string text = corbel::serializeProject(loaded.document);
  EXPECT_EQ(text.find(R"("feature": "none")"), std::string::npos) << "a plain anchor is written as before";
  EXPECT_EQ(corbel::serializeProject(corbel::parseProject(text).document), text);
}

TEST(ProjectIoErrors, FeatureAndRepeatFaultsNameTheirPath) {
  const std::string head = withExtrusion(R"("profiles": [{"name": "hip", "points": [[0, 0], [1, 1]]}],
      "plan": {"loops": [[[0, 0], [10, 0], [10, 6]]]}, "anchors": [{"loop": 0, "edge": 0, "name": "a", )");
  auto with = [&](const std::string& fields) { return head.substr(0, head.size() - 4) + fields + "}]}}]}"; };
  EXPECT_FAULT(with(R"("feature": "gargoyle")"), "objects[0].extrusion.anchors[0].feature",
               R"(expected "none", "door", "window", "roof_window" or "chimney_pot", found "gargoyle")");
  EXPECT_FAULT(with(R"("feature": 3)"), "objects[0].extrusion.anchors[0].feature", "expected a string, found a number");
  EXPECT_FAULT(with(R"("feature": "door", "size": [1, -2, 0.1])"), "objects[0].extrusion.anchors[0].size[1]",
               "must be greater than 0 and at most 1000 m");
  EXPECT_FAULT(with(R"("feature": "door", "size": [1, 2])"), "objects[0].extrusion.anchors[0].size",
               "expected [width, height, depth] in metres");
  EXPECT_FAULT(with(R"("feature": "door", "size": [1, "2", 1])"), "objects[0].extrusion.anchors[0].size[1]",
               "expected a number, found a string");
  EXPECT_FAULT(with(R"("repeat": {"kind": "row", "along": 0.9, "spacing": 0})"),
               "objects[0].extrusion.anchors[0].repeat.spacing", "must be greater than 0 m");
  EXPECT_FAULT(with(R"("repeat": {"kind": "spiral", "along": 0.9, "spacing": 1})"),
               "objects[0].extrusion.anchors[0].repeat.kind", R"(expected "row" or "grid", found "spiral")");
  EXPECT_FAULT(with(R"("repeat": {"kind": "grid", "along": 0.9, "spacing": 1, "height": 5})"),
               "objects[0].extrusion.anchors[0].repeat.row_spacing", "missing");
  EXPECT_FAULT(with(R"("repeat": {"kind": "row", "along": 0.9, "spacing": 0.0002})"), "objects[0].extrusion.anchors[0].repeat",
               "20001 x 1 instances make 20001, more than the limit of 10000 per extrusion");
}

TEST(ProjectIoErrors, ExtrusionFaultsNameTheirPath) {
  const std::string profiles = R"("profiles": [{"name": "hip", "points": [[0, 0], [1, 1]]}])";
  EXPECT_FAULT(withExtrusion(profiles + R"(, "plan": {"loops": [[[0, 0], [1, 0], [1, 1], [0, "1"]]]})"),
               "objects[0].extrusion.plan.loops[0][3]", "expected [x, y] numbers");
  EXPECT_FAULT(withExtrusion(profiles + R"(, "plan": {"loops": [[[0, 0], [1, 0], [1, 1]]], "profile": "gable"})"),
               "objects[0].extrusion.plan.profile", R"(no profile named "gable" in this object's profiles)");
  EXPECT_FAULT(withExtrusion(profiles + R"(, "plan": {"loops": [[[0, 0], [1, 0], [1, 1]]], "edge_profiles": [["hip"]]})"),
               "objects[0].extrusion.plan.edge_profiles[0]", "expected one profile per edge (3), found 1");
  EXPECT_FAULT(withExtrusion(R"("plan": {"loops": []}, "profiles": [{"name": "a", "points": []}, {"name": "a", "points": []}])"),
               "objects[0].extrusion.profiles[1].name", R"(profile name "a" is used twice)");
  EXPECT_FAULT(withExtrusion(profiles + R"(, "plan": {"loops": []}, "priority": "tallest")"),
               "objects[0].extrusion.priority", R"(expected "maximise_volume", "minimise_volume" or "manual", found "tallest")");
  const std::string plan = R"(, "plan": {"loops": [[[0, 0], [1, 0], [1, 1]]]})";
  EXPECT_FAULT(withExtrusion(profiles + plan + R"(, "steps": [{"anchor": {"loop": 0, "edge": 0}, "width": 1, "depth": 1, "front_profile": "x"}])"),
               "objects[0].extrusion.steps[0].front_profile", R"(no profile named "x" in this object's profiles)");
  EXPECT_FAULT(withExtrusion(profiles + plan + R"(, "steps": [{"anchor": {"loop": 0, "edge": 0, "fraction": 0.5, "at": 2}, "width": 1, "depth": 1, "front_profile": "hip"}])"),
               "objects[0].extrusion.steps[0].anchor", R"(give either "fraction" (relative anchor) or "at" (absolute anchor), not both)");
  EXPECT_FAULT(withExtrusion(profiles + plan + R"(, "steps": [{"anchor": {"loop": 0, "edge": 0}, "width": 1, "depth": 1, "shape": "dome", "front_profile": "hip"}])"),
               "objects[0].extrusion.steps[0].shape", R"(expected "rectangle", "bay" or "forced", found "dome")");
  EXPECT_FAULT_CONTAINS(withExtrusion(profiles + plan + R"(, "anchors": [{"loop": 0, "edge": 0, "fraction": 1.5, "name": "a"}])"),
                        "objects[0].extrusion.anchors[0].fraction", "1.5");
  EXPECT_FAULT(withExtrusion(profiles), "objects[0].extrusion.plan", "missing");
}

// ---------------------------------------------------------------------------------------------
// Plan backgrounds (an image under the plan pane for tracing).

namespace background {

Document withBackground(const std::string& image) {
  Document d;
  d.name = "traced";
  DocObject o;
  o.id = 4;
  o.name = "House";
  BoxSpec b;
  o.spec = b;
  o.background = corbel::PlanBackground{image, 0.025, corbel::Vec2(-3.5, 12.25), 0.4};
  d.objects.push_back(o);
  return d;
}

TEST(ProjectIo, PlanBackgroundIsSavedRelativeToTheProjectFile) {
  TempDir dir;
  const std::string folder = std::filesystem::path(dir.file("x")).parent_path().string();
  const std::string image = folder + "/scans/plan.png";
  const Document doc = withBackground(image);
  corbel::saveProject(doc, dir.file("a.corbel"));
  const std::string a = readText(dir.file("a.corbel"));
  EXPECT_NE(a.find(R"("image": "scans/plan.png")"), std::string::npos) << a;
  EXPECT_NE(a.find(R"("scale": 0.025)"), std::string::npos);
  // Loading resolves it against the file's folder: the same document comes back.
  const corbel::LoadedProject loaded = corbel::loadProject(dir.file("a.corbel"));
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_EQ(loaded.document, doc);
  corbel::saveProject(loaded.document, dir.file("b.corbel"));
  EXPECT_EQ(readText(dir.file("b.corbel")), a) << "save → load → save is byte-identical";
  // From a project one folder down the path climbs out; it still resolves to the image.
  std::filesystem::create_directories(folder + "/sub");
  corbel::saveProject(doc, folder + "/sub/c.corbel");
  EXPECT_NE(readText(folder + "/sub/c.corbel").find(R"("image": "../scans/plan.png")"), std::string::npos);
  EXPECT_EQ(corbel::loadProject(folder + "/sub/c.corbel").document, doc);
  // Without a folder, paths are written and read as they are.
  EXPECT_EQ(corbel::parseProject(corbel::serializeProject(doc)).document, doc);
  const Document rel = withBackground("plan.png");
  EXPECT_EQ(corbel::parseProject(corbel::serializeProject(rel)).document, rel);
  EXPECT_EQ(corbel::parseProject(corbel::serializeProject(rel), "/work/p").document.objects[0].background->image,
            "/work/p/plan.png");
}

TEST(ProjectIo, PlanBackgroundOptionalFieldsTakeDefaults) {
  const Document d = corbel::parseProject(
      R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A", "box": {"size": [1, 1, 1]}, "plan_background": {"image": "/a.png"}}]})")
                         .document;
  ASSERT_TRUE(d.objects.at(0).background);
  EXPECT_EQ(*d.objects[0].background, (corbel::PlanBackground{"/a.png", 0.05, corbel::Vec2(0, 0), 0.5}));
  // An object without one has none, and writes none.
  const Document plain = corbel::parseProject(withBox(R"("size": [1, 1, 1])")).document;
  EXPECT_FALSE(plain.objects.at(0).background);
  EXPECT_EQ(corbel::serializeProject(plain).find("plan_background"), std::string::npos);
}

TEST(ProjectIoErrors, PlanBackgroundFaultsNameTheirPath) {
  auto with = [](const std::string& bg) { return withBox(R"("size": [1, 1, 1])", R"("plan_background": )" + bg + ", "); };
  EXPECT_FAULT(with("[]"), "objects[0].plan_background", "expected an object, found an array");
  EXPECT_FAULT(with("{}"), "objects[0].plan_background.image", "missing");
  EXPECT_FAULT(with(R"({"image": 3})"), "objects[0].plan_background.image", "expected a string, found a number");
  EXPECT_FAULT(with(R"({"image": ""})"), "objects[0].plan_background.image", "the image's path must not be empty");
  EXPECT_FAULT(with(R"({"image": "a.png", "scale": "0.1"})"), "objects[0].plan_background.scale",
               "expected a number, found a string");
  EXPECT_FAULT_CONTAINS(with(R"({"image": "a.png", "scale": 0})"), "objects[0].plan_background.scale", "is outside");
  EXPECT_FAULT(with(R"({"image": "a.png", "origin": [1]})"), "objects[0].plan_background.origin", "expected [x, y] numbers");
  EXPECT_FAULT(with(R"({"image": "a.png", "origin": [1e8, 0]})"), "objects[0].plan_background.origin",
               "must lie within 1e7 m of the origin");
  EXPECT_FAULT(with(R"({"image": "a.png", "opacity": true})"), "objects[0].plan_background.opacity",
               "expected a number, found a boolean");
  EXPECT_FAULT_CONTAINS(with(R"({"image": "a.png", "opacity": 1.5})"), "objects[0].plan_background.opacity", "is outside [0, 1]");
  const corbel::LoadedProject w = corbel::parseProject(with(R"({"image": "a.png", "rotation": 5})"));
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0], "objects[0].plan_background.rotation: unknown key kept");
}

}  // namespace background

// ---------------------------------------------------------------------------------------------
// Masonry objects: a statics model by name with set and freed parameters.

namespace {

std::string withMasonry(const std::string& body) {
  return R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "M", "masonry": {)" + body + "}}]}";
}

}  // namespace

// Parameters are JSON objects keyed by name, so they load in name order.
TEST(ProjectIo, MasonrySpecsRoundTrip) {
  Document d;
  corbel::MasonrySpec m;
  m.model = "barrel-vault";
  m.parameters = {{"buttressWidth", 0.6}, {"radius", 2.0}, {"thickness", 0.25}};
  m.free = {{"buttressWidth", 0.1, 1.5}, {"thickness", 0.05, 0.5}};
  m.friction = 0.6;
  m.kern = 0.1;
  m.material = "limestone";
  d.add("vault", m);
  d.add("defaults", corbel::MasonrySpec{});
  const std::string text = corbel::serializeProject(d);
  const corbel::LoadedProject back = corbel::parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document), text);
  EXPECT_NE(text.find(R"("buttressWidth": [)"), std::string::npos) << "free bounds are [lo, hi] by name";
  // Only the model is required; the rest takes the defaults.
  const auto minimal = corbel::parseProject(withMasonry(R"("model": "tower")"));
  const auto& spec = std::get<corbel::MasonrySpec>(minimal.document.objects[0].spec);
  corbel::MasonrySpec tower;
  tower.model = "tower";
  EXPECT_EQ(spec, tower);
  EXPECT_EQ(spec.friction, 0.7);
  EXPECT_FALSE(spec.conservativeFriction);
  EXPECT_EQ(spec.kern, 0.0);
  EXPECT_TRUE(spec.loads.empty());
  EXPECT_EQ(spec.material, "stone");
}

// A key the reader does not know inside a placement that is otherwise the identity (a misspelt
// "translation") is kept through a save: the placement is written to hold it.
TEST(ProjectIo, AnUnknownKeyInAnIdentityPlacementIsKept) {
  const std::string text = R"({"format": "corbel", "version": 2, "objects": [{"id": 1, "name": "B", "box": {"size": [1, 1, 1]},
    "placement": {"traslation": [1, 2, 3]}}]})";
  const corbel::LoadedProject p = corbel::parseProject(text);
  ASSERT_EQ(p.warnings.size(), 1u);
  const std::string saved = corbel::serializeProject(p.document);
  EXPECT_NE(saved.find("traslation"), std::string::npos) << saved;
  EXPECT_EQ(corbel::parseProject(saved).document, p.document);
}

// Loads and α/√2 round trip: a point load keeps its block, offset and force, a pressure its face;
// a spec without them writes neither key (older files stay as they were).
TEST(ProjectIo, MasonryLoadsAndConservativeFrictionRoundTrip) {
  Document d;
  corbel::MasonrySpec m;
  m.model = "arch-on-columns";
  m.conservativeFriction = true;
  m.loads = {{"bell", "arch/voussoir 4", corbel::Vec3(0, 0.1, 0.05), corbel::Vec3(0, 0, -9810), -1, 0.0},
             {"wind 1", "left column/drum 0", corbel::Vec3(0.0), corbel::Vec3(0.0), 2, 600.0}};
  m.ground = false;
  d.add("arch", m);
  d.add("plain", corbel::MasonrySpec{});
  const std::string text = corbel::serializeProject(d);
  const corbel::LoadedProject back = corbel::parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document), text);
  EXPECT_NE(text.find(R"("conservative_friction": true)"), std::string::npos);
  EXPECT_NE(text.find(R"("ground": false)"), std::string::npos);
  EXPECT_EQ(text.find(R"("ground": true)"), std::string::npos) << "the default is not written";
  EXPECT_NE(text.find(R"("face": 2)"), std::string::npos);
  EXPECT_EQ(text.find(R"("conservative_friction": false)"), std::string::npos);
  const std::string plain = corbel::serializeProject([] {
    Document one;
    one.add("plain", corbel::MasonrySpec{});
    return one;
  }());
  EXPECT_EQ(plain.find("loads"), std::string::npos);
}

TEST(ProjectIoErrors, MasonryFaultsNameTheirPath) {
  EXPECT_FAULT(withMasonry(R"("parameters": {})"), "objects[0].masonry.model", "missing");
  EXPECT_FAULT(withMasonry(R"("model": "")"), "objects[0].masonry.model", "the model name must not be empty");
  EXPECT_FAULT_CONTAINS(withMasonry(R"("model": "tower", "parameters": [1, 2])"), "objects[0].masonry.parameters",
                        "object");
  EXPECT_FAULT_CONTAINS(withMasonry(R"("model": "tower", "parameters": {"x1": "0.1"})"),
                        "objects[0].masonry.parameters.x1", "number");
  EXPECT_FAULT(withMasonry(R"("model": "tower", "free": {"x1": [0.2, -0.2]})"), "objects[0].masonry.free.x1",
               "the lower bound 0.200000 is above the upper bound -0.200000");
  EXPECT_FAULT_CONTAINS(withMasonry(R"("model": "tower", "free": {"x1": 0.2})"), "objects[0].masonry.free.x1",
                        "[x, y]");
  EXPECT_FAULT(withMasonry(R"("model": "tower", "kern": 1)"), "objects[0].masonry.kern",
               "the kern factor must be below 1 (1 would shrink every contact to a point)");
  EXPECT_FAULT_CONTAINS(withMasonry(R"("model": "tower", "friction": -0.1)"), "objects[0].masonry.friction", "-0.1");
  EXPECT_FAULT(withMasonry(R"("model": "tower", "loads": [{"block": "b", "face": 1, "pressure": 5, "force": [0, 0, 1]}])"),
               "objects[0].masonry.loads[0]", "a load has either a face and a pressure or a force, not both");
  EXPECT_FAULT(withMasonry(R"("model": "tower", "loads": [{"block": "b", "pressure": 5}])"),
               "objects[0].masonry.loads[0]", "a pressure needs the face it acts on (\"face\": index in the block)");
  EXPECT_FAULT(withMasonry(R"("model": "tower", "loads": [{"force": [0, 0, 1]}])"), "objects[0].masonry.loads[0].block",
               "missing");
  EXPECT_FAULT_CONTAINS(withMasonry(R"("model": "tower", "loads": [{"block": "b", "face": -1, "pressure": 5}])"),
                        "objects[0].masonry.loads[0].face", "-1");
  EXPECT_FAULT(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "M", "masonry": {"model": "tower"}, "box": {"size": [1, 1, 1]}}]})",
               "objects[0]", "more than one spec: an object has exactly one");
}

// ---------------------------------------------------------------------------------------------
// KIFS buildings: the numbers of kifs/params.h under the same names.

namespace {

// A project of one object whose spec is `key` with this body.
std::string withSpec(const std::string& key, const std::string& body) {
  return R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "O", ")" + key + R"(": {)" + body +
         "}}]}";
}
std::string withKifs(const std::string& body) { return withSpec("kifs", body); }

}  // namespace

TEST(ProjectIo, KifsSpecsRoundTripEveryField) {
  corbel::KifsSpec k;
  k.preset = "h-building";
  k.iterations = 4;
  k.scale = 2.5;
  k.centre = corbel::Vec3(0.9, 0.8, 0.3);
  k.r1 = corbel::Vec3(1, 2, 3);
  k.r2 = corbel::Vec3(0, 15, 0);
  k.bailout = 500;
  k.mass = {"H", 12, 10, 15, 3.5, 1.1, "", "w3", 64};
  k.facade = {5.5, corbel::Vec3(0.2, 0.1, 0.3), 0.5, 1.5, 0.2, -0.1};
  k.floors = {3.2, 0.4, 0.9};
  k.curvilinear = {true, 9, 0.1, 1.2, -12, 0.5};
  k.trace = {250, 0.8, 1.3, 1.5};
  k.meshResolution = 96;
  k.material = "concrete";
  corbel::Document d;
  d.add("tower", k);
  d.add("defaults", corbel::KifsSpec{});
  const std::string text = corbel::serializeProject(d);
  const corbel::LoadedProject back = corbel::parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document), text);
  // Every key is optional: an empty spec is the default building.
  const auto minimal = corbel::parseProject(withKifs(""));
  EXPECT_EQ(std::get<corbel::KifsSpec>(minimal.document.objects[0].spec), corbel::KifsSpec{});
  const auto unknown = corbel::parseProject(withKifs(R"("mass": {"roof": 1}, "colour": 2)"));
  ASSERT_EQ(unknown.warnings.size(), 2u);
  EXPECT_EQ(unknown.warnings[0], "objects[0].kifs.colour: unknown key kept");
  EXPECT_EQ(unknown.warnings[1], "objects[0].kifs.mass.roof: unknown key kept");
}

TEST(ProjectIoErrors, KifsFaultsNameTheirPath) {
  EXPECT_FAULT_CONTAINS(withKifs(R"("scale": "3")"), "objects[0].kifs.scale", "number");
  EXPECT_FAULT_CONTAINS(withKifs(R"("iterations": 2.5)"), "objects[0].kifs.iterations", "integer");
  EXPECT_FAULT_CONTAINS(withKifs(R"("iterations": -1)"), "objects[0].kifs.iterations", "-1");
  EXPECT_FAULT_CONTAINS(withKifs(R"("centre": [1, 2])"), "objects[0].kifs.centre", "[x, y, z]");
  EXPECT_FAULT_CONTAINS(withKifs(R"("mass": [])"), "objects[0].kifs.mass", "object");
  EXPECT_FAULT(withKifs(R"("mass": {"footprint": "L"})"), "objects[0].kifs.mass.footprint",
               R"(expected "box", "T", "H" or "object", found "L")");
  EXPECT_FAULT_CONTAINS(withKifs(R"("facade": {"r": [0, "x", 0]})"), "objects[0].kifs.facade.r", "[x, y, z]");
  EXPECT_FAULT_CONTAINS(withKifs(R"("curvilinear": {"enabled": 1})"), "objects[0].kifs.curvilinear.enabled", "true or false");
  EXPECT_FAULT_CONTAINS(withKifs(R"("trace": {"maxSteps": 0})"), "objects[0].kifs.trace.maxSteps", "0");
  EXPECT_FAULT_CONTAINS(withKifs(R"("meshResolution": 5000)"), "objects[0].kifs.meshResolution", "5000");
  EXPECT_FAULT_CONTAINS(withKifs(R"("floors": {"sy": null})"), "objects[0].kifs.floors.sy", "number");
}

// ---------------------------------------------------------------------------------------------
// Growth sites: the site file's object embedded as it is, the seed and the steps.

namespace {

std::string withGrowth(const std::string& body) { return withSpec("growth", body); }

}  // namespace

TEST(ProjectIo, GrowthSpecsRoundTripWithTheSiteAsAnObject) {
  corbel::GrowthSpec g;
  g.site = R"({"envelope":{"origin":[0,0],"size":[30,20]},"seeds":[{"at":[1.5,2],"target_area":40}],"storeys":3})";
  g.seed = 42;
  g.steps = 17;
  corbel::Document d;
  d.add("site", g);
  d.add("to the end", corbel::GrowthSpec{g.site, 1, -1});
  const std::string text = corbel::serializeProject(d);
  EXPECT_NE(text.find(R"("storeys": 3)"), std::string::npos) << "the site is an object in the file, not a string";
  const corbel::LoadedProject back = corbel::parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document), text);
  const auto minimal = corbel::parseProject(withGrowth(R"("site": {})"));
  EXPECT_EQ(std::get<corbel::GrowthSpec>(minimal.document.objects[0].spec), (corbel::GrowthSpec{"{}", 1, 0}));
}

TEST(ProjectIoErrors, GrowthFaultsNameTheirPath) {
  EXPECT_FAULT(withGrowth(R"("seed": 1)"), "objects[0].growth.site", "missing");
  EXPECT_FAULT_CONTAINS(withGrowth(R"("site": "alpha.json")"), "objects[0].growth.site", "object");
  EXPECT_FAULT_CONTAINS(withGrowth(R"("site": {}, "seed": -1)"), "objects[0].growth.seed", "-1");
  EXPECT_FAULT_CONTAINS(withGrowth(R"("site": {}, "steps": -2)"), "objects[0].growth.steps", "-2");
  EXPECT_FAULT_CONTAINS(withGrowth(R"("site": {}, "steps": 1.5)"), "objects[0].growth.steps", "integer");
  const auto w = corbel::parseProject(withGrowth(R"("site": {}, "speed": 2)"));
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0], "objects[0].growth.speed: unknown key kept");
}

TEST(ProjectIo, UnitSpecsRoundTripAsRowsOfBoxes) {
  corbel::UnitSpec u;
  u.parts = {{{36, 13, 0}, {42, 20, 3}}, {{42, 13, 0}, {45.25, 17, 3}}};
  u.material = "glass";
  corbel::Document d;
  d.add("form unit 1", u);
  const std::string text = corbel::serializeProject(d);
  const corbel::LoadedProject back = corbel::parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document), text);
  const auto minimal = corbel::parseProject(withSpec("unit", R"("parts": [[0, 0, 0, 3, 3, 3]])"));
  EXPECT_EQ(std::get<corbel::UnitSpec>(minimal.document.objects[0].spec).material, "plaster");
}

TEST(ProjectIoErrors, UnitFaultsNameTheirPath) {
  EXPECT_FAULT(withSpec("unit", R"("material": "glass")"), "objects[0].unit.parts", "missing");
  EXPECT_FAULT_CONTAINS(withSpec("unit", R"("parts": [])"), "objects[0].unit.parts", "at least one");
  EXPECT_FAULT_CONTAINS(withSpec("unit", R"("parts": [[0, 0, 0, 3, 3]])"), "objects[0].unit.parts[0]", "x0, y0");
  EXPECT_FAULT_CONTAINS(withSpec("unit", R"("parts": [[0, 0, 0, 3, 3, 3], [5, 0, 0, 4, 3, 3]])"),
                        "objects[0].unit.parts[1]", "hi must exceed lo");
}

namespace {
std::string withTown(const std::string& body) { return withSpec("town", body); }
}  // namespace

TEST(ProjectIo, TownSpecsRoundTripWithPathsRelativeToTheProject) {
  corbel::TownSpec t;
  t.footprints = "/data/p/town.geojson";
  t.crs = "EPSG:32632";
  t.layer = "buildings";
  t.where = "height > 3";
  t.style = "/data/styles/oldtown.json";
  t.seed = 7;
  t.detail = "steps";
  t.overrides["w12"].type = "garage";
  t.overrides["w13"].profiles = {{"street", "gable"}, {"back", "hip"}};
  corbel::TownStreet st;
  st.points = {{0.5, -3}, {40.25, 12}, {80, 0}};
  st.width = 8;
  st.setback = 0;
  st.depth = 15.5;
  st.plotWidth = 6;
  st.bothSides = false;
  st.skeletonPlots = true;
  t.streets = {st, corbel::TownStreet{{{{1, 2}, {3, 4}}}}};
  t.overrides["street 1/left/0"].type = "garage";
  t.overrides["w7"].edges = {{"0:3", "oldtown gable"}, {"1:0", "oldtown eaves"}};
  corbel::Document d;
  d.add("town", t);
  const std::string text = corbel::serializeProject(d, "/data/p");
  EXPECT_NE(text.find(R"("footprints": "town.geojson")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("style": "../styles/oldtown.json")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("crs": "EPSG:32632")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("where": "height > 3")"), std::string::npos) << text;
  const corbel::LoadedProject back = corbel::parseProject(text, "/data/p");
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, d);
  EXPECT_EQ(corbel::serializeProject(back.document, "/data/p"), text);
  // Saved elsewhere, the paths follow the new folder and still name the same files.
  const std::string moved = corbel::serializeProject(back.document, "/data/q");
  EXPECT_EQ(corbel::parseProject(moved, "/data/q").document, d);
}

TEST(ProjectIo, TownSpecsCanEmbedTheirFootprintsAndStyle) {
  const auto p = corbel::parseProject(withTown(
      R"("footprints": {"type": "FeatureCollection", "features": []}, "style": {"name": "s", "profiles": [], "types": []})"));
  const auto& t = std::get<corbel::TownSpec>(p.document.objects[0].spec);
  EXPECT_TRUE(t.footprints.empty());
  EXPECT_EQ(t.footprintsJson, R"({"features":[],"type":"FeatureCollection"})");
  EXPECT_EQ(t.styleJson, R"({"name":"s","profiles":[],"types":[]})");
  EXPECT_EQ(t.seed, 1u);
  EXPECT_EQ(t.detail, "full");
  const std::string text = corbel::serializeProject(p.document);
  EXPECT_EQ(corbel::parseProject(text).document, p.document);
  EXPECT_EQ(corbel::serializeProject(corbel::parseProject(text).document), text);
}

TEST(ProjectIoErrors, TownFaultsNameTheirPath) {
  EXPECT_FAULT(withTown(R"("style": "s.json")"), "objects[0].town.footprints", "missing");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson")"), "objects[0].town.style", "missing");
  EXPECT_FAULT(withTown(R"("footprints": 3, "style": "s.json")"), "objects[0].town.footprints",
               "expected a file path (a string) or the JSON itself (an object), found a number");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": ["s.json"])"), "objects[0].town.style",
               "expected a file path (a string) or the JSON itself (an object), found an array");
  EXPECT_FAULT(withTown(R"("footprints": "", "style": "s.json")"), "objects[0].town.footprints",
               "the path must not be empty");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "seed": -1)"), "objects[0].town.seed",
               "-1 is outside [0, 9007199254740992]");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "detail": "high")"), "objects[0].town.detail",
               R"(expected "massing", "steps" or "full", found "high")");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "overrides": [])"),
               "objects[0].town.overrides", "expected an object, found an array");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "overrides": {"w1": {}})"),
               R"(objects[0].town.overrides["w1"])", R"(overrides nothing: expected "type", "profiles" or "edges")");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "overrides": {"w1": {"type": 2}})"),
               R"(objects[0].town.overrides["w1"].type)", "expected a string, found a number");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "overrides": {"w1": {"profiles": {"roof": "x"}}})"),
               R"(objects[0].town.overrides["w1"].profiles.roof)", R"(expected "street", "side" or "back", found "roof")");
  EXPECT_FAULT(withTown(R"("footprints": "f.geojson", "style": "s.json", "overrides": {"w1": {"profiles": {"side": ""}}})"),
               R"(objects[0].town.overrides["w1"].profiles.side)", "the profile name must not be empty");
  const std::string fs = R"("footprints": "f.geojson", "style": "s.json", )";
  EXPECT_FAULT(withTown(fs + R"("overrides": {"w1": {"edges": ["0:1"]}})"), R"(objects[0].town.overrides["w1"].edges)",
               "expected an object, found an array");
  for (const char* key : {"3", "a:1", "0:", ":2", "01:2", "0:-1", "0:1:2", "1234567:0"})
    EXPECT_FAULT(withTown(fs + R"("overrides": {"w1": {"edges": {")" + key + R"(": "x"}}})"),
                 std::string(R"(objects[0].town.overrides["w1"].edges[")") + key + R"("])",
                 std::string(R"(expected an edge "LOOP:EDGE" (as "0:3"), found ")") + key + "\"");
  EXPECT_FAULT(withTown(fs + R"("overrides": {"w1": {"edges": {"0:1": 4}}})"),
               R"(objects[0].town.overrides["w1"].edges["0:1"])", "expected a string, found a number");
  EXPECT_FAULT(withTown(fs + R"("overrides": {"w1": {"edges": {"0:1": ""}}})"),
               R"(objects[0].town.overrides["w1"].edges["0:1"])", "the profile name must not be empty");
  EXPECT_FAULT(withTown(fs + R"("streets": {})"), "objects[0].town.streets", "expected an array of streets");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"width": 8}])"), "objects[0].town.streets[0].points", "missing");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0], [1, 0]], "plots": "voronoi"}])"),
               "objects[0].town.streets[0].plots", R"(expected "normals" or "skeleton", found "voronoi")");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0]]}])"), "objects[0].town.streets[0].points",
               "expected 2 to 64 control points, found 1");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0], [1]]}])"), "objects[0].town.streets[0].points[1]",
               "expected [x, y]");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0], [1, "a"]]}])"),
               "objects[0].town.streets[0].points[1][1]", "expected a number, found a string");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0], [0, 0]]}])"), "objects[0].town.streets[0].points[1]",
               "repeats the point before it");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0], [9, 0]], "depth": 1}])"),
               "objects[0].town.streets[0].depth", "1 is outside [3, 200]");
  EXPECT_FAULT(withTown(fs + R"("streets": [{"points": [[0, 0], [9, 0]], "both_sides": 1}])"),
               "objects[0].town.streets[0].both_sides", "expected true or false, found a number");
  const auto w = corbel::parseProject(withTown(R"("footprints": "f.geojson", "style": "s.json", "colour": 1)"));
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0], "objects[0].town.colour: unknown key kept");
}

// An extrusion's masonry section (core/stone_walls.h): read with its defaults, written back
// as read, a key this build does not know kept with a warning, bad values refused at their path.
TEST(ProjectIo, ExtrusionMasonrySection) {
  const std::string profiles = R"("profiles": [{"name": "hip", "points": [[0, 0], [0, 3], [2, 5]]}])";
  const std::string plan = R"(, "plan": {"loops": [[[0, 0], [4, 0], [4, 4], [0, 4]]]})";
  const corbel::LoadedProject p = corbel::parseProject(withExtrusion(
      profiles + plan +
      R"(, "masonry": {"thickness": 0.6, "ties": true, "mortar": "lime", "wind_pressure": 750, "wind_direction": -90, "openings": {"door": "flat_arch", "window": "semicircular_arch"}})"));
  const auto& e = std::get<corbel::ExtrusionSpec>(p.document.objects.at(0).spec);
  ASSERT_TRUE(e.masonry.has_value());
  EXPECT_EQ(e.masonry->thickness, 0.6);
  EXPECT_TRUE(e.masonry->ties);
  EXPECT_EQ(e.masonry->windPressure, 750.0);
  EXPECT_EQ(e.masonry->windDirection, -90.0);
  EXPECT_EQ(e.masonry->courseHeight, 0.4);      // defaults
  EXPECT_EQ(e.masonry->coveringWeight, 600.0);
  ASSERT_EQ(e.masonry->openings.size(), 2u);
  EXPECT_EQ(e.masonry->openings[0].anchor, "door");
  EXPECT_EQ(e.masonry->openings[0].head, corbel::OpeningHead::FlatArch);
  EXPECT_EQ(e.masonry->openings[1].anchor, "window");
  EXPECT_EQ(e.masonry->openings[1].head, corbel::OpeningHead::SemicircularArch);
  EXPECT_NE(std::find(p.warnings.begin(), p.warnings.end(), "objects[0].extrusion.masonry.mortar: unknown key kept"),
            p.warnings.end());
  const std::string saved = corbel::serializeProject(p.document);
  const corbel::LoadedProject again = corbel::parseProject(saved);
  EXPECT_EQ(std::get<corbel::ExtrusionSpec>(again.document.objects.at(0).spec), e);
  EXPECT_EQ(nlohmann::json::parse(saved)["objects"][0]["extrusion"]["masonry"]["mortar"], "lime");
  // Without the section, none is written.
  const corbel::LoadedProject plain = corbel::parseProject(withExtrusion(profiles + plan));
  EXPECT_FALSE(std::get<corbel::ExtrusionSpec>(plain.document.objects.at(0).spec).masonry.has_value());
  // No wind: none written.
  const corbel::LoadedProject calm = corbel::parseProject(withExtrusion(profiles + plan + R"(, "masonry": {})"));
  EXPECT_EQ(corbel::serializeProject(calm.document).find("wind"), std::string::npos);
  EXPECT_EQ(corbel::serializeProject(plain.document).find("masonry"), std::string::npos);

  EXPECT_FAULT(withExtrusion(profiles + plan + R"(, "masonry": {"thickness": 0})"),
               "objects[0].extrusion.masonry.thickness", "must be greater than 0 and at most 1000 m");
  EXPECT_FAULT(withExtrusion(profiles + plan + R"(, "masonry": {"openings": {"door": "gothic"}})"),
               "objects[0].extrusion.masonry.openings.door", R"(expected "lintel", "flat_arch" or "semicircular_arch", found "gothic")");
  EXPECT_FAULT_CONTAINS(withExtrusion(profiles + plan + R"(, "masonry": {"wind_pressure": -5})"),
                        "objects[0].extrusion.masonry.wind_pressure", "-5 is outside [0, 100000]");
  EXPECT_FAULT_CONTAINS(withExtrusion(profiles + plan + R"(, "masonry": {"ties": 1})"), "objects[0].extrusion.masonry.ties",
               "expected true or false");
}
