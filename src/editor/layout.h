#pragma once
// Where the editor's panels go: the menu bar along the top, the object panel on the left, the
// status and log bar along the bottom, a kernel's panel on the right when one is open, a
// splitter between each side panel and the 3D view (drag to resize, double-click to collapse),
// the toolbar above the view, and the 3D view in what is left. The sizes are the user's
// (PanelSizes, kept with their settings) times the UI scale; a pure function, so tests need no
// window.
namespace corbel::editor {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;  // window pixels, top-left origin
};

// Sizes at UI scale 1.
inline constexpr float kLeftPanelWidth = 320.0f;
inline constexpr float kStatusBarHeight = 118.0f;
inline constexpr float kRightPaneWidth = 460.0f;     // the plan and profile panes, the kernels' panels
inline constexpr float kGrowthPanelHeight = 470.0f;  // the growth panel, over the form completion panel
inline constexpr float kMinViewWidth = 200.0f;       // a right pane opens only when this much view is left
inline constexpr float kSplitterWidth = 6.0f;
inline constexpr float kToolbarHeight = 32.0f;
inline constexpr float kMinPanelWidth = 180.0f;  // narrower by a drag collapses nothing: it stops here

// The side panels' widths (at UI scale 1) and whether they are shown, and the UI scale.
struct PanelSizes {
  float left = kLeftPanelWidth, right = kRightPaneWidth;
  bool leftShown = true, rightShown = true;
  float scale = 1.0f;
  bool operator==(const PanelSizes&) const = default;
};

struct Layout {
  Rect leftPanel, statusBar, rightPane, view, toolbar;
  Rect leftSplitter, rightSplitter;  // rightSplitter.w == 0: no right pane is wanted
  bool rightPaneShown = false;
};

// A right pane fits when the view keeps at least kMinViewWidth beside it and the left panel.
bool rightPaneFits(float windowWidth, const PanelSizes& sizes = {});
// The layout of a window of `width` × `height` whose menu bar is `menuHeight` high; the right
// pane is laid out when `wantRightPane`, it is not collapsed and it fits; the left panel is
// narrowed to leave the view kMinViewWidth. The panels, splitters, toolbar and view tile the
// window below the menu bar and above the status bar.
Layout layoutWindow(float width, float height, float menuHeight, bool wantRightPane, const PanelSizes& sizes = {});

// A side panel's width (at scale 1) after its splitter was dragged by `dx` window pixels
// (positive: to the right), kept between kMinPanelWidth and what leaves the view kMinViewWidth.
float draggedWidth(float width, float dx, bool leftPanel, float windowWidth, const PanelSizes& sizes);

}  // namespace corbel::editor
