// Renderer properties, each checked against an independent computation: projected areas from
// the camera matrices and the shoelace formula, the documented lighting model, visibility.
#include "core/massing.h"
#include "core/materials.h"
#include "core/textures.h"
#include "golden_support.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace corbel::test {
namespace {

constexpr int kSize = 400;

Scene oneBox(const BoxSpec& spec, ObjectId id = 1) {
  Scene s;
  s.replaceObject(id, Kind::Mass, "box", buildBoxes(spec));
  return s;
}

render::OrbitCamera topCamera() {
  render::OrbitCamera c;
  render::applyPreset(c, render::CameraPreset::Top);
  c.target = Vec3(0, 0, 0);
  c.distance = 40.0;
  return c;
}

// Pixel position of a world point (top row = 0), through the camera's own matrices.
glm::dvec2 project(const render::OrbitCamera& c, const Vec3& p, int w, int h) {
  const glm::dvec4 clip = c.projection(double(w) / h) * c.view() * glm::dvec4(p[0], p[1], p[2], 1.0);
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return {(ndc.x * 0.5 + 0.5) * w, (1.0 - (ndc.y * 0.5 + 0.5)) * h};
}

// The lighting model documented in shaders/mesh.frag.glsl, for a face with normal n.
std::array<int, 3> litColor(const Rgb& albedo, const Vec3& n) {
  const Vec3 sun = Vec3(0.45, -0.35, 0.82).normalized();
  const double s = std::max(0.0, OpenMesh::dot(n, sun));
  const double sky = 0.5 + 0.5 * n[2];
  const double sunColor[3] = {1.0, 0.97, 0.9}, low[3] = {0.28, 0.26, 0.24}, high[3] = {0.42, 0.46, 0.52};
  std::array<int, 3> out;
  for (int k = 0; k < 3; ++k) {
    const double light = sunColor[k] * s * 0.75 + low[k] + (high[k] - low[k]) * sky;
    out[k] = static_cast<int>(std::lround(std::pow(std::clamp(albedo[k] * light, 0.0, 1.0), 1.0 / 2.2) * 255.0));
  }
  return out;
}

std::size_t countColor(const render::Image& img, const std::array<int, 3>& c, int tol) {
  std::size_t n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto* p = img.at(x, y);
      if (std::abs(p[0] - c[0]) <= tol && std::abs(p[1] - c[1]) <= tol && std::abs(p[2] - c[2]) <= tol) ++n;
    }
  return n;
}

render::RenderSettings plain() {
  render::RenderSettings s;
  s.grid = false;
  s.edges = false;
  return s;
}

TEST(Renderer, TopViewCoversTheProjectedRoofArea) {
  BoxSpec spec;
  spec.size = Vec3(10, 6, 4);
  spec.rotation_deg = 30;
  spec.material = "plaster";
  const Scene scene = oneBox(spec);
  const auto camera = topCamera();
  const render::Image img = render::renderImage(sharedRenderer(), scene, camera, kSize, kSize, plain());

  // Roof corners projected by the camera matrices; area by the shoelace formula.
  const MeshData mesh = buildBoxes(spec);
  std::vector<glm::dvec2> roof;
  for (int i = 0; i < 6; ++i)
    if (mesh.tags[mesh.faceTag[i]] == "roof")
      for (int v : mesh.faces[i]) roof.push_back(project(camera, mesh.points[v], kSize, kSize));
  ASSERT_EQ(roof.size(), 4u);
  double area = 0;
  for (std::size_t i = 0; i < roof.size(); ++i) {
    const auto& a = roof[i];
    const auto& b = roof[(i + 1) % roof.size()];
    area += a.x * b.y - a.y * b.x;
  }
  area = std::abs(area) / 2;
  const auto roofColor = litColor(materialColor("plaster", Kind::Mass), Vec3(0, 0, 1));
  const double covered = double(countColor(img, roofColor, 3));
  EXPECT_GT(area, 1000.0);
  EXPECT_NEAR(covered / area, 1.0, 0.02) << "covered " << covered << " px, projected " << area << " px";
}

