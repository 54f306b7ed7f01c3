#include "editor/completion_panel.h"

#include "editor/symbols.h"

#include "core/materials.h"
#include "editor/completion_edits.h"
#include "editor/completion_view.h"
#include "editor/pane_window.h"
#include "growth/constraints.h"
#include "growth/tolerances.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace corbel::editor {

namespace {

constexpr double kMinRegion = 3.0;  // meters each way (as corbel-cli complete --region)

ImU32 unitColour(int id, float alpha = 1.0f) {
  const Rgb c = materialColor(unitMaterial(id), Kind::Unit);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], alpha));
}

growth::Fraction fractionOf(double v) { return growth::Fraction::of(std::llround(v * 10000.0), 10000); }

std::string fq(const growth::Complexity& c) {
  const growth::Fraction v = c.value();
  char text[64];
  std::snprintf(text, sizeof text, "F_q %lld/%lld = %.3f", static_cast<long long>(v.num), static_cast<long long>(v.den),
                v.value());
  return text;
}

}  // namespace

const GrowthSpec* CompletionPanel::specOf(const CompletionHost& host) const {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  return o ? std::get_if<GrowthSpec>(&o->spec) : nullptr;
}

growth::GrowthInput CompletionPanel::inputOf(const CompletionHost& host) const {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  return o ? growth::growthInputOf(*host.doc, *o) : growth::GrowthInput{};
}

bool CompletionPanel::modelCurrent(const CompletionHost& host) const {
  const GrowthSpec* spec = specOf(host);
  return spec && model_ && model_->of == inputOf(host) && model_->maps == host.maps;
}

void CompletionPanel::reset() { *this = CompletionPanel(); }

double CompletionPanel::storeyZ() const {
  if (!model_) return 0.0;
  return model_->grown.site.base + storey_ * model_->grown.site.storeyHeight;
}

void CompletionPanel::defaultRegion(const growth::Site& site) {
  // The middle fifth of the site across, its middle half deep: on the example sites a gap
  // between two cores that the growth leaves partly empty.
  const growth::Box b = site.bounds();
  const double w = b.size(0), d = b.size(1);
  region_ = {std::round(b.lo[0] + 0.4 * w), std::round(b.lo[1] + 0.25 * d), std::round(b.lo[0] + 0.6 * w),
             std::round(b.lo[1] + 0.75 * d)};
  regionSet_ = true;
}

std::pair<growth::EntranceOptions, std::vector<growth::Box>> CompletionPanel::entranceSetup() const {
  const growth::Site& site = model_->grown.site;
  return {growth::storeyOptions(site, storey_), growth::entranceObstacles(site)};
}

void CompletionPanel::gapRegion() {
  if (!model_) return;
  const growth::EntranceOptions eo = entranceSetup().first;
  const growth::Box b = model_->grown.site.bounds();
  growth::PlanRect gap;
  // The gap keeps the clearance the growth keeps from cores and circulation.
  if (growth::findGap(model_->grown.units, growth::clearanceZones(model_->grown.site),
                      {b.lo[0], b.lo[1], b.hi[0], b.hi[1]}, eo, growth::kGapMinSide, growth::kGapMaxSide, gap)) {
    region_ = gap;
    regionSet_ = true;
  }
}

void CompletionPanel::updateEntrances() {
  if (!model_) {
    entrances_.clear();
    return;
  }
  const growth::PlanRect& r = region_;
  if (entrancesModel_ == model_.get() && entrancesStorey_ == storey_ && entrancesFor_.x0 == r.x0 &&
      entrancesFor_.y0 == r.y0 && entrancesFor_.x1 == r.x1 && entrancesFor_.y1 == r.y1)
    return;
  const auto [eo, obstacles] = entranceSetup();
  entrances_ = growth::entrancesInRegion(model_->grown.units, region_, eo, obstacles);
  entrancesModel_ = model_.get();
  entrancesStorey_ = storey_;
  entrancesFor_ = region_;
}

