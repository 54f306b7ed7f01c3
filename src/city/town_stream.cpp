#include "city/town_stream.h"

#include "city/split.h"
#include "core/error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <istream>
#include <streambuf>

#include <ogr_core.h>

namespace corbel::city {

namespace {

// A file read through a buffer of its own that counts the bytes it has handed on, so that a
// parser's callback can tell where in the file it is.
class CountingBuffer : public std::streambuf {
 public:
  explicit CountingBuffer(const std::string& path) : in_(path, std::ios::binary) {}
  bool ok() const { return static_cast<bool>(in_); }
  // The place in the file of the next byte to be handed on.
  std::uint64_t position() const { return before_ + static_cast<std::uint64_t>(gptr() - eback()); }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    before_ += static_cast<std::uint64_t>(egptr() - eback());
    in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    const std::streamsize n = in_.gcount();
    if (n <= 0) return traits_type::eof();
    setg(buffer_.data(), buffer_.data(), buffer_.data() + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  std::ifstream in_;
  std::vector<char> buffer_ = std::vector<char>(std::size_t{1} << 16);
  std::uint64_t before_ = 0;
};

// Calls `visit` on each entry of the file's "features" array in order, each built and dropped in
// turn, and returns the document without them. An entry that is not an object stays in the
// returned document's "features". With `spans`, each visited entry's bytes in the file (from its
// "{" to its "}") are appended to it.
nlohmann::json forEachFeature(const std::string& path, const std::function<void(nlohmann::json&)>& visit,
                              std::vector<std::pair<std::uint64_t, std::uint64_t>>* spans = nullptr) {
  CountingBuffer buffer(path);
  if (!buffer.ok()) throw InputError(path, "cannot read it");
  std::istream in(&buffer);
  using Event = nlohmann::json::parse_event_t;
  std::string member;       // the root's member being read
  std::uint64_t start = 0;  // of the entry being read
  try {
    // The parser has taken a "{" or "}" itself, and nothing past it, when it calls back with
    // its object_start or object_end (a number's end, the one token read ahead, is never there).
    nlohmann::json root = nlohmann::json::parse(in, [&](int depth, Event event, nlohmann::json& parsed) {
      if (depth > 64) throw InputError(path, "nested deeper than 64 levels");
      if (depth == 1 && event == Event::key) member = parsed.get<std::string>();
      if (depth == 2 && event == Event::object_start && member == "features") start = buffer.position() - 1;
      if (depth == 2 && event == Event::object_end && member == "features") {
        if (spans) spans->emplace_back(start, buffer.position());
        visit(parsed);
        return false;  // dropped
      }
      return true;
    });
    return root;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, std::string("not JSON: ") + e.what());
  }
}

// The document's members but "features", checked as a FeatureCollection's.
nlohmann::json membersOf(nlohmann::json root, const std::string& path) {
  if (!root.is_object()) throw InputError(path, "expected a JSON object (a FeatureCollection)");
  const auto type = root.find("type");
  if (type == root.end() || !type->is_string() || *type != "FeatureCollection")
    throw InputError(path, "type: expected \"FeatureCollection\"");
  const auto features = root.find("features");
  if (features == root.end() || !features->is_array()) throw InputError(path, "features: expected an array");
  if (!features->empty()) throw InputError(path, "features: an entry is not an object (a Feature)");
  root.erase("features");
  return root;
}

// A feature's id as the kernel's reader gives it when it has none of its own: its place among
// the file's footprint features.
void nameByPlace(nlohmann::json& f, std::size_t place) {
  const auto id = f.find("id");
  if (id != f.end() && (id->is_string() || id->is_number())) return;
  const auto p = f.find("properties");
  if (p != f.end() && p->is_object() && p->contains("source_id") && (*p)["source_id"].is_string()) return;
  f["id"] = std::to_string(place);
}

// What the reader says of a building of the part's feature `from` (its notes and problem name
// "features[from]"), said of the feature's place in the source, as a whole read says it.
void renumber(Building& b, std::size_t from, std::size_t to) {
  if (from == to) return;
  const std::string was = "features[" + std::to_string(from) + "]", is = "features[" + std::to_string(to) + "]";
  auto fix = [&](std::string& text) {
    for (std::size_t at = text.find(was); at != std::string::npos; at = text.find(was, at + is.size()))
      text.replace(at, was.size(), is);
  };
  for (std::string& note : b.notes) fix(note);
  fix(b.problem);
}

nlohmann::json collectionOf(const nlohmann::json& members) {
  nlohmann::json c = members;
  c["features"] = nlohmann::json::array();
  return c;
}

}  // namespace

TownStream::TownStream(std::string path, ReadOptions options)
    : path_(std::move(path)), options_(std::move(options)), ogr_(!readsGeoJsonText(path_, options_)) {
  try {
    // Pass 1: the bounds of every position, for the frame, and the credit.
    PositionBounds bounds;
    std::string credit;
    auto pass1 = [&](nlohmann::json& f) {
      if (credit.empty()) credit = creditOf(nlohmann::json::object(), f);
      addPositions(bounds, f);
    };
    SourceLayer layer;
    if (!ogr_) {
      members_ = membersOf(forEachFeature(path_, pass1), path_);
    } else {
      layer = forEachOgrFeature(path_, {options_.layer, options_.where}, pass1);
      // A GeoJSON file's own members say what its coordinates are, as when it is read whole.
      members_ = layer.driver == "GeoJSON" ? membersOf(forEachFeature(path_, [](nlohmann::json&) {}), path_)
                                           : nlohmann::json{{"type", "FeatureCollection"}};
    }
    // The document's own credit first, as a whole read gives it.
    if (const std::string own = creditOf(members_, nullptr); !own.empty()) credit = own;
    attribution_ = credit;
    placement_ =
        ogr_ ? layerPlacement(layer, members_, bounds, options_) : geoJsonPlacement(members_, bounds, options_);
    frame_ = placement_.frame;
    // Pass 2: each feature placed and cleaned alone; of its buildings only their centres and
    // boxes kept, and of a GeoJSON file's features where they lie in it.
    double east = 0;
    std::size_t place = 0, feature = 0;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> spans;
    std::vector<std::int64_t> fids;
    auto pass2 = [&](nlohmann::json& f) {
      const std::uint32_t at = static_cast<std::uint32_t>(feature++);
      const bool line = isLineFeature(f);
      if (!ogr_) {
        if (spans.size() != feature) throw InputError(path_, "a feature's place in the file was not found");
        const auto [from, to] = spans.back();
        if (to - from > UINT32_MAX) throw InputError(path_, "features[" + std::to_string(at) + "]: larger than 4 GB");
        spans_.push_back({from, static_cast<std::uint32_t>(to - from), static_cast<std::uint32_t>(place)});
      } else {
        if (fids.size() != feature) throw InputError(path_, "a feature's id was not found");
        refs_.push_back({fids.back(), static_cast<std::uint32_t>(place)});
      }
      if (!line) nameByPlace(f, place++);
      nlohmann::json one = collectionOf(members_);
      one["features"].push_back(std::move(f));
      Town t = placePart(one, placement_, options_, &east);
      for (Street& s : t.streets) streets_.push_back(std::move(s));
      for (const Building& b : t.buildings) {
        Entry e;
        e.feature = at;
        e.margin = marksMargin(b.properties);
        if (!b.loops.empty() && !b.loops[0].empty()) {
          for (const Vec2& p : b.loops[0]) e.centre += p;
          e.centre /= static_cast<double>(b.loops[0].size());
          for (const auto& loop : b.loops)
            for (const Vec2& p : loop)
              for (int k = 0; k < 2; ++k) {
                e.lo[k] = std::min(e.lo[k], p[k]);
                e.hi[k] = std::max(e.hi[k], p[k]);
              }
        }
        buildings_.push_back(e);
      }
    };
    if (ogr_) {
      const SourceLayer read = forEachOgrFeature(path_, {options_.layer, options_.where}, pass2, &fids);
      // A part fetches its features by id where the layer can, and the ids tell them apart.
      std::sort(fids.begin(), fids.end());
      const bool distinct = std::adjacent_find(fids.begin(), fids.end()) == fids.end();
      if (!read.randomRead || !distinct || (!fids.empty() && fids.front() == OGRNullFID)) refs_.clear();
      refs_.shrink_to_fit();
    } else {
      forEachFeature(path_, pass2, &spans);
    }
    if (placement_.to) frame_.scaleError = transverseMercatorScaleError(east);
    buildings_.shrink_to_fit();  // held to the end: not the doubling's slack too
    spans_.shrink_to_fit();
    streets_.shrink_to_fit();
  } catch (const InputError& e) {
    if (e.where.rfind(path_, 0) == 0) throw;
    throw InputError(e.where.empty() ? path_ : path_ + ": " + e.where, e.reason);
  }
}

void TownStream::forEach(const std::function<void(nlohmann::json&)>& visit) const {
  if (ogr_)
    forEachOgrFeature(path_, {options_.layer, options_.where}, visit);
  else
    forEachFeature(path_, visit);
}

Town TownStream::part(const std::vector<std::vector<std::size_t>>& tiles, double reach, double streetReach,
                      std::vector<std::size_t>& indices) const {
  // Each tile's box around its outlines: a building farther than `reach` from all, or a street
  // farther than `streetReach`, matters to no label.
  struct Box {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  };
  std::vector<Box> boxes;
  std::vector<bool> wanted(buildings_.size(), false);
  for (const auto& tile : tiles) {
    Box& t = boxes.emplace_back();
    for (std::size_t i : tile) {
      wanted[i] = true;
      for (int k = 0; k < 2; ++k) {
        t.lo[k] = std::min(t.lo[k], buildings_[i].lo[k]);
        t.hi[k] = std::max(t.hi[k], buildings_[i].hi[k]);
      }
    }
  }
  auto near = [&](const double* l, const double* h, double r) {
    for (const Box& t : boxes)
      if (l[0] <= t.hi[0] + r && h[0] >= t.lo[0] - r && l[1] <= t.hi[1] + r && h[1] >= t.lo[1] - r) return true;
    return false;
  };
  for (std::size_t i = 0; i < buildings_.size(); ++i)
    if (!wanted[i] && near(buildings_[i].lo, buildings_[i].hi, reach)) wanted[i] = true;
  std::vector<bool> features;
  for (std::size_t i = 0; i < buildings_.size(); ++i)
    if (wanted[i]) {
      if (features.size() <= buildings_[i].feature) features.resize(buildings_[i].feature + 1, false);
      features[buildings_[i].feature] = true;
    }
  // The wanted features read again, in the file's order: a GeoJSON file's each from its own
  // bytes, any other source's by reading it through.
  nlohmann::json collection = collectionOf(members_);
  std::vector<std::size_t> first;    // each read feature's first building
  std::vector<std::size_t> placeOf;  // each read feature's place among the source's footprint features
  std::size_t building = 0;
  auto take = [&](std::size_t at, std::size_t place, nlohmann::json& f) {
    nameByPlace(f, place);
    while (building < buildings_.size() && buildings_[building].feature < at) ++building;
    first.push_back(building);
    placeOf.push_back(place);
    collection["features"].push_back(std::move(f));
  };
  if (!ogr_) {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw InputError(path_, "cannot read it");
    std::string text;
    for (std::size_t at = 0; at < features.size(); ++at) {
      if (!features[at]) continue;
      const Span& s = spans_.at(at);
      text.resize(s.bytes);
      in.seekg(static_cast<std::streamoff>(s.offset));
      in.read(text.data(), static_cast<std::streamsize>(s.bytes));
      nlohmann::json f = nlohmann::json::parse(text, nullptr, false);
      if (!in || !f.is_object() || isLineFeature(f)) throw InputError(path_, "changed while it was read");
      take(at, s.place, f);
    }
  } else if (!refs_.empty()) {
    std::vector<std::int64_t> fids;
    std::vector<std::size_t> ats;
    for (std::size_t at = 0; at < features.size(); ++at)
      if (features[at]) {
        fids.push_back(refs_.at(at).fid);
        ats.push_back(at);
      }
    std::size_t k = 0;
    forEachOgrFeatureById(path_, {options_.layer, options_.where}, fids, [&](nlohmann::json& f) {
      const std::size_t at = ats[k++];
      if (isLineFeature(f)) throw InputError(path_, "changed while it was read");
      take(at, refs_[at].place, f);
    });
  } else {
    std::size_t place = 0, feature = 0;
    forEach([&](nlohmann::json& f) {
      const std::size_t at = feature++;
      const bool line = isLineFeature(f);
      if (!line) ++place;
      if (line || at >= features.size() || !features[at]) return;
      take(at, place - 1, f);
    });
  }
  Town t = placePart(collection, placement_, options_);
  if (!t.streets.empty()) throw InputError(path_, "changed while it was read");
  Town out;
  out.frame = frame_;
  out.attribution = attribution_;
  indices.clear();
  // A read feature's buildings are numbered on from its first.
  std::size_t k = 0;
  for (std::size_t f = 0; f < first.size(); ++f) {
    for (std::size_t g = first[f]; g < buildings_.size() && buildings_[g].feature == buildings_[first[f]].feature;
         ++g) {
      if (k >= t.buildings.size()) throw InputError(path_, "changed while it was read");
      Building& b = t.buildings[k++];
      if (!wanted[g]) continue;
      renumber(b, f, placeOf[f]);
      indices.push_back(g);
      out.buildings.push_back(std::move(b));
    }
  }
  if (k != t.buildings.size()) throw InputError(path_, "changed while it was read");
  for (const Street& s : streets_) {
    double sl[2] = {INFINITY, INFINITY}, sh[2] = {-INFINITY, -INFINITY};
    for (const Vec2& p : s.points)
      for (int d = 0; d < 2; ++d) {
        sl[d] = std::min(sl[d], p[d]);
        sh[d] = std::max(sh[d], p[d]);
      }
    if (near(sl, sh, streetReach)) out.streets.push_back(s);
  }
  return out;
}

}  // namespace corbel::city
