#include "core/io/preset.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/io.hpp"
#include "core/io/json_input.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"
#include "default_preset_text.hpp"

namespace foldlab {
namespace {

using detail::join_comma;
using detail::join_lines;
using nlohmann::json;

// The JSON key of each validated field, so that a range error names the key in the file.
std::string json_pointer_for(const std::string& field) {
  const InputSpec* spec = find_input_by_field(field);
  return spec != nullptr ? std::string(spec->preset) : "";
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
              const std::vector<std::string>& allowed) {
    if (!object.is_object()) {
      problem(pointer.empty() ? "/" : pointer, "expected an object, got " + describe_json(object));
      return false;
    }
    for (const auto& [key, value] : object.items()) {
      bool known = false;
      for (const std::string& a : allowed) {
        known = known || key == a;
      }
      if (!known) {
        problem(pointer + "/" + detail::cut(key),
                "unknown key (allowed here: " + join_comma(allowed) + ")");
      }
    }
    return true;
  }

  std::optional<double> number(const json& object, const std::string& pointer,
                               const std::string& key, bool required) {
    const std::string at = pointer + "/" + key;
    if (!object.contains(key)) {
      if (required) {
        problem(at, "missing (a number is required)");
      }
      return std::nullopt;
    }
    const json& v = object.at(key);
    if (!v.is_number()) {
      problem(at, "expected a number, got " + describe_json(v));
      return std::nullopt;
    }
    return v.get<double>();
  }

  std::optional<int> integer(const json& object, const std::string& pointer,
                             const std::string& key) {
    if (!object.contains(key)) {
      return std::nullopt;
    }
    const json& v = object.at(key);
    if (!v.is_number_integer()) {
      problem(pointer + "/" + key, "expected a whole number, got " + describe_json(v));
      return std::nullopt;
    }
    // Unsigned values above 2^63 - 1 would wrap in get<long long>(): range-check them first.
    const bool too_large = v.is_number_unsigned() && v.get<unsigned long long>() > 1'000'000'000ULL;
    const auto value = too_large ? 0LL : v.get<long long>();
    if (too_large || value < -1'000'000'000LL || value > 1'000'000'000LL) {
      problem(pointer + "/" + key, "whole number " + v.dump() + " is out of range");
      return std::nullopt;
    }
    return static_cast<int>(value);
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
      problem(at, "expected a string, got " + describe_json(v));
      return;
    }
    out = v.get<std::string>();
  }

  // A choice of the input table (method, span rule, ...), by name.
  void choice(const json& object, const std::string& pointer, const InputSpec& spec,
              const std::string& key, Parameters& p) {
    if (!object.contains(key)) {
      return;
    }
    std::string value;
    const std::size_t before = problems_.size();
    text(object, pointer, key.c_str(), value, false);
    if (problems_.size() == before && !spec.set_choice(p, value)) {
      problem(pointer + "/" + key,
              "\"" + detail::cut(value) + "\" is not one of: " + std::string(spec.choices));
    }
  }

 private:
  std::string origin_;
  std::vector<std::string>& problems_;
};

// The inputs of one section of a preset ("fabric", "hanging", "model", "shape"): the rows of the
// input table whose preset key lies in it.
void read_section(Reader& r, const json& j, const std::string& section, Parameters& p) {
  const std::string pointer = "/" + section;
  std::vector<const InputSpec*> rows;
  std::vector<std::string> keys;
  bool required = false;
  for (const InputSpec& spec : input_table()) {
    if (spec.preset.starts_with(pointer + "/")) {
      rows.push_back(&spec);
      keys.emplace_back(spec.preset.substr(pointer.size() + 1));
      required = required || spec.required;
    }
  }
  if (!j.contains(section)) {
    if (required) {
      r.problem(pointer, "missing (an object with " + join_comma(keys) + ")");
    }
    return;
  }
  const json& object = j.at(section);
  if (!r.object(object, pointer, keys)) {
    return;
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const InputSpec& spec = *rows[i];
    switch (spec.kind) {
      case InputKind::number:
        if (const std::optional<double> v = r.number(object, pointer, keys[i], spec.required)) {
          spec.access.set(p, *v);
        }
        break;
      case InputKind::whole_number:
        if (const std::optional<int> v = r.integer(object, pointer, keys[i])) {
          spec.access.set(p, *v);
        }
        break;
      case InputKind::choice:
        r.choice(object, pointer, spec, keys[i], p);
        break;
      case InputKind::stiffness_K:
        break;  // derived from c: never stored
    }
  }
}

