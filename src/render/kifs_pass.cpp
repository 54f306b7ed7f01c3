#include "render/kifs_pass.h"

#include "core/error.h"
#include "kifs/facings.h"
#include "kifs/follow.h"
#include "kifs/kernel.h"
#include "kifs/trace.h"
#include "render/gl.h"
#include "render/shader_sources.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace corbel::render {

namespace {

// Writes uniforms by name and remembers the names; a name the program lacks is an error.
struct UniformWriter {
  GLuint program;
  std::vector<std::string> names;
  GLint at(const char* name) {
    const GLint loc = glGetUniformLocation(program, name);
    if (loc < 0) throw Error(std::string("kifs.frag.glsl has no active uniform ") + name);
    names.push_back(name);
    return loc;
  }
  // A uniform that only some variants use (kifsVariant): written when `needed`, which the
  // program must then have; otherwise written only if the program kept it.
  bool optional(const char* name, bool needed) { return needed || glGetUniformLocation(program, name) >= 0; }
  void i(const char* n, int v) { glUniform1i(at(n), v); }
  void f(const char* n, double v) { glUniform1f(at(n), float(v)); }
  void v2(const char* n, double x, double y) { glUniform2f(at(n), float(x), float(y)); }
  void v3(const char* n, const glm::dvec3& v) { glUniform3f(at(n), float(v.x), float(v.y), float(v.z)); }
  void i3(const char* n, const glm::ivec3& v) { glUniform3i(at(n), v.x, v.y, v.z); }
  void v4(const char* n, double x, double y, double z, double w) {
    glUniform4f(at(n), float(x), float(y), float(z), float(w));
  }
  void m3(const char* n, const glm::dmat3& m) { glUniformMatrix3fv(at(n), 1, GL_FALSE, glm::value_ptr(glm::mat3(m))); }
  void m4(const char* n, const glm::dmat4& m) { glUniformMatrix4fv(at(n), 1, GL_FALSE, glm::value_ptr(glm::mat4(m))); }
};

glm::dmat4 viewProjection(const OrbitCamera& camera, int width, int height) {
  return camera.projection(double(width) / std::max(height, 1)) * camera.view();
}

}  // namespace

KifsVariant kifsVariant(const kifs::Building& b) {
  const kifs::KifsParams& p = b.params();
  KifsVariant v;
  v.footprint = static_cast<int>(p.mass.footprint);
  v.curvilinear = p.curvilinear.enabled;
  v.r1Identity = b.r1Identity();
  v.r2Identity = b.r2Identity();
  v.idsCut = b.idsCut();
  v.closedRing = p.curvilinear.enabled && b.closedRing();
  v.walls = v.footprint == 3 && b.mass() && !b.mass()->walls.empty() && !v.curvilinear;  // as Building::evaluate
  return v;
}

int KifsVariant::key() const {
  return footprint | curvilinear << 2 | r1Identity << 3 | r2Identity << 4 | idsCut << 5 | closedRing << 6 | walls << 7;
}

std::string kifsShaderSource(const KifsVariant& v) {
  std::string text = shaderSource("kifs.frag.glsl");
  const std::size_t line = text.find('\n');  // after #version, which must come first
  if (text.rfind("#version", 0) != 0 || line == std::string::npos)
    throw Error("kifs.frag.glsl must start with its #version line");
  const std::string defines =
      "#define KIFS_R1_IDENTITY " + std::to_string(int(v.r1Identity)) + "\n#define KIFS_R2_IDENTITY " +
      std::to_string(int(v.r2Identity)) + "\n#define KIFS_FOOTPRINT " + std::to_string(v.footprint) +
      "\n#define KIFS_IDS_CUT " + std::to_string(int(v.idsCut)) + "\n#define KIFS_CURVILINEAR " +
      std::to_string(int(v.curvilinear)) + "\n#define KIFS_CLOSED_RING " + std::to_string(int(v.closedRing)) + "\n#define KIFS_WALLS " + std::to_string(int(v.walls)) +
      "\n#define KIFS_MAX_WALLS " + std::to_string(kifs::kMaxWalls) + "\n#define KIFS_MAX_FACINGS " +
      std::to_string(kifs::kMaxFacings) + "\n";
  return text.insert(line + 1, defines);
}

