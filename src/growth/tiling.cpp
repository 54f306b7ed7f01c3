#include "growth/tiling.h"

#include "core/error.h"

namespace corbel::growth {

Site tiledSite(const Site& site, int nx, int ny) {
  if (nx < 1 || ny < 1 || nx > 100 || ny > 100) throw InputError("tiles", "1 to 100 copies along x and along y");
  const Box b = site.bounds();
  if (site.plan != rectanglePlan(b.lo[0], b.lo[1], b.hi[0], b.hi[1]))
    throw InputError("envelope", "only a rectangular envelope can be tiled");
  const double w = b.size(0), h = b.size(1);
  Site out = site;
  out.plan = rectanglePlan(b.lo[0], b.lo[1], b.lo[0] + nx * w, b.lo[1] + ny * h);
  out.cores.clear();
  out.circulation.clear();
  out.seeds.clear();
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double dx = i * w, dy = j * h;
      for (Rect c : site.cores) out.cores.push_back({c.u0 + dx, c.v0 + dy, c.u1 + dx, c.v1 + dy});
      for (Box c : site.circulation) {
        c.lo[0] += dx, c.hi[0] += dx, c.lo[1] += dy, c.hi[1] += dy;
        out.circulation.push_back(c);
      }
      for (Seed s : site.seeds) {
        s.at = s.at + Vec2(dx, dy);
        out.seeds.push_back(s);
      }
    }
  return out;
}

}  // namespace corbel::growth
