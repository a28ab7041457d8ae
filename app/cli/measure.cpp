#include "app/cli/measure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/analysis/fold_measurement.hpp"
#include "core/io/image.hpp"
#include "core/io/measurements.hpp"
#include "core/model/settings.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace measure_command {
namespace {

using detail::printf_string;

// "A0,A1,..." into numbers; InputError naming the option otherwise.
std::vector<double> number_list(const std::string& option, const std::string& text,
                                std::size_t at_least, std::size_t exactly = 0) {
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma - start);
    const std::optional<double> value = parse_number(item);
    if (!value) {
      throw InputError(option + " " + detail::cut(text) + ": \"" + detail::cut(item) +
                       "\" is not a number (give numbers separated by commas)");
    }
    out.push_back(*value);
    if (comma == std::string::npos) {
      break;
    }
    start = comma + 1;
  }
  if (exactly != 0 && out.size() != exactly) {
    throw InputError(option + " " + detail::cut(text) + ": expected " + std::to_string(exactly) +
                     " numbers, got " + std::to_string(out.size()));
  }
  if (out.size() < at_least) {
    throw InputError(option + " " + detail::cut(text) + ": expected at least " +
                     std::to_string(at_least) + " numbers, got " + std::to_string(out.size()));
  }
  return out;
}

// The photo's size in pixels; InputError when it is not an image FoldLab reads or is too large.
std::pair<int, int> photo_size(const std::string& path) {
  Image image;
  try {
    // Decoded in full, not only its header read: a file cut short or corrupt after a sound header
    // would otherwise give pixel positions on a picture that does not exist.
    image = load_image(path);
  } catch (const ImageError& e) {
    throw InputError(std::string("--photo ") + e.what());
  }
  if (std::all_of(image.rgba.begin(), image.rgba.end(),
                  [&](std::uint32_t pixel) { return pixel == image.rgba.front(); })) {
    throw InputError("--photo " + detail::cut(path, 200) +
                     ": every pixel has the same colour, so no fold can be seen on it (a blank "
                     "or corrupt file?)");
  }
  return {image.width_px, image.height_px};
}

void check_inside(const std::string& option, const std::vector<double>& values, bool x_and_y,
                  std::pair<int, int> size) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const bool is_x = x_and_y && i % 2 == 0;
    const double limit = is_x ? size.first : size.second;
    if (!(values[i] >= 0.0 && values[i] <= limit)) {
      throw InputError(option + ": " + (is_x ? "x" : "y") + " = " +
                       detail::shortest_number(values[i]) + " px lies outside the photo (" +
                       std::to_string(size.first) + " x " + std::to_string(size.second) + " px)");
    }
  }
}

std::string number_text(const std::vector<double>& values) {
  std::vector<std::string> items;
  for (double v : values) {
    items.push_back(printf_string("%.4g", v));
  }
  return detail::join_comma(items);
}

// Either depths or a photo with its supports and folds, never both: true for depths.
bool by_depth(const Options& o) {
  const bool depths = !o.depths_mm.empty();
  const bool photo = !o.photo.empty() || !o.supports_px.empty() || !o.folds_px.empty();
  const std::string either =
      "--depths-mm A0,A1,... or --photo FILE --supports-px X1,Y1,X2,Y2 --folds-px Y0,Y1,...";
  if (!depths && !photo) {
    throw InputError("measure needs the folds, and none were given: " + either);
  }
  if (depths && photo) {
    throw InputError("measure takes either " + either + ", not both");
  }
  if (photo) {
    for (const auto& [option, value] :
         {std::pair{"--photo", &o.photo}, std::pair{"--supports-px", &o.supports_px},
          std::pair{"--folds-px", &o.folds_px}}) {
      if (value->empty()) {
        throw InputError(std::string(option) +
                         " is missing: a photo needs --photo, --supports-px and --folds-px");
      }
    }
  }
  return depths;
}

void check_name(const std::string& name) {
  // The name goes into the row and the JSON output, which hold UTF-8 only.
  if (!detail::is_valid_utf8(name)) {
    throw InputError("--name '" + detail::cut(name) + "' is not UTF-8 text");
  }
  // One line of text: a CSV cell holds no line break, and a terminal escape in a file's
  // names would reach every screen that prints them.
  if (detail::escaped(name) != name) {
    throw InputError("--name '" + detail::cut(name) +
                     "' holds a control character (a line break, an escape): give one line "
                     "of text");
  }
}