void CompletionPanel::run(const CompletionHost& host, std::string title, BackgroundJob::Work work,
                          std::function<void()> done) {
  if (host.wait) {
    Progress p;
    try {
      work(p);
      done();
    } catch (const std::exception& e) {
      host.log(title + " failed: " + e.what(), true);
    }
    return;
  }
  if (host.busy) {
    host.log("Busy with another job; try again when it finishes.", true);
    return;
  }
  host.startJob(std::move(title), std::move(work), std::move(done));
}

void CompletionPanel::takeSeeds(const CompletionHost& host) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  fromModel_ = true;
  if (modelCurrent(host)) return;
  auto result = std::make_shared<Model>();
  result->of = inputOf(host);
  result->maps = host.maps;
  attempted_ = result->of;
  run(
      host, "Growing the model for its entrances",
      [result, mapper = host.mapper](Progress& p) { result->grown = growth::grow(result->of, &p, mapper.get()); },
      [this, result] {
        model_ = result;
        if (!regionChosen_) gapRegion();
        storey_ = std::clamp(storey_, 0, model_->grown.site.storeys - 1);
        updateEntrances();
        status_ = std::to_string(model_->grown.units.size()) + " grown units";
      });
}

void CompletionPanel::generate(const CompletionHost& host) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  if (fromModel_ && !modelCurrent(host)) {
    takeSeeds(host);
    if (!modelCurrent(host)) {
      host.log("Form completion: the model is being grown for its entrances; Generate again when it is done", false);
      return;
    }
  }
  updateEntrances();
  growth::FormRequest rq;
  rq.seeds = fromModel_ ? int(entrances_.size()) : count_;
  if (rq.seeds < 1) {
    host.log("Form completion: no entrance in the region (move it against grown units, or set the seeds by count)",
             true);
    return;
  }
  rq.lo = fractionOf(std::min(lo_, hi_));
  rq.hi = fractionOf(std::max(lo_, hi_));
  rq.count = forms_wanted_;
  rq.seed = std::uint64_t(std::max(0, seed_));
  auto result = std::make_shared<growth::FormSet>();
  const int seeds = rq.seeds;
  // Among a grown model, batches from the next seeds follow (at most kRounds) until a form obeys
  // the growth rules in the region: a shallow gap leaves many forms with a room under 3 m.
  std::shared_ptr<const Model> model = fromModel_ ? model_ : nullptr;
  auto work = [result, rq, model, region = region_, at = doors(), fo = fitOptions()](Progress& p) {
    constexpr int kRounds = 4;
    growth::FormRequest r = rq;
    std::set<std::string> seen;
    for (int round = 0; round < kRounds; ++round, ++r.seed) {
      growth::FormSet batch = growth::generateForms(r, &p);
      result->attempts += batch.attempts;
      if (result->note.empty()) result->note = batch.note;
      bool fits = false;
      for (growth::Form& f : batch.forms) {
        if (!seen.insert(f.topology).second) continue;
        if (model && !fits)
          fits = growth::formViolations(model->grown.site, model->grown.units, growth::fitForm(f.plan, region, at, fo))
                     .empty();
        result->forms.push_back(std::move(f));
      }
      if (!model || fits || p.cancelled()) break;
    }
  };
  run(
      host, "Generating forms", work,
      [this, result, seeds, log = host.log] {
        forms_ = std::move(*result);
        formsSeeds_ = seeds;
        picked_ = forms_.forms.empty() ? -1 : 0;
        fitted_.reset();
        status_ = std::to_string(forms_.forms.size()) + " forms of " + std::to_string(seeds) + " units" +
                  (forms_.note.empty() ? "" : " (" + forms_.note + ")");
        judgeForms();
        if (!formFits_.empty()) {
          const int fitting = int(std::count(formFits_.begin(), formFits_.end(), true));
          status_ += "; " + std::to_string(fitting) + (fitting == 1 ? " obeys" : " obey") +
                     " the growth rules in the region";
        }
        log("Form completion: " + status_, forms_.forms.empty());
      });
}

