#include "app/cli/field.hpp"

#include <filesystem>
#include <iostream>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/field/field_svg.hpp"
#include "core/io/io.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace field_command {
namespace {

using detail::printf_string;

std::string share_text(double share) {
  return printf_string("%.1f %%", 100.0 * share);
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "field",
      "solve the tension field of the hung cloth (Pipkin's relaxed membrane, Newton) and print "
      "its taut, wrinkled and slack shares, the supports' reactions and the rays beside the "
      "closed form's cosines");
  add_input_options(*command, options.inputs);
  app::add_field_cut_options(*command, options.cut);
  command->add_option("--cells-x", options.cells_x, "mesh cells across the cut (default 40)")
      ->transform(app::whole_number_in(1, 2000));
  command->add_option("--cells-y", options.cells_y, "mesh cells down the cut (default 28)")
      ->transform(app::whole_number_in(1, 2000));
  command
      ->add_option("--split", options.split,
                   "how a cell is cut into triangles: uniform, union-jack, crossed")
      ->check(app::one_of("split", {"uniform", "union-jack", "crossed"}));
  command
      ->add_option("--rays", options.rays,
                   "rays traced (default 8): from the centre line, or shared among the spans "
                   "between neighbouring top supports, at least 2 a span")
      ->transform(app::whole_number_in(0, 100));
  command
      ->add_option("--svg", options.svg_path,
                   "also draw the field: the hung cloth by region, the rays and the supports' "
                   "reactions")
      ->check(app::non_empty_path());
  command
      ->add_option("--budget-s", options.budget_s,
                   "stop the solve after S seconds and print the field as NOT converged with its "
                   "residual (default 60)")
      ->check(app::number_in(0.001, 86400.0));
  command->add_flag("--json", options.json, "print one JSON object instead of text");
}

Result run(const Options& options) {
  std::error_code not_a_folder;
  if (!options.svg_path.empty() && std::filesystem::is_directory(options.svg_path, not_a_folder)) {
    throw InputError("--svg " + detail::cut(options.svg_path) +
                     " is a folder; name the SVG file to write");
  }
  check_outputs({{"--svg", options.svg_path}},
                {app::preset_input("--preset", options.inputs.preset_path),
                 {"--outline", options.cut.outline_path}});
  app::check_output_extension("--svg", options.svg_path, ".svg", "SVG");
  Result r;
  r.preset = app::resolve_named_inputs(options.inputs);
  r.outline = app::read_field_cut(options.cut, r.preset, r.outline_name);
  r.resolution.cells_x = options.cells_x;
  r.resolution.cells_y = options.cells_y;
  field::parse_mesh_split(options.split, r.resolution.split);
  const bool preset_cut =
      options.cut.outline_path.empty() && r.preset.outline && options.cut.shape.empty();
  try {
    r.solved_outline = field::translated(r.outline, -field::solve_origin_mm(r.outline));
    field::Solver solver(field::make_mesh(r.solved_outline, r.resolution));
    r.nodes = static_cast<int>(solver.mesh().nodes_mm.size());
    r.triangles = static_cast<int>(solver.mesh().triangles.size());
    const field::Material material = field::material_of(r.preset.parameters.fabric);
    field::SolveOptions solve_options;
    solve_options.time_budget_ms = 1000.0 * options.budget_s;
    field::Solution solution =
        field::solve_cold(solver, r.solved_outline, material, r.resolution, solve_options);
    if (!(solution.weight_N > 0.0)) {
      throw field::OutlineError(printf_string(
          "the mesh of this cut weighs %g N: it has no area to hang (give it more cells)",
          solution.weight_N));
    }
    r.report =
        field::report_field(solver, std::move(solution), r.solved_outline, material, options.rays);
    r.mesh = solver.mesh();
    r.folds = field::field_folds(r.mesh, r.report.solution,
                                 field::support_targets(r.solved_outline), r.preset.parameters);
  } catch (const field::OutlineError& e) {
    throw InputError(std::string(preset_cut ? "/outline: " : "") + e.what());
  }
  // A cut of the preset's shape is the preset's cloth; one read from a file has its own h, L, d.
  Parameters closed = r.preset.parameters;
  const bool own_cut =
      !options.cut.outline_path.empty() || (r.preset.outline && options.cut.shape.empty());
  if (own_cut) {
    if (const std::optional<Parameters> of_cut = app::closed_form_of_cut(r.outline, closed)) {
      closed = *of_cut;
      r.closed_form_of_cut = true;
    }
  }
  r.closed_form_hanging = closed.hanging;
  r.closed_form = solve(closed);
  return r;
}

