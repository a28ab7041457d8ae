# The browser build's dependencies, the same libraries as the desktop's (FoldLabDependencies.cmake)
# compiled by emcc from what Debian ships: header-only ones from Debian's own headers, stb and
# TinyGLTF from their Debian headers with the implementation macro set once, Dear ImGui 1.86 from
# Debian's source package, which scripts/web.sh fetches into FOLDLAB_IMGUI_SOURCE_DIR. GLFW and
# GLES come with emscripten. Nothing is downloaded here.
set(FOLDLAB_IMGUI_SOURCE_DIR "" CACHE PATH "Dear ImGui's sources (scripts/web.sh fetches them)")
if(NOT EXISTS "${FOLDLAB_IMGUI_SOURCE_DIR}/imgui.h")
  message(FATAL_ERROR "FOLDLAB_IMGUI_SOURCE_DIR must hold Dear ImGui's sources; "
    "scripts/web.sh fetches Debian's into build-web/cache/imgui")
endif()

# Only the named system headers, not all of /usr/include, are put where emcc looks: the host's C
# library headers must never shadow emscripten's.
set(system_headers ${PROJECT_BINARY_DIR}/system-headers)
file(MAKE_DIRECTORY ${system_headers})
foreach(entry nlohmann CLI stb tiny_gltf.h)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "/usr/include/${entry} is missing: run scripts/install-deps.sh")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${system_headers}/${entry} SYMBOLIC)
endforeach()

add_library(Eigen3::Eigen INTERFACE IMPORTED)
set_target_properties(Eigen3::Eigen PROPERTIES
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES /usr/include/eigen3
  INTERFACE_INCLUDE_DIRECTORIES /usr/include/eigen3)
foreach(target nlohmann_json::nlohmann_json CLI11::CLI11)
  add_library(${target} INTERFACE IMPORTED)
  set_target_properties(${target} PROPERTIES
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${system_headers}
    INTERFACE_INCLUDE_DIRECTORIES ${system_headers})
endforeach()
# No threads in the browser build (app/gui/background_job.hpp says why).
add_library(Threads::Threads INTERFACE IMPORTED)

add_library(foldlab_stb STATIC ${CMAKE_CURRENT_LIST_DIR}/web/stb.cpp)
target_include_directories(foldlab_stb SYSTEM PUBLIC ${system_headers}/stb)
add_library(foldlab::stb ALIAS foldlab_stb)

add_library(foldlab_tinygltf STATIC ${CMAKE_CURRENT_LIST_DIR}/web/tiny_gltf.cpp)
target_include_directories(foldlab_tinygltf SYSTEM PUBLIC ${system_headers})
target_link_libraries(foldlab_tinygltf PUBLIC foldlab::stb)
add_library(TinyGLTF::TinyGLTF ALIAS foldlab_tinygltf)

set(imgui ${FOLDLAB_IMGUI_SOURCE_DIR})
add_library(foldlab_imgui STATIC
  ${imgui}/imgui.cpp ${imgui}/imgui_draw.cpp ${imgui}/imgui_tables.cpp ${imgui}/imgui_widgets.cpp
  ${imgui}/backends/imgui_impl_glfw.cpp ${imgui}/backends/imgui_impl_opengl3.cpp)
target_include_directories(foldlab_imgui SYSTEM PUBLIC ${imgui})
# WebGL2 is OpenGL ES 3.0: the backend's ES3 path (VAOs, GLSL 300 es), not its default for
# emscripten, ES2.
target_compile_definitions(foldlab_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_link_libraries(foldlab_imgui PUBLIC glfw)
add_library(foldlab::imgui ALIAS foldlab_imgui)

add_library(glfw INTERFACE IMPORTED)
# A link setting only: emcc finds GLFW's header without it, and warns when a compile is given it.
set_target_properties(glfw PROPERTIES
  INTERFACE_LINK_OPTIONS "-sUSE_GLFW=3;-sMIN_WEBGL_VERSION=2;-sMAX_WEBGL_VERSION=2;-sFULL_ES3=1")
