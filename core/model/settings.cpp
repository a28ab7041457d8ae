#include "core/model/settings.hpp"
#include "core/model/settings_testing.hpp"

#include "core/model/arithmetic.hpp"

#include "core/model/text_format.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace foldlab {
namespace {

constexpr InputInterval closed(double lo, double hi) {
  return {lo, hi, false, false};
}

template <class Enum>
bool set_named(Enum& field, std::string_view text, bool (*parse)(std::string_view, Enum&)) {
  return parse(text, field);
}

// "conci, cerda-mahadevan": the laws' keys from their one list, so that a new law needs no edit
// here.
std::string_view law_choices() {
  static const std::string text = [] {
    std::string out;
    for (const WrinkleLaw* law : wrinkle_laws()) {
      out += (out.empty() ? "" : ", ") + std::string(law->key());
    }
    return out;
  }();
  return text;
}

constexpr InputUnit kWeightUnits[] = {
    {"g/m²", kNPerMm2PerGramPerM2, "%.3g", "gsm"},
    {"oz/yd²", kGramPerM2PerOuncePerYd2* kNPerMm2PerGramPerM2, "%.3g"}};
constexpr InputUnit kLengthUnits[] = {{"cm", 10.0, "%.4g"}, {"m", 1000.0, "%.4g"}};
constexpr InputUnit kModulusUnits[] = {{"GPa", 1000.0, "%.4g"}};

// One row per input. `valid` is where a value can still describe a cloth (or a sane numerical
// setting); `typical` is where the fabrics one meets lie, used by sliders and the stress test.
std::vector<InputSpec> build_table() {
  std::vector<InputSpec> table = {
      {.key = "t",
       .name = "thickness",
       .unit = "mm",
       .quantity = "length",
       .field = "t_mm",
       .preset = "/fabric/thickness_mm",
       .help = "fabric thickness: silk chiffon about 0.09 mm, cotton poplin 0.2, linen 0.4, "
               "denim 0.8 (the fabric presets, presets/FABRICS.md)",
       .valid = closed(1e-3, 50.0),
       .why = "a membrane or fabric from 1 micrometre to 50 mm thick",
       .typical_lo = 0.01,
       .typical_hi = 5.0,
       .beginner_lo = 0.05,
       .beginner_hi = 3.0,
       .scale = InputScale::logarithmic,
       .format = "%.3g",
       .required = true,
       .cloth = true,
       .place = InputPlace::list,
       .other_units = kLengthUnits,
       .sampled = true,
       .realistic_lo = 0.05,
       .realistic_hi = 1.5,
       .access = input_field<&Parameters::fabric, &Fabric::thickness_mm>()},
      {.key = "E",
       .name = "Young's modulus",
       .unit = "MPa",
       .quantity = "stress",
       .field = "E_MPa",
       .preset = "/fabric/youngs_modulus_MPa",
       .help = "Young's modulus (MPa = N/mm²): cotton jersey knit about 9 MPa, silk chiffon 78, "
               "denim 150, woven cotton poplin 160, polyester satin 380, nylon ripstop 430; "
               "estimates good to a factor of 2-3 (presets/FABRICS.md)",
       .valid = closed(1e-3, 1e6),
       .why = "from a soft gel (1e-3 MPa) to beyond steel (1e6 MPa)",
       .typical_lo = 1.0,
       .typical_hi = 1e4,
       .beginner_lo = 3.0,
       .beginner_hi = 1000.0,
       .scale = InputScale::logarithmic,
       .format = "%.4g",
       .required = true,
       .cloth = true,
       .place = InputPlace::list,
       .other_units = kModulusUnits,
       .sampled = true,
       .realistic_lo = 5.0,
       .realistic_hi = 2000.0,
       .access = input_field<&Parameters::fabric, &Fabric::youngs_modulus_MPa>()},
      {.key = "w",
       .name = "weight per area",
       .unit = "N/mm²",
       .quantity = "weight per area",
       .field = "w_N_per_mm2",
       .preset = "/fabric/weight_N_per_mm2",
       .help = "weight per area: silk chiffon about 35 g/m², cotton poplin 120, linen 200, "
               "denim (13 oz/yd²) 441 (presets/FABRICS.md); 1.5e-6 N/mm² = 153 g/m², and "
               "80g/m2, 80gsm, 2.4oz/yd2 are read too; a bare number is N/mm² in --set and "
               "presets (150 g/m² is w=150gsm) and g/m² typed into the explorer's slider",
       .valid = closed(0.1 * kNPerMm2PerGramPerM2, 1e6 * kNPerMm2PerGramPerM2),
       .why = "from the lightest tissue to a tonne per square metre",
       .typical_lo = 1e-7,
       .typical_hi = 1e-4,
       .beginner_lo = 1e-7,
       .beginner_hi = 1000.0 * kNPerMm2PerGramPerM2,
       .scale = InputScale::logarithmic,
       .format = "%.3e",
       .required = true,
       .cloth = true,
       .place = InputPlace::list,
       .other_units = kWeightUnits,
       .shown_unit = 1,
       .sampled = true,
       .realistic_lo = 3e-07,
       .realistic_hi = 1e-05,
       .access = input_field<&Parameters::fabric, &Fabric::weight_N_per_mm2>()},
      {.key = "nu",
       .name = "Poisson's ratio",
       .symbol = "ν",
       .field = "nu",
       .preset = "/fabric/poisson_ratio",
       .help = "Poisson's ratio: 0.3 for every fabric preset, the paper's value (no "
               "fabric's own was measured)",
       .valid = {0.0, 0.5, false, true},
       .why = "Poisson's ratio of an isotropic material, 0 <= nu < 0.5",
       .typical_lo = 0.0,
       .typical_hi = 0.49,
       .format = "%.3f",
       .expert = true,
       .place = InputPlace::list,
       .axis_over_typical = true,
       .sampled = true,
       .access = input_field<&Parameters::fabric, &Fabric::poisson_ratio>()},
      {.key = "h",
       .name = "height",
       .unit = "mm",
       .quantity = "length",
       .field = "h_mm",
       .preset = "/hanging/height_mm",
       .help = "height of the cloth at the centre: a window curtain about 1500-2500 mm, the "
               "paper's cloths 900-2350 mm",
       .valid = closed(1.0, 1e5),
       .why = "the cloth's height, from 1 mm to 100 m",
       .typical_lo = 100.0,
       .typical_hi = 5000.0,
       .format = "%.0f",
       .required = true,
       .cloth = true,
       .place = InputPlace::list,
       .other_units = kLengthUnits,
       .sampled = true,
       .realistic_lo = 300.0,
       .realistic_hi = 3000.0,
       .access = input_field<&Parameters::hanging, &Hanging::height_mm>()},
      {.key = "L",
       .name = "width",
       .unit = "mm",
       .quantity = "length",
       .field = "L_mm",
       .preset = "/hanging/length_mm",
       .help = "length of the upper edge (width): the paper's cloth 1400 mm, a curtain panel "
               "1000-3000 mm",
       .valid = closed(1.0, 1e5),
       .why = "the upper edge's length, from 1 mm to 100 m",
       .typical_lo = 100.0,
       .typical_hi = 5000.0,
       .format = "%.0f",
       .required = true,
       .cloth = true,
       .place = InputPlace::list,
       .other_units = kLengthUnits,
       .sampled = true,
       .realistic_lo = 300.0,
       .realistic_hi = 3000.0,
       .access = input_field<&Parameters::hanging, &Hanging::length_mm>()},
      {.key = "d",
       .name = "support displacement",
       .unit = "mm",
       .quantity = "length",
       .field = "d_mm",
       .preset = "/hanging/support_displacement_mm",
       .help = "support displacement: the span is l = L - d (span_rule L-2d: each support moves d)",
       .valid = closed(0.0, 5e4),
       .why = "below half of L, where the supports would meet under the span rule L-2d (kept under "
              "L-d too)",
       .upper_bound = [](const Parameters& p) -> std::optional<double> {
         const double L = p.hanging.length_mm;
         // Found once: validate() asks on every edit and every point of a sweep.
         static const InputInterval L_valid = find_input("L")->valid;
         return L_valid.contains(L) ? std::optional(0.5 * L) : std::nullopt;
       },
       .upper_bound_name = "L/2",
       .upper_bound_why =
           "where the supports would meet under the span rule L-2d (kept under L-d too)",
       .typical_lo = 0.0,
       .typical_hi = 2500.0,
       .format = "%.0f",
       .required = true,
       .cloth = true,
       .place = InputPlace::list,
       .other_units = kLengthUnits,
       .sampled = true,
       .realistic_lo = 1.0,
       .realistic_part_of_upper_bound = 0.6,
       .access = input_field<&Parameters::hanging, &Hanging::support_displacement_mm>()},
      {.key = "K",
       .name = "eq. 7 constant c/(1-ν²)",
       .field = "K",
       .help = "c/(1-ν²) of eq. 7 (sets c at the current ν)",
       .kind = InputKind::stiffness_K,
       .typical_lo = 0.5,
       .typical_hi = 300.0,
       .scale = InputScale::logarithmic,
       .format = "%.3g",
       .expert = true,
       .place = InputPlace::list,
       .access = {stiffness_constant_K, set_stiffness_constant_K}},
      {.key = "c",
       .name = "load-condition constant",
       .field = "c",
       .preset = "/model/load_constant_c",
       .help = "load-condition constant of eq. 7",
       .valid = closed(1e-3, 1e4),
       .why = "the load-condition constant of eq. 7, from 1e-3 to 1e4",
       .typical_lo = 0.5,
       .typical_hi = 300.0,
       .scale = InputScale::logarithmic,
       .format = "%.3g",
       .expert = true,
       .place = InputPlace::readout,
       .access = input_field<&Parameters::model, &ModelSettings::load_constant_c>()},
      {.key = "p",
       .name = "eq. 7 exponent",
       .field = "p",
       .preset = "/model/stress_exponent_p",
       .help = "exponent on eq. 7's stress ratio, s -> s^p (1 = the paper; foldlab calibrate)",
       .valid = closed(0.05, 5.0),
       .why = "the exponent on eq. 7's stress ratio (1 = the paper), from 0.05 (below, s^p is 1 "
              "for any cloth) to 5 (the calibration's search range)",
       .typical_lo = 0.2,
       .typical_hi = 2.0,
       .format = "%.3f",
       .expert = true,
       .place = InputPlace::after,
       .access = input_field<&Parameters::model, &ModelSettings::stress_exponent_p>()},
      {.key = "method",
       .name = "method",
       .preset = "/model/method",
       .help = "paper | exact",
       .kind = InputKind::choice,
       .expert = true,
       .place = InputPlace::list,
       .choices = "paper, exact",
       .set_choice = [](Parameters& p,
                        std::string_view v) { return set_named(p.model.method, v, parse_method); },
       .choice = [](const Parameters& p) { return to_string(p.model.method); }},
      {.key = "law",
       .name = "wrinkle law",
       .preset = "/model/law",
       .help = "the law that counts the folds (c and p are its constants): see model.md",
       .kind = InputKind::choice,
       .expert = true,
       .place = InputPlace::list,
       .choices = law_choices(),
       .set_choice =
           [](Parameters& p, std::string_view v) {
             return set_named(p.model.law, v, parse_wrinkle_law);
           },
       .choice = [](const Parameters& p) { return to_string(p.model.law); }},
      {.key = "span_rule",
       .name = "span rule",
       .preset = "/model/span_rule",
       .help = "L-d | L-2d: how the span l follows from L and d",
       .kind = InputKind::choice,
       .expert = true,
       .place = InputPlace::list,
       .choices = "L-d, L-2d",
       .set_choice =
           [](Parameters& p, std::string_view v) {
             return set_named(p.model.span_rule, v, parse_span_rule);
           },
       .choice = [](const Parameters& p) { return to_string(p.model.span_rule); }},
      {.key = "int_rounding",
       .name = "Int[]",
       .preset = "/model/int_rounding",
       .help = "nearest | floor: Int[] of eq. 10",
       .kind = InputKind::choice,
       .expert = true,
       .place = InputPlace::list,
       .choices = "nearest, floor",
       .set_choice =
           [](Parameters& p, std::string_view v) {
             return set_named(p.model.int_rounding, v, parse_int_rounding);
           },
       .choice = [](const Parameters& p) { return to_string(p.model.int_rounding); }},
      {.key = "simpson_intervals",
       .name = "quadrature intervals",
       .field = "simpson_intervals",
       .preset = "/model/simpson_intervals",
       .help = "paper method: intervals of the eq. 8 quadrature (even for Simpson)",
       .kind = InputKind::whole_number,
       .valid = closed(2.0, 10000.0),
       .why = "the paper method's quadrature of eq. 8 needs at least 2 intervals; beyond 10000 "
              "it is exact to rounding and only slower",
       .typical_lo = 2.0,
       .typical_hi = 200.0,
       .format = "%.0f",
       .expert = true,
       .access = input_field<&Parameters::model, &ModelSettings::simpson_intervals>()},
      {.key = "length_tolerance",
       .name = "length tolerance",
       .field = "length_tolerance",
       .preset = "/model/length_tolerance",
       .help = "paper method: stop when |L'/L - 1| <= this",
       .valid = closed(1e-12, 0.5),
       .why = "the paper method's relative tolerance on L (0.05 is the paper's 5%), from 1e-12 "
              "(rounding) to 0.5",
       .typical_lo = 1e-4,
       .typical_hi = 0.1,
       .scale = InputScale::logarithmic,
       .format = "%.3g",
       .expert = true,
       .access = input_field<&Parameters::model, &ModelSettings::length_tolerance>()},
      {.key = "max_iterations",
       .name = "iteration cap",
       .field = "max_iterations",
       .preset = "/model/max_iterations",
       .help = "paper method: iteration cap",
       .kind = InputKind::whole_number,
       .valid = closed(1.0, 1000.0),
       .why = "the paper method needs at least one iteration; it converges or cycles within a "
              "few dozen, so more than 1000 only costs time",
       .typical_lo = 1.0,
       .typical_hi = 1000.0,
       .format = "%.0f",
       .expert = true,
       .access = input_field<&Parameters::model, &ModelSettings::max_iterations>()},
      {.key = "length_quadrature",
       .name = "quadrature rule",
       .preset = "/model/length_quadrature",
       .help = "simpson | trapezoid: paper method's rule for eq. 8 (simpson_intervals intervals)",
       .kind = InputKind::choice,
       .expert = true,
       .choices = "simpson, trapezoid",
       .set_choice =
           [](Parameters& p, std::string_view v) {
             return set_named(p.model.length_quadrature, v, parse_length_quadrature);
           },
       .choice = [](const Parameters& p) { return to_string(p.model.length_quadrature); }},
      {.key = "shape",
       .name = "shape",
       .preset = "/shape/kind",
       .help = "cosine | rectangular | strip | inclined: the cloth the pattern is laid on",
       .kind = InputKind::choice,
       .choices = "cosine, rectangular, strip, inclined",
       .set_choice =
           [](Parameters& p, std::string_view v) {
             return set_named(p.shape.kind, v, parse_shape_kind);
           },
       .choice = [](const Parameters& p) { return to_string(p.shape.kind); }},
      {.key = "supports",
       .name = "supports",
       .field = "supports",
       .preset = "/shape/supports",
       .help = "strip: number of equally spaced supports (k - 1 spans)",
       .kind = InputKind::whole_number,
       .valid = closed(2.0, 64.0),
       .why = "a strip hangs from 2 to 64 equally spaced supports",
       .typical_lo = 2.0,
       .typical_hi = 8.0,
       .format = "%.0f",
       .place = InputPlace::shape,
       .access = input_field<&Parameters::shape, &Shape::supports>()},
      {.key = "incline_deg",
       .name = "incline",
       .unit = "deg",
       .quantity = "angle",
       .field = "incline_deg",
       .preset = "/shape/incline_deg",
       .help = "inclined: angle of the line through the supports",
       .valid = {-80.0, 80.0, true, true},
       .why = "the line through inclined supports is steeper than vertical beyond +-80 deg",
       .typical_lo = -45.0,
       .typical_hi = 45.0,
       .format = "%.1f",
       .place = InputPlace::shape,
       .access = input_field<&Parameters::shape, &Shape::incline_deg>()},
  };
  return table;
}

}  // namespace

