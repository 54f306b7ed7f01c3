// corbel-cli grow on the Alpha-like example: exit codes, messages, and statistics that agree
// with their own definitions (Table 8.1) and with the exported model.
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace {

struct CliRun {
  int code = -1;
  std::string out;
};

CliRun cli(const std::string& args) {
  CliRun r;
  const std::string cmd = std::string(CORBEL_CLI) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

const std::string kAlpha = std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json";

TEST(GrowCli, AlphaGrowsToCompletionWithConsistentStatistics) {
  const std::string obj = testing::TempDir() + "growth-alpha.obj";
  const CliRun r = cli("grow " + kAlpha + " --seed 3 --stats --out " + obj);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["finished"].get<bool>());
  EXPECT_TRUE(j["constraints_hold"].get<bool>());
  const auto& s = j["statistics"];
  EXPECT_EQ(s["units"].get<int>(), 72);  // one unit per seed in the file
  EXPECT_DOUBLE_EQ(s["site_area"].get<double>(), 90.0 * 50.0);
  const int a = s["type_a"].get<int>(), b = s["type_b"].get<int>(), c = s["type_c"].get<int>();
  const int none = s["unclassified"].get<int>();
  EXPECT_EQ(a + b + c + none, 72);
  EXPECT_EQ(s["occupants"].get<int>(), 5 * a + 3 * b + c);
  EXPECT_DOUBLE_EQ(s["occupancy_ratio"].get<double>(), s["occupants"].get<int>() / (4500.0 * 5));
  EXPECT_LE(s["two_views"].get<int>() + s["three_views"].get<int>() + s["four_views"].get<int>(), 72);
  EXPECT_GT(s["average_floor_area"].get<double>(), 30.0);
  // The OBJ names every unit, core and landing.
  std::ifstream in(obj);
  std::string line;
  int units = 0, others = 0;
  while (std::getline(in, line))
    if (line.rfind("o unit_", 0) == 0)  // names as OBJ tokens (docs/export.md)
      ++units;
    else if (line.rfind("o ", 0) == 0)
      ++others;
  EXPECT_EQ(units, 72);
  EXPECT_EQ(others, 4 + 40);
}

TEST(GrowCli, SameSeedSameModel) {
  const CliRun a = cli("grow " + kAlpha + " --seed 11 --stats");
  const CliRun b = cli("grow " + kAlpha + " --seed 11 --stats");
  ASSERT_EQ(a.code, 0);
  auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  ja.erase("grow_ms");
  jb.erase("grow_ms");
  EXPECT_EQ(ja, jb);
}

TEST(GrowCli, BadInputAndBadCommandLines) {
  const std::string bad = testing::TempDir() + "growth-bad.json";
  std::ofstream(bad) << R"({"envelope": {"size": [20, 20]}, "storeys": 2,
    "seeds": [{"at": [30, 2], "target_area": 40}]})";
  CliRun r = cli("grow " + bad);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("seeds[0].at"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("outside the site envelope"), std::string::npos) << r.out;
  r = cli("grow " + kAlpha + " --seed x");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--seed"), std::string::npos);
  r = cli("grow " + kAlpha + " --out model.xyz");
  EXPECT_EQ(r.code, 2);
  r = cli("grow");
  EXPECT_EQ(r.code, 2);
}

}  // namespace

namespace {

// GL view maps through OSMesa and the CPU rasterizer sample the same pixel grid the same
// way, so the whole Alpha run (thousands of moves chosen by view gains) comes out the same.
TEST(GrowCli, GlViewMapsGrowTheSameModelAsTheCpuRasterizer) {
  const std::string glObj = testing::TempDir() + "growth-gl.obj", cpuObj = testing::TempDir() + "growth-cpu.obj";
  const CliRun gl = cli("grow " + kAlpha + " --view-maps gl --pixel 0.25 --stats --out " + glObj);
  const CliRun cpu = cli("grow " + kAlpha + " --view-maps raster --pixel 0.25 --stats --out " + cpuObj);
  ASSERT_EQ(gl.code, 0) << gl.out;
  ASSERT_EQ(cpu.code, 0) << cpu.out;
  auto a = nlohmann::json::parse(gl.out), b = nlohmann::json::parse(cpu.out);
  EXPECT_EQ(a["statistics"], b["statistics"]);
  EXPECT_EQ(a["moves"], b["moves"]);
  // The same vertices and faces (the files differ only in the name of their .mtl).
  auto geometry = [](const std::string& path) {
    std::ifstream in(path);
    std::string line, text;
    while (std::getline(in, line))
      if (line.rfind("mtllib", 0) != 0) text += line + "\n";
    return text;
  };
  const std::string ta = geometry(glObj), tb = geometry(cpuObj);
  EXPECT_GT(ta.size(), 1000u);
  EXPECT_TRUE(ta == tb);
  EXPECT_EQ(cli("grow " + kAlpha + " --view-maps paint").code, 2);
}

}  // namespace

