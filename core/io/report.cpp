#include "core/io/report.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/geometry/rounded_folds.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

using detail::finite_or_throw;
using detail::printf_string;

std::string line(const char* label, const char* symbol, double value, const char* unit,
                 const char* format = "%.6g", const std::string& after = "") {
  finite_or_throw(value, *symbol != '\0' ? symbol : label);
  char number[64];
  std::snprintf(number, sizeof number, format, value);
  // Padded by characters as a terminal shows them, not by bytes: "ν²" is four bytes, two columns.
  const auto padded = [](const char* text, std::size_t width) {
    std::string out(text);
    std::size_t shown = 0;
    for (const unsigned char c : out) {
      shown += (c & 0xC0) != 0x80 ? 1 : 0;
    }
    out.append(shown < width ? width - shown : 0, ' ');
    return out;
  };
  char shown[96];
  std::snprintf(shown, sizeof shown, "%14s%s%s", number, *unit ? " " : "", unit);
  return "  " + padded(label, 34) + " " + padded(symbol, 6) + " " + shown + after + "\n";
}

// " (6–8)"; " (7–7)" says that the range was computed and is a single value.

}  // namespace

std::string range_text(double lo, double hi, const char* format) {
  return " (" + detail::printf_string(format, lo) + "–" + detail::printf_string(format, hi) + ")";
}

nlohmann::json solution_to_json(const Solution& s, const Parameters& p,
                                const ModelStanding* standing) {
  for (std::size_t i = 0; i < s.a_mm.size(); ++i) {
    finite_or_throw(s.a_mm[i], "a_mm[" + std::to_string(i) + "]");
  }
  nlohmann::json j = {
      {"method", to_string(s.method)},
      {"law", to_string(p.model.law)},
      {"regime", to_string(s.regime)},
      {"message", describe(s, p)},
      {"n", s.n},
      {"Q", finite_or_throw(s.Q, "Q")},
      {"Q7", s.Q7 ? nlohmann::json(finite_or_throw(*s.Q7, "Q7")) : nlohmann::json(nullptr)},
      {"fold_spacing_mm",
       s.count_rule && s.count_rule->spacing == FoldSpacing::even
           ? nlohmann::json(finite_or_throw(s.count_rule->step, "fold_spacing_mm"))
           : nlohmann::json(nullptr)},
      {"s", finite_or_throw(s.stress_ratio, "s")},
      {"z_max_mm", finite_or_throw(s.z_max_mm, "z_max_mm")},
      {"a_mm", s.a_mm},
      {"l_mm", finite_or_throw(s.span_mm, "l_mm")},
      {"A_mm", finite_or_throw(s.sag_amplitude_mm, "A_mm")},
      {"iterations", s.iterations},
      {"hit_iteration_cap", s.hit_iteration_cap},
      {"stopped_at_first_iterate", s.stopped_at_first_iterate},
      {"n_capped", s.n_capped},
      {"n_cycle", s.n_cycle},
      {"residual_length", finite_or_throw(s.residual_length, "residual_length")},
      {"residual_height", finite_or_throw(s.residual_height, "residual_height")},
      {"B_Nmm", finite_or_throw(bending_stiffness_Nmm(p.fabric), "B_Nmm")},
      {"c_b_mm", finite_or_throw(bending_length_mm(p.fabric), "c_b_mm")},
  };
  const FoldRounding rounding = fold_rounding(s, p);
  for (double radius_mm : rounding.radius_mm) {
    finite_or_throw(radius_mm, "rounded_folds.radius_mm");
  }
  j["rounded_folds"] = {
      {"rounded", rounding.rounded},
      {"radius_mm", rounding.radius_mm},
      {"depth_scale", finite_or_throw(rounding.depth_scale, "rounded_folds.depth_scale")},
      {"z_fold_mm", finite_or_throw(rounding.depth_scale * s.z_max_mm, "rounded_folds.z_fold_mm")},
      {"length_kept", rounding.length_kept},
  };
  if (standing != nullptr) {
    const auto& r = standing->range;
    auto pair = [&r](auto lo, auto hi) {
      return r ? nlohmann::json::array({*r.*lo, *r.*hi}) : nlohmann::json(nullptr);
    };
    j["form"] = standing->form;
    j["form_label"] = standing->label;
    j["n_range"] = pair(&PredictionRange::n_min, &PredictionRange::n_max);
    j["z_max_range_mm"] = pair(&PredictionRange::z_max_min_mm, &PredictionRange::z_max_max_mm);
    j["Q_range"] = pair(&PredictionRange::Q_min, &PredictionRange::Q_max);
    j["range_basis"] = standing->range_basis;
    j["interval_level"] = r ? nlohmann::json(r->level) : nlohmann::json(nullptr);
    j["interval_basis"] = standing->range_basis;
  }
  nlohmann::json& inputs = j["inputs"];
  for (const InputSpec& spec : input_table()) {
    // The preset's key for what a preset stores, the --set key for K (derived from c and nu).
    const std::string_view name =
        spec.preset.empty() ? spec.key : spec.preset.substr(spec.preset.rfind('/') + 1);
    if (spec.kind == InputKind::choice) {
      inputs[std::string(name)] = spec.choice(p);
    } else {
      inputs[std::string(name)] = finite_or_throw(*spec.value(p), name);
    }
  }
  return j;
}

