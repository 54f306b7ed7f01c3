#pragma once
// GLSL sources from shaders/, embedded at build time (cmake/EmbedShaders.cmake).
#include <string>
#include <vector>

namespace corbel::render {

struct ShaderSource {
  const char* name;
  const char* text;
};
const std::vector<ShaderSource>& embeddedShaders();
// The text of shaders/<name>; throws corbel::Error if there is no such file.
std::string shaderSource(const std::string& name);

}  // namespace corbel::render
