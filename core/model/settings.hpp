// The one table of inputs. Every front end reads an input from here: `--set KEY=VALUE`, presets,
// measurements files, reports, sweeps, the stress test's sampling ranges, the validation of
// physical ranges and the explorer's sliders. Adding an input is one row in settings.cpp plus its
// physics (a field in Parameters and the code that uses it).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/model/parameters.hpp"

namespace foldlab {

enum class InputKind {
  number,        // a real number in a field of Parameters
  whole_number,  // an int field
  stiffness_K,   // K = c / (1 - nu²): derived, sets c at the Poisson ratio in force
  choice,        // one of a few names (method, span rule, ...)
};

enum class InputScale { linear, logarithmic };

// Where the Parameters panel shows an input.
enum class InputPlace {
  none,     // typed only: presets, --set, sweeps
  list,     // the panel's list: a slider the play button can animate (a beginner sees those that
            // are not `expert`), or a choice's box among the expert's settings
  after,    // a slider after the list, with the model's constants, not animated (p)
  readout,  // a line after the list reading its value (c, which the K slider sets)
  shape,    // with the shape's own rows, when the shape uses it (supports, incline)
};

// A unit a value may be typed in: `symbol` as shown, `per_unit` the stored value of one of it
// (1 g/m² is 9.81e-9 N/mm²), `format` how a value in it is shown, and `plain`, when the symbol
// needs more than letters, a name of it in letters alone, written in links ("gsm" for g/m²).
// A symbol is read in its own case, as SI writes it (m is a metre, M would be mega); a plain
// name, which no prefix can change, in any case ("gsm", "GSM").
struct InputUnit {
  std::string_view symbol{};
  double per_unit = 1.0;
  std::string_view format{};
  std::string_view plain{};
};

// How a row reads and writes its value in Parameters: a number, a whole number (stored as int)
// or K (derived: c at the Poisson ratio in force). `set` stores without range checks.
struct InputAccess {
  double (*get)(const Parameters&) = nullptr;
  void (*set)(Parameters&, double) = nullptr;
};

// The access of a field of Parameters: input_field<&Parameters::fabric, &Fabric::thickness_mm>().
template <auto Group, auto Member>
constexpr InputAccess input_field() {
  return {[](const Parameters& p) { return static_cast<double>((p.*Group).*Member); },
          [](Parameters& p, double v) {
            auto& field = (p.*Group).*Member;
            field = static_cast<std::remove_cvref_t<decltype(field)>>(v);
          }};
}

// An interval with open or closed ends.
struct InputInterval {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const;
  // "[0.001, 50]" or "[0, 0.5)": for messages.
  std::string text() const;
};

struct InputSpec {
  std::string_view key{};     // as typed after --set, and the sweep axis: "t", "E", ...
  std::string_view name{};    // what it is, for labels and help: "thickness"
  std::string_view symbol{};  // as the paper writes it where that is not the key: "ν" for nu
  std::string_view unit{};    // "mm", "MPa", ...; empty when dimensionless
  // What its units measure, for a message about a unit that is not one: "length"; empty: the
  // input's own name.
  std::string_view quantity{};
  std::string_view field{};   // validation and report name, with the unit: "t_mm"
  std::string_view preset{};  // JSON pointer in a preset file: "/fabric/thickness_mm"; empty: none
  std::string_view help{};    // one line for help texts and tooltips
  InputKind kind = InputKind::number;
  // Values that can describe a cloth; outside them validate() refuses, saying `why`.
  InputInterval valid{};
  std::string_view why{};
  // An open upper end that follows from other inputs (d below L/2), checked by validate() after
  // `valid`, named `upper_bound_name` with the reason `upper_bound_why`; nullopt while the inputs
  // it follows from are refused themselves.
  std::optional<double> (*upper_bound)(const Parameters&) = nullptr;
  std::string_view upper_bound_name{};
  std::string_view upper_bound_why{};
  // Where values of real fabrics lie: the slider's ends and the stress test's sampling range.
  double typical_lo = 0.0;
  double typical_hi = 0.0;
  // Where the cloths one buys lie, narrower than `typical`: the beginner's slider, so that a
  // pixel of it is a step a person can see. Both zero: the beginner's slider is the typical one.
  double beginner_lo = 0.0;
  double beginner_hi = 0.0;
  InputScale scale = InputScale::linear;
  std::string_view format{};  // printf format of the value alone, e.g. "%.3g"
  bool required = false;      // must appear in a preset
  bool expert = false;        // a model setting rather than a property of the cloth
  // One of the numbers that say which cloth hangs how, as the paper's experiments vary them (t,
  // E, w, h, L, d): the strip over a presented view, a picture's caption, the benchmark's
  // realistic cloths and the beginner's help list the cloth inputs, in table order.
  bool cloth = false;
  InputPlace place = InputPlace::none;
  // A new sweep, map or animation axis over this input starts over its typical range rather than
  // around the value in force (a decade either way on a log scale, 0.3 to 3 times on a linear
  // one): for an input whose whole range is narrow (ν).
  bool axis_over_typical = false;
  // Units besides `unit` a value may be typed in, and which of all (0: `unit`) the explorer shows.
  std::span<const InputUnit> other_units{};
  std::size_t shown_unit = 0;
  std::string_view choices{};  // for InputKind::choice: "paper, exact"
  // The stress test draws this input over its typical range (below upper_bound), and its report
  // names it in each case.
  bool sampled = false;
  // Where the benchmark's realistic cloths draw a cloth input, log-uniformly: from realistic_lo to
  // realistic_hi or, for an input whose upper end follows from others, to this part of
  // upper_bound (d: up to 0.6 of L/2).
  double realistic_lo = 0.0;
  double realistic_hi = 0.0;
  double realistic_part_of_upper_bound = 0.0;
  InputAccess access{};  // for number, whole_number and stiffness_K
  bool (*set_choice)(Parameters&, std::string_view) = nullptr;  // for choice
  std::string_view (*choice)(const Parameters&) = nullptr;      // for choice