void print_text(const Result& r, std::ostream& out) {
  const field::Solution& s = r.report.solution;
  out << "Tension field of " << detail::escaped(r.preset.name) << "\n";
  out << "cut: " << r.outline_name << ", mesh " << r.resolution.cells_x << " x "
      << r.resolution.cells_y << " cells (" << field::to_string(r.resolution.split) << "), "
      << r.nodes << " nodes, " << r.triangles << " triangles\n";
  out << (s.converged ? "converged" : "NOT converged: the field below is the last iterate")
      << printf_string(": relative force residual %.2e after %d Newton iterations, %.1f ms\n",
                       s.relative_residual, s.iterations, s.solve_ms);
  out << printf_string("weight: %.6g N\n", s.weight_N);
  out << "regions (share of the cloth's area): taut " << share_text(s.taut_share);
  out << ", wrinkled " << share_text(s.wrinkled_share);
  out << ", slack " << share_text(s.slack_share);
  if (s.folded_share > 0.0) {
    out << "; turned over " << share_text(s.folded_share);
  }
  out << " (single slack triangles between tensed ones count with their neighbours; "
      << share_text(s.element_slack_share) << " of the area is in triangles slack on their own)\n";
  out << "supports (the force each exerts on the cloth; x right, y down):\n";
  for (std::size_t i = 0; i < r.outline.supports.size(); ++i) {
    const field::Support& sup = r.outline.supports[i];
    out << printf_string(
        "  %zu: at (%.1f, %.1f) mm, pinned at (%.1f, %.1f) mm: horizontal %+.6g N, vertical "
        "%+.6g N\n",
        i + 1, sup.at_mm.x(), sup.at_mm.y(), sup.to_mm.x(), sup.to_mm.y(), s.reactions_N[i].x(),
        s.reactions_N[i].y());
  }
  const std::vector<field::SpanReport>& spans = r.report.spans;
  if (spans.size() > 1) {
    out << "spans between neighbouring supports on the top edge: the horizontal force carried "
           "across each one's centre line beside its own cosine pencil's, w l² / pi² ln(a_0 / "
           "a_n):\n";
    for (std::size_t k = 0; k < spans.size(); ++k) {
      const field::SpanReport& sp = spans[k];
      out << printf_string(
          "  span %zu, supports %d-%d%s: thrust %.6g N, the cosine pencil %.6g N (l = %.1f mm, "
          "a_n = %.1f mm, a_0 = %.1f mm at its centre)\n",
          k + 1, sp.left_support + 1, sp.right_support + 1,
          static_cast<int>(k) == r.report.widest_span ? " (the widest)" : "", sp.thrust_N,
          sp.pencil_thrust_N, sp.span_mm, sp.centre_top_depth_mm, sp.centre_bottom_depth_mm);
    }
  } else if (r.report.span_mm > 0.0) {
    out << printf_string("thrust H: %.6g N; the cosine pencil through the supports: %.6g N",
                         r.report.thrust_N, r.report.pencil_thrust_N);
    out << printf_string(" (l = %.1f mm, a_n = %.1f mm, a_0 = %.1f mm at the centre)\n",
                         r.report.span_mm, r.report.centre_top_depth_mm,
                         r.report.centre_bottom_depth_mm);
  }
  if (!r.report.rays.empty()) {
    if (spans.size() > 1) {
      out << "rays from each span's centre line, each beside the cosine a cos(pi x / l) of its "
             "span fitted to it:\n";
    } else {
      out << "rays from the centre line, each beside the cosine a cos(pi x / l) fitted to it:\n";
    }
    for (const field::Ray& ray : r.report.rays) {
      out << printf_string("  %sat depth %.1f mm: fitted a = %.1f mm, rms distance %.1f mm\n",
                           spans.size() > 1 ? printf_string("span %d, ", ray.span + 1).c_str() : "",
                           ray.depth_mm, ray.fitted_amplitude_mm, ray.fit_rms_mm);
    }
  }
  const field::FieldFolds& f = r.folds;
  if (!s.converged) {
    out << "folds from the field: not read from a field that did not converge\n";
  } else {
    out << printf_string(
        "folds from the field (%s): n = %d, Q = %.4g, z_max = %.1f mm; the folds take up "
        "%.1f mm of the centre fibre's %.1f mm (mean ray tension %.3g N/mm)\n",
        r.outline.supports.size() > 2
            ? "along the centre line of the widest span between neighbouring supports"
            : "along the centre line",
        f.n, f.Q, f.z_max_mm, f.slack_width_mm, f.kept_length_mm, f.mean_ray_tension_N_per_mm);
    if (!f.a_mm.empty()) {
      out << "  a_i from the bottom up (mm):";
      for (double a : f.a_mm) {
        out << printf_string(" %.1f", a);
      }
      out << "\n";
    }
  }
  const Solution& c = r.closed_form;
  const Hanging& g = r.closed_form_hanging;
  out << printf_string(
      "folds from the closed form, for %s h = %.1f mm, L = %.1f mm, d = %.1f mm%s: n = %d, Q = "
      "%.4g, z_max = %.1f mm (%s)\n",
      r.closed_form_of_cut ? "the cut's" : "the preset's", g.height_mm, g.length_mm,
      g.support_displacement_mm,
      r.closed_form_of_cut
          ? " (its height midway between the supports, their distance as cut, how far they moved "
            "in)"
          : "",
      c.n, c.Q, c.z_max_mm, std::string(regime_info(c.regime).label).c_str());
}

