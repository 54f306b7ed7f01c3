#include "render/renderer.h"

#include "core/error.h"
#include "core/materials.h"
#include "core/textures.h"
#include "render/gl.h"
#include "render/shader_sources.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace corbel::render {

std::string shaderSource(const std::string& name) {
  for (const auto& s : embeddedShaders())
    if (name == s.name) return s.text;
  throw Error("no shader named '" + name + "' was embedded");
}

namespace {

GLuint compile(GLenum type, const char* text, const std::string& label) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw Error("shader " + label + " failed to compile: " + log);
  }
  return s;
}

// A VAO + VBO pair holding interleaved float attributes.
struct Buffer {
  GLuint vao = 0, vbo = 0;
  GLsizei count = 0;
  void create(const std::vector<int>& sizes) {
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    int stride = 0;
    for (int s : sizes) stride += s;
    std::size_t offset = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      glEnableVertexAttribArray(static_cast<GLuint>(i));
      glVertexAttribPointer(static_cast<GLuint>(i), sizes[i], GL_FLOAT, GL_FALSE, stride * sizeof(float),
                            reinterpret_cast<const void*>(offset * sizeof(float)));
      offset += sizes[i];
    }
    stride_ = stride;
    glBindVertexArray(0);
  }
  void upload(const std::vector<float>& data) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_DYNAMIC_DRAW);
    count = static_cast<GLsizei>(data.size() / stride_);
  }
  void destroy() {
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
  }
  int stride_ = 1;
};

void setMat(GLuint program, const char* name, const glm::mat4& m) {
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, glm::value_ptr(m));
}
void setVec3(GLuint program, const char* name, float x, float y, float z) {
  glUniform3f(glGetUniformLocation(program, name), x, y, z);
}

double niceStep(double span) {
  const double raw = span / 20.0;
  const double p = std::pow(10.0, std::floor(std::log10(std::max(raw, 1e-6))));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * p) return m * p;
  return 10.0 * p;
}

}  // namespace

unsigned linkSources(const char* vertText, const char* fragText, const std::string& vertLabel,
                     const std::string& fragLabel) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertText, vertLabel);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragText, fragLabel);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    glDeleteProgram(p);
    throw Error("program " + vertLabel + " + " + fragLabel + " failed to link: " + log);
  }
  return p;
}

unsigned linkProgram(const std::string& vert, const std::string& frag) {
  const std::string vs = shaderSource(vert), fs = shaderSource(frag);
  return linkSources(vs.c_str(), fs.c_str(), vert, frag);
}

Vec3 defaultSun() { return Vec3(0.45, -0.35, 0.82).normalized(); }

Vec3 sunDirection(double azimuthDeg, double elevationDeg) {
  const double a = glm::radians(azimuthDeg), e = glm::radians(elevationDeg);
  return Vec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
}

glm::mat4 lightViewProj(const BBox& box, const Vec3& sunIn) {
  const Vec3 sun = sunIn.norm() > 0 ? sunIn.normalized() : defaultSun();
  const Vec3 c = box.empty() ? Vec3(0.0) : box.center();
  const double r = box.empty() ? 1.0 : std::max(0.5 * box.size().norm(), 1e-3);
  const glm::dvec3 centre(c[0], c[1], c[2]), toSun(sun[0], sun[1], sun[2]);
  // Up: +Z unless the sun is (nearly) overhead.
  const glm::dvec3 up = std::abs(sun[2]) > 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  const glm::dmat4 view = glm::lookAt(centre + toSun * (2.0 * r), centre, up);
  const glm::dmat4 proj = glm::ortho(-r, r, -r, r, r, 3.0 * r);
  return glm::mat4(proj * view);
}