std::vector<Vec2> CompletionPanel::doors() const {
  std::vector<Vec2> at;
  if (fromModel_)
    for (const growth::Entrance& e : entrances_) at.push_back(e.at);
  return at;
}

growth::FitOptions CompletionPanel::fitOptions() const {
  growth::FitOptions fo;
  fo.z0 = storeyZ();
  if (model_) {
    fo.storeyHeight = model_->grown.site.storeyHeight;
    fo.roomWidth = growth::kMinPartWidth;  // rooms as the growth makes them
  }
  return fo;
}

// Among a grown model each form is fitted into the region and judged by the growth rules; the
// pick is the best that obeys them (as corbel-cli complete --from places it).
void CompletionPanel::judgeForms() {
  formFits_.clear();
  if (!model_ || !fromModel_ || forms_.forms.empty()) return;
  updateEntrances();
  std::vector<growth::FittedForm> fitted;
  for (const growth::Form& f : forms_.forms) {
    try {
      fitted.push_back(growth::fitForm(f.plan, region_, doors(), fitOptions()));
      formFits_.push_back(growth::formViolations(model_->grown.site, model_->grown.units, fitted.back()).empty());
    } catch (const std::exception&) {
      fitted.emplace_back();
      formFits_.push_back(false);
    }
  }
  const int best = growth::bestFit(fitted, formFits_);
  if (best >= 0) picked_ = best;
}

void CompletionPanel::fit(const CompletionHost& host) {
  if (!canFit()) return;
  updateEntrances();
  const std::vector<Vec2> at = doors();
  const growth::FitOptions fo = fitOptions();
  try {
    fitted_ = growth::fitForm(forms_.forms[std::size_t(picked_)].plan, region_, at, fo);
    fittedViolations_.clear();
    fittedForm_ = picked_;
    fittedZ_ = fo.z0;
    fittedRegion_ = region_;
    char text[160];
    std::snprintf(text, sizeof text, "form %d fitted: orientation %d, sizing error %.2f -> %.2f", picked_ + 1,
                  fitted_->orientation, fitted_->sizing.before, fitted_->sizing.after);
    status_ = text;
    if (!fitted_->entranceFits.empty()) {
      const auto met = std::count_if(fitted_->entranceFits.begin(), fitted_->entranceFits.end(),
                                     [](const growth::EntranceFit& e) { return e.realized; });
      status_ += "; doors met " + std::to_string(met) + " of " + std::to_string(fitted_->entranceFits.size());
      for (const growth::EntranceFit& e : fitted_->entranceFits)
        if (!e.realized)
          host.log("Fit to region: entrance " + std::to_string(e.entrance + 1) + " not met: " + e.why, false);
    }
    // Among a grown model the form obeys the growth rules (clearance, rooms 3 m wide, envelope,
    // supports, no overlap), or it is not extruded: each broken rule goes to the log.
    if (model_) {
      fittedViolations_ = growth::formViolations(model_->grown.site, model_->grown.units, *fitted_);
      if (!fittedViolations_.empty()) {
        status_ += "; breaks " + std::to_string(fittedViolations_.size()) +
                   " growth rules (see the log): choose another region or form";
        for (const std::string& v : fittedViolations_) host.log("Fit to region: " + v, true);
      }
    }
  } catch (const std::exception& e) {
    host.log(std::string("Fit to region: ") + e.what(), true);
  }
}

