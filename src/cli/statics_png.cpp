#include "cli/statics_png.h"

#include "core/document.h"
#include "core/error.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "render/headless_context.h"
#include "render/renderer.h"
#include "statics/kernel.h"

#include <algorithm>
#include <cmath>

namespace corbel::cli {

render::Image renderMasonryView(const editor::MasonryView& view, int width, int height) {
  if (!view.error.empty()) throw Error("cannot draw the masonry model: " + view.error);
  Scene scene;
  if (view.fromModel) {
    // No spec to build (an extrusion in stone): the view's own blocks, in stone.
    MeshData mesh;
    const int stone = mesh.addMaterial("stone");
    const int block = mesh.addTag("block"), ground = mesh.addTag("ground");
    for (std::size_t b = 0; b < view.blockFaces.size(); ++b)
      for (const auto& face : view.blockFaces[b]) {
        std::vector<int> loop;
        for (const Vec3& p : face) loop.push_back(mesh.addPoint(p));
        mesh.addFace(std::move(loop), view.fixed[b] ? ground : block, stone);
      }
    scene.replaceObject(1, Kind::Block, "stone", mesh);
  } else {
    Document doc;
    doc.add("masonry", view.spec);
    SceneSync sync;
    statics::registerKernel(sync);
    sync.update(doc, scene);
    for (const auto& [id, st] : sync.status())
      if (!st.error.empty()) throw Error("cannot build the masonry model: " + st.error);
  }

  const editor::MasonryPicture picture = editor::masonryPicture(view);
  BBox box;
  for (std::size_t b = 0; b < view.blockFaces.size(); ++b)
    if (!view.fixed[b])
      for (const auto& face : view.blockFaces[b])
        for (const Vec3& p : face) box.add(p);
  for (const editor::ForceArrow& a : picture.arrows) {
    box.add(a.from);
    box.add(a.to);
  }
  if (box.empty()) box = scene.bounds();

  render::Renderer renderer;
  for (const editor::ColouredPolygon& p : picture.polygons) renderer.overlay().polygon(p.corners, p.color);
  for (const editor::ForceArrow& a : picture.arrows)
    renderer.overlayOnTop().arrow(a.from, a.to, editor::arrowColor(a), 0.25);
  render::OrbitCamera camera;
  camera.azimuth_deg = -80;  // nearly the front: the arches of the examples stand in the x-z plane
  camera.elevation_deg = 15;
  camera.frame(box, double(width) / height);
  render::RenderSettings settings;
  return render::renderImage(renderer, scene, camera, width, height, settings);
}

namespace {

void disc(render::Image& image, double cx, double cy, double radius, std::uint8_t shade) {
  for (int y = int(std::floor(cy - radius)); y <= int(std::ceil(cy + radius)); ++y)
    for (int x = int(std::floor(cx - radius)); x <= int(std::ceil(cx + radius)); ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) > radius * radius) continue;
      std::uint8_t* px = image.at(x, y);
      px[0] = px[1] = px[2] = shade;
      px[3] = 255;
    }
}

}  // namespace

render::Image landscapeImage(const editor::LandscapeGrid& grid, int cell,
                             const std::vector<std::pair<double, double>>& path) {
  cell = std::max(cell, 1);
  const std::vector<std::array<float, 4>> colours = editor::landscapeColors(grid);
  render::Image image(grid.x.samples * cell, grid.y.samples * cell);
  for (int j = 0; j < grid.y.samples; ++j)
    for (int i = 0; i < grid.x.samples; ++i) {
      const auto& c = colours[static_cast<std::size_t>(j) * grid.x.samples + i];
      const int top = (grid.y.samples - 1 - j) * cell;  // the second parameter grows upwards
      for (int y = top; y < top + cell; ++y)
        for (int x = i * cell; x < (i + 1) * cell; ++x) {
          std::uint8_t* px = image.at(x, y);
          for (int k = 0; k < 4; ++k)
            px[k] = static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255));
        }
    }
  // A parameter value to the pixel of its place: sample centres at cell centres.
  const auto place = [&](const editor::LandscapeAxis& a, double v) {
    return a.hi > a.lo ? (v - a.lo) / (a.hi - a.lo) * (a.samples - 1) : 0.0;
  };
  const auto pixel = [&](const std::pair<double, double>& p) {
    return std::make_pair((place(grid.x, p.first) + 0.5) * cell,
                          (grid.y.samples - 1 - place(grid.y, p.second) + 0.5) * cell);
  };
  const double r = std::max(2.0, cell * 0.3);
  for (int pass = 0; pass < 2; ++pass)  // black rings, then white lines and dots over them
    for (std::size_t k = 0; k < path.size(); ++k) {
      const auto [x1, y1] = pixel(path[k]);
      const double radius = (k + 1 == path.size() ? 1.6 : 1.0) * r;
      if (pass == 0) {
        disc(image, x1, y1, radius + 1.5, 0);
        continue;
      }
      if (k > 0) {
        const auto [x0, y0] = pixel(path[k - 1]);
        const int steps = int(std::ceil(std::hypot(x1 - x0, y1 - y0))) + 1;
        for (int s = 0; s <= steps; ++s) disc(image, x0 + (x1 - x0) * s / steps, y0 + (y1 - y0) * s / steps, 1.0, 255);
      }
      disc(image, x1, y1, radius, 255);
    }
  return image;
}

}  // namespace corbel::cli