std::vector<std::string> setKifsUniforms(unsigned program, const kifs::Building& b) {
  const kifs::KifsParams& p = b.params();
  const KifsVariant v = kifsVariant(b);
  UniformWriter w{program, {}};
  glUseProgram(program);
  w.i("uIterations", p.iterations);
  w.f("uScale", p.scale);
  w.v3("uCentre", p.centre);
  if (w.optional("uR1", !v.r1Identity)) w.m3("uR1", b.r1());
  if (w.optional("uR2", !v.r2Identity)) w.m3("uR2", b.r2());
  w.f("uBailout", p.bailout);
  w.f("uRho", b.rho());
  if (w.optional("uMass", v.footprint != 3)) w.v3("uMass", {p.mass.halfWidth, p.mass.halfDepth, p.mass.height});
  if (w.optional("uWing", v.footprint == 1 || v.footprint == 2)) w.f("uWing", p.mass.wing);
  if (v.footprint == 3) {  // the samples themselves are KifsPass::bindMassField's (texture unit 0)
    const kifs::MassField& m = *b.mass();
    w.i("uMassField", 0);
    w.v3("uFieldOrigin", m.origin);
    w.f("uFieldCell", m.cell);
    w.i3("uFieldCount", m.count);
    w.v3("uShellLo", m.shell.lo);
    w.v3("uShellHi", m.shell.hi);
    w.v3("uFrameOrigin", m.frameOrigin);
    w.v2("uFrameAxis", m.frameAxis.x, m.frameAxis.y);
    if (v.walls) {
      std::vector<float> walls, facings;
      std::vector<int> facing;
      for (const kifs::PlanWall& wall : m.walls) {
        walls.insert(walls.end(), {float(wall.a.x), float(wall.a.y), float(wall.b.x), float(wall.b.y)});
        facing.push_back(wall.facing);
      }
      for (const glm::dvec2& f : m.facings) facings.insert(facings.end(), {float(f.x), float(f.y)});
      w.i("uWallCount", int(m.walls.size()));
      w.i("uFacingCount", int(m.facings.size()));
      glUniform4fv(w.at("uWalls[0]"), GLsizei(m.walls.size()), walls.data());
      glUniform1iv(w.at("uWallFacing[0]"), GLsizei(facing.size()), facing.data());
      glUniform2fv(w.at("uFacings[0]"), GLsizei(m.facings.size()), facings.data());
    }
  }
  w.f("uShell", p.mass.shell);
  w.f("uPeriod", p.facade.period);
  w.v3("uFoldR", p.facade.r);
  w.v4("uIdTransform", p.facade.a1, p.facade.a2, p.facade.b1, p.facade.b2);
  w.v3("uFloors", {p.floors.height, p.floors.y0, p.floors.sy});
  w.f("uStretch", b.fractalStretch());
  if (w.optional("uPolar", v.curvilinear))
    w.v4("uPolar", p.curvilinear.sTheta, p.curvilinear.cTheta, p.curvilinear.sR, p.curvilinear.cR);
  if (w.optional("uPolarZ0", v.curvilinear)) w.f("uPolarZ0", p.curvilinear.z0);
  if (w.optional("uRing", v.curvilinear)) w.v2("uRing", b.ringInner(), b.ringOuter());
  w.i("uMaxSteps", p.trace.maxSteps);
  w.f("uLipschitz", p.trace.lipschitz);
  w.f("uOverRelax", p.trace.overRelax);
  w.f("uHitFactor", p.trace.hitFactor);
  w.f("uPixelAngle", p.trace.pixelAngle);
  w.v3("uBoundsLo", b.worldBounds().lo);
  w.v3("uBoundsHi", b.worldBounds().hi);
  return w.names;
}

KifsPass::KifsPass() {
  glGenVertexArrays(1, &vao_);
  program_ = programFor(kifsVariant(kifs::Building(kifs::KifsParams{})));
}

KifsPass::~KifsPass() {
  glDeleteVertexArrays(1, &vao_);
  if (fieldTexture_) glDeleteTextures(1, &fieldTexture_);
  for (const auto& [key, program] : programs_) glDeleteProgram(program);
}

void KifsPass::bindMassField(const std::shared_ptr<const kifs::MassField>& field) {
  if (!fieldTexture_) glGenTextures(1, &fieldTexture_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_3D, fieldTexture_);
  if (field_ != field) {
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_R32F, field->count.x, field->count.y, field->count.z, 0, GL_RED, GL_FLOAT,
                 field->values.data());
    field_ = field;
  }
}

unsigned KifsPass::programFor(const KifsVariant& variant) {
  auto it = programs_.find(variant.key());
  if (it != programs_.end()) return it->second;
  const std::string vs = shaderSource("kifs.vert.glsl"), fs = kifsShaderSource(variant);
  const unsigned program = linkSources(vs.c_str(), fs.c_str(), "kifs.vert.glsl", "kifs.frag.glsl");
  programs_.emplace(variant.key(), program);
  return program;
}

