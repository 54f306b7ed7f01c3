#pragma once
// The statics pictures of a masonry model, headless (corbel-cli statics --render, --landscape;
// Whiting et al. 2009): what the editor's 3D view shows of an analysis (editor/masonry_view.h's
// masonryPicture over the Scene of the spec's blocks: blocks by their share of tension, force
// arrows, ground reactions apart), and the energy landscape over two parameters (Fig. 8).
#include "core/masonry_spec.h"
#include "editor/masonry_view.h"
#include "render/image.h"

#include <utility>
#include <vector>

namespace corbel::cli {

// The view's blocks (the Scene of view.spec, as SceneSync builds it) with the view's picture,
// from the front and a little above, framed on the blocks that are not fixed and the arrows.
// Needs a current GL context (the CLI's HeadlessContext). Throws corbel::Error when the view
// has an error or the spec's blocks cannot be built.
render::Image renderMasonryView(const editor::MasonryView& view, int width, int height);

// The grid's colours (editor::landscapeColors) as an image, `cell` pixels a sample, the first
// parameter left to right and the second bottom to top (as a plot's axes). `path` (values of
// the two parameters, in order: a search's evaluations, Fig. 8's optimisation path) is drawn
// over it in white, each point a dot ringed in black, the last one larger.
render::Image landscapeImage(const editor::LandscapeGrid& grid, int cell,
                             const std::vector<std::pair<double, double>>& path = {});

}  // namespace corbel::cli
