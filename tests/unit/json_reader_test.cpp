// json_reader.h: JSON paths in errors, typed access, integer ranges, and parseJsonText's
// handling of empty, deep, malformed and out-of-range input.
#include "core/json_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

namespace {

using corbel::InputError;
using corbel::JsonReader;
using nlohmann::json;

// Runs f, which must throw InputError; returns it.
template <class F>
InputError inputError(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("<none>", "<none>");
}

TEST(JsonReader, BuildsPathsThroughObjectsAndArrays) {
  const json j = json::parse(R"({"objects": [{"box": {"size": [1, 2, "x"]}}, {"name": 5}]})");
  const JsonReader root(j, "");
  EXPECT_EQ(root.path(), "");
  const JsonReader objects = root.at("objects");
  EXPECT_EQ(objects.path(), "objects");
  const auto items = objects.array(10);
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].path(), "objects[0]");
  EXPECT_EQ(items[1].path(), "objects[1]");
  EXPECT_EQ(items[0].at("box").path(), "objects[0].box");
  EXPECT_EQ(items[0].at("box").at("size").path(), "objects[0].box.size");
  EXPECT_EQ(items[0].at("box").find("size")->path(), "objects[0].box.size");
  EXPECT_EQ(items[0].at("box").at("size").array(3)[2].path(), "objects[0].box.size[2]");

  const InputError e = inputError([&] { items[0].at("box").at("size").vec3(); });
  EXPECT_EQ(e.where, "objects[0].box.size");
  EXPECT_EQ(e.reason, "expected [x, y, z] numbers");
  EXPECT_EQ(std::string(e.what()), "objects[0].box.size: expected [x, y, z] numbers");

  const InputError n = inputError([&] { items[1].at("name").string(10); });
  EXPECT_EQ(n.where, "objects[1].name");
  EXPECT_EQ(n.reason, "expected a string, found a number");

  const InputError m = inputError([&] { items[1].at("id"); });
  EXPECT_EQ(m.where, "objects[1].id");
  EXPECT_EQ(m.reason, "missing");
  EXPECT_EQ(inputError([&] { root.at("format"); }).where, "format");
}

TEST(JsonReader, FindAndExpectObject) {
  const json j = json::parse(R"({"a": {"b": 1}, "list": [1]})");
  const JsonReader root(j, "");
  EXPECT_FALSE(root.find("zzz").has_value());
  EXPECT_TRUE(root.find("a").has_value());
  const InputError e = inputError([&] { root.at("list").at("b"); });
  EXPECT_EQ(e.where, "list");
  EXPECT_EQ(e.reason, "expected an object, found an array");
  EXPECT_EQ(inputError([&] { root.at("a").at("b").find("c"); }).reason, "expected an object, found a number");
}

TEST(JsonReader, UnknownKeysAreFullPaths) {
  const json j = json::parse(R"({"format": 1, "extra": 2, "box": {"size": 1, "colour": 3, "zz": 4}})");
  const JsonReader root(j, "");
  EXPECT_EQ(root.unknownKeys({"format", "box"}), std::vector<std::string>{"extra"});
  EXPECT_EQ(root.at("box").unknownKeys({"size"}), (std::vector<std::string>{"box.colour", "box.zz"}));
  EXPECT_TRUE(root.at("box").unknownKeys({"size", "colour", "zz"}).empty());
  EXPECT_TRUE(JsonReader(json::array(), "x").unknownKeys({}).empty());
}

TEST(JsonReader, OddKeysAreQuotedInPaths) {
  // Keys that are not plain words appear as JSON strings in brackets, so a path never holds
  // raw control characters and stays unambiguous.
  const json j = json::parse(R"({"box": {"two words": 1, "a.b": 2, "": 3, "\u0000x": 4, "plain_key-2": 5}})");
  const JsonReader box = JsonReader(j, "").at("box");
  std::vector<std::string> keys = box.unknownKeys({});
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys, (std::vector<std::string>{"box.plain_key-2", R"(box[""])", R"(box["\u0000x"])", R"(box["a.b"])",
                                            R"(box["two words"])"}));
  EXPECT_EQ(inputError([&] { box.at("no such"); }).where, R"(box["no such"])");
  EXPECT_EQ(JsonReader(j, "").at("box").at("a.b").path(), R"(box["a.b"])");
  const InputError e = inputError([] { corbel::parseJsonText(R"({"\u0000": [{"k k": [1, -1e999]}]})"); });
  EXPECT_EQ(e.where, R"(["\u0000"][0]["k k"][1])");
}