// corbel-cli complete (Ch. 7): every form reported lies in the range and its units tile
// what the sizing left them; bad arguments are refused with the flag named.
TEST(CompleteCli, FormsInRangeAndClearErrors) {
  const std::string obj = testing::TempDir() + "complete.obj";
  const CliRun r = cli("complete --seeds 4 --complexity 0.30:0.36 --count 3 --region 0,0,20,12 --out " + obj);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["found"].get<int>(), 3);
  for (const auto& f : j["forms"]) {
    EXPECT_GE(f["value"].get<double>(), 0.30);
    EXPECT_LE(f["value"].get<double>(), 0.36);
    EXPECT_DOUBLE_EQ(f["value"].get<double>(), f["incidences"].get<double>() / f["faces"].get<double>());
    EXPECT_EQ(f["units"].size(), 4u);
    EXPECT_LE(f["area_error_after"].get<double>(), f["area_error_before"].get<double>());
    double area = 0;
    for (const auto& u : f["units"]) area += u["area"].get<double>();
    EXPECT_LT(area, 20.0 * 12.0 + 1e-9);  // the units fit in the region (the sea takes the rest)
  }
  std::ifstream in(obj);
  std::string line;
  int units = 0;
  while (std::getline(in, line)) units += line.rfind("o form_", 0) == 0 && line.find("_unit_") != std::string::npos;
  EXPECT_EQ(units, 3 * 4);

  for (const auto& [args, flag] :
       std::vector<std::pair<std::string, std::string>>{{"--complexity 0.2:0.3", "--seeds"},
                                                        {"--seeds 13 --complexity 0.2:0.3", "--seeds"},
                                                        {"--seeds 3 --complexity 0.3:0.2", "--complexity"},
                                                        {"--seeds 3 --complexity 0.2:0.5", "--complexity"},
                                                        {"--seeds 3 --complexity abc", "--complexity"},
                                                        {"--seeds 3 --complexity 0.2:0.3 --count 0", "--count"},
                                                        {"--seeds 3 --complexity 0.2:0.3 --region 0,0,10", "--region"},
                                                        {"--seeds 3 --complexity 0.2:0.3 --region 0,0,1,1", "--region"},
                                                        {"--seeds 3 --complexity 0.2:0.3 --wat", "--wat"}}) {
    const CliRun bad = cli("complete " + args);
    EXPECT_EQ(bad.code, 2) << args;
    EXPECT_NE(bad.out.find(flag), std::string::npos) << args << ": " << bad.out;
  }
}

namespace {

// Vertices per object of an OBJ file, in corbel's frame (Z up; the file says which way it is
// up). "o NAME" starts an object's faces; each face's corners are indices into the file's
// vertices, so an object's vertices are those its faces use.
std::map<std::string, std::vector<std::array<double, 3>>> objVertices(const std::string& path) {
  std::map<std::string, std::vector<std::array<double, 3>>> out;
  std::ifstream in(path);
  std::string line, current;
  std::vector<std::array<double, 3>> all;
  bool yUp = false;
  while (std::getline(in, line)) {
    if (line.rfind("# corbel export:", 0) == 0) yUp = line.find("Y up") != std::string::npos;
    if (line.rfind("o ", 0) == 0) current = line.substr(2);
    if (line.rfind("v ", 0) == 0) {
      std::array<double, 3> v{};
      std::sscanf(line.c_str(), "v %lf %lf %lf", &v[0], &v[1], &v[2]);
      all.push_back(yUp ? std::array<double, 3>{v[0], -v[2], v[1]} : v);
    }
    if (line.rfind("f ", 0) == 0) {
      std::istringstream corners(line.substr(2));
      for (std::size_t i; corners >> i;) out[current].push_back(all.at(i - 1));
    }
  }
  return out;
}

}  // namespace

