#include "render/gl_view_mapper.h"

#include "render/shader_sources.h"

#include "core/error.h"
#include "render/gl.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace corbel::render {

namespace {

constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;  // already in clip space (orthographic)
layout(location = 1) in vec4 aId;        // the box index + 1 as four normalised bytes
flat out vec4 vId;
void main() {
  gl_Position = vec4(aPosition, 1.0);
  vId = aId;
}
)";

constexpr const char* kFragment = R"(#version 330 core
flat in vec4 vId;
out vec4 fragId;
void main() { fragId = vId; }
)";

struct Vertex {
  float x, y, z;
  std::uint8_t id[4];
};

// The state render() changes, read when it starts and put back when it ends (also when it
// throws), so a view-map render can run between the draws of the editor's frame.
class SavedState {
 public:
  SavedState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo_);
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetBooleanv(GL_COLOR_WRITEMASK, colourMask_);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColour_);
    glGetDoublev(GL_DEPTH_CLEAR_VALUE, &clearDepth_);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
    for (int i = 0; i < kCaps; ++i) enabled_[i] = glIsEnabled(kCap[i]);
  }
  ~SavedState() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFbo_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFbo_));
    glBindRenderbuffer(GL_RENDERBUFFER, GLuint(renderbuffer_));
    glUseProgram(GLuint(program_));
    glBindVertexArray(GLuint(vao_));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glDepthFunc(GLenum(depthFunc_));
    glDepthMask(depthMask_);
    glColorMask(colourMask_[0], colourMask_[1], colourMask_[2], colourMask_[3]);
    glClearColor(clearColour_[0], clearColour_[1], clearColour_[2], clearColour_[3]);
    glClearDepth(clearDepth_);
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    for (int i = 0; i < kCaps; ++i) (enabled_[i] ? glEnable : glDisable)(kCap[i]);
  }
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;

 private:
  static constexpr int kCaps = 5;
  static constexpr GLenum kCap[kCaps] = {GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_MULTISAMPLE, GL_SCISSOR_TEST};
  GLint drawFbo_ = 0, readFbo_ = 0, renderbuffer_ = 0, program_ = 0, vao_ = 0, arrayBuffer_ = 0;
  GLint viewport_[4] = {0, 0, 0, 0};
  GLint depthFunc_ = GL_LESS, packAlignment_ = 4;
  GLboolean depthMask_ = GL_TRUE, colourMask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
  GLfloat clearColour_[4] = {0, 0, 0, 0};
  GLdouble clearDepth_ = 1;
  GLboolean enabled_[kCaps] = {};
};

}  // namespace

GlViewMapper::GlViewMapper(double pixelSize) : pixel_(pixelSize) {
  if (!(pixelSize > 0)) throw Error("view map pixel size must be positive");
  const SavedState saved;
  program_ = linkSources(kVertex, kFragment, "view map vertex", "view map fragment");
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, x)));
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, id)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
}

void GlViewMapper::setPixelSize(double pixelSize) {
  if (!(pixelSize > 0)) throw Error("view map pixel size must be positive");
  pixel_ = pixelSize;
}

GlViewMapper::~GlViewMapper() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