TEST(Renderer, FaceShadingFollowsTheDocumentedLightingModel) {
  BoxSpec spec;
  spec.size = Vec3(8, 8, 3);
  spec.material = "brick";
  const Scene scene = oneBox(spec);
  const auto camera = topCamera();
  const render::Image img = render::renderImage(sharedRenderer(), scene, camera, kSize, kSize, plain());
  const auto expected = litColor(materialColor("brick", Kind::Mass), Vec3(0, 0, 1));
  const auto* centre = img.at(kSize / 2, kSize / 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(centre[k], expected[k], 2) << "channel " << k;
}

TEST(Renderer, EmptySceneShowsOnlyTheSkyGradient) {
  const Scene scene;
  render::RenderSettings s = plain();
  const render::Image img = render::renderImage(sharedRenderer(), scene, topCamera(), 64, 64, s);
  // Top row is close to the gradient's top colour, bottom row to its bottom colour, and every
  // column of a row is the same.
  const auto* top = img.at(0, 0);
  const auto* bottom = img.at(0, 63);
  EXPECT_NEAR(top[0], 0.62 * 255, 3);
  EXPECT_NEAR(top[2], 0.84 * 255, 3);
  EXPECT_NEAR(bottom[0], 0.93 * 255, 3);
  for (int y = 0; y < 64; ++y)
    for (int x = 1; x < 64; ++x)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(img.at(x, y)[k], img.at(0, y)[k]);
}

TEST(Renderer, HiddenObjectsAreNotDrawn) {
  BoxSpec spec;
  spec.size = Vec3(8, 8, 3);
  const Scene scene = oneBox(spec);
  render::RenderSettings s = plain();
  const render::Image empty = render::renderImage(sharedRenderer(), Scene(), topCamera(), 64, 64, s);
  s.visible = [](ObjectId) { return false; };
  const render::Image hidden = render::renderImage(sharedRenderer(), scene, topCamera(), 64, 64, s);
  EXPECT_EQ(hidden.rgba, empty.rgba);
  s.visible = [](ObjectId) { return true; };
  const render::Image shown = render::renderImage(sharedRenderer(), scene, topCamera(), 64, 64, s);
  EXPECT_NE(shown.rgba, empty.rgba);
}

// Outlines: two unit quads sharing the edge x = 0, the second folded up by `degrees` about it,
// tagged `tag`. By hand: 7 edges, the shared one among them unless it is not drawn. A plain
// face's fold is an outline at any angle; a meshed KIFS building's ("kifs") only past 30°.
std::size_t outlineEdges(double degrees, const std::string& tag) {
  MeshData m;
  const int t = m.addTag(tag);
  const double c = std::cos(degrees * 3.14159265358979323846 / 180.0), s = std::sin(degrees * 3.14159265358979323846 / 180.0);
  const int a = m.addPoint(Vec3(0, 0, 0)), b = m.addPoint(Vec3(0, 1, 0));
  const int p = m.addPoint(Vec3(-1, 0, 0)), q = m.addPoint(Vec3(-1, 1, 0));
  const int r = m.addPoint(Vec3(c, 0, s)), u = m.addPoint(Vec3(c, 1, s));
  m.addFace({p, a, b, q}, t);
  m.addFace({a, r, u, b}, t);
  Scene scene;
  scene.replaceObject(1, Kind::Ornament, "folded", m);
  render::RenderSettings settings = plain();
  settings.edges = true;
  sharedRenderer().setScene(scene, settings);
  return sharedRenderer().edgeCount();
}

TEST(Renderer, AMeshedKifsBuildingIsOutlinedAtItsCreasesOnly) {
  EXPECT_EQ(outlineEdges(10, ""), 7u);
  EXPECT_EQ(outlineEdges(10, "kifs"), 6u);
  EXPECT_EQ(outlineEdges(29, "kifs"), 6u);
  EXPECT_EQ(outlineEdges(31, "kifs"), 7u);
  EXPECT_EQ(outlineEdges(90, "kifs"), 7u);
  EXPECT_EQ(outlineEdges(0, ""), 6u);  // one planar face cut in two: no outline inside it
}

TEST(Renderer, OverlayArrowIsDrawnWhereItProjects) {
  const Scene scene;
  auto& renderer = sharedRenderer();
  const auto camera = topCamera();
  renderer.overlay().clear();
  renderer.overlay().arrow(Vec3(-8, 0, 0), Vec3(8, 0, 0), {1.0f, 0.0f, 0.0f, 1.0f}, 0.25);
  const render::Image img = render::renderImage(renderer, scene, camera, kSize, kSize, plain());
  renderer.overlay().clear();
  // The shaft's midpoint and a point inside the head are red.
  const glm::dvec2 mid = project(camera, Vec3(0, 0, 0), kSize, kSize);
  const glm::dvec2 head = project(camera, Vec3(6.5, 0, 0), kSize, kSize);
  auto reddish = [&](glm::dvec2 p) {
    bool any = false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const auto* q = img.at(int(p.x) + dx, int(p.y) + dy);
        // A 1-pixel shaft is blended by multisampling: red must dominate clearly.
        any = any || (int(q[0]) - std::max(int(q[1]), int(q[2])) > 60);
      }
    return any;
  };
  EXPECT_TRUE(reddish(mid));
  EXPECT_TRUE(reddish(head));
}

