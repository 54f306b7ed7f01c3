#pragma once
// The scene renderer: OpenGL 3.3 core, independent of the window system. It draws into
// whatever framebuffer is bound (the editor's window, or an OffscreenTarget headless).
#include "core/scene.h"
#include "core/textures.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/overlay.h"

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace corbel::render {

struct RenderSettings {
  bool edges = true;        // polygon edge overlay
  bool grid = true;         // ground grid at z = 0
  bool wireframe = false;   // edges only, no filled faces
  bool background = true;   // sky gradient (off: clear to transparent black)
  // Objects to draw; all when empty.
  std::function<bool(ObjectId)> visible;
  std::optional<ObjectId> highlight;
  // The sun: the direction towards it (normalised when drawn); none = the fixed studio sun of
  // shaders/mesh.frag.glsl. With `shadows` (Ng, Fig. 8.5) a shadow map is rendered from the sun
  // over the visible faces and a ground plane at z = 0 under the grid receives them too.
  std::optional<Vec3> sun;
  bool shadows = false;
  // Textured faces (docs/city.md, "Textures"): a face shows the texture `tagTextures` gives its
  // object and tag (a style's tag_textures) or else its built-in material's, with the glb's
  // texture coordinates (core/textures.h), sampled with repeat and mipmaps; other faces keep
  // their colour. Off by default: the golden images are of colours. Read when the buffers are
  // rebuilt (a new scene revision, visibility, highlight or `textures`).
  bool textures = false;
  TagTextures tagTextures;
};

// The studio sun (towards it), and a sun by azimuth (degrees from +X towards +Y, as the camera's)
// and elevation above the ground.
Vec3 defaultSun();
Vec3 sunDirection(double azimuthDeg, double elevationDeg);
// The sun's view for the shadow map: orthographic along -sun, fitted so that the sphere around
// `box` lies inside the clip volume (x, y, z in [-1, 1]).
glm::mat4 lightViewProj(const BBox& box, const Vec3& sun);

class Renderer {
 public:
  // Needs a current GL 3.3 core context. Throws corbel::Error if a shader fails to build.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Rebuilds GPU buffers when the scene's revision or the visibility changed.
  void setScene(const Scene& scene, const RenderSettings& settings);
  Overlay& overlay() { return overlay_; }
  // Drawn last, without the depth test: what acts inside solids (force arrows on interfaces).
  Overlay& overlayOnTop() { return onTop_; }
  // Draws into the currently bound framebuffer, viewport (x, y, width, height).
  void draw(const OrbitCamera& camera, int x, int y, int width, int height, const RenderSettings& settings);

  std::size_t triangleCount() const;
  // The outline segments the last setScene drew (with settings.edges): the faces' edges, less
  // those inside one planar face and a meshed KIFS building's edges under 30°.
  std::size_t edgeCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Overlay overlay_, onTop_;
};

// A framebuffer object with multisampled color and depth, resolved on read-back.
class OffscreenTarget {
 public:
  OffscreenTarget(int width, int height, int samples = 4);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;
  void bind();
  Image read();  // resolves and returns RGBA, top row first
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_, samples_;
  unsigned msFbo_ = 0, msColor_ = 0, msDepth_ = 0, fbo_ = 0, color_ = 0;
};

// GL strings, for logs and bug reports ("4.5 (Core Profile) Mesa 22.3.6, llvmpipe").
std::string glDescription();

}  // namespace corbel::render
