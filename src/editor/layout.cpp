#include "editor/layout.h"

#include <algorithm>

namespace corbel::editor {

namespace {
float leftWidth(const PanelSizes& s) { return s.leftShown ? s.left * s.scale : 0.0f; }
}  // namespace

bool rightPaneFits(float windowWidth, const PanelSizes& s) {
  return s.rightShown && windowWidth > leftWidth(s) + s.right * s.scale + (2 * kSplitterWidth + kMinViewWidth) * s.scale;
}

Layout layoutWindow(float width, float height, float menuHeight, bool wantRightPane, const PanelSizes& s) {
  Layout l;
  const float k = s.scale, statusH = std::min(kStatusBarHeight * k, std::max(0.0f, height - menuHeight) / 2);
  const float body = std::max(0.0f, height - menuHeight - statusH);
  const float split = kSplitterWidth * k;
  // A panel wider than the window allows (a settings file from a larger screen) leaves the view
  // its least width.
  const float left = std::max(0.0f, std::min(leftWidth(s), width - split - kMinViewWidth * k));
  l.leftPanel = {0, menuHeight, left, body};
  l.leftSplitter = {left, menuHeight, split, body};
  l.statusBar = {0, height - statusH, width, statusH};
  l.rightPaneShown = wantRightPane && rightPaneFits(width, s);
  float right = 0;  // what the right pane and its splitter take
  if (l.rightPaneShown) {
    l.rightPane = {width - s.right * k, menuHeight, s.right * k, body};
    l.rightSplitter = {l.rightPane.x - split, menuHeight, split, body};
    right = l.rightPane.w + split;
  } else if (wantRightPane && !s.rightShown) {
    l.rightSplitter = {width - split, menuHeight, split, body};  // collapsed: the splitter stays to open it
    right = split;
  }
  const float viewX = left + split, viewW = std::max(1.0f, width - viewX - right);
  const float toolbarH = std::min(kToolbarHeight * k, body / 2);
  l.toolbar = {viewX, menuHeight, viewW, toolbarH};
  l.view = {viewX, menuHeight + toolbarH, viewW, std::max(1.0f, body - toolbarH)};
  return l;
}

float draggedWidth(float width, float dx, bool leftPanel, float windowWidth, const PanelSizes& s) {
  const float k = std::max(s.scale, 0.1f);
  const float other = leftPanel ? (s.rightShown ? s.right * k + kSplitterWidth * k : 0.0f) : leftWidth(s);
  const float most = (windowWidth - other - (2 * kSplitterWidth + kMinViewWidth) * k) / k;
  const float w = width + (leftPanel ? dx : -dx) / k;
  return std::max(kMinPanelWidth, std::min(w, most));
}

}  // namespace corbel::editor