void CompletionPanel::extrude(const CompletionHost& host) {
  if (!fitted_ || !host.doc) return;
  const DocObject* site = host.doc->find(host.object);
  Document d = *host.doc;
  UnitExtrusion how;
  how.storeys = storeys_;
  how.storeyHeight = model_ ? model_->grown.site.storeyHeight : 3.0;
  // "<site> form k": the first k no object's name starts with.
  const std::string prefix = (site ? site->name + " " : std::string()) + "form ";
  for (int k = 1;; ++k) {
    const std::string name = prefix + std::to_string(k);
    const bool used = std::any_of(d.objects.begin(), d.objects.end(),
                                  [&](const DocObject& o) { return o.name.rfind(name + " ", 0) == 0; });
    if (!used) {
      how.name = name;
      break;
    }
  }
  try {
    const std::vector<ObjectId> ids = extrudeUnits(d, fitted_->units, how);
    host.commit(std::move(d), "Extrude " + how.name + " into " + std::to_string(ids.size()) + " units", "");
    host.log("Form completion: " + how.name + " extruded into " + std::to_string(ids.size()) + " unit objects", false);
    fitted_.reset();  // the 3D view shows the units themselves now
    status_ = how.name + " extruded: " + std::to_string(ids.size()) + " unit objects (Ctrl+Z removes them)";
  } catch (const std::exception& e) {
    host.log(std::string("Extrude to units: ") + e.what(), true);
  }
}

void CompletionPanel::drawOverlay(render::Overlay& overlay) const {
  if (!regionSet_) return;
  const double z = storeyZ() + 0.05;
  const render::Rgba yellow{1.0f, 0.85f, 0.2f, 1.0f};
  const Vec3 c[4] = {{region_.x0, region_.y0, z},
                     {region_.x1, region_.y0, z},
                     {region_.x1, region_.y1, z},
                     {region_.x0, region_.y1, z}};
  for (int i = 0; i < 4; ++i) overlay.line(c[i], c[(i + 1) % 4], yellow);
  for (const growth::Entrance& e : entrances_)
    overlay.arrow(Vec3(e.at[0], e.at[1], z),
                  Vec3(e.at[0] + sideSign(e.facing) * (sideAxis(e.facing) == 0 ? 1.5 : 0),
                       e.at[1] + sideSign(e.facing) * (sideAxis(e.facing) == 1 ? 1.5 : 0), z),
                  {0.3f, 0.9f, 0.4f, 1.0f}, 0.4);
  if (!fitted_) return;
  // The doors the fit was asked to meet: green where the unit opens onto its entrance, red where not.
  for (const growth::EntranceFit& e : fitted_->entranceFits) {
    const growth::PlanRect& r = fittedRegion_;
    const bool alongX = e.side == 0 || e.side == 2;
    const double at = e.side == 0 ? r.y0 : e.side == 1 ? r.x1 : e.side == 2 ? r.y1 : r.x0;
    const Vec3 a = alongX ? Vec3(e.from, at, z + 0.1) : Vec3(at, e.from, z + 0.1);
    const Vec3 b = alongX ? Vec3(e.to, at, z + 0.1) : Vec3(at, e.to, z + 0.1);
    overlay.line(a, b, e.realized ? render::Rgba{0.2f, 0.95f, 0.3f, 1.0f} : render::Rgba{0.95f, 0.2f, 0.2f, 1.0f});
  }
  for (const growth::Unit& u : fitted_->units) {
    const Rgb rgb = materialColor(unitMaterial(u.id), Kind::Unit);
    const render::Rgba col{rgb[0], rgb[1], rgb[2], 1.0f};
    for (const growth::Box& b : u.parts) {
      const double zs[2] = {b.lo[2] + 0.02, b.hi[2]};
      for (double zz : zs) {
        const Vec3 q[4] = {
            {b.lo[0], b.lo[1], zz}, {b.hi[0], b.lo[1], zz}, {b.hi[0], b.hi[1], zz}, {b.lo[0], b.hi[1], zz}};
        for (int i = 0; i < 4; ++i) overlay.line(q[i], q[(i + 1) % 4], col);
      }
      for (double x : {b.lo[0], b.hi[0]})
        for (double y : {b.lo[1], b.hi[1]}) overlay.line({x, y, zs[0]}, {x, y, zs[1]}, col);
    }
  }
}

