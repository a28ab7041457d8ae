#include "core/io/export_formats.hpp"

#include "core/io/export.hpp"
#include "core/io/gltf_export.hpp"

namespace foldlab {

const std::array<ExportFormat, 4> kExportFormats = {{
    {"obj", ".obj", ExportFormat::Content::mesh, "deformed mesh, Wavefront OBJ", "OBJ mesh (.obj)",
     [](const ExportSource& s) { return mesh_to_obj(*s.mesh, s.title); }},
    {"glb", ".glb", ExportFormat::Content::mesh, "deformed mesh, binary glTF (metres, +Y up)",
     "glTF mesh (.glb)", [](const ExportSource& s) { return mesh_to_glb(*s.mesh, s.title); }},
    {"csv", ".csv", ExportFormat::Content::fold_lines, "fold lines as CSV", "Fold lines (.csv)",
     [](const ExportSource& s) { return fold_lines_to_csv(*s.lines); }},
    {"svg", ".svg", ExportFormat::Content::fold_lines, "fold lines as an SVG drawing",
     "Fold lines (.svg)",
     [](const ExportSource& s) { return fold_lines_to_svg(*s.lines, *s.solution, s.title); }},
}};

}  // namespace foldlab
