#include "render/kifs_layer.h"

#include "core/error.h"
#include "render/gl.h"
#include "render/shader_sources.h"

#include <algorithm>

namespace corbel::render {

KifsLayer::KifsLayer() {
  program_ = linkProgram("background.vert.glsl", "kifs_layer.frag.glsl");
  glGenVertexArrays(1, &vao_);
  glGenFramebuffers(1, &fbo_);
}

KifsLayer::~KifsLayer() {
  glDeleteTextures(1, &color_);
  glDeleteTextures(1, &depth_);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

void KifsLayer::resize(int w, int h) {
  if (w == w_ && h == h_ && color_) return;
  glDeleteTextures(1, &color_);
  glDeleteTextures(1, &depth_);
  glGenTextures(1, &color_);
  glBindTexture(GL_TEXTURE_2D, color_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenTextures(1, &depth_);
  glBindTexture(GL_TEXTURE_2D, depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, w, h, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  if (!complete) throw Error("the KIFS layer's framebuffer is incomplete");
  w_ = w;
  h_ = h;
}

bool KifsLayer::update(KifsPass& pass, const std::vector<kifs::KifsParams>& buildings, const OrbitCamera& camera,
                       int width, int height, int scale, KifsMode mode, const std::string& key,
                       const std::vector<Placement>& placements,
                       const std::vector<std::shared_ptr<const kifs::MassField>>& masses) {
  scale = std::max(1, scale);
  const int w = std::max(1, (width + scale - 1) / scale), h = std::max(1, (height + scale - 1) / scale);
  if (key == key_ && !key.empty() && w == w_ && h == h_ && scale == scale_) return false;
  GLint previous = 0, viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glGetIntegerv(GL_VIEWPORT, viewport);
  resize(w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, w, h);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // The same camera over the smaller layer: the projection depends only on the aspect, so
  // texel (i, j) sees what viewport pixels (i·scale.., j·scale..) would.
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    kifs::KifsParams coarse = buildings[i];
    coarse.trace.pixelAngle *= scale;  // a texel spans `scale` pixels: a hit within it is enough
    // While the view keeps changing, the coarse frames skip shadows and occlusion.
    const KifsMode drawn = scale > 1 && mode == KifsMode::Shaded ? KifsMode::Preview : mode;
    pass.draw(kifs::Building(coarse, i < masses.size() ? masses[i] : nullptr), i < placements.size() ? cameraInFrameOf(camera, placements[i]) : camera, 0, 0, w, h,
              drawn);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  key_ = key.empty() ? std::string("(unnamed)") : key;
  scale_ = scale;
  return true;
}

void KifsLayer::composite(int x, int y, int width, int height) {
  if (!color_) return;
  glUseProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, color_);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, depth_);
  glUniform1i(glGetUniformLocation(program_, "uColor"), 0);
  glUniform1i(glGetUniformLocation(program_, "uDepth"), 1);
  glUniform4i(glGetUniformLocation(program_, "uViewport"), x, y, width, height);
  glUniform1i(glGetUniformLocation(program_, "uScale"), scale_);
  drawDepthWritingTriangle(vao_, x, y, width, height);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
}

}  // namespace corbel::render
