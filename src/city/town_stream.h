#pragma once
// A footprint source read in parts (corbel-cli city with --tiles or --tileset,
// docs/city.md "Memory"): one pass finds the frame, a second keeps of each building only what a
// tiling needs (its centre, box and margin mark), and each part is read again from the file
// with its neighbours, so that memory grows with a part, not with the town: a GeoJSON file's
// features each from their own bytes (found by the second pass), so that a part costs its own
// features' parsing, not the file's; any other source's by its feature ids where its layer reads
// by id (Shapefile, GeoPackage, FlatGeobuf), else by reading the source through. A part's buildings
// are the ones a whole read gives, cleaned and placed alike; read with the buildings and streets
// within the labels' reach of them, they are labelled alike too.
#include "city/import.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace corbel::city {

class TownStream {
 public:
  // Reads the source twice, holding one feature at a time: a GeoJSON file by itself, any other
  // source (or a GeoJSON file with options.layer or options.where) through GDAL/OGR
  // (city/ogr_source.h), as readTownFile reads them. Throws InputError naming the path as
  // readTownFile does (not JSON, not a FeatureCollection, no CRS, no such layer, a bad
  // where-clause); a feature of a GeoJSON file that is not a JSON object is refused here (a whole
  // read reports it as that building's problem).
  TownStream(std::string path, ReadOptions options);

  const Frame& frame() const { return frame_; }
  const std::string& attribution() const { return attribution_; }
  const std::vector<Street>& streets() const { return streets_; }
  std::size_t size() const { return buildings_.size(); }  // buildings, numbered as readTownFile's
  // The mean of the corners of the building's cleaned outer ring; (0, 0) without an outline.
  Vec2 centre(std::size_t i) const { return buildings_[i].centre; }
  // Marked as a margin building of a city-split tile (kMarginProperty): labelled, not built.
  bool margin(std::size_t i) const { return buildings_[i].margin; }

  // The buildings of `tiles` (each a tile's buildings) with every other building within `reach`
  // m and every street within `streetReach` m of the box around a tile's outlines, read again
  // from the file: a town whose building k is building indices[k] of the source (ascending).
  Town part(const std::vector<std::vector<std::size_t>>& tiles, double reach, double streetReach,
            std::vector<std::size_t>& indices) const;

 private:
  struct Entry {
    Vec2 centre{0, 0};
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};  // of the outline
    std::uint32_t feature = 0;                                            // the file's feature it came from
    bool margin = false;
  };
  // A GeoJSON file's feature: where its bytes lie in the file, and its place among the file's
  // footprint features (its name when it has no id of its own).
  struct Span {
    std::uint64_t offset = 0;
    std::uint32_t bytes = 0;
    std::uint32_t place = 0;
  };
  // An OGR source's feature: its id (GDAL's FID, by which a part fetches it) and its place among
  // the source's footprint features.
  struct OgrRef {
    std::int64_t fid = 0;
    std::uint32_t place = 0;
  };
  // Calls `visit` on each of the source's features in order, one at a time.
  void forEach(const std::function<void(nlohmann::json&)>& visit) const;

  std::string path_;
  ReadOptions options_;
  bool ogr_ = false;        // read through GDAL/OGR
  nlohmann::json members_;  // the document's members but "features"
  Placement placement_;
  Frame frame_;
  std::string attribution_;
  std::vector<Entry> buildings_;
  std::vector<Span> spans_;  // a GeoJSON file's features, in order (read by itself, not through OGR)
  // An OGR source's features, in order, when its layer reads a feature by its id and the ids are
  // distinct; empty otherwise (a part then reads the source through).
  std::vector<OgrRef> refs_;
  std::vector<Street> streets_;
};

}  // namespace corbel::city
