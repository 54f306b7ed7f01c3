#include "editor/town_panel.h"

#include "city/ogr_source.h"
#include "editor/fields.h"

#include "city/street.h"
#include "core/error.h"
#include "editor/pane_window.h"
#include "editor/town_edits.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace corbel::editor {

namespace {

const TownSpec* townOf(const TownHost& host) {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  return o ? std::get_if<TownSpec>(&o->spec) : nullptr;
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

const city::BuiltBuilding* findBuilding(const std::vector<city::BuiltBuilding>& list, const std::string& id) {
  for (const auto& b : list)
    if (b.id == id) return &b;
  return nullptr;
}

// The selected building's index in the town's inputs, or -1.
int buildingIndex(const city::TownInputs& in, const std::string& id) {
  for (std::size_t i = 0; i < in.town.buildings.size(); ++i)
    if (in.town.buildings[i].id == id) return static_cast<int>(i);
  return -1;
}

ImU32 orientationColour(city::Orientation o, float alpha = 1.0f) {
  const int a = static_cast<int>(alpha * 255);
  switch (o) {
    case city::Orientation::Street:
      return IM_COL32(240, 150, 60, a);
    case city::Orientation::Side:
      return IM_COL32(110, 200, 120, a);
    case city::Orientation::Back:
      return IM_COL32(110, 150, 235, a);
  }
  return IM_COL32(200, 200, 200, a);
}

// The building as the style makes it under the override `over` (its profile per edge).
city::StyledBuilding styledWith(const city::TownInputs& in, const TownSpec& spec, int index, const TownOverride& over) {
  city::BuildingOverride resolved;
  if (!over.empty()) {
    TownSpec one = spec;
    one.overrides = {{in.town.buildings[std::size_t(index)].id, over}};
    try {
      const auto all = city::resolveOverrides(in.style, one);
      if (auto it = all.begin(); it != all.end()) resolved = it->second;
    } catch (const Error&) {
      // A bad override is reported by the build; show the style's own draw.
    }
  }
  return city::styleBuilding(in.style, in.town.buildings[std::size_t(index)], in.labels[std::size_t(index)], spec.seed,
                             &resolved);
}

}  // namespace

void TownPanel::selectNextEdge(const TownHost& host) {
  const auto inputs = host.cache->inputs(host.object);
  if (!inputs) return;
  const int bi = buildingIndex(*inputs, selected_);
  if (bi < 0) return;
  const auto& loops = inputs->town.buildings[std::size_t(bi)].loops;
  if (loops.empty()) return;
  auto [l, e] = edgeOf_ == selected_ ? edge_ : std::pair{0, -1};
  if (l < 0) l = 0, e = -1;
  if (++e >= static_cast<int>(loops[std::size_t(l)].size())) e = 0, l = (l + 1) % static_cast<int>(loops.size());
  edge_ = {l, e};
  edgeOf_ = selected_;
}

void TownPanel::overrideNextEdgeProfile(const TownHost& host) {
  const TownSpec* spec = townOf(host);
  const auto inputs = host.cache->inputs(host.object);
  if (!spec || !inputs || edgeOf_ != selected_ || edge_.first < 0 || inputs->style.profiles.empty()) return;
  const int bi = buildingIndex(*inputs, selected_);
  if (bi < 0) return;
  TownOverride over;
  if (auto it = spec->overrides.find(selected_); it != spec->overrides.end()) over = it->second;
  // The profile the edge takes now (the style's draw with the current override), then the next.
  const city::StyledBuilding styled = styledWith(*inputs, *spec, bi, over);
  if (!styled.problem.empty() || edge_.first >= static_cast<int>(styled.spec.loops.size())) return;
  const auto& profile = styled.spec.loops[std::size_t(edge_.first)].profile;
  if (edge_.second >= static_cast<int>(profile.size())) return;
  const std::size_t next = (std::size_t(profile[std::size_t(edge_.second)]) + 1) % inputs->style.profiles.size();
  Document doc = *host.doc;
  const std::string name = inputs->style.profiles[next].name;
  try {
    setTownEdgeProfile(doc, host.object, selected_, edge_.first, edge_.second, name);
  } catch (const Error& e) {
    host.log(e.what(), true);
    return;
  }
  host.commit(std::move(doc),
              "Set edge " + townEdgeKey(edge_.first, edge_.second) + " to " + name + " of building " + selected_, {});
}

void TownPanel::drawEdges(const TownHost& host, const TownSpec& spec, const TownOverride& over) {
  const auto inputs = host.cache->inputs(host.object);
  if (!inputs) return;
  const int bi = buildingIndex(*inputs, selected_);
  if (bi < 0) return;
  const city::Building& b = inputs->town.buildings[std::size_t(bi)];
  const city::BuildingLabels& labels = inputs->labels[std::size_t(bi)];
  if (b.loops.empty() || labels.edges.empty()) return;
  if (edgeOf_ != selected_) edge_ = {-1, -1}, edgeOf_ = selected_;

  // What each edge takes now: the style's draw under the current override.
  const city::StyledBuilding styled = styledWith(*inputs, spec, bi, over);

  ImGui::TextUnformatted("Edges (click one: street orange, side green, back blue)");
  const float side = std::min(ImGui::GetContentRegionAvail().x, 190.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("plan", ImVec2(ImGui::GetContentRegionAvail().x, side));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + ImGui::GetContentRegionAvail().x, origin.y + side);
  dl->AddRectFilled(origin, end, IM_COL32(28, 30, 34, 255));
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& ring : b.loops)
    for (const Vec2& p : ring) lo.minimize(p), hi.maximize(p);
  const float margin = 14.0f, w = end.x - origin.x - 2 * margin, h = side - 2 * margin;
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-6});
  const double scale = std::min(w, h) / extent;
  const Vec2 mid = 0.5 * (lo + hi);
  const ImVec2 centre(origin.x + margin + w / 2, origin.y + margin + h / 2);
  const auto toScreen = [&](const Vec2& p) {
    return ImVec2(centre.x + float((p[0] - mid[0]) * scale), centre.y - float((p[1] - mid[1]) * scale));
  };
  for (const city::EdgeLabel& e : labels.edges) {
    const auto& ring = b.loops[std::size_t(e.loop)];
    const ImVec2 a = toScreen(ring[std::size_t(e.edge)]), c = toScreen(ring[(std::size_t(e.edge) + 1) % ring.size()]);
    const bool picked = edge_ == std::pair{e.loop, e.edge};
    const bool overridden = over.edges.count(townEdgeKey(e.loop, e.edge)) > 0;
    if (picked) dl->AddLine(a, c, IM_COL32(255, 255, 255, 255), 6.0f);
    dl->AddLine(a, c, orientationColour(e.orientation), overridden ? 3.5f : 2.0f);
    const std::string label = std::to_string(e.edge) + (overridden ? "*" : "");
    dl->AddText(ImVec2(0.5f * (a.x + c.x) + 3, 0.5f * (a.y + c.y) - 14), IM_COL32(230, 230, 230, 255), label.c_str());
  }
  if (ImGui::IsItemClicked()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const Vec2 p(mid[0] + (m.x - centre.x) / scale, mid[1] - (m.y - centre.y) / scale);
    if (auto hit = nearestEdge(b.loops, p, 10.0 / scale)) edge_ = *hit;
  }

  if (edge_.first < 0) return;
  const city::EdgeLabel* picked = nullptr;
  for (const auto& e : labels.edges)
    if (std::pair{e.loop, e.edge} == edge_) picked = &e;
  if (!picked) return;
  const std::string key = townEdgeKey(edge_.first, edge_.second);
  auto it = over.edges.find(key);
  std::string now = "?";
  if (styled.problem.empty() && edge_.first < static_cast<int>(styled.spec.loops.size()) &&
      edge_.second < static_cast<int>(styled.spec.loops[std::size_t(edge_.first)].profile.size()))
    now = inputs->style
              .profiles[std::size_t(styled.spec.loops[std::size_t(edge_.first)].profile[std::size_t(edge_.second)])]
              .name;
  ImGui::Text("Edge %s: %s, %.1f m", key.c_str(), std::string(city::orientationName(picked->orientation)).c_str(),
              picked->length);
  const std::string shown =
      it == over.edges.end()
          ? "(as its " + std::string(city::orientationName(picked->orientation)) + " edges: " + now + ")"
          : it->second;
  if (ImGui::BeginCombo("Edge profile", shown.c_str())) {
    if (ImGui::Selectable("(as its orientation's edges)", it == over.edges.end())) {
      Document doc = *host.doc;
      setTownEdgeProfile(doc, host.object, selected_, edge_.first, edge_.second, "");
      host.commit(std::move(doc), "Give back edge " + key + " of building " + selected_, {});
    }
    for (const auto& p : inputs->style.profiles)
      if (ImGui::Selectable(p.name.c_str(), it != over.edges.end() && it->second == p.name)) {
        Document doc = *host.doc;
        setTownEdgeProfile(doc, host.object, selected_, edge_.first, edge_.second, p.name);
        host.commit(std::move(doc), "Set edge " + key + " to " + p.name + " of building " + selected_, {});
      }
    ImGui::EndCombo();
  }
}