// A polygon laid on a face recolours it (the Scene's faces are pushed back by the polygon
// offset), lit by the same model as a face of that colour.
TEST(Renderer, OverlayPolygonRecoloursTheFaceItCovers) {
  const Scene scene = oneBox(BoxSpec{.size = Vec3(8, 8, 3), .material = "brick"});
  auto& renderer = sharedRenderer();
  const Rgb blue{0.1f, 0.3f, 0.9f};
  renderer.overlay().clear();
  renderer.overlay().polygon({Vec3(-4, -4, 3), Vec3(4, -4, 3), Vec3(4, 4, 3), Vec3(-4, 4, 3)},
                             {blue[0], blue[1], blue[2], 1.0f});
  const render::Image img = render::renderImage(renderer, scene, topCamera(), kSize, kSize, plain());
  renderer.overlay().clear();
  const auto expected = litColor(blue, Vec3(0, 0, 1));
  const auto* centre = img.at(kSize / 2, kSize / 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(centre[k], expected[k], 2) << "channel " << k;
  // Fewer than three corners, or all on one line, draw nothing.
  renderer.overlay().polygon({Vec3(0, 0, 3), Vec3(1, 0, 3)}, {1, 0, 0, 1});
  renderer.overlay().polygon({Vec3(0, 0, 3), Vec3(1, 0, 3), Vec3(2, 0, 3)}, {1, 0, 0, 1});
  EXPECT_TRUE(renderer.overlay().empty());
}

// An arrow inside a solid is hidden in the depth-tested overlay and seen in the one on top.
TEST(Renderer, OverlayOnTopShowsThroughSolids) {
  const Scene scene = oneBox(BoxSpec{.size = Vec3(20, 20, 3), .material = "plaster"});
  auto& renderer = sharedRenderer();
  const auto camera = topCamera();
  const glm::dvec2 head = project(camera, Vec3(6.5, 0, 1.5), kSize, kSize);
  auto redAtHead = [&](const render::Image& img) {
    const auto* q = img.at(int(head.x), int(head.y));
    return int(q[0]) - std::max(int(q[1]), int(q[2])) > 60;
  };
  renderer.overlay().arrow(Vec3(-8, 0, 1.5), Vec3(8, 0, 1.5), {1.0f, 0.0f, 0.0f, 1.0f}, 0.25);
  EXPECT_FALSE(redAtHead(render::renderImage(renderer, scene, camera, kSize, kSize, plain())));
  renderer.overlay().clear();
  renderer.overlayOnTop().arrow(Vec3(-8, 0, 1.5), Vec3(8, 0, 1.5), {1.0f, 0.0f, 0.0f, 1.0f}, 0.25);
  EXPECT_TRUE(redAtHead(render::renderImage(renderer, scene, camera, kSize, kSize, plain())));
  renderer.overlayOnTop().clear();
}

// Textured mode: a square face 8 × 8 m at z = 1 seen from straight above, textured either by a
// tag (the lookup of RenderSettings::tagTextures) or by its material. The oracle: each pixel's
// centre unprojected through the camera's matrices onto the face, its texture coordinates by
// hand (plan (x, y) over the repeat, shifted by whole repeats so the face starts at u = 0 and its
// top at v = 0, v down the image), the generated texels (core/textures.h) sampled bilinearly with
// repeat as GL magnifies, and lit by the documented lighting model.
struct TexturedView {
  render::OrbitCamera camera;
  Scene scene;
};

TexturedView texturedSquare(const std::string& material, double cameraDistance) {
  TexturedView t;
  MeshData m;
  for (const Vec3& p : {Vec3(-4, -4, 1), Vec3(4, -4, 1), Vec3(4, 4, 1), Vec3(-4, 4, 1)}) m.addPoint(p);
  m.addFace({0, 1, 2, 3}, m.addTag("roof"), m.addMaterial(material));
  t.scene.replaceObject(1, Kind::Shell, "square", m);
  t.camera = topCamera();
  t.camera.target = Vec3(0, 0, 1);
  t.camera.distance = cameraDistance;
  return t;
}

// Where pixel (px, py)'s centre sees the plane z = height.
Vec3 pixelOnPlane(const render::OrbitCamera& c, int px, int py, int w, int h, double height) {
  const glm::dmat4 inv = glm::inverse(c.projection(double(w) / h) * c.view());
  const double x = (px + 0.5) / w * 2 - 1, y = 1 - (py + 0.5) / h * 2;
  glm::dvec4 a = inv * glm::dvec4(x, y, -1, 1), b = inv * glm::dvec4(x, y, 1, 1);
  a /= a.w;
  b /= b.w;
  const double s = (height - a.z) / (b.z - a.z);
  return Vec3(a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), height);
}