// corbel-cli complete --from: the Alpha example grown as the editor grows it, its most enclosed gap
// on storey 1, one seed per entrance opening onto the gap. Every entrance lies on the region's
// boundary; each form has one unit per entrance; every door called met is covered, in the
// exported model, by the unit's vertices on that side of the region (an independent reading of
// the geometry); the grown model is exported with the form.
TEST(CompleteCli, FromAGrownModelMeetsTheDoorsOfItsEntrances) {
  const std::string project = std::string(CORBEL_SOURCE_DIR) + "/assets/examples/housing-alpha.corbel";
  const std::string obj = testing::TempDir() + "complete-alpha.obj";
  const CliRun r = cli("complete --from " + project + " --storey 0 --complexity 0.2:0.45 --count 8 --out " + obj);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const auto& region = j["region"];
  const double x0 = region[0], y0 = region[1], x1 = region[2], y1 = region[3];
  const std::size_t seeds = j["entrances"].size();
  ASSERT_GE(seeds, 2u);
  EXPECT_EQ(j["seeds"].get<std::size_t>(), seeds);
  for (const auto& e : j["entrances"]) {
    const double x = e[0], y = e[1];
    const bool onX = (std::abs(x - x0) < 1e-6 || std::abs(x - x1) < 1e-6) && y >= y0 && y <= y1;
    const bool onY = (std::abs(y - y0) < 1e-6 || std::abs(y - y1) < 1e-6) && x >= x0 && x <= x1;
    EXPECT_TRUE(onX || onY) << x << ", " << y;
  }
  const auto objects = objVertices(obj);
  const int best = j["best"];
  int met = 0, forms = 0;
  for (const auto& f : j["forms"]) {
    ++forms;
    EXPECT_EQ(f["units"].size(), seeds);
    EXPECT_EQ(f["doors"].size(), seeds);
    int count = 0;
    for (const auto& d : f["doors"]) {
      count += d["realized"].get<bool>();
      if (!d["realized"].get<bool>()) {
        EXPECT_FALSE(d["why"].get<std::string>().empty());
      }
    }
    EXPECT_EQ(f["doors_met"].get<int>(), count);
    if (forms != best) continue;
    met = count;
    for (const auto& d : f["doors"]) {
      if (!d["realized"].get<bool>()) continue;
      const int side = d["side"];
      const double from = d["door"][0], to = d["door"][1];
      const double at = side == 0 ? y0 : side == 1 ? x1 : side == 2 ? y1 : x0;
      const auto it = objects.find("form_" + std::to_string(best) + "_unit_" + std::to_string(d["unit"].get<int>()));
      ASSERT_NE(it, objects.end());
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& v : it->second) {
        const double across = side == 0 || side == 2 ? v[1] : v[0], along = side == 0 || side == 2 ? v[0] : v[1];
        if (std::abs(across - at) < 1e-6) lo = std::min(lo, along), hi = std::max(hi, along);
      }
      EXPECT_LE(lo, from + 1e-6);
      EXPECT_GE(hi, to - 1e-6);
    }
  }
  EXPECT_GE(met, 1);
  EXPECT_TRUE(j["forms"][best - 1]["fits_growth_rules"].get<bool>());
  int grown = 0, formUnits = 0;
  for (const auto& [name, v] : objects) {
    grown += name.rfind("unit_", 0) == 0;
    formUnits += name.rfind("form_", 0) == 0;
  }
  EXPECT_GT(grown, 10);
  EXPECT_EQ(formUnits, int(seeds));
}

// The region the completion finds on storey 1 has no grown unit under it: no form placed there
// is supported, and none is placed.
TEST(CompleteCli, FormsThatBreakTheGrowthRulesAreRefused) {
  const std::string project = std::string(CORBEL_SOURCE_DIR) + "/assets/examples/housing-alpha.corbel";
  const CliRun ground = cli("complete --from " + project + " --storey 0 --complexity 0.2:0.45 --count 8");
  const CliRun above = cli("complete --from " + project + " --storey 1 --complexity 0.2:0.45 --count 8");
  ASSERT_EQ(ground.code, 0) << ground.out;
  ASSERT_EQ(above.code, 1) << above.out;
  EXPECT_NE(above.out.find("forms obeys the growth rules"), std::string::npos) << above.out;
  const auto a = nlohmann::json::parse(above.out.substr(0, above.out.find('\n')));
  EXPECT_FALSE(a.contains("best"));
  for (const auto& f : a["forms"]) {
    EXPECT_FALSE(f["fits_growth_rules"].get<bool>());
    bool unsupported = false;
    for (const auto& v : f["violations"])
      unsupported = unsupported || v.get<std::string>().find("reaches beyond its supports") != std::string::npos;
    EXPECT_TRUE(unsupported) << f["violations"];
  }
}