// A stored K and p go through the same input table as typed ones: K as the c it stands for at the
// preset's Poisson ratio, p through p's own row. Returns false after naming what is out of range.
bool check_constants(Reader& r, const std::string& K_pointer, const std::string& p_pointer,
                     const Eq7Constants& k, double nu) {
  const InputSpec& c_row = *find_input("c");
  const InputSpec& p_row = *find_input("p");
  const double c = k.K * (1.0 - nu * nu);
  bool ok = true;
  if (!c_row.valid.contains(c)) {
    r.problem(K_pointer, "K = " + detail::shortest_number(k.K) +
                             " is c = " + detail::shortest_number(c) +
                             " at nu = " + detail::shortest_number(nu) + ", outside c's range " +
                             c_row.valid.text() + ": " + std::string(c_row.why));
    ok = false;
  }
  if (!p_row.valid.contains(k.p)) {
    r.problem(p_pointer, "p = " + detail::shortest_number(k.p) + " is outside " +
                             p_row.valid.text() + ": " + std::string(p_row.why));
    ok = false;
  }
  return ok;
}

// [[K, p], ...], each in the input table's ranges, at most kMaxCalibrationEntries of them.
std::vector<Eq7Constants> read_constants_list(Reader& r, const json& list,
                                              const std::string& pointer, double nu) {
  std::vector<Eq7Constants> out;
  if (!list.is_array()) {
    r.problem(pointer, "expected an array of [K, p] pairs, got " + describe_json(list));
    return out;
  }
  // Refused before any entry is read: every stored entry is evaluated at every solve.
  if (list.size() > kMaxCalibrationEntries) {
    r.problem(pointer + "/" + std::to_string(kMaxCalibrationEntries),
              std::to_string(list.size()) + " entries, at most " +
                  std::to_string(kMaxCalibrationEntries) + " are allowed");
    return out;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& pair = list[i];
    const std::string at = pointer + "/" + std::to_string(i);
    if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number() || !pair[1].is_number() ||
        !(pair[0].get<double>() > 0.0) || !(pair[1].get<double>() > 0.0)) {
      r.problem(at, "expected [K, p] with K > 0 and p > 0, got " + describe_json(pair));
      continue;
    }
    const Eq7Constants k{pair[0].get<double>(), pair[1].get<double>()};
    if (check_constants(r, at, at, k, nu)) {
      out.push_back(k);
    }
  }
  return out;
}

// [[n, ln z_max, ln Q], ...]: finite numbers or null, n a whole number.
std::vector<HeldOutResidual> read_residuals(Reader& r, const json& list,
                                            const std::string& pointer) {
  std::vector<HeldOutResidual> out;
  if (!list.is_array()) {
    r.problem(pointer,
              "expected an array of [n, ln z_max, ln Q] residuals, got " + describe_json(list));
    return out;
  }
  if (list.size() > kMaxCalibrationEntries) {
    r.problem(pointer, "holds " + std::to_string(list.size()) + " residuals, above the limit of " +
                           std::to_string(kMaxCalibrationEntries));
    return out;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& triple = list[i];
    const std::string at = pointer + "/" + std::to_string(i);
    auto usable = [](const json& v) {
      return v.is_null() || (v.is_number() && std::isfinite(v.get<double>()));
    };
    if (!triple.is_array() || triple.size() != 3 || !usable(triple[0]) || !usable(triple[1]) ||
        !usable(triple[2]) ||
        (triple[0].is_number() && triple[0].get<double>() != std::floor(triple[0].get<double>()))) {
      r.problem(at, "expected [n, ln z_max, ln Q] (finite numbers or null, n whole), got " +
                        describe_json(triple));
      continue;
    }
    // Each bound with its reason, so that a hand-edited record says which number is wrong.
    auto beyond = [&](const json& v, double bound) {
      return v.is_number() && std::abs(v.get<double>()) > bound;
    };
    bool bounded = true;
    if (beyond(triple[0], kMaxResidualFolds)) {
      r.problem(at + "/0", "n residual " + detail::shortest_number(triple[0].get<double>()) +
                               " is outside [-" + detail::shortest_number(kMaxResidualFolds) +
                               ", " + detail::shortest_number(kMaxResidualFolds) +
                               "]: a prediction never counts more folds than the solver's cap");
      bounded = false;
    }
    for (int k : {1, 2}) {
      if (beyond(triple[k], kMaxLogResidual)) {
        r.problem(at + "/" + std::to_string(k),
                  std::string(k == 1 ? "ln z_max" : "ln Q") + " residual " +
                      detail::shortest_number(triple[k].get<double>()) + " is outside ±" +
                      detail::printf_string("%.4g", kMaxLogResidual) +
                      " (ln 1e6: a factor of a million either way): no fit worth storing misses "
                      "by more, and its interval would not be finite");
        bounded = false;
      }
    }
    if (!bounded) {
      continue;
    }
    auto value = [](const json& v) {
      return v.is_null() ? std::optional<double>() : std::optional<double>(v.get<double>());
    };
    out.push_back({value(triple[0]), value(triple[1]), value(triple[2])});
  }
  return out;
}

