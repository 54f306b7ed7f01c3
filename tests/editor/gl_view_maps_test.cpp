// The editor's growth on GL view maps (render/gl_view_mapper.h: ContextViewMapper, the mapper the
// editor's growth builds and view-map inspector use, editor/view_map_context.h), on OSMesa
// contexts: a growth object's build on GL maps run off the test's thread equals, part for part,
// the same build on the CPU rasterizer (the oracle of the growth kernel's own GL test), and a
// view-map render leaves the caller's GL state as it found it.
#include "core/error.h"
#include "core/live_sync.h"
#include "editor/growth_inspect.h"
#include "growth/kernel.h"
#include "render/gl.h"
#include "render/gl_view_mapper.h"
#include "render/headless_context.h"
#include "render/shader_sources.h"

#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <future>
#include <mutex>
#include <set>
#include <thread>

namespace corbel::editor {
namespace {

// An OSMesa context of its own, made current on whichever thread renders, as the editor's
// hidden window is (editor/view_map_context.cpp); what the thread had current is put back.
class OsMesaLease : public render::GlContextLease {
 public:
  OsMesaLease() {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) throw Error("OSMesa could not create a context for the view maps");
  }
  ~OsMesaLease() override { OSMesaDestroyContext(context_); }
  OsMesaLease(const OsMesaLease&) = delete;
  OsMesaLease& operator=(const OsMesaLease&) = delete;
  void enter() override {
    previous_ = OSMesaGetCurrentContext();
    if (previous_) OSMesaGetColorBuffer(previous_, &width_, &height_, &format_, &previousBuffer_);
    {
      const std::lock_guard<std::mutex> lock(*threadsMutex_);
      threads_->insert(std::this_thread::get_id());
    }
    ASSERT_TRUE(OSMesaMakeCurrent(context_, buffer_, GL_UNSIGNED_BYTE, 4, 4));
  }
  void leave() override {
    if (previous_)
      OSMesaMakeCurrent(previous_, previousBuffer_, GL_UNSIGNED_BYTE, width_, height_);
    else
      OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  }
  // The threads it was entered on (kept by the test when the mapper owns the lease).
  std::shared_ptr<std::set<std::thread::id>> threads_ = std::make_shared<std::set<std::thread::id>>();
  std::shared_ptr<std::mutex> threadsMutex_ = std::make_shared<std::mutex>();

 private:
  OSMesaContext context_ = nullptr;
  unsigned char buffer_[4 * 4 * 4] = {};
  OSMesaContext previous_ = nullptr;
  void* previousBuffer_ = nullptr;
  GLint width_ = 0, height_ = 0, format_ = 0;
};

struct GlMaps {
  std::shared_ptr<render::ContextViewMapper> mapper;
  std::shared_ptr<std::set<std::thread::id>> threads;
  std::shared_ptr<std::mutex> mutex;
  std::set<std::thread::id> threadsSeen() const {
    const std::lock_guard<std::mutex> lock(*mutex);
    return *threads;
  }
};
GlMaps glMaps(double pixel) {
  auto lease = std::make_unique<OsMesaLease>();
  GlMaps out{nullptr, lease->threads_, lease->threadsMutex_};
  out.mapper = std::make_shared<render::ContextViewMapper>(std::move(lease), pixel);
  return out;
}

// The growth kernel's GL test site (tests/growth/gl_view_mapper_test.cpp) as a site file: 40 × 30
// m, two storeys, a core with landings beside it on both storeys and four seeds at them.
GrowthSpec landingSite(int steps) {
  GrowthSpec s;
  s.site =
      R"({"envelope": {"origin": [0, 0], "size": [40, 30]}, "storeys": 2, "storey_height": 3,)"
      R"( "clearance": {"core": 0.5, "circulation": 0}, "cores": [{"at": [18, 13], "size": [4, 4]}],)"
      R"( "circulation": [{"at": [22.5, 14, 0], "size": [3.5, 2, 3]}, {"at": [22.5, 14, 3], "size": [3.5, 2, 3]}],)"
      R"( "seeds": [{"at": [26, 14], "storey": 0, "target_area": 60}, {"at": [23, 16], "storey": 0, "target_area": 45},)"
      R"( {"at": [23, 11], "storey": 1, "target_area": 50}, {"at": [26, 13], "storey": 1, "target_area": 70}]})";
  s.steps = steps;
  return s;
}

// A Document of one growth object, built by a SceneSync whose growth builder grows on `mapper`
// (the editor's registration), through LiveSync: the build runs off this thread.
MeshData builtOn(const GrowthSpec& spec, std::shared_ptr<growth::ViewMapper> mapper,
                 std::vector<std::string>* warnings) {
  SceneSync sync;
  growth::registerKernelWith(sync, [mapper] { return mapper; });
  Document doc;
  const ObjectId id = doc.add("site", spec);
  Scene scene;
  LiveSync live(sync);
  live.settle(doc, 1, scene);
  const auto& st = sync.status().at(id);
  EXPECT_EQ(st.error, "");
  if (warnings) *warnings = st.warnings;
  return objectMesh(scene, id);
}

void expectSameMesh(const MeshData& a, const MeshData& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]) << "point " << i;
  for (std::size_t f = 0; f < a.faces.size(); ++f) EXPECT_EQ(a.faces[f], b.faces[f]) << "face " << f;
}