growth::ViewMaps GlViewMapper::render(const std::vector<growth::ViewBox>& boxes, const growth::Box& frame) {
  using growth::ViewDirection;
  growth::ViewMaps out;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  const SavedState saved;
  for (ViewDirection d : growth::kViewDirections) {
    const growth::Rect f = growth::projectFrame(frame, d);
    const int cols = std::max(1, int(std::ceil((f.u1 - f.u0) / pixel_ - 1e-9)));
    const int rows = std::max(1, int(std::ceil((f.v1 - f.v0) / pixel_ - 1e-9)));
    if (cols > maxSize || rows > maxSize)
      throw Error("view map of " + std::to_string(cols) + " x " + std::to_string(rows) + " pixels exceeds GL's " +
                  std::to_string(maxSize) + " per side: use larger pixels");
    // Depth: the frame's near face maps to -1, its far face to +1 (GL_LESS keeps the nearest).
    const double nearS = growth::frontDepth(frame, d);
    const double farS = -growth::frontDepth(frame, ViewDirection(int(d) ^ 1));
    const double w = cols * pixel_, h = rows * pixel_;
    std::vector<Vertex> vertices;
    vertices.reserve(boxes.size() * 6);
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const growth::Rect r = growth::projectBox(boxes[k].box, d);
      const double s = growth::frontDepth(boxes[k].box, d);
      const float z = float(std::clamp(-1 + 2 * (nearS - s) / std::max(nearS - farS, 1e-9), -1.0, 1.0));
      const std::uint32_t id = std::uint32_t(k + 1);
      const std::uint8_t b[4] = {std::uint8_t(id), std::uint8_t(id >> 8), std::uint8_t(id >> 16),
                                 std::uint8_t(id >> 24)};
      auto x = [&](double u) { return float(-1 + 2 * (u - f.u0) / w); };
      auto y = [&](double v) { return float(-1 + 2 * (v - f.v0) / h); };
      const Vertex q[4] = {{x(r.u0), y(r.v0), z, {b[0], b[1], b[2], b[3]}},
                           {x(r.u1), y(r.v0), z, {b[0], b[1], b[2], b[3]}},
                           {x(r.u1), y(r.v1), z, {b[0], b[1], b[2], b[3]}},
                           {x(r.u0), y(r.v1), z, {b[0], b[1], b[2], b[3]}}};
      for (int i : {0, 1, 2, 0, 2, 3}) vertices.push_back(q[i]);
    }
    GLuint fbo = 0, color = 0, depth = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, cols, rows);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, cols, rows);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glDeleteRenderbuffers(1, &color);
      glDeleteRenderbuffers(1, &depth);
      glDeleteFramebuffers(1, &fbo);
      throw Error("view map framebuffer is incomplete");
    }
    glViewport(0, 0, cols, rows);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_MULTISAMPLE);
    glDisable(GL_SCISSOR_TEST);  // the editor's ImGui pass leaves it on; it would clip the clear
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(program_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
    std::vector<std::uint8_t> pixels(std::size_t(cols) * rows * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, cols, rows, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());  // bottom row first: v increasing
    glBindFramebuffer(GL_FRAMEBUFFER, 0);  // not bound while deleted; `saved` puts the caller's back
    glDeleteRenderbuffers(1, &color);
    glDeleteRenderbuffers(1, &depth);
    glDeleteFramebuffers(1, &fbo);

    growth::ViewMap m = growth::ViewMap::uniform({f.u0, f.v0, f.u0 + w, f.v0 + h}, cols, rows);
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < cols; ++i) {
        const std::uint8_t* p = &pixels[(std::size_t(j) * cols + i) * 4];
        const std::uint32_t k =
            std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
        if (k == 0 || k > boxes.size()) continue;
        m.offer(i, j, boxes[k - 1].id, growth::frontDepth(boxes[k - 1].box, d));
      }
    m.finish();
    out[d] = std::move(m);
  }
  return out;
}

ContextViewMapper::ContextViewMapper(std::unique_ptr<GlContextLease> lease, double pixelSize)
    : lease_(std::move(lease)), pixel_(pixelSize) {
  if (!lease_) throw Error("the GL view mapper needs a context");
  if (!(pixelSize > 0)) throw Error("view map pixel size must be positive");
}

ContextViewMapper::~ContextViewMapper() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!gl_) return;
  lease_->enter();
  gl_.reset();
  lease_->leave();
}

double ContextViewMapper::pixelSize() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return pixel_;
}

void ContextViewMapper::setPixelSize(double pixelSize) {
  if (!(pixelSize > 0)) throw Error("view map pixel size must be positive");
  const std::lock_guard<std::mutex> lock(mutex_);
  pixel_ = pixelSize;
  if (gl_) gl_->setPixelSize(pixelSize);
}

growth::ViewMaps ContextViewMapper::render(const std::vector<growth::ViewBox>& boxes, const growth::Box& frame) {
  const std::lock_guard<std::mutex> lock(mutex_);
  lease_->enter();
  struct Leave {
    GlContextLease& lease;
    ~Leave() { lease.leave(); }
  } leave{*lease_};
  if (!gl_) gl_ = std::make_unique<GlViewMapper>(pixel_);
  return gl_->render(boxes, frame);
}

}  // namespace corbel::render
