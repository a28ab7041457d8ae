// The commands' parts called directly: run() computes and neither prints nor writes a file (the
// command's glue does both), and its result holds what the user's input implies.
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app/cli/bench.hpp"
#include "app/cli/calibrate.hpp"
#include "app/cli/compare.hpp"
#include "app/cli/export.hpp"
#include "app/cli/measure.hpp"
#include "app/cli/solve.hpp"
#include "app/cli/stress.hpp"
#include "app/cli/sweep.hpp"
#include "app/common/inputs.hpp"
#include "core/io/io.hpp"
#include "core/io/preset.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using namespace foldlab::cli;

namespace {

const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;
const fs::path kMeasurements = kPresetsDir.parent_path() / "data" / "paper-measurements.csv";

// What `work` printed on stdout and stderr together.
std::string printed_by(const std::function<void()>& work) {
  std::ostringstream captured;
  std::streambuf* out = std::cout.rdbuf(captured.rdbuf());
  std::streambuf* err = std::cerr.rdbuf(captured.rdbuf());
  try {
    work();
  } catch (...) {
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    throw;
  }
  std::cout.rdbuf(out);
  std::cerr.rdbuf(err);
  return captured.str();
}

class CliPartsTest : public foldlab::testing::TempDirTest {
 protected:
  CliPartsTest() : TempDirTest("foldlab_cli_parts_") {}
};

// Table 1's h = 1400 mm preset with h = 900 typed is Table 1's first row, solved by the paper's
// method: the paper printed n = 5 and Q = 1.31 for it.
TEST_F(CliPartsTest, SolveRunPrintsNothingAndItsPrintersShowTheSolution) {
  solve_command::Options options;
  options.inputs.preset_path = (kPresetsDir / "paper-table1-h1400.json").string();
  options.inputs.assignments = {"h=900"};
  solve_command::Result result;
  EXPECT_EQ(printed_by([&] { result = solve_command::run(options); }), "");
  EXPECT_EQ(result.preset.parameters.hanging.height_mm, 900.0);  // as typed
  const nlohmann::json j = solve_command::print_json(result);
  EXPECT_EQ(j.at("n"), 5);
  EXPECT_NEAR(j.at("Q").get<double>(), 1.31, 0.005);
  EXPECT_FALSE(j.contains("stats"));  // not asked for
  std::ostringstream text;
  solve_command::print_text(result, text);
  // "  number of wrinkles                 n                   5"
  const std::string printed = text.str();
  const std::size_t at = printed.find("number of wrinkles");
  ASSERT_NE(at, std::string::npos) << printed;
  const std::string line = printed.substr(at, printed.find('\n', at) - at);
  EXPECT_TRUE(line.ends_with(" 5")) << line;
}

TEST_F(CliPartsTest, ExportRunWritesNoFileTheGlueWritesThem) {
  export_command::Options options;
  const fs::path obj = dir_ / "cloth.obj";
  const fs::path svg = dir_ / "folds.svg";
  options.paths = {obj.string(), "", "", svg.string()};  // kExportFormats: obj, glb, csv, svg
  options.grid = "8x6";
  export_command::Result result;
  EXPECT_EQ(printed_by([&] { result = export_command::run(options); }), "");
  EXPECT_FALSE(fs::exists(obj));
  EXPECT_FALSE(fs::exists(svg));
  EXPECT_TRUE(result.mesh);
  EXPECT_TRUE(result.lines);
  export_command::write_files(options, result);
  // 8 x 6 vertices, as typed: one "v" line each in the OBJ.
  const std::string text = foldlab::read_text_file(obj, 1 << 20);
  std::istringstream lines(text);
  int vertices = 0;
  for (std::string line; std::getline(lines, line);) {
    vertices += line.rfind("v ", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(vertices, 48);
  EXPECT_TRUE(fs::exists(svg));
}

TEST_F(CliPartsTest, CompareGroupsRowsByTheTableInEachPresetsName) {
  compare_command::Options options;
  for (const char* file : {"paper-table1-h900.json", "paper-table2-w10.json",
                           "paper-table1-h1400.json", "fabric-denim-13oz.json"}) {
    options.presets.push_back((kPresetsDir / file).string());
  }
  compare_command::Result result;
  EXPECT_EQ(printed_by([&] { result = compare_command::run(options); }), "");
  // The denim carries no published results and is left out; the others keep their order.
  ASSERT_EQ(result.names.size(), 3u);
  EXPECT_EQ(result.names[0], "Table 1, h = 900 mm");
  EXPECT_EQ(result.names[2], "Table 1, h = 1400 mm");
  ASSERT_EQ(result.accuracy_by_table.size(), 2u);
  EXPECT_EQ(result.accuracy_by_table[0].group, "Table 1");
  EXPECT_EQ(result.accuracy_by_table[0].rows, 2);
  EXPECT_EQ(result.accuracy_by_table[1].group, "Table 2");
  EXPECT_EQ(result.accuracy_by_table[1].rows, 1);
  // Each row against the n the paper printed (Table 1: 5 at h = 900 mm and 7 at h = 1400 mm;
  // Table 2: 4 at w = 10e-7 N/mm²) and the n both methods give (docs/calibration.md: 5, 3, 8).
  const int printed_n[] = {5, 4, 7};
  const int model_n[] = {5, 3, 8};
  for (const auto& method_rows : result.rows) {
    ASSERT_EQ(method_rows.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      SCOPED_TRACE(result.names[i]);
      EXPECT_EQ(method_rows[i].published.n, printed_n[i]);
      EXPECT_EQ(method_rows[i].solution.n, model_n[i]);
      EXPECT_EQ(method_rows[i].n_difference, model_n[i] - printed_n[i]);
    }
  }
}

TEST_F(CliPartsTest, SweepRunCountsTheValuesTheOtherInputsRefuse) {
  sweep_command::Options options;
  options.inputs.assignments = {"L=1400"};
  options.axis.key = "d";
  options.axis.from = "300";
  options.axis.to = "800";
  options.axis.steps = 6;  // d = 300, 400, ..., 800; d must stay below L/2 = 700
  sweep_command::Result result;
  EXPECT_EQ(printed_by([&] { result = sweep_command::run(options); }), "");
  EXPECT_EQ(result.refused, 2);
  EXPECT_EQ(result.first_reason.rfind("d = 700: ", 0), 0u) << result.first_reason;
  ASSERT_EQ(result.notes.size(), 1u);
  std::ostringstream csv;
  sweep_command::print_csv(result, csv);
  EXPECT_NE(csv.str().find("\n700,,,,invalid,\n800,,,,invalid,\n"), std::string::npos) << csv.str();
}

TEST_F(CliPartsTest, MeasureRunFitsAGeometricProgressionAndAppendsOnlyInTheGlue) {
  measure_command::Options options;
  options.depths_mm = "80,40,20,10";  // each half the one below: Q = 2, n = 3
  const fs::path rows = dir_ / "rows.csv";
  options.append_path = rows.string();
  measure_command::Result result;
  EXPECT_EQ(printed_by([&] { result = measure_command::run(options); }), "");
  EXPECT_FALSE(fs::exists(rows));
  EXPECT_EQ(result.folds.n, 3);
  EXPECT_NEAR(result.folds.Q, 2.0, 1e-12);
  std::ostringstream text;
  measure_command::print_text(result, text);
  EXPECT_EQ(text.str().rfind("n = 3\nQ = 2\na_mm = 80, 40, 20, 10\n", 0), 0u) << text.str();
  measure_command::append_row(result);
  EXPECT_TRUE(fs::exists(rows));
}

TEST_F(CliPartsTest, CalibrateRunPrintsNothingAndSavesOnlyInTheGlue) {
  calibrate_command::Options options;
  options.data_path = kMeasurements.string();
  options.no_held_out = true;
  const fs::path saved = dir_ / "fitted.json";
  options.save_preset_path = saved.string();
  calibrate_command::Result result;
  EXPECT_EQ(printed_by([&] { result = calibrate_command::run(options); }), "");
  EXPECT_FALSE(fs::exists(saved));
  EXPECT_FALSE(result.interrupted);
  // The paper's six rows of Tables 1-2 (data/paper-measurements.csv), every one a fit row.
  EXPECT_EQ(result.report.fit_row_count, 6);
  EXPECT_FALSE(result.interval_level);  // JSON only
  calibrate_command::save_calibrated_preset(options, result);
  EXPECT_TRUE(fs::exists(saved));
}

TEST_F(CliPartsTest, BenchRunWritesNoFileTheGlueWritesThem) {
  bench_command::Options options;
  options.cases = 2;
  options.repeats = 1;
  options.no_pipeline = true;
  options.csv_path = (dir_ / "bench.csv").string();
  bench_command::Result result;
  EXPECT_EQ(printed_by([&] { result = bench_command::run(options); }), "");
  EXPECT_FALSE(fs::exists(options.csv_path));
  // The two random fabrics and the six printed rows of Tables 1-2 (three each).
  EXPECT_EQ(result.cases, 8u);
  EXPECT_EQ(result.table_rows, 6);
  EXPECT_TRUE(result.pipeline.empty());
  bench_command::write_files(options, result);
  EXPECT_TRUE(fs::exists(options.csv_path));
}

TEST_F(CliPartsTest, StressRunReadsTheSeedAsTyped) {
  stress_command::Options options;
  options.samples = 10;
  options.threads = 1;
  options.seed = "18446744073709551615";  // 2^64 - 1, the largest seed
  foldlab::StressReport report;
  EXPECT_EQ(printed_by([&] { report = stress_command::run(options); }), "");
  EXPECT_EQ(report.seed, 18446744073709551615ull);
  // Every sample solved once by each method, and a grid built for sample 0 only (one in 50) by
  // both.
  for (const foldlab::MethodStress* method : {&report.paper, &report.exact}) {
    int solved = 0;
    for (const auto& [regime, count] : method->regimes) {
      solved += count;
    }
    EXPECT_EQ(solved, 10);
  }
  EXPECT_EQ(report.grids, 2);
  options.seed = "-1";
  EXPECT_THROW(stress_command::run(options), foldlab::app::InputError);
}

}  // namespace

namespace {

// The page's link (app/common/inputs.hpp, forgiving_link): what can be read opens, a refused
// value is kept as typed, and every piece that cannot be read is said in plain words.
TEST(StartInputsTest, AForgivingLinkOpensWhatItCanAndSaysWhatItLeftOut) {
  foldlab::app::InputOptions options;
  options.link = {"t=abc", "E=1e999", "w=-5gsm", "h=NaN", "zz=1", "L=2000", "loose"};
  options.forgiving_link = true;
  const foldlab::Preset preset = foldlab::default_preset();
  const foldlab::app::StartInputs start = foldlab::app::resolve_start_inputs(options);
  // L from the link; w refused (kept as typed, the cloth without it); the rest the preset's.
  ASSERT_TRUE(start.refused.has_value());
  EXPECT_EQ(start.refused->hanging.length_mm, 2000.0);
  EXPECT_EQ(start.refused->fabric.weight_N_per_mm2, -5 * 9.81e-9);
  EXPECT_EQ(start.refused->fabric.thickness_mm, preset.parameters.fabric.thickness_mm);
  EXPECT_EQ(start.preset.parameters.fabric.weight_N_per_mm2,
            preset.parameters.fabric.weight_N_per_mm2);
  EXPECT_TRUE(start.origin.parameters == preset.parameters);
  const std::vector<std::string> want = {
      "t = 'abc' is not a number (with an optional unit: mm, cm, m), so t is the preset's 0.25 mm",
      "E = '1e999' is beyond the range of a double (magnitudes 2.2e-308 to 1.8e308), so E is the "
      "preset's 165 MPa",
      "h = 'NaN' is not a number (with an optional unit: mm, cm, m), so h is the preset's 1400 mm",
      "'zz' is no key FoldLab knows (known: ", "'loose' is no KEY=VALUE, so it is left out"};
  ASSERT_EQ(start.link_notes.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_TRUE(start.link_notes[i].starts_with(want[i])) << start.link_notes[i];
  }
  EXPECT_TRUE(start.link_notes[3].ends_with("), so it is left out")) << start.link_notes[3];
  // A command line's link stays strict: the same pieces stop the start, named by the option.
  options.forgiving_link = false;
  try {
    (void)foldlab::app::resolve_start_inputs(options);
    ADD_FAILURE() << "a strict link with unreadable pieces started";
  } catch (const foldlab::app::InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("--link t = 'abc' is not a number"), std::string::npos) << message;
    EXPECT_NE(message.find("--link unknown key 'zz'"), std::string::npos) << message;
  }
}

// A key given twice: a command line's link refuses it ("which one is meant?"), the page's keeps the
// first value and says so.
TEST(StartInputsTest, AForgivingLinkKeepsTheFirstOfARepeatedKey) {
  foldlab::app::InputOptions options;
  options.link = {"t=0.4", "t=3"};
  options.forgiving_link = true;
  const foldlab::app::StartInputs start = foldlab::app::resolve_start_inputs(options);
  EXPECT_EQ(start.preset.parameters.fabric.thickness_mm, 0.4);
  ASSERT_EQ(start.link_notes.size(), 1u);
  EXPECT_TRUE(
      start.link_notes[0].starts_with("t is given twice in the link; the first value is "
                                      "used, so t is 0.4 mm"))
      << start.link_notes[0];
  options.forgiving_link = false;
  EXPECT_THROW((void)foldlab::app::resolve_start_inputs(options), foldlab::app::InputError);
}

TEST(StartInputsTest, ALinksFabricIsAnEditOfItsPreset) {
  foldlab::app::InputOptions options;
  options.link = {"t=0.4", "E=200", "w=600gsm", "h=2400"};
  const foldlab::app::StartInputs start = foldlab::app::resolve_start_inputs(options);
  EXPECT_FALSE(start.refused.has_value());
  EXPECT_EQ(start.preset.parameters.fabric.thickness_mm, 0.4);
  EXPECT_TRUE(start.origin.parameters == foldlab::default_preset().parameters);
  EXPECT_TRUE(start.link_notes.empty());
  // Without a link the origin is the preset itself.
  const foldlab::app::StartInputs plain = foldlab::app::resolve_start_inputs({});
  EXPECT_TRUE(plain.origin.parameters == plain.preset.parameters);
}

}  // namespace