struct Renderer::Impl {
  GLuint meshProgram = 0, lineProgram = 0, backgroundProgram = 0, shadowProgram = 0;
  Buffer faces, highlightFaces, edges, grid, overlayLines, overlayTriangles, topLines, topTriangles, ground;
  // With RenderSettings::textures: faces that show a texture, [x y z nx ny nz r g b u v layer].
  Buffer texturedFaces, texturedHighlight;
  // The built-in textures (core/textures.h) as layers of one array texture, made on first use.
  GLuint textureArray = 0;
  void makeTextureArray();
  bool textured = false;  // what the buffers were built for
  // The shadow map: a depth texture and its framebuffer, made on first use.
  GLuint shadowFbo = 0, shadowTexture = 0;
  int shadowSize = 2048;
  BBox bounds;  // of the visible faces
  // Renders the depth of the faces from the sun into the shadow map, and puts the framebuffer,
  // viewport and scissor back as they were.
  void renderShadowMap(const glm::mat4& light);
  GLuint emptyVao = 0;
  std::uint64_t sceneRevision = ~0ull;
  std::vector<ObjectId> visibleIds;
  std::optional<ObjectId> highlight;
  Vec3 gridCenter{0.0};
  double gridRadius = 50.0;
  std::size_t triangles = 0;
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
  impl_->meshProgram = linkProgram("mesh.vert.glsl", "mesh.frag.glsl");
  impl_->lineProgram = linkProgram("line.vert.glsl", "line.frag.glsl");
  impl_->backgroundProgram = linkProgram("background.vert.glsl", "background.frag.glsl");
  impl_->shadowProgram = linkProgram("shadow.vert.glsl", "shadow.frag.glsl");
  impl_->faces.create({3, 3, 3});
  impl_->ground.create({3, 3, 3});
  impl_->highlightFaces.create({3, 3, 3});
  impl_->edges.create({3, 4});
  impl_->grid.create({3, 4});
  impl_->overlayLines.create({3, 4});
  impl_->overlayTriangles.create({3, 3, 3});
  impl_->topLines.create({3, 4});
  impl_->topTriangles.create({3, 3, 3});
  impl_->texturedFaces.create({3, 3, 3, 3});
  impl_->texturedHighlight.create({3, 3, 3, 3});
  glGenVertexArrays(1, &impl_->emptyVao);
}

Renderer::~Renderer() {
  for (Buffer* b : {&impl_->faces, &impl_->highlightFaces, &impl_->edges, &impl_->grid, &impl_->overlayLines,
                    &impl_->overlayTriangles, &impl_->topLines, &impl_->topTriangles, &impl_->ground,
                    &impl_->texturedFaces, &impl_->texturedHighlight})
    b->destroy();
  if (impl_->textureArray) glDeleteTextures(1, &impl_->textureArray);
  if (impl_->shadowFbo) glDeleteFramebuffers(1, &impl_->shadowFbo);
  if (impl_->shadowTexture) glDeleteTextures(1, &impl_->shadowTexture);
  glDeleteProgram(impl_->shadowProgram);
  glDeleteVertexArrays(1, &impl_->emptyVao);
  glDeleteProgram(impl_->meshProgram);
  glDeleteProgram(impl_->lineProgram);
  glDeleteProgram(impl_->backgroundProgram);
}

std::size_t Renderer::triangleCount() const { return impl_->triangles; }
std::size_t Renderer::edgeCount() const { return std::size_t(impl_->edges.count) / 2; }

