#include "editor/masonry_view.h"

#include "statics/kernel.h"
#include "statics/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::editor {

statics::AnalysisOptions analysisOptionsOf(const MasonrySpec& spec) {
  statics::AnalysisOptions options;
  options.friction = spec.friction;
  options.kernShrink = spec.kern;
  return options;
}

MasonryView analyseMasonry(const MasonrySpec& spec, Progress* progress) {
  MasonryView view;
  view.spec = spec;
  try {
    const statics::ParametricModel model = statics::modelOf(spec);
    view.parameters = model.parameters.all();
    view.suggestedFree = model.suggestedFree;
    const statics::Assembly assembly = model.build(model.parameters);
    BBox box;
    for (const statics::Block& b : assembly.blocks) {
      std::vector<std::vector<Vec3>> faces;
      for (const auto& f : b.faces) {
        std::vector<Vec3> corners;
        for (int v : f) corners.push_back(b.vertices[static_cast<std::size_t>(v)]);
        faces.push_back(std::move(corners));
      }
      for (const Vec3& p : b.vertices) box.add(p);
      view.blockFaces.push_back(std::move(faces));
      view.fixed.push_back(b.fixed);
    }
    view.modelSize = box.empty() ? 1.0 : std::max(box.diagonal(), 1e-9);
    if (progress && progress->cancelled()) throw Cancelled();
    view.result = statics::analyse(assembly, analysisOptionsOf(spec));
    view.tensionShare = blockTensionShares(assembly.blocks.size(), view.result);
  } catch (const Cancelled&) {
    throw;
  } catch (const std::exception& e) {
    view.error = e.what();
    view.tensionShare.assign(view.blockFaces.size(), 0.0);
  }
  return view;
}

std::vector<double> blockTensionShares(std::size_t blocks, const statics::AnalysisResult& result) {
  std::vector<double> tension(blocks, 0.0);
  double largestVertex = 0;
  for (const statics::InterfaceForces& f : result.interfaces)
    for (const statics::VertexForce& v : f.vertices) {
      for (int b : {f.a, f.b})
        if (b >= 0 && static_cast<std::size_t>(b) < blocks) tension[static_cast<std::size_t>(b)] += v.tension;
      largestVertex = std::max(largestVertex, v.tension);
    }
  const double largest = tension.empty() ? 0.0 : *std::max_element(tension.begin(), tension.end());
  if (!(largestVertex > statics::kTensionSite * result.totalWeight) || !(largest > 0))
    return std::vector<double>(blocks, 0.0);
  for (double& t : tension) t /= largest;
  return tension;
}

std::array<float, 4> tensionColor(double share) {
  const double s = std::isnan(share) ? 0.0 : std::clamp(share, 0.0, 1.0);
  constexpr std::array<double, 3> stone{0.86, 0.80, 0.70}, blue{0.12, 0.32, 0.95};
  std::array<float, 4> c{0, 0, 0, 1};
  for (int k = 0; k < 3; ++k) c[k] = static_cast<float>(stone[k] + s * (blue[k] - stone[k]));
  return c;
}

std::vector<ForceArrow> forceArrows(const statics::AnalysisResult& result, double longest) {
  double compression = 0, tension = 0;
  for (const statics::InterfaceForces& f : result.interfaces)
    if (f.normalForce > 0) compression = std::max(compression, f.resultant.norm());
  for (const statics::TensionSite& t : result.tensionSites) tension = std::max(tension, t.tension);
  std::vector<ForceArrow> arrows;
  if (compression > 0)
    for (const statics::InterfaceForces& f : result.interfaces)
      if (f.normalForce > 0 && f.resultant.norm() > 0)
        arrows.push_back({f.centreOfPressure - f.resultant * (longest / compression), f.centreOfPressure, false});
  for (const statics::TensionSite& t : result.tensionSites) {
    if (t.interface < 0 || static_cast<std::size_t>(t.interface) >= result.interfaces.size()) continue;
    const Vec3& n = result.interfaces[static_cast<std::size_t>(t.interface)].normal;
    arrows.push_back({t.point, t.point - n * (t.tension * 0.5 * longest / tension), true});
  }
  return arrows;
}

double Landscape::valueAt(std::size_t i) const {
  if (measure.size() < 2) return lo;
  return lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(measure.size() - 1);
}

Landscape sampleLandscape(const statics::ParametricModel& model, const statics::AnalysisOptions& options,
                          const std::string& parameter, double lo, double hi, int samples, Progress* progress) {
  Landscape l;
  l.parameter = parameter;
  l.lo = lo;
  l.hi = hi;
  l.measure.assign(static_cast<std::size_t>(std::max(samples, 2)), 0.0);
  statics::ParameterSet values = model.parameters;
  values.find(parameter);  // throws for an unknown name, naming the known ones
  for (std::size_t i = 0; i < l.measure.size(); ++i) {
    if (progress && progress->cancelled()) throw Cancelled();
    try {
      values.set(parameter, l.valueAt(i));
      const statics::AnalysisResult r = statics::analyse(model.build(values), options);
      l.measure[i] = r.yNormalised;
    } catch (const std::exception&) {
      l.measure[i] = std::numeric_limits<double>::quiet_NaN();
    }
    if (progress) progress->report(double(i + 1) / double(l.measure.size()), "energy landscape");
  }
  return l;
}

Landscape sampleLandscape(const MasonrySpec& spec, const std::string& parameter, double lo, double hi, int samples,
                          Progress* progress) {
  return sampleLandscape(statics::modelOf(spec), analysisOptionsOf(spec), parameter, lo, hi, samples, progress);
}

}  // namespace corbel::editor
