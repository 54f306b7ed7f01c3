#include "city/merge.h"

#include "core/error.h"
#include "core/geometry.h"

#include <array>
#include <cmath>
#include <functional>

namespace corbel::city {

nlohmann::json mergeTilesets(const std::vector<TilesetPart>& parts) {
  using json = nlohmann::json;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  json children = json::array();
  for (const TilesetPart& part : parts) {
    json root = part.tileset.at("root");
    const json& box = root.at("boundingVolume").value("box", json());
    if (!box.is_array() || box.size() != 12)
      throw Error("city-merge: " + part.folder + ": the root's bounding volume is not a box");
    std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // column-major
    if (root.contains("transform")) {
      if (!root["transform"].is_array() || root["transform"].size() != 16)
        throw Error("city-merge: " + part.folder + ": the root's transform is not 16 numbers");
      m = root["transform"].get<std::array<double, 16>>();
    }
    // The box's 8 corners, centre ± its three half axes, placed by the transform.
    for (int c = 0; c < 8; ++c) {
      double p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = box[k].get<double>() + (c & 1 ? 1 : -1) * box[3 + k].get<double>() +
               (c & 2 ? 1 : -1) * box[6 + k].get<double>() + (c & 4 ? 1 : -1) * box[9 + k].get<double>();
      for (int k = 0; k < 3; ++k) {
        const double v = m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
        lo[k] = std::min(lo[k], v);
        hi[k] = std::max(hi[k], v);
      }
    }
    // Content addresses under the part's folder.
    std::function<void(json&)> move = [&](json& tile) {
      if (tile.contains("content") && tile["content"].contains("uri"))
        tile["content"]["uri"] = part.folder + "/" + tile["content"]["uri"].get<std::string>();
      if (tile.contains("contents"))
        for (json& c : tile["contents"])
          if (c.contains("uri")) c["uri"] = part.folder + "/" + c["uri"].get<std::string>();
      if (tile.contains("children"))
        for (json& child : tile["children"]) move(child);
    };
    move(root);
    children.push_back(std::move(root));
  }
  json root;
  if (children.empty()) {  // nothing built anywhere: an empty tile, which the format allows
    root = {{"boundingVolume", {{"box", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}}}}, {"geometricError", 0}};
  } else {
    const double c[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    // Grown by 1 cm, so the parts' corners stay inside through the rounding of ECEF metres
    // (about 1e-9 m at 6,400 km).
    const double pad = 0.01;
    const double h[3] = {(hi[0] - lo[0]) / 2 + pad, (hi[1] - lo[1]) / 2 + pad, (hi[2] - lo[2]) / 2 + pad};
    root = {{"boundingVolume", {{"box", {c[0], c[1], c[2], h[0], 0, 0, 0, h[1], 0, 0, 0, h[2]}}}},
            {"geometricError", 2 * std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2])},
            {"children", std::move(children)}};
  }
  root["refine"] = "REPLACE";
  json out;
  out["asset"] = {{"version", "1.1"}, {"generator", "corbel"}};
  out["geometricError"] = root["geometricError"];
  out["root"] = std::move(root);
  return out;
}

}  // namespace corbel::city