  // The value of a number, whole number or K; nullopt for a choice.
  std::optional<double> value(const Parameters& p) const;
};

// Every input, in the order help texts and reports list them.
const std::vector<InputSpec>& input_table();
// The row of a key, or nullptr.
const InputSpec* find_input(std::string_view key);
// The row whose `field` (validation name, "t_mm") is this, or nullptr.
const InputSpec* find_input_by_field(std::string_view field);

// The cloth inputs (`cloth`), in table order: t, E, w, h, L, d.
std::vector<const InputSpec*> cloth_inputs();

// "t (mm)" or "nu": a key with its unit, for axis labels and tables.
std::string input_label(const InputSpec& spec);

// Why a value given for an input is refused, as data. Reading and storing a value yield one of
// these rather than a sentence; the sentence is built from it by refusal_sentence() (or, for a
// sentence that quotes the value in its own words, refusal_reason()) where it is shown.
enum class RefusalKind {
  unknown_key,        // no row has `key`
  not_a_choice,       // a choice given a name it does not take
  number_for_choice,  // a choice given a number
  not_a_number,       // no number, arithmetic or number with one of the row's units
  nested_too_deeply,  // arithmetic nested more than kMaxArithmeticDepth parentheses deep
  unknown_unit,       // a number followed by a name that is none of the row's units
  beyond_double,      // a number or a result a double cannot hold (1e999, 1e-999, 1e200*1e200)
  divides_by_zero,    // arithmetic that divides by zero (1/0)
  not_whole,          // a whole-number row given a fraction
  out_of_range,       // outside `range`, past `bound`
  not_below_bound,    // at or above the bound that follows from other inputs (d below L/2)
};

struct InputRefusal {
  RefusalKind kind = RefusalKind::not_a_number;
  std::string key{};                // as given
  const InputSpec* spec = nullptr;  // its row; nullptr for unknown_key
  std::string typed{};              // the text as typed; empty for a value given as a number
  // not_whole, out_of_range, not_below_bound: the value and the end it crossed, in `unit`.
  double value = 0.0;
  double bound = 0.0;
  std::string_view unit{};        // the row's own (stored) unit; empty when dimensionless
  InputInterval range{};          // out_of_range: the interval refused from, in `unit`
  std::string_view why{};         // out_of_range, not_below_bound: why values end there
  std::string_view bound_name{};  // not_below_bound: "L/2"
  // unknown_unit: the unit as typed ("M") and a unit of the row it differs from only in case.
  std::string typed_unit{};
  std::string_view meant_unit{};
};

// The sentence for a refusal, as the command line, a link's note and validate() say it:
// "h = '2.4M': 'M' is not a unit of length (known: mm, cm, m); did you mean 'm'?", "weight per
// area w = −5 g/m² must be between 0.1 and 1,000,000 g/m²: WHY".
std::string refusal_sentence(const InputRefusal& refusal);
// For a refusal of typed text (not_a_choice, not_a_number, nested_too_deeply, unknown_unit,
// beyond_double, divides_by_zero): the rest of a sentence that has just quoted the text, ": 'M' is
// not a unit of length (known: mm, cm, m); did you mean 'm'?", " is not a number".
std::string refusal_reason(const InputRefusal& refusal);
// The refusal of `value` (stored unit) of `spec` for lying outside `range`, for `why`.
InputRefusal range_refusal(const InputSpec& spec, double value, const InputInterval& range,
                           std::string_view why);
// "t, E, w, ...": every key, as a sentence about an unknown key lists them.
std::string known_keys();

// Sets one input from its text: a number (or arithmetic, with an optional unit) or a choice's
// name; then assign_number() stores it. `K` sets c so that c / (1 - nu²) = K at the Poisson
// ratio in force: apply it after `nu`. A refusal for an unknown key, or a value that cannot be
// read; a value out of range is stored, for validate() to name.
std::optional<InputRefusal> assign_text(Parameters& p, std::string_view key,
                                        std::string_view value);
// The one way a value reaches a field of Parameters, for text (assign_text), sliders, sweeps,
// scripts and map clicks alike. Stores the value and leaves range checks to validate(), so that a
// refused value is kept as typed with its reason; a refusal only for an unknown key, a choice,
// or a whole number given a fraction (or beyond what its field holds). K sets c at the Poisson
// ratio in force.
std::optional<InputRefusal> assign_number(Parameters& p, std::string_view key, double value);

// Every input of `p` out of its row's range, or at or above the bound that follows from the
// other inputs (d below L/2), in the table's order: what validate() names for the rows.
std::vector<InputRefusal> input_refusals(const Parameters& p);

// assign_text and assign_number with the refusal as its sentence.
std::optional<std::string> apply_setting(Parameters& p, std::string_view key,
                                         std::string_view value);
std::optional<std::string> set_input(Parameters& p, std::string_view key, double value);
std::optional<double> numeric_setting(const Parameters& p, std::string_view key);

// One input set by its key: to a number (assign_number) or to text, a choice's name or a number
// with a unit (assign_text).
struct Assignment {
  std::string key;
  std::variant<double, std::string> value;
};
std::optional<InputRefusal> assign(Parameters& p, const Assignment& assignment);
std::optional<std::string> apply_assignment(Parameters& p, const Assignment& assignment);

// Every key that more than one of the "KEY=VALUE" assignments sets, as a sentence naming them
// after `option`: "--set h=2.4m and --set h=1000: duplicate key (each key may appear once; which
// one is meant?)". Applied in order, the last would win without a word, as a preset file does
// not allow either.
std::vector<std::string> repeated_keys(const std::vector<std::string>& assignments,
                                       std::string_view option);

// Applies "KEY=VALUE" assignments in order, except that every K comes after all the others
// (so `--set K=30 --set nu=0.2` means K = 30 at nu = 0.2). Returns every error at once.
std::vector<std::string> apply_assignments(Parameters& p,
                                           const std::vector<std::string>& assignments);

// Strict number parsing: the whole text must be one finite decimal number.
std::optional<double> parse_number(std::string_view text);

// The weight of 1 g/m² in N/mm², at the g = 9.81 m/s² the presets and their tables were made
// with: every conversion between g/m² and N/mm² uses this one number.
inline constexpr double kNPerMm2PerGramPerM2 = 9.81e-9;
// 1 oz/yd² in g/m²: 28.349523125 g (avoirdupois ounce) over 0.83612736 m² (square yard).
inline constexpr double kGramPerM2PerOuncePerYd2 = 28.349523125 / 0.83612736;

// The units a value of `spec` may be typed in, its own unit first (w: N/mm², g/m², oz/yd²;
// lengths: mm, cm, m); empty when it has none.
std::vector<InputUnit> input_units(const InputSpec& spec);
// The unit the explorer shows and takes `spec` in: the row's `shown_unit` (g/m² for w).
InputUnit shown_unit(const InputSpec& spec);
// A stored value in shown_unit(spec) and back: 1.5e-6 N/mm² is 152.9 g/m².
double to_shown_unit(const InputSpec& spec, double stored);
double from_shown_unit(const InputSpec& spec, double shown);
// The symbol as the paper writes it ("ν"), else the key.
std::string_view input_symbol(const InputSpec& spec);
// "w (g/m²)", "ν": the symbol with the shown unit, for the explorer's axes and tables.
std::string shown_label(const InputSpec& spec);

// How a sentence names an input, as its slider reads: "weight per area w", "Poisson's ratio ν".
std::string input_title(const InputSpec& spec);
// A stored value as a sentence for people shows it, in the shown unit: "−5 g/m²", "0.25 mm",
// "1,000,000 g/m²" (detail::message_number).
std::string shown_quantity(const InputSpec& spec, double stored);
// "80 g/m2", "80 g/m²", "80gsm", "2.4 oz/yd2", "1.5e-6 N/mm2", "2*153 g/m2", "(80 + 120)/2": a
// number or simple arithmetic of numbers (+ - * / and parentheses), optionally followed by
// one of input_units(spec) (spaces and ² vs 2 do not matter; case does, see InputUnit), as the
// value in the stored unit. A bare number is in `bare_unit` (a symbol from input_units, or empty
// for the stored unit). Else why it cannot be read (not_a_number, nested_too_deeply, unknown_unit,
// beyond_double): the text is read once, and the refusal says what it found.
std::variant<double, InputRefusal> read_quantity(const InputSpec& spec, std::string_view text,
                                                 std::string_view bare_unit = {});
// read_quantity's value; nullopt when the number or the unit cannot be read.
std::optional<double> parse_quantity(const InputSpec& spec, std::string_view text,
                                     std::string_view bare_unit = {});
// When `text` is a bare number (no unit) for an input that the explorer shows in another unit
// than it stores: what a bare number means here and how to write it in the shown unit ("a bare
// number for w is read in N/mm²; for 150 g/m² write w=150gsm"). nullopt otherwise.
std::optional<std::string> bare_number_hint(const InputSpec& spec, std::string_view text);

// The part of the slider's range (slider_ends) that validate() accepts with the other
// inputs of `p` as they are: d stops below L/2, L above 2d. Found by bisection against
// validate(), so that it follows whatever validation checks. The typical range itself when the
// value in `p` is refused (then nothing is known about where validity lies).
// A beginner's slider runs over the row's beginner range, where it has one; an expert's over
// the whole typical range. A value typed outside the slider is still taken when validate() does.
enum class SliderReach { beginner, expert };
InputInterval slider_ends(const InputSpec& spec, SliderReach reach);
InputInterval slider_interval(const InputSpec& spec, const Parameters& p,
                              SliderReach reach = SliderReach::expert);

}  // namespace foldlab