bool InputInterval::contains(double v) const {
  const bool above_lo = lo_open ? v > lo : v >= lo;
  const bool below_hi = hi_open ? v < hi : v <= hi;
  return std::isfinite(v) && above_lo && below_hi;
}

std::string InputInterval::text() const {
  return std::string(lo_open ? "(" : "[") + detail::shortest_number(lo) + ", " +
         detail::shortest_number(hi) + (hi_open ? ")" : "]");
}

std::optional<double> InputSpec::value(const Parameters& p) const {
  if (kind == InputKind::choice) {
    return std::nullopt;
  }
  return access.get(p);
}

namespace {

// Callers keep pointers to rows: room is reserved so that a row added by a test never moves them.
constexpr std::size_t kMaxInputRows = 64;

std::vector<InputSpec>& rows() {
  static std::vector<InputSpec> table = [] {
    std::vector<InputSpec> out = build_table();
    out.reserve(kMaxInputRows);
    return out;
  }();
  return table;
}

}  // namespace

const std::vector<InputSpec>& input_table() {
  return rows();
}

void add_input_row_for_testing(const InputSpec& spec) {
  if (rows().size() == kMaxInputRows || find_input(spec.key) != nullptr) {
    throw std::logic_error("cannot add input row " + std::string(spec.key));
  }
  rows().push_back(spec);
}