void TownPanel::commitOverride(const TownHost& host, const TownOverride& o, const std::string& what) {
  Document doc = *host.doc;
  try {
    setTownOverride(doc, host.object, selected_, o);
  } catch (const Error& e) {
    host.log(e.what(), true);
    return;
  }
  host.commit(std::move(doc), what + " of building " + selected_, {});
}

void TownPanel::selectNext(const TownHost& host) {
  const auto list = host.cache->buildings(host.object);
  if (list.empty()) return;
  std::size_t next = 0;
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i].id == selected_) next = (i + 1) % list.size();
  selected_ = list[next].id;
  scrollToSelected_ = true;
}

void TownPanel::overrideNextType(const TownHost& host) {
  const TownSpec* spec = townOf(host);
  const auto inputs = host.cache->inputs(host.object);
  const auto list = host.cache->buildings(host.object);
  const city::BuiltBuilding* b = findBuilding(list, selected_);
  if (!spec || !inputs || !b || inputs->style.types.empty()) return;
  const auto& types = inputs->style.types;
  std::size_t at = 0;
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i].name == b->type) at = (i + 1) % types.size();
  TownOverride o;
  if (auto it = spec->overrides.find(selected_); it != spec->overrides.end()) o = it->second;
  o.type = types[at].name;
  commitOverride(host, o, "Set the type to " + o.type);
}

