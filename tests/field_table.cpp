// The closed form against the tension field, as the Markdown table of docs/field.md: for each
// preset given, n, Q, z_max and a_n as the paper measured them (when the preset carries them),
// as the closed form solves them and as the field of the rectangle and of the cosine cut gives
// them (core/field/field_folds), with the fields' solve times. Not a test: a tool run by hand
// (docs/field.md says how), since its numbers are reported as they come out, not judged.
//   build/tests/foldlab_field_table [--cells N] PRESET.json ...
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "core/field/field_case.hpp"
#include "core/field/field_folds.hpp"
#include "core/io/preset.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace {

using foldlab::detail::printf_string;

template <class T>
std::string published(const std::optional<T>& value, const char* format) {
  return value ? printf_string(format, *value) : std::string("–");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace foldlab;
  int cells = 40;
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--cells" && i + 1 < argc) {
      cells = std::atoi(argv[++i]);
    } else {
      paths.push_back(arg);
    }
  }
  if (paths.empty() || cells < 2) {
    std::cerr << "usage: foldlab_field_table [--cells N] PRESET.json ...\n";
    return 2;
  }
  std::cout << "| preset | n: paper / closed / rect. / cos. | Q: paper / closed / rect. / cos. | "
               "z_max mm: paper / closed / rect. / cos. | a_n mm: closed / rect. / cos. | field "
               "ms: rect. / cos. |\n";
  std::cout << "|---|---|---|---|---|---|\n";
  for (const std::string& path : paths) {
    const Preset preset = load_preset(path);
    const Parameters& p = preset.parameters;
    const Solution closed = solve(p);
    const PublishedResult& paper = preset.published;
    std::string n = published(paper.n, "%d") + printf_string(" / %d", closed.n);
    std::string Q = published(paper.Q, "%.2f") + printf_string(" / %.2f", closed.Q);
    std::string z = published(paper.z_max_mm, "%.0f") + printf_string(" / %.0f", closed.z_max_mm);
    std::string a = printf_string("%.0f", closed.a_mm.empty() ? 0.0 : closed.a_mm.back());
    std::string ms;
    // Conci's experiment hung a rectangle from its top corners; the closed form idealises it as
    // the cosine membrane: the field of each.
    for (field::OutlineKind kind : {field::OutlineKind::rectangular, field::OutlineKind::cosine}) {
      const field::Outline outline = field::make_outline(p, kind);
      const field::MeshResolution resolution{cells, cells * 7 / 10, field::MeshSplit::union_jack};
      field::Solver solver(field::make_mesh(outline, resolution));
      const field::Solution solution =
          field::solve_cold(solver, outline, field::material_of(p.fabric), resolution);
      const field::FieldFolds folds =
          field::field_folds(solver.mesh(), solution, field::support_targets(outline), p);
      const char* mark = solution.converged ? "" : " (not converged)";
      n += printf_string(" / %d%s", folds.n, mark);
      Q += printf_string(" / %.2f", folds.Q);
      z += printf_string(" / %.0f", folds.z_max_mm);
      a += printf_string(" / %.0f", folds.a_mm.empty() ? 0.0 : folds.a_mm.back());
      ms += printf_string("%s%.0f", ms.empty() ? "" : " / ", solution.solve_ms);
    }
    std::cout << "| " << detail::markdown_cell(preset.name) << " | " << n << " | " << Q << " | "
              << z << " | " << a << " | " << ms << " |\n";
  }
  return 0;
}
