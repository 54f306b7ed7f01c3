#pragma once
// What statics_panel.cpp and statics_simulate.cpp share: the panel's good and bad colours and
// the host's object. Private to the statics panel's files (and the stone panel's).
#include "editor/statics_panel.h"

#include <imgui.h>

namespace corbel::editor::statics_panel {

inline const ImVec4 kGood(0.4f, 0.85f, 0.4f, 1), kBad(1, 0.45f, 0.35f, 1);

inline const DocObject* objectOf(const StaticsHost& host) { return host.doc ? host.doc->find(host.object) : nullptr; }

// Finished work of a job: rethrows its exception into `error`; Cancelled counts as nothing to
// show. Resets the job once it has finished; false while it runs.
bool collect(std::unique_ptr<BackgroundJob>& job, bool wait, std::string* error);

// What a search changed, as a table: parameter, before, after (nothing when empty).
void drawChanges(const char* id, const std::vector<ParameterChange>& changes);

}  // namespace corbel::editor::statics_panel