TEST(JsonReader, ArrayLimit) {
  const json j = json::parse("[1, 2, 3]");
  EXPECT_EQ(JsonReader(j, "list").array(3).size(), 3u);
  const InputError e = inputError([&] { JsonReader(j, "list").array(2); });
  EXPECT_EQ(e.where, "list");
  EXPECT_EQ(e.reason, "has 3 entries, more than the limit of 2");
  EXPECT_EQ(inputError([&] { JsonReader(json("s"), "p").array(2); }).reason, "expected an array, found a string");
}

TEST(JsonReader, TypeNamesInMessages) {
  auto reason = [](const json& v) { return inputError([&] { JsonReader(v, "v").number(); }).reason; };
  EXPECT_EQ(reason(json(nullptr)), "expected a number, found null");
  EXPECT_EQ(reason(json::object()), "expected a number, found an object");
  EXPECT_EQ(reason(json::array()), "expected a number, found an array");
  EXPECT_EQ(reason(json("1")), "expected a number, found a string");
  EXPECT_EQ(reason(json(true)), "expected a number, found a boolean");
  EXPECT_EQ(inputError([] { JsonReader(json(1), "flag").boolean(); }).reason, "expected true or false, found a number");
}

TEST(JsonReader, Numbers) {
  EXPECT_EQ(JsonReader(json(2.5), "").number(), 2.5);
  EXPECT_EQ(JsonReader(json(-7), "").number(), -7.0);
  EXPECT_EQ(JsonReader(json(18446744073709551615ull), "").number(), 18446744073709551615.0);
  const InputError nan = inputError([] { JsonReader(json(std::numeric_limits<double>::quiet_NaN()), "x").number(); });
  EXPECT_EQ(nan.where, "x");
  EXPECT_EQ(nan.reason, "number is not finite");
  EXPECT_EQ(inputError([] { JsonReader(json(-HUGE_VAL), "x").number(); }).reason, "number is not finite");
  EXPECT_EQ(JsonReader(json(3.0), "").number(0, 3), 3.0);
  EXPECT_EQ(JsonReader(json(0), "").number(0, 3), 0.0);
  EXPECT_EQ(inputError([] { JsonReader(json(3.5), "x").number(0, 3); }).reason, "3.5 is outside [0, 3]");
  EXPECT_EQ(inputError([] { JsonReader(json(-1), "x").number(0, 3); }).reason, "-1 is outside [0, 3]");
}

TEST(JsonReader, IntegerRanges) {
  auto integer = [](const json& v, long lo, long hi) { return JsonReader(v, "n").integer(lo, hi); };
  auto reason = [&](const json& v, long lo, long hi) { return inputError([&] { integer(v, lo, hi); }).reason; };
  // Integers of each nlohmann storage type, at and beyond the bounds.
  EXPECT_EQ(integer(json(5u), 1, 5), 5);
  EXPECT_EQ(integer(json(1), 1, 5), 1);
  EXPECT_EQ(integer(json(-5), -5, 5), -5);
  EXPECT_EQ(reason(json(6u), 1, 5), "6 is larger than 5");
  EXPECT_EQ(reason(json(0), 1, 5), "0 is outside [1, 5]");
  EXPECT_EQ(reason(json(-6), -5, 5), "-6 is outside [-5, 5]");
  EXPECT_EQ(reason(json(18446744073709551615ull), 0, LONG_MAX),
            "18446744073709551615 is larger than 9223372036854775807");
  EXPECT_EQ(integer(json(9223372036854775807ull), 0, LONG_MAX), LONG_MAX);
  EXPECT_EQ(integer(json(LLONG_MIN), LONG_MIN, 0), LONG_MIN);
  // An unsigned value can never satisfy a range below zero.
  EXPECT_EQ(reason(json(18446744073709551615ull), -10, -1), "18446744073709551615 is larger than -1");
  // Whole floating-point values are integers; fractional ones are not.
  EXPECT_EQ(integer(json(3.0), 1, 5), 3);
  EXPECT_EQ(integer(json(-0.0), 0, 5), 0);
  EXPECT_EQ(integer(json(1e4), 1, 10000), 10000);
  EXPECT_EQ(reason(json(3.5), 1, 5), "expected an integer, found a fractional number");
  EXPECT_EQ(reason(json(-0.25), -5, 5), "expected an integer, found a fractional number");
  EXPECT_EQ(reason(json(1e30), 1, 5), "1e+30 is outside [1, 5]");
  EXPECT_EQ(reason(json(-1e30), 1, 5), "-1e+30 is outside [1, 5]");
  // 2^63 is a whole number just past LONG_MAX (it rounds to (double)LONG_MAX).
  EXPECT_NE(reason(json(9223372036854775808.0), 0, LONG_MAX).find("is outside"), std::string::npos);
  EXPECT_EQ(reason(json("3"), 1, 5), "expected an integer, found a string");
}