void CompletionPanel::drawPlan(const CompletionHost& host, float w, float h) {
  (void)host;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const Cell cell{p0.x, p0.y, w, h};
  dl->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(30, 32, 36, 255));
  // The whole site, or the region and its surroundings; kept while a corner is dragged, so the
  // view does not move under the mouse.
  if (!dragging_) {
    mapBounds_ = region_;
    if (zoom_) {
      const double pad = std::max(6.0, 0.6 * std::max(region_.x1 - region_.x0, region_.y1 - region_.y0));
      mapBounds_ = {region_.x0 - pad, region_.y0 - pad, region_.x1 + pad, region_.y1 + pad};
    } else if (model_) {
      const growth::Box b = model_->grown.site.bounds();
      mapBounds_ = {b.lo[0], b.lo[1], b.hi[0], b.hi[1]};
    }
  }
  const CellMap m = fitInCell(mapBounds_, cell, 8.0f);
  dl->PushClipRect(p0, ImVec2(p0.x + w, p0.y + h), true);
  auto rect = [&](double x0, double y0, double x1, double y1, ImU32 fill, ImU32 line) {
    float ax, ay, bx, by;
    m.apply(x0, y1, ax, ay);
    m.apply(x1, y0, bx, by);
    if (fill) dl->AddRectFilled(ImVec2(ax, ay), ImVec2(bx, by), fill);
    if (line) dl->AddRect(ImVec2(ax, ay), ImVec2(bx, by), line);
  };
  if (model_) {
    const growth::Site& site = model_->grown.site;
    std::vector<ImVec2> outline;
    for (const Vec2& p : site.plan) {
      float px, py;
      m.apply(p[0], p[1], px, py);
      outline.emplace_back(px, py);
    }
    if (outline.size() >= 3)
      dl->AddPolyline(outline.data(), int(outline.size()), IM_COL32(150, 150, 160, 255), ImDrawFlags_Closed, 1.0f);
    const double zMid = storeyZ() + 0.5 * site.storeyHeight;
    for (const growth::Unit& u : model_->grown.units)
      for (const growth::Box& b : u.parts)
        if (b.lo[2] < zMid && b.hi[2] > zMid)
          rect(b.lo[0], b.lo[1], b.hi[0], b.hi[1], IM_COL32(200, 196, 185, 200), IM_COL32(90, 90, 90, 255));
    for (const growth::Rect& c : site.cores) rect(c.u0, c.v0, c.u1, c.v1, IM_COL32(120, 120, 125, 255), 0);
    for (const growth::Box& c : site.circulation)
      if (c.lo[2] < zMid && c.hi[2] > zMid) rect(c.lo[0], c.lo[1], c.hi[0], c.hi[1], IM_COL32(80, 90, 110, 255), 0);
  }
  if (fitted_)
    for (const growth::Unit& u : fitted_->units)
      for (const growth::Box& b : u.parts)
        rect(b.lo[0], b.lo[1], b.hi[0], b.hi[1], unitColour(u.id, 0.9f), IM_COL32(20, 20, 20, 255));
  rect(region_.x0, region_.y0, region_.x1, region_.y1, 0, IM_COL32(255, 215, 50, 255));
  for (const growth::Entrance& e : entrances_) {
    float px, py;
    m.apply(e.at[0], e.at[1], px, py);
    dl->AddCircleFilled(ImVec2(px, py), 3.5f, IM_COL32(80, 230, 100, 255));
  }
  dl->PopClipRect();
  // The region's corners are handles: drag one to move that corner (0.5 m steps).
  bool anyActive = false;
  double* xs[4] = {&region_.x0, &region_.x1, &region_.x1, &region_.x0};
  double* ys[4] = {&region_.y0, &region_.y0, &region_.y1, &region_.y1};
  for (int k = 0; k < 4; ++k) {
    float px, py;
    m.apply(*xs[k], *ys[k], px, py);
    ImGui::SetCursorScreenPos(ImVec2(px - 5, py - 5));
    ImGui::PushID(k);
    ImGui::InvisibleButton("corner", ImVec2(10, 10));
    const bool active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
    anyActive |= active;
    if (active && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
      regionChosen_ = true;
      double x, y;
      const ImVec2 mp = ImGui::GetIO().MousePos;
      m.invert(mp.x, mp.y, x, y);
      x = std::round(x * 2) / 2, y = std::round(y * 2) / 2;
      if (xs[k] == &region_.x0)
        region_.x0 = std::min(x, region_.x1 - kMinRegion);
      else
        region_.x1 = std::max(x, region_.x0 + kMinRegion);
      if (ys[k] == &region_.y0)
        region_.y0 = std::min(y, region_.y1 - kMinRegion);
      else
        region_.y1 = std::max(y, region_.y0 + kMinRegion);
    }
    ImGui::PopID();
    dl->AddRectFilled(ImVec2(px - 4, py - 4), ImVec2(px + 4, py + 4),
                      active || hovered ? IM_COL32(255, 255, 255, 255) : IM_COL32(255, 215, 50, 255));
  }
  dragging_ = anyActive;
  ImGui::SetCursorScreenPos(ImVec2(p0.x, p0.y + h + 4));
  ImGui::Dummy(ImVec2(w, 0));
}