bool TownPanel::commitStreets(const TownHost& host, const std::function<void(Document&)>& edit, const std::string& what,
                              const std::string& merge) {
  Document doc = *host.doc;
  try {
    edit(doc);
  } catch (const Error& e) {
    host.log(e.what(), true);
    return false;
  }
  host.commit(std::move(doc), what, merge);
  return true;
}

void TownPanel::addStreet(const TownHost& host) {
  if (!townOf(host)) return;
  const TownStreet st = defaultStreet(*host.cache, host.object);
  std::size_t k = 0;
  if (commitStreets(
          host, [&](Document& d) { k = editor::addStreet(d, host.object, st); }, "Add a street"))
    street_ = int(k), point_ = 1, openStreets_ = true;
}

void TownPanel::bendStreet(const TownHost& host) {
  const TownSpec* t = townOf(host);
  if (!t || t->streets.empty()) return;
  if (street_ < 0 || street_ >= int(t->streets.size())) street_ = int(t->streets.size()) - 1;
  const auto& pts = t->streets[std::size_t(street_)].points;
  const std::size_t mid = pts.size() / 2;
  const Vec2 to(pts[mid][0], pts[mid][1] - 10);
  commitStreets(
      host, [&](Document& d) { moveStreetPoint(d, host.object, std::size_t(street_), mid, to); },
      "Bend street " + std::to_string(street_ + 1));
}

void TownPanel::pick(const TownHost& host, const Vec3& origin, const Vec3& dir) {
  const TownSpec* t = townOf(host);
  if (moveOnClick_ && t && street_ >= 0 && street_ < int(t->streets.size()) && point_ >= 0 &&
      point_ < int(t->streets[std::size_t(street_)].points.size())) {
    if (auto g = groundPoint(origin, dir)) {
      const std::size_t k = std::size_t(street_), i = std::size_t(point_);
      commitStreets(
          host, [&](Document& d) { moveStreetPoint(d, host.object, k, i, *g); },
          "Move point " + std::to_string(i + 1) + " of street " + std::to_string(k + 1));
    }
    return;
  }
  if (auto id = pickBuilding(*host.cache, host.object, origin, dir)) {
    selected_ = *id;
    scrollToSelected_ = true;
    host.log("picked building " + *id, false);
  }
}

