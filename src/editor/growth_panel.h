#pragma once
// The growth panel of a selected growth site (Ng, Ch. 4), right of the 3D view: the site's
// summary, the run's seed, and Step, Run, Pause, Grow to the end and Reset. The Document holds
// how many steps the site grows (core/growth_spec.h); every button commits a new count and the
// object's Scene build grows it off the UI thread (core/live_sync.h), so the window never
// waits and a whole Run is one undo step.
#include "core/document.h"

#include <functional>
#include <string>
#include <vector>

namespace corbel::editor {

struct GrowthHost {
  const Document* doc = nullptr;
  ObjectId object = 0;
  bool current = true;                // the Scene shows the current document
  std::string error;                  // the kernel's message for the object
  std::vector<std::string> warnings;  // of its last build (growth/kernel.h: when every unit stopped)
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void()> endDrag;
  std::function<void(const std::string&, bool)> log;
};

class GrowthPanel {
 public:
  // Advances a running growth by one step once the Scene has caught up with the last one.
  void update(const GrowthHost& host);
  void draw(const GrowthHost& host, float x, float y, float w, float h);
  void reset() { running_ = false; }
  // The buttons, also the actions growth.step and growth.run.
  void step(const GrowthHost& host);
  void toggleRun(const GrowthHost& host);
  bool running() const { return running_; }

 private:
  void commitSteps(const GrowthHost& host, int steps, const std::string& label, const std::string& merge = {});
  bool running_ = false;
  std::string summaryOf_, summary_;  // the site text summarised, and the summary
};

}  // namespace corbel::editor