void check_z_max(const std::optional<double>& z_max_mm) {
  // In the words of the rule a measurements file is read by, which refuses 0 too.
  if (z_max_mm && !(*z_max_mm > 0.0 && std::isfinite(*z_max_mm))) {
    throw InputError("--z-max-mm " + detail::shortest_number(*z_max_mm) +
                     " must be > 0: an observed depth is compared by ratio");
  }
}

// A depth beyond what the cloth can hang to (`reach_mm`, said as `reach` with its value) is a
// typing error (a unit off, say), not a measurement: the z_max and the folds' depths alike.
void check_reach(const std::string& what, double depth_mm, double reach_mm,
                 const std::string& reach) {
  if (depth_mm > reach_mm) {
    throw InputError(what + " is deeper than " + reach + ", which no fold of this cloth can reach");
  }
}

// The upper edge is held at its supports, so no point of it lies further than half its length L
// from them.
void check_z_max_reach(const std::optional<double>& z_max_mm, const Parameters& p) {
  const double half_mm = 0.5 * p.hanging.length_mm;
  if (z_max_mm) {
    check_reach("--z-max-mm " + detail::shortest_number(*z_max_mm), *z_max_mm, half_mm,
                "half the upper edge, L/2 = " + detail::shortest_number(half_mm) + " mm");
  }
}

// The centre line hangs from the supports' line down to the cloth's lower boundary, which the
// model puts at a_0 = 1.01 h: a fold below it is not on this cloth. The bound is the model's, so
// that the amplitudes `solve` prints are accepted back.
void check_depths_reach(const std::string& option, const std::vector<double>& depths_mm,
                        const Parameters& p) {
  const double boundary_mm = kLowerBoundaryFactor * p.hanging.height_mm;
  const std::string reach = "the cloth's lower boundary at the centre, " +
                            detail::shortest_number(kLowerBoundaryFactor) +
                            " h = " + detail::shortest_number(boundary_mm) +
                            " mm at h = " + detail::shortest_number(p.hanging.height_mm) + " mm";
  for (std::size_t i = 0; i < depths_mm.size(); ++i) {
    check_reach(option + ": depth " + std::to_string(i) + " = " +
                    detail::shortest_number(depths_mm[i]) + " mm",
                depths_mm[i], boundary_mm, reach);
  }
}

// The folds' depths in mm, typed or from the photo's pixels (scaled by the span l).
std::vector<double> measured_depths(const Options& o, bool depths, const Parameters& p) {
  try {
    if (depths) {
      return number_list("--depths-mm", o.depths_mm, 1);
    }
    const std::vector<double> supports = number_list("--supports-px", o.supports_px, 4, 4);
    const std::vector<double> folds = number_list("--folds-px", o.folds_px, 1);
    const std::pair<int, int> size = photo_size(o.photo);
    check_inside("--supports-px", supports, true, size);
    check_inside("--folds-px", folds, false, size);
    return depths_from_pixels({supports[0], supports[1]}, {supports[2], supports[3]}, folds,
                              span_mm(p));
  } catch (const FoldMeasurementError& e) {
    throw InputError("--" + e.input() + (e.input() == "depths" ? "-mm" : "-px") + ": " + e.what());
  }
}

MeasurementSet one_row(const Measurement& row) {
  MeasurementSet set;
  set.rows.push_back(row);
  return set;
}

