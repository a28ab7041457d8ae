#include "foldlab/preset.hpp"

#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "default_preset_text.hpp"
#include "foldlab/io.hpp"
#include "text_format.hpp"

namespace foldlab {
namespace {

using nlohmann::json;

// The JSON key of each validated field, so that a range error names the key in the file.
const char* json_pointer_for(const std::string& field) {
  static const std::pair<const char*, const char*> table[] = {
      {"t_mm", "/fabric/thickness_mm"},
      {"E_MPa", "/fabric/youngs_modulus_MPa"},
      {"w_N_per_mm2", "/fabric/weight_N_per_mm2"},
      {"nu", "/fabric/poisson_ratio"},
      {"h_mm", "/hanging/height_mm"},
      {"L_mm", "/hanging/length_mm"},
      {"d_mm", "/hanging/support_displacement_mm"},
      {"c", "/model/load_constant_c"},
      {"p", "/model/stress_exponent_p"},
      {"simpson_intervals", "/model/simpson_intervals"},
      {"length_tolerance", "/model/length_tolerance"},
      {"max_iterations", "/model/max_iterations"},
      {"supports", "/shape/supports"},
      {"incline_deg", "/shape/incline_deg"},
  };
  for (const auto& [name, pointer] : table) {
    if (field == name) {
      return pointer;
    }
  }
  return "";
}

std::string type_name(const json& v) {
  return v.is_null() ? "null" : v.type_name();
}

// Reads one object's fields, collecting every problem instead of stopping at the first.
class Reader {
 public:
  Reader(std::string origin, std::vector<std::string>& problems)
      : origin_(std::move(origin)), problems_(problems) {}

  void problem(const std::string& pointer, const std::string& what) {
    problems_.push_back(origin_ + ": " + pointer + ": " + what);
  }

  // Checks that `object` is an object whose keys are all in `allowed`.
  bool object(const json& object, const std::string& pointer,
              std::initializer_list<const char*> allowed) {
    if (!object.is_object()) {
      problem(pointer.empty() ? "/" : pointer, "expected an object, got " + type_name(object));
      return false;
    }
    for (const auto& [key, value] : object.items()) {
      bool known = false;
      for (const char* a : allowed) {
        known = known || key == a;
      }
      if (!known) {
        std::string list;
        for (const char* a : allowed) {
          list += (list.empty() ? "" : ", ") + std::string(a);
        }
        problem(pointer + "/" + key, "unknown key (allowed here: " + list + ")");
      }
    }
    return true;
  }

  void number(const json& object, const std::string& pointer, const char* key, double& out,
              bool required) {
    const std::string at = pointer + "/" + key;
    if (!object.contains(key)) {
      if (required) {
        problem(at, "missing (a number is required)");
      }
      return;
    }
    const json& v = object.at(key);
    if (!v.is_number()) {
      problem(at, "expected a number, got " + type_name(v) + " " + v.dump());
      return;
    }
    out = v.get<double>();
  }

  void integer(const json& object, const std::string& pointer, const char* key, int& out) {
    if (!object.contains(key)) {
      return;
    }
    const json& v = object.at(key);
    if (!v.is_number_integer()) {
      problem(pointer + "/" + key, "expected a whole number, got " + type_name(v) + " " + v.dump());
      return;
    }
    // Unsigned values above 2^63 - 1 would wrap in get<long long>(): range-check them first.
    const bool too_large = v.is_number_unsigned() && v.get<unsigned long long>() > 1'000'000'000ULL;
    const auto value = too_large ? 0LL : v.get<long long>();
    if (too_large || value < -1'000'000'000LL || value > 1'000'000'000LL) {
      problem(pointer + "/" + key, "whole number " + v.dump() + " is out of range");
      return;
    }
    out = static_cast<int>(value);
  }

  void text(const json& object, const std::string& pointer, const char* key, std::string& out,
            bool required) {
    const std::string at = pointer + "/" + key;
    if (!object.contains(key)) {
      if (required) {
        problem(at, "missing (a string is required)");
      }
      return;
    }
    const json& v = object.at(key);
    if (!v.is_string()) {
      problem(at, "expected a string, got " + type_name(v) + " " + v.dump());
      return;
    }
    out = v.get<std::string>();
  }

