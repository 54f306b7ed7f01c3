// splitTouchingLoops: a face whose loop touches itself parts into two faces (docs/extrude.md,
// "Decisions").
#include "extrude/extrude.h"
#include "extrude/sweep.h"
#include "saved_plan_checks.h"
#include "shell_checks.h"
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace corbel::extrude::test {
namespace {

// A prism of height 1 over a loop of the plane z = 0, counter-clockwise seen from above: the
// top face first, the bottom second, then one wall per edge. Its vertices are the loop's at
// z = 1 (0 … n−1) and at z = 0 (n … 2n−1).
SweepOutput prism(const std::vector<Vec2>& plan) {
  SweepOutput s;
  const int n = static_cast<int>(plan.size());
  for (const Vec2& p : plan) s.points.emplace_back(p[0], p[1], 1);
  for (const Vec2& p : plan) s.points.emplace_back(p[0], p[1], 0);
  std::vector<int> top, bottom;
  for (int i = 0; i < n; ++i) top.push_back(i);
  for (int i = n - 1; i >= 0; --i) bottom.push_back(n + i);
  addFace(s, top, Vec3(0, 0, 1));
  addFace(s, bottom, Vec3(0, 0, -1));
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const Vec2 d = plan[j] - plan[i];
    addFace(s, {j, i, n + i, n + j}, Vec3(d[1], -d[0], 0).normalized());
  }
  return s;
}

// Two triangles of area 1/2 pinched at c = (2, y), y above the edge (3, 0) → (1, 0) that
// runs over them: seen from above the loop c → (2.5, −1) → (3, 0) → (1, 0) → (1.5, −1)
// crosses that edge just beside c, so it is not simple.
std::vector<Vec2> pinched(double y) { return {{2, y}, {2.5, -1}, {3, 0}, {1, 0}, {1.5, -1}}; }
constexpr int kTouchedWall = 2 + 2;  // the wall under the edge (3, 0) → (1, 0)

TEST(SplitTouchingLoops, PartsALoopAtTheCornerThatTouchesItsOwnEdge) {
  SweepOutput s = prism(pinched(1e-8));
  ASSERT_EQ(unpairedEdges(s), 0u);
  ASSERT_FALSE(simpleInItsPlane(s, s.faces[0], s.faces[0].loops[0]));
  const double volume = measure(s).volume;
  // The top and the bottom each touch themselves once.
  EXPECT_EQ(splitTouchingLoops(s, 1e-6), 2u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  ASSERT_EQ(s.faces.size(), 2u + 5u + 2u);
  for (const ShellFace& f : s.faces) EXPECT_TRUE(simpleInItsPlane(s, f, f.loops[0]));
  // By hand: the top parts into the triangles c, (2.5, −1), (3, 0) and c, (1, 0), (1.5, −1),
  // each of base 1 and height 1 (less the 1e-8 that c stands above their bases' line).
  EXPECT_EQ(s.faces[0].loops[0], (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(s.faces[7].loops[0], (std::vector<int>{0, 3, 4}));
  EXPECT_NEAR(topArea(s, 0), 0.5, 1e-7);
  EXPECT_NEAR(topArea(s, 7), 0.5, 1e-7);
  // The wall under the touched edge takes c at both ends of the prism: (1, 0) → c → (3, 0)
  // along its top, from below its bottom.
  const std::vector<int>& wall = s.faces[kTouchedWall].loops[0];
  EXPECT_EQ(std::count(wall.begin(), wall.end(), 0), 1);
  EXPECT_EQ(std::count(wall.begin(), wall.end(), 5), 1);
  // What the shell holds is as before but for the walls' bend to c: the surface moves by at
  // most c's distance from the edge (1e-8) over the touched wall (2 m²).
  EXPECT_NEAR(measure(s).volume, volume, 2e-8);
  EXPECT_NEAR(measure(s).volume, 1.0, 1e-7);
}

// The distance decides: a corner 1e-4 from the edge is no touch within 1e-6, one within 1e-3.
TEST(SplitTouchingLoops, LeavesACornerFartherThanTheLength) {
  SweepOutput s = prism(pinched(1e-4));
  const std::vector<int> before = s.faces[0].loops[0];
  EXPECT_EQ(splitTouchingLoops(s, 1e-6), 0u);
  EXPECT_EQ(s.faces[0].loops[0], before);
  EXPECT_EQ(splitTouchingLoops(s, 1e-3), 2u);
  EXPECT_EQ(unpairedEdges(s), 0u);
}

// A loop that crosses itself at the touch (a figure of eight: one lobe runs clockwise) is not
// two faces of the face's side, and stays.
TEST(SplitTouchingLoops, LeavesAFigureOfEight) {
  SweepOutput s = prism({{2, 1e-8}, {2.5, 1}, {3, 0}, {1, 0}, {1.5, -1}});
  const std::vector<int> before = s.faces[0].loops[0];
  EXPECT_EQ(splitTouchingLoops(s, 1e-6), 0u);
  EXPECT_EQ(s.faces[0].loops[0], before);
}

// Without its bottom the prism is not closed: which face lies across the edge is not known.
TEST(SplitTouchingLoops, LeavesAShellThatIsNotClosed) {
  SweepOutput s = prism(pinched(1e-8));
  s.faces.erase(s.faces.begin() + 1);
  EXPECT_EQ(splitTouchingLoops(s, 1e-6), 0u);
  EXPECT_EQ(s.faces.size(), 1u + 5u);
}

// random87918: a roof's corner 8.4e-8 m from the same face's edge up to the plan's centre, a
// lobe of 0.11 m² beyond it. Split, the shell passes the shell checks.
TEST(SplitTouchingLoops, ARoofThatTouchesItsOwnEdgeIsSplit) {
  expectClean("tests/data/extrude/loop_touching_itself.corbel");
}

}  // namespace
}  // namespace corbel::extrude::test
