// The files the cloth can be exported to, one row each: the command line's flag, the Export menu's
// item and the writer come from the same row, so a new format is one row here and its writer.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "core/geometry/geometry.hpp"
#include "core/io/export.hpp"
#include "core/io/gltf_export.hpp"

namespace foldlab {

// What a writer reads. Only what its format needs is set: `mesh` for a mesh format, `lines` and
// `solution` for a fold-line format, so that a caller builds no grid for an SVG alone.
struct ExportSource {
  const DeformedGrid* mesh = nullptr;
  const FoldLines* lines = nullptr;
  const Solution* solution = nullptr;
  std::string title;  // the fabric's name, written into the file where the format has a place
};

struct ExportFormat {
  enum class Content { mesh, fold_lines };
  std::string_view key;        // the command line's flag without "--"
  std::string_view extension;  // with its dot
  Content content;
  std::string_view what;  // help text and the menu item, e.g. "deformed mesh, Wavefront OBJ"
  std::string_view menu_label;
  std::string (*write)(const ExportSource&);
};

// Defined here, where its size is known to every user (the command line keeps a path per row).
inline constexpr auto kExportFormats = std::to_array<ExportFormat>({
    {"obj", ".obj", ExportFormat::Content::mesh, "deformed mesh, Wavefront OBJ", "OBJ mesh (.obj)",
     [](const ExportSource& s) { return mesh_to_obj(*s.mesh, s.title); }},
    {"glb", ".glb", ExportFormat::Content::mesh, "deformed mesh, binary glTF (metres, +Y up)",
     "glTF mesh (.glb)", [](const ExportSource& s) { return mesh_to_glb(*s.mesh, s.title); }},
    {"csv", ".csv", ExportFormat::Content::fold_lines, "fold lines as CSV", "Fold lines (.csv)",
     [](const ExportSource& s) { return fold_lines_to_csv(*s.lines); }},
    {"svg", ".svg", ExportFormat::Content::fold_lines, "fold lines as an SVG drawing",
     "Fold lines (.svg)",
     [](const ExportSource& s) { return fold_lines_to_svg(*s.lines, *s.solution, s.title); }},
});

}  // namespace foldlab