const InputSpec* find_input(std::string_view key) {
  for (const InputSpec& spec : input_table()) {
    if (spec.key == key) {
      return &spec;
    }
  }
  return nullptr;
}

std::vector<const InputSpec*> cloth_inputs() {
  std::vector<const InputSpec*> out;
  for (const InputSpec& spec : input_table()) {
    if (spec.cloth) {
      out.push_back(&spec);
    }
  }
  return out;
}

const InputSpec* find_input_by_field(std::string_view field) {
  for (const InputSpec& spec : input_table()) {
    if (!spec.field.empty() && spec.field == field) {
      return &spec;
    }
  }
  return nullptr;
}

std::string input_label(const InputSpec& spec) {
  return spec.unit.empty() ? std::string(spec.key)
                           : std::string(spec.key) + " (" + std::string(spec.unit) + ")";
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = detail::read_double(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::vector<InputUnit> input_units(const InputSpec& spec) {
  if (spec.unit.empty()) {
    return {};
  }
  std::vector<InputUnit> units{{spec.unit, 1.0, spec.format}};
  units.insert(units.end(), spec.other_units.begin(), spec.other_units.end());
  return units;
}

InputUnit shown_unit(const InputSpec& spec) {
  const std::vector<InputUnit> units = input_units(spec);
  if (units.empty()) {
    return {{}, 1.0, spec.format};
  }
  return units.at(spec.shown_unit);
}

double to_shown_unit(const InputSpec& spec, double stored) {
  return stored / shown_unit(spec).per_unit;
}

double from_shown_unit(const InputSpec& spec, double shown) {
  return shown * shown_unit(spec).per_unit;
}

std::string_view input_symbol(const InputSpec& spec) {
  return spec.symbol.empty() ? spec.key : spec.symbol;
}

std::string shown_label(const InputSpec& spec) {
  const std::string_view unit = shown_unit(spec).symbol;
  const std::string symbol(input_symbol(spec));
  return unit.empty() ? symbol : symbol + " (" + std::string(unit) + ")";
}

std::string input_title(const InputSpec& spec) {
  const std::string_view symbol = input_symbol(spec);
  // "supports", not "supports supports": a row named by its symbol says it once.
  return symbol == spec.name ? std::string(spec.name)
                             : std::string(spec.name) + " " + std::string(symbol);
}

namespace {

std::string with_unit(const InputSpec& spec, const std::string& number) {
  const std::string_view unit = shown_unit(spec).symbol;
  return unit.empty() ? number : number + " " + std::string(unit);
}

}  // namespace

std::string shown_quantity(const InputSpec& spec, double stored) {
  return with_unit(spec, detail::message_number(to_shown_unit(spec, stored)));
}

InputRefusal range_refusal(const InputSpec& spec, double value, const InputInterval& range,
                           std::string_view why) {
  // A NaN is below no end and above none: it is said against the lower one.
  const bool above_lo = range.lo_open ? value > range.lo : value >= range.lo;
  return {.kind = RefusalKind::out_of_range,
          .key = std::string(spec.key),
          .spec = &spec,
          .value = value,
          .bound = above_lo ? range.hi : range.lo,
          .unit = spec.unit,
          .range = range,
          .why = why};
}

std::string known_keys() {
  std::vector<std::string_view> keys;
  for (const InputSpec& spec : input_table()) {
    keys.push_back(spec.key);
  }
  return detail::join(keys, ", ");
}

namespace {

// "must be between 0.1 and 1,000,000 g/m²" for a value out of range, in the slider's unit.
std::string range_sentence(const InputRefusal& refusal) {
  const InputSpec& spec = *refusal.spec;
  const InputInterval& range = refusal.range;
  const std::string lo = detail::message_number(to_shown_unit(spec, range.lo));
  const std::string hi_number = detail::message_number(to_shown_unit(spec, range.hi));
  const std::string hi = with_unit(spec, hi_number);
  // 0.5000000000001 is refused by "below 0.5": then it is written with all its digits.
  std::string shown = detail::message_number(to_shown_unit(spec, refusal.value));
  if (shown == lo || shown == hi_number) {
    shown = detail::message_number(to_shown_unit(spec, refusal.value), true);
  }
  const std::string bounds =
      range.lo_open == range.hi_open
          ? (range.lo_open ? "above " + lo + " and below " + hi : "between " + lo + " and " + hi)
          : (range.lo_open ? "above " + lo + " and at most " + hi
                           : "at least " + lo + " and below " + hi);
  return input_title(spec) + " = " + with_unit(spec, shown) + " must be " + bounds + ": " +
         std::string(refusal.why);
}

}  // namespace

std::string refusal_reason(const InputRefusal& refusal) {
  const std::vector<InputUnit> units =
      refusal.spec == nullptr ? std::vector<InputUnit>{} : input_units(*refusal.spec);
  switch (refusal.kind) {
    case RefusalKind::not_a_choice:
      return " is not one of: " + std::string(refusal.spec->choices);
    case RefusalKind::nested_too_deeply:
      return " is nested too deeply: arithmetic may nest at most " +
             std::to_string(kMaxArithmeticDepth) + " parentheses deep";
    case RefusalKind::beyond_double:
      return " is beyond the range of a double (magnitudes 2.2e-308 to 1.8e308)";
    case RefusalKind::divides_by_zero:
      return " divides by zero";
    case RefusalKind::unknown_unit: {
      std::vector<std::string_view> known;
      for (const InputUnit& unit : units) {
        known.push_back(unit.symbol);
      }
      for (const InputUnit& unit : units) {
        if (!unit.plain.empty()) {
          known.push_back(unit.plain);
        }
      }
      const InputSpec& spec = *refusal.spec;
      const std::string_view quantity = spec.quantity.empty() ? spec.name : spec.quantity;
      return ": '" + detail::cut(refusal.typed_unit) + "' is not a unit of " +
             std::string(quantity) + " (known: " + detail::join(known, ", ") + ")" +
             (refusal.meant_unit.empty()
                  ? ""
                  : "; did you mean '" + std::string(refusal.meant_unit) + "'?");
    }
    case RefusalKind::unknown_key:
    case RefusalKind::number_for_choice:
    case RefusalKind::not_a_number:
    case RefusalKind::not_whole:
    case RefusalKind::out_of_range:
    case RefusalKind::not_below_bound:
      break;
  }
  std::vector<std::string_view> symbols;
  for (const InputUnit& unit : units) {
    symbols.push_back(unit.symbol);
  }
  return std::string(" is not a number") +
         (symbols.size() > 1 ? " (with an optional unit: " + detail::join(symbols, ", ") + ")"
                             : "");
}

std::string refusal_sentence(const InputRefusal& refusal) {
  switch (refusal.kind) {
    case RefusalKind::unknown_key:
      return "unknown key '" + detail::cut(refusal.key) + "' (known: " + known_keys() + ")";
    case RefusalKind::number_for_choice:
      return refusal.key + " takes one of: " + std::string(refusal.spec->choices) +
             ", not a number";
    case RefusalKind::not_whole:
      return refusal.key + " = " + detail::shortest_number(refusal.value) +
             " must be a whole number";
    case RefusalKind::out_of_range:
      return range_sentence(refusal);
    case RefusalKind::not_below_bound:
      return input_title(*refusal.spec) + " = " + shown_quantity(*refusal.spec, refusal.value) +
             " must be below " + std::string(refusal.bound_name) + " = " +
             shown_quantity(*refusal.spec, refusal.bound) + ", " + std::string(refusal.why);
    case RefusalKind::not_a_choice:
    case RefusalKind::not_a_number:
    case RefusalKind::nested_too_deeply:
    case RefusalKind::unknown_unit:
    case RefusalKind::beyond_double:
    case RefusalKind::divides_by_zero:
      break;
  }
  return refusal.key + " = '" + detail::cut(refusal.typed) + "'" + refusal_reason(refusal);
}

namespace {

// A unit as typed, for comparison: no spaces, ² as 2, so that "g/m²" and "g / m2" are one unit.
// Case is kept: SI prefixes differ only in it (m, M).
std::string unit_key(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (text.substr(i).starts_with("²")) {
      out += '2';
      i += std::string_view("²").size() - 1;
    } else if (c != ' ' && c != '\t') {
      out += c;
    }
  }
  return out;
}

std::string lower_case(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

bool names_unit(const InputUnit& unit, const std::string& typed) {
  return typed == unit_key(unit.symbol) ||
         (!unit.plain.empty() && lower_case(typed) == lower_case(unit.plain));
}

// The number (or arithmetic) at the front of `text` and the unit typed after it, as unit_key
// writes it; nullopt when no number starts the text or only spaces follow it.
struct TypedQuantity {
  double number = 0.0;
  std::string unit;
  std::string_view unit_text;
};

std::optional<TypedQuantity> split_quantity(std::string_view text) {
  const std::optional<ArithmeticPrefix> arithmetic = arithmetic_prefix(text);
  // A number alone must be the whole text, as for parse_number: no space before it either.
  if (!arithmetic || text.starts_with(' ') || text.starts_with('\t')) {
    return std::nullopt;
  }
  const std::string_view rest = text.substr(arithmetic->end);
  TypedQuantity out{arithmetic->value, unit_key(rest), rest};
  // A number alone must be the whole text, as for parse_number; before a unit, spaces may stand.
  if (out.unit.empty() && !rest.empty()) {
    return std::nullopt;
  }
  return out;
}

int parenthesis_depth(std::string_view text) {
  int depth = 0;
  int deepest = 0;
  for (const char c : text) {
    depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

}  // namespace

namespace {

InputRefusal text_refusal(RefusalKind kind, const InputSpec& spec, std::string_view text) {
  return {.kind = kind,
          .key = std::string(spec.key),
          .spec = &spec,
          .typed = std::string(text),
          .unit = spec.unit};
}

// A number whose magnitude a double cannot hold, and nothing after it: 1e999, 1e-999.
bool beyond_double(std::string_view text) {
  double ignored = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = detail::read_double(text.data(), end, ignored);
  return ec == std::errc::result_out_of_range && ptr == end;
}

// Only a name after the number (letters, or a symbol such as µ, with at most a square's 2 at its
// end) is a unit the person meant; "2*", "1)" or "0x10" is a number gone wrong.
bool names_a_unit(std::string_view unit) {
  const auto first = static_cast<unsigned char>(unit.front());
  const std::string_view body = unit.ends_with('2') ? unit.substr(0, unit.size() - 1) : unit;
  return (std::isalpha(first) != 0 || first >= 0x80) &&
         std::none_of(body.begin(), body.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A whole number's text: a plain number, without arithmetic or unit.
std::variant<double, InputRefusal> read_whole_number(const InputSpec& spec, std::string_view text) {
  if (const std::optional<double> number = parse_number(text)) {
    return *number;
  }
  return text_refusal(beyond_double(text) ? RefusalKind::beyond_double : RefusalKind::not_a_number,
                      spec, text);
}

}  // namespace

std::variant<double, InputRefusal> read_quantity(const InputSpec& spec, std::string_view text,
                                                 std::string_view bare_unit) {
  const std::optional<TypedQuantity> typed = split_quantity(text);
  const std::vector<InputUnit> units = input_units(spec);
  if (typed) {
    const std::string bare = unit_key(bare_unit);
    for (const InputUnit& unit : units) {
      const bool bare_here = bare.empty() ? &unit == &units.front() : bare == unit_key(unit.symbol);
      if (typed->unit.empty() ? bare_here : names_unit(unit, typed->unit)) {
        return typed->number * unit.per_unit;
      }
    }
    if (typed->unit.empty() && units.empty()) {
      return typed->number;
    }
  }
  // One wording for one cause, whether a number is typed too large or computed so.
  if (beyond_double(text) || arithmetic_fault(text) == ArithmeticFault::beyond_double) {
    return text_refusal(RefusalKind::beyond_double, spec, text);
  }
  if (arithmetic_fault(text) == ArithmeticFault::division_by_zero) {
    return text_refusal(RefusalKind::divides_by_zero, spec, text);
  }
  if (parenthesis_depth(text) > kMaxArithmeticDepth) {
    return text_refusal(RefusalKind::nested_too_deeply, spec, text);
  }
  if (!typed || typed->unit.empty() || units.empty() || !names_a_unit(typed->unit)) {
    return text_refusal(RefusalKind::not_a_number, spec, text);
  }
  InputRefusal refusal = text_refusal(RefusalKind::unknown_unit, spec, text);
  std::string_view unit_text = typed->unit_text;
  while (!unit_text.empty() && (unit_text.front() == ' ' || unit_text.front() == '\t')) {
    unit_text.remove_prefix(1);
  }
  refusal.typed_unit = std::string(unit_text);
  for (const InputUnit& unit : units) {
    if (lower_case(typed->unit) == lower_case(unit_key(unit.symbol))) {
      refusal.meant_unit = unit.symbol;
    }
  }
  return refusal;
}

std::optional<double> parse_quantity(const InputSpec& spec, std::string_view text,
                                     std::string_view bare_unit) {
  const std::variant<double, InputRefusal> read = read_quantity(spec, text, bare_unit);
  const double* value = std::get_if<double>(&read);
  return value != nullptr ? std::optional(*value) : std::nullopt;
}

std::optional<std::string> bare_number_hint(const InputSpec& spec, std::string_view text) {
  const std::optional<TypedQuantity> typed = split_quantity(text);
  const InputUnit shown = shown_unit(spec);
  if (!typed || !typed->unit.empty() || spec.shown_unit == 0) {
    return std::nullopt;
  }
  const std::string written = detail::shortest_number(typed->number) +
                              std::string(shown.plain.empty() ? shown.symbol : shown.plain);
  return "a bare number for " + std::string(spec.key) + " is read in " + std::string(spec.unit) +
         "; for " + detail::message_number(typed->number) + " " + std::string(shown.symbol) +
         " write " + std::string(spec.key) + "=" + written;
}

InputInterval slider_ends(const InputSpec& spec, SliderReach reach) {
  if (reach == SliderReach::beginner && spec.beginner_hi > spec.beginner_lo) {
    return closed(spec.beginner_lo, spec.beginner_hi);
  }
  return closed(spec.typical_lo, spec.typical_hi);
}

InputInterval slider_interval(const InputSpec& spec, const Parameters& p, SliderReach reach) {
  const InputInterval typical = slider_ends(spec, reach);
  const std::optional<double> current = spec.value(p);
  if (!current || spec.kind == InputKind::choice) {
    return typical;
  }
  const std::size_t allowed = validate(p).size();
  const auto accepted = [&](double v) {
    Parameters trial = p;
    return !set_input(trial, spec.key, v) && validate(trial).size() <= allowed;
  };
  if (!accepted(*current)) {
    return typical;
  }
  const bool log = spec.scale == InputScale::logarithmic && typical.lo > 0.0;
  const double start = std::clamp(*current, typical.lo, typical.hi);
  // Between an accepted and a refused value, the accepted one next to the boundary.
  const auto boundary = [&](double good, double bad) {
    for (int i = 0; i < 200 && good != bad; ++i) {
      const double mid = log ? std::sqrt(good * bad) : 0.5 * (good + bad);
      if (mid == good || mid == bad) {
        break;
      }
      (accepted(mid) ? good : bad) = mid;
    }
    return good;
  };
  InputInterval out = typical;
  if (!accepted(out.lo) && accepted(start)) {
    out.lo = boundary(start, out.lo);
  }
  if (!accepted(out.hi) && accepted(start)) {
    out.hi = boundary(start, out.hi);
  }
  return out;
}

std::optional<InputRefusal> assign_number(Parameters& p, std::string_view key, double value) {
  const InputSpec* spec = find_input(key);
  if (spec == nullptr) {
    return InputRefusal{.kind = RefusalKind::unknown_key, .key = std::string(key), .value = value};
  }
  const auto refusal = [&](RefusalKind kind) {
    return InputRefusal{
        .kind = kind, .key = std::string(key), .spec = spec, .value = value, .unit = spec->unit};
  };
  switch (spec->kind) {
    case InputKind::choice:
      return refusal(RefusalKind::number_for_choice);
    case InputKind::whole_number:
      if (value != std::floor(value)) {
        return refusal(RefusalKind::not_whole);
      }
      if (std::abs(value) > 1e9) {  // beyond what the field holds: the row's range says why
        return range_refusal(*spec, value, spec->valid, spec->why);
      }
      break;
    case InputKind::stiffness_K:  // stored as c: a c out of range is named by validate()
    case InputKind::number:
      break;
  }
  spec->access.set(p, value);
  return std::nullopt;
}

std::vector<InputRefusal> input_refusals(const Parameters& p) {
  std::vector<InputRefusal> refusals;
  for (const InputSpec& spec : input_table()) {
    if (spec.kind != InputKind::number && spec.kind != InputKind::whole_number) {
      continue;
    }
    const double value = *spec.value(p);
    if (!spec.valid.contains(value)) {
      refusals.push_back(range_refusal(spec, value, spec.valid, spec.why));
      continue;
    }
    // Asked only of a value in its own range: the bound follows from other inputs.
    const std::optional<double> upper = spec.upper_bound ? spec.upper_bound(p) : std::nullopt;
    if (upper && !(value < *upper)) {
      refusals.push_back({.kind = RefusalKind::not_below_bound,
                          .key = std::string(spec.key),
                          .spec = &spec,
                          .value = value,
                          .bound = *upper,
                          .unit = spec.unit,
                          .why = spec.upper_bound_why,
                          .bound_name = spec.upper_bound_name});
    }
  }
  return refusals;
}

std::optional<double> numeric_setting(const Parameters& p, std::string_view key) {
  const InputSpec* spec = find_input(key);
  if (spec == nullptr || spec->kind == InputKind::whole_number) {
    return std::nullopt;
  }
  return spec->value(p);
}

std::optional<InputRefusal> assign_text(Parameters& p, std::string_view key,
                                        std::string_view value) {
  const InputSpec* spec = find_input(key);
  if (spec == nullptr) {
    return InputRefusal{
        .kind = RefusalKind::unknown_key, .key = std::string(key), .typed = std::string(value)};
  }
  if (spec->kind == InputKind::choice) {
    if (spec->set_choice(p, value)) {
      return std::nullopt;
    }
    return text_refusal(RefusalKind::not_a_choice, *spec, value);
  }
  std::variant<double, InputRefusal> read = spec->kind == InputKind::whole_number
                                                ? read_whole_number(*spec, value)
                                                : read_quantity(*spec, value);
  if (InputRefusal* refusal = std::get_if<InputRefusal>(&read)) {
    return std::move(*refusal);
  }
  return assign_number(p, key, std::get<double>(read));
}

std::optional<InputRefusal> assign(Parameters& p, const Assignment& assignment) {
  if (const double* number = std::get_if<double>(&assignment.value)) {
    return assign_number(p, assignment.key, *number);
  }
  return assign_text(p, assignment.key, std::get<std::string>(assignment.value));
}

namespace {

std::optional<std::string> sentence_of(const std::optional<InputRefusal>& refusal) {
  return refusal ? std::optional(refusal_sentence(*refusal)) : std::nullopt;
}

}  // namespace

std::optional<std::string> set_input(Parameters& p, std::string_view key, double value) {
  return sentence_of(assign_number(p, key, value));
}

std::optional<std::string> apply_setting(Parameters& p, std::string_view key,
                                         std::string_view value) {
  return sentence_of(assign_text(p, key, value));
}

std::optional<std::string> apply_assignment(Parameters& p, const Assignment& assignment) {
  return sentence_of(assign(p, assignment));
}

std::vector<std::string> repeated_keys(const std::vector<std::string>& assignments,
                                       std::string_view option) {
  std::vector<std::string> problems;
  std::vector<std::string_view> reported;
  // K is c at the Poisson ratio in force: K=... and c=... set one field, and K, applied last,
  // would win without a word.
  const auto input_of = [](std::string_view assignment) {
    const std::string_view key = assignment.substr(0, assignment.find('='));
    const InputSpec* spec = find_input(key);
    return spec != nullptr && spec->kind == InputKind::stiffness_K ? std::string_view("c") : key;
  };
  for (std::size_t i = 0; i < assignments.size(); ++i) {
    const std::string_view input = input_of(assignments[i]);
    if (input.empty() || std::find(reported.begin(), reported.end(), input) != reported.end()) {
      continue;
    }
    std::vector<std::string> givers{std::string(option) + " " + detail::cut(assignments[i])};
    bool one_key = true;
    for (std::size_t j = i + 1; j < assignments.size(); ++j) {
      if (input_of(assignments[j]) == input) {
        givers.push_back(std::string(option) + " " + detail::cut(assignments[j]));
        one_key = one_key && assignments[j].substr(0, assignments[j].find('=')) ==
                                 assignments[i].substr(0, assignments[i].find('='));
      }
    }
    if (givers.size() > 1) {
      reported.push_back(input);
      // Thousands of copies are one problem: the first few quoted, the rest counted.
      constexpr std::size_t kQuoted = 3;
      std::string last = givers.back();
      givers.pop_back();
      if (givers.size() > kQuoted) {
        last = std::to_string(givers.size() + 1 - kQuoted) + " more";
        givers.resize(kQuoted);
      }
      problems.push_back(
          detail::join(givers, ", ") + " and " + last +
          (one_key ? ": duplicate key (each key may appear once; which one is meant?)"
                   : ": c and K set the same input (K = c / (1 - nu²)); which one is meant?"));
    }
  }
  return problems;
}

std::vector<std::string> apply_assignments(Parameters& p,
                                           const std::vector<std::string>& assignments) {
  std::vector<std::string> errors;
  std::vector<std::pair<std::string, std::string>> deferred;
  for (const std::string& assignment : assignments) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
      errors.push_back("'" + detail::cut(assignment) + "' is not KEY=VALUE");
      continue;
    }
    std::string key = assignment.substr(0, eq);
    std::string value = assignment.substr(eq + 1);
    if (key == "K") {
      deferred.emplace_back(std::move(key), std::move(value));
      continue;
    }
    if (auto error = apply_setting(p, key, value)) {
      errors.push_back(*error);
    }
  }
  for (const auto& [key, value] : deferred) {
    if (auto error = apply_setting(p, key, value)) {
      errors.push_back(*error);
    }
  }
  return errors;
}

}  // namespace foldlab