  template <class Enum>
  void named(const json& object, const std::string& pointer, const char* key, Enum& out,
             bool (*parse)(std::string_view, Enum&), const char* allowed) {
    std::string value;
    if (!object.contains(key)) {
      return;
    }
    const std::size_t before = problems_.size();
    text(object, pointer, key, value, false);
    if (problems_.size() == before && !parse(value, out)) {
      problem(pointer + "/" + key, "\"" + value + "\" is not one of: " + allowed);
    }
  }

 private:
  std::string origin_;
  std::vector<std::string>& problems_;
};

using detail::join_lines;

}  // namespace

Preset preset_from_json(const json& j, const std::string& origin) {
  std::vector<std::string> problems;
  Reader r(origin, problems);
  Preset preset;
  if (!r.object(j, "",
                {"foldlab_preset", "name", "description", "source", "fabric", "hanging", "model",
                 "shape", "published"})) {
    throw PresetError(join_lines(problems));
  }
  if (!j.contains("foldlab_preset")) {
    r.problem("/foldlab_preset", "missing: not a FoldLab preset (expected \"foldlab_preset\": " +
                                     std::to_string(kPresetFormatVersion) + ")");
  } else if (!j.at("foldlab_preset").is_number_integer() ||
             j.at("foldlab_preset").get<long long>() != kPresetFormatVersion) {
    r.problem("/foldlab_preset", "format version " + j.at("foldlab_preset").dump() +
                                     " is not supported (this FoldLab reads version " +
                                     std::to_string(kPresetFormatVersion) + ")");
  }
  r.text(j, "", "name", preset.name, true);
  r.text(j, "", "description", preset.description, false);
  r.text(j, "", "source", preset.source, false);

  Parameters& p = preset.parameters;
  if (!j.contains("fabric")) {
    r.problem("/fabric", "missing (an object with thickness_mm, youngs_modulus_MPa, ...)");
  } else if (const json& f = j.at("fabric"); r.object(
                 f, "/fabric",
                 {"thickness_mm", "youngs_modulus_MPa", "weight_N_per_mm2", "poisson_ratio"})) {
    r.number(f, "/fabric", "thickness_mm", p.fabric.thickness_mm, true);
    r.number(f, "/fabric", "youngs_modulus_MPa", p.fabric.youngs_modulus_MPa, true);
    r.number(f, "/fabric", "weight_N_per_mm2", p.fabric.weight_N_per_mm2, true);
    r.number(f, "/fabric", "poisson_ratio", p.fabric.poisson_ratio, false);
  }
  if (!j.contains("hanging")) {
    r.problem("/hanging", "missing (an object with height_mm, length_mm, support_displacement_mm)");
  } else if (const json& g = j.at("hanging");
             r.object(g, "/hanging", {"height_mm", "length_mm", "support_displacement_mm"})) {
    r.number(g, "/hanging", "height_mm", p.hanging.height_mm, true);
    r.number(g, "/hanging", "length_mm", p.hanging.length_mm, true);
    r.number(g, "/hanging", "support_displacement_mm", p.hanging.support_displacement_mm, true);
  }
  if (j.contains("model")) {
    const json& m = j.at("model");
    if (r.object(
            m, "/model",
            {"method", "load_constant_c", "span_rule", "int_rounding", "simpson_intervals",
             "length_tolerance", "max_iterations", "length_quadrature", "stress_exponent_p"})) {
      r.named(m, "/model", "method", p.model.method, &parse_method, "paper, exact");
      r.number(m, "/model", "load_constant_c", p.model.load_constant_c, false);
      r.named(m, "/model", "span_rule", p.model.span_rule, &parse_span_rule, "L-d, L-2d");
      r.named(m, "/model", "int_rounding", p.model.int_rounding, &parse_int_rounding,
              "nearest, floor");
      r.integer(m, "/model", "simpson_intervals", p.model.simpson_intervals);
      r.number(m, "/model", "length_tolerance", p.model.length_tolerance, false);
      r.integer(m, "/model", "max_iterations", p.model.max_iterations);
      r.named(m, "/model", "length_quadrature", p.model.length_quadrature, &parse_length_quadrature,
              "simpson, trapezoid");
      r.number(m, "/model", "stress_exponent_p", p.model.stress_exponent_p, false);
    }
  }
  if (j.contains("shape")) {
    const json& sh = j.at("shape");
    if (r.object(sh, "/shape", {"kind", "supports", "incline_deg"})) {
      r.named(sh, "/shape", "kind", p.shape.kind, &parse_shape_kind,
              "cosine, rectangular, strip, inclined");
      r.integer(sh, "/shape", "supports", p.shape.supports);
      r.number(sh, "/shape", "incline_deg", p.shape.incline_deg, false);
    }
  }
  if (j.contains("published")) {
    const json& pub = j.at("published");
    if (r.object(pub, "/published", {"n", "z_max_mm", "Q"})) {
      int n = 0;
      double z = 0.0;
      double Q = 0.0;
      const std::size_t before = problems.size();
      if (pub.contains("n")) {
        r.integer(pub, "/published", "n", n);
        preset.published.n = n;
      }
      if (pub.contains("z_max_mm")) {
        r.number(pub, "/published", "z_max_mm", z, false);
        preset.published.z_max_mm = z;
      }
      if (pub.contains("Q")) {
        r.number(pub, "/published", "Q", Q, false);
        preset.published.Q = Q;
      }
      if (preset.published.n && *preset.published.n < 0) {
        r.problem("/published/n", "a number of wrinkles is >= 0");
      }
      if (preset.published.z_max_mm && !(*preset.published.z_max_mm >= 0.0)) {
        r.problem("/published/z_max_mm", "an out-of-plane depth is >= 0");
      }
      if (preset.published.Q && !(*preset.published.Q > 1.0)) {
        r.problem("/published/Q",
                  "a ratio of consecutive amplitudes is > 1 (leave out a misprint)");
      }
      if (problems.size() != before) {
        preset.published = {};
      }
    }
  }
  if (problems.empty()) {
    for (const ValidationIssue& issue : validate(p)) {
      r.problem(json_pointer_for(issue.field), issue.message);
    }
  }
  if (!problems.empty()) {
    throw PresetError(join_lines(problems));
  }
  return preset;
}

Preset preset_from_text(const std::string& text, const std::string& origin) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    // parse_error, and out_of_range for a number no double holds (e.g. 1e400).
    throw PresetError(origin + ": not valid JSON: " + e.what());
  }
  return preset_from_json(j, origin);
}

