// libFuzzer target for the export writers given a preset's name, which is the user's text: any
// bytes must leave an OBJ with exactly its vertices (a line break in the name once added one) and
// an SVG with no control character and valid UTF-8 (XML refuses both).
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target export_names with the
// shipped presets as the seed corpus.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/io/export.hpp"
#include "core/model/text_format.hpp"

namespace {

// A 2 x 2 grid: the writers need no solve to show where a name ends up.
foldlab::DeformedGrid small_grid() {
  foldlab::DeformedGrid grid;
  grid.nx = 2;
  grid.ny = 2;
  grid.positions_mm = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  grid.material_mm = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  grid.normals.assign(4, Eigen::Vector3f(0, 0, 1));
  grid.triangle_indices = {0, 1, 2, 1, 3, 2};
  return grid;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string name(reinterpret_cast<const char*>(data), size);
  static const foldlab::DeformedGrid grid = small_grid();
  const std::string obj = foldlab::mesh_to_obj(grid, name);
  std::istringstream lines(obj);
  int vertices = 0;
  for (std::string line; std::getline(lines, line);) {
    vertices += line.starts_with("v ") ? 1 : 0;
  }
  if (vertices != 4) {
    std::abort();  // the name started a statement of its own
  }
  foldlab::Solution solution;
  solution.n = 1;
  solution.Q = 2.0;
  solution.span_mm = 100.0;
  solution.z_max_mm = 5.0;
  solution.a_mm = {10.0, 5.0};
  const std::string svg = foldlab::fold_lines_to_svg(foldlab::FoldLines{}, solution, name);
  if (std::any_of(svg.begin(), svg.end(),
                  [](char c) {
                    const auto b = static_cast<unsigned char>(c);
                    return (b < 0x20 && c != '\n') || b == 0x7F;
                  }) ||
      !foldlab::detail::is_valid_utf8(svg)) {
    std::abort();  // not XML
  }
  return 0;
}