// Bilinear filtering of the texture at (u, v) with repeat, texel centres at half-integers.
Rgb bilinear(const MaterialTexture& t, double u, double v) {
  const double s = u * t.size - 0.5, r = v * t.size - 0.5;
  const int i0 = int(std::floor(s)), j0 = int(std::floor(r));
  const double fs = s - i0, fr = r - j0;
  auto texel = [&](int i, int j, int k) {
    i = ((i % t.size) + t.size) % t.size;
    j = ((j % t.size) + t.size) % t.size;
    return t.rgb[(std::size_t(j) * t.size + i) * 3 + k] / 255.0;
  };
  Rgb out;
  for (int k = 0; k < 3; ++k)
    out[k] = float((1 - fr) * ((1 - fs) * texel(i0, j0, k) + fs * texel(i0 + 1, j0, k)) +
                   fr * ((1 - fs) * texel(i0, j0 + 1, k) + fs * texel(i0 + 1, j0 + 1, k)));
  return out;
}

struct OracleFit {
  std::size_t pixels = 0, off = 0;  // pixels compared; those with a channel more than 8 off
  double meanError = 0;             // per channel, 0..255
};

// Compares the image inside the square (0.2 m from its edges) with the oracle for a repeat of
// `metres`; `flipV` makes the oracle wrong on purpose (v up the image), to show it can tell.
OracleFit fitTexture(const render::Image& img, const render::OrbitCamera& camera, const MaterialTexture& tex,
                     double metres, bool flipV = false) {
  OracleFit fit;
  double sum = 0;
  // By hand for this square: u = x / metres − floor(−4 / metres), v = ceil(4 / metres) − y / metres.
  const double u0 = std::floor(-4 / metres), v0 = std::ceil(4 / metres);
  for (int py = 0; py < img.height; ++py)
    for (int px = 0; px < img.width; ++px) {
      const Vec3 p = pixelOnPlane(camera, px, py, img.width, img.height, 1.0);
      if (std::abs(p[0]) > 3.8 || std::abs(p[1]) > 3.8) continue;
      const double u = p[0] / metres - u0, v = flipV ? p[1] / metres : v0 - p[1] / metres;
      const auto want = litColor(bilinear(tex, u, v), Vec3(0, 0, 1));
      const auto* got = img.at(px, py);
      int worst = 0;
      for (int k = 0; k < 3; ++k) {
        worst = std::max(worst, std::abs(int(got[k]) - want[k]));
        sum += std::abs(int(got[k]) - want[k]);
      }
      ++fit.pixels;
      fit.off += worst > 8;
    }
  fit.meanError = fit.pixels ? sum / (3.0 * fit.pixels) : 1e9;
  return fit;
}

