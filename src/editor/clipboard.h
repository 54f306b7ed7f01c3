#pragma once
// Copy and paste of objects between projects. The clipboard holds the objects as a project
// file's JSON (core/project_io.h) with their file paths written relative to the project they
// were copied from, and that project's folder beside them ("copied_from"), so a paste reads
// each relative path against the source and the target's save writes it relative to the
// target. No GL.
#include "core/document.h"

#include <string>
#include <vector>

namespace corbel::editor {

// The objects `ids` of `doc` (in document order) as clipboard text; `sourceFolder` is the
// folder of the project's file ("" for a project never saved: paths stay as they are).
std::string objectsToClipboard(const Document& doc, const std::vector<ObjectId>& ids, const std::string& sourceFolder);

// Adds the clipboard's objects to `doc` with fresh ids and unique names (their placements as
// copied); returns their ids. Throws InputError (naming the fault) for text that is not
// corbel objects.
std::vector<ObjectId> pasteObjects(Document& doc, const std::string& text);

}  // namespace corbel::editor
