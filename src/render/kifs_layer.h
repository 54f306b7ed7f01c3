#pragma once
// Progressive refinement of ray-marched KIFS buildings (issue: "on a CPU renderer the editor
// stays responsive"): the buildings are marched alone into an off-screen layer (colour and
// depth textures) only when what they show changes, coarse (1/scale of the viewport) while the
// camera or a parameter is moving and full size once it is still; every frame composites the
// cached layer over the Scene with the depth test, which costs a texture fetch per pixel
// instead of a march.
#include "render/kifs_pass.h"

#include <string>
#include <vector>

namespace corbel::render {

class KifsLayer {
 public:
  KifsLayer();  // needs a current GL 3.3 core context
  ~KifsLayer();
  KifsLayer(const KifsLayer&) = delete;
  KifsLayer& operator=(const KifsLayer&) = delete;

  // Marches `buildings` (their pixel angle set for a full-size view) seen by `camera` into the
  // layer at ceil(width / scale) × ceil(height / scale) texels, unless the layer already holds
  // the same `key` at the same size and scale. `key` must change whenever the buildings, the
  // camera or the mode do (the caller knows what it draws). Returns whether it marched. The
  // bound framebuffer and the viewport are as they were afterwards. At scale > 1 a Shaded
  // layer is drawn as KifsMode::Preview (no soft shadow, no occlusion: a cheaper coarse frame).
  // `placements` (empty: none) places each building (RaymarchedKifs::placements); `masses`
  // (empty: none) are the followers' baked masses (RaymarchedKifs::masses).
  bool update(KifsPass& pass, const std::vector<kifs::KifsParams>& buildings, const OrbitCamera& camera, int width,
              int height, int scale, KifsMode mode, const std::string& key,
              const std::vector<Placement>& placements = {},
              const std::vector<std::shared_ptr<const kifs::MassField>>& masses = {});
  // Draws the layer into the bound framebuffer's viewport (x, y, width, height), depth-tested
  // against what is there.
  void composite(int x, int y, int width, int height);
  int scale() const { return scale_; }
  bool empty() const { return key_.empty(); }
  void invalidate() { key_.clear(); }

 private:
  void resize(int w, int h);
  unsigned fbo_ = 0, color_ = 0, depth_ = 0, program_ = 0, vao_ = 0;
  int w_ = 0, h_ = 0, scale_ = 1;
  std::string key_;
};

}  // namespace corbel::render
