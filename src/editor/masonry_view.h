#pragma once
// What the statics panel shows of a masonry object (Whiting et al. 2009), computed without GL
// or ImGui so it can run on a worker thread and be tested: the analysis of the spec, each
// block's share of the tension (Sec. 3.2, Fig. 6), the interface force arrows with the ground
// reactions apart (Fig. 1 right), and the energy landscape y/W² over one parameter or a grid of
// two (Fig. 8). corbel-cli draws the same pictures headless (cli/statics_png.h).
#include "core/geometry.h"
#include "core/masonry_spec.h"
#include "core/progress.h"
#include "statics/analysis.h"
#include "statics/loads.h"
#include "statics/parameters.h"
#include "statics/scene_blocks.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace corbel::editor {

// The analysis of one spec, as the panel and the viewport draw it.
struct MasonryView {
  MasonrySpec spec;                            // what was analysed
  std::vector<statics::Parameter> parameters;  // the model's, with the spec's values set
  std::vector<statics::FreeParameter> suggestedFree;
  std::vector<std::vector<std::vector<Vec3>>> blockFaces;  // per block, its faces' corners
  std::vector<bool> fixed;                                 // per block: ground or abutment
  std::vector<std::string> blockNames;                     // per block, as the model names it
  std::vector<Vec3> blockCentres;                          // per block: the mean of its corners
  std::vector<statics::ResolvedLoad> loads;                // the spec's loads, in its order
  std::vector<double> tensionShare;                        // per block, in [0, 1] (blockTensionShares)
  statics::AnalysisResult result;
  // The strict LP phase-1 test of the same assembly (statics::checkFeasibility): a
  // compression-only force field with no tension variables at all, the verdict the
  // thresholds are decided by. Shown beside the QP's.
  statics::FeasibilityResult strict;
  double modelSize = 1.0;  // the model's bounding-box diagonal, m
  std::string error;       // the model could not be built or analysed ("" = fine)
  // Set by analyseSceneBlocks: the blocks are the Scene's (no spec, no parameters).
  bool fromScene = false;
  int sceneLoads = 0;             // nonstructural pieces carried as point loads
  double sceneLoadWeight = 0;     // their weight, N
  bool groundPlaneAdded = false;  // no piece was tagged "ground": a ground slab was added
  bool fromModel = false;         // set by analyseModel: `spec` does not describe the blocks
};

// Builds and analyses the spec's model with its friction and kern. A model that cannot be
// built or analysed gives a view with `error` set (and what could be filled in); Cancelled is
// thrown when the progress (may be null) is cancelled before the analysis.
MasonryView analyseMasonry(const MasonrySpec& spec, Progress* progress = nullptr);
// The same with analysis settings of the caller's (the CLI's --friction-sides and overrides).
MasonryView analyseMasonry(const MasonrySpec& spec, const statics::AnalysisOptions& options,
                           Progress* progress = nullptr);

// The analysis of a parametric model at `values` (an extrusion built in stone, which has no
// MasonrySpec; compose/stone_extrusion.h), as the same view with `spec` left default.
MasonryView analyseModel(const statics::ParametricModel& model, const statics::ParameterSet& values,
                         const statics::AnalysisOptions& options, Progress* progress = nullptr);

// The analysis of the blocks of a Scene (statics/scene_blocks.h: every connected piece of the
// objects of kind Block one block with its material's density, pieces tagged "ground" fixed,
// nonstructural shapes carried as loads), as the same view: the assembly of several masonry
// objects together, or of blocks that no template made. No spec and no parameters. A Scene
// whose blocks cannot be made or analysed gives a view with `error` naming the object and piece.
MasonryView analyseSceneBlocks(const Scene& scene, const statics::SceneBlockOptions& blocks,
                               const statics::AnalysisOptions& options, Progress* progress = nullptr);

// The panel's two verdicts on a view without an error, the penalty QP's (Sec. 3.2: y/W² at most
// statics::kFeasibleMeasure) and the strict LP's (violation at most statics::kFeasibleViolation
// W), each one line and whether it says the structure stands; a third line when they differ
// (the design sits on its threshold, where the QP's y ≈ 0 and the LP's violation ≈ 0 are
// decided by their tolerances).
struct Verdict {
  std::string text;
  bool stands = false;
};
std::vector<Verdict> staticsVerdicts(const MasonryView& view);

// Each block's tension T_b = Σ f_n⁻ over the contact vertices of every interface it takes
// part in, divided by the largest T_b. All zero when no vertex carries more than the tension
// site threshold (statics::kTensionSite·W), so a standing structure shows no tension.
std::vector<double> blockTensionShares(std::size_t blocks, const statics::AnalysisResult& result);

// The colour of a block with tension share s: stone (s = 0) blending linearly to the blue of
// tension (s = 1); s is clamped into [0, 1] and a NaN counts as 0.
std::array<float, 4> tensionColor(double share);

// One arrow of the force display, from `from` to `to` (the tip).
struct ForceArrow {
  Vec3 from{0.0}, to{0.0};
  bool tension = false;   // a vertex pulling (f_n⁻); otherwise an interface's compressive resultant
  bool reaction = false;  // a compressive resultant where a fixed block (the ground) holds the structure
  bool load = false;      // an applied load the artist placed (MasonrySpec::loads), ending where it acts
};

// Interface resultants with compression, each ending at its centre of pressure and pointing
// along the force on block b, and the tension at each tension site, pointing from the
// vertex against the interface normal (the pull that holds b). Lengths are proportional to
// the force within each kind: the largest resultant is `longest` long and the largest
// tension half that (tension is often far smaller than the loads, and would not show).
// With `fixed` (per block, as MasonryView::fixed), the resultants of interfaces with a fixed
// block are ground reactions (Fig. 1 right): the force the fixed block exerts on the
// structure's block, ending at the contact's centre of pressure, scaled as their own kind
// (the largest reaction `longest` long: they carry the whole weight and would dwarf the rest).
std::vector<ForceArrow> forceArrows(const statics::AnalysisResult& result, double longest,
                                    const std::vector<bool>& fixed = {});