TEST(JsonReader, IntegersParsedFromText) {
  // The same through the parser, which picks the storage type from the text.
  auto parsed = [](const char* text) { return corbel::parseJsonText(text); };
  EXPECT_EQ(JsonReader(parsed("[7]")[0], "").integer(1, 10), 7);
  EXPECT_EQ(JsonReader(parsed("[7.0]")[0], "").integer(1, 10), 7);
  EXPECT_EQ(JsonReader(parsed("[7e0]")[0], "").integer(1, 10), 7);
  EXPECT_EQ(JsonReader(parsed("[-0]")[0], "").integer(0, 10), 0);
  EXPECT_EQ(inputError([&] { JsonReader(parsed("[7.5]")[0], "").integer(1, 10); }).reason,
            "expected an integer, found a fractional number");
  EXPECT_EQ(inputError([&] { JsonReader(parsed("[99999999999999999999999]")[0], "").integer(1, 10); }).reason,
            "1e+23 is outside [1, 10]");
}

TEST(JsonReader, StringsBooleansAndPairs) {
  EXPECT_EQ(JsonReader(json("abc"), "").string(3), "abc");
  EXPECT_EQ(inputError([] { JsonReader(json("abcd"), "s").string(3); }).reason, "text longer than 3 bytes");
  EXPECT_TRUE(JsonReader(json(true), "").boolean());
  EXPECT_FALSE(JsonReader(json(false), "").boolean());

  const json pair = json::parse("[2, 3]");
  EXPECT_EQ(JsonReader(pair, "c").integerPair(1, 5), (std::pair<long, long>{2, 3}));
  const InputError second = inputError([] { JsonReader(json::parse("[2, 9]"), "c").integerPair(1, 5); });
  EXPECT_EQ(second.where, "c[1]");
  EXPECT_EQ(second.reason, "9 is larger than 5");
  EXPECT_EQ(inputError([] { JsonReader(json::parse("[2]"), "c").integerPair(1, 5); }).reason,
            "expected [a, b] integers");

  const corbel::Vec2 v = JsonReader(json::parse("[1.5, -2]"), "").vec2();
  EXPECT_EQ(v, corbel::Vec2(1.5, -2));
  EXPECT_EQ(inputError([] { JsonReader(json::parse("[1, 2, 3]"), "s").vec2(); }).reason, "expected [x, y] numbers");
  const corbel::Vec3 p = JsonReader(json::parse("[1, 2.5, -3]"), "").vec3();
  EXPECT_EQ(p, corbel::Vec3(1, 2.5, -3));
  EXPECT_EQ(inputError([] { JsonReader(json::parse("[1, 2]"), "o").vec3(); }).reason, "expected [x, y, z] numbers");
  EXPECT_EQ(inputError([] { JsonReader(json::parse("[1, null, 2]"), "o").vec3(); }).reason,
            "expected [x, y, z] numbers");
  // A non-finite element is reported at its own index.
  json withNan = json::array({1.0, 2.0, std::numeric_limits<double>::quiet_NaN()});
  const InputError e = inputError([&] { JsonReader(withNan, "o").vec3(); });
  EXPECT_EQ(e.where, "o[2]");
  EXPECT_EQ(e.reason, "number is not finite");
}

TEST(ParseJsonText, EmptyAndWhitespace) {
  for (const char* text : {"", " ", "\n\t\r\n  "}) {
    const InputError e = inputError([&] { corbel::parseJsonText(text); });
    EXPECT_EQ(e.where, "");
    EXPECT_EQ(e.reason, "file is empty");
  }
}