TEST(RendererTextures, ATagsTextureIsDrawnAtItsRepeatAsTheTexelsSay) {
  // brick at 8 m per repeat: 128 texels over 8 m, about 2.9 pixels per texel (magnified).
  const TexturedView view = texturedSquare("plaster", 12.0);
  const SurfaceTexture brick{"brick", 8.0};
  render::RenderSettings settings = plain();
  settings.textures = true;
  settings.tagTextures = [&](ObjectId, const std::string& tag) { return tag == "roof" ? &brick : nullptr; };
  const render::Image img = render::renderImage(sharedRenderer(), view.scene, view.camera, kSize, kSize, settings);
  const MaterialTexture& tex = *materialTexture("brick");
  const OracleFit fit = fitTexture(img, view.camera, tex, 8.0);
  EXPECT_GT(fit.pixels, 100000u);
  EXPECT_LT(double(fit.off) / fit.pixels, 0.01) << fit.off << " of " << fit.pixels << " pixels off";
  EXPECT_LT(fit.meanError, 1.5);
  // The oracle can tell: with v running the wrong way, or at the brick's own 1.28 m repeat
  // (which the tag replaced), most pixels are off.
  EXPECT_GT(double(fitTexture(img, view.camera, tex, 8.0, true).off) / fit.pixels, 0.2);
  EXPECT_GT(double(fitTexture(img, view.camera, tex, tex.metres).off) / fit.pixels, 0.2);

  // Without the textured mode the same face is flat plaster (the golden images' look).
  settings.textures = false;
  const render::Image flat = render::renderImage(sharedRenderer(), view.scene, view.camera, kSize, kSize, settings);
  const auto plaster = litColor(materialColor("plaster", Kind::Shell), Vec3(0, 0, 1));
  for (const auto& [px, py] : {std::pair{200, 200}, {120, 90}, {300, 310}})
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(flat.at(px, py)[k], plaster[k], 2);
}

TEST(RendererTextures, AMaterialsOwnTextureIsDrawnWithoutATag) {
  // slate, 2 m per repeat, seen from 3 m: about 2.9 pixels per texel again.
  const TexturedView view = texturedSquare("slate", 3.0);
  render::RenderSettings settings = plain();
  settings.textures = true;
  const render::Image img = render::renderImage(sharedRenderer(), view.scene, view.camera, kSize, kSize, settings);
  const MaterialTexture& tex = *materialTexture("slate");
  const OracleFit fit = fitTexture(img, view.camera, tex, tex.metres);
  EXPECT_GT(fit.pixels, 100000u);
  EXPECT_LT(double(fit.off) / fit.pixels, 0.01) << fit.off << " of " << fit.pixels << " pixels off";
  EXPECT_LT(fit.meanError, 1.5);
  EXPECT_GT(double(fitTexture(img, view.camera, tex, tex.metres, true).off) / fit.pixels, 0.2);
  // A material with no built-in texture keeps its colour in the textured mode.
  const TexturedView other = texturedSquare("unobtainium", 3.0);
  const render::Image plain = render::renderImage(sharedRenderer(), other.scene, other.camera, kSize, kSize, settings);
  const auto want = litColor(materialColor("unobtainium", Kind::Shell), Vec3(0, 0, 1));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(plain.at(200, 200)[k], want[k], 2);
}

// The lighting model of shaders/mesh.frag.glsl with any sun, and the share of the sun a shadow
// lets through (0: in shadow, 1: lit).
std::array<int, 3> litColor(const Rgb& albedo, const Vec3& n, const Vec3& sun, double sunSeen) {
  const double s = std::max(0.0, OpenMesh::dot(n, sun)) * sunSeen;
  const double sky = 0.5 + 0.5 * n[2];
  const double sunColor[3] = {1.0, 0.97, 0.9}, low[3] = {0.28, 0.26, 0.24}, high[3] = {0.42, 0.46, 0.52};
  std::array<int, 3> out;
  for (int k = 0; k < 3; ++k) {
    const double light = sunColor[k] * s * 0.75 + low[k] + (high[k] - low[k]) * sky;
    out[k] = static_cast<int>(std::lround(std::pow(std::clamp(albedo[k] * light, 0.0, 1.0), 1.0 / 2.2) * 255.0));
  }
  return out;
}