namespace {

// The cloth's inputs and K; p only for the calibrated variant, so that the paper's form reads as
// before.
std::string input_lines(const Parameters& p) {
  std::string out;
  for (const InputSpec& spec : input_table()) {
    const bool cloth = spec.preset.starts_with("/fabric/") || spec.preset.starts_with("/hanging/");
    const bool shown = cloth || spec.key == "K" || (spec.key == "p" && *spec.value(p) != 1.0);
    if (shown) {
      out += line(std::string(spec.name).c_str(), std::string(spec.key).c_str(), *spec.value(p),
                  std::string(spec.unit).c_str());
    }
  }
  out += "  span rule l = " + std::string(to_string(p.model.span_rule)) +
         ", Int[] of eq. 10 = " + std::string(to_string(p.model.int_rounding)) + "\n";
  return out;
}

// n, Q, eq. 7's root (or the spacing that stands in for it), s and z_max, with the prediction
// interval where the standing has one.
std::string prediction_lines(const Solution& s, const ModelStanding* standing) {
  const PredictionRange* range =
      standing != nullptr && standing->range ? &*standing->range : nullptr;
  auto in_range = [range](auto lo, auto hi, const char* format) {
    return range != nullptr ? range_text(static_cast<double>(range->*lo),
                                         static_cast<double>(range->*hi), format)
                            : std::string();
  };
  std::string out = line("number of wrinkles", "n", s.n, "", "%.0f",
                         in_range(&PredictionRange::n_min, &PredictionRange::n_max, "%.0f") +
                             (s.n_capped ? " (capped: eq. 10 asks for more)" : ""));
  out += line("amplitude ratio (a_0/a_n)^(1/n)", "Q", s.Q, "", "%.6g",
              in_range(&PredictionRange::Q_min, &PredictionRange::Q_max, "%.4f"));
  if (s.Q7) {
    out += line("root of eq. 7", "Q7", *s.Q7, "");
  } else if (s.count_rule && s.count_rule->spacing == FoldSpacing::even) {
    out += line("fold spacing (wavelength)", "lambda", s.count_rule->step, "mm", "%.2f");
  } else {
    out += "  root of eq. 7                      Q7               none (s >= 1)\n";
  }
  out += line("stress ratio of eq. 7", "s", s.stress_ratio, "");
  out += line("out-of-plane depth", "z_max", s.z_max_mm, "mm", "%.2f",
              in_range(&PredictionRange::z_max_min_mm, &PredictionRange::z_max_max_mm, "%.1f"));
  if (standing != nullptr) {
    out += standing->range ? detail::printf_string("  %.0f %% prediction interval: ",
                                                   100.0 * standing->range->level)
                           : std::string("  interval: ");
    out += standing->range_basis + "\n";
  }
  return out;
}

// The span, the sag, the cloth's bending and, where the folds are rounded, their crests.
std::string shape_lines(const Solution& s, const Parameters& p) {
  std::string out = line("span between supports", "l", s.span_mm, "mm", "%.2f");
  out += line("sag of the upper edge", "A", s.sag_amplitude_mm, "mm", "%.2f");
  out += line("bending stiffness Et³/12(1-ν²)", "B", bending_stiffness_Nmm(p.fabric), "N mm");
  out += line("bending length (B/w)^(1/3)", "c_b", bending_length_mm(p.fabric), "mm", "%.2f");
  if (const FoldRounding rounding = fold_rounding(s, p); rounding.rounded) {
    const auto [smallest, largest] =
        std::minmax_element(rounding.radius_mm.begin(), rounding.radius_mm.end());
    out += line("crest radius (at most c_b), min", "R", *smallest, "mm", "%.2f");
    out += line("crest radius (at most c_b), max", "R", *largest, "mm", "%.2f");
    out += line(
        "rounded fold depth", "z_fold", rounding.depth_scale * s.z_max_mm,
        printf_string("mm (%.2f %% below z_max)", 100.0 * (1.0 - rounding.depth_scale)).c_str(),
        "%.2f");
  }
  return out;
}

std::string convergence_lines(const Solution& s) {
  std::string out = line("iterations", "", s.iterations, "", "%.0f");
  out += line("residual of eq. 8, L'/L - 1", "", s.residual_length, "", "%.3e");
  out += line("residual of eq. 9, fibre/h - 1", "", s.residual_height, "", "%.3e");
  return out;
}

// The first 40 amplitudes, four to a line.
std::string amplitude_lines(const Solution& s) {
  if (s.a_mm.empty()) {
    return "";
  }
  std::string out = "\n  fold amplitudes a_i (mm), i = 0 (lower boundary) .. n (upper edge):\n";
  const std::size_t shown = std::min<std::size_t>(s.a_mm.size(), 40);
  for (std::size_t i = 0; i < shown; ++i) {
    finite_or_throw(s.a_mm[i], "a_" + std::to_string(i));
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
  return out;
}

}  // namespace

std::string solution_table(const Solution& s, const Parameters& p, const std::string& preset_name,
                           const ModelStanding* standing) {
  std::string out = "FoldLab: " + std::string(to_string(s.method)) + " method, " +
                    std::string(wrinkle_law(p.model.law).title());
  if (!preset_name.empty()) {
    out += ", preset \"" + detail::escaped(preset_name) + "\"";
  }
  out += "\n\nInputs\n" + input_lines(p);
  if (standing != nullptr) {
    out += "  form of eq. 7: " + standing->form + ", " + standing->label + "\n";
  }
  out += "\nResult: " + std::string(to_string(s.regime)) + "\n";
  if (const std::string message = describe(s, p); !message.empty()) {
    out += "  " + message + "\n";
  }
  out += prediction_lines(s, standing);
  out += shape_lines(s, p);
  out += convergence_lines(s);
  out += amplitude_lines(s);
  return out;
}

}  // namespace foldlab
