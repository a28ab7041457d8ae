// The files the cloth can be exported to, one row each: the command line's flag, the Export menu's
// item and the writer come from the same row, so a new format is one row here and its writer.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "core/geometry/geometry.hpp"

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

extern const std::array<ExportFormat, 4> kExportFormats;

}  // namespace foldlab
