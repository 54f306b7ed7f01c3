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

}  // namespace

GlViewMapper::GlViewMapper(double pixelSize) : pixel_(pixelSize) {
  if (!(pixelSize > 0)) throw Error("view map pixel size must be positive");
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
  GLint previousFbo = 0, viewport[4];
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFbo);
  glGetIntegerv(GL_VIEWPORT, viewport);
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
      glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFbo));
      glDeleteRenderbuffers(1, &color);
      glDeleteRenderbuffers(1, &depth);
      glDeleteFramebuffers(1, &fbo);
      throw Error("view map framebuffer is incomplete");
    }
    glViewport(0, 0, cols, rows);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_MULTISAMPLE);
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
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFbo));
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
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  return out;
}

}  // namespace corbel::render
