#include "editor/layout.h"

#include <algorithm>

namespace corbel::editor {

bool rightPaneFits(float windowWidth) { return windowWidth > kLeftPanelWidth + kRightPaneWidth + kMinViewWidth; }

Layout layoutWindow(float width, float height, float menuHeight, bool wantRightPane) {
  Layout l;
  const float body = std::max(0.0f, height - menuHeight - kStatusBarHeight);
  l.leftPanel = {0, menuHeight, kLeftPanelWidth, body};
  l.statusBar = {0, height - kStatusBarHeight, width, kStatusBarHeight};
  l.rightPaneShown = wantRightPane && rightPaneFits(width);
  if (l.rightPaneShown) l.rightPane = {width - kRightPaneWidth, menuHeight, kRightPaneWidth, body};
  l.view = {kLeftPanelWidth, menuHeight,
            std::max(1.0f, width - kLeftPanelWidth - (l.rightPaneShown ? kRightPaneWidth : 0.0f)), std::max(1.0f, body)};
  return l;
}

}  // namespace corbel::editor