TEST(CompleteCli, EntrancesAndModelsAreCheckedBeforeAnythingRuns) {
  const std::string project = std::string(CORBEL_SOURCE_DIR) + "/assets/examples/housing-alpha.corbel";
  const std::string house = std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel";
  for (const auto& [args, code, says] : std::vector<std::tuple<std::string, int, std::string>>{
           {"--from " + project + " --seeds 3 --complexity 0.2:0.3", 2, "--seeds"},
           {"--seeds 3 --object Alpha --complexity 0.2:0.3", 2, "--object"},
           {"--seeds 3 --storey 1 --complexity 0.2:0.3", 2, "--storey"},
           {"--seeds 2 --entrance 0,1 --entrance 1,0 --entrance 2,0 --complexity 0.2:0.3", 2, "3 entrances for 2"},
           {"--seeds 2 --entrance '0;1' --complexity 0.2:0.3", 2, "--entrance"},
           {"--from " + project + " --storey 99 --complexity 0.2:0.3", 2, "--storey"},
           {"--from " + house + " --complexity 0.2:0.3", 1, "no growth object"},
           {"--from " + project + " --object Nope --complexity 0.2:0.3", 1, "Nope"},
           {"--from /nonexistent.corbel --complexity 0.2:0.3", 1, "nonexistent"}}) {
    const CliRun bad = cli("complete " + args);
    EXPECT_EQ(bad.code, code) << args << ": " << bad.out;
    EXPECT_NE(bad.out.find(says), std::string::npos) << args << ": " << bad.out;
  }
  // Doors given by hand on the region's sides are reported per form.
  const CliRun r =
      cli("complete --seeds 3 --complexity 0.25:0.40 --count 2 --region 0,0,20,12 --entrance 0,6 "
          "--entrance 20,6");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["entrances"].size(), 2u);
  for (const auto& f : j["forms"]) EXPECT_EQ(f["doors"].size(), 2u);
}

namespace {

// The numbers in a table cell, in order ("22 / 27 / 22 (1 under 30 m²)" → 22, 27, 22, 1, 30).
std::vector<double> numbersIn(const std::string& cell) {
  std::vector<double> out;
  std::size_t i = 0;
  while (i < cell.size()) {
    if (std::isdigit(static_cast<unsigned char>(cell[i]))) {
      std::size_t used = 0;
      std::string digits;
      while (i + used < cell.size() && (std::isdigit(static_cast<unsigned char>(cell[i + used])) ||
                                        cell[i + used] == '.' || cell[i + used] == ','))
        if (cell[i + used] != ',') digits += cell[i + used++];
        else ++used;
      out.push_back(std::stod(digits));
      i += used;
    } else {
      ++i;
    }
  }
  return out;
}

// docs/growth.md's Table 8.1 for our sites: row label → the cells of one column.
std::map<std::string, std::string> docsColumn(const std::string& header) {
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/docs/growth.md");
  std::string line;
  int column = -1;
  std::map<std::string, std::string> out;
  auto cells = [](const std::string& row) {
    std::vector<std::string> c;
    std::stringstream s(row);
    std::string cell;
    while (std::getline(s, cell, '|')) {
      const auto a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      c.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
    }
    return c;
  };
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) != 0) {
      if (column >= 0) break;  // the table ended
      continue;
    }
    const std::vector<std::string> c = cells(line);
    if (column < 0) {
      for (std::size_t k = 0; k < c.size(); ++k)
        if (c[k] == header) column = int(k);
      continue;
    }
    if (int(c.size()) > column) out[c[1]] = c[std::size_t(column)];
  }
  return out;
}

}  // namespace

