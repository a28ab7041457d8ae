#include "foldlab/report.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

namespace foldlab {
namespace {

std::string line(const char* label, const char* symbol, double value, const char* unit,
                 const char* format = "%.6g") {
  char number[64];
  std::snprintf(number, sizeof number, format, value);
  char out[160];
  std::snprintf(out, sizeof out, "  %-34s %-6s %14s%s%s\n", label, symbol, number, *unit ? " " : "",
                unit);
  return out;
}

}  // namespace

nlohmann::json solution_to_json(const Solution& s, const Parameters& p) {
  nlohmann::json j = {
      {"method", to_string(s.method)},
      {"regime", to_string(s.regime)},
      {"message", describe(s, p)},
      {"n", s.n},
      {"Q", s.Q},
      {"Q7", s.Q7 ? nlohmann::json(*s.Q7) : nlohmann::json(nullptr)},
      {"s", s.stress_ratio},
      {"z_max_mm", s.z_max_mm},
      {"a_mm", s.a_mm},
      {"l_mm", s.span_mm},
      {"A_mm", s.sag_amplitude_mm},
      {"iterations", s.iterations},
      {"hit_iteration_cap", s.hit_iteration_cap},
      {"n_capped", s.n_capped},
      {"n_cycle", s.n_cycle},
      {"residual_length", s.residual_length},
      {"residual_height", s.residual_height},
      {"inputs",
       {{"thickness_mm", p.fabric.thickness_mm},
        {"youngs_modulus_MPa", p.fabric.youngs_modulus_MPa},
        {"weight_N_per_mm2", p.fabric.weight_N_per_mm2},
        {"poisson_ratio", p.fabric.poisson_ratio},
        {"height_mm", p.hanging.height_mm},
        {"length_mm", p.hanging.length_mm},
        {"support_displacement_mm", p.hanging.support_displacement_mm},
        {"load_constant_c", p.model.load_constant_c},
        {"K", stiffness_constant_K(p)},
        {"stress_exponent_p", p.model.stress_exponent_p},
        {"span_rule", to_string(p.model.span_rule)},
        {"int_rounding", to_string(p.model.int_rounding)}}},
  };
  return j;
}

std::string solution_table(const Solution& s, const Parameters& p, const std::string& preset_name) {
  std::string out = "FoldLab: " + std::string(to_string(s.method)) + " method";
  if (!preset_name.empty()) {
    out += ", preset \"" + preset_name + "\"";
  }
  out += "\n\nInputs\n";
  out += line("thickness", "t", p.fabric.thickness_mm, "mm");
  out += line("Young's modulus", "E", p.fabric.youngs_modulus_MPa, "MPa");
  out += line("weight per area", "w", p.fabric.weight_N_per_mm2, "N/mm²");
  out += line("Poisson's ratio", "nu", p.fabric.poisson_ratio, "");
  out += line("height", "h", p.hanging.height_mm, "mm");
  out += line("upper edge length", "L", p.hanging.length_mm, "mm");
  out += line("support displacement", "d", p.hanging.support_displacement_mm, "mm");
  out += line("eq. 7 constant c/(1-nu^2)", "K", stiffness_constant_K(p), "");
  if (p.model.stress_exponent_p != 1.0) {
    // Only the calibrated variant prints its exponent: the paper's form reads as before.
    out += line("eq. 7 exponent, s -> s^p", "p", p.model.stress_exponent_p, "");
  }
  out += "  span rule l = " + std::string(to_string(p.model.span_rule)) +
         ", Int[] of eq. 10 = " + std::string(to_string(p.model.int_rounding)) + "\n";

  out += "\nResult: " + std::string(to_string(s.regime)) + "\n";
  if (const std::string message = describe(s, p); !message.empty()) {
    out += "  " + message + "\n";
  }
  out += line("number of wrinkles", "n", s.n, "", "%.0f");
  out += line("amplitude ratio (a_0/a_n)^(1/n)", "Q", s.Q, "");
  if (s.Q7) {
    out += line("root of eq. 7", "Q7", *s.Q7, "");
  } else {
    out += "  root of eq. 7                      Q7               none (s >= 1)\n";
  }
  out += line("stress ratio of eq. 7", "s", s.stress_ratio, "");
  out += line("out-of-plane depth", "z_max", s.z_max_mm, "mm", "%.2f");
  out += line("span between supports", "l", s.span_mm, "mm", "%.2f");
  out += line("sag of the upper edge", "A", s.sag_amplitude_mm, "mm", "%.2f");
  out += line("iterations", "", s.iterations, "", "%.0f");
  out += line("residual of eq. 8, L'/L - 1", "", s.residual_length, "", "%.3e");
  out += line("residual of eq. 9, fibre/h - 1", "", s.residual_height, "", "%.3e");
  if (!s.a_mm.empty()) {
    out += "\n  fold amplitudes a_i (mm), i = 0 (lower boundary) .. n (upper edge):\n";
    const std::size_t shown = std::min<std::size_t>(s.a_mm.size(), 40);
    for (std::size_t i = 0; i < shown; ++i) {
      char cell[48];
      std::snprintf(cell, sizeof cell, "    a_%-3zu %10.2f%s", i, s.a_mm[i],
                    (i % 4 == 3) ? "\n" : "");
      out += cell;
    }
    if (shown % 4 != 0) {
      out += "\n";
    }
    if (shown < s.a_mm.size()) {
      out += "    ... " + std::to_string(s.a_mm.size() - shown) + " more (see --json)\n";
    }
  }
  return out;
}

}  // namespace foldlab