void TownPanel::drawOverlay(const TownHost& host, render::Overlay& overlay) const {
  // The streets: their centrelines (the spline the plots are cut along) and control points, the
  // selected street in yellow, its selected point larger.
  if (const TownSpec* t = townOf(host))
    for (std::size_t k = 0; k < t->streets.size(); ++k) {
      const TownStreet& st = t->streets[k];
      std::vector<Vec2> control;
      for (const auto& p : st.points) control.emplace_back(p[0], p[1]);
      const bool chosen = int(k) == street_;
      const render::Rgba line = chosen ? render::Rgba{1.0f, 0.85f, 0.2f, 1.0f} : render::Rgba{0.85f, 0.85f, 0.9f, 1.0f};
      const std::vector<Vec2> spline = city::catmullRom(control);
      for (std::size_t i = 0; i + 1 < spline.size(); ++i)
        overlay.line(Vec3(spline[i][0], spline[i][1], 0.15), Vec3(spline[i + 1][0], spline[i + 1][1], 0.15), line);
      for (std::size_t i = 0; i < control.size(); ++i) {
        const double r = chosen && int(i) == point_ ? 2.5 : 1.2;
        const Vec3 c(control[i][0], control[i][1], 0.2);
        overlay.line(c - Vec3(r, 0, 0), c + Vec3(r, 0, 0), line);
        overlay.line(c - Vec3(0, r, 0), c + Vec3(0, r, 0), line);
      }
    }
  if (selected_.empty()) return;
  const auto list = host.cache->buildings(host.object);
  const city::BuiltBuilding* b = findBuilding(list, selected_);
  if (!b || b->bounds.empty()) return;
  const Vec3 lo = b->bounds.lo, hi = b->bounds.hi;
  const render::Rgba c{1.0f, 0.55f, 0.1f, 1.0f};
  Vec3 p[8];
  for (int k = 0; k < 8; ++k) p[k] = Vec3(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]);
  const int edges[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                            {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : edges) overlay.line(p[e[0]], p[e[1]], c);
  // The edge picked in the plan view: white, a little above the ground, with a post at each end.
  if (edgeOf_ != selected_ || edge_.first < 0) return;
  const auto inputs = host.cache->inputs(host.object);
  const int bi = inputs ? buildingIndex(*inputs, selected_) : -1;
  if (bi < 0) return;
  const auto& loops = inputs->town.buildings[std::size_t(bi)].loops;
  if (edge_.first >= static_cast<int>(loops.size()) ||
      edge_.second >= static_cast<int>(loops[std::size_t(edge_.first)].size()))
    return;
  const auto& ring = loops[std::size_t(edge_.first)];
  const Vec2 a = ring[std::size_t(edge_.second)], e2 = ring[(std::size_t(edge_.second) + 1) % ring.size()];
  const render::Rgba white{1.0f, 1.0f, 1.0f, 1.0f};
  for (double z : {0.1, 0.3}) overlay.line(Vec3(a[0], a[1], z), Vec3(e2[0], e2[1], z), white);
  overlay.line(Vec3(a[0], a[1], 0.1), Vec3(a[0], a[1], hi[2]), white);
  overlay.line(Vec3(e2[0], e2[1], 0.1), Vec3(e2[0], e2[1], hi[2]), white);
}