// The Table 8.1 figures docs/growth.md gives for the shipped Alpha-like and Beta-like sites
// (scripts/growth-table81: each row's mean and range over seeds 1–5) are what
// `corbel-cli grow --stats` computes for them (the statistics themselves are held to a recount
// from the boxes in shipped_statistics_test.cpp; this keeps the published table true).
TEST(GrowCli, TheDocsTable81IsWhatTheShippedSitesGrowInto) {
  for (const auto& [file, header] : {std::pair{"growth-alpha.json", "Alpha-like, seeds 1–5"},
                                     std::pair{"growth-beta.json", "Beta-like, seeds 1–5"}}) {
    SCOPED_TRACE(file);
    const auto table = docsColumn(header);
    ASSERT_GE(table.size(), 10u) << "no column \"" << header << "\" in docs/growth.md";
    std::vector<nlohmann::json> runs;
    for (int seed = 1; seed <= 5; ++seed) {
      const CliRun r = cli("grow " + std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + file + " --seed " +
                           std::to_string(seed) + " --stats");
      ASSERT_EQ(r.code, 0) << r.out;
      nlohmann::json j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
      j["statistics"]["reached"] = j["reached"];
      j["statistics"]["stuck"] = j["stuck"];
      runs.push_back(j["statistics"]);
    }
    // A cell holds "mean (least–most)" per figure; `k` picks the figure, `printed` its step.
    auto check = [&](const std::string& row, std::size_t k, const std::string& key, double printed) {
      const std::vector<double> n = numbersIn(table.at(row));
      ASSERT_GE(n.size(), 3 * k + 3) << row;
      double sum = 0, lo = INFINITY, hi = -INFINITY;
      for (const auto& s : runs) {
        const double v = s[key].get<double>();
        sum += v, lo = std::min(lo, v), hi = std::max(hi, v);
      }
      EXPECT_NEAR(n[3 * k], sum / runs.size(), printed / 2 + 1e-12) << row << " mean";
      EXPECT_NEAR(n[3 * k + 1], lo, printed / 2 + 1e-12) << row << " least";
      EXPECT_NEAR(n[3 * k + 2], hi, printed / 2 + 1e-12) << row << " most";
    };
    EXPECT_EQ(numbersIn(table.at("units")).at(0), runs[0]["units"].get<double>());
    auto units = [&](std::size_t k, const std::string& key) {  // "132; reached m (a–b), stuck m (a–b)"
      const std::vector<double> n = numbersIn(table.at("units"));
      ASSERT_GE(n.size(), 7u);
      double sum = 0, lo = INFINITY, hi = -INFINITY;
      for (const auto& s : runs) {
        const double v = s[key].get<double>();
        sum += v, lo = std::min(lo, v), hi = std::max(hi, v);
      }
      EXPECT_NEAR(n[1 + 3 * k], sum / runs.size(), 0.05);
      EXPECT_EQ(n[2 + 3 * k], lo);
      EXPECT_EQ(n[3 + 3 * k], hi);
    };
    units(0, "reached");
    units(1, "stuck");
    check("occupants", 0, "occupants", 0.1);
    check("occupancy ratio", 0, "occupancy_ratio", 1e-4);
    check("type A / B / C", 0, "type_a", 0.1);
    check("type A / B / C", 1, "type_b", 0.1);
    check("type A / B / C", 2, "type_c", 0.1);
    check("average view", 0, "average_view", 0.1);
    check("two / three views", 0, "two_views", 0.1);
    check("two / three views", 1, "three_views", 0.1);
    check("average floor area", 0, "average_floor_area", 0.1);
    check("double volume", 0, "double_volume", 0.1);
    check("outdoor space", 0, "outdoor_space", 0.1);
  }
}