void KifsPass::draw(const kifs::Building& building, const OrbitCamera& camera, int x, int y, int width, int height,
                    KifsMode mode) {
  program_ = programFor(kifsVariant(building));
  if (building.mass()) bindMassField(building.mass());
  const glm::dmat4 vp = viewProjection(camera, width, height);
  UniformWriter w{program_, setKifsUniforms(program_, building)};
  w.m4("uViewProj", vp);
  w.m4("uInvViewProj", glm::inverse(vp));
  const Vec3 eye = camera.eye();
  w.v3("uEye", {eye[0], eye[1], eye[2]});
  w.i("uOrtho", camera.orthographic ? 1 : 0);
  w.v4("uViewport", x, y, width, height);
  w.i("uMode", static_cast<int>(mode));
  w.v3("uSunDir", glm::normalize(glm::dvec3(0.45, -0.35, 0.82)));  // the Renderer's sun
  const KifsCover cover = kifsCover(building, camera, width, height);
  w.v3("uCoverLo", cover.lo);
  w.v3("uCoverHi", cover.hi);
  w.i("uFullScreen", cover.fullScreen);
  glViewport(x, y, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindVertexArray(vao_);
  if (cover.fullScreen) {
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    // Back faces only: each covered pixel is shaded once.
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(GL_FRONT);
    glDrawArrays(GL_TRIANGLES, 0, 36);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  written_ = w.names;
}

KifsCover kifsCover(const kifs::Building& building, const OrbitCamera& camera, int width, int height) {
  const kifs::Aabb box = building.worldBounds();
  const Vec3 e = camera.eye();
  const glm::dvec3 eye(e[0], e[1], e[2]);
  const double diagonal = glm::length(box.size());
  // A box grown by m in each direction holds the ball of radius m round each of its points.
  // Seen from distance d ≤ d_max that ball spans at least m / d radians, and an angle maps to
  // at least as long a step on the image plane (d tan θ ≥ dθ): with m = 2 · pixel · d_max,
  // pixel = 2 tan(fov / 2) / height, the cover reaches two pixels past the bounds everywhere.
  const double tanHalf = std::tan(0.5 * glm::radians(camera.fov_deg));
  const double pixel = 2.0 * tanHalf / std::max(height, 1);
  const double farthest = glm::length(eye - 0.5 * (box.lo + box.hi)) + diagonal;
  const double m = 2.0 * pixel * farthest + 1e-3 * diagonal;
  KifsCover c;
  c.lo = box.lo - glm::dvec3(m);
  c.hi = box.hi + glm::dvec3(m);
  // The back faces are at least dist(eye, cover) from the eye; inside the frustum a point that
  // far has a view depth of at least that over the corner ray's stretch. Keep twice the near
  // plane's distance clear of them, else cover the whole viewport.
  const double aspect = double(width) / std::max(height, 1);
  const double stretch = std::sqrt(1.0 + tanHalf * tanHalf * (1.0 + aspect * aspect));
  const glm::dvec3 gap = glm::max(glm::max(c.lo - eye, eye - c.hi), glm::dvec3(0.0));
  c.fullScreen = glm::length(gap) <= 2.0 * camera.nearPlane() * stretch;
  return c;
}

void drawDepthWritingTriangle(unsigned vao, int x, int y, int width, int height) {
  glViewport(x, y, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

kifs::KifsParams kifsForView(kifs::KifsParams params, const OrbitCamera& camera, int height) {
  params.trace.pixelAngle = kifs::pixelAngle(camera.fov_deg, height);
  return params;
}

OrbitCamera kifsCamera(const kifs::Building& building, double aspect, double azimuthDeg, double elevationDeg) {
  const kifs::Aabb box = building.worldBounds();
  BBox bb;
  bb.add(Vec3(box.lo.x, box.lo.y, box.lo.z));
  bb.add(Vec3(box.hi.x, box.hi.y, box.hi.z));
  OrbitCamera c;
  c.azimuth_deg = azimuthDeg;
  c.elevation_deg = elevationDeg;
  c.frame(bb, aspect);
  return c;
}

DepthTarget::DepthTarget(int width, int height) : width_(width), height_(height) {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    this->~DepthTarget();
    throw Error("the depth framebuffer is incomplete");
  }
}

DepthTarget::~DepthTarget() {
  glDeleteRenderbuffers(1, &color_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteFramebuffers(1, &fbo_);
  fbo_ = color_ = depth_ = 0;
}

void DepthTarget::bind() { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }

std::vector<float> DepthTarget::readDepth() {
  std::vector<float> out(static_cast<std::size_t>(width_) * height_, 1.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

Image DepthTarget::readColor() {
  Image img(width_, height_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return img;
}

namespace {

// The building alone into a cleared target.
void drawAlone(DepthTarget& target, KifsPass& pass, const kifs::Building& building, const OrbitCamera& camera,
               int width, int height, KifsMode mode) {
  target.bind();
  glClearDepth(1.0);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pass.draw(building, camera, 0, 0, width, height, mode);
}

}  // namespace

KifsCost measureKifsCost(KifsPass& pass, const kifs::Building& building, const OrbitCamera& camera, int width,
                         int height) {
  DepthTarget target(width, height);
  drawAlone(target, pass, building, camera, width, height, KifsMode::Cost);
  const Image raw = target.readColor();
  const std::vector<float> depth = target.readDepth();
  KifsCost c;
  std::vector<int>& count = c.perPixel;
  count.resize(depth.size());
  c.ids.resize(depth.size());
  c.storeys.resize(depth.size());
  c.depth = depth;
  double sumHit = 0, sumMiss = 0;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    count[i] = raw.rgba[4 * i] + 256 * raw.rgba[4 * i + 1];
    c.ids[i] = raw.rgba[4 * i + 2];
    c.storeys[i] = raw.rgba[4 * i + 3] - 128;
    if (depth[i] < 1.0f) {
      ++c.hits;
      sumHit += count[i];
      c.maxHit = std::max(c.maxHit, count[i]);
    } else {
      ++c.misses;
      sumMiss += count[i];
    }
  }
  c.meanHit = c.hits ? sumHit / c.hits : 0.0;
  c.meanMiss = c.misses ? sumMiss / c.misses : 0.0;
  const int most = std::max(1, *std::max_element(count.begin(), count.end()));
  c.heat = Image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto v = static_cast<std::uint8_t>(255.0 * count[std::size_t(height - 1 - y) * width + x] / most);
      std::uint8_t* px = c.heat.at(x, y);
      px[0] = px[1] = px[2] = v;
      px[3] = 255;
    }
  return c;
}

std::vector<float> renderKifsDepth(KifsPass& pass, const kifs::Building& building, const OrbitCamera& camera, int width,
                                   int height, KifsMode mode) {
  DepthTarget target(width, height);
  drawAlone(target, pass, building, camera, width, height, mode);
  return target.readDepth();
}

Image renderKifsImage(Renderer& renderer, KifsPass& pass, const kifs::Building& building, const Scene& scene,
                      const OrbitCamera& camera, int width, int height, KifsMode mode,
                      const RenderSettings& settings) {
  OffscreenTarget target(width, height);
  target.bind();
  renderer.setScene(scene, settings);
  renderer.draw(camera, 0, 0, width, height, settings);
  pass.draw(building, camera, 0, 0, width, height, mode);
  glFinish();
  return target.read();
}

RaymarchedKifs raymarchedKifs(const Document& doc, const std::function<bool(ObjectId)>& visible, const Scene* scene,
                              const kifs::TownBuildings& buildings) {
  RaymarchedKifs out;
  for (const DocObject& o : doc.objects) {
    const auto* k = std::get_if<KifsSpec>(&o.spec);
    if (!k || k->meshResolution > 0 || (visible && !visible(o.id))) continue;
    std::optional<kifs::Building> building;
    try {
      if (k->mass.footprint != "object") building.emplace(kifs::paramsOf(*k));
      else if (scene) building.emplace(kifs::buildingOf(doc, *scene, o, nullptr, buildings));
    } catch (const Error& e) {
      if (k->mass.footprint == "object" && scene) out.errors.push_back(o.name + ": " + e.what());
    }
    if (!building) continue;
    const Placement placement = building->mass() ? Placement{} : o.placement;
    out.buildings.push_back(building->params());
    out.placements.push_back(placement);
    out.masses.push_back(building->mass());
    const kifs::Aabb b = building->worldBounds();
    for (int corner = 0; corner < 8; ++corner)
      out.bounds.add(placement.apply(Vec3(corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y,
                                          corner & 4 ? b.hi.z : b.lo.z)));
  }
  return out;
}

OrbitCamera cameraInFrameOf(const OrbitCamera& camera, const Placement& placement) {
  if (placement.identity()) return camera;
  OrbitCamera c = camera;
  c.target = placement.unapply(camera.target);
  c.azimuth_deg = camera.azimuth_deg - placement.rotation_deg;
  return c;
}

Image renderSceneWithKifs(Renderer& renderer, const Scene& scene, const std::vector<kifs::KifsParams>& buildings,
                          const OrbitCamera& camera, int width, int height, const RenderSettings& settings,
                          const std::vector<Placement>& placements,
                          const std::vector<std::shared_ptr<const kifs::MassField>>& masses) {
  std::optional<KifsPass> pass;
  if (!buildings.empty()) pass.emplace();
  OffscreenTarget target(width, height);
  target.bind();
  renderer.setScene(scene, settings);
  renderer.draw(camera, 0, 0, width, height, settings);
  for (std::size_t i = 0; i < buildings.size(); ++i)
    pass->draw(kifs::Building(kifsForView(buildings[i], camera, height), i < masses.size() ? masses[i] : nullptr),
               i < placements.size() ? cameraInFrameOf(camera, placements[i]) : camera, 0, 0, width, height,
               KifsMode::Shaded);
  glFinish();
  return target.read();
}

}  // namespace corbel::render
