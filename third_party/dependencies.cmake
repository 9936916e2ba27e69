# Build glue for Debian's packages (see install-deps.sh), included from the top level so the
# imported targets are visible everywhere. Nothing is vendored here.
find_package(glm REQUIRED)
find_package(embree 3 REQUIRED)
find_package(TBB REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.2 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET GLOBAL stb)

# glm: the Debian package exports glm::glm; older ones only `glm`.
add_library(levrt_glm INTERFACE)
if(TARGET glm::glm)
  target_link_libraries(levrt_glm INTERFACE glm::glm)
else()
  target_link_libraries(levrt_glm INTERFACE glm)
endif()

add_library(levrt_embree INTERFACE)
target_link_libraries(levrt_embree INTERFACE embree)

add_library(levrt_stb INTERFACE)
target_link_libraries(levrt_stb INTERFACE PkgConfig::STB)

# tinyexr (libtinyexr-dev): tinyexr.h plus Debian's libtinyexr.so, which holds the implementation
# (do not define TINYEXR_IMPLEMENTATION) and uses zlib, not miniz. Its CMake package exports
# tinyexr::tinyexr with only a NONE configuration, which CMake uses for any build type.
find_package(tinyexr CONFIG REQUIRED)
add_library(levrt_tinyexr INTERFACE)
target_link_libraries(levrt_tinyexr INTERFACE tinyexr::tinyexr)

if(LEVRT_BUILD_VIEWER)
  find_package(glfw3 3.3 REQUIRED)
  set(OpenGL_GL_PREFERENCE GLVND)
  find_package(OpenGL REQUIRED)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET GLOBAL imgui)
  # Debian's libimgui.a already holds the glfw and opengl3 backends; their headers live in
  # /usr/include/imgui/backends.
  add_library(levrt_imgui INTERFACE)
  target_include_directories(levrt_imgui SYSTEM INTERFACE /usr/include/imgui /usr/include/imgui/backends)
  target_link_libraries(levrt_imgui INTERFACE PkgConfig::IMGUI glfw OpenGL::GL ${CMAKE_DL_LIBS})
endif()