nlohmann::json print_json(const Result& r) {
  const field::Solution& s = r.report.solution;
  nlohmann::json out;
  out["preset"] = detail::escaped(r.preset.name);
  out["outline"] = r.outline_name;
  out["mesh"] = {{"cells_x", r.resolution.cells_x},
                 {"cells_y", r.resolution.cells_y},
                 {"split", std::string(field::to_string(r.resolution.split))},
                 {"nodes", r.nodes},
                 {"triangles", r.triangles}};
  out["converged"] = s.converged;
  out["relative_residual"] = s.relative_residual;
  out["iterations"] = s.iterations;
  out["solve_ms"] = s.solve_ms;
  out["weight_N"] = s.weight_N;
  out["supports"] = nlohmann::json::array();
  for (std::size_t i = 0; i < r.outline.supports.size(); ++i) {
    const field::Support& sup = r.outline.supports[i];
    out["supports"].push_back({{"at_mm", {sup.at_mm.x(), sup.at_mm.y()}},
                               {"to_mm", {sup.to_mm.x(), sup.to_mm.y()}},
                               {"reaction_N", {s.reactions_N[i].x(), s.reactions_N[i].y()}}});
  }
  out["regions"] = {{"taut", s.taut_share},
                    {"wrinkled", s.wrinkled_share},
                    {"slack", s.slack_share},
                    {"turned_over", s.folded_share},
                    {"slack_triangles", s.element_slack_share}};
  out["thrust_N"] = r.report.thrust_N;
  out["pencil_thrust_N"] = r.report.pencil_thrust_N;
  out["span_mm"] = r.report.span_mm;
  out["rays"] = nlohmann::json::array();
  for (const field::Ray& ray : r.report.rays) {
    out["rays"].push_back({{"a_mm", ray.depth_mm},
                           {"fitted_a_mm", ray.fitted_amplitude_mm},
                           {"fit_rms_mm", ray.fit_rms_mm},
                           {"span", ray.span}});
  }
  out["spans"] = nlohmann::json::array();
  for (const field::SpanReport& sp : r.report.spans) {
    out["spans"].push_back({{"l_mm", sp.span_mm},
                            {"thrust_N", sp.thrust_N},
                            {"pencil_thrust_N", sp.pencil_thrust_N},
                            {"left_support", sp.left_support},
                            {"right_support", sp.right_support}});
  }
  out["field_folds"] = {{"n", r.folds.n},
                        {"Q", r.folds.Q},
                        {"z_max_mm", r.folds.z_max_mm},
                        {"a_mm", r.folds.a_mm},
                        {"slack_width_mm", r.folds.slack_width_mm},
                        {"kept_length_mm", r.folds.kept_length_mm},
                        {"count_argument", r.folds.count_argument},
                        {"mean_ray_tension_N_per_mm", r.folds.mean_ray_tension_N_per_mm},
                        {"n_capped", r.folds.n_capped}};
  // Folds read from a field that did not converge would be figures of no cloth: null.
  if (!s.converged) {
    out["field_folds"] = nullptr;
  }
  out["closed_form"] = {{"n", r.closed_form.n},
                        {"Q", r.closed_form.Q},
                        {"z_max_mm", r.closed_form.z_max_mm},
                        {"a_mm", r.closed_form.a_mm},
                        {"regime", std::string(regime_info(r.closed_form.regime).key)},
                        {"cloth", r.closed_form_of_cut ? "cut" : "preset"},
                        {"h_mm", r.closed_form_hanging.height_mm},
                        {"L_mm", r.closed_form_hanging.length_mm},
                        {"d_mm", r.closed_form_hanging.support_displacement_mm}};
  return out;
}

int execute(const Options& options) {
  const Result result = run(options);
  if (!options.svg_path.empty()) {
    write_file_atomically(options.svg_path,
                          field::field_to_svg(result.mesh, result.report, result.solved_outline,
                                              "Tension field, " + result.outline_name +
                                                  " cut: " + detail::escaped(result.preset.name)));
  }
  print_result(result, options.json, &print_text);
  return result.report.solution.converged ? kExitOk : kExitInternal;
}

}  // namespace field_command

Command add_field_command(CLI::App& app) {
  return make_command(app, field_command::declare, field_command::execute);
}

}  // namespace foldlab::cli
