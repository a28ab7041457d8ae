// `foldlab field`: the tension field of one hung cloth, solved and printed as text or JSON — the
// regions' shares, each support's reaction, the weight, the rays beside the closed form's cosines,
// and how the solve went.
#pragma once

#include <ostream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/common/field_cut.hpp"
#include "app/common/inputs.hpp"
#include "core/field/field_case.hpp"
#include "core/field/field_folds.hpp"
#include "core/io/preset.hpp"
#include "core/model/solver.hpp"

namespace foldlab::cli::field_command {

struct Options {
  app::InputOptions inputs;
  app::FieldCutOptions cut;
  int cells_x = field::MeshResolution{}.cells_x;
  int cells_y = field::MeshResolution{}.cells_y;
  std::string split = std::string(field::to_string(field::MeshResolution{}.split));
  int rays = field::kDefaultRayCount;
  std::string svg_path;  // empty: no drawing
  bool json = false;
  double budget_s = 60.0;  // the solve stops after this long, not converged
};

struct Result {
  Preset preset;
  std::string outline_name;  // the shape's name or the outline file
  field::Outline outline;
  field::MeshResolution resolution;
  // The cut moved by -field::solve_origin_mm: the mesh, the field and the rays are in its frame,
  // so that where the cut sits changes nothing; the supports are printed where `outline` has them.
  field::Outline solved_outline;
  int nodes = 0;
  int triangles = 0;
  field::Mesh mesh;  // the mesh the field was solved on, for the drawing
  field::FieldReport report;
  field::FieldFolds folds;  // n, Q, z_max and a_i from the field
  // The same from the closed form: for the cut's own h, L and d when it is a cloth hung from two
  // supports on its top edge read from a file, else for the preset's.
  Solution closed_form;
  Hanging closed_form_hanging;
  bool closed_form_of_cut = false;
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for inputs, a shape or an outline the solver refuses, and for an --svg
// that cannot be written (checked before the solve).
Result run(const Options& options);
void print_text(const Result& result, std::ostream& out);
nlohmann::json print_json(const Result& result);
// Exit 0 when the field converged, 1 when it did not (printed and drawn all the same, marked so).
int execute(const Options& options);

}  // namespace foldlab::cli::field_command