void TownPanel::drawStreets(const TownHost& host, const TownSpec& spec) {
  const ObjectId id = host.object;
  if (street_ >= int(spec.streets.size())) street_ = point_ = -1;
  if (street_ < 0 && !spec.streets.empty()) street_ = int(spec.streets.size()) - 1, point_ = 0;  // one is always chosen
  ImGui::SetNextItemOpen(!spec.streets.empty(), ImGuiCond_Appearing);
  if (openStreets_) ImGui::SetNextItemOpen(true), openStreets_ = false;
  if (!ImGui::CollapsingHeader("Streets (Fig. 26)")) return;
  if (ImGui::SmallButton("Add street")) addStreet(host);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A straight street along the town's south side; its plots become houses");
  for (std::size_t k = 0; k < spec.streets.size(); ++k) {
    const std::string label =
        "street " + std::to_string(k + 1) + " (" + std::to_string(spec.streets[k].points.size()) + " points)";
    ImGui::SameLine();
    if (ImGui::SmallButton(label.c_str())) street_ = int(k), point_ = 0;
  }
  if (street_ < 0) {
    ImGui::TextDisabled("Select a street to edit its points; plots become houses facing it.");
    return;
  }
  const std::size_t k = std::size_t(street_);
  const TownStreet& st = spec.streets[k];
  const std::string key = "town.street." + std::to_string(id) + "." + std::to_string(k);
  for (std::size_t i = 0; i < st.points.size(); ++i) {
    float xy[2] = {float(st.points[i][0]), float(st.points[i][1])};
    ImGui::PushID(int(i));
    if (ImGui::RadioButton("##pick", point_ == int(i))) point_ = int(i);
    ImGui::SameLine();
    if (ImGui::DragFloat2(("point " + std::to_string(i + 1)).c_str(), xy, 0.25f, -1e6f, 1e6f, "%.2f")) {
      const Vec2 to(xy[0], xy[1]);
      commitStreets(
          host, [&](Document& d) { moveStreetPoint(d, id, k, i, to); },
          "Move point " + std::to_string(i + 1) + " of street " + std::to_string(k + 1),
          key + ".point." + std::to_string(i));
    }
    ImGui::PopID();
  }
  ImGui::Checkbox("Move the chosen point on click", &moveOnClick_);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A click on the ground in the 3D view moves the chosen point there");
  TownStreet edit = st;
  bool changed = false;
  float v[4] = {float(st.width), float(st.setback), float(st.depth), float(st.plotWidth)};
  changed |= ImGui::DragFloat("Street width", &v[0], 0.1f, 1, 100, "%.1f m");
  changed |= ImGui::DragFloat("Setback", &v[1], 0.1f, 0, 50, "%.1f m");
  changed |= ImGui::DragFloat("Plot depth", &v[2], 0.1f, 3, 200, "%.1f m");
  changed |= ImGui::DragFloat("Plot width", &v[3], 0.1f, 3, 200, "%.1f m");
  bool both = st.bothSides;
  changed |= ImGui::Checkbox("Plots on both sides", &both);
  bool grown = st.skeletonPlots;
  changed |= ImGui::Checkbox("Grow plots from seeds (skeleton)", &grown);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Fig. 26: each plot grown from a seed by a second application of the skeleton; "
        "off: cut along the street's normals");
  if (changed) {
    edit.width = v[0], edit.setback = v[1], edit.depth = v[2], edit.plotWidth = v[3], edit.bothSides = both;
    edit.skeletonPlots = grown;
    commitStreets(
        host, [&](Document& d) { setStreet(d, id, k, edit); }, "Edit street " + std::to_string(k + 1), key + ".values");
  }
  if (ImGui::SmallButton("Add point")) {
    TownStreet more = st;
    const auto& a = st.points[st.points.size() - 2];
    const auto& b = st.points.back();
    more.points.push_back({2 * b[0] - a[0], 2 * b[1] - a[1]});  // continues the last span
    commitStreets(
        host, [&](Document& d) { setStreet(d, id, k, more); }, "Add a point to street " + std::to_string(k + 1));
  }
  ImGui::SameLine();
  if (st.points.size() > 2 && point_ >= 0 && ImGui::SmallButton("Remove point")) {
    TownStreet fewer = st;
    fewer.points.erase(fewer.points.begin() + point_);
    commitStreets(
        host, [&](Document& d) { setStreet(d, id, k, fewer); }, "Remove a point of street " + std::to_string(k + 1));
    point_ = std::min(point_, int(fewer.points.size()) - 1);
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("Delete street")) {
    commitStreets(
        host, [&](Document& d) { removeStreet(d, id, k); }, "Delete street " + std::to_string(k + 1));
    street_ = point_ = -1;
  }
}

