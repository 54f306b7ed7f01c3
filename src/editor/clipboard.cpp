#include "editor/clipboard.h"

#include "core/error.h"
#include "core/json_reader.h"
#include "core/project_io.h"

#include <nlohmann/json.hpp>

namespace corbel::editor {

std::string objectsToClipboard(const Document& doc, const std::vector<ObjectId>& ids, const std::string& sourceFolder) {
  Document part;
  part.name = doc.name;
  for (const DocObject& o : doc.objects)
    if (std::find(ids.begin(), ids.end(), o.id) != ids.end()) part.objects.push_back(o);
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(serializeProject(part, sourceFolder));
  j["copied_from"] = sourceFolder;
  return j.dump(1);
}

std::vector<ObjectId> pasteObjects(Document& doc, const std::string& text) {
  nlohmann::json j = parseJsonText(text);
  if (!j.is_object() || j.value("format", "") != "corbel")
    throw InputError("clipboard", "holds no corbel objects (copy objects in corbel first)");
  std::string folder;
  if (j.contains("copied_from") && j["copied_from"].is_string()) folder = j["copied_from"].get<std::string>();
  j.erase("copied_from");
  const LoadedProject copied = parseProject(j.dump(), folder);
  std::vector<ObjectId> added;
  for (const DocObject& o : copied.document.objects) {
    const ObjectId id = doc.add(o.name, o.spec);
    DocObject& n = *doc.find(id);
    n.visible = o.visible;
    n.background = o.background;
    n.kept = o.kept;
    n.placement = o.placement;
    added.push_back(id);
  }
  return added;
}

}  // namespace corbel::editor
