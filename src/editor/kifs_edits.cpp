#include "editor/kifs_edits.h"

#include "core/error.h"
#include "kifs/kernel.h"

namespace corbel::editor {

void setKifsSpec(Document& doc, ObjectId id, const KifsSpec& spec) {
  DocObject* o = doc.find(id);
  if (!o) throw Error("there is no object with id " + std::to_string(id));
  auto* k = std::get_if<KifsSpec>(&o->spec);
  if (!k) throw Error(o->name + " is not a KIFS building");
  kifs::paramsOf(spec);  // throws naming the field
  *k = spec;
}

KifsSpec withPreset(const KifsSpec& current, const std::string& name) {
  KifsSpec s = kifs::specOf(kifs::preset(name), name);
  s.meshResolution = current.meshResolution;
  s.material = current.material;
  return s;
}

}  // namespace corbel::editor