void CompletionPanel::drawThumbnails(float w) {
  const int perRow = 5;
  const float gap = 5.0f, cw = std::floor((w - gap * (perRow - 1)) / perRow), ch = cw * 0.55f;
  const float textH = ImGui::GetTextLineHeight();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (int i = 0; i < int(forms_.forms.size()); ++i) {
    const growth::Form& f = forms_.forms[std::size_t(i)];
    if (i % perRow) ImGui::SameLine(0, gap);
    ImGui::PushID(i);
    const ImVec2 p = ImGui::GetCursorScreenPos();
    if (ImGui::InvisibleButton("form", ImVec2(cw, ch + textH + 4))) {
      if (picked_ != i) fitted_.reset();
      picked_ = i;
    }
    const bool breaks = i < int(formFits_.size()) && !formFits_[std::size_t(i)];
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("form %d: %s, %d moves\ntopology %s%s", i + 1, fq(f.complexity).c_str(), f.moves,
                        f.topology.substr(0, 60).c_str(),
                        breaks ? "\nbreaks the growth rules in this region (Fit to region says which)" : "");
    const bool sel = picked_ == i;
    dl->AddRectFilled(p, ImVec2(p.x + cw, p.y + ch), sel ? IM_COL32(55, 60, 75, 255) : IM_COL32(36, 38, 44, 255));
    for (const CellRect& r : thumbnailRects(f.plan, {p.x, p.y, cw, ch}, 5.0f)) {
      dl->AddRectFilled(ImVec2(r.x0, r.y0), ImVec2(r.x1, r.y1), unitColour(r.unit + 1));
      dl->AddRect(ImVec2(r.x0, r.y0), ImVec2(r.x1, r.y1), IM_COL32(15, 15, 15, 255));
    }
    if (sel) dl->AddRect(p, ImVec2(p.x + cw, p.y + ch), IM_COL32(255, 215, 50, 255), 0, 0, 2.0f);
    const growth::Fraction v = f.complexity.value();
    char text[48];
    std::snprintf(text, sizeof text, "F_q %lld/%lld%s", static_cast<long long>(v.num), static_cast<long long>(v.den),
                  breaks ? " (breaks rules)" : "");
    dl->AddText(ImVec2(p.x + 2, p.y + ch + 2), breaks ? IM_COL32(240, 110, 100, 255) : IM_COL32(220, 220, 220, 255),
                text);
    ImGui::PopID();
  }
}

