#pragma once
// What the statics panel shows of a masonry object (Whiting et al. 2009), computed without GL
// or ImGui so it can run on a worker thread and be tested: the analysis of the spec, each
// block's share of the tension (Sec. 3.2, Fig. 6), the interface force arrows, and the energy
// landscape y/W² over one parameter (Fig. 8).
#include "core/geometry.h"
#include "core/masonry_spec.h"
#include "core/progress.h"
#include "statics/analysis.h"
#include "statics/parameters.h"

#include <array>
#include <string>
#include <vector>

namespace corbel::editor {

// The analysis of one spec, as the panel and the viewport draw it.
struct MasonryView {
  MasonrySpec spec;                            // what was analysed
  std::vector<statics::Parameter> parameters;  // the model's, with the spec's values set
  std::vector<statics::FreeParameter> suggestedFree;
  std::vector<std::vector<std::vector<Vec3>>> blockFaces;  // per block, its faces' corners
  std::vector<bool> fixed;                                 // per block: ground or abutment
  std::vector<double> tensionShare;                        // per block, in [0, 1] (blockTensionShares)
  statics::AnalysisResult result;
  double modelSize = 1.0;  // the model's bounding-box diagonal, m
  std::string error;       // the model could not be built or analysed ("" = fine)
};

// Builds and analyses the spec's model with its friction and kern. A model that cannot be
// built or analysed gives a view with `error` set (and what could be filled in); Cancelled is
// thrown when the progress (may be null) is cancelled before the analysis.
MasonryView analyseMasonry(const MasonrySpec& spec, Progress* progress = nullptr);

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
  bool tension = false;  // a vertex pulling (f_n⁻); otherwise an interface's compressive resultant
};

// Interface resultants with compression, each ending at its centre of pressure and pointing
// along the force on block b, and the tension at each tension site, pointing from the
// vertex against the interface normal (the pull that holds b). Lengths are proportional to
// the force within each kind: the largest resultant is `longest` long and the largest
// tension half that (tension is often far smaller than the loads, and would not show).
std::vector<ForceArrow> forceArrows(const statics::AnalysisResult& result, double longest);

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

// The analysis settings of a spec (friction, kern).
statics::AnalysisOptions analysisOptionsOf(const MasonrySpec& spec);

}  // namespace corbel::editor
