#pragma once
// Draws a KIFS building (McGraw, Sec. 3) by sphere tracing in shaders/kifs.frag.glsl, over
// whatever the bound framebuffer holds: it writes gl_FragDepth and is depth-tested, so it
// composes with the Scene drawn by Renderer before it.
#include "core/document.h"
#include "kifs/distance.h"
#include "kifs/follow.h"
#include "kifs/mass_field.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/renderer.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace corbel::render {

// Display modes of Fig. 5-6, and the cost of each pixel (evaluations of the distance function,
// march and shading together; decode with kifsCost).
// Preview is Shaded without the soft shadow and the ambient occlusion (about half the
// evaluations of a hit pixel): render/kifs_layer's coarse frames.
// What a ray-marched KIFS building shows. Bare is Shaded without the inner shell (McGraw's
// Fig. 3c: the fractal carved by the outer shell alone), so the fractal's own shape shows where
// the inner shell would hide it.
enum class KifsMode { Shaded = 0, Facades = 1, Floors = 2, Cost = 3, Preview = 4, Bare = 5 };

// Evaluations of the distance function per pixel (march and shading), drawn in KifsMode::Cost.
struct KifsCost {
  int hits = 0, misses = 0;
  double meanHit = 0, meanMiss = 0;  // per pixel whose ray hit / missed the building
  int maxHit = 0;
  std::vector<int> perPixel;  // bottom row first, as glReadPixels gives them
  Image heat;                 // black (no evaluation) to white (the most), top row first
  // At hit pixels (bottom row first): the GPU's facade ids id_x + 4·id_z and storey index
  // (clamped to −128..127), and its window depth (1 where the ray missed).
  std::vector<int> ids, storeys;
  std::vector<float> depth;
};

// What kifs.frag.glsl is compiled for (its KIFS_* defines). llvmpipe executes both sides of
// every branch, even one on a uniform, so each building is drawn by a program holding only the
// code it uses (docs/kifs.md, "Speed"); the pictures are the same as with the branches.
struct KifsVariant {
  int footprint = 0;  // kifs::Footprint
  bool curvilinear = false, r1Identity = true, r2Identity = true, idsCut = false, closedRing = false;
  bool walls = false;  // a followed mass whose walls face more than one way (kifs/facings.h)
  int key() const;  // distinct for distinct variants
};
KifsVariant kifsVariant(const kifs::Building& building);
// kifs.frag.glsl with the variant's defines after its #version line.
std::string kifsShaderSource(const KifsVariant& variant);

// The one place that turns a building's parameters into kifs.frag.glsl's uniforms (camera and
// mode aside), for a program compiled for kifsVariant(building). Returns the names written;
// throws corbel::Error if the program has no active uniform of a name the variant uses, so a
// field renamed on one side only cannot go unnoticed. Uniforms the variant does not use (R1
// when it is I, the wing of a box, the polar ones of a rectilinear building) are written only
// if the program kept them.
std::vector<std::string> setKifsUniforms(unsigned program, const kifs::Building& building);

class KifsPass {
 public:
  // Needs a current GL 3.3 core context; throws corbel::Error if the shader fails to build.
  // Compiles the default parameters' variant; a draw compiles its building's variant on first
  // use and keeps it.
  KifsPass();
  ~KifsPass();
  KifsPass(const KifsPass&) = delete;
  KifsPass& operator=(const KifsPass&) = delete;

  // Draws into the bound framebuffer's viewport (x, y, width, height). The building's
  // trace.pixelAngle should match the view (kifsForView).
  void draw(const kifs::Building& building, const OrbitCamera& camera, int x, int y, int width, int height,
            KifsMode mode);
  unsigned program() const { return program_; }  // the last draw's (before any: the default's)
  // Every uniform the last draw wrote (setKifsUniforms' and the camera's).
  const std::vector<std::string>& writtenUniforms() const { return written_; }

 private:
  unsigned programFor(const KifsVariant& variant);
  void bindMassField(const std::shared_ptr<const kifs::MassField>& field);
  unsigned program_ = 0, vao_ = 0;
  // The last mass field uploaded (a 3D texture of its samples), held so that it is not freed
  // and another one given its address while the texture stands for it.
  std::shared_ptr<const kifs::MassField> field_;
  unsigned fieldTexture_ = 0;
  std::map<int, unsigned> programs_;  // by KifsVariant::key
  std::vector<std::string> written_;
};