void Renderer::setScene(const Scene& scene, const RenderSettings& settings) {
  std::vector<ObjectId> ids;
  for (const auto& [id, info] : scene.objects())
    if (!settings.visible || settings.visible(id)) ids.push_back(id);
  if (scene.revision() == impl_->sceneRevision && ids == impl_->visibleIds && settings.highlight == impl_->highlight &&
      settings.textures == impl_->textured)
    return;
  impl_->textured = settings.textures;
  impl_->sceneRevision = scene.revision();
  impl_->visibleIds = ids;
  impl_->highlight = settings.highlight;

  const PolyMesh& mesh = scene.mesh();
  std::vector<char> show(static_cast<std::size_t>(ids.empty() ? 1 : ids.back() + 1), 0);
  for (ObjectId id : ids) show[id] = 1;
  auto visible = [&](ObjectId id) { return id < show.size() && show[id]; };

  std::vector<float> faceData, highlightData, edgeData, texturedData, texturedHighlightData;
  std::vector<Vec3> poly;
  std::vector<Vec2> uv;
  const std::vector<std::string_view>& layers = builtinTextureNames();
  BBox box;
  impl_->triangles = 0;
  std::vector<Vec3> normals(mesh.n_faces(), Vec3(0, 0, 0));
  for (auto f : mesh.faces()) {
    const ObjectId id = scene.faceObject(f);
    if (!visible(id)) continue;
    poly.clear();
    for (auto v : mesh.fv_range(f)) {
      poly.push_back(mesh.point(v));
      box.add(mesh.point(v));
    }
    Vec3 n = newellNormal(poly);
    if (n.norm() > 0) n.normalize();
    normals[f.idx()] = n;
    const Rgb c = materialColor(scene.faceMaterial(f), scene.faceKind(f));
    const bool lit = settings.highlight && *settings.highlight == id;
    const SurfaceTexture* own =
        settings.textures && settings.tagTextures ? settings.tagTextures(id, scene.faceTag(f)) : nullptr;
    const TextureUse use = settings.textures ? textureFor(own, scene.faceMaterial(f)) : TextureUse{};
    if (use.texture) {  // the glb's coordinates; the layer is the texture's place among the built-in ones
      faceTextureCoordinates(poly, n, use.metres, uv);
      const float layer = float(std::find(layers.begin(), layers.end(), use.name) - layers.begin());
      std::vector<float>& out = lit ? texturedHighlightData : texturedData;
      for (const auto& t : triangulatePolygon(poly)) {
        for (int k : t)
          out.insert(out.end(), {float(poly[k][0]), float(poly[k][1]), float(poly[k][2]), float(n[0]), float(n[1]),
                                 float(n[2]), c[0], c[1], c[2], float(uv[k][0]), float(uv[k][1]), layer});
        ++impl_->triangles;
      }
      continue;
    }
    std::vector<float>& out = lit ? highlightData : faceData;
    for (const auto& t : triangulatePolygon(poly)) {
      for (int k : t)
        out.insert(out.end(), {float(poly[k][0]), float(poly[k][1]), float(poly[k][2]), float(n[0]), float(n[1]),
                               float(n[2]), c[0], c[1], c[2]});
      ++impl_->triangles;
    }
  }
  for (auto e : mesh.edges()) {
    auto h = mesh.halfedge_handle(e, 0);
    auto f0 = mesh.face_handle(h), f1 = mesh.opposite_face_handle(h);
    const bool on =
        (f0.is_valid() && visible(scene.faceObject(f0))) || (f1.is_valid() && visible(scene.faceObject(f1)));
    if (!on) continue;
    // An edge inside one planar face (a kernel triangulated a face with holes) is not drawn,
    // except in wireframe: outlines show the model's faces, not how they were cut up.
    if (!settings.wireframe && f0.is_valid() && f1.is_valid() && scene.faceObject(f0) == scene.faceObject(f1) &&
        scene.faceMaterial(f0) == scene.faceMaterial(f1) && scene.faceTag(f0) == scene.faceTag(f1) &&
        OpenMesh::dot(normals[f0.idx()], normals[f1.idx()]) > 1 - 1e-9)
      continue;
    // A meshed KIFS building is an isosurface cut into many small facets: outlined, every facet
    // edge would paint it dark. Only its creases (faces more than 30° apart) are drawn.
    if (!settings.wireframe && f0.is_valid() && f1.is_valid() && scene.faceObject(f0) == scene.faceObject(f1) &&
        scene.faceTag(f0) == "kifs" && scene.faceTag(f1) == "kifs" &&
        OpenMesh::dot(normals[f0.idx()], normals[f1.idx()]) > 0.8660254037844387)  // cos 30°
      continue;
    for (auto v : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)}) {
      const auto& p = mesh.point(v);
      edgeData.insert(edgeData.end(), {float(p[0]), float(p[1]), float(p[2]), 0.12f, 0.12f, 0.14f, 0.85f});
    }
  }
  impl_->faces.upload(faceData);
  impl_->highlightFaces.upload(highlightData);
  impl_->texturedFaces.upload(texturedData);
  impl_->texturedHighlight.upload(texturedHighlightData);
  if (!texturedData.empty() || !texturedHighlightData.empty()) impl_->makeTextureArray();
  impl_->edges.upload(edgeData);

  // Ground grid: a 1-2-5 step with about 20 cells across the scene, major lines every 5.
  const Vec3 center = box.empty() ? Vec3(0.0) : box.center();
  const double span = box.empty() ? 40.0 : std::max({box.size()[0], box.size()[1], 4.0}) * 2.5;
  const double step = niceStep(span);
  const int half = static_cast<int>(std::ceil(0.5 * span / step));
  const double cx = std::round(center[0] / step) * step, cy = std::round(center[1] / step) * step;
  std::vector<float> gridData;
  for (int i = -half; i <= half; ++i) {
    const float a = (i % 5 == 0) ? 0.45f : 0.22f;
    const float x = float(cx + i * step), y = float(cy + i * step);
    const float x0 = float(cx - half * step), x1 = float(cx + half * step);
    const float y0 = float(cy - half * step), y1 = float(cy + half * step);
    gridData.insert(gridData.end(), {x, y0, 0.f, 0.3f, 0.32f, 0.35f, a, x, y1, 0.f, 0.3f, 0.32f, 0.35f, a});
    gridData.insert(gridData.end(), {x0, y, 0.f, 0.3f, 0.32f, 0.35f, a, x1, y, 0.f, 0.3f, 0.32f, 0.35f, a});
  }
  impl_->grid.upload(gridData);
  impl_->gridCenter = Vec3(cx, cy, 0.0);
  impl_->gridRadius = half * step;
  impl_->bounds = box;
  // The ground that receives shadows, facing up: the grid's square, or three times the radius of
  // the scene's bounding sphere if that is larger (long shadows of a low sun).
  const double groundR = std::max(half * step, box.empty() ? 0.0 : 1.5 * box.size().norm());
  const float g0x = float(cx - groundR), g1x = float(cx + groundR);
  const float g0y = float(cy - groundR), g1y = float(cy + groundR);
  const float gc[3] = {0.80f, 0.79f, 0.76f};
  std::vector<float> groundData;
  for (auto [px, py] : {std::pair{g0x, g0y}, {g1x, g0y}, {g1x, g1y}, {g0x, g0y}, {g1x, g1y}, {g0x, g1y}})
    groundData.insert(groundData.end(), {px, py, 0.f, 0.f, 0.f, 1.f, gc[0], gc[1], gc[2]});
  impl_->ground.upload(groundData);
}

