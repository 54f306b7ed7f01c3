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
// Compiles and links two embedded shaders into a program (needs a current GL context); throws
// corbel::Error with the compiler's log.
unsigned linkProgram(const std::string& vert, const std::string& frag);
// The same from shader texts (labels name them in errors).
unsigned linkSources(const char* vertText, const char* fragText, const std::string& vertLabel,
                     const std::string& fragLabel);

}  // namespace corbel::render
