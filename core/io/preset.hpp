// Presets: versioned JSON files with the units in every key (see presets/README.md for the format).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/field/outline.hpp"
#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

inline constexpr int kPresetFormatVersion = 1;

// Results printed in the paper for the case a preset reproduces; any of them may be absent.
struct PublishedResult {
  std::optional<int> n;
  std::optional<double> z_max_mm;
  std::optional<double> Q;
};

// The most entries a stored calibration's equally_good or leave_one_out list may hold. Every entry
// is solved again at each solve (about 40 ms each), and a fit writes two equally-good ends and one
// leave-one-out fit per row of a small data set, so 64 leaves room for real records and keeps a
// preset's solve under a few seconds.
inline constexpr std::size_t kMaxCalibrationEntries = 64;

// Where a preset's eq. 7 constants come from, with what else fitted the same data as well: the
// prediction ranges (core/analysis/uncertainty.hpp) evaluate these stored constants rather than
// calibrating again at every solve.
// One fit row's leave-one-out residual: what was observed minus what the fit without the row
// predicts for it; n as a difference, z_max and Q as natural-log ratios (they scale). Absent where
// the row observed nothing, or the prediction has no folds to compare.
// The bounds a stored residual keeps, so that every interval built from it is finite: n misses
// by at most the solver's fold cap (a prediction cannot count more), and z_max and Q by at most a
// factor of 1e6 either way (ln 1e6), far beyond any fit worth storing and far from exp's overflow
// at 709. held_out_residual() clamps to them, so a calibration never writes what the reader
// refuses.
inline constexpr double kMaxResidualFolds = kMaxWrinkles;
inline constexpr double kMaxLogResidual = 13.815510557964274;  // ln 1e6
struct HeldOutResidual {
  std::optional<double> n;
  std::optional<double> log_z_max;
  std::optional<double> log_Q;

  bool operator==(const HeldOutResidual&) const = default;
};

struct CalibrationRecord {
  std::string calibrated_on;  // the data, for labels: "Conci's Tables 1–2"
  Method method = Method::exact;
  WrinkleLawKind law = WrinkleLawKind::conci;  // the constants are this law's
  Eq7Constants fitted;                         // the constants the preset was given
  int fit_rows = 0;
  // Constants at the ends of the set that scores as well as `fitted` on the same data.
  std::vector<Eq7Constants> equally_good;
  // The fits on the data without one row each (empty when there was only one row).
  std::vector<Eq7Constants> leave_one_out;
  // The residual of each leave-one-out fit on the row it left out, in leave_one_out's order: with
  // those fits they make the prediction intervals (core/analysis/uncertainty.hpp).
  std::vector<HeldOutResidual> residuals;
  // How often such intervals covered rows they were not fitted to, in words (empty: not measured).
  std::string coverage;

  bool operator==(const CalibrationRecord&) const = default;
};

// An sRGB colour, 8 bits a channel, as a preset stores it: "#8b1a2b".
struct ColourRgb8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;

  bool operator==(const ColourRgb8&) const = default;
};

// "#RRGGBB" (either case) to a colour; nothing for any other text.
std::optional<ColourRgb8> parse_hex_colour(std::string_view text);
// The colour as "#rrggbb", lower case, which parse_hex_colour reads back.
std::string hex_colour(ColourRgb8 colour);

// How the fabric looks, apart from what the model computes: absent parts keep the views' own.
struct Appearance {
  std::optional<ColourRgb8> colour;  // the cloth's front face

  bool operator==(const Appearance&) const = default;
};

struct Preset {
  std::string name;
  std::string description;
  std::string source;  // where the numbers come from
  // The name of the preset this one was saved from in the explorer; empty for an original.
  std::string derived_from;
  // The program that saved it, "FoldLab 0.1.0 (66ffc2b)"; empty for the shipped presets, which
  // are written by hand. Kept as read, written when not empty.
  std::string written_by;
  Parameters parameters;
  PublishedResult published;
  std::optional<CalibrationRecord> calibration;
  Appearance appearance;
  // A designer's own cut for the tension field, read and checked as `field --outline` reads its
  // file; none: the field is solved on the cut of the shape.
  std::optional<field::Outline> outline;
};

// A preset that cannot be read: the message names the file, the key (as a JSON pointer) and the
// problem, one line per problem.
class PresetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `origin` names the source in messages (a file path, or "<default preset>").
Preset preset_from_json(const nlohmann::json& j, const std::string& origin);
Preset preset_from_text(const std::string& text, const std::string& origin);
nlohmann::json preset_to_json(const Preset& preset);

Preset load_preset(const std::filesystem::path& path);
// Writes a temporary file beside `path`, flushes it to disk and renames it over `path`, so that a
// crash leaves either the old file or the new one, never half of one. Throws PresetError for
// parameters out of range, WriteError (io.hpp) for a file that cannot be written.
void save_preset(const Preset& preset, const std::filesystem::path& path);

// The default preset (Table 1, h = 1400 mm: the case of the paper's Fig. 5), compiled in from
// presets/paper-table1-h1400.json so that it is there without the presets folder.
const Preset& default_preset();

}  // namespace foldlab