namespace {

const std::string kExamples = std::string(CORBEL_SOURCE_DIR) + "/assets/examples/";

nlohmann::json lastJson(const CliRun& r) { return nlohmann::json::parse(r.out.substr(r.out.find('{'))); }

TEST(GrowCli, AProjectGrowsItsGrowthObjectAsTheSiteFileGrows) {
  // housing-alpha.corbel holds growth-alpha.json's site with seed 1, grown to the end.
  const CliRun p = cli("grow " + kExamples + "housing-alpha.corbel --stats");
  const CliRun s = cli("grow " + kAlpha + " --seed 1 --stats");
  ASSERT_EQ(p.code, 0) << p.out;
  ASSERT_EQ(s.code, 0) << s.out;
  const auto jp = lastJson(p), js = lastJson(s);
  EXPECT_EQ(jp["object"], "Alpha");
  EXPECT_EQ(jp["seed"], 1);
  EXPECT_TRUE(jp["finished"].get<bool>());
  for (const char* k : {"steps", "moves", "reached", "stuck", "statistics"}) EXPECT_EQ(jp[k], js[k]) << k;
  // --seed and --steps override the object's.
  const auto p3 = lastJson(cli("grow " + kExamples + "housing-alpha.corbel --seed 3 --steps 4 --stats"));
  const auto s3 = lastJson(cli("grow " + kAlpha + " --seed 3 --steps 4 --stats"));
  EXPECT_EQ(p3["steps"], 4);
  EXPECT_EQ(p3["statistics"], s3["statistics"]);
  EXPECT_EQ(p3["moves"], s3["moves"]);
}

TEST(GrowCli, ABadProjectOrObjectIsNamed) {
  CliRun r = cli("grow " + kExamples + "house.corbel");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("house.corbel: no growth object to grow"), std::string::npos) << r.out;
  r = cli("grow " + kExamples + "housing-alpha.corbel --object Beta");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("no growth object named \"Beta\""), std::string::npos) << r.out;
  r = cli("grow " + kAlpha + " --object Alpha");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--object needs a project"), std::string::npos) << r.out;
  r = cli("grow " + testing::TempDir() + "missing.corbel");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("no such file"), std::string::npos) << r.out;
  // A project whose site is bad: the field by its path in the project.
  std::ifstream in(kExamples + "housing-alpha.corbel");
  nlohmann::json j = nlohmann::json::parse(in);
  j["objects"][0]["growth"]["site"]["storeys"] = 0;
  const std::string bad = testing::TempDir() + "bad-site.corbel";
  std::ofstream(bad) << j.dump();
  r = cli("grow " + bad);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("objects[0].growth.site.storeys: "), std::string::npos) << r.out;
}

}  // namespace

namespace {

// The materials of the meshes under the node named `name`, as assimp reads the file.
std::set<std::string> nodeMaterials(const aiScene* scene, const aiNode* n, const std::string& name) {
  std::set<std::string> out;
  if (name == n->mName.C_Str())
    for (unsigned i = 0; i < n->mNumMeshes; ++i) {
      aiString m;
      scene->mMaterials[scene->mMeshes[n->mMeshes[i]]->mMaterialIndex]->Get(AI_MATKEY_NAME, m);
      out.insert(m.C_Str());
    }
  for (unsigned i = 0; i < n->mNumChildren; ++i) out.merge(nodeMaterials(scene, n->mChildren[i], name));
  return out;
}

TEST(GrowCli, AFinishedBlockExportsToGlbWithRoofsAndFeaturesInTheirOwnMaterials) {
  const std::string glb = testing::TempDir() + "growth-finished.glb";
  const CliRun r = cli("grow " + kExamples + "growth-finished.json --out " + glb);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;  // every region roofed
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(glb, aiProcess_Triangulate);
  ASSERT_TRUE(scene && scene->mRootNode) << importer.GetErrorString();
  // The site's gable roofs: tiles, and gable ends in plaster; doors and windows: their frames,
  // leaves, panes and sills (extrude/features.h).
  EXPECT_EQ(nodeMaterials(scene, scene->mRootNode, "roofs"), (std::set<std::string>{"roof_tile", "plaster"}));
  EXPECT_EQ(nodeMaterials(scene, scene->mRootNode, "doors and windows"),
            (std::set<std::string>{"stone", "timber", "glass"}));
  EXPECT_EQ(nodeMaterials(scene, scene->mRootNode, "unit 1"), (std::set<std::string>{"unit"}));
}

}  // namespace

namespace {

// complete --from shows the model sliced at the storey (Fig. 8.3): cut tops, no roofs over them.
TEST(GrowCli, ASectionOfAFinishedModelHasNoRoofsOrOpenings) {
  const std::string obj = testing::TempDir() + "finished-section.obj";
  const CliRun r = cli("complete --from " + kExamples + "housing-finished.corbel --complexity 0.2:0.45 --count 2 --out " + obj);
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(obj);
  std::string line;
  int units = 0, finishes = 0;
  while (std::getline(in, line)) {
    units += line.rfind("o unit_", 0) == 0;
    finishes += line == "o roofs" || line == "o doors_and_windows";
  }
  EXPECT_GT(units, 0);
  EXPECT_EQ(finishes, 0);
}

}  // namespace
