#include "editor/masonry_view.h"

#include "statics/kernel.h"
#include "statics/tolerances.h"

#include "core/error.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

namespace corbel::editor {

statics::AnalysisOptions analysisOptionsOf(const MasonrySpec& spec) {
  statics::AnalysisOptions options;
  options.friction = spec.friction;
  options.conservativeFriction = spec.conservativeFriction;
  options.kernShrink = spec.kern;
  return options;
}

namespace {

// The view's blocks (faces, fixed) and model size from an assembly.
void fillBlocks(MasonryView& view, const statics::Assembly& assembly) {
  BBox box;
  for (const statics::Block& b : assembly.blocks) {
    std::vector<std::vector<Vec3>> faces;
    for (const auto& f : b.faces) {
      std::vector<Vec3> corners;
      for (int v : f) corners.push_back(b.vertices[static_cast<std::size_t>(v)]);
      faces.push_back(std::move(corners));
    }
    Vec3 centre(0.0);
    for (const Vec3& p : b.vertices) {
      box.add(p);
      centre += p;
    }
    view.blockFaces.push_back(std::move(faces));
    view.fixed.push_back(b.fixed);
    view.blockNames.push_back(b.name);
    view.blockCentres.push_back(b.vertices.empty() ? centre : centre / double(b.vertices.size()));
  }
  view.modelSize = box.empty() ? 1.0 : std::max(box.diagonal(), 1e-9);
}

}  // namespace

// Makes the assembly with `make` (which may fill in more of the view) and analyses it into
// the view: the blocks, the result, the tension shares. An error other than Cancelled goes to
// view.error, with what could be filled in kept.
template <class Make>
void analyseInto(MasonryView& view, const statics::AnalysisOptions& options, Progress* progress, Make make) {
  try {
    const statics::Assembly assembly = make();
    fillBlocks(view, assembly);
    if (progress && progress->cancelled()) throw Cancelled();
    view.result = statics::analyse(assembly, options);
    view.tensionShare = blockTensionShares(assembly.blocks.size(), view.result);
    if (progress && progress->cancelled()) throw Cancelled();
    view.strict = statics::checkFeasibility(assembly, options);
  } catch (const Cancelled&) {
    throw;
  } catch (const std::exception& e) {
    view.error = e.what();
    view.tensionShare.assign(view.blockFaces.size(), 0.0);
  }
}

MasonryView analyseSceneBlocks(const Scene& scene, const statics::SceneBlockOptions& blocks,
                               const statics::AnalysisOptions& options, Progress* progress) {
  MasonryView view;
  view.fromScene = true;
  analyseInto(view, options, progress, [&] {
    statics::SceneAssembly sa = statics::assemblyFromScene(scene, blocks);
    view.sceneLoads = sa.nonstructuralPieces;
    view.sceneLoadWeight = sa.nonstructuralWeight;
    view.groundPlaneAdded = sa.groundPlaneAdded;
    return std::move(sa.assembly);
  });
  return view;
}

MasonryView analyseMasonry(const MasonrySpec& spec, Progress* progress) {
  return analyseMasonry(spec, analysisOptionsOf(spec), progress);
}

MasonryView analyseMasonry(const MasonrySpec& spec, const statics::AnalysisOptions& options, Progress* progress) {
  MasonryView view;
  view.spec = spec;
  analyseInto(view, options, progress, [&] {
    // The blocks without the loads first, so a load that no longer fits (its block is gone)
    // is reported over a model that is still drawn.
    MasonrySpec bare = spec;
    bare.loads.clear();
    const statics::ParametricModel model = statics::modelOf(bare);
    view.parameters = model.parameters.all();
    view.suggestedFree = model.suggestedFree;
    statics::Assembly assembly = model.build(model.parameters);
    try {
      view.loads = statics::resolveLoads(assembly, spec.loads);
    } catch (const std::exception&) {
      fillBlocks(view, assembly);
      throw;
    }
    for (const statics::ResolvedLoad& l : view.loads) assembly.blocks[std::size_t(l.block)].pointLoads.push_back(l.load);
    return assembly;
  });
  if (!spec.ground && !view.error.empty())
    view.error = "it rests on other objects (its ground is off): analyse it with them, under \"All masonry objects "
                 "together\" (" + view.error + ")";
  return view;
}

MasonryView analyseModel(const statics::ParametricModel& model, const statics::ParameterSet& values,
                         const statics::AnalysisOptions& options, Progress* progress) {
  MasonryView view;
  view.fromModel = true;
  view.spec.friction = options.friction;
  view.spec.conservativeFriction = options.conservativeFriction;
  view.spec.kern = options.kernShrink;
  analyseInto(view, options, progress, [&] {
    view.parameters = values.all();
    view.suggestedFree = model.suggestedFree;
    return model.build(values);
  });
  return view;
}

std::vector<Verdict> staticsVerdicts(const MasonryView& view) {
  std::vector<Verdict> out;
  if (!view.error.empty()) return out;
  char text[160];
  const statics::AnalysisResult& r = view.result;
  if (r.feasible)
    out.push_back({"stands (penalty QP): a compression-only force field exists", true});
  else
    out.push_back({"does not stand (penalty QP): it needs tension (glue) to hold", false});
  const statics::FeasibilityResult& lp = view.strict;
  if (lp.feasible)
    std::snprintf(text, sizeof text, "stands (strict LP): no tension variables, least violation %.2g W", lp.violation);
  else if (lp.status == statics::SolveStatus::Optimal || lp.status == statics::SolveStatus::ReducedAccuracy)
    std::snprintf(text, sizeof text, "does not stand (strict LP): without tension equilibrium misses by %.3g W",
                  lp.violation);
  else
    std::snprintf(text, sizeof text, "strict LP: no verdict (solver %s)", statics::toString(lp.status).c_str());
  out.push_back({text, lp.feasible});
  if (r.feasible != lp.feasible)
    out.push_back({"the QP and the LP disagree: the design sits on its threshold", false});
  return out;
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

std::vector<ForceArrow> forceArrows(const statics::AnalysisResult& result, double longest,
                                    const std::vector<bool>& fixed) {
  const auto isFixed = [&](int b) { return b >= 0 && static_cast<std::size_t>(b) < fixed.size() && fixed[b]; };
  const auto isReaction = [&](const statics::InterfaceForces& f) { return isFixed(f.a) != isFixed(f.b); };
  double compression = 0, reaction = 0, tension = 0;
  for (const statics::InterfaceForces& f : result.interfaces)
    if (f.normalForce > 0) {
      double& largest = isReaction(f) ? reaction : compression;
      largest = std::max(largest, f.resultant.norm());
    }
  for (const statics::TensionSite& t : result.tensionSites) tension = std::max(tension, t.tension);
  std::vector<ForceArrow> arrows;
  for (const statics::InterfaceForces& f : result.interfaces) {
    if (!(f.normalForce > 0) || !(f.resultant.norm() > 0)) continue;
    if (isReaction(f)) {
      // The force on the structure's block: +resultant on b, its opposite on a.
      const Vec3 onStructure = isFixed(f.b) ? -f.resultant : f.resultant;
      arrows.push_back({f.centreOfPressure - onStructure * (longest / reaction), f.centreOfPressure, false, true});
    } else {
      arrows.push_back({f.centreOfPressure - f.resultant * (longest / compression), f.centreOfPressure, false, false});
    }
  }
  for (const statics::TensionSite& t : result.tensionSites) {
    if (t.interface < 0 || static_cast<std::size_t>(t.interface) >= result.interfaces.size()) continue;
    const Vec3& n = result.interfaces[static_cast<std::size_t>(t.interface)].normal;
    arrows.push_back({t.point, t.point - n * (t.tension * 0.5 * longest / tension), true, false});
  }
  return arrows;
}

std::array<float, 4> arrowColor(const ForceArrow& arrow) {
  return arrow.load ? kLoadColor : arrow.tension ? kTensionColor : arrow.reaction ? kReactionColor : kCompressionColor;
}

MasonryPicture masonryPicture(const MasonryView& view, bool colours, bool arrows) {
  MasonryPicture picture;
  // The applied loads, scaled among themselves, each ending where it acts.
  double largest = 0;
  for (const statics::ResolvedLoad& l : view.loads) largest = std::max(largest, l.load.force.norm());
  for (const statics::ResolvedLoad& l : view.loads) {
    if (!(largest > 0) || !(l.load.force.norm() > 0)) continue;
    ForceArrow a;
    a.to = l.load.at;
    a.from = l.load.at - l.load.force * (kLongestArrowOfModel * view.modelSize / largest);
    a.load = true;
    picture.arrows.push_back(a);
  }
  if (!view.error.empty()) return picture;
  if (colours)
    for (std::size_t b = 0; b < view.blockFaces.size(); ++b) {
      if (b < view.fixed.size() && view.fixed[b]) continue;
      const auto colour = tensionColor(b < view.tensionShare.size() ? view.tensionShare[b] : 0.0);
      for (const auto& face : view.blockFaces[b]) picture.polygons.push_back({face, colour});
    }
  if (arrows)
    for (const ForceArrow& a : forceArrows(view.result, kLongestArrowOfModel * view.modelSize, view.fixed))
      picture.arrows.push_back(a);
  return picture;
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

double LandscapeAxis::valueAt(int i) const {
  if (samples < 2) return lo;
  return lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(samples - 1);
}

std::pair<int, int> LandscapeGrid::minimum() const {
  std::pair<int, int> best{-1, -1};
  double least = std::numeric_limits<double>::infinity();
  for (int j = 0; j < y.samples; ++j)
    for (int i = 0; i < x.samples; ++i)
      if (at(i, j) < least) {
        least = at(i, j);
        best = {i, j};
      }
  return best;
}

// Fig. 8: y(θ) over two parameters, one analysis per grid point.
LandscapeGrid sampleLandscapeGrid(const statics::ParametricModel& model, const statics::AnalysisOptions& options,
                                  const LandscapeAxis& x, const LandscapeAxis& y, Progress* progress, int threads) {
  for (const LandscapeAxis* a : {&x, &y}) {
    model.parameters.find(a->parameter);  // throws for an unknown name, naming the known ones
    if (a->samples < 2 || a->samples > 4096)
      throw Error("energy landscape: " + a->parameter + " needs 2 to 4096 samples, not " + std::to_string(a->samples));
    if (!std::isfinite(a->lo) || !std::isfinite(a->hi))
      throw Error("energy landscape: the range of " + a->parameter + " must be finite");
  }
  if (x.parameter == y.parameter)
    throw Error("energy landscape: two different parameters are needed, not " + x.parameter + " twice");
  LandscapeGrid g;
  g.x = x;
  g.y = y;
  const std::size_t total = static_cast<std::size_t>(x.samples) * static_cast<std::size_t>(y.samples);
  g.measure.assign(total, std::numeric_limits<double>::quiet_NaN());
  g.stands.assign(total, 0);
  std::atomic<int> nextRow{0};
  std::atomic<bool> stop{false};
  std::mutex reportMutex;
  std::size_t done = 0;
  std::exception_ptr failure;
  auto worker = [&] {
    statics::ParameterSet values = model.parameters;  // this thread's own copy
    while (!stop.load()) {
      const int j = nextRow.fetch_add(1);
      if (j >= y.samples) return;
      for (int i = 0; i < x.samples; ++i) {
        if (progress && progress->cancelled()) {
          stop = true;
          return;
        }
        const std::size_t k = static_cast<std::size_t>(j) * x.samples + i;
        try {
          values.set(x.parameter, x.valueAt(i));
          values.set(y.parameter, y.valueAt(j));
          const statics::AnalysisResult r = statics::analyse(model.build(values), options);
          g.measure[k] = r.yNormalised;
          g.stands[k] = r.feasible;
        } catch (const std::exception&) {
          // NaN, does not stand (as assigned)
        } catch (...) {
          std::lock_guard<std::mutex> lock(reportMutex);
          if (!failure) failure = std::current_exception();
          stop = true;
          return;
        }
        std::lock_guard<std::mutex> lock(reportMutex);
        ++done;
        if (progress) progress->report(double(done) / double(total), "energy landscape");
      }
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const int wanted = threads > 0 ? threads : static_cast<int>(cores);
  const int n = std::clamp(wanted, 1, y.samples);
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (progress && progress->cancelled()) throw Cancelled();
  return g;
}

LandscapeGrid sampleLandscapeGrid(const MasonrySpec& spec, const LandscapeAxis& x, const LandscapeAxis& y,
                                  Progress* progress, int threads) {
  return sampleLandscapeGrid(statics::modelOf(spec), analysisOptionsOf(spec), x, y, progress, threads);
}

std::array<float, 4> landscapeRampColor(double t) {
  // Dark blue, teal, green, yellow (viridis-like stops): ordered in lightness, no red.
  constexpr std::array<std::array<double, 3>, 5> stops{
      {{0.27, 0.00, 0.33}, {0.23, 0.32, 0.55}, {0.13, 0.57, 0.55}, {0.37, 0.79, 0.38}, {0.99, 0.91, 0.14}}};
  const double s = (std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0)) * double(stops.size() - 1);
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(s), stops.size() - 2);
  const double f = s - double(k);
  std::array<float, 4> c{0, 0, 0, 1};
  for (int q = 0; q < 3; ++q) c[q] = static_cast<float>(stops[k][q] + f * (stops[k + 1][q] - stops[k][q]));
  return c;
}

std::vector<std::array<float, 4>> landscapeColors(const LandscapeGrid& grid) {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < grid.measure.size(); ++k) {
    const double m = grid.measure[k];
    if (grid.stands[k] || !(m > 0) || !std::isfinite(m)) continue;
    lo = std::min(lo, std::log10(m));
    hi = std::max(hi, std::log10(m));
  }
  std::vector<std::array<float, 4>> out(grid.measure.size(), kLandscapeMissingColor);
  for (std::size_t k = 0; k < grid.measure.size(); ++k) {
    const double m = grid.measure[k];
    if (grid.stands[k])
      out[k] = kLandscapeStandsColor;
    else if (std::isfinite(m))
      out[k] = landscapeRampColor(hi > lo ? (std::log10(std::max(m, 1e-300)) - lo) / (hi - lo) : 0.5);
  }
  return out;
}

std::vector<std::pair<double, double>> searchPathOnGrid(const LandscapeGrid& grid,
                                                        const std::vector<statics::FreeParameter>& free,
                                                        const std::vector<std::vector<double>>& values) {
  std::vector<std::pair<double, double>> out;
  if (free.size() != 2) return out;
  const int ix = free[0].name == grid.x.parameter ? 0 : free[1].name == grid.x.parameter ? 1 : -1;
  const int iy = free[0].name == grid.y.parameter ? 0 : free[1].name == grid.y.parameter ? 1 : -1;
  if (ix < 0 || iy < 0 || ix == iy) return out;
  for (const std::vector<double>& v : values)
    if (v.size() == 2) out.emplace_back(v[std::size_t(ix)], v[std::size_t(iy)]);
  return out;
}

}  // namespace corbel::editor