TEST(EditorGlViewMaps, AGrowthBuildOnGlMapsEqualsTheCpuRasterBuildPartForPart) {
  render::HeadlessContext window;  // the test thread's context, as the editor's window is the UI thread's
  const GlMaps gl = glMaps(0.25);
  const GrowthSpec spec = landingSite(-1);
  std::vector<std::string> glWarnings, cpuWarnings;
  const MeshData onGl = builtOn(spec, gl.mapper, &glWarnings);
  const MeshData onCpu = builtOn(spec, std::make_shared<growth::RasterViewMapper>(0.25), &cpuWarnings);
  const MeshData onExact = builtOn(spec, nullptr, nullptr);
  // The GL maps were rendered, and only off this thread (LiveSync's worker).
  const auto threads = gl.threadsSeen();
  ASSERT_FALSE(threads.empty());
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 0u);
  expectSameMesh(onGl, onCpu);
  EXPECT_EQ(glWarnings, cpuWarnings);  // both say after how many steps every unit stopped
  ASSERT_EQ(growth::stoppedAfter(glWarnings) > 0, true);
  // The builder really grows on the mapper it is given: the exact maps grow another model.
  EXPECT_FALSE(onExact.points == onCpu.points && onExact.faces == onCpu.faces);

  // The inspector's path, off this thread as the panel runs it: the same units, and the four
  // maps cell for cell (id and depth), against the rasterizer's.
  auto inspected = std::async(std::launch::async, [&] { return inspectGrowth(spec, nullptr, gl.mapper.get(), "GL"); });
  const GrowthInspection a = inspected.get();
  growth::RasterViewMapper raster(0.25);
  const GrowthInspection b = inspectGrowth(spec, nullptr, &raster, "raster");
  EXPECT_EQ(a.maps, "GL");
  ASSERT_EQ(a.grown.units.size(), 4u);
  ASSERT_EQ(a.grown.units.size(), b.grown.units.size());
  for (std::size_t i = 0; i < a.grown.units.size(); ++i)
    EXPECT_EQ(a.grown.units[i].parts, b.grown.units[i].parts) << "unit " << a.grown.units[i].id;
  for (growth::ViewDirection d : growth::kViewDirections) {
    const growth::ViewMap &ma = a.views[d], &mb = b.views[d];
    ASSERT_EQ(ma.columns(), mb.columns());
    ASSERT_EQ(ma.rows(), mb.rows());
    int differ = 0;
    for (int j = 0; j < ma.rows(); ++j)
      for (int i = 0; i < ma.columns(); ++i)
        if (ma.id(i, j) != mb.id(i, j) || ma.depth(i, j) != mb.depth(i, j)) ++differ;
    EXPECT_EQ(differ, 0) << viewDirectionName(d);
  }
  EXPECT_EQ(statisticsRows(a.stats), statisticsRows(b.stats));
}