json preset_to_json(const Preset& preset) {
  const Parameters& p = preset.parameters;
  json j = {
      {"foldlab_preset", kPresetFormatVersion},
      {"name", preset.name},
      {"description", preset.description},
      {"source", preset.source},
      {"fabric",
       {{"thickness_mm", p.fabric.thickness_mm},
        {"youngs_modulus_MPa", p.fabric.youngs_modulus_MPa},
        {"weight_N_per_mm2", p.fabric.weight_N_per_mm2},
        {"poisson_ratio", p.fabric.poisson_ratio}}},
      {"hanging",
       {{"height_mm", p.hanging.height_mm},
        {"length_mm", p.hanging.length_mm},
        {"support_displacement_mm", p.hanging.support_displacement_mm}}},
      {"model",
       {{"method", to_string(p.model.method)},
        {"load_constant_c", p.model.load_constant_c},
        {"span_rule", to_string(p.model.span_rule)},
        {"int_rounding", to_string(p.model.int_rounding)},
        {"simpson_intervals", p.model.simpson_intervals},
        {"length_tolerance", p.model.length_tolerance},
        {"max_iterations", p.model.max_iterations},
        {"length_quadrature", to_string(p.model.length_quadrature)},
        {"stress_exponent_p", p.model.stress_exponent_p}}},
      {"shape",
       {{"kind", to_string(p.shape.kind)},
        {"supports", p.shape.supports},
        {"incline_deg", p.shape.incline_deg}}},
  };
  json published = json::object();
  if (preset.published.n)
    published["n"] = *preset.published.n;
  if (preset.published.z_max_mm)
    published["z_max_mm"] = *preset.published.z_max_mm;
  if (preset.published.Q)
    published["Q"] = *preset.published.Q;
  if (!published.empty()) {
    j["published"] = published;
  }
  return j;
}

Preset load_preset(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_text_file(path);
  } catch (const ReadError& e) {
    throw PresetError(e.what());
  }
  return preset_from_text(text, path.string());
}

void save_preset(const Preset& preset, const std::filesystem::path& path) {
  if (const auto issues = validate(preset.parameters); !issues.empty()) {
    throw PresetError(path.string() + ": not saved: " + format_issues(issues));
  }
  try {
    write_file_atomically(path, preset_to_json(preset).dump(2) + "\n");
  } catch (const WriteError& e) {
    throw PresetError(e.what());
  }
}

const Preset& default_preset() {
  static const Preset preset = preset_from_text(kDefaultPresetText, kDefaultPresetOrigin);
  return preset;
}

}  // namespace foldlab