std::optional<CalibrationRecord> read_calibration(Reader& r, const json& c, double nu,
                                                  std::vector<std::string>& problems) {
  const std::string at = "/calibration";
  if (!r.object(c, at,
                {"calibrated_on", "method", "law", "K", "p", "fit_rows", "equally_good",
                 "leave_one_out", "residuals", "coverage"})) {
    return std::nullopt;
  }
  const std::size_t before = problems.size();
  CalibrationRecord record;
  r.text(c, at, "calibrated_on", record.calibrated_on, true);
  std::string method;
  r.text(c, at, "method", method, true);
  if (!method.empty() && !parse_method(method, record.method)) {
    r.problem(at + "/method", "\"" + detail::cut(method) + "\" is not one of: paper, exact");
  }
  std::string law;
  r.text(c, at, "law", law, false);
  if (!law.empty() && !parse_wrinkle_law(law, record.law)) {
    r.problem(at + "/law", "\"" + detail::cut(law) + "\" is not a wrinkle law");
  }
  record.fitted.K = r.number(c, at, "K", true).value_or(record.fitted.K);
  record.fitted.p = r.number(c, at, "p", true).value_or(record.fitted.p);
  record.fit_rows = r.integer(c, at, "fit_rows").value_or(record.fit_rows);
  if (record.fit_rows < 0) {
    r.problem(at + "/fit_rows", "a number of rows is >= 0");
  }
  if (c.contains("equally_good")) {
    record.equally_good = read_constants_list(r, c.at("equally_good"), at + "/equally_good", nu);
  }
  if (c.contains("leave_one_out")) {
    record.leave_one_out = read_constants_list(r, c.at("leave_one_out"), at + "/leave_one_out", nu);
  }
  if (c.contains("residuals")) {
    const std::size_t before_residuals = problems.size();
    record.residuals = read_residuals(r, c.at("residuals"), at + "/residuals");
    // A refused entry is named already; the count is compared only when each entry was read.
    if (problems.size() == before_residuals &&
        record.residuals.size() != record.leave_one_out.size()) {
      r.problem(at + "/residuals", "expected one residual per leave_one_out fit (" +
                                       std::to_string(record.leave_one_out.size()) + "), got " +
                                       std::to_string(record.residuals.size()));
    }
  }
  r.text(c, at, "coverage", record.coverage, false);
  if (problems.size() == before && !(record.fitted.K > 0.0 && record.fitted.p > 0.0)) {
    r.problem(at, "K and p must be > 0");
  } else if (problems.size() == before) {
    check_constants(r, at + "/K", at + "/p", record.fitted, nu);
  }
  return problems.size() == before ? std::optional(record) : std::nullopt;
}

void read_appearance(Reader& r, const json& a, Appearance& out) {
  const std::string at = "/appearance";
  if (!r.object(a, at, {"colour"})) {
    return;
  }
  if (!a.contains("colour")) {
    return;
  }
  const json& v = a.at("colour");
  const std::optional<ColourRgb8> colour =
      v.is_string() ? parse_hex_colour(v.get<std::string>()) : std::nullopt;
  if (!colour) {
    r.problem(at + "/colour",
              "expected an sRGB colour as \"#RRGGBB\" (six hex digits), got " + describe_json(v));
    return;
  }
  out.colour = colour;
}

}  // namespace