// Arrow colours: compression red, tension blue (Fig. 6), ground reactions green.
inline constexpr std::array<float, 4> kCompressionColor{0.85f, 0.25f, 0.12f, 1.0f};
inline constexpr std::array<float, 4> kTensionColor{0.1f, 0.35f, 1.0f, 1.0f};
inline constexpr std::array<float, 4> kReactionColor{0.1f, 0.7f, 0.2f, 1.0f};
inline constexpr std::array<float, 4> kLoadColor{0.95f, 0.75f, 0.05f, 1.0f};  // applied loads: amber
std::array<float, 4> arrowColor(const ForceArrow& arrow);

// What the 3D view draws of a view, for the editor's overlay and the CLI's --render alike: the
// faces of every block that is not fixed in its tension colour, and the force arrows (the
// largest a fifth of the model's size), ground reactions apart, and the applied loads (amber,
// the largest a fifth of the model's size, the tip where each acts; drawn with or without the
// force arrows). Empty for a view with an error, but for the loads, which show where they are.
struct ColouredPolygon {
  std::vector<Vec3> corners;
  std::array<float, 4> color{0, 0, 0, 1};
};
struct MasonryPicture {
  std::vector<ColouredPolygon> polygons;  // drawn depth-tested, over the Scene's faces
  std::vector<ForceArrow> arrows;         // drawn on top (they act inside the blocks)
};
inline constexpr double kLongestArrowOfModel = 0.2;
MasonryPicture masonryPicture(const MasonryView& view, bool colours = true, bool arrows = true);

// y/W² over one parameter (Fig. 8), the others as in the spec: `samples` values spread
// evenly over [lo, hi] (both ends included). A value where the model cannot be built or
// analysed gives NaN. Reports progress and throws Cancelled when cancelled.
struct Landscape {
  std::string parameter;
  double lo = 0, hi = 0;
  std::vector<double> measure;  // y/W² per sample
  double valueAt(std::size_t i) const;
};
Landscape sampleLandscape(const statics::ParametricModel& model, const statics::AnalysisOptions& options,
                          const std::string& parameter, double lo, double hi, int samples,
                          Progress* progress = nullptr);
Landscape sampleLandscape(const MasonrySpec& spec, const std::string& parameter, double lo, double hi, int samples,
                          Progress* progress = nullptr);

// y/W² over a grid of two parameters (Fig. 8), the others as in the model: x.samples values
// of x's parameter across [x.lo, x.hi] times y.samples of y's, both ends included. Rows (one
// value of y each) are sampled on up to `threads` threads (0: one per core), each with its
// own copy of the parameters; the model's build and the analysis share no state. A sample
// where the model cannot be built or analysed is NaN and does not stand. Reports the
// fraction of samples done and throws Cancelled when cancelled (each thread stops after its
// current sample). Throws corbel::Error for an unknown or repeated parameter or fewer than 2
// samples on an axis.
struct LandscapeAxis {
  std::string parameter;
  double lo = 0, hi = 0;
  int samples = 0;
  double valueAt(int i) const;
};
struct LandscapeGrid {
  LandscapeAxis x, y;
  std::vector<double> measure;  // y/W², x fastest: measure[j·x.samples + i] at (x_i, y_j)
  std::vector<char> stands;     // the analysis called it feasible (y/W² ≤ kFeasibleMeasure, optimal)
  double at(int i, int j) const { return measure[static_cast<std::size_t>(j) * x.samples + i]; }
  bool standsAt(int i, int j) const { return stands[static_cast<std::size_t>(j) * x.samples + i] != 0; }
  // The sample with the least y/W² (the first in row order among equals); {-1, -1} when all are NaN.
  std::pair<int, int> minimum() const;
};
LandscapeGrid sampleLandscapeGrid(const statics::ParametricModel& model, const statics::AnalysisOptions& options,
                                  const LandscapeAxis& x, const LandscapeAxis& y, Progress* progress = nullptr,
                                  int threads = 0);
LandscapeGrid sampleLandscapeGrid(const MasonrySpec& spec, const LandscapeAxis& x, const LandscapeAxis& y,
                                  Progress* progress = nullptr, int threads = 0);

// A search's evaluations (`values[k]`: the values of `free`, in order) as points (x value,
// y value) on the grid's two parameters — Fig. 8's optimisation path. Empty unless the search
// moved exactly the grid's two parameters (in either order).
std::vector<std::pair<double, double>> searchPathOnGrid(const LandscapeGrid& grid,
                                                        const std::vector<statics::FreeParameter>& free,
                                                        const std::vector<std::vector<double>>& values);

// The colour of each sample of a grid, x fastest: standing samples red (Fig. 8's zero plane),
// the others by log10(y/W²) from the smallest positive to the largest measure of the grid on a
// dark-blue-to-yellow ramp with no red in it, NaN dark grey.
inline constexpr std::array<float, 4> kLandscapeStandsColor{0.9f, 0.1f, 0.1f, 1.0f};
inline constexpr std::array<float, 4> kLandscapeMissingColor{0.25f, 0.25f, 0.25f, 1.0f};
std::array<float, 4> landscapeRampColor(double t);  // t in [0, 1] (clamped), low to high
std::vector<std::array<float, 4>> landscapeColors(const LandscapeGrid& grid);

// The analysis settings of a spec (friction, kern).
statics::AnalysisOptions analysisOptionsOf(const MasonrySpec& spec);

}  // namespace corbel::editor