void CompletionPanel::draw(const CompletionHost& host, float x, float y, float w, float h) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Form completion", nullptr, kPaneFlags);
  if (!regionSet_) {
    try {
      defaultRegion(growth::parseSite(spec->site));
    } catch (const std::exception&) {
      region_ = {0, 0, 24, 16};
      regionSet_ = true;
    }
  }
  const bool current = modelCurrent(host);
  if (fromModel_ && !current && !host.busy && !host.wait && host.settled && !(attempted_ && *attempted_ == inputOf(host)))
    takeSeeds(host);  // the entrances follow the model
  updateEntrances();
  ImGui::TextDisabled("Ng, Ch. 7: complete a region of the model (Fig. 8.6)");

  ImGui::PushItemWidth(w * 0.5f);
  double r[4] = {region_.x0, region_.y0, region_.x1, region_.y1};
  if (ImGui::InputScalarN("Region x0 y0 x1 y1", ImGuiDataType_Double, r, 4, nullptr, nullptr, "%.1f")) {
    if (r[2] - r[0] >= kMinRegion && r[3] - r[1] >= kMinRegion && std::isfinite(r[0] + r[1] + r[2] + r[3]))
      region_ = {r[0], r[1], r[2], r[3]}, regionChosen_ = true;
  }
  const int storeys = model_ ? model_->grown.site.storeys : 1;
  ImGui::SetNextItemWidth(w * 0.3f);
  if (ImGui::SliderInt("Storey", &storey_, 0, std::max(0, storeys - 1))) {
    fitted_.reset();
    if (!regionChosen_) gapRegion();
  }
  ImGui::SameLine();
  ImGui::Checkbox("Zoom to region", &zoom_);
  ImGui::PopItemWidth();
  drawPlan(host, w - 16, std::min(140.0f, 0.4f * (w - 16)));

  int mode = fromModel_ ? 0 : 1;
  ImGui::RadioButton("Seeds from the model's entrances", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("by count", &mode, 1);
  if ((mode == 0) != fromModel_) {
    fromModel_ = mode == 0;
    if (fromModel_) takeSeeds(host);
  }
  ImGui::PushItemWidth(110);
  if (fromModel_) {
    if (!current)
      ImGui::TextDisabled("growing the model for its entrances...");
    else
      ImGui::Text("%zu entrances in the region (green)", entrances_.size());
  } else {
    ImGui::SliderInt("Seeds N", &count_, 1, 12);
    explainSymbol("Seeds N");
  }
  ImGui::InputFloat("LO", &lo_, 0.01f, 0.05f, "%.3f");
  explainSymbol("LO");
  ImGui::SameLine();
  ImGui::InputFloat("HI", &hi_, 0.01f, 0.05f, "%.3f");
  explainSymbol("HI");
  lo_ = std::clamp(lo_, 0.0f, 0.49f), hi_ = std::clamp(hi_, 0.0f, 0.49f);
  ImGui::SliderInt("Forms K", &forms_wanted_, 1, 64);
  explainSymbol("Forms K");
  ImGui::SameLine();
  ImGui::InputInt("Seed", &seed_, 1, 10);
  ImGui::PopItemWidth();
  ImGui::BeginDisabled(host.busy);
  if (ImGui::Button("Generate")) generate(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!canFit());
  if (ImGui::Button("Fit to region")) fit(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  ImGui::InputInt("##storeys", &storeys_, 1, 1);
  storeys_ = std::clamp(storeys_, 1, 100);
  ImGui::SameLine();
  ImGui::BeginDisabled(!canExtrude());
  char label[48];
  std::snprintf(label, sizeof label, "Extrude to units (%d storey%s)", storeys_, storeys_ == 1 ? "" : "s");
  if (ImGui::Button(label)) extrude(host);
  ImGui::EndDisabled();
  // A fitted form follows the region as it is typed or dragged.
  if (fitted_ &&
      (fittedRegion_.x0 != region_.x0 || fittedRegion_.y0 != region_.y0 || fittedRegion_.x1 != region_.x1 ||
       fittedRegion_.y1 != region_.y1) &&
      canFit())
    fit(host);
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
  ImGui::Separator();
  ImGui::BeginChild("forms", ImVec2(0, 0), false);
  if (forms_.forms.empty())
    ImGui::TextDisabled("No forms yet: Generate.");
  else
    drawThumbnails(ImGui::GetContentRegionAvail().x);
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace corbel::editor