std::optional<ColourRgb8> parse_hex_colour(std::string_view text) {
  if (text.size() != 7 || text[0] != '#') {
    return std::nullopt;
  }
  std::uint8_t channels[3] = {};
  for (std::size_t i = 0; i < 3; ++i) {
    const int high = detail::hex_digit(text[1 + 2 * i]);
    const int low = detail::hex_digit(text[2 + 2 * i]);
    if (high < 0 || low < 0) {
      return std::nullopt;
    }
    channels[i] = static_cast<std::uint8_t>(high * 16 + low);
  }
  return ColourRgb8{channels[0], channels[1], channels[2]};
}

std::string hex_colour(ColourRgb8 colour) {
  return detail::printf_string("#%02x%02x%02x", unsigned{colour.r}, unsigned{colour.g},
                               unsigned{colour.b});
}

Preset preset_from_json(const json& j, const std::string& origin) {
  std::vector<std::string> problems;
  Reader r(origin, problems);
  Preset preset;
  if (!r.object(j, "",
                {"foldlab_preset", "name", "description", "source", "derived_from", "written_by",
                 "fabric", "hanging", "model", "shape", "published", "calibration", "appearance",
                 "outline"})) {
    throw PresetError(join_lines(problems));
  }
  if (!j.contains("foldlab_preset")) {
    r.problem("/foldlab_preset", "missing: not a FoldLab preset (expected \"foldlab_preset\": " +
                                     std::to_string(kPresetFormatVersion) + ")");
  } else if (!j.at("foldlab_preset").is_number_integer() ||
             j.at("foldlab_preset").get<long long>() != kPresetFormatVersion) {
    r.problem("/foldlab_preset", "format version " + describe_json(j.at("foldlab_preset")) +
                                     " is not supported (this FoldLab reads version " +
                                     std::to_string(kPresetFormatVersion) + ")");
  }
  r.text(j, "", "name", preset.name, true);
  r.text(j, "", "description", preset.description, false);
  r.text(j, "", "source", preset.source, false);
  r.text(j, "", "derived_from", preset.derived_from, false);
  r.text(j, "", "written_by", preset.written_by, false);

  Parameters& p = preset.parameters;
  for (const char* section : {"fabric", "hanging", "model", "shape"}) {
    read_section(r, j, section, p);
  }
  if (j.contains("published")) {
    const json& pub = j.at("published");
    if (r.object(pub, "/published", {"n", "z_max_mm", "Q"})) {
      const std::size_t before = problems.size();
      if (pub.contains("n")) {
        preset.published.n = r.integer(pub, "/published", "n").value_or(0);
      }
      if (pub.contains("z_max_mm")) {
        preset.published.z_max_mm = r.number(pub, "/published", "z_max_mm", false).value_or(0.0);
      }
      if (pub.contains("Q")) {
        preset.published.Q = r.number(pub, "/published", "Q", false).value_or(0.0);
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
  if (j.contains("calibration")) {
    preset.calibration = read_calibration(r, j.at("calibration"), p.fabric.poisson_ratio, problems);
  }
  if (j.contains("appearance")) {
    read_appearance(r, j.at("appearance"), preset.appearance);
  }
  if (j.contains("outline")) {
    // The same reader and rules as `field --outline FILE`, so that a cut moves between a file and
    // a preset unchanged.
    try {
      preset.outline = field::outline_from_json(j.at("outline"));
    } catch (const field::OutlineError& e) {
      r.problem("/outline", e.what());
    }
  }
  // Range problems too, except for a key that already has one: its value was not read, so the
  // range check would be about the default standing in for it.
  const std::vector<std::string> read_problems = problems;
  for (const ValidationIssue& issue : validate(p)) {
    const std::string pointer = json_pointer_for(issue.field);
    const std::string prefix = origin + ": " + pointer + ":";
    const bool already =
        std::any_of(read_problems.begin(), read_problems.end(),
                    [&](const std::string& line) { return line.starts_with(prefix); });
    if (!already) {
      r.problem(pointer, issue.message);
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
    j = parse_json(text, origin);
  } catch (const JsonInputError& e) {
    throw PresetError(e.what());
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
  };
  if (!preset.derived_from.empty()) {
    j["derived_from"] = preset.derived_from;
  }
  if (!preset.written_by.empty()) {
    j["written_by"] = preset.written_by;
  }
  for (const InputSpec& spec : input_table()) {
    if (spec.preset.empty()) {
      continue;
    }
    const json::json_pointer at{std::string(spec.preset)};
    if (spec.kind == InputKind::choice) {
      j[at] = spec.choice(p);
    } else if (spec.kind == InputKind::whole_number) {
      j[at] = static_cast<int>(spec.access.get(p));
    } else {
      j[at] = detail::finite_or_throw(*spec.value(p), spec.preset);
    }
  }
  json published = json::object();
  if (preset.published.n)
    published["n"] = *preset.published.n;
  if (preset.published.z_max_mm)
    published["z_max_mm"] =
        detail::finite_or_throw(*preset.published.z_max_mm, "/published/z_max_mm");
  if (preset.published.Q)
    published["Q"] = detail::finite_or_throw(*preset.published.Q, "/published/Q");
  if (!published.empty()) {
    j["published"] = published;
  }
  if (const auto& c = preset.calibration) {
    auto pairs = [](const std::vector<Eq7Constants>& list) {
      json out = json::array();
      for (const Eq7Constants& k : list) {
        out.push_back({k.K, k.p});
      }
      return out;
    };
    j["calibration"] = {{"calibrated_on", c->calibrated_on},
                        {"method", to_string(c->method)},
                        {"K", c->fitted.K},
                        {"p", c->fitted.p},
                        {"fit_rows", c->fit_rows},
                        {"equally_good", pairs(c->equally_good)},
                        {"leave_one_out", pairs(c->leave_one_out)}};
    if (!c->residuals.empty()) {
      json residuals = json::array();
      for (const HeldOutResidual& r : c->residuals) {
        auto value = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
        residuals.push_back({value(r.n), value(r.log_z_max), value(r.log_Q)});
      }
      j["calibration"]["residuals"] = std::move(residuals);
    }
    if (!c->coverage.empty()) {
      j["calibration"]["coverage"] = c->coverage;
    }
    // Conci's law is the default, so files from before there were laws read the same.
    if (c->law != WrinkleLawKind::conci) {
      j["calibration"]["law"] = to_string(c->law);
    }
  }
  if (preset.appearance.colour) {
    j["appearance"] = {{"colour", hex_colour(*preset.appearance.colour)}};
  }
  if (preset.outline) {
    const auto point = [](const Eigen::Vector2d& at) {
      return json::array({detail::finite_or_throw(at.x(), "/outline"),
                          detail::finite_or_throw(at.y(), "/outline")});
    };
    const auto edge = [&](const std::vector<Eigen::Vector2d>& vertices) {
      json out = json::array();
      for (const Eigen::Vector2d& v : vertices) {
        out.push_back(point(v));
      }
      return out;
    };
    json supports = json::array();
    for (const field::Support& s : preset.outline->supports) {
      supports.push_back({{"at", point(s.at_mm)}, {"to", point(s.to_mm)}});
    }
    j["outline"] = {{"top", edge(preset.outline->top_mm)},
                    {"bottom", edge(preset.outline->bottom_mm)},
                    {"supports", std::move(supports)}};
  }
  return j;
}

Preset load_preset(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_text_file(path, kMaxPresetFileBytes);
  } catch (const ReadError& e) {
    throw PresetError(e.what());
  }
  return preset_from_text(text, path.string());
}

void save_preset(const Preset& preset, const std::filesystem::path& path) {
  if (const auto issues = validate(preset.parameters); !issues.empty()) {
    throw PresetError(path.string() + ": not saved: " + format_issues(issues));
  }
  const json j = preset_to_json(preset);
  // A file that load_preset would refuse (a calibration list above its cap, constants out of
  // range) is not written: what is saved must open again.
  (void)preset_from_json(j, path.string() + " (not saved)");
  // A WriteError stays one: a file that cannot be written is not bad input.
  write_file_atomically(path, j.dump(2) + "\n");
}

const Preset& default_preset() {
  static const Preset preset = preset_from_text(kDefaultPresetText, kDefaultPresetOrigin);
  return preset;
}

}  // namespace foldlab
