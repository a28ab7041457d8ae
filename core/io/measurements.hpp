// Measured hangings: the inputs of one experiment (t, E, w, h, L, d in mm, MPa, N/mm²) and what was
// observed (n, z_max, Q; any of them may be missing), read from CSV or JSON for `foldlab
// calibrate`. The format is described in docs/calibration.md.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/io/preset.hpp"
#include "core/model/parameters.hpp"

namespace foldlab {

inline constexpr int kMeasurementsFormatVersion = 1;

// The plausible observations a row may give; beyond them a value is a typing error (a unit or a
// few digits off), not a measurement. n: `foldlab measure` takes at most 1000 depths, more folds
// than any photo shows, and a calibration follows n to 4 times the observed n, which above this
// would take minutes per row. Q: consecutive folds 100 times apart no longer look like a series
// of folds. z_max: no point of the held upper edge lies further than L/2 from its supports.
inline constexpr int kMaxObservedFolds = 1000;
inline constexpr double kMaxObservedRatio = 100.0;

// `fit` rows are what a calibration fits; `check` rows are never fitted and are always reported as
// held out (the paper's Fig. 4, whose d is assumed, is one).
enum class MeasurementRole { fit, check };

struct Measurement {
  std::string name;   // optional label, e.g. "Table 1, h = 900 mm"
  std::string group;  // optional series, e.g. "table1": held-out validation fits on the others
  MeasurementRole role = MeasurementRole::fit;
  // The row's inputs: the input table's required rows (t, E, w, h, L, d) as measured; the other
  // fields are not part of a row and come from the base a calibration solves it with.
  Parameters inputs;
  // Optional: the cloth's shape by its ShapeKind name (shape.hpp). Recorded, not used by the fit:
  // the solver is the same for every shape.
  std::string shape;
  PublishedResult observed;  // n, z_max_mm, Q; at least one of them is present
  int row = 0;               // 1-based data row in the file, for messages
};

struct MeasurementSet {
  std::string origin;  // the file, for messages
  std::string description;
  std::string source;
  std::vector<Measurement> rows;
};

// A file that cannot be read: one line per problem, each naming the file, the row and the column.
class MeasurementError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The columns of the CSV header and the keys of a JSON row, in the order the writers use.
// Required: t_mm, E_MPa, w_N_per_mm2, h_mm, L_mm, d_mm. Optional: name, group, role (fit |
// check), shape, and the observations n in [0, kMaxObservedFolds], z_max_mm in (0, L/2], Q in
// (1, kMaxObservedRatio] (at least one per row).
const std::vector<std::string_view>& measurement_columns();

// CSV: one header line naming the columns (any order), then one row per line; fields may be
// quoted ("a, b"; "" for a quote); an empty field is a missing value; blank lines and lines
// starting with # are skipped. Throws MeasurementError listing every problem at once.
MeasurementSet measurements_from_csv(const std::string& text, const std::string& origin);
// JSON: {"foldlab_measurements": 1, "description": ..., "source": ..., "rows": [{column: value}]}
// with the CSV's column names as keys; a missing observation is absent or null.
MeasurementSet measurements_from_json(const nlohmann::json& j, const std::string& origin);
// By extension (.csv or .json), else by content (JSON starts with '{').
MeasurementSet measurements_from_text(const std::string& text, const std::string& origin,
                                      std::string_view extension);
MeasurementSet load_measurements(const std::filesystem::path& path);

// Writers that the readers read back to the same rows (numbers in their shortest exact form).
// The CSV carries the description and source as leading comment lines.
std::string measurements_to_csv(const MeasurementSet& set);
nlohmann::json measurements_to_json(const MeasurementSet& set);

// Adds one row to a measurements file, creating a CSV file with its header when there is none. An
// existing file must read as it is (so the result is a file `calibrate` reads) and keeps its
// format, comments and column order; a row value with no column there is refused. Appends from
// several processes at once each keep their row: the file is locked (flock) from reading to
// replacing it, and replaced atomically. Throws
// MeasurementError (the file's problems, or a write error).
void append_measurement(const std::filesystem::path& path, const Measurement& row);

// `base` with the measured fabric and hanging put in (its model settings and Poisson ratio kept).
Parameters parameters_for(const Measurement& row, const Parameters& base);

std::string_view to_string(MeasurementRole role);
bool parse_measurement_role(std::string_view s, MeasurementRole& out);

}  // namespace foldlab