// Boxes for the state test: two units, one behind the other from +x, and a core.
std::vector<growth::ViewBox> fewBoxes() {
  return {{{{2, 2, 0}, {6, 7, 3}}, 1}, {{{9, 4, 0}, {12, 9, 6}}, 2}, {{{14, 1, 0}, {16, 3, 6}}, growth::kObstacleId}};
}
const growth::Box kFrame{{0, 0, 0}, {20, 10, 9}};

void expectSameMaps(const growth::ViewMaps& a, const growth::ViewMaps& b) {
  for (growth::ViewDirection d : growth::kViewDirections) {
    ASSERT_EQ(a[d].columns(), b[d].columns());
    ASSERT_EQ(a[d].rows(), b[d].rows());
    int differ = 0;
    for (int j = 0; j < a[d].rows(); ++j)
      for (int i = 0; i < a[d].columns(); ++i)
        if (a[d].id(i, j) != b[d].id(i, j) || a[d].depth(i, j) != b[d].depth(i, j)) ++differ;
    EXPECT_EQ(differ, 0) << viewDirectionName(d);
  }
}

TEST(EditorGlViewMaps, AViewMapRenderLeavesTheCallersGlStateAsItWas) {
  render::HeadlessContext context;
  // The caller's frame: its own framebuffer cleared to a colour, a viewport inside it, a program,
  // a vertex array and buffer, blending and a small scissor box on, depth test off with
  // GL_LEQUAL, no depth writes, no alpha writes, and odd clear values and pack alignment: much
  // of what the editor's ImGui pass leaves set.
  GLuint fbo = 0, colour = 0, vao = 0, vbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(1, &colour);
  glBindRenderbuffer(GL_RENDERBUFFER, colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 64, 48);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLuint program = render::linkSources("#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n",
                                             "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n",
                                             "test vertex", "test fragment");
  glUseProgram(program);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glViewport(3, 5, 17, 19);
  glEnable(GL_BLEND);
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 1, 2, 2);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(0.5);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);

  growth::ViewMaps maps;
  {
    render::GlViewMapper gl(0.5);
    maps = gl.render(fewBoxes(), kFrame);
  }
  // The maps are right in spite of the scissor box and masks (they are the rasterizer's).
  expectSameMaps(maps, growth::RasterViewMapper(0.5).render(fewBoxes(), kFrame));

  GLint i = 0, v[4] = {};
  GLboolean b[4] = {};
  GLfloat f[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &i);
  EXPECT_EQ(GLuint(i), fbo);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &i);
  EXPECT_EQ(GLuint(i), fbo);
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &i);
  EXPECT_EQ(GLuint(i), colour);
  glGetIntegerv(GL_CURRENT_PROGRAM, &i);
  EXPECT_EQ(GLuint(i), program);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &i);
  EXPECT_EQ(GLuint(i), vao);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &i);
  EXPECT_EQ(GLuint(i), vbo);
  glGetIntegerv(GL_VIEWPORT, v);
  EXPECT_EQ(v[0], 3);
  EXPECT_EQ(v[1], 5);
  EXPECT_EQ(v[2], 17);
  EXPECT_EQ(v[3], 19);
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  glGetIntegerv(GL_SCISSOR_BOX, v);
  EXPECT_EQ(v[2], 2);
  glGetIntegerv(GL_DEPTH_FUNC, &i);
  EXPECT_EQ(i, GL_LEQUAL);
  glGetBooleanv(GL_DEPTH_WRITEMASK, b);
  EXPECT_EQ(b[0], GL_FALSE);
  glGetBooleanv(GL_COLOR_WRITEMASK, b);
  EXPECT_EQ(b[3], GL_FALSE);
  EXPECT_EQ(b[0], GL_TRUE);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, f);
  EXPECT_FLOAT_EQ(f[0], 0.1f);
  EXPECT_FLOAT_EQ(f[3], 0.4f);
  GLdouble depth = 0;
  glGetDoublev(GL_DEPTH_CLEAR_VALUE, &depth);
  EXPECT_DOUBLE_EQ(depth, 0.5);
  glGetIntegerv(GL_PACK_ALIGNMENT, &i);
  EXPECT_EQ(i, 8);
  // Nothing was drawn into the caller's framebuffer: every pixel keeps its clear colour.
  glDisable(GL_SCISSOR_TEST);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<unsigned char> pixels(64 * 48 * 4);
  glReadPixels(0, 0, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  int changed = 0;
  for (std::size_t k = 0; k < pixels.size(); k += 4)
    if (pixels[k] != 51 || pixels[k + 1] != 102 || pixels[k + 2] != 153 || pixels[k + 3] != 255) ++changed;
  EXPECT_EQ(changed, 0);
  glDeleteProgram(program);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  glDeleteRenderbuffers(1, &colour);
  glDeleteFramebuffers(1, &fbo);
}

