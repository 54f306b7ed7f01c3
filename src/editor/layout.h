#pragma once
// Where the editor's panels go: the menu bar along the top, the object panel on the left, the
// status and log bar along the bottom, a kernel's panel on the right when one is open, and the
// 3D view in what is left. Fixed sizes for now; a pure function, so tests need no window.
namespace corbel::editor {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;  // window pixels, top-left origin
};

inline constexpr float kLeftPanelWidth = 320.0f;
inline constexpr float kStatusBarHeight = 118.0f;
inline constexpr float kRightPaneWidth = 460.0f;     // the plan and profile panes, the kernels' panels
inline constexpr float kGrowthPanelHeight = 470.0f;  // the growth panel, over the form completion panel
inline constexpr float kMinViewWidth = 200.0f;       // a right pane opens only when this much view is left

struct Layout {
  Rect leftPanel, statusBar, rightPane, view;
  bool rightPaneShown = false;
};

// A right pane fits when the view keeps at least kMinViewWidth beside it and the left panel.
bool rightPaneFits(float windowWidth);
// The layout of a window of `width` × `height` whose menu bar is `menuHeight` high; the right
// pane is laid out when `wantRightPane` and it fits.
Layout layoutWindow(float width, float height, float menuHeight, bool wantRightPane);

}  // namespace corbel::editor
