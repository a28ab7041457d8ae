# Imported targets for the Debian 12 system packages FoldLab uses. Nothing here is downloaded:
# scripts/install-deps.sh installs the packages, this file only finds them.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
# glTF export: Debian builds tinygltf as a shared library (README.Debian), so no
# TINYGLTF_IMPLEMENTATION, stb or JSON defines are needed here.
find_package(TinyGLTF REQUIRED)

# stb (Debian's libstb-dev): reading the photo of `foldlab measure`, and the explorer's PNGs.
find_library(FOLDLAB_STB_LIBRARY stb REQUIRED)
find_path(FOLDLAB_STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb REQUIRED)
add_library(foldlab_stb UNKNOWN IMPORTED)
set_target_properties(foldlab_stb PROPERTIES
  IMPORTED_LOCATION ${FOLDLAB_STB_LIBRARY}
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${FOLDLAB_STB_INCLUDE_DIR}
  INTERFACE_INCLUDE_DIRECTORIES ${FOLDLAB_STB_INCLUDE_DIR})
add_library(foldlab::stb ALIAS foldlab_stb)

# The GUI: Dear ImGui 1.86 (static, with its GLFW and OpenGL3 backends inside libimgui.a), stb for
# PNG, GLFW for the window, libepoxy for our own GL calls, EGL for headless rendering.
if(FOLDLAB_BUILD_GUI)
  find_library(FOLDLAB_IMGUI_LIBRARY imgui REQUIRED)
  find_path(FOLDLAB_IMGUI_INCLUDE_DIR imgui.h PATH_SUFFIXES imgui REQUIRED)
  find_package(glfw3 3.3 REQUIRED)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(FOLDLAB_EPOXY REQUIRED IMPORTED_TARGET epoxy)
  pkg_check_modules(FOLDLAB_EGL REQUIRED IMPORTED_TARGET egl)

  add_library(foldlab_imgui UNKNOWN IMPORTED)
  set_target_properties(foldlab_imgui PROPERTIES
    IMPORTED_LOCATION ${FOLDLAB_IMGUI_LIBRARY}
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${FOLDLAB_IMGUI_INCLUDE_DIR}
    INTERFACE_INCLUDE_DIRECTORIES ${FOLDLAB_IMGUI_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES "foldlab::stb;glfw;${CMAKE_DL_LIBS}")
  add_library(foldlab::imgui ALIAS foldlab_imgui)
endif()