TEST(Shadows, SunDirectionAndTheLightsFrustum) {
  const Vec3 s0 = render::sunDirection(0, 45), s1 = render::sunDirection(90, 0), s2 = render::sunDirection(180, 90);
  EXPECT_NEAR(s0[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s0[1], 0, 1e-12);
  EXPECT_NEAR(s0[2], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s1[1], 1, 1e-12);
  EXPECT_NEAR(s2[2], 1, 1e-12);
  // Every corner of the box lands inside the light's clip volume, for suns high, low and overhead.
  BBox box;
  box.add(Vec3(-10, -4, 0));
  box.add(Vec3(30, 8, 15));
  for (const Vec3& sun : {s0, s1, s2, render::defaultSun(), render::sunDirection(-120, 10)}) {
    const glm::mat4 m = render::lightViewProj(box, sun);
    for (int k = 0; k < 8; ++k) {
      const glm::vec4 p = m * glm::vec4(k & 1 ? 30 : -10, k & 2 ? 8 : -4, k & 4 ? 15 : 0, 1);
      for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(p[a] / p.w), 1.0f + 1e-5f);
    }
    // The sun's direction is the light's depth axis: moving towards the sun brings a point nearer.
    const glm::vec4 a = m * glm::vec4(5, 2, 7, 1), b = m * glm::vec4(5 + sun[0], 2 + sun[1], 7 + sun[2], 1);
    EXPECT_LT(b.z / b.w, a.z / a.w);
  }
}

TEST(Shadows, ATallBoxCastsItsShadowWhereTheSunSays) {
  // A 2 × 2 × 6 m box on the ground, the sun from +x at 45°: its shadow on the ground runs from
  // x = -1 to x = -7 (6 m / tan 45°) over y in [-1, 1].
  BoxSpec spec;
  spec.size = Vec3(2, 2, 6);
  spec.material = "plaster";
  const Scene scene = oneBox(spec);
  const auto camera = topCamera();
  render::RenderSettings s = plain();
  s.sun = render::sunDirection(0, 45);
  s.shadows = true;
  const render::Image img = render::renderImage(sharedRenderer(), scene, camera, kSize, kSize, s);
  const Rgb ground{0.80f, 0.79f, 0.76f};
  const Vec3 up(0, 0, 1);
  auto pixel = [&](double x, double y, double z) {
    const glm::dvec2 p = project(camera, Vec3(x, y, z), kSize, kSize);
    return img.at(int(p.x), int(p.y));
  };
  auto expectColour = [&](const std::uint8_t* px, const std::array<int, 3>& c, const char* what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(px[k], c[k], 3) << what << ", channel " << k;
  };
  const auto lit = litColor(ground, up, *s.sun, 1.0), dark = litColor(ground, up, *s.sun, 0.0);
  ASSERT_GT(lit[0] - dark[0], 20);  // the two differ clearly
  expectColour(pixel(-4, 0, 0), dark, "ground in the shadow");
  expectColour(pixel(-6.5, 0.5, 0), dark, "ground near the shadow's far end");
  expectColour(pixel(4, 0, 0), lit, "ground on the sunny side");
  expectColour(pixel(-4, 3, 0), lit, "ground beside the shadow");
  expectColour(pixel(-8, 0, 0), lit, "ground past the shadow's end");
  // The roof is lit whole: no shadow acne.
  expectColour(pixel(0, 0, 6), litColor(materialColor("plaster", Kind::Mass), up, *s.sun, 1.0), "the roof");
  // Without shadows nothing changes where there is no ground: the roof is the same colour.
  s.shadows = false;
  const render::Image plainImg = render::renderImage(sharedRenderer(), scene, camera, kSize, kSize, s);
  const glm::dvec2 roof = project(camera, Vec3(0, 0, 6), kSize, kSize);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(plainImg.at(int(roof.x), int(roof.y))[k], pixel(0, 0, 6)[k]);
}

TEST(Camera, TargetProjectsToTheImageCentreAndFramingContainsTheBox) {
  render::OrbitCamera c;
  BBox box;
  box.add(Vec3(-5, -3, 0));
  box.add(Vec3(5, 3, 4));
  c.frame(box, 4.0 / 3.0);
  const glm::dvec2 centre = project(c, c.target, 800, 600);
  EXPECT_NEAR(centre.x, 400, 1e-6);
  EXPECT_NEAR(centre.y, 300, 1e-6);
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? box.hi[0] : box.lo[0], (k & 2) ? box.hi[1] : box.lo[1], (k & 4) ? box.hi[2] : box.lo[2]);
    const glm::dvec2 p = project(c, corner, 800, 600);
    EXPECT_GE(p.x, 0);
    EXPECT_LE(p.x, 800);
    EXPECT_GE(p.y, 0);
    EXPECT_LE(p.y, 600);
  }
  EXPECT_NEAR((c.eye() - c.target).norm(), c.distance, 1e-9);
}

}  // namespace
}  // namespace corbel::test