// The rules `calibrate` reads a row by: a row it would refuse is no measurement.
void check_row(const Measurement& row) {
  try {
    (void)measurements_from_csv(measurements_to_csv(one_row(row)), "the measured row");
  } catch (const MeasurementError& e) {
    throw InputError(e.what());
  }
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "measure",
      "n and Q of folds measured on a real cloth (a least-squares fit of ln a_i against i), and "
      "the measurements row that `foldlab calibrate --data` reads");
  command
      ->add_option("--preset", options.preset_path,
                   "the cloth's preset: its fabric and hanging go into the row, its span l "
                   "scales a photo (default: the built-in preset)")
      ->check(app::non_empty_path());
  command
      ->add_option("--set", options.assignments,
                   "override an input of the cloth, KEY=VALUE (see `foldlab solve --help`)")
      ->type_name("KEY=VALUE");
  command->add_option("--depths-mm", options.depths_mm,
                      "the folds' depths below the supports' line at the centre, lowest first "
                      "(a_0, a_1, ..., a_n in mm)");
  command
      ->add_option("--photo", options.photo,
                   "a front photo of the hanging cloth (PNG or JPEG) that the pixels refer to")
      ->check(app::non_empty_path());
  command->add_option("--supports-px", options.supports_px,
                      "the two supports in the photo, X1,Y1,X2,Y2 (pixels, y downward): their "
                      "distance is the span l");
  command->add_option("--folds-px", options.folds_px,
                      "the pixel rows where the folds cross the centre line, lowest first");
  command->add_option("--z-max-mm", options.z_max_mm,
                      "the largest out-of-plane depth, if measured (a front photo does not show "
                      "it)");
  command->add_option("--name", options.name, "a label for the row");
  command
      ->add_option("--append", options.append_path,
                   "add the row to this measurements file, .csv or .json (created with its "
                   "header if absent)")
      ->check(app::non_empty_path());
  command->add_flag("--json", options.json, "print JSON instead of text");
}

Result run(const Options& options) {
  const bool depths = by_depth(options);
  check_name(options.name);
  check_z_max(options.z_max_mm);
  const Preset preset = resolve_inputs({options.preset_path, options.assignments, "", ""});
  // Before the photo is measured: a missing folder is known at once.
  check_outputs({{"--append", options.append_path}},
                {app::preset_input("--preset", options.preset_path), {"--photo", options.photo}});
  const Parameters& p = preset.parameters;
  check_z_max_reach(options.z_max_mm, p);
  const std::vector<double> depths_mm = measured_depths(options, depths, p);
  Result result;
  result.z_max_mm = options.z_max_mm;
  result.append_path = options.append_path;
  try {
    result.folds = measure_folds(depths_mm);
  } catch (const FoldMeasurementError& e) {
    throw InputError(std::string(depths ? "--depths-mm" : "--folds-px") + ": " + e.what());
  }
  check_depths_reach(depths ? "--depths-mm" : "--folds-px", depths_mm, p);
  app::check_output_extension("--append", options.append_path, {".csv", ".json"},
                              "a measurements file, CSV or JSON by its extension");
  result.row = measurement_row(p, result.folds, options.z_max_mm, options.name);
  check_row(result.row);
  return result;
}

void append_row(const Result& result) {
  if (result.append_path.empty()) {
    return;
  }
  try {
    append_measurement(result.append_path, result.row);
  } catch (const MeasurementError& e) {
    throw InputError(std::string("--append: ") + e.what());
  }
}

void print_text(const Result& result, std::ostream& out) {
  const FoldMeasurement& folds = result.folds;
  out << "n = " << folds.n << "\nQ = " << printf_string("%.4g", folds.Q)
      << "\na_mm = " << number_text(folds.a_mm)
      << "\nfit_residual = " << printf_string("%.3g", folds.fit_residual)
      << " (rms of ln a_i about the fitted line)\n";
  out << (result.append_path.empty()
              ? "row (not appended: no --append):\n"
              : "row appended to " + detail::escaped(result.append_path) + ":\n");
  // The row holds the name as given: echoed, its control characters are spelt out.
  std::istringstream lines(measurements_to_csv(one_row(result.row)));
  for (std::string line; std::getline(lines, line);) {
    out << detail::escaped(line) << "\n";
  }
}

nlohmann::json print_json(const Result& result) {
  const FoldMeasurement& folds = result.folds;
  return {{"n", folds.n},
          {"Q", folds.Q},
          {"a_mm", folds.a_mm},
          {"fit_residual", folds.fit_residual},
          {"z_max_mm", optional_json(result.z_max_mm)},
          {"row", measurements_to_json(one_row(result.row))["rows"][0]},
          {"appended_to", result.append_path.empty() ? nlohmann::json(nullptr)
                                                     : nlohmann::json(result.append_path)}};
}

int execute(const Options& options) {
  const Result result = run(options);
  append_row(result);
  print_result(result, options.json, &print_text);
  return kExitOk;
}

}  // namespace measure_command

Command add_measure_command(CLI::App& app) {
  return make_command(app, measure_command::declare, measure_command::execute);
}

}  // namespace foldlab::cli
