// document.h: ids, names, removal, and every limit of checkBoxSpec naming its field.
#include "core/document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using corbel::BoxSpec;
using corbel::DocObject;
using corbel::Document;
using corbel::Vec3;
namespace limits = corbel::limits;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

DocObject object(corbel::ObjectId id, std::string name) {
  DocObject o;
  o.id = id;
  o.name = std::move(name);
  o.spec = BoxSpec{};
  return o;
}

TEST(Document, NextIdIsOnePastTheLargest) {
  Document d;
  EXPECT_EQ(d.nextId(), 1u);
  d.objects.push_back(object(3, "a"));
  d.objects.push_back(object(7, "b"));
  d.objects.push_back(object(5, "c"));
  EXPECT_EQ(d.nextId(), 8u);
  EXPECT_TRUE(d.remove(7));
  EXPECT_EQ(d.nextId(), 6u);
}

TEST(Document, AddGivesFreshIdsAndUniqueNames) {
  Document d;
  const auto a = d.add("House", BoxSpec{});
  const auto b = d.add("House", BoxSpec{});
  const auto c = d.add("House", BoxSpec{});
  EXPECT_EQ(a, 1u);
  EXPECT_EQ(b, 2u);
  EXPECT_EQ(c, 3u);
  EXPECT_EQ(d.find(a)->name, "House");
  EXPECT_EQ(d.find(b)->name, "House 2");
  EXPECT_EQ(d.find(c)->name, "House 3");
  EXPECT_EQ(d.uniqueName("House"), "House 4");
  EXPECT_EQ(d.uniqueName("Barn"), "Barn");
  // A gap is reused: after removing "House 2" that name is free again.
  d.remove(b);
  EXPECT_EQ(d.uniqueName("House"), "House 2");
}

TEST(Document, FindAndRemove) {
  Document d;
  d.objects.push_back(object(4, "Tower"));
  d.objects.push_back(object(9, "Hall"));
  const Document& cd = d;
  ASSERT_NE(cd.find(9), nullptr);
  EXPECT_EQ(cd.find(9)->name, "Hall");
  EXPECT_EQ(cd.find(5), nullptr);
  ASSERT_NE(d.findByName("Tower"), nullptr);
  EXPECT_EQ(d.findByName("Tower")->id, 4u);
  EXPECT_EQ(d.findByName("tower"), nullptr);
  d.find(4)->visible = false;
  EXPECT_FALSE(cd.find(4)->visible);
  EXPECT_FALSE(d.remove(5));
  EXPECT_EQ(d.objects.size(), 2u);
  EXPECT_TRUE(d.remove(4));
  EXPECT_EQ(d.objects.size(), 1u);
  EXPECT_EQ(d.find(4), nullptr);
  EXPECT_FALSE(d.remove(4));
}

TEST(Document, EqualityComparesEveryField) {
  Document a;
  a.add("Box", BoxSpec{});
  Document b = a;
  EXPECT_EQ(a, b);
  std::get<BoxSpec>(b.objects[0].spec).spacing_y = 1;
  EXPECT_NE(a, b);
  b = a;
  b.objects[0].visible = false;
  EXPECT_NE(a, b);
  b = a;
  b.name = "other";
  EXPECT_NE(a, b);
}

// The field a checkBoxSpec message names: the text before ": ".
std::string fieldOf(const std::optional<std::string>& message) {
  if (!message) return "<accepted>";
  return message->substr(0, message->find(": "));
}

TEST(CheckBoxSpec, DefaultsAndBoundaryValuesAreAccepted) {
  EXPECT_EQ(corbel::checkBoxSpec(BoxSpec{}), std::nullopt);
  BoxSpec b;
  b.origin = Vec3(limits::kMaxCoordinate, -limits::kMaxCoordinate, 0);
  b.size = Vec3(limits::kMinSize, limits::kMaxCoordinate, 1);
  b.rotation_deg = -3600;
  b.repeat_x = 100;
  b.repeat_y = 100;  // exactly kMaxRepeat boxes
  b.spacing_x = limits::kMaxCoordinate / 100;
  b.material = std::string(limits::kMaxNameLength, 'm');
  EXPECT_EQ(corbel::checkBoxSpec(b), std::nullopt) << *corbel::checkBoxSpec(b);
}

TEST(CheckBoxSpec, OriginLimit) {
  for (int k = 0; k < 3; ++k) {
    for (double bad : {kNaN, kInf, -kInf, 1.0000001e7, -2e7}) {
      BoxSpec b;
      b.origin[k] = bad;
      EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "origin") << "k=" << k << " value " << bad;
    }
  }
}

TEST(CheckBoxSpec, SizeLimits) {
  for (int k = 0; k < 3; ++k) {
    for (double bad : {kNaN, kInf, 0.0, -1.0, -0.0, 0.99e-4, 1.0000001e7}) {
      BoxSpec b;
      b.size[k] = bad;
      const auto message = corbel::checkBoxSpec(b);
      EXPECT_EQ(fieldOf(message), "size") << "k=" << k << " value " << bad;
    }
  }
  BoxSpec b;
  b.size[1] = 0.0;
  EXPECT_NE(corbel::checkBoxSpec(b)->find("got 0"), std::string::npos) << *corbel::checkBoxSpec(b);
}

TEST(CheckBoxSpec, RotationLimit) {
  for (double bad : {kNaN, kInf, 3600.5, -7200.0}) {
    BoxSpec b;
    b.rotation_deg = bad;
    EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "rotation") << bad;
  }
}

TEST(CheckBoxSpec, RepeatCountLimits) {
  for (auto [x, y] : {std::pair{0, 1}, std::pair{1, 0}, std::pair{-3, 2}, std::pair{101, 100}, std::pair{10001, 1},
                      std::pair{1000000, 1000000}}) {
    BoxSpec b;
    b.repeat_x = x;
    b.repeat_y = y;
    const auto message = corbel::checkBoxSpec(b);
    EXPECT_EQ(fieldOf(message), "repeat.count") << x << "x" << y;
    if (x > 0 && y > 0) {
      EXPECT_NE(message->find(std::to_string(limits::kMaxRepeat)), std::string::npos) << *message;
    }
  }
}

TEST(CheckBoxSpec, RepeatSpacingLimits) {
  BoxSpec b;
  b.spacing_x = kNaN;
  EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "repeat.spacing");
  b = BoxSpec{};
  b.spacing_y = -kInf;
  EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "repeat.spacing");
  // The row would reach beyond the coordinate limit.
  b = BoxSpec{};
  b.repeat_x = 1001;
  b.spacing_x = 1e4;
  EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "repeat.spacing");
  b = BoxSpec{};
  b.repeat_y = 2;
  b.spacing_y = -6e6;
  EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "repeat.spacing");
}

TEST(CheckBoxSpec, MaterialNameLength) {
  BoxSpec b;
  b.material = std::string(limits::kMaxNameLength + 1, 'm');
  EXPECT_EQ(fieldOf(corbel::checkBoxSpec(b)), "material");
}

}  // namespace
