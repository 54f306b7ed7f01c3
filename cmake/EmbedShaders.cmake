# Turns every file in shaders/ into a string in a generated C++ source, so the binaries do not
# depend on where they are run from. The generated table is looked up by file name
# (render/shader_sources.h).
function(corbel_embed_shaders out_cpp)
  file(GLOB shader_files CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/shaders/*.glsl")
  set(script "${CMAKE_CURRENT_BINARY_DIR}/embed_shaders.cmake")
  file(WRITE "${script}" [=[
file(WRITE "${OUT}" "// Generated from shaders/ by cmake/EmbedShaders.cmake. Do not edit.\n#include \"render/shader_sources.h\"\nnamespace corbel::render {\nconst std::vector<ShaderSource>& embeddedShaders() {\n  static const std::vector<ShaderSource> table = {\n")
file(GLOB FILES "${DIR}/*.glsl")
list(SORT FILES)
foreach(f IN LISTS FILES)
  get_filename_component(name "${f}" NAME)
  file(READ "${f}" text)
  file(APPEND "${OUT}" "    {\"${name}\", R\"corbelglsl(${text})corbelglsl\"},\n")
endforeach()
file(APPEND "${OUT}" "  };\n  return table;\n}\n}  // namespace corbel::render\n")
]=])
  add_custom_command(
    OUTPUT "${out_cpp}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} -DDIR=${PROJECT_SOURCE_DIR}/shaders -P "${script}"
    DEPENDS ${shader_files} "${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake"
    COMMENT "Embedding GLSL shaders")
endfunction()