void Renderer::draw(const OrbitCamera& camera, int x, int y, int width, int height, const RenderSettings& settings) {
  Impl& r = *impl_;
  const Vec3 sunDir = settings.sun && settings.sun->norm() > 0 ? settings.sun->normalized() : defaultSun();
  const bool shadows = settings.shadows && !settings.wireframe;
  const glm::mat4 light = lightViewProj(r.bounds, sunDir);
  if (shadows) r.renderShadowMap(light);
  glViewport(x, y, width, height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, width, height);
  glClearColor(0.f, 0.f, 0.f, 0.f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);

  if (settings.background) {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(r.backgroundProgram);
    setVec3(r.backgroundProgram, "uTop", 0.62f, 0.72f, 0.84f);
    setVec3(r.backgroundProgram, "uBottom", 0.93f, 0.93f, 0.91f);
    glBindVertexArray(r.emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  const glm::mat4 viewProj = glm::mat4(camera.projection(double(width) / std::max(height, 1)) * camera.view());
  const Vec3 eye = camera.eye();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);

  glUseProgram(r.meshProgram);
  setMat(r.meshProgram, "uViewProj", viewProj);
  const glm::vec3 sun = settings.sun ? glm::vec3(float(sunDir[0]), float(sunDir[1]), float(sunDir[2]))
                                     : glm::normalize(glm::vec3(0.45f, -0.35f, 0.82f));
  setVec3(r.meshProgram, "uSunDir", sun.x, sun.y, sun.z);
  glUniform1i(glGetUniformLocation(r.meshProgram, "uShadows"), shadows ? 1 : 0);
  glUniform1i(glGetUniformLocation(r.meshProgram, "uShadowMap"), 1);
  glUniform1i(glGetUniformLocation(r.meshProgram, "uTextures"), 2);
  glUniform1i(glGetUniformLocation(r.meshProgram, "uTextured"), 0);
  if (shadows) {
    setMat(r.meshProgram, "uLightViewProj", light);
    glUniform1f(glGetUniformLocation(r.meshProgram, "uShadowTexel"), 1.0f / float(r.shadowSize));
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.shadowTexture);
    glActiveTexture(GL_TEXTURE0);
  }
  setVec3(r.meshProgram, "uEye", float(eye[0]), float(eye[1]), float(eye[2]));
  setVec3(r.meshProgram, "uTintColor", 1.0f, 0.62f, 0.15f);
  if (!settings.wireframe) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.0f);
    glBindVertexArray(r.faces.vao);
    glDrawArrays(GL_TRIANGLES, 0, r.faces.count);
    glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.35f);
    glBindVertexArray(r.highlightFaces.vao);
    glDrawArrays(GL_TRIANGLES, 0, r.highlightFaces.count);
    if (r.texturedFaces.count + r.texturedHighlight.count > 0) {
      glActiveTexture(GL_TEXTURE2);
      glBindTexture(GL_TEXTURE_2D_ARRAY, r.textureArray);
      glActiveTexture(GL_TEXTURE0);
      glUniform1i(glGetUniformLocation(r.meshProgram, "uTextured"), 1);
      glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.0f);
      glBindVertexArray(r.texturedFaces.vao);
      glDrawArrays(GL_TRIANGLES, 0, r.texturedFaces.count);
      glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.35f);
      glBindVertexArray(r.texturedHighlight.vao);
      glDrawArrays(GL_TRIANGLES, 0, r.texturedHighlight.count);
      glUniform1i(glGetUniformLocation(r.meshProgram, "uTextured"), 0);
      glActiveTexture(GL_TEXTURE2);
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
      glActiveTexture(GL_TEXTURE0);
    }
    if (shadows) {
      // The ground, pushed further back than the faces so floors at z = 0 win over it.
      glPolygonOffset(4.0f, 16.0f);
      glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.0f);
      glBindVertexArray(r.ground.vao);
      glDrawArrays(GL_TRIANGLES, 0, r.ground.count);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  r.overlayTriangles.upload(overlay_.triangleVertices());
  r.overlayLines.upload(overlay_.lineVertices());
  glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.0f);
  glBindVertexArray(r.overlayTriangles.vao);
  glDrawArrays(GL_TRIANGLES, 0, r.overlayTriangles.count);

  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(r.lineProgram);
  setMat(r.lineProgram, "uViewProj", viewProj);
  if (settings.grid) {
    setVec3(r.lineProgram, "uFadeCenter", float(r.gridCenter[0]), float(r.gridCenter[1]), 0.f);
    glUniform1f(glGetUniformLocation(r.lineProgram, "uFadeRadius"), float(r.gridRadius * 1.05));
    glDepthMask(GL_FALSE);
    glBindVertexArray(r.grid.vao);
    glDrawArrays(GL_LINES, 0, r.grid.count);
    glDepthMask(GL_TRUE);
  }
  glUniform1f(glGetUniformLocation(r.lineProgram, "uFadeRadius"), 0.0f);
  if (settings.edges || settings.wireframe) {
    glBindVertexArray(r.edges.vao);
    glDrawArrays(GL_LINES, 0, r.edges.count);
  }
  glBindVertexArray(r.overlayLines.vao);
  glDrawArrays(GL_LINES, 0, r.overlayLines.count);

  if (!onTop_.empty()) {
    glDisable(GL_DEPTH_TEST);
    r.topTriangles.upload(onTop_.triangleVertices());
    r.topLines.upload(onTop_.lineVertices());
    glUseProgram(r.meshProgram);
    glUniform1f(glGetUniformLocation(r.meshProgram, "uTint"), 0.0f);
    glBindVertexArray(r.topTriangles.vao);
    glDrawArrays(GL_TRIANGLES, 0, r.topTriangles.count);
    glUseProgram(r.lineProgram);
    glBindVertexArray(r.topLines.vao);
    glDrawArrays(GL_LINES, 0, r.topLines.count);
    glEnable(GL_DEPTH_TEST);
  }

  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  if (shadows) {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
  }
}