TEST(EditorGlViewMaps, TheContextMapperGivesBackTheCallersContextSharesItsOwnAcrossThreadsAndChangesPixels) {
  render::HeadlessContext context;
  const OSMesaContext mine = OSMesaGetCurrentContext();
  ASSERT_NE(mine, nullptr);
  glViewport(1, 2, 3, 4);
  const GlMaps gl = glMaps(0.5);
  const growth::ViewMaps expected = growth::RasterViewMapper(0.5).render(fewBoxes(), kFrame);
  // On this thread: the mapper's context is current only while it renders.
  expectSameMaps(gl.mapper->render(fewBoxes(), kFrame), expected);
  EXPECT_EQ(OSMesaGetCurrentContext(), mine);
  GLint v[4] = {};
  glGetIntegerv(GL_VIEWPORT, v);
  EXPECT_EQ(v[2], 3);
  // From three threads at once: one render at a time, each right, each thread left with none.
  std::vector<std::future<std::pair<growth::ViewMaps, bool>>> runs;
  for (int t = 0; t < 3; ++t)
    runs.push_back(std::async(std::launch::async, [&] {
      auto maps = gl.mapper->render(fewBoxes(), kFrame);
      return std::make_pair(std::move(maps), OSMesaGetCurrentContext() == nullptr);
    }));
  for (auto& r : runs) {
    auto [maps, released] = r.get();
    expectSameMaps(maps, expected);
    EXPECT_TRUE(released);
  }
  // (Finished threads' ids may be reused, so at least this one and one more.)
  const auto threads = gl.threadsSeen();
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 1u);
  EXPECT_GE(threads.size(), 2u);
  // The Grow tab's pixel choice: the next render is on the new pixels (the rasterizer's maps at
  // 0.25 m); a size that is not positive is refused and changes nothing.
  gl.mapper->setPixelSize(0.25);
  EXPECT_EQ(gl.mapper->pixelSize(), 0.25);
  const growth::ViewMaps finer = gl.mapper->render(fewBoxes(), kFrame);
  EXPECT_EQ(finer[growth::ViewDirection::PosX].columns(), 40);  // 10 m of y in 0.25 m pixels
  expectSameMaps(finer, growth::RasterViewMapper(0.25).render(fewBoxes(), kFrame));
  EXPECT_THROW(gl.mapper->setPixelSize(0), Error);
  EXPECT_EQ(gl.mapper->pixelSize(), 0.25);
}

}  // namespace
}  // namespace corbel::editor