// Draws the full-screen triangle (background.vert.glsl) of the bound program into the viewport
// (x, y, width, height), depth-tested (LEQUAL) and writing depth, blending off.
void drawDepthWritingTriangle(unsigned vao, int x, int y, int width, int height);

// Where a KifsPass draw runs the fragment shader: the back faces of the building's bounds box
// grown by at least two pixels on screen, or the whole viewport when the eye is inside that
// box or so near it that the near plane could cut its back faces.
struct KifsCover {
  glm::dvec3 lo, hi;
  bool fullScreen = false;
};
KifsCover kifsCover(const kifs::Building& building, const OrbitCamera& camera, int width, int height);

// `params` with the hit threshold's pixel angle for a camera seeing `height` pixels.
kifs::KifsParams kifsForView(kifs::KifsParams params, const OrbitCamera& camera, int height);
// A camera framing the building's outer shell.
OrbitCamera kifsCamera(const kifs::Building& building, double aspect, double azimuthDeg = -60.0,
                       double elevationDeg = 22.0);

// A single-sample framebuffer with a 32-bit float depth buffer, for reading depths back.
class DepthTarget {
 public:
  DepthTarget(int width, int height);  // throws corbel::Error if the framebuffer is incomplete
  ~DepthTarget();
  DepthTarget(const DepthTarget&) = delete;
  DepthTarget& operator=(const DepthTarget&) = delete;
  void bind();
  // Window depths in [0, 1] (1: nothing drawn), bottom row first as glReadPixels gives them.
  std::vector<float> readDepth();
  Image readColor();  // RGBA, bottom row first (not flipped)

 private:
  int width_, height_;
  unsigned fbo_ = 0, color_ = 0, depth_ = 0;
};

// The window depth ([0, 1], 1 where the ray misses) of the building alone (DepthTarget).
std::vector<float> renderKifsDepth(KifsPass& pass, const kifs::Building& building, const OrbitCamera& camera, int width,
                                   int height, KifsMode mode = KifsMode::Shaded);
// The cost of drawing the building alone, one sample per pixel.
KifsCost measureKifsCost(KifsPass& pass, const kifs::Building& building, const OrbitCamera& camera, int width,
                         int height);
// A picture: the Scene (with the renderer's sky and grid), then the building over it.
Image renderKifsImage(Renderer& renderer, KifsPass& pass, const kifs::Building& building, const Scene& scene,
                      const OrbitCamera& camera, int width, int height, KifsMode mode,
                      const RenderSettings& settings);

// The KIFS objects of a document that are drawn by ray marching (core/kifs_spec.h: not meshed)
// and shown by `visible`, with their world bounds. A spec the kernel refuses is left out (its
// error is the object's build error, kifs/kernel.h). A building that follows a mass object
// (kifs/follow.h) is baked from `scene` (none given: left out), in world space, its placement
// the identity; one whose mass cannot be baked is left out with its error in `errors`.
struct RaymarchedKifs {
  std::vector<kifs::KifsParams> buildings;
  std::vector<Placement> placements;  // each building's (core/placement.h), in the same order
  std::vector<std::shared_ptr<const kifs::MassField>> masses;  // the same order; null: not a follower
  std::vector<std::string> errors;    // "NAME: what", followers left out
  BBox bounds;                        // placed
};

// The camera that sees a building standing at its kernel's origin as `camera` sees it placed
// by `placement` (a move and a turn about z; a KIFS placement has no scale): the marcher draws
// a placed building by marching its own frame with this camera, so pixels and depths match.
OrbitCamera cameraInFrameOf(const OrbitCamera& camera, const Placement& placement);
// `buildings` gives a town's building to a follower that names one (kifs.mass.building).
RaymarchedKifs raymarchedKifs(const Document& doc, const std::function<bool(ObjectId)>& visible,
                              const Scene* scene = nullptr, const kifs::TownBuildings& buildings = {});

// A picture of the Scene with ray-marched buildings over it (none: the Scene alone), each one's
// hit threshold set for this view (kifsForView); compiles a KifsPass only when there are some.
// `placements` (empty: none) places each building (RaymarchedKifs::placements); `masses` (empty:
// none) are the followers' (RaymarchedKifs::masses).
Image renderSceneWithKifs(Renderer& renderer, const Scene& scene, const std::vector<kifs::KifsParams>& buildings,
                          const OrbitCamera& camera, int width, int height, const RenderSettings& settings,
                          const std::vector<Placement>& placements = {},
                          const std::vector<std::shared_ptr<const kifs::MassField>>& masses = {});

}  // namespace corbel::render