void Renderer::Impl::makeTextureArray() {
  if (textureArray) return;
  const std::vector<std::string_view>& names = builtinTextureNames();
  const int size = materialTexture(names.front())->size;
  for (std::string_view n : names)
    if (materialTexture(n)->size != size) throw Error("the built-in textures differ in size");
  glGenTextures(1, &textureArray);
  glBindTexture(GL_TEXTURE_2D_ARRAY, textureArray);
  GLint alignment = 4;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Rows top first, as the glb's PNG: v = 0 is the image's top row in both.
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGB8, size, size, GLsizei(names.size()), 0, GL_RGB, GL_UNSIGNED_BYTE,
               nullptr);
  for (std::size_t i = 0; i < names.size(); ++i)
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(i), size, size, 1, GL_RGB, GL_UNSIGNED_BYTE,
                    materialTexture(names[i])->rgb.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void Renderer::Impl::renderShadowMap(const glm::mat4& light) {
  Impl& r = *this;
  GLint drawFbo = 0, readFbo = 0, viewport[4] = {}, scissor[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_SCISSOR_BOX, scissor);
  const GLboolean scissorOn = glIsEnabled(GL_SCISSOR_TEST);
  if (!r.shadowTexture) {
    glGenTextures(1, &r.shadowTexture);
    glBindTexture(GL_TEXTURE_2D, r.shadowTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, r.shadowSize, r.shadowSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &r.shadowFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, r.shadowFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, r.shadowTexture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, r.shadowFbo);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, r.shadowSize, r.shadowSize);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glUseProgram(r.shadowProgram);
  setMat(r.shadowProgram, "uLightViewProj", light);
  for (const Buffer* b : {&r.faces, &r.highlightFaces, &r.texturedFaces, &r.texturedHighlight}) {
    glBindVertexArray(b->vao);
    glDrawArrays(GL_TRIANGLES, 0, b->count);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindVertexArray(0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFbo));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFbo));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glScissor(scissor[0], scissor[1], scissor[2], scissor[3]);
  if (scissorOn) glEnable(GL_SCISSOR_TEST);
}

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1..16384");
  GLint maxSamples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  samples_ = std::min(samples_, static_cast<int>(maxSamples));
  glGenFramebuffers(1, &msFbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, msFbo_);
  glGenRenderbuffers(1, &msColor_);
  glBindRenderbuffer(GL_RENDERBUFFER, msColor_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColor_);
  glGenRenderbuffers(1, &msDepth_);
  glBindRenderbuffer(GL_RENDERBUFFER, msDepth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msDepth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("offscreen framebuffer is incomplete");
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("resolve framebuffer is incomplete");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

OffscreenTarget::~OffscreenTarget() {
  glDeleteFramebuffers(1, &msFbo_);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &msColor_);
  glDeleteRenderbuffers(1, &msDepth_);
  glDeleteRenderbuffers(1, &color_);
}

void OffscreenTarget::bind() { glBindFramebuffer(GL_FRAMEBUFFER, msFbo_); }

Image OffscreenTarget::read() {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  Image img(width_, height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  img.flipVertically();
  return img;
}

std::string glDescription() {
  auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "?");
  };
  return str(GL_VERSION) + ", " + str(GL_RENDERER);
}

}  // namespace corbel::render