void TownPanel::draw(const TownHost& host, float x, float y, float w, float h) {
  const TownSpec* current = townOf(host);
  if (!current) return;
  const DocObject* o = host.doc->find(host.object);
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Town", nullptr, kPaneFlags);
  ImGui::PushItemWidth(-110.0f);
  ImGui::Text("%s: town from footprints (Kelly & Wonka 3.7)", o->name.c_str());
  const ObjectId id = host.object;
  const auto commitSpec = [&host, id](TownSpec s, const std::string& label, const std::string& merge) {
    Document doc = *host.doc;
    try {
      setTownSpec(doc, id, s);
    } catch (const Error& e) {
      host.log(e.what(), true);
      return;
    }
    host.commit(std::move(doc), label, merge);
  };

  // Inputs: footprints, style, seed, detail.
  ImGui::TextUnformatted("Footprints");
  ImGui::SameLine(110);
  ImGui::TextUnformatted(current->footprints.empty() ? "(embedded GeoJSON)" : fileName(current->footprints).c_str());
  if (ImGui::IsItemHovered() && !current->footprints.empty()) ImGui::SetTooltip("%s", current->footprints.c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("Open...")) {
    const TownSpec s = *current;
    host.openFile("Open footprints", city::vectorFileExtensions(), s.footprints, [commitSpec, s](const std::string& path) {
      TownSpec t = s;
      t.footprints = path;
      t.footprintsJson.clear();
      t.overrides.clear();  // other footprints: the ids mean other buildings
      commitSpec(t, "Open footprints " + fileName(path), {});
    });
  }
  // Where GDAL needs telling: the source's CRS when it names none, the layer of a source with
  // several, an attribute filter. Each applies when its field is left; overrides stay, by id.
  struct SourceField {
    const char* label;
    std::string TownSpec::*member;
    const char* help;
  };
  const SourceField sourceFields[] = {
      {"CRS", &TownSpec::crs, "The footprints' CRS when the file names none: EPSG:32632, a WKT, a PROJ string, or "
                              "\"local\" for metres as they are. Empty: the file's own."},
      {"Layer", &TownSpec::layer, "The layer to read from a source with several (a GeoPackage, a folder). Empty: the only one."},
      {"Filter", &TownSpec::where, "An OGR SQL attribute filter, e.g. building = 'house' AND height > 3. Empty: every feature."}};
  for (const SourceField& f : sourceFields) {
    std::string value;
    if (commitText(f.label, current->*f.member, value, 1000)) {
      TownSpec t = *current;
      t.*f.member = value;
      commitSpec(t, std::string("Footprints' ") + (f.label == std::string("Filter") ? "filter" : f.label) + " " + value, {});
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.help);
  }
  const std::vector<std::string> styles = stylesIn(host.stylesFolder);
  const std::string styleLabel = current->style.empty() ? "(embedded)" : fileName(current->style);
  if (ImGui::BeginCombo("Style", styleLabel.c_str())) {
    for (const std::string& path : styles)
      if (ImGui::Selectable(fileName(path).c_str(), fileName(path) == styleLabel && !current->style.empty())) {
        TownSpec t = *current;
        t.style = path;
        t.styleJson.clear();
        commitSpec(t, "Style the town " + fileName(path), {});
      }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("File...")) {
    const TownSpec s = *current;
    host.openFile("Open a style", {".json"}, s.style.empty() ? host.stylesFolder + "/" : s.style,
                  [commitSpec, s](const std::string& path) {
                    TownSpec t = s;
                    t.style = path;
                    t.styleJson.clear();
                    commitSpec(t, "Style the town " + fileName(path), {});
                  });
  }
  int seed = static_cast<int>(current->seed);
  if (ImGui::InputInt("Seed", &seed) && seed >= 0) {
    TownSpec t = *current;
    t.seed = static_cast<std::uint64_t>(seed);
    commitSpec(t, "Seed the town " + std::to_string(seed), "town.seed." + std::to_string(id));
  }
  const char* details[] = {"massing", "steps", "full"};
  if (ImGui::BeginCombo("Detail", current->detail.c_str())) {
    for (const char* d : details)
      if (ImGui::Selectable(d, current->detail == d)) {
        TownSpec t = *current;
        t.detail = d;
        commitSpec(t, std::string("Town detail ") + d, {});
      }
    ImGui::EndCombo();
  }

  // The build.
  if (host.building) {
    ImGui::ProgressBar(static_cast<float>(host.fraction), ImVec2(-70, 0), "Building the town...");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) host.cancel();
  } else if (host.cancelled) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Cancelled: the view shows the last build.");
    ImGui::SameLine();
    if (ImGui::SmallButton("Build")) host.retry();
  }
  if (!host.error.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", host.error.c_str());

  const auto list = host.cache->buildings(host.object);
  const auto inputs = host.cache->inputs(host.object);
  std::map<std::string, int> types;
  std::size_t built = 0;
  for (const auto& b : list) {
    if (b.error.empty()) ++built, ++types[b.type];
  }
  ImGui::Text("%zu buildings, %zu built, %zu overridden", list.size(), built, current->overrides.size());
  std::string byType;
  for (const auto& [t, n] : types) byType += (byType.empty() ? "" : ", ") + std::to_string(n) + " " + t;
  if (!byType.empty()) ImGui::TextWrapped("%s", byType.c_str());

  drawStreets(host, *current);

  // The buildings, by footprint id.
  ImGui::Separator();
  ImGui::TextUnformatted("Buildings (click one here or in the 3D view)");
  // Below the list: the building's type and orientation combos, its plan view and edge combo.
  const float listH =
      std::max(60.0f, ImGui::GetContentRegionAvail().y - 10 * ImGui::GetFrameHeightWithSpacing() - 200.0f);
  ImGui::BeginChild("buildings", ImVec2(0, listH), true);
  // Only the visible rows are drawn (a real town has thousands of buildings).
  const float rowH = ImGui::GetTextLineHeightWithSpacing();
  if (scrollToSelected_) {
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i].id == selected_) ImGui::SetScrollY(std::max(0.0f, float(i) * rowH - 0.5f * listH));
    scrollToSelected_ = false;
  }
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(list.size()), rowH);
  while (clipper.Step())
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const city::BuiltBuilding& b = list[std::size_t(i)];
      const bool overridden = current->overrides.count(b.id) > 0;
      const std::string row = b.id + "  " + (b.error.empty() ? b.type : "(not built)") + (overridden ? "  *" : "");
      if (ImGui::Selectable(row.c_str(), b.id == selected_)) selected_ = b.id;
      if (!b.error.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", b.error.c_str());
    }
  ImGui::EndChild();

  // The selected building: its type and profiles, overridable.
  const city::BuiltBuilding* b = findBuilding(list, selected_);
  if (b && inputs) {
    TownOverride over;
    if (auto it = current->overrides.find(b->id); it != current->overrides.end()) over = it->second;
    ImGui::Text("Building %s: %s", b->id.c_str(), b->type.empty() ? "no type" : b->type.c_str());
    if (!b->error.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", b->error.c_str());
    if (ImGui::BeginCombo("Type", over.type.empty() ? "(the style's choice)" : over.type.c_str())) {
      if (ImGui::Selectable("(the style's choice)", over.type.empty())) {
        TownOverride n = over;
        n.type.clear();
        commitOverride(host, n, "Give back the style's type");
      }
      for (const auto& t : inputs->style.types)
        if (ImGui::Selectable(t.name.c_str(), t.name == over.type)) {
          TownOverride n = over;
          n.type = t.name;
          commitOverride(host, n, "Set the type to " + t.name);
        }
      ImGui::EndCombo();
    }
    for (const char* side : {"street", "side", "back"}) {
      auto it = over.profiles.find(side);
      const std::string shown = it == over.profiles.end() ? "(the style's choice)" : it->second;
      if (ImGui::BeginCombo((std::string(side) + " edges").c_str(), shown.c_str())) {
        if (ImGui::Selectable("(the style's choice)", it == over.profiles.end())) {
          TownOverride n = over;
          n.profiles.erase(side);
          commitOverride(host, n, std::string("Give back the style's ") + side + " profiles");
        }
        for (const auto& p : inputs->style.profiles)
          if (ImGui::Selectable(p.name.c_str(), it != over.profiles.end() && it->second == p.name)) {
            TownOverride n = over;
            n.profiles[side] = p.name;
            commitOverride(host, n, std::string("Set the ") + side + " profiles to " + p.name);
          }
        ImGui::EndCombo();
      }
    }
    drawEdges(host, *current, over);
    if (!over.empty() && ImGui::Button("Clear override")) commitOverride(host, TownOverride{}, "Clear the override");
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace corbel::editor