TEST(ParseJsonText, SyntaxErrorsGiveLineAndColumn) {
  const InputError e = inputError([] { corbel::parseJsonText("{\n  \"a\": 1,\n  \"b\": }"); });
  EXPECT_EQ(e.where, "");
  EXPECT_EQ(e.reason.rfind("not valid JSON: ", 0), 0u) << e.reason;
  EXPECT_NE(e.reason.find("line 3, column"), std::string::npos) << e.reason;
  EXPECT_EQ(e.reason.find("json.exception"), std::string::npos) << e.reason;
  for (const char* bad :
       {"{", "[1, 2", "nope", "{\"a\": NaN}", "[Infinity]", "{\"a\" 1}", "[1,]", "\"\xff\"", "[1] [2]"}) {
    const InputError b = inputError([&] { corbel::parseJsonText(bad); });
    EXPECT_EQ(b.where, "") << bad;
    EXPECT_EQ(b.reason.rfind("not valid JSON: ", 0), 0u) << bad << " → " << b.reason;
  }
}

TEST(ParseJsonText, NumberTooLargeForADoubleIsReportedAtItsPath) {
  const InputError a = inputError([] { corbel::parseJsonText(R"({"objects": [{"box": {"size": [1, 1e999, 2]}}]})"); });
  EXPECT_EQ(a.where, "objects[0].box.size[1]");
  EXPECT_NE(a.reason.find("not finite"), std::string::npos) << a.reason;
  EXPECT_NE(a.reason.find("1e999"), std::string::npos) << a.reason;
  const InputError b = inputError([] { corbel::parseJsonText(R"([[0, [5]], {"k": -1e400}])"); });
  EXPECT_EQ(b.where, "[1].k");
  const InputError c = inputError([] { corbel::parseJsonText("1e999"); });
  EXPECT_EQ(c.where, "");
  EXPECT_NE(c.reason.find("not finite"), std::string::npos);
  // Underflow is fine: it is just zero.
  EXPECT_EQ(corbel::parseJsonText("[1e-999]")[0].get<double>(), 0.0);
}

TEST(ParseJsonText, ParsesLikeNlohmann) {
  const std::string text =
      R"({"a": [1, -2, 3.5, "x", null, true, {"b": []}], "a2": {"c": {"d": [[], [{}]]}}, "u": 18446744073709551615})";
  EXPECT_EQ(corbel::parseJsonText(text), json::parse(text));
  // Duplicate keys: the last one wins, as in nlohmann's own parser.
  EXPECT_EQ(corbel::parseJsonText(R"({"k": 1, "k": [2]})"), json::parse(R"({"k": 1, "k": [2]})"));
  EXPECT_EQ(corbel::parseJsonText("  [ ]  "), json::array());
  EXPECT_EQ(corbel::parseJsonText("\"s\""), json("s"));
}

TEST(ParseJsonText, NestingLimit) {
  const std::string ok = std::string(64, '[') + std::string(64, ']');
  EXPECT_NO_THROW(corbel::parseJsonText(ok));
  const std::string deep = std::string(65, '[') + std::string(65, ']');
  const InputError e = inputError([&] { corbel::parseJsonText(deep); });
  EXPECT_EQ(e.where, "");
  EXPECT_EQ(e.reason, "line 1, column 65: nesting deeper than 64 levels");
  // Objects count too, and the limit is a parameter.
  const InputError o = inputError([] { corbel::parseJsonText("{\"a\":\n{\"b\": {}}}", 2); });
  EXPECT_EQ(o.reason, "line 2, column 7: nesting deeper than 2 levels");
  // Brackets inside strings (escaped quotes included) do not count.
  const std::string inString = "[\"" + std::string(100, '[') + "\\\"" + std::string(100, '{') + "\"]";
  EXPECT_EQ(corbel::parseJsonText(inString)[0].get<std::string>().size(), 201u);
  // 100,000 levels are refused before any parsing.
  const std::string huge = std::string(100000, '[');
  EXPECT_NE(inputError([&] { corbel::parseJsonText(huge); }).reason.find("nesting deeper"), std::string::npos);
}

}  // namespace
