// End-to-end tests of the foldlab executable: run it as a user or a script would and check the exit
// status, stdout and stderr.
#include <fcntl.h>
#include <pty.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include "core/io/measurements.hpp"
#include "json_output.hpp"
#include "outline_area.hpp"
#include "process.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kExecutable = FOLDLAB_EXECUTABLE;
const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;
const std::string kH900 = (kPresetsDir / "paper-table1-h900.json").string();
// The name written in presets/default.json, the built-in default.
const std::string kDefaultPresetName =
    "Default: the Table 1 cloth, h = 1400 mm, eq. 7 calibrated on Conci's Tables 1–2";

using foldlab::testing::read_file;
using foldlab::testing::RunResult;

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
  }
  return lines;
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

// A temporary directory per test, removed afterwards.
class CliTest : public foldlab::testing::TempDirTest {
 protected:
  CliTest() : TempDirTest("foldlab_cli_") {}

  // Runs foldlab with `args` (no shell), DISPLAY unset, stdout and stderr captured separately
  // through files in the test's directory.
  RunResult run(const std::vector<std::string>& args) {
    return foldlab::testing::run_process(kExecutable, args, dir_);
  }

  // `solve ... --json`, expected to succeed; returns the parsed object.
  json solve_json(std::vector<std::string> args) {
    args.insert(args.begin(), "solve");
    args.push_back("--json");
    return foldlab::testing::json_output(run(args));
  }

  // Starts foldlab with `args`, DISPLAY unset, its output thrown away, and returns at once with its
  // process id (-1 when it cannot start): for a test that signals it while it works.
  pid_t start(const std::vector<std::string>& args) const {
    std::vector<std::string> argv = {kExecutable};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> pointers;
    for (std::string& arg : argv) {
      pointers.push_back(arg.data());
    }
    pointers.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
      ::unsetenv("DISPLAY");
      ::unsetenv("WAYLAND_DISPLAY");
      ::execv(kExecutable.c_str(), pointers.data());
      ::_exit(127);
    }
    return pid;
  }

  // A measurements file of `count` fit rows of the Table 1 cloth, h from 900 mm up by `step_mm`,
  // in ten groups: data for calibrate whose fit is beside the point.
  fs::path fit_rows_file(int count, double step_mm) const {
    const fs::path data = dir_ / "fit-rows.csv";
    std::ofstream out(data);
    out << "name,group,role,t_mm,E_MPa,w_N_per_mm2,h_mm,L_mm,d_mm,shape,n,z_max_mm,Q\n";
    for (int i = 0; i < count; ++i) {
      out << "row " << i << ",g" << i % 10 << ",fit,0.25,165,1.5e-6," << 900 + step_mm * i
          << ",1400,100,,6,50,1.3\n";
    }
    return data;
  }

  // Files in the test's directory, ignoring the capture files.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const fs::directory_entry& e : fs::directory_iterator(dir_)) {
      names.push_back(e.path().filename().string());
    }
    return names;
  }
};

TEST_F(CliTest, SolveJsonHasEveryKeyAndAConsistentSolution) {
  const json j = solve_json({"--preset", kH900});
  ASSERT_TRUE(j.is_object());
  for (const char* key :
       {"method", "regime", "message", "n", "Q", "Q7", "z_max_mm", "a_mm", "l_mm", "iterations",
        "residual_length", "residual_height", "B_Nmm", "c_b_mm", "rounded_folds"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.at("method"), "paper");
  EXPECT_EQ(j.at("regime"), "wrinkled");
  const int n = j.at("n").get<int>();
  EXPECT_GE(n, 1);
  const json& a = j.at("a_mm");
  ASSERT_TRUE(a.is_array());
  ASSERT_EQ(static_cast<int>(a.size()), n + 1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(a[i].is_number()) << i;
    if (i > 0) {
      EXPECT_LT(a[i].get<double>(), a[i - 1].get<double>()) << "a_" << i;
    }
  }
  EXPECT_EQ(j.at("l_mm").get<double>(), 1300.0);  // l = L - d = 1400 - 100
  EXPECT_GT(j.at("z_max_mm").get<double>(), 0.0);
  EXPECT_GE(j.at("iterations").get<int>(), 1);
  // The inputs echo the preset file.
  EXPECT_EQ(j.at("inputs").at("height_mm").get<double>(), 900.0);
  EXPECT_EQ(j.at("inputs").at("length_mm").get<double>(), 1400.0);
  // Table 1's fabric: B = 165 x 0.25³ / (12 x 0.91) N mm, c_b = (B / 1.5e-6)^(1/3) mm.
  EXPECT_NEAR(j.at("B_Nmm").get<double>(), 0.2360920, 1e-6);
  EXPECT_NEAR(j.at("c_b_mm").get<double>(), 53.99208, 1e-4);
  const json& rounded = j.at("rounded_folds");
  EXPECT_TRUE(rounded.at("rounded").get<bool>());
  EXPECT_EQ(static_cast<int>(rounded.at("radius_mm").size()), n + 1);
  EXPECT_LT(rounded.at("z_fold_mm").get<double>(), j.at("z_max_mm").get<double>());
}

TEST_F(CliTest, ExactMethodSolvesToMachinePrecision) {
  const json j = solve_json({"--preset", kH900, "--method", "exact"});
  EXPECT_EQ(j.at("method"), "exact");
  EXPECT_LT(std::abs(j.at("residual_length").get<double>()), 1e-10);
  EXPECT_LT(std::abs(j.at("residual_height").get<double>()), 1e-10);
  EXPECT_EQ(static_cast<int>(j.at("a_mm").size()), j.at("n").get<int>() + 1);
}

TEST_F(CliTest, ZeroDisplacementHasNoSlack) {
  const json j = solve_json({"--preset", kH900, "--set", "d=0"});
  EXPECT_EQ(j.at("regime"), "no_slack");
  EXPECT_EQ(j.at("n").get<int>(), 0);
  EXPECT_EQ(j.at("l_mm").get<double>(), 1400.0);
}

TEST_F(CliTest, DisplacementOfHalfTheLengthIsInvalidInput) {
  const RunResult r = run({"solve", "--preset", kH900, "--set", "d=700", "--json"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "support displacement d = 700 mm must be below L/2 = 700 mm"))
      << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(CliTest, BadSettingsAreInvalidInput) {
  const RunResult bogus = run({"solve", "--preset", kH900, "--set", "bogus=1"});
  EXPECT_EQ(bogus.exit_status, 2);
  EXPECT_TRUE(contains(bogus.err, "unknown key")) << bogus.err;
  EXPECT_TRUE(bogus.out.empty()) << bogus.out;

  const RunResult not_number = run({"solve", "--preset", kH900, "--set", "t=abc"});
  EXPECT_EQ(not_number.exit_status, 2);
  EXPECT_TRUE(contains(not_number.err, "is not a number")) << not_number.err;
  EXPECT_TRUE(not_number.out.empty()) << not_number.out;

  // Every problem at once.
  const RunResult both = run({"solve", "--set", "bogus=1", "--set", "t=abc"});
  EXPECT_EQ(both.exit_status, 2);
  EXPECT_TRUE(contains(both.err, "unknown key")) << both.err;
  EXPECT_TRUE(contains(both.err, "is not a number")) << both.err;

  // K is kept as c = K (1 - nu²): a K outside c's range is refused by validation like any range,
  // naming the K that was typed beside the c it gives.
  const RunResult huge_K = run({"solve", "--set", "K=1e9"});
  EXPECT_EQ(huge_K.exit_status, 2);
  EXPECT_TRUE(
      contains(huge_K.err, "load-condition constant c = 9.1e8 must be between 0.001 and 10,000"))
      << huge_K.err;
  EXPECT_TRUE(contains(huge_K.err, "(K = c / (1 − ν²) = 1e9)")) << huge_K.err;
}

TEST_F(CliTest, ControlCharactersInKeysAndValuesAreEscapedInMessages) {
  const RunResult r =
      run({"solve", "--set", "\x1b[2Jkey=1", "--set", "method=\x1b[31mred", "--set", "t=\x07\xff"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\xff'), std::string::npos) << r.err;
  EXPECT_TRUE(contains(r.err, "unknown key '\\x1b[2Jkey'")) << r.err;
  EXPECT_TRUE(contains(r.err, "'\\x1b[31mred'")) << r.err;
  EXPECT_TRUE(contains(r.err, "'\\x07\\xff'")) << r.err;
}

TEST_F(CliTest, UnknownMethodIsInvalidInput) {
  const RunResult r = run({"solve", "--preset", kH900, "--method", "fast"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "fast")) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// --law brings the law's published constant (c = 4 pi² / 3 for Cerda-Mahadevan, p = 1), which
// --set then overrides; the JSON names the law and its fold spacing.
TEST_F(CliTest, LawIsChosenWithItsPublishedConstants) {
  const json cm = solve_json({"--preset", kH900, "--law", "cerda-mahadevan", "--method", "exact"});
  EXPECT_EQ(cm.at("law"), "cerda-mahadevan");
  EXPECT_TRUE(cm.at("Q7").is_null());
  // lambda = sqrt(2 pi 1300 0.25) / (3 (1 - 0.09) 1.5e-6 x 900 / (165 x 0.25))^(1/4)
  //        = 45.189 / 0.097222 = 464.8 mm
  EXPECT_NEAR(cm.at("fold_spacing_mm").get<double>(), 464.8, 0.1);
  EXPECT_NEAR(cm.at("inputs").at("load_constant_c").get<double>(),
              4.0 * std::numbers::pi * std::numbers::pi / 3.0, 1e-9);
  const json tuned = solve_json(
      {"--preset", kH900, "--law", "cerda-mahadevan", "--set", "c=3", "--method", "exact"});
  EXPECT_EQ(tuned.at("inputs").at("load_constant_c"), 3.0);
  EXPECT_LT(tuned.at("fold_spacing_mm").get<double>(), cm.at("fold_spacing_mm").get<double>());
  const json conci = solve_json({"--preset", kH900});
  EXPECT_EQ(conci.at("law"), "conci");
  EXPECT_TRUE(conci.at("fold_spacing_mm").is_null());

  const RunResult bad = run({"solve", "--preset", kH900, "--law", "hooke"});
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_TRUE(contains(bad.err, "hooke")) << bad.err;
}

TEST_F(CliTest, UnknownOptionIsInvalidInput) {
  const RunResult r = run({"solve", "--frobnicate"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "--frobnicate")) << r.err;

  const RunResult command = run({"frobnicate"});
  EXPECT_EQ(command.exit_status, 2);
}

TEST_F(CliTest, MissingPresetFileIsInvalidInputNamingTheFile) {
  const std::string missing = (dir_ / "no-such-preset.json").string();
  const RunResult r = run({"solve", "--preset", missing});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, missing)) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// A designer saves "Studio linen" in the explorer and scripts a picture of it: --preset takes a
// preset's name as the Presets panel lists it (the user's, then the shipped ones; case and
// punctuation aside) or its file's name, without the folder.
TEST_F(CliTest, APresetIsFoundByItsNameAmongTheUsersAndTheShippedOnes) {
  const fs::path config = dir_ / "config";
  fs::create_directories(config / "foldlab" / "presets");
  json mine = json::parse(std::ifstream(fs::path(kPresetsDir) / "default.json"));
  mine["name"] = "Studio linen, 2.4 m";
  mine["hanging"]["height_mm"] = 2400.0;
  std::ofstream(config / "foldlab" / "presets" / "studio-linen-2-4-m.json") << mine.dump();
  foldlab::testing::Environment env;
  env.set = {{"XDG_CONFIG_HOME", config.string()}, {"HOME", dir_.string()}};
  const auto height_of = [&](const std::string& preset) {
    const RunResult r = foldlab::testing::run_process(
        kExecutable, {"solve", "--preset", preset, "--json"}, dir_, env);
    EXPECT_EQ(r.exit_status, 0) << preset << ": " << r.err;
    return r.exit_status == 0 ? json::parse(r.out).at("inputs").at("height_mm").get<double>()
                              : -1.0;
  };
  EXPECT_EQ(height_of("Studio linen, 2.4 m"), 2400.0);
  EXPECT_EQ(height_of("studio linen 2.4 m"), 2400.0);
  EXPECT_EQ(height_of("studio-linen-2-4-m.json"), 2400.0);
  EXPECT_EQ(height_of("Table 1, h = 2350 mm"), 2350.0);  // a shipped one
  EXPECT_EQ(height_of("paper-table1-h900"), 900.0);
  const RunResult unknown =
      foldlab::testing::run_process(kExecutable, {"solve", "--preset", "Studio silk"}, dir_, env);
  EXPECT_EQ(unknown.exit_status, 2);
  EXPECT_TRUE(contains(unknown.err,
                       "--preset Studio silk: there is no such file, and no preset is "
                       "named so. The presets: Studio linen, 2.4 m; Default"))
      << unknown.err;
}

// Two presets whose names differ only in case and punctuation: the one named exactly as typed is
// meant; a name that matches several, none exactly, is refused naming each, never one at random.
TEST_F(CliTest, APresetNameMeansTheExactOneAndAnAmbiguousNameIsRefused) {
  const fs::path config = dir_ / "config";
  const fs::path presets = config / "foldlab" / "presets";
  fs::create_directories(presets);
  const auto save = [&](const std::string& file, const std::string& name, double height_mm) {
    json preset = json::parse(std::ifstream(kPresetsDir / "default.json"));
    preset["name"] = name;
    preset["hanging"]["height_mm"] = height_mm;
    std::ofstream(presets / file) << preset.dump();
  };
  save("fab-a.json", "Fab A", 2000.0);
  save("fab-a-2.json", "fab-a", 2100.0);
  foldlab::testing::Environment env;
  env.set = {{"XDG_CONFIG_HOME", config.string()}, {"HOME", dir_.string()}};
  const auto solve = [&](const std::string& preset) {
    return foldlab::testing::run_process(kExecutable, {"solve", "--preset", preset, "--json"}, dir_,
                                         env);
  };
  const auto height_of = [&](const std::string& preset) {
    const RunResult r = solve(preset);
    EXPECT_EQ(r.exit_status, 0) << preset << ": " << r.err;
    return r.exit_status == 0 ? json::parse(r.out).at("inputs").at("height_mm").get<double>()
                              : -1.0;
  };
  EXPECT_EQ(height_of("fab-a"), 2100.0);
  EXPECT_EQ(height_of("Fab A"), 2000.0);
  const RunResult ambiguous = solve("FAB A");
  EXPECT_EQ(ambiguous.exit_status, 2) << ambiguous.out;
  EXPECT_TRUE(contains(ambiguous.err, "--preset FAB A")) << ambiguous.err;
  EXPECT_TRUE(contains(ambiguous.err, "\"Fab A\" (" + (presets / "fab-a.json").string() + ")"))
      << ambiguous.err;
  EXPECT_TRUE(contains(ambiguous.err, "\"fab-a\" (" + (presets / "fab-a-2.json").string() + ")"))
      << ambiguous.err;
}

// A file in the presets folder that is no preset (half written, or another program's) is passed
// over by every command that lists the folder, with a word naming it and why.
TEST_F(CliTest, AFileInThePresetsFolderThatIsNoPresetIsSkippedWithANotice) {
  const fs::path presets = dir_ / "presets";
  fs::create_directories(presets);
  fs::copy_file(kPresetsDir / "paper-table1-h900.json", presets / "paper-table1-h900.json");
  fs::copy_file(kPresetsDir / "paper-table1-h1400.json", presets / "paper-table1-h1400.json");
  std::ofstream(presets / "junk.json") << "{ not json";
  foldlab::testing::Environment env;
  env.set = {{"FOLDLAB_PRESETS_DIR", presets.string()}};
  const RunResult r = foldlab::testing::run_process(kExecutable, {"compare", "--json"}, dir_, env);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).at("rows").size(), 2u) << r.out;
  EXPECT_TRUE(contains(r.err, "skipped " + (presets / "junk.json").string() + ": ")) << r.err;
}

TEST_F(CliTest, AnEmptyPresetPathIsInvalidInputNotTheDefault) {
  for (const std::string command : {"solve", "export", "sweep", "calibrate", "measure"}) {
    SCOPED_TRACE(command);
    const RunResult r = run({command, "--preset", ""});
    EXPECT_EQ(r.exit_status, 2) << r.out;
    EXPECT_TRUE(contains(r.err, "--preset")) << r.err;
    EXPECT_TRUE(contains(r.err, "empty path")) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
  }
}

TEST_F(CliTest, InvalidPresetFileIsInvalidInputNamingTheKey) {
  const fs::path path = dir_ / "bad.json";
  json j = json::parse(read_file(kH900));
  j["fabric"]["thickness_mm"] = "thin";
  std::ofstream(path) << j.dump(2);
  const RunResult r = run({"solve", "--preset", path.string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, path.string())) << r.err;
  EXPECT_TRUE(contains(r.err, "/fabric/thickness_mm")) << r.err;
}

TEST_F(CliTest, AStoredCalibrationOfTwentyThousandEntriesIsRefusedNotSolved) {
  // A solve evaluates each stored entry, about 40 ms each: some 13 minutes for these.
  json preset = json::parse(read_file(kH900));
  json list = json::array();
  for (int i = 0; i < 20'000; ++i) {
    list.push_back({30.0, 0.5});
  }
  preset["calibration"] = {{"calibrated_on", "x"}, {"method", "exact"},   {"K", 30.0}, {"p", 0.5},
                           {"fit_rows", 1},        {"equally_good", list}};
  const fs::path path = dir_ / "long.json";
  std::ofstream(path) << preset.dump();
  const RunResult r = run({"solve", "--preset", path.string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, path.string() + ": /calibration/equally_good/64: 20000 entries"))
      << r.err.substr(0, 400);
  EXPECT_TRUE(r.out.empty());
}

TEST_F(CliTest, SolvePrintsATableOfTheDefaultPreset) {
  const RunResult r = run({"solve"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  for (const char* text : {"n", "z_max", "mm"}) {
    EXPECT_TRUE(contains(r.out, text)) << text << "\n" << r.out;
  }
  EXPECT_TRUE(contains(r.out, kDefaultPresetName)) << r.out;
  EXPECT_TRUE(contains(r.out, "wrinkled")) << r.out;
}

TEST_F(CliTest, NoArgumentsWithoutADisplayPrintsTheTable) {
  const RunResult r = run({});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "z_max")) << r.out;
  EXPECT_TRUE(contains(r.out, "mm")) << r.out;
  EXPECT_TRUE(contains(r.out, kDefaultPresetName)) << r.out;
}

// A preset's name may state its values ("h = 1400 mm"): once --set changes them, the header, the
// OBJ's comment and compare's rows say the values solved after it, not only the preset's.
TEST_F(CliTest, ReportsNameTheInputsSolvedNotOnlyThePresets) {
  const RunResult solved = run({"solve", "--set", "h=5"});
  ASSERT_EQ(solved.exit_status, 0) << solved.err;
  const std::string header = split_lines(solved.out).at(0);
  EXPECT_TRUE(contains(header, kDefaultPresetName + " (edited: h = 5 mm)")) << header;

  const fs::path obj = dir_ / "k.obj";
  ASSERT_EQ(run({"export", "--set", "h=1.2m", "--obj", obj.string()}).exit_status, 0);
  const std::string comment = split_lines(read_file(obj)).at(0);
  EXPECT_TRUE(contains(comment, "(edited: h = 1200 mm)")) << comment;

  const RunResult compared = run({"compare", "--preset", kH900, "--set", "h=950"});
  ASSERT_EQ(compared.exit_status, 0) << compared.err;
  EXPECT_TRUE(contains(compared.out, "(edited: h = 950 mm)")) << compared.out;

  // Without overrides the name is the preset's alone.
  const RunResult plain = run({"solve"});
  EXPECT_FALSE(contains(plain.out, "(edited")) << plain.out;
}

// Table 1's h = 900 mm row by its preset's method, the paper's: the paper printed n = 5, and so
// do the table and the JSON.
TEST_F(CliTest, SolveTableAndJsonGiveThePapersNForTable1sFirstRow) {
  const json j = solve_json({"--preset", kH900});
  EXPECT_EQ(j.at("n").get<int>(), 5);
  const RunResult r = run({"solve", "--preset", kH900});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  bool found = false;
  for (const std::string& line : split_lines(r.out)) {
    std::istringstream words(line);
    std::vector<std::string> w{std::istream_iterator<std::string>(words),
                               std::istream_iterator<std::string>()};
    // "  number of wrinkles                 n                   5"
    if (w.size() >= 2 && w[w.size() - 2] == "n" && contains(line, "wrinkles")) {
      found = true;
      EXPECT_EQ(w.back(), "5") << line;
    }
  }
  EXPECT_TRUE(found) << r.out;
}

TEST_F(CliTest, SetKIsEchoedInTheInputs) {
  const json j = solve_json({"--preset", kH900, "--set", "K=37.5"});
  EXPECT_DOUBLE_EQ(j.at("inputs").at("K").get<double>(), 37.5);
  EXPECT_NEAR(j.at("inputs").at("load_constant_c").get<double>(), 37.5 * 0.91, 1e-12);

  // K applies at the Poisson ratio given on the same command line, whatever the order.
  const json k = solve_json({"--preset", kH900, "--set", "K=37.5", "--set", "nu=0.2"});
  EXPECT_DOUBLE_EQ(k.at("inputs").at("K").get<double>(), 37.5);
  EXPECT_EQ(k.at("inputs").at("poisson_ratio").get<double>(), 0.2);
  EXPECT_NEAR(k.at("inputs").at("load_constant_c").get<double>(), 37.5 * 0.96, 1e-12);
}

TEST_F(CliTest, ExportWritesObjCsvAndSvg) {
  const json solved = solve_json({"--preset", kH900});
  const int n = solved.at("n").get<int>();
  ASSERT_GE(n, 1);

  const fs::path obj = dir_ / "X.obj";
  const fs::path csv = dir_ / "X.csv";
  const fs::path svg = dir_ / "X.svg";
  const RunResult r = run({"export", "--preset", kH900, "--obj", obj.string(), "--csv",
                           csv.string(), "--svg", svg.string(), "--grid", "16x12"});
  ASSERT_EQ(r.exit_status, 0) << r.err;

  // OBJ: 16 x 12 vertices, texture coordinates and normals, two triangles per cell.
  int v = 0;
  int vt = 0;
  int vn = 0;
  int f = 0;
  for (const std::string& line : split_lines(read_file(obj))) {
    v += starts_with(line, "v ");
    vt += starts_with(line, "vt ");
    vn += starts_with(line, "vn ");
    f += starts_with(line, "f ");
  }
  EXPECT_EQ(v, 16 * 12);
  EXPECT_EQ(vt, 16 * 12);
  EXPECT_EQ(vn, 16 * 12);
  EXPECT_EQ(f, 2 * 15 * 11);

  // CSV: one line per fold, 0 (lower boundary) .. n (upper edge); odd lines are negative folds.
  const std::vector<std::string> rows = split_lines(read_file(csv));
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0], "line,sign,x_mm,y_mm,z_mm");
  std::set<int> indices;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::istringstream row(rows[i]);
    std::string line_field;
    std::string sign_field;
    ASSERT_TRUE(std::getline(row, line_field, ',')) << rows[i];
    ASSERT_TRUE(std::getline(row, sign_field, ',')) << rows[i];
    const int index = std::stoi(line_field);
    const int sign = std::stoi(sign_field);
    indices.insert(index);
    EXPECT_EQ(sign, index % 2 == 1 ? -1 : 1) << rows[i];
  }
  std::set<int> expected;
  for (int i = 0; i <= n; ++i) {
    expected.insert(i);
  }
  EXPECT_EQ(indices, expected);
  // The default is 201 points per fold line.
  EXPECT_EQ(rows.size() - 1, static_cast<std::size_t>(201 * (n + 1)));

  // SVG: one polyline per fold line, the negative (odd) ones red.
  const std::string drawing = read_file(svg);
  EXPECT_TRUE(contains(drawing, "<svg")) << drawing.substr(0, 200);
  EXPECT_TRUE(contains(drawing, "#d62728"));
  int polylines = 0;
  int red_polylines = 0;
  for (std::size_t at = drawing.find("<polyline"); at != std::string::npos;
       at = drawing.find("<polyline", at + 1)) {
    ++polylines;
    const std::size_t end = drawing.find('>', at);
    red_polylines += contains(drawing.substr(at, end - at), "#d62728");
  }
  EXPECT_EQ(polylines, n + 1);
  EXPECT_EQ(red_polylines, (n + 1) / 2);

  // Only the three requested files are left (no temporaries).
  std::vector<std::string> names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"X.csv", "X.obj", "X.svg"}));
}

TEST_F(CliTest, ExportNeedsAnOutput) {
  const RunResult r = run({"export", "--preset", kH900});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "--obj")) << r.err;
  EXPECT_TRUE(contains(r.err, "--glb")) << r.err;
}

TEST_F(CliTest, ExportWritesBinaryGltf) {
  const fs::path glb = dir_ / "X.glb";
  const RunResult r = run({"export", "--preset", kH900, "--glb", glb.string(), "--grid", "16x12"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::string bytes = read_file(glb);
  ASSERT_GE(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  // The GLB header's total length (little-endian uint32 at byte 8) is the file's size.
  const auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]));
  };
  const std::uint32_t length = byte(8) | byte(9) << 8 | byte(10) << 16 | byte(11) << 24;
  EXPECT_EQ(length, bytes.size());
  EXPECT_EQ(entries(), std::vector<std::string>{"X.glb"});  // no temporaries left
}

TEST_F(CliTest, ExportRejectsBadGrids) {
  const fs::path obj = dir_ / "grid.obj";
  for (const char* grid : {"1x5", "abc", "16", "16x", "5000x16"}) {
    SCOPED_TRACE(grid);
    const RunResult r = run({"export", "--obj", obj.string(), "--grid", grid});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err, "--grid")) << r.err;
    EXPECT_FALSE(fs::exists(obj));
  }
}

TEST_F(CliTest, ExportIntoAMissingDirectoryFailsNamingThePath) {
  const fs::path obj = dir_ / "no-such-dir" / "X.obj";
  const RunResult r = run({"export", "--preset", kH900, "--obj", obj.string(), "--grid", "8x8"});
  EXPECT_NE(r.exit_status, 0);
  EXPECT_TRUE(contains(r.err, obj.string())) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "no-such-dir"));
}

}  // namespace

TEST_F(CliTest, SolveStatsShowThatNoGridIsBuilt) {
  const json j = solve_json({"--stats"});
  const json& stats = j.at("stats");
  EXPECT_EQ(stats.at("solution").at("evaluations").get<int>(), 1);
  EXPECT_EQ(stats.at("fold_lines").at("evaluations").get<int>(), 0);
  EXPECT_EQ(stats.at("grid").at("evaluations").get<int>(), 0);
  EXPECT_EQ(stats.at("normals").at("evaluations").get<int>(), 0);
  EXPECT_GE(stats.at("solution").at("total_ms").get<double>(), 0.0);
}

TEST_F(CliTest, ExportStatsRunOnlyTheStagesItsOutputsNeed) {
  const std::string svg = (dir_ / "lines.svg").string();
  const RunResult svg_only = run({"export", "--svg", svg, "--stats"});
  ASSERT_EQ(svg_only.exit_status, 0) << svg_only.err;
  const json a = json::parse(svg_only.out).at("stats");
  EXPECT_EQ(a.at("fold_lines").at("evaluations").get<int>(), 1);
  EXPECT_EQ(a.at("grid").at("evaluations").get<int>(), 0);
  EXPECT_EQ(a.at("normals").at("evaluations").get<int>(), 0);

  const std::string obj = (dir_ / "mesh.obj").string();
  const std::string csv = (dir_ / "lines.csv").string();
  const RunResult all = run({"export", "--obj", obj, "--csv", csv, "--svg", svg, "--stats"});
  ASSERT_EQ(all.exit_status, 0) << all.err;
  const json b = json::parse(all.out).at("stats");
  EXPECT_EQ(b.at("solution").at("evaluations").get<int>(), 1);
  EXPECT_EQ(b.at("fold_lines").at("evaluations").get<int>(), 1);  // shared by CSV and SVG
  EXPECT_EQ(b.at("grid").at("evaluations").get<int>(), 1);
  EXPECT_EQ(b.at("normals").at("evaluations").get<int>(), 1);
}

TEST_F(CliTest, QuadratureSettingsThatWouldRunForHoursAreRefusedWithTheirRanges) {
  // A million intervals times a million iterations at a tolerance below rounding ran for hours.
  const RunResult r = run({"solve", "--set", "simpson_intervals=1000000", "--set",
                           "max_iterations=1000000", "--set", "length_tolerance=1e-300"});
  EXPECT_EQ(r.exit_status, 2);
  for (const char* range :
       {"quadrature intervals simpson_intervals = 1,000,000 must be between 2 and 10,000",
        "iteration cap max_iterations = 1,000,000 must be between 1 and 1000",
        "length tolerance length_tolerance = 1e-300 must be between 1e-12 and 0.5"}) {
    EXPECT_TRUE(contains(r.err, range)) << range << "\n" << r.err;
  }
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(CliTest, ExportRefusesAGridAboveTheVertexBudget) {
  // 4096 x 4096 peaked at 8.5 GB; the limit is 1024 x 1024 = 1048576 vertices.
  const fs::path obj = dir_ / "big.obj";
  for (const char* grid : {"4096x4096", "1025x1024"}) {
    SCOPED_TRACE(grid);
    const RunResult r = run({"export", "--obj", obj.string(), "--grid", grid});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err, "limit of 1048576")) << r.err;
    EXPECT_FALSE(fs::exists(obj));
  }
  // The fold lines alone build no grid, so the grid's size does not matter to them.
  const fs::path csv = dir_ / "lines.csv";
  const RunResult lines = run({"export", "--csv", csv.string(), "--grid", "4096x4096"});
  EXPECT_EQ(lines.exit_status, 0) << lines.err;
  EXPECT_TRUE(fs::exists(csv));
}

TEST_F(CliTest, ExportRefusesFoldLinesAboveThePointBudget) {
  // n is capped at 10^4 folds, of which about 1000 lines are drawn: 100000 samples a line make
  // about 10^8 points (10.8 GB and 195 s before), far above the limit of 4000000.
  const fs::path csv = dir_ / "lines.csv";
  const RunResult r = run({"export", "--set", "t=1e-3", "--set", "E=1e-3", "--set",
                           "w=1000000 g/m2", "--samples", "100000", "--csv", csv.string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "limit of 4000000")) << r.err;
  EXPECT_FALSE(fs::exists(csv));
}

TEST_F(CliTest, ACappedFoldCountIsSmallEnoughToUseAndFlaggedWhereverItIsShown) {
  // Valid inputs whose eq. 10 asks for millions of folds: with the cap at 10^7 `solve --json` wrote
  // 233 MB of a_i.
  const std::vector<std::string> many = {"--set",  "t=1e-3", "--set",
                                         "E=1e-3", "--set",  "w=1000000 g/m2"};
  const RunResult r =
      run({"solve", "--set", "t=1e-3", "--set", "E=1e-3", "--set", "w=1000000 g/m2", "--json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_LT(r.out.size(), 1'000'000u);
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("n"), 10000);
  EXPECT_EQ(j.at("n_capped"), true);
  EXPECT_EQ(j.at("a_mm").size(), 10001u);

  std::vector<std::string> args = many;
  args.insert(args.begin(), "solve");
  const RunResult table = run(args);
  ASSERT_EQ(table.exit_status, 0) << table.err;
  EXPECT_TRUE(contains(table.out, "(capped: eq. 10 asks for more)")) << table.out;

  args = many;
  args.insert(args.begin(),
              {"sweep", "--param", "h", "--from", "900", "--to", "1000", "--steps", "2"});
  const RunResult sweep = run(args);
  ASSERT_EQ(sweep.exit_status, 0) << sweep.err;
  EXPECT_TRUE(contains(sweep.out, "10000+")) << sweep.out;
  EXPECT_TRUE(contains(sweep.out, "wrinkled, n capped")) << sweep.out;
  EXPECT_TRUE(contains(sweep.err, "n is capped there")) << sweep.err;
  args.push_back("--csv");
  const RunResult csv = run(args);
  ASSERT_EQ(csv.exit_status, 0) << csv.err;
  const std::vector<std::string> lines = split_lines(csv.out);
  ASSERT_EQ(lines.size(), 3u) << csv.out;
  EXPECT_EQ(lines[0], "h,n,Q,z_max_mm,regime,n_capped");
  EXPECT_TRUE(lines[1].ends_with(",wrinkled,1")) << lines[1];

  // compare, on a paper row with those inputs set: the table and the JSON say so too.
  args = many;
  args.insert(args.begin(), {"compare", "--preset", kH900});
  const RunResult compared = run(args);
  ASSERT_EQ(compared.exit_status, 0) << compared.err;
  EXPECT_TRUE(contains(compared.out, "| 10000+ (capped) |")) << compared.out;
  args.push_back("--json");
  const json rows = foldlab::testing::json_output(run(args)).at("rows");
  EXPECT_EQ(rows.at(0).at("exact").at("n_capped"), true) << rows.dump();
}

TEST_F(CliTest, SweepRefusesEndsThatCannotDescribeACloth) {
  // These printed rows of inf (or ran) and exited 0.
  const std::vector<std::vector<std::string>> attacks = {
      {"--param", "w", "--from", "1e-320", "--to", "0.01", "--steps", "2000", "--log"},
      {"--param", "t", "--from", "1e-308", "--to", "1", "--log"},
      {"--param", "K", "--from", "1e-300", "--to", "1e300"},
      {"--param", "h", "--from", "900", "--to", "2350", "--steps", "100000"},
  };
  for (std::vector<std::string> args : attacks) {
    SCOPED_TRACE(args[1] + " from " + args[3]);
    args.insert(args.begin(), "sweep");
    args.push_back("--csv");
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
    EXPECT_TRUE(contains(r.err, " must be ") || contains(r.err, "subnormal")) << r.err;
  }
}

TEST_F(CliTest, StressSeedMustBeAnUnsigned64BitNumber) {
  // -1 and 2^64 both became 2^64 - 1.
  for (const char* seed : {"-1", "18446744073709551616", "1.5", "", "0x10"}) {
    SCOPED_TRACE(seed);
    const RunResult r = run({"stress", "--samples", "1", "--seed", seed});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err, "--seed")) << r.err;
  }
  const RunResult largest =
      run({"stress", "--samples", "1", "--json", "--seed", "18446744073709551615"});
  ASSERT_EQ(largest.exit_status, 0) << largest.err;
  EXPECT_EQ(json::parse(largest.out).at("seed").get<std::uint64_t>(), UINT64_MAX);
}

// One cause, one wording: a number too large for a double is "beyond the range of a double"
// whether typed (1e999) or computed on the way (1e200*1e200/1e200); a division by zero says so.
TEST_F(CliTest, ArithmeticBeyondADoubleIsRefusedInTheWordsOfATooLargeNumber) {
  for (const char* value : {"1e999", "1e200*1e200", "1e200*1e200/1e200", "-1e300*1e300 mm"}) {
    SCOPED_TRACE(value);
    const RunResult r = run({"solve", "--set", std::string("h=") + value});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err,
                         "' is beyond the range of a double (magnitudes 2.2e-308 to "
                         "1.8e308)"))
        << r.err;
  }
  for (const char* value : {"1/0", "0/0", "(2+3)/(1-1) m"}) {
    SCOPED_TRACE(value);
    const RunResult r = run({"solve", "--set", std::string("h=") + value});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err, "' divides by zero")) << r.err;
  }
}

// A seed written with an exponent is the whole number it names: 1e19 lies below 2^64 and runs.
TEST_F(CliTest, StressSeedMayBeWrittenWithAnExponent) {
  const RunResult r = run({"stress", "--samples", "1", "--json", "--seed", "1e19"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).at("seed").get<std::uint64_t>(), 10000000000000000000ull);
  EXPECT_EQ(json::parse(run({"stress", "--samples", "1", "--json", "--seed", "1.5e3"}).out)
                .at("seed")
                .get<std::uint64_t>(),
            1500u);
  for (const char* seed : {"2e19", "1.5e0", "1e-3", "1e"}) {
    SCOPED_TRACE(seed);
    const RunResult refused = run({"stress", "--samples", "1", "--seed", seed});
    EXPECT_EQ(refused.exit_status, 2);
    EXPECT_TRUE(contains(refused.err, "must be a whole number from 0 to 18446744073709551615"))
        << refused.err;
  }
}

// A refused sweep end says its value in the unit it was given in, with the input's name.
TEST_F(CliTest, ASubnormalSweepEndIsSaidWithItsUnit) {
  const RunResult r = run({"sweep", "--param", "w", "--from", "1e-300gsm", "--to", "100gsm"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "weight per area w = 1e-300 g/m² is subnormal")) << r.err;
}

// 12,000 copies of one piece of a link are one problem: a few of them are quoted, the rest
// counted, on a line a terminal can show.
TEST_F(CliTest, ALinkWithThousandsOfRepeatedPiecesIsSummarisedOnAShortLine) {
  std::string link = "#t=0.3";
  for (int i = 0; i < 12000; ++i) {
    link += "&h=1400";
  }
  const RunResult r =
      run({"render", "--link", link, "--out", (dir_ / "never.png").string(), "--size", "320x240"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_FALSE(fs::exists(dir_ / "never.png"));
  EXPECT_TRUE(contains(r.err,
                       "--link h=1400, --link h=1400, --link h=1400 and 11997 more: "
                       "duplicate key"))
      << r.err.substr(0, 500);
  for (const std::string& line : split_lines(r.err)) {
    EXPECT_LT(line.size(), 400u) << line.substr(0, 200);
  }
}

// A caption shows a preset's name cut to a length a picture holds: a 900 KB name stays a line.
TEST_F(CliTest, ACaptionShowsAPresetsNameCutToALine) {
  json preset = json::parse(std::ifstream(kPresetsDir / "default.json"));
  preset["name"] = std::string(900000, 'x');
  const fs::path file = dir_ / "long.json";
  std::ofstream(file) << preset.dump();
  const fs::path svg = dir_ / "plot.svg";
  const RunResult r = run({"export", "--preset", file.string(), "--svg", svg.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err.substr(0, 300);
  for (const std::string& line : split_lines(read_file(svg))) {
    if (starts_with(line, "<text")) {
      EXPECT_LT(line.size(), 1000u) << line.substr(0, 200);
    }
  }
  EXPECT_TRUE(contains(read_file(svg), std::string(100, 'x') + "…")) << "the cut is marked";
}

TEST_F(CliTest, BenchRefusesMoreSolvesThanItsBudget) {
  // 1,000,000 cases x 10 would take about an hour and 10 GB.
  RunResult r = run({"bench", "--cases", "1000000", "--repeats", "10"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "1000000 must be a whole number from 1 to 100000")) << r.err;
  r = run({"bench", "--cases", "100000", "--repeats", "11"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "--cases x --repeats = 1100000 must be in [1, 1000000]")) << r.err;
}

TEST_F(CliTest, SweepPrintsOneRowPerStepAsCsv) {
  const RunResult r =
      run({"sweep", "--param", "h", "--from", "900", "--to", "2350", "--steps", "4", "--csv"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::vector<std::string> lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "h,n,Q,z_max_mm,regime,n_capped");
  EXPECT_TRUE(starts_with(lines[1], "900,"));
  EXPECT_TRUE(starts_with(lines[4], "2350,"));
  // The first row is the Table 1, h = 900 mm case: the same n as `solve`.
  const json j = solve_json({"--set", "h=900"});
  EXPECT_TRUE(starts_with(lines[1], "900," + std::to_string(j.at("n").get<int>()) + ","));
  const RunResult bad = run({"sweep", "--param", "q", "--from", "1", "--to", "2"});
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_TRUE(contains(bad.err, "cannot be swept"));
}

// A stranger's input: every case below ends in a clear message and the documented exit status.

namespace {

// The h = 900 mm preset with the text of its thickness value replaced by `value`.
std::string h900_with_thickness(const std::string& value) {
  std::string text = read_file(kH900);
  const std::string key = "\"thickness_mm\": 0.25";
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  return text.replace(at, key.size(), "\"thickness_mm\": " + value);
}

}  // namespace

TEST_F(CliTest, DeeplyNestedPresetIsInvalidInputNotACrash) {
  const fs::path path = dir_ / "deep.json";
  std::ofstream(path) << h900_with_thickness(std::string(60000, '[') + "1" +
                                             std::string(60000, ']'));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"solve", "--preset", path.string()},
        std::vector<std::string>{"compare", "--preset", path.string()}}) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_status, 2) << args[0] << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "nested deeper than 64 levels")) << r.err;
    EXPECT_LT(r.err.size(), 400u) << r.err;
  }
}

TEST_F(CliTest, DuplicateKeyInAPresetIsInvalidInputNamingIt) {
  const fs::path path = dir_ / "dup.json";
  std::ofstream(path) << h900_with_thickness("-5, \"thickness_mm\": 0.25");
  const RunResult r = run({"solve", "--preset", path.string()});
  EXPECT_EQ(r.exit_status, 2) << r.out;
  EXPECT_TRUE(contains(r.err, "/fabric/thickness_mm: duplicate key")) << r.err;
}

TEST_F(CliTest, SetReportsParseAndRangeProblemsTogether) {
  const RunResult r = run({"solve", "--set", "t=abc", "--set", "h=-5"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "t = 'abc' is not a number")) << r.err;
  EXPECT_TRUE(contains(r.err, "height h = −5 mm must be between 1 and 100,000 mm")) << r.err;
}

TEST_F(CliTest, UnitsAreCaseSensitiveWhereCaseIsAPrefix) {
  // 2.4M was 2400 mm, 1Mm 1 mm and 2.4MM 2.4 mm.
  for (const char* value : {"h=2.4M", "h=1Mm", "h=2.4MM"}) {
    SCOPED_TRACE(value);
    const RunResult r = run({"solve", "--set", value});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(contains(r.err, "is not a unit of length (known: mm, cm, m)")) << r.err;
  }
  const RunResult mega = run({"solve", "--set", "h=2.4M"});
  EXPECT_TRUE(contains(mega.err,
                       "'M' is not a unit of length (known: mm, cm, m); did you mean "
                       "'m'?"))
      << mega.err;
  const json solved = solve_json({"--set", "h=2.4m", "--set", "w=150GSM"});
  EXPECT_EQ(solved.at("inputs").at("height_mm").get<double>(), 2400.0);
}

TEST_F(CliTest, ARefusedBareWeightSaysItWasReadInNewtonsPerSquareMillimetre) {
  // The explorer's w field reads 150 as 150 g/m²; --set, as the input table says, as N/mm².
  const RunResult bare = run({"solve", "--set", "w=150"});
  EXPECT_EQ(bare.exit_status, 2);
  EXPECT_TRUE(contains(bare.err, "weight per area w = ")) << bare.err;
  EXPECT_TRUE(contains(bare.err,
                       "(a bare number for w is read in N/mm²; for 150 g/m² write "
                       "w=150gsm)"))
      << bare.err;
  // With a unit the same refusal has no such note, and 150gsm is a fabric.
  const RunResult heavy = run({"solve", "--set", "w=2e6gsm"});
  EXPECT_EQ(heavy.exit_status, 2);
  EXPECT_FALSE(contains(heavy.err, "bare number")) << heavy.err;
  EXPECT_EQ(run({"solve", "--set", "w=150gsm"}).exit_status, 0);
}

TEST_F(CliTest, AKeySetTwiceIsRefusedAsInAPreset) {
  // The last one won without a word.
  const RunResult set = run({"solve", "--set", "h=2.4m", "--set", "h=1000"});
  EXPECT_EQ(set.exit_status, 2);
  EXPECT_TRUE(set.out.empty()) << set.out;
  EXPECT_TRUE(contains(set.err,
                       "--set h=2.4m and --set h=1000: duplicate key (each key may "
                       "appear once; which one is meant?)"))
      << set.err;
  // The same through every command that takes --set.
  const RunResult sweep = run({"sweep", "--param", "h", "--from", "900", "--to", "1000", "--set",
                               "t=0.3", "--set", "t=0.4"});
  EXPECT_EQ(sweep.exit_status, 2);
  EXPECT_TRUE(contains(sweep.err, "duplicate key")) << sweep.err;
  // A link's pieces, its view keys as well; refused before any window or EGL is asked for.
  const std::string out = (dir_ / "linked.png").string();
  for (const char* link :
       {"#t=0.4&t=3", "https://host/foldlab/index.html#theme=dark&theme=light"}) {
    SCOPED_TRACE(link);
    const RunResult linked = run({"render", "--link", link, "--out", out});
    EXPECT_EQ(linked.exit_status, 2);
    EXPECT_TRUE(contains(linked.err,
                         "duplicate key (each key may appear once; which one is "
                         "meant?)"))
        << linked.err;
  }
  const RunResult twice_t = run({"render", "--link", "#t=0.4&t=3", "--out", out});
  EXPECT_TRUE(contains(twice_t.err, "--link t=0.4 and --link t=3: duplicate key")) << twice_t.err;
  EXPECT_FALSE(fs::exists(out));
}

// Two ways of giving one input: K is c at the Poisson ratio, and --method is --set method=. K,
// applied after c, and the option, applied after --set, won without a word.
TEST_F(CliTest, OneInputGivenTwoWaysIsRefusedNamingBoth) {
  const RunResult stiffness = run({"solve", "--set", "c=1.5", "--set", "K=2"});
  EXPECT_EQ(stiffness.exit_status, 2);
  EXPECT_TRUE(stiffness.out.empty()) << stiffness.out;
  EXPECT_TRUE(contains(stiffness.err, "--set c=1.5 and --set K=2: c and K set the same input"))
      << stiffness.err;
  const RunResult method = run({"solve", "--set", "method=paper", "--method", "exact"});
  EXPECT_EQ(method.exit_status, 2);
  EXPECT_TRUE(
      contains(method.err, "--method exact and --set method=paper: both set method; which one"))
      << method.err;
  // Each alone, or K with the Poisson ratio it is taken at, is one input each.
  EXPECT_EQ(run({"solve", "--set", "K=2", "--set", "nu=0.2"}).exit_status, 0);
  EXPECT_EQ(run({"solve", "--method", "paper"}).exit_status, 0);
}

TEST_F(CliTest, AnOutputNamedForAnotherFormatIsRefused) {
  // picture --out x.jpg wrote PNG data under a JPEG name and exited 0. The checks come before any
  // EGL is asked for, so they hold without one.
  const std::vector<std::vector<std::string>> wrong = {
      {"picture", "cloth", "--size", "400x300", "--out", "x.jpg"},
      {"render", "--out", "x.jpeg"},
      {"gui", "--frames", "1", "--screenshot", "x.bmp"},
      {"export", "--obj", "x.stl"},
      {"export", "--glb", "x.gltf"},
      {"export", "--csv", "x.txt"},
      {"export", "--svg", "x.png"},
      {"bench", "--cases", "1", "--repeats", "1", "--csv", "x.tsv"},
      {"bench", "--cases", "1", "--repeats", "1", "--svg", "x.pdf"},
      {"calibrate", "--data",
       (kPresetsDir.parent_path() / "data" / "paper-measurements.csv").string(), "--save-preset",
       "x.txt"},
      {"measure", "--depths-mm", "80,40,20,10", "--append", "rows.txt"},
  };
  for (std::vector<std::string> args : wrong) {
    SCOPED_TRACE(args[0] + " " + args[args.size() - 2]);
    args.back() = (dir_ / args.back()).string();
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err, args[args.size() - 2] + " " + dir_.string().substr(0, 20)))
        << r.err;
    EXPECT_TRUE(contains(r.err, " must end in .")) << r.err;
  }
  // The name is said as given (cut as any quoted text is), then the rule.
  const RunResult jpg =
      run({"picture", "cloth", "--size", "400x300", "--out", (dir_ / "x.jpg").string()});
  EXPECT_EQ(jpg.exit_status, 2);
  EXPECT_TRUE(contains(jpg.err, "--out " + dir_.string().substr(0, 20))) << jpg.err;
  EXPECT_TRUE(contains(jpg.err, " must end in .png (in any case): what is written there is PNG"))
      << jpg.err;
  EXPECT_TRUE(entries().empty());
  // Upper case is a spelling of the same extension.
  const RunResult upper = run(
      {"export", "--svg", (dir_ / "LINES.SVG").string(), "--csv", (dir_ / "Lines.Csv").string()});
  EXPECT_EQ(upper.exit_status, 0) << upper.err;
  EXPECT_TRUE(fs::exists(dir_ / "LINES.SVG"));
  // A measurements file may be either: CSV or JSON, by its extension.
  EXPECT_EQ(
      run({"measure", "--depths-mm", "80,40,20,10", "--append", (dir_ / "rows.JSON").string()})
          .exit_status,
      0);
  EXPECT_TRUE(fs::exists(dir_ / "rows.JSON"));
}

TEST_F(CliTest, OptionValuesAreRefusedInOneVoice) {
  // 1e9 said "Could not convert: --steps = 1e9", 0 gave the range.
  for (const char* steps : {"1e9", "0", "1", "10001", "2.5"}) {
    SCOPED_TRACE(steps);
    const RunResult r =
        run({"sweep", "--param", "h", "--from", "900", "--to", "1000", "--steps", steps});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(
        r.err, "--steps: " + std::string(steps) + " must be a whole number from 2 to 10000"))
        << r.err;
  }
  const RunResult sweep =
      run({"sweep", "--param", "h", "--from", "900", "--to", "1000", "--steps", "1e1", "--csv"});
  ASSERT_EQ(sweep.exit_status, 0) << sweep.err;
  EXPECT_EQ(std::count(sweep.out.begin(), sweep.out.end(), '\n'), 11);  // header and 10 rows
  // A choice in the words --set uses, not CLI11's "Exact not in {paper,exact}".
  const RunResult method = run({"solve", "--method", "Exact"});
  EXPECT_EQ(method.exit_status, 2);
  EXPECT_TRUE(contains(method.err, "method = 'Exact' is not one of: paper, exact")) << method.err;
  const RunResult set_method = run({"solve", "--set", "method=Exact"});
  EXPECT_TRUE(contains(set_method.err, "method = 'Exact' is not one of: paper, exact"))
      << set_method.err;
  const RunResult law = run({"solve", "--law", "Conci"});
  EXPECT_EQ(law.exit_status, 2);
  EXPECT_TRUE(contains(law.err, "law = 'Conci' is not one of: conci, cerda-mahadevan")) << law.err;
  const RunResult fit = run({"calibrate", "--data", "x.csv", "--fit", "k"});
  EXPECT_EQ(fit.exit_status, 2);
  EXPECT_TRUE(contains(fit.err, "fit = 'k' is not one of: K, K,p")) << fit.err;
  // Twenty parentheses deep is no typo in a number: the limit is said.
  const std::string deep = std::string(20, '(') + "1400" + std::string(20, ')');
  const RunResult nested = run({"solve", "--set", "h=" + deep});
  EXPECT_EQ(nested.exit_status, 2);
  EXPECT_TRUE(contains(nested.err, "h = '" + deep +
                                       "' is nested too deeply: arithmetic may nest at most 16 "
                                       "parentheses deep"))
      << nested.err;
  const std::string sixteen = std::string(16, '(') + "1400" + std::string(16, ')');
  EXPECT_EQ(solve_json({"--set", "h=" + sixteen}).at("inputs").at("height_mm").get<double>(),
            1400.0);
}

TEST_F(CliTest, AHugeBadValueIsEchoedCut) {
  const RunResult r = run({"solve", "--set", "t=" + std::string(100000, 'x')});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_LT(r.err.size(), 300u);
  EXPECT_TRUE(contains(r.err, "xxx…' is not a number")) << r.err;
}

TEST_F(CliTest, ExportThroughASymlinkWritesItsTarget) {
  std::ofstream(dir_ / "real.csv") << "old\n";
  fs::create_symlink("real.csv", dir_ / "link.csv");
  const RunResult r = run({"export", "--csv", (dir_ / "link.csv").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
  EXPECT_TRUE(starts_with(read_file(dir_ / "real.csv"), "line,sign,x_mm,y_mm,z_mm\n"));
}

TEST_F(CliTest, ExportToAFifoOrDirectoryIsAFileErrorAndLeavesItAlone) {
  const fs::path fifo = dir_ / "out.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const RunResult r = run({"export", "--obj", fifo.string(), "--grid", "8x8"});
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_TRUE(contains(r.err, "a FIFO, not a regular file")) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  fs::create_directory(dir_ / "dir.svg");
  const RunResult d = run({"export", "--svg", (dir_ / "dir.svg").string()});
  EXPECT_EQ(d.exit_status, 1);
  EXPECT_TRUE(contains(d.err, "a directory, not a regular file")) << d.err;
}

// A target that cannot be written is a file error (exit 1); a folder that cannot hold it is the
// user's path, refused as invalid input before the fit.
TEST_F(CliTest, CalibrateSavePresetThatCannotBeWrittenExitsOne) {
  std::ofstream(dir_ / "one.csv") << "t_mm,E_MPa,w_N_per_mm2,h_mm,L_mm,d_mm,n\n"
                                     "0.25,165,1.5e-6,900,1400,100,5\n";
  const fs::path target = dir_ / "fitted.json";
  fs::create_directory(target);
  const RunResult r = run({"calibrate", "--data", (dir_ / "one.csv").string(), "--fit", "K",
                           "--save-preset", target.string()});
  EXPECT_EQ(r.exit_status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, target.string() + ": cannot write: a directory, not a regular file"))
      << r.err;
  EXPECT_FALSE(contains(r.err, "invalid input")) << r.err;
  std::ofstream(dir_ / "plain") << "a file, not a folder\n";
  const RunResult in_a_file = run({"calibrate", "--data", (dir_ / "one.csv").string(), "--fit", "K",
                                   "--save-preset", (dir_ / "plain" / "fitted.json").string()});
  EXPECT_EQ(in_a_file.exit_status, 2) << in_a_file.err;
  EXPECT_TRUE(
      contains(in_a_file.err, "the folder " + (dir_ / "plain").string() + " is not a folder"))
      << in_a_file.err;
}

TEST_F(CliTest, UnreadablePresetGivesTheSystemsReason) {
  std::ofstream(dir_ / "plain") << "x\n";
  const RunResult r = run({"solve", "--preset", (dir_ / "plain" / "p.json").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "cannot open for reading (Not a directory)")) << r.err;
}

TEST_F(CliTest, StiffMessageWithAnExponentShowsSToTheP) {
  // t = 50 mm makes s = K E t^3 / (w h l^2) far above 1; eq. 7 sees s^p.
  const json j = solve_json({"--set", "t=50", "--set", "p=0.5"});
  ASSERT_EQ(j.at("regime"), "stiff");
  const std::string message = j.at("message");
  EXPECT_TRUE(contains(message, "Stiff: s^p = ")) << message;
  const double s = j.at("s").get<double>();
  char expected[64];
  std::snprintf(expected, sizeof expected, "= %.3g >= 1", std::sqrt(s));
  EXPECT_TRUE(contains(message, expected)) << message << " / " << expected;
}

TEST_F(CliTest, ExponentJustAboveItsLimitIsEchoedUnrounded) {
  const RunResult r = run({"solve", "--set", "p=5.0000001"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "eq. 7 exponent p = 5.0000001 must be between 0.05 and 5")) << r.err;
}

TEST_F(CliTest, SweepPastTheValidRangeSaysWhyOnceAndAllRefusedIsInvalidInput) {
  // L = 1400 allows d < 700 (half of L): of 600, 650, 700 only the last is refused.
  const RunResult partly =
      run({"sweep", "--param", "d", "--from", "600", "--to", "700", "--steps", "3", "--csv"});
  EXPECT_EQ(partly.exit_status, 0) << partly.err;
  EXPECT_TRUE(contains(partly.out, "\n700,,,,invalid,\n")) << partly.out;
  EXPECT_TRUE(contains(partly.err, "1 of 3 values are refused")) << partly.err;
  EXPECT_TRUE(contains(partly.err, "d = 700")) << partly.err;
  const RunResult all =
      run({"sweep", "--param", "d", "--from", "700", "--to", "800", "--steps", "3"});
  EXPECT_EQ(all.exit_status, 2);
  EXPECT_TRUE(contains(all.err, "no value of the range is valid")) << all.err;
  EXPECT_TRUE(all.out.empty()) << all.out;
}

// picture sweep draws what sweep solves: a range sweep refuses is refused there in the same words,
// before anything is drawn.
TEST_F(CliTest, PictureSweepRefusesWhatSweepRefuses) {
  const RunResult swept = run({"sweep", "--param", "d", "--from", "700", "--to", "900"});
  ASSERT_EQ(swept.exit_status, 2);
  const fs::path png = dir_ / "x.png";
  const RunResult drawn = run({"picture", "sweep", "--size", "800x600", "--param", "d", "--from",
                               "700", "--to", "900", "--out", png.string()});
  EXPECT_EQ(drawn.exit_status, 2) << drawn.err;
  EXPECT_TRUE(contains(drawn.err,
                       "no value of the range is valid given the other inputs; at d = "
                       "700"))
      << drawn.err;
  EXPECT_EQ(drawn.err, swept.err);
  EXPECT_FALSE(fs::exists(png));
}

// The other inputs are judged at the swept values: d = 800 mm needs L above 1600 mm, which the
// preset's L = 1400 mm is not but most of the swept L are.
TEST_F(CliTest, SweepJudgesTheOtherInputsAtTheSweptValues) {
  const RunResult r = run({"sweep", "--set", "d=800", "--param", "L", "--from", "1000", "--to",
                           "3000", "--steps", "5", "--csv"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::vector<std::string> lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 6u) << r.out;
  EXPECT_EQ(lines[1], "1000,,,,invalid,");
  EXPECT_EQ(lines[2], "1500,,,,invalid,");
  for (std::size_t i = 3; i < lines.size(); ++i) {
    EXPECT_FALSE(contains(lines[i], "invalid")) << lines[i];
  }
  EXPECT_TRUE(contains(r.err, "2 of 5 values are refused")) << r.err;
  EXPECT_TRUE(contains(r.err, "L = 1000")) << r.err;
  // No swept L leaves room for d: refused, at the swept values rather than the preset's L.
  const RunResult none =
      run({"sweep", "--set", "d=800", "--param", "L", "--from", "1000", "--to", "1500"});
  EXPECT_EQ(none.exit_status, 2);
  EXPECT_TRUE(contains(none.err,
                       "no value of the range is valid given the other inputs; at L = "
                       "1000"))
      << none.err;
  EXPECT_FALSE(contains(none.err, "700 mm")) << none.err;
}

// --from and --to read a value as --set reads one of the swept input: with its unit, and a bare
// weight with --set's hint.
TEST_F(CliTest, SweepEndsAreReadWithTheirUnitsAsSetReadsThem) {
  const RunResult r = run(
      {"sweep", "--param", "w", "--from", "100gsm", "--to", "300 g/m2", "--steps", "2", "--csv"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::vector<std::string> lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_TRUE(starts_with(lines[1], "9.81e-07,")) << lines[1];
  EXPECT_TRUE(starts_with(lines[2], "2.943e-06,")) << lines[2];
  const RunResult metres =
      run({"sweep", "--param", "L", "--from", "1m", "--to", "2m", "--steps", "2", "--csv"});
  ASSERT_EQ(metres.exit_status, 0) << metres.err;
  EXPECT_TRUE(starts_with(split_lines(metres.out).at(1), "1000,")) << metres.out;

  const RunResult bare = run({"sweep", "--param", "w", "--from", "100", "--to", "300"});
  EXPECT_EQ(bare.exit_status, 2);
  EXPECT_TRUE(contains(bare.err,
                       "a bare number for w is read in N/mm²; for 100 g/m² write "
                       "w=100gsm"))
      << bare.err;
  const RunResult mega = run({"sweep", "--param", "L", "--from", "1.4M", "--to", "2m"});
  EXPECT_EQ(mega.exit_status, 2);
  EXPECT_TRUE(contains(mega.err, "--from L = '1.4M': 'M' is not a unit of length")) << mega.err;
  // picture sweep reads them the same way.
  const RunResult picture = run({"picture", "sweep", "--size", "400x300", "--param", "w", "--from",
                                 "100", "--to", "300", "--out", (dir_ / "w.png").string()});
  EXPECT_EQ(picture.exit_status, 2);
  EXPECT_EQ(picture.err, bare.err);
}

TEST_F(CliTest, OverflowingNumberIsNamedAsSuch) {
  const RunResult r = run({"solve", "--set", "t=1e309"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "beyond the range of a double")) << r.err;
  // A sweep's end is read as --set reads it, and named in the same words.
  const RunResult end = run({"sweep", "--param", "t", "--from", "1e309", "--to", "1"});
  EXPECT_EQ(end.exit_status, 2);
  EXPECT_TRUE(contains(end.err, "--from t = '1e309' is beyond the range of a double")) << end.err;
}

// Counts are read as numbers, so that 1e3 is 1000 and 2.5 is refused as not whole.
TEST_F(CliTest, StressAndBenchCountsAcceptWholeNumbersInAnyNotation) {
  RunResult r = run({"stress", "--samples", "1e3", "--json"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).at("samples"), 1000) << r.out;
  r = run({"stress", "--samples", "2.5"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "2.5 must be a whole number from 1 to 10000000")) << r.err;
  r = run({"bench", "--cases", "1e0", "--repeats", "1.5"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "1.5 must be a whole number from 1 to 1000")) << r.err;
}

TEST_F(CliTest, ExportSamplesAcceptWholeNumbersInAnyNotation) {
  const fs::path svg = dir_ / "lines.svg";
  const fs::path csv = dir_ / "lines.csv";
  const RunResult ok = run({"export", "--samples", "1e3", "--csv", csv.string()});
  EXPECT_EQ(ok.exit_status, 0) << ok.err;
  const RunResult half = run({"export", "--samples", "2.5", "--svg", svg.string()});
  EXPECT_EQ(half.exit_status, 2);
  EXPECT_TRUE(contains(half.err, "--samples 2.5 must be a whole number")) << half.err;
  EXPECT_FALSE(fs::exists(svg));
}

TEST_F(CliTest, ExportRefusesTwoOutputsOnOnePath) {
  const fs::path svg = dir_ / "lines.svg";
  const fs::path same = dir_ / "." / "lines.svg";
  const RunResult r = run({"export", "--svg", svg.string(), "--csv", same.string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "name the same file")) << r.err;
  EXPECT_FALSE(fs::exists(svg));
}

TEST_F(CliTest, MeasuredDepthBeyondHalfTheUpperEdgeIsRefused) {
  // The default preset's L is 1400 mm, so no fold can stand out more than 700 mm.
  const RunResult deep = run({"measure", "--depths-mm", "80,40,20,10", "--z-max-mm", "701"});
  EXPECT_EQ(deep.exit_status, 2);
  EXPECT_TRUE(contains(deep.err, "L/2 = 700 mm")) << deep.err;
  const RunResult fine = run({"measure", "--depths-mm", "80,40,20,10", "--z-max-mm", "700"});
  EXPECT_EQ(fine.exit_status, 0) << fine.err;
}

// A fold depth is bounded as z_max is, by how far the cloth hangs: its lower boundary at the
// centre, a_0 = 1.01 h (1414 mm for the default h = 1400 mm), which solve's own a_0 stays within.
TEST_F(CliTest, MeasuredFoldDeeperThanTheClothHangsIsRefused) {
  const RunResult deep = run({"measure", "--depths-mm", "90000,60000"});
  EXPECT_EQ(deep.exit_status, 2) << deep.out;
  EXPECT_TRUE(contains(deep.err,
                       "--depths-mm: depth 0 = 90000 mm is deeper than the cloth's "
                       "lower boundary at the centre, 1.01 h = 1414 mm at h = 1400 mm"))
      << deep.err;
  EXPECT_TRUE(contains(run({"measure", "--depths-mm", "1415,700"}).err, "depth 0 = 1415 mm"));
  const json solved = solve_json({});
  const double a0 = solved.at("a_mm").at(0).get<double>();
  char first[32];
  std::snprintf(first, sizeof first, "%.17g", a0);
  const RunResult back = run({"measure", "--depths-mm", std::string(first) + ",700"});
  EXPECT_EQ(back.exit_status, 0) << back.err;
}

// Refusals say what is wrong in words that agree with each other and name the option given.
TEST_F(CliTest, MeasureAndPictureRefusalsSayWhatIsWrongAndWhose) {
  const RunResult nothing = run({"measure"});
  EXPECT_EQ(nothing.exit_status, 2);
  EXPECT_TRUE(contains(nothing.err, "measure needs the folds, and none were given")) << nothing.err;
  EXPECT_FALSE(contains(nothing.err, "not both")) << nothing.err;

  const RunResult order = run({"measure", "--depths-mm", "100,200"});
  EXPECT_EQ(order.exit_status, 2);
  EXPECT_TRUE(contains(order.err, "the depths must be listed deepest first")) << order.err;
  EXPECT_TRUE(contains(order.err, "depth 1 = 200 mm is not shallower than depth 0 = 100 mm"))
      << order.err;

  // A negative z_max and a zero one are refused in the same words.
  const RunResult negative = run({"measure", "--depths-mm", "80,40", "--z-max-mm", "-1"});
  const RunResult zero = run({"measure", "--depths-mm", "80,40", "--z-max-mm", "0"});
  EXPECT_EQ(negative.exit_status, 2);
  EXPECT_EQ(zero.exit_status, 2);
  EXPECT_TRUE(contains(negative.err, "--z-max-mm -1 must be > 0")) << negative.err;
  EXPECT_TRUE(contains(zero.err, "--z-max-mm 0 must be > 0")) << zero.err;

  const fs::path png = dir_ / "ab.png";
  const RunResult unknown =
      run({"picture", "compare", "--size", "400x300", "--b-set", "zz=1", "--out", png.string()});
  EXPECT_EQ(unknown.exit_status, 2);
  EXPECT_TRUE(contains(unknown.err, "--b-set unknown key 'zz'")) << unknown.err;
  EXPECT_FALSE(contains(unknown.err, "--set")) << unknown.err;
  const RunResult range =
      run({"picture", "compare", "--size", "400x300", "--b-set", "h=2e5", "--out", png.string()});
  EXPECT_EQ(range.exit_status, 2);
  EXPECT_TRUE(contains(range.err, "B's height h = 200,000 mm must be between")) << range.err;
  EXPECT_FALSE(fs::exists(png));
}

// `measure` refuses a row that its own readers would refuse (Q above 100, z_max of 0), with or
// without --append, and leaves the file as it was: every later append and calibration on it goes
// on working.
TEST_F(CliTest, MeasureNeverWritesARowItsReadersRefuse) {
  const fs::path rows = dir_ / "rows.csv";
  ASSERT_EQ(run({"measure", "--depths-mm", "80,40,20,10", "--append", rows.string()}).exit_status,
            0);
  const std::string before = read_file(rows);
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--depths-mm", "1000,0.001"},
        std::vector<std::string>{"--depths-mm", "80,40,20,10", "--z-max-mm", "0"}}) {
    for (const bool append : {false, true}) {
      std::vector<std::string> args = {"measure"};
      args.insert(args.end(), bad.begin(), bad.end());
      if (append) {
        args.insert(args.end(), {"--append", rows.string()});
      }
      const RunResult r = run(args);
      EXPECT_EQ(r.exit_status, 2) << bad[1] << ": " << r.out;
      // A z_max of 0 is refused up front, in the words of the row's rule.
      EXPECT_TRUE(contains(r.err, bad.size() > 2 ? "must be > 0" : "the measured row")) << r.err;
    }
  }
  EXPECT_EQ(read_file(rows), before);
  EXPECT_EQ(run({"measure", "--depths-mm", "60,30,15", "--append", rows.string()}).exit_status, 0);
}

// A name is the user's text: a terminal escape in it (clear the screen, ring the bell) is spelt out
// as \xNN wherever a command prints it, never sent to the terminal.
TEST_F(CliTest, NamesReachTheTerminalSpeltOutNeverAsEscapes) {
  const std::string evil = "Evil\x1b[2J\x07";
  const std::string spelt = "Evil\\x1b[2J\\x07";
  const auto clean = [](const RunResult& r) {
    return r.out.find('\x1b') == std::string::npos && r.err.find('\x1b') == std::string::npos;
  };
  const fs::path rows = dir_ / "rows.csv";
  // measure refuses such a name (it would go into the file), spelt out in the refusal.
  const RunResult measured =
      run({"measure", "--depths-mm", "80,40,20,10", "--name", evil, "--append", rows.string()});
  EXPECT_EQ(measured.exit_status, 2) << measured.err;
  EXPECT_TRUE(clean(measured));
  EXPECT_TRUE(contains(measured.err, spelt)) << measured.err;
  EXPECT_FALSE(fs::exists(rows));
  // A file written by another tool may hold one: calibrate prints it spelt out. The name is
  // the first column.
  ASSERT_EQ(run({"measure", "--depths-mm", "80,40,20,10", "--append", rows.string()}).exit_status,
            0);
  ASSERT_EQ(run({"measure", "--depths-mm", "60,30,15", "--append", rows.string()}).exit_status, 0);
  std::string text = read_file(rows);
  const std::size_t first_row = text.find('\n', text.find("name,")) + 1;
  text.insert(first_row, evil);
  std::ofstream(rows) << text;
  const RunResult calibrated = run({"calibrate", "--data", rows.string(), "--fit", "K"});
  EXPECT_TRUE(clean(calibrated)) << calibrated.out;
  EXPECT_TRUE(contains(calibrated.out, spelt)) << calibrated.out;

  json preset = json::parse(read_file(kH900));
  preset["name"] = evil;
  const fs::path preset_path = dir_ / "evil.json";
  std::ofstream(preset_path) << preset.dump();
  const RunResult solved = run({"solve", "--preset", preset_path.string()});
  ASSERT_EQ(solved.exit_status, 0) << solved.err;
  EXPECT_TRUE(clean(solved));
  EXPECT_TRUE(contains(solved.out, spelt)) << solved.out;

  // Text of the command line quoted in any message: a missing file, an unknown option, a value.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"solve", "--preset", evil},
        std::vector<std::string>{"export", "--obj", evil + "/x.obj"},
        std::vector<std::string>{"solve", "--method", evil},
        std::vector<std::string>{"sweep", "--param", evil},
        std::vector<std::string>{"solve", evil}}) {
    const RunResult r = run(args);
    EXPECT_NE(r.exit_status, 0) << args[1];
    EXPECT_TRUE(clean(r)) << args[1] << ": " << r.err;
  }
  // In a Markdown table a '|' in a name stays inside its cell.
  preset["name"] = "X|Y";
  std::ofstream(preset_path) << preset.dump();
  const RunResult compared = run({"compare", "--preset", preset_path.string()});
  ASSERT_EQ(compared.exit_status, 0) << compared.err;
  EXPECT_TRUE(contains(compared.out, "| X\\|Y |")) << compared.out;
  // A line break in a name is one line too.
  const RunResult two_lines = run({"measure", "--depths-mm", "80,40", "--name", "A\nB"});
  EXPECT_EQ(two_lines.exit_status, 2) << two_lines.err;
  EXPECT_TRUE(contains(two_lines.err, "A\\x0aB")) << two_lines.err;
}

// An export stopped by SIGTERM or SIGINT while it writes removes its temporary, 100 MB for a
// 1024 x 1024 OBJ, and leaves no file under the target's name: nothing was written.
TEST_F(CliTest, AnExportInterruptedWhileItWritesLeavesNoTemporary) {
  for (const int number : {SIGTERM, SIGINT}) {
    const fs::path obj = dir_ / "k.obj";
    const pid_t pid = start({"export", "--obj", obj.string(), "--grid", "1024x1024"});
    ASSERT_GE(pid, 0);
    const auto temporaries = [&] {
      int count = 0;
      for (const std::string& name : entries()) {
        count += contains(name, ".tmp.") ? 1 : 0;
      }
      return count;
    };
    // Polled until the temporary appears: the signal must come while the file is written.
    bool writing = false;
    int status = 0;
    bool exited = false;
    while (!writing && !exited) {
      writing = temporaries() > 0;
      if (!writing) {
        exited = ::waitpid(pid, &status, WNOHANG) == pid;
        ::usleep(500);
      }
    }
    ASSERT_TRUE(writing) << "the export finished before a temporary was seen";
    ASSERT_EQ(::kill(pid, number), 0);
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == number) << status;
    EXPECT_EQ(temporaries(), 0) << number;
    EXPECT_FALSE(fs::exists(obj)) << number;
  }
}

// An output that exists and that the user could not open for writing is refused (exit 1), not
// replaced by a rename that only needs the folder's permission: a read-only file of the user's, and
// another user's file in a world-writable folder. Run as an unprivileged user (nobody) when the
// suite runs as root, for whom every file is writable.
TEST_F(CliTest, AnOutputTheUserCouldNotOpenForWritingIsRefusedNotReplaced) {
  const bool root = ::geteuid() == 0;
  constexpr uid_t kNobody = 65534;
  const auto run_as_user = [&](std::vector<std::string> args) {
    if (!root) {
      return run(args);
    }
    args.insert(args.begin(), {"--reuid=65534", "--regid=65534", "--clear-groups", kExecutable});
    return foldlab::testing::run_process("setpriv", args, dir_);
  };
  fs::permissions(dir_, fs::perms::all);  // rwxrwxrwx, not sticky
  const fs::path read_only = dir_ / "read-only.obj";
  std::ofstream(read_only) << "keep\n";
  fs::permissions(read_only,
                  fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  if (root) {
    ASSERT_EQ(::chown(read_only.c_str(), kNobody, kNobody), 0);
  }
  RunResult r = run_as_user({"export", "--grid", "8x8", "--obj", read_only.string()});
  EXPECT_EQ(r.exit_status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "cannot write " + read_only.string() + ": read-only")) << r.err;
  EXPECT_EQ(read_file(read_only), "keep\n");
  if (!root) {
    GTEST_SKIP() << "another user's file needs a second user: run as root to test it";
  }
  const fs::path theirs = dir_ / "theirs.svg";
  std::ofstream(theirs) << "keep\n";  // root's, 0644
  r = run_as_user({"export", "--svg", theirs.string()});
  EXPECT_EQ(r.exit_status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "cannot write " + theirs.string() + ": owned by another user"))
      << r.err;
  EXPECT_EQ(read_file(theirs), "keep\n");
  struct stat info {};
  ASSERT_EQ(::stat(theirs.c_str(), &info), 0);
  EXPECT_EQ(info.st_uid, 0u);
  // What the user may write is still written.
  r = run_as_user({"export", "--svg", (dir_ / "mine.svg").string()});
  EXPECT_EQ(r.exit_status, 0) << r.err;
}

TEST_F(CliTest, NoOutputOverwritesAnInputOrAnotherOutputThroughLinks) {
  const fs::path preset = dir_ / "fabric.json";
  fs::copy_file(kH900, preset);
  const std::string before = read_file(preset);
  const RunResult onto_input =
      run({"export", "--preset", preset.string(), "--obj", preset.string()});
  EXPECT_EQ(onto_input.exit_status, 2);
  EXPECT_TRUE(contains(onto_input.err, "would destroy the input")) << onto_input.err;
  EXPECT_EQ(read_file(preset), before);
  // A symlink and a hard link name the file they link to.
  const fs::path obj = dir_ / "real.obj";
  std::ofstream(obj) << "o kept\n";
  fs::create_symlink(obj, dir_ / "link.glb");
  fs::create_hard_link(obj, dir_ / "hard.csv");
  for (const char* other : {"link.glb", "hard.csv"}) {
    SCOPED_TRACE(other);
    const std::string option = std::string(other).ends_with(".glb") ? "--glb" : "--csv";
    const RunResult r = run({"export", "--obj", obj.string(), option, (dir_ / other).string()});
    EXPECT_EQ(r.exit_status, 2);
    EXPECT_TRUE(contains(r.err, "name the same file")) << r.err;
    EXPECT_EQ(read_file(obj), "o kept\n");
  }
  const RunResult bench =
      run({"bench", "--cases", "2", "--repeats", "1", "--csv", (dir_ / "b.csv").string(), "--svg",
           (dir_ / "." / "b.csv").string()});
  EXPECT_EQ(bench.exit_status, 2);
  EXPECT_TRUE(contains(bench.err, "name the same file")) << bench.err;
}

TEST_F(CliTest, CalibrateNeverSavesOverItsMeasurements) {
  const fs::path data = dir_ / "rows.csv";
  fs::copy_file(kPresetsDir.parent_path() / "data" / "paper-measurements.csv", data);
  const std::string before = read_file(data);
  const RunResult r = run({"calibrate", "--data", data.string(), "--no-held-out", "--save-preset",
                           (dir_ / "." / "rows.csv").string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "would destroy the input")) << r.err;
  EXPECT_EQ(read_file(data), before);
}

TEST_F(CliTest, MeasureAppendsToAnEmptyFileAsToANewOne) {
  const fs::path rows = dir_ / "rows.csv";
  std::ofstream{rows};  // created empty, as `touch` would
  const RunResult r = run({"measure", "--depths-mm", "100,50", "--append", rows.string()});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  const std::vector<std::string> lines = split_lines(read_file(rows));
  ASSERT_EQ(lines.size(), 2u) << read_file(rows);
  EXPECT_TRUE(starts_with(lines[0], "name,")) << lines[0];
  EXPECT_TRUE(contains(lines[1], ",fit,")) << lines[1];
}

// Ten `measure --append` processes at once on one file: each reads the file, adds its row and
// replaces the file, so without a lock all but the last writer's row were lost (all exiting 0).
TEST_F(CliTest, ParallelAppendsKeepEveryRow) {
  const fs::path rows = dir_ / "rows.csv";
  constexpr int kProcesses = 10;
  // The children wait on a pipe and start together when it closes, so that they overlap.
  int start[2];
  ASSERT_EQ(::pipe(start), 0);
  std::vector<pid_t> children;
  for (int i = 0; i < kProcesses; ++i) {
    const std::string name = "parallel " + std::to_string(i);
    const std::string err = (dir_ / ("err" + std::to_string(i))).string();
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::close(start[1]);
      char byte = 0;
      while (::read(start[0], &byte, 1) < 0 && errno == EINTR) {
      }
      const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int null_fd = ::open("/dev/null", O_WRONLY);
      if (err_fd < 0 || null_fd < 0 || ::dup2(null_fd, STDOUT_FILENO) < 0 ||
          ::dup2(err_fd, STDERR_FILENO) < 0) {
        ::_exit(126);
      }
      ::execl(kExecutable.c_str(), kExecutable.c_str(), "measure", "--depths-mm", "100,50,25",
              "--name", name.c_str(), "--append", rows.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    children.push_back(pid);
  }
  ::close(start[0]);
  ::close(start[1]);
  for (std::size_t i = 0; i < children.size(); ++i) {
    int status = 0;
    ASSERT_EQ(::waitpid(children[i], &status, 0), children[i]);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "process " << i << ": " << read_file(dir_ / ("err" + std::to_string(i)));
  }
  foldlab::MeasurementSet set;
  ASSERT_NO_THROW(set = foldlab::load_measurements(rows)) << read_file(rows);
  std::set<std::string> names;
  for (const foldlab::Measurement& row : set.rows) {
    names.insert(row.name);
  }
  EXPECT_EQ(set.rows.size(), static_cast<std::size_t>(kProcesses)) << read_file(rows);
  for (int i = 0; i < kProcesses; ++i) {
    EXPECT_EQ(names.count("parallel " + std::to_string(i)), 1u) << read_file(rows);
  }
  // Nothing but the file itself is left beside it (no temporaries, no lock files).
  for (const fs::directory_entry& e : fs::directory_iterator(dir_)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name == "rows.csv" || name.starts_with("err")) << name;
  }
}

TEST_F(CliTest, PlayingAFolderIsInvalidInputNotAnInternalError) {
  const RunResult r = run({"render", "--play", dir_.string()});
  EXPECT_EQ(r.exit_status, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "a directory, not a regular file")) << r.err;
}

// Every --play step costs frames (a typed character one, a key chord four, a drag ten), and they
// all count toward the one cap that frames steps have: a script over it is refused before a frame
// runs, naming the step that takes it past, as 100,001 frames are.
TEST_F(CliTest, EveryPlayStepCountsTowardTheScriptsFrameCap) {
  const auto play = [&](const json& steps) {
    const fs::path script = dir_ / "script.json";
    std::ofstream(script) << json{{"steps", steps}}.dump();
    return run({"render", "--play", script.string(), "--size", "320x240"});
  };
  const auto refused_at = [&](const json& steps, const std::string& said) {
    const RunResult r = play(steps);
    EXPECT_EQ(r.exit_status, 2) << r.err;
    EXPECT_TRUE(contains(r.err, said)) << r.err.substr(0, 500);
  };
  const auto repeated = [](const json& step, int count) {
    json steps = json::array();
    for (int i = 0; i < count; ++i) {
      steps.push_back(step);
    }
    return steps;
  };
  refused_at(json::array({{{"type", std::string(150000, 'a')}}}),
             "step 1 (type) takes the script past the cap: its steps add up to 150001, more "
             "than the 100000 frames a script may run");
  // 25,000 chords are 100,000 frames, the cap; one more frame is too many.
  json keys = repeated({{"key", "escape"}}, 25000);
  keys.push_back({{"screenshot", (dir_ / "never.png").string()}});
  refused_at(keys,
             "step 25001 (screenshot) takes the script past the cap: its steps add up to "
             "100001");
  EXPECT_FALSE(fs::exists(dir_ / "never.png"));
  refused_at(repeated({{"drag", "h"}, {"dx", 1}}, 10001),
             "step 10001 (drag) takes the script past the cap: its steps add up to 100010");
}

// Every file a command reads goes through one reader: a FIFO is refused without waiting for a
// writer, a device without reading forever, a file over its kind's cap from its size alone. Each
// is bad input (exit 2) that names the file, for every loader. `timeout` turns a hang into a
// failure instead of a stuck suite.
TEST_F(CliTest, EveryLoaderRefusesFifosDevicesAndHugeFilesAsInvalidInput) {
  const fs::path fifo = dir_ / "input.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path huge = dir_ / "huge.csv";
  std::ofstream(huge).put('x');
  fs::resize_file(huge, std::uintmax_t{2} << 30);  // sparse: no disk, no memory
  const std::vector<std::pair<std::string, std::string>> inputs = {
      {fifo.string(), "a FIFO, not a regular file"},
      {"/dev/zero", "a character device, not a regular file"},
      {huge.string(), "2.0 GB, more than the"}};
  const std::string svg = (dir_ / "o.svg").string();
  const std::vector<std::vector<std::string>> commands = {
      {"solve", "--preset"},
      {"calibrate", "--data"},
      {"render", "--play"},
      {"export", "--svg", svg, "--preset"},
      {"measure", "--supports-px", "10,10,90,10", "--folds-px", "60,50", "--photo"}};
  for (const auto& [path, reason] : inputs) {
    for (std::vector<std::string> args : commands) {
      args.push_back(path);
      args.insert(args.begin(), {"20", kExecutable});
      const RunResult r = foldlab::testing::run_process("timeout", args, dir_);
      EXPECT_EQ(r.exit_status, 2) << args[2] << " " << path << ": " << r.err;
      EXPECT_TRUE(contains(r.err, reason)) << args[2] << " " << path << ": " << r.err;
      EXPECT_TRUE(contains(r.err, path)) << args[2] << ": " << r.err;
    }
  }
}

TEST_F(CliTest, ExportSaysWhenItDrawsOnlyEveryKthFoldLine) {
  // t = 0.001 mm, E = 0.001 MPa, w = 1e-3 N/mm²: s is tiny and eq. 10 asks for tens of thousands
  // of folds, above the 1000 lines a drawing holds.
  const fs::path csv = dir_ / "lines.csv";
  const RunResult r = run({"export", "--set", "t=0.001", "--set", "E=0.001", "--set", "w=1e-3",
                           "--samples", "2", "--csv", csv.string()});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "are too many to draw: the CSV and SVG hold one line in")) << r.err;
  const RunResult few = run({"export", "--csv", csv.string()});
  EXPECT_FALSE(contains(few.err, "too many to draw")) << few.err;
}

// `foldlab --version`: the version of project(VERSION ...), the commit when built from git, and
// the presets folder it found (here, run from its build folder: the source tree's).
TEST_F(CliTest, VersionPrintsTheProjectVersionAndThePresetsFolder) {
  const RunResult r = run({"--version"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::vector<std::string> lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  EXPECT_TRUE(lines[0] == "FoldLab " FOLDLAB_VERSION ||
              starts_with(lines[0], "FoldLab " FOLDLAB_VERSION " ("))
      << lines[0];
  EXPECT_EQ(fs::weakly_canonical(lines[1].substr(lines[1].find(": ") + 2)),
            fs::weakly_canonical(kPresetsDir))
      << lines[1];
}

// A path or folder the user gave reaches the terminal spelt as every quoted text is (\x1b for
// ESC), on stdout and on stderr alike, so that a file name cannot clear or recolour the screen.
TEST_F(CliTest, OutputPathsAndThePresetsFolderReachTheTerminalEscaped) {
  const std::string esc = "\x1b[2J";
  const fs::path csv = dir_ / ("m" + esc + ".csv");
  const RunResult measured =
      run({"measure", "--depths-mm", "80,40,20,10", "--append", csv.string()});
  ASSERT_EQ(measured.exit_status, 0) << measured.err;
  EXPECT_FALSE(contains(measured.out + measured.err, "\x1b")) << measured.out;
  EXPECT_TRUE(contains(measured.out, "m\\x1b[2J.csv")) << measured.out;

  const fs::path saved = dir_ / ("p" + esc + ".json");
  const RunResult calibrated = run({"calibrate", "--data", csv.string(), "--fit", "K",
                                    "--no-held-out", "--save-preset", saved.string()});
  ASSERT_EQ(calibrated.exit_status, 0) << calibrated.err;
  EXPECT_FALSE(contains(calibrated.out + calibrated.err, "\x1b")) << calibrated.err;
  EXPECT_TRUE(contains(calibrated.err, "p\\x1b[2J.json")) << calibrated.err;
  EXPECT_TRUE(contains(calibrated.out, "m\\x1b[2J.csv")) << calibrated.out;

  const fs::path presets = dir_ / ("pre" + esc + "sets");
  fs::create_directories(presets);
  foldlab::testing::Environment env;
  env.set = {{"FOLDLAB_PRESETS_DIR", presets.string()}};
  const RunResult version = foldlab::testing::run_process(kExecutable, {"--version"}, dir_, env);
  ASSERT_EQ(version.exit_status, 0) << version.err;
  EXPECT_FALSE(contains(version.out, "\x1b")) << version.out;
  EXPECT_TRUE(contains(version.out, "pre\\x1b[2Jsets")) << version.out;
}

// The presets folder is the first that exists: a $FOLDLAB_PRESETS_DIR that does not exist is
// passed over, with a word saying so, and the shipped presets stay in reach.
TEST_F(CliTest, APresetsFolderThatDoesNotExistIsPassedOverWithANotice) {
  const fs::path missing = dir_ / "no-such-folder";
  foldlab::testing::Environment env;
  env.set = {{"FOLDLAB_PRESETS_DIR", missing.string()}};
  const RunResult version = foldlab::testing::run_process(kExecutable, {"--version"}, dir_, env);
  ASSERT_EQ(version.exit_status, 0) << version.err;
  const std::vector<std::string> lines = split_lines(version.out);
  ASSERT_EQ(lines.size(), 2u) << version.out;
  EXPECT_EQ(fs::weakly_canonical(lines[1].substr(lines[1].find(": ") + 2)),
            fs::weakly_canonical(kPresetsDir))
      << lines[1];
  EXPECT_TRUE(contains(version.err, "FOLDLAB_PRESETS_DIR " + missing.string() + " does not exist"))
      << version.err;
  const RunResult named = foldlab::testing::run_process(
      kExecutable, {"solve", "--preset", "paper-table1-h900", "--json"}, dir_, env);
  ASSERT_EQ(named.exit_status, 0) << named.err;
  EXPECT_EQ(json::parse(named.out).at("inputs").at("height_mm").get<double>(), 900.0);
  EXPECT_TRUE(contains(named.err, "does not exist")) << named.err;
}

// Fitting K and p with leave-one-out refits both once per fit row, so its time grows as m²: 500
// rows would run for most of an hour. What cannot finish in about a minute is refused before any
// fit, saying why and what to do instead; K alone, or K and p without held-out fits, still run.
TEST_F(CliTest, CalibrateRefusesUpFrontAFitThatWouldRunForMinutes) {
  const fs::path data = fit_rows_file(500, 3.0);
  const RunResult refused = run({"calibrate", "--data", data.string(), "--fit", "K,p"});
  EXPECT_EQ(refused.exit_status, 2) << refused.err;
  EXPECT_TRUE(refused.out.empty()) << refused.out.substr(0, 300);
  EXPECT_TRUE(contains(refused.err, "--fit K,p with held-out fits: 500 fit rows")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "--fit K")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "--no-held-out")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "at most 80 fit rows")) << refused.err;
}

// A long fit says how far it is, on stderr and only where a person watches (a terminal): a
// script capturing stderr gets no progress line.
TEST_F(CliTest, CalibrateShowsProgressOnATerminalOnly) {
  const fs::path data = fit_rows_file(12, 100.0);
  const std::vector<std::string> args = {"calibrate", "--data", data.string(), "--fit", "K,p"};
  const RunResult captured = run(args);
  ASSERT_EQ(captured.exit_status, 0) << captured.err;
  EXPECT_FALSE(contains(captured.err, "% (Ctrl+C stops)")) << captured.err;

  int terminal = -1;
  const pid_t pid = ::forkpty(&terminal, nullptr, nullptr, nullptr);
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    std::vector<char*> argv = {const_cast<char*>(kExecutable.c_str())};
    for (const std::string& arg : args) {
      argv.push_back(const_cast<char*>(arg.c_str()));
    }
    argv.push_back(nullptr);
    ::execv(kExecutable.c_str(), argv.data());
    ::_exit(127);
  }
  std::string seen;
  char buffer[4096];
  for (ssize_t got; (got = ::read(terminal, buffer, sizeof buffer)) > 0;) {
    seen.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(terminal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << seen;
  EXPECT_TRUE(contains(seen, "calibrate: ")) << seen;
  EXPECT_TRUE(contains(seen, "% (Ctrl+C stops)")) << seen;
}

// A preset the program saves says which FoldLab wrote it.
TEST_F(CliTest, SavedPresetRecordsTheVersionThatWroteIt) {
  const fs::path out = dir_ / "fitted.json";
  const RunResult r = run({"calibrate", "--data",
                           (kPresetsDir.parent_path() / "data" / "paper-measurements.csv").string(),
                           "--fit", "K", "--no-held-out", "--save-preset", out.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(read_file(out));
  EXPECT_TRUE(starts_with(j.at("written_by").get<std::string>(), "FoldLab " FOLDLAB_VERSION))
      << j.dump(2);
  EXPECT_EQ(run({"solve", "--preset", out.string()}).exit_status, 0);
}

// --- The paper accuracy report: how close the model gets to the paper, table by table. ---

namespace {

// The paper's printed results, typed here from the paper (Tables 1-2 and Fig. 4), not read from
// the presets or data/: the report is checked against them, and the presets and data/ too.
struct PrintedRow {
  const char* preset;  // the preset that carries the row's inputs
  const char* table;
  int n;
  double z_max_mm;
  double Q;  // 0: the paper prints no usable Q (Fig. 4's 0.6 is impossible)
};
constexpr PrintedRow kPrinted[] = {
    {"paper-table1-h900", "Table 1", 5, 54.0, 1.31},
    {"paper-table1-h1400", "Table 1", 7, 48.0, 1.29},
    {"paper-table1-h2350", "Table 1", 8, 60.0, 1.34},
    {"paper-table2-w10", "Table 2", 4, 56.0, 1.78},
    {"paper-table2-w33", "Table 2", 6, 46.0, 1.46},
    {"paper-table2-w54", "Table 2", 7, 44.0, 1.39},
    {"paper-fig4", "Fig. 4", 4, 70.0, 0.0},
};

class PaperAccuracy : public CliTest {};

// The published values in the presets and in data/paper-measurements.csv are the paper's.
TEST_F(PaperAccuracy, ThePresetsAndTheMeasurementsCarryThePapersPrintedNumbers) {
  const foldlab::MeasurementSet data =
      foldlab::load_measurements(kPresetsDir.parent_path() / "data" / "paper-measurements.csv");
  ASSERT_EQ(data.rows.size(), std::size(kPrinted));
  for (std::size_t i = 0; i < std::size(kPrinted); ++i) {
    const PrintedRow& printed = kPrinted[i];
    SCOPED_TRACE(printed.preset);
    const json published =
        json::parse(read_file(kPresetsDir / (std::string(printed.preset) + ".json")))
            .at("published");
    EXPECT_EQ(published.at("n"), printed.n);
    EXPECT_EQ(published.at("z_max_mm"), printed.z_max_mm);
    EXPECT_EQ(published.value("Q", 0.0), printed.Q);
    // data/ lists the rows in the same order, Fig. 4 last.
    const foldlab::PublishedResult& observed = data.rows[i].observed;
    EXPECT_EQ(observed.n, printed.n);
    EXPECT_EQ(observed.z_max_mm, printed.z_max_mm);
    EXPECT_EQ(observed.Q.value_or(0.0), printed.Q);
  }
}

// `foldlab compare`'s "Paper accuracy by table" and its JSON twin: per table and method, the rows
// whose n is the paper's, those within one of it, and the median |z_max / printed z_max - 1|,
// counted here again from the model's values and the paper's printed ones.
TEST_F(PaperAccuracy, CompareReportsEachTableAgainstThePapersPrintedNumbers) {
  std::vector<std::string> args = {"compare"};
  for (const PrintedRow& printed : kPrinted) {
    args.insert(args.end(),
                {"--preset", (kPresetsDir / (std::string(printed.preset) + ".json")).string()});
  }
  const RunResult text = run(args);
  ASSERT_EQ(text.exit_status, 0) << text.err;
  args.push_back("--json");
  const json out = foldlab::testing::json_output(run(args));
  const json& rows = out.at("rows");
  ASSERT_EQ(rows.size(), std::size(kPrinted)) << out.dump(2);

  struct Expected {
    std::string table;
    int rows = 0;
    int n_exact[2] = {0, 0};
    int n_within_one[2] = {0, 0};
    std::vector<double> z_errors[2];
  };
  std::vector<Expected> expected;  // in the order the rows first name a table
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PrintedRow& printed = kPrinted[i];
    auto table = std::find_if(expected.begin(), expected.end(),
                              [&](const Expected& e) { return e.table == printed.table; });
    if (table == expected.end()) {
      expected.emplace_back();
      expected.back().table = printed.table;
      table = expected.end() - 1;
    }
    ++table->rows;
    for (int m = 0; m < 2; ++m) {
      const json& model = rows[i].at(m == 0 ? "paper" : "exact");
      const int n = model.at("n").get<int>();
      table->n_exact[m] += n == printed.n;
      table->n_within_one[m] += std::abs(n - printed.n) <= 1;
      table->z_errors[m].push_back(
          std::abs(model.at("z_max_mm").get<double>() / printed.z_max_mm - 1.0));
    }
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t mid = v.size() / 2;
    return v.size() % 2 == 1 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
  };

  const json& report = out.at("accuracy_by_table");
  ASSERT_EQ(expected.size(), 3u);  // Table 1, Table 2 and Fig. 4
  ASSERT_EQ(report.size(), expected.size()) << report.dump(2);
  const std::size_t section = text.out.find("\nPaper accuracy by table:\n");
  ASSERT_NE(section, std::string::npos) << text.out;
  const std::string printed_section = text.out.substr(section);
  std::printf("%s", printed_section.c_str());  // the report, in the test's log
  for (std::size_t t = 0; t < expected.size(); ++t) {
    const Expected& e = expected[t];
    SCOPED_TRACE(e.table);
    EXPECT_EQ(report[t].at("table"), e.table);
    EXPECT_EQ(report[t].at("rows"), e.rows);
    std::string line = "| " + e.table + " | " + std::to_string(e.rows);
    for (int m = 0; m < 2; ++m) {
      const json& got = report[t].at(m == 0 ? "paper" : "exact");
      EXPECT_EQ(got.at("rows_with_n"), e.rows);
      EXPECT_EQ(got.at("n_exact"), e.n_exact[m]);
      EXPECT_EQ(got.at("n_within_one"), e.n_within_one[m]);
      const double z = median(e.z_errors[m]);
      EXPECT_NEAR(got.at("median_abs_z_error").get<double>(), z, 1e-12);
      char cells[96];
      std::snprintf(cells, sizeof cells, " | %d/%d | %d/%d | %.1f %%", e.n_exact[m], e.rows,
                    e.n_within_one[m], e.rows, 100.0 * z);
      line += cells;
    }
    line += " |\n";
    EXPECT_TRUE(contains(printed_section, line)) << line << printed_section;
  }
  // The report shows what the model misses: Table 1's h = 2350 mm row gets n = 14 for the
  // printed 8, so Table 1 cannot be within one everywhere.
  ASSERT_EQ(report[0].at("table"), "Table 1");
  EXPECT_LT(report[0].at("paper").at("n_within_one").get<int>(), 3) << report.dump(2);
}

// A preset of the user's own with published results is a table of its own in the report.
TEST_F(PaperAccuracy, APresetNamedWithoutACommaIsAGroupOfItsOwn) {
  json preset = json::parse(read_file(kH900));
  preset["name"] = "My cloth";
  preset["published"] = {{"n", 4}, {"z_max_mm", 50.0}};
  const fs::path path = dir_ / "mine.json";
  std::ofstream(path) << preset.dump(2);
  const json out = foldlab::testing::json_output(
      run({"compare", "--json", "--preset", kH900, "--preset", path.string()}));
  const json& report = out.at("accuracy_by_table");
  ASSERT_EQ(report.size(), 2u) << out.dump(2);
  EXPECT_EQ(report[0].at("table"), "Table 1");
  EXPECT_EQ(report[1].at("table"), "My cloth");
  // Its model n is 5 (Table 1's h = 900 mm row): one more than the 4 published here.
  EXPECT_EQ(report[1].at("exact").at("n_exact"), 0);
  EXPECT_EQ(report[1].at("exact").at("n_within_one"), 1);
  EXPECT_EQ(report[1].at("exact").at("rows_with_Q"), 0);
  EXPECT_TRUE(report[1].at("exact").at("median_abs_Q_error").is_null());
}

// `foldlab field` on Conci's set-up: the weight is w L h of the preset (1.5e-6 N/mm² x 1400 mm x
// 1400 mm), the supports carry it between them, the regions share the whole cloth.
TEST_F(CliTest, FieldJsonCarriesTheWeightOnTheSupports) {
  const RunResult r =
      run({"field", "--shape", "rectangular", "--cells-x", "12", "--cells-y", "8", "--json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(r.out);
  for (const char* key : {"converged", "relative_residual", "iterations", "solve_ms", "weight_N",
                          "supports", "regions", "rays"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(j.at("converged").get<bool>());
  EXPECT_LE(j.at("relative_residual").get<double>(), 1e-8);
  const double weight = 1.5e-6 * 1400.0 * 1400.0;
  EXPECT_NEAR(j.at("weight_N").get<double>(), weight, 1e-12 * weight);
  double sum_x = 0.0;
  double sum_y = 0.0;
  ASSERT_EQ(j.at("supports").size(), 2u);
  for (const json& s : j.at("supports")) {
    sum_x += s.at("reaction_N")[0].get<double>();
    sum_y += s.at("reaction_N")[1].get<double>();
  }
  EXPECT_NEAR(sum_x, 0.0, 1e-6 * weight);
  EXPECT_NEAR(sum_y, -weight, 1e-6 * weight);  // y is down: the supports pull the cloth up
  // The left top corner, pinned where the default span rule l = L - d puts it.
  EXPECT_EQ(j.at("supports")[0].at("at_mm"), json({-700.0, 0.0}));
  EXPECT_EQ(j.at("supports")[0].at("to_mm"), json({-650.0, 0.0}));
  const json& regions = j.at("regions");
  EXPECT_NEAR(regions.at("taut").get<double>() + regions.at("wrinkled").get<double>() +
                  regions.at("slack").get<double>(),
              1.0, 1e-12);
  EXPECT_EQ(j.at("rays").size(), 8u);
  // The folds from the field beside the closed form's, which is `solve`'s for the same inputs.
  const json& folds = j.at("field_folds");
  ASSERT_GE(folds.at("n").get<int>(), 1);
  EXPECT_EQ(folds.at("a_mm").size(), folds.at("n").get<std::size_t>() + 1);
  EXPECT_GT(folds.at("z_max_mm").get<double>(), 0.0);
  EXPECT_GT(folds.at("Q").get<double>(), 1.0);
  // The folds take up what the centre fibre keeps beyond its hung in-plane length: never more
  // than the fibre itself, the cut's h = 1400 mm.
  EXPECT_GT(folds.at("slack_width_mm").get<double>(), 0.0);
  EXPECT_LT(folds.at("slack_width_mm").get<double>(), 1400.0);
  const json solved = solve_json({});
  const json& closed = j.at("closed_form");
  EXPECT_EQ(closed.at("n"), solved.at("n"));
  EXPECT_EQ(closed.at("Q"), solved.at("Q"));
  EXPECT_EQ(closed.at("z_max_mm"), solved.at("z_max_mm"));
}

// A cut of the user's own: a valid one solves, a self-crossing one is refused with exit 2 and a
// sentence naming the edge and the vertex.
TEST_F(CliTest, FieldOutlineFileSolvesOrIsRefusedByName) {
  const fs::path good = dir_ / "panel.json";
  std::ofstream(good)
      << R"({"top": [[0, 0], [600, 0]], "bottom": [[0, 400], [300, 500], [600, 400]],
    "supports": [{"at": [0, 0], "to": [30, 0]}, {"at": [600, 0], "to": [570, 0]}]})";
  const RunResult ok =
      run({"field", "--outline", good.string(), "--cells-x", "12", "--cells-y", "8", "--json"});
  ASSERT_EQ(ok.exit_status, 0) << ok.err;
  const json j = json::parse(ok.out);
  // The area by hand: 600 x 400 plus the triangle of base 600 and height 100 below it.
  const double weight = 1.5e-6 * (600.0 * 400.0 + 0.5 * 600.0 * 100.0);
  EXPECT_NEAR(j.at("weight_N").get<double>(), weight, 1e-12 * weight);
  // The closed form beside it is the cut's cloth: 500 mm down the middle, 600 mm between the
  // supports as cut, moved in by 60 mm in all (the default span rule, l = L - d).
  const json& closed = j.at("closed_form");
  EXPECT_EQ(closed.at("cloth"), "cut");
  EXPECT_DOUBLE_EQ(closed.at("h_mm").get<double>(), 500.0);
  EXPECT_DOUBLE_EQ(closed.at("L_mm").get<double>(), 600.0);
  EXPECT_DOUBLE_EQ(closed.at("d_mm").get<double>(), 60.0);
  const RunResult solved =
      run({"solve", "--set", "h=500", "--set", "L=600", "--set", "d=60", "--json"});
  ASSERT_EQ(solved.exit_status, 0) << solved.err;
  const json by_solve = json::parse(solved.out);
  EXPECT_EQ(closed.at("n"), by_solve.at("n"));
  EXPECT_NEAR(closed.at("z_max_mm").get<double>(), by_solve.at("z_max_mm").get<double>(), 1e-9);
  const RunResult shape = run({"field", "--shape", "triangle", "--cells-x", "8", "--json"});
  ASSERT_EQ(shape.exit_status, 0) << shape.err;
  EXPECT_EQ(json::parse(shape.out).at("closed_form").at("cloth"), "preset");

  const fs::path crossing = dir_ / "crossing.json";
  std::ofstream(crossing) << R"({"top": [[0, 0], [600, 0], [300, 10]],
    "bottom": [[0, 400], [600, 400]], "supports": [{"at": [0, 0], "to": [0, 0]}]})";
  const RunResult refused = run({"field", "--outline", crossing.string()});
  EXPECT_EQ(refused.exit_status, 2);
  EXPECT_TRUE(contains(refused.err, "top edge turns back")) << refused.err;
  EXPECT_TRUE(refused.out.empty());

  // Mansfield's parallelogram is the cut on inclined supports, by either name.
  const RunResult parallelogram =
      run({"field", "--shape", "parallelogram", "--cells-x", "8", "--json"});
  const RunResult inclined = run({"field", "--shape", "inclined", "--cells-x", "8", "--json"});
  ASSERT_EQ(parallelogram.exit_status, 0) << parallelogram.err;
  EXPECT_EQ(json::parse(parallelogram.out).at("weight_N"),
            json::parse(inclined.out).at("weight_N"));
  EXPECT_EQ(json::parse(parallelogram.out).at("supports"),
            json::parse(inclined.out).at("supports"));

  const RunResult bad_shape = run({"field", "--shape", "hexagon"});
  EXPECT_EQ(bad_shape.exit_status, 2);
  EXPECT_TRUE(contains(bad_shape.err, "hexagon")) << bad_shape.err;
}

// The shipped designer's cut: `field --preset` solves the preset's own outline, whose weight is
// w times its area by the shoelace formula over the file's vertices; a preset whose cut hangs
// from a point inside the cloth is refused with exit 2, naming the key and the support.
TEST_F(CliTest, FieldSolvesAPresetsOwnCutAndRefusesABadOne) {
  const json file = json::parse(std::ifstream(kPresetsDir / "shaped-curtain-curved-hem.json"));
  const json& outline = file.at("outline");
  const double weight = file.at("fabric").at("weight_N_per_mm2").get<double>() *
                        foldlab::testing::shoelace_area_mm2(outline);

  const RunResult r = run({"field", "--preset", "shaped-curtain-curved-hem", "--json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("outline"), "the preset's own cut");
  // On the default 40 x 28 cells the mesh tiles the curved hem's cut within 2e-5 of its area
  // (its weight tends to w times the area as the mesh is refined: 1.1e-4 short at 16 cells
  // across, 1.7e-5 at 40).
  EXPECT_NEAR(j.at("weight_N").get<double>(), weight, 1e-4 * weight);
  ASSERT_EQ(j.at("supports").size(), outline.at("supports").size());
  for (std::size_t i = 0; i < j.at("supports").size(); ++i) {
    EXPECT_EQ(j.at("supports")[i].at("at_mm"), outline.at("supports")[i].at("at"));
    EXPECT_EQ(j.at("supports")[i].at("to_mm"), outline.at("supports")[i].at("to"));
  }
  // --shape still asks for the shape's cut: the rectangle of the inputs, w h L.
  const RunResult shaped = run({"field", "--preset", "shaped-curtain-curved-hem", "--shape",
                                "rectangular", "--cells-x", "16", "--cells-y", "16", "--json"});
  ASSERT_EQ(shaped.exit_status, 0) << shaped.err;
  const double rectangle = file.at("fabric").at("weight_N_per_mm2").get<double>() *
                           file.at("hanging").at("height_mm").get<double>() *
                           file.at("hanging").at("length_mm").get<double>();
  EXPECT_NEAR(json::parse(shaped.out).at("weight_N").get<double>(), rectangle, 1e-12 * rectangle);

  json bad = file;
  bad["outline"]["supports"][1]["at"] = {600.0, 700.0};
  const fs::path bad_path = dir_ / "hook-inside.json";
  std::ofstream(bad_path) << bad.dump(2);
  const RunResult refused = run({"field", "--preset", bad_path.string()});
  EXPECT_EQ(refused.exit_status, 2);
  EXPECT_TRUE(contains(refused.err, "/outline: support 2 at (600, 700) mm is off the outline"))
      << refused.err;
  EXPECT_TRUE(refused.out.empty());
}

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size())) {
    ++count;
  }
  return count;
}

// The tags of an XML text nest: every <name ...> is closed by </name> or is <name .../>, in
// order. Empty when they do, else the first tag out of place.
std::string unbalanced_tag(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) {
      return xml.substr(at, 40);
    }
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.starts_with("?") || tag.starts_with("!")) {
      continue;
    }
    if (tag.starts_with("/")) {
      if (open.empty() || open.back() != tag.substr(1)) {
        return "<" + tag + ">";
      }
      open.pop_back();
    } else if (!tag.ends_with("/")) {
      open.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
  }
  return open.empty() ? "" : "<" + open.back() + "> never closed";
}

// `foldlab field --svg`: one polygon per mesh triangle, one polyline per ray, the supports with
// their reactions' values, the legend's words; a well-nested SVG document. An --svg whose folder
// is a plain file is refused before the solve, with exit 2, and nothing is written.
TEST_F(CliTest, FieldSvgDrawsEveryTriangleRayAndSupport) {
  const fs::path svg_path = dir_ / "field.svg";
  const RunResult r = run({"field", "--shape", "rectangular", "--cells-x", "12", "--cells-y", "8",
                           "--rays", "5", "--json", "--svg", svg_path.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(r.out);
  const std::string svg = read_file(svg_path);
  EXPECT_TRUE(starts_with(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  EXPECT_EQ(unbalanced_tag(svg), "");
  EXPECT_EQ(count_of(svg, "class=\"triangle "), j.at("mesh").at("triangles").get<std::size_t>());
  // Conci's rectangle is wholly wrinkled: every triangle carries the wrinkled colour.
  EXPECT_EQ(count_of(svg, "class=\"triangle wrinkled\""),
            j.at("mesh").at("triangles").get<std::size_t>());
  EXPECT_EQ(count_of(svg, "class=\"ray\""), 5u);
  EXPECT_EQ(count_of(svg, "class=\"support\""), 2u);
  EXPECT_EQ(count_of(svg, "class=\"reaction\""), 2u);
  for (const char* word : {"taut", "wrinkled", "slack", "tension ray", "reaction on the cloth",
                           "regions (area)", " mm</text>"}) {
    EXPECT_TRUE(contains(svg, word)) << word;
  }
  // Each support's value as the JSON gives it, to the drawing's four digits.
  const double Rx = j.at("supports")[0].at("reaction_N")[0].get<double>();
  const double Ry = j.at("supports")[0].at("reaction_N")[1].get<double>();
  char label[64];
  std::snprintf(label, sizeof label, "(%+.4g, %+.4g) N", Rx, Ry);
  EXPECT_TRUE(contains(svg, label)) << label;

  std::ofstream(dir_ / "plain.txt") << "a file\n";
  const fs::path refused_path = dir_ / "plain.txt" / "field.svg";
  const RunResult refused = run({"field", "--svg", refused_path.string()});
  EXPECT_EQ(refused.exit_status, 2) << refused.err;
  EXPECT_TRUE(
      contains(refused.err, "the folder " + (dir_ / "plain.txt").string() + " is not a folder"))
      << refused.err;
  EXPECT_TRUE(refused.out.empty());
  const RunResult wrong_extension = run({"field", "--svg", (dir_ / "field.png").string()});
  EXPECT_EQ(wrong_extension.exit_status, 2) << wrong_extension.err;
  EXPECT_FALSE(fs::exists(dir_ / "field.png"));
}

// The curtain preset hangs from three hooks on its top edge, 500 mm apart once its corners are
// moved in by 100 mm: two spans, each with its rays, its thrust and its own pencil; the report's
// figures are the widest (the first of the equal two), and the text gives a line per span.
TEST_F(CliTest, FieldOnThreeHooksReportsEachSpan) {
  const fs::path svg_path = dir_ / "curtain.svg";
  const RunResult r =
      run({"field", "--preset", "shaped-curtain-curved-hem", "--json", "--svg", svg_path.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(r.out);
  const json& spans = j.at("spans");
  ASSERT_EQ(spans.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(spans[k].at("left_support").get<int>(), static_cast<int>(k));
    EXPECT_EQ(spans[k].at("right_support").get<int>(), static_cast<int>(k) + 1);
    EXPECT_DOUBLE_EQ(spans[k].at("l_mm").get<double>(), 500.0);
    const double thrust = spans[k].at("thrust_N").get<double>();
    const double pencil = spans[k].at("pencil_thrust_N").get<double>();
    EXPECT_GT(thrust, 0.0);
    EXPECT_GT(thrust, 0.5 * pencil);
    EXPECT_LT(thrust, 2.0 * pencil);
    int rays = 0;
    for (const json& ray : j.at("rays")) {
      for (const char* key : {"a_mm", "fitted_a_mm", "fit_rms_mm"}) {
        EXPECT_TRUE(ray.contains(key)) << key;
      }
      rays += ray.at("span").get<std::size_t>() == k ? 1 : 0;
    }
    EXPECT_GE(rays, 2);
  }
  // The outer hooks alone pull across either span's middle.
  const double outer = -j.at("supports")[0].at("reaction_N")[0].get<double>();
  EXPECT_NEAR(spans[0].at("thrust_N").get<double>(), outer, 1e-6 * outer);
  EXPECT_EQ(j.at("thrust_N"), spans[0].at("thrust_N"));
  EXPECT_EQ(j.at("pencil_thrust_N"), spans[0].at("pencil_thrust_N"));
  EXPECT_DOUBLE_EQ(j.at("span_mm").get<double>(), 500.0);
  const std::string svg = read_file(svg_path);
  EXPECT_TRUE(contains(svg, "widest of 2 spans: H")) << svg.substr(0, 600);
  EXPECT_EQ(count_of(svg, "<title>span 1: ray"), 4u);
  EXPECT_EQ(count_of(svg, "<title>span 2: ray"), 4u);

  const RunResult text = run({"field", "--preset", "shaped-curtain-curved-hem"});
  ASSERT_EQ(text.exit_status, 0) << text.err;
  EXPECT_TRUE(contains(text.out, "  span 1, supports 1-2 (the widest): thrust ")) << text.out;
  EXPECT_TRUE(contains(text.out, "  span 2, supports 2-3: thrust ")) << text.out;
  EXPECT_TRUE(contains(text.out, "  span 2, at depth ")) << text.out;
  EXPECT_FALSE(contains(text.out, "(centre line)")) << text.out;
  EXPECT_FALSE(contains(text.out, "0 N (l = 1000.0 mm")) << text.out;
}

// A cut of `width` x `height` mm whose top left corner is at (x0, y0), hung from its top corners
// moved in by a twentieth of its width each: the outline file's text.
std::string rectangle_outline(double x0, double y0, double width = 600.0, double height = 400.0) {
  const auto pair = [](double x, double y) {
    std::ostringstream out;
    out.precision(17);
    out << "[" << x << ", " << y << "]";
    return out.str();
  };
  return "{\"top\": [" + pair(x0, y0) + ", " + pair(x0 + width, y0) + "], \"bottom\": [" +
         pair(x0, y0 + height) + ", " + pair(x0 + width, y0 + height) +
         "], \"supports\": [{\"at\": " + pair(x0, y0) + ", \"to\": " + pair(x0 + 0.05 * width, y0) +
         "}, {\"at\": " + pair(x0 + width, y0) + ", \"to\": " + pair(x0 + 0.95 * width, y0) + "}]}";
}

// Names that are not UTF-8 or hold control characters are printed as \xNN, as `solve` prints a
// preset's name, in the text and the JSON alike (the JSON writer threw on the byte 0xff).
TEST_F(CliTest, FieldSpellsAnOutlinesAndAPresetsNameAsEscapes) {
  const fs::path odd = dir_ / "bad\xffname.json";
  std::ofstream(odd) << rectangle_outline(0.0, 0.0);
  const RunResult j = run({"field", "--outline", odd.string(), "--cells-x", "8", "--cells-y", "6",
                           "--json", "--svg", (dir_ / "odd.svg").string()});
  ASSERT_EQ(j.exit_status, 0) << j.err;
  EXPECT_EQ(json::parse(j.out).at("outline"), (dir_ / "bad\\xffname.json").string());
  EXPECT_TRUE(contains(read_file(dir_ / "odd.svg"), "bad\\xffname.json"));
  const RunResult text =
      run({"field", "--outline", odd.string(), "--cells-x", "8", "--cells-y", "6"});
  ASSERT_EQ(text.exit_status, 0) << text.err;
  EXPECT_TRUE(contains(text.out, "cut: " + (dir_ / "bad\\xffname.json").string())) << text.out;

  json preset = json::parse(std::ifstream(kPresetsDir / "default.json"));
  preset["name"] = "Evil \x1b[31mRED\x07 name";
  const fs::path evil = dir_ / "evil.json";
  std::ofstream(evil) << preset.dump();
  const RunResult e = run({"field", "--preset", evil.string(), "--cells-x", "8", "--cells-y", "6"});
  ASSERT_EQ(e.exit_status, 0) << e.err;
  EXPECT_TRUE(contains(e.out, "Tension field of Evil \\x1b[31mRED\\x07 name")) << e.out;
  EXPECT_FALSE(contains(e.out, "\x1b")) << e.out;
  const RunResult ej =
      run({"field", "--preset", evil.string(), "--cells-x", "8", "--cells-y", "6", "--json"});
  ASSERT_EQ(ej.exit_status, 0) << ej.err;
  EXPECT_EQ(json::parse(ej.out).at("preset"), "Evil \\x1b[31mRED\\x07 name");
}

// Meshes and cuts that cannot be solved are refused before the solve, exit 2, by what is wrong:
// never a field of no triangle called converged, never nan printed.
TEST_F(CliTest, FieldRefusesCutsAndMeshesItCannotSolve) {
  // One cell across the cosine cut: its two columns are its ends, which have no height.
  const RunResult one = run({"field", "--cells-x", "1"});
  EXPECT_EQ(one.exit_status, 2);
  EXPECT_TRUE(contains(one.err, "no triangle")) << one.err;
  EXPECT_FALSE(contains(one.out + one.err, "nan"));
  // 401 columns of 401 nodes at 4 KB a node: 628 MB, above the 512 MB a solve may take.
  const RunResult big = run({"field", "--cells-x", "400", "--cells-y", "400"});
  EXPECT_EQ(big.exit_status, 2);
  EXPECT_TRUE(
      contains(big.err, "about 160801 nodes and take about 628 MB to solve; at most 512 MB"))
      << big.err;

  const auto refusal = [&](const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    const RunResult r = run({"field", "--outline", path.string(), "--cells-x", "8"});
    EXPECT_EQ(r.exit_status, 2) << name << ": " << r.out;
    EXPECT_TRUE(r.out.empty()) << name;
    return r.err;
  };
  const std::string rest =
      R"("bottom": [[0, 400], [600, 400]], "supports": [{"at": [0, 0], "to": [30, 0]}, )";
  // Pinned 1e9 mm off: beyond the 1e7 mm every coordinate keeps to.
  EXPECT_TRUE(contains(refusal("far.json", R"({"top": [[0, 0], [600, 0]], )" + rest +
                                               R"({"at": [600, 0], "to": [1e9, 0]}]})"),
                       "support 2 is pinned at (1e+09, 0) mm, out of range"));
  // 6001 mm from its place: just beyond 10 x 600 mm.
  EXPECT_TRUE(contains(refusal("just.json", R"({"top": [[0, 0], [600, 0]], )" + rest +
                                                R"({"at": [600, 0], "to": [600, -6001]}]})"),
                       "within 10 times the cut's size (6000 mm)"));
  EXPECT_TRUE(contains(refusal("to200.json", R"({"top": [[0, 0], [600, 0]], )" + rest +
                                                 R"({"at": [600, 0], "to": [1e200, 0]}]})"),
                       "out of range"));
  // A step 1e-6 mm wide on a 600 mm cut: narrower than 6e-4 mm, the mesh's resolution.
  EXPECT_TRUE(contains(refusal("corner.json",
                               R"({"top": [[0, 0], [300, 0], [300.000001, 100], [600, 100]],
    "bottom": [[0, 400], [600, 400]], "supports": [{"at": [0, 0], "to": [30, 0]},
    {"at": [600, 100], "to": [570, 100]}]})"),
                       "vertices 1 and 2 are 1e-06 mm apart in x"));
  // Thin but not flat: named as too thin, not as edges that coincide.
  const std::string thin =
      refusal("thin.json", R"({"top": [[0, 0], [1000, 0]], "bottom": [[0, 0.001], [1000, 0.001]],
    "supports": [{"at": [0, 0], "to": [10, 0]}, {"at": [1000, 0], "to": [990, 0]}]})");
  EXPECT_TRUE(contains(thin, "too thin to mesh")) << thin;
  EXPECT_FALSE(contains(thin, "coincide")) << thin;
  EXPECT_TRUE(contains(refusal("big.json", R"({"top": [[0, 0], [1e308, 0]],
    "bottom": [[0, 400], [1e308, 400]], "supports": [{"at": [0, 0], "to": [0, 0]}]})"),
                       "vertex 1 (1e+308, 0) mm is out of range"));
  // One reader for a file and a preset's "outline": a key twice or one unknown is named.
  EXPECT_TRUE(
      contains(refusal("dup.json", R"({"top": [[0, 0], [600, 0]], "top": [[0, 0], [600, 0]], )" +
                                       rest + R"({"at": [600, 0], "to": [570, 0]}]})"),
               "the key \"top\" is given twice"));
  EXPECT_TRUE(contains(refusal("extra.json", R"({"top": [[0, 0], [600, 0]], "bogus": 1, )" + rest +
                                                 R"({"at": [600, 0], "to": [570, 0]}]})"),
                       "unknown key \"bogus\""));
  EXPECT_TRUE(
      contains(refusal("extra-support.json", R"({"top": [[0, 0], [600, 0]], )" + rest +
                                                 R"({"at": [600, 0], "to": [570, 0], "zz": 0}]})"),
               "supports[1]: unknown key \"zz\""));

  json preset = json::parse(std::ifstream(kPresetsDir / "shaped-curtain-curved-hem.json"));
  preset["outline"]["zzz"] = 1;
  const fs::path unknown = dir_ / "unknown-key.json";
  std::ofstream(unknown) << preset.dump();
  const RunResult u = run({"field", "--preset", unknown.string()});
  EXPECT_EQ(u.exit_status, 2);
  EXPECT_TRUE(contains(u.err, "/outline: unknown key \"zzz\"")) << u.err;
}

// A preset's own cut that cannot be meshed (here above the node cap) names /outline, exit 2.
TEST_F(CliTest, FieldNamesAPresetsOutlineWhenItsMeshIsRefused) {
  const RunResult r = run(
      {"field", "--preset", "shaped-curtain-curved-hem", "--cells-x", "2000", "--cells-y", "2000"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_TRUE(contains(r.err, "/outline: a mesh of 2000 x 2000 cells")) << r.err;
}

// The same cut far from the origin hangs as at the origin: its thrust the same and converged.
TEST_F(CliTest, FieldOfACutIsTheSameWhereverItSits) {
  const auto thrust = [&](double offset) {
    const fs::path path = dir_ / ("at-" + std::to_string(offset) + ".json");
    std::ofstream(path) << rectangle_outline(offset, offset);
    const RunResult r =
        run({"field", "--outline", path.string(), "--cells-x", "12", "--cells-y", "8", "--json"});
    EXPECT_EQ(r.exit_status, 0) << offset << ": " << r.err;
    const json j = json::parse(r.out);
    EXPECT_TRUE(j.at("converged").get<bool>()) << offset;
    EXPECT_LE(j.at("relative_residual").get<double>(), 1e-8) << offset;
    return j.at("thrust_N").get<double>();
  };
  const double at_origin = thrust(0.0);
  EXPECT_GT(at_origin, 0.0);
  EXPECT_NEAR(thrust(1e5), at_origin, 1e-9 * at_origin);
  EXPECT_NEAR(thrust(1e6), at_origin, 1e-9 * at_origin);
}

// --budget-s stops the solve: NOT converged with its residual, exit 1, and no folds read from
// that field (null in the JSON).
TEST_F(CliTest, FieldStopsAtItsBudgetAndReadsNoFoldsFromAnUnconvergedField) {
  const RunResult j = run({"field", "--budget-s", "0.001", "--json"});
  EXPECT_EQ(j.exit_status, 1) << j.err;
  const json out = json::parse(j.out);
  EXPECT_FALSE(out.at("converged").get<bool>());
  EXPECT_GT(out.at("relative_residual").get<double>(), 1e-8);
  EXPECT_TRUE(out.at("field_folds").is_null());
  const RunResult text = run({"field", "--budget-s", "0.001"});
  EXPECT_EQ(text.exit_status, 1);
  EXPECT_TRUE(contains(text.out, "NOT converged")) << text.out;
  EXPECT_TRUE(
      contains(text.out, "folds from the field: not read from a field that did not converge"))
      << text.out;
  EXPECT_FALSE(contains(text.out, "folds from the field (centre line)")) << text.out;
  for (const char* bad : {"nan", "0", "-1", "inf"}) {
    const RunResult refused = run({"field", "--budget-s", bad});
    EXPECT_EQ(refused.exit_status, 2) << bad;
  }
  const RunResult margin = run({"stress", "--solver", "field", "--hang-margin", "nan"});
  EXPECT_EQ(margin.exit_status, 2);
  EXPECT_TRUE(contains(margin.err, "--hang-margin")) << margin.err;
}

// An --svg that cannot be written is refused before the solve, exit 2: a folder, a folder that
// takes no file, a name longer than the folder's limit.
TEST_F(CliTest, FieldRefusesAnSvgItCannotWriteBeforeTheSolve) {
  for (const std::string& svg : {dir_.string(), std::string("/proc/x.svg"),
                                 (dir_ / (std::string(300, 'a') + ".svg")).string()}) {
    const RunResult r = run({"field", "--svg", svg, "--cells-x", "400", "--cells-y", "400"});
    EXPECT_EQ(r.exit_status, 2) << svg << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << svg;
    EXPECT_TRUE(contains(r.err, "--svg")) << r.err;
  }
}

// A preset given by name is the file it resolves to: no output may be written over it, whether
// named by its path or through a symbolic link, and the refusal names both options.
TEST_F(CliTest, NoOutputOverwritesAPresetGivenByItsName) {
  const fs::path config = dir_ / "config";
  const fs::path presets = config / "foldlab" / "presets";
  fs::create_directories(presets);
  json mine = json::parse(std::ifstream(kPresetsDir / "default.json"));
  mine["name"] = "myfab";
  const fs::path file = presets / "myfab.json";
  std::ofstream(file) << mine.dump();
  const std::string before = read_file(file);
  foldlab::testing::Environment env;
  env.set = {{"XDG_CONFIG_HOME", config.string()}, {"HOME", dir_.string()}};
  const auto run_env = [&](const std::vector<std::string>& args) {
    return foldlab::testing::run_process(kExecutable, args, dir_, env);
  };
  const auto refused = [&](const RunResult& r, const std::string& output) {
    EXPECT_EQ(r.exit_status, 2) << r.err;
    EXPECT_TRUE(contains(r.err, output)) << r.err;
    EXPECT_TRUE(contains(r.err, "-preset myfab (" + file.string() + ")")) << r.err;
    EXPECT_TRUE(contains(r.err, "would destroy the input")) << r.err;
    EXPECT_TRUE(read_file(file) == before) << "the preset was replaced";
  };
  refused(run_env({"calibrate", "--preset", "myfab", "--data",
                   (kPresetsDir.parent_path() / "data" / "paper-measurements.csv").string(),
                   "--no-held-out", "--save-preset", file.string()}),
          "--save-preset " + file.string());
  for (const char* link : {"link.obj", "link.png", "link.csv"}) {
    fs::create_symlink(file, dir_ / link);
  }
  refused(run_env({"export", "--preset", "myfab", "--obj", (dir_ / "link.obj").string()}),
          "--obj " + (dir_ / "link.obj").string());
  refused(run_env({"measure", "--preset", "myfab", "--depths-mm", "80,40,20,10", "--append",
                   (dir_ / "link.csv").string()}),
          "--append " + (dir_ / "link.csv").string());
  refused(run_env({"picture", "cloth", "--preset", "myfab", "--size", "400x300", "--out",
                   (dir_ / "link.png").string()}),
          "--out " + (dir_ / "link.png").string());
  refused(run_env({"picture", "compare", "--b-preset", "myfab", "--size", "400x300", "--out",
                   (dir_ / "link.png").string()}),
          "--out " + (dir_ / "link.png").string());
  // A new file is nobody's input: the same commands write one beside the preset.
  const RunResult fresh =
      run_env({"export", "--preset", "myfab", "--obj", (dir_ / "new.obj").string()});
  EXPECT_EQ(fresh.exit_status, 0) << fresh.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "new.obj"));
}

// An output whose name is as long as a name may be (250 bytes: 82 CJK characters and ".svg") is
// written: its temporary's name is cut to fit the 255-byte limit, and nothing is left beside it.
TEST_F(CliTest, AnOutputNameOfTheLongestLegalLengthIsWritten) {
  std::string name;
  for (int i = 0; i < 82; ++i) {
    name += "\xE5\xB8\x83";  // 布, three bytes in UTF-8
  }
  name += ".svg";
  ASSERT_EQ(name.size(), 250u);
  const RunResult r = run({"export", "--svg", (dir_ / name).string()});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(contains(read_file(dir_ / name), "<svg")) << r.err;
  std::vector<std::string> names = entries();
  std::erase_if(names, [](const std::string& n) { return n.starts_with(".std"); });
  EXPECT_EQ(names, std::vector<std::string>{name});
}

// A command whose output's folder is missing, or is not a folder, refuses before any work (a
// picture renders for seconds first otherwise), as invalid input naming the folder.
TEST_F(CliTest, AnOutputsFolderIsCheckedBeforeTheWork) {
  const fs::path missing = dir_ / "missing";
  std::ofstream(dir_ / "plain.txt") << "a file\n";
  const std::vector<std::vector<std::string>> commands = {
      {"picture", "cloth", "--size", "400x300", "--out", (missing / "x.png").string()},
      {"export", "--obj", (missing / "x.obj").string()},
      {"measure", "--depths-mm", "80,40,20,10", "--append", (missing / "x.csv").string()},
      {"field", "--svg", (missing / "x.svg").string()},
      {"calibrate", "--data",
       (kPresetsDir.parent_path() / "data" / "paper-measurements.csv").string(), "--no-held-out",
       "--save-preset", (missing / "x.json").string()},
  };
  for (const std::vector<std::string>& args : commands) {
    SCOPED_TRACE(args.front());
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_status, 2) << r.err;
    EXPECT_TRUE(contains(r.err, "the folder " + missing.string() + " does not exist")) << r.err;
  }
  const RunResult not_folder = run({"export", "--obj", (dir_ / "plain.txt" / "x.obj").string()});
  EXPECT_EQ(not_folder.exit_status, 2) << not_folder.err;
  EXPECT_TRUE(
      contains(not_folder.err, "the folder " + (dir_ / "plain.txt").string() + " is not a folder"))
      << not_folder.err;
  EXPECT_FALSE(fs::exists(missing));
}

// measure --append to a new file, stopped by SIGTERM at any moment, leaves either no file or the
// whole one, never the empty placeholder it locks: a later read would refuse an empty file. The
// signal is sent as soon as the placeholder is seen, over several runs.
TEST_F(CliTest, AnAppendToANewFileStoppedBySigtermLeavesNoEmptyFile) {
  int stopped = 0;
  for (int attempt = 0; attempt < 40; ++attempt) {
    const fs::path rows = dir_ / ("new" + std::to_string(attempt) + ".csv");
    const pid_t pid = start({"measure", "--depths-mm", "80,40,20,10", "--append", rows.string()});
    ASSERT_GE(pid, 0);
    int status = 0;
    bool exited = false;
    bool seen_empty = false;
    while (!seen_empty && !exited) {
      struct stat info {};
      seen_empty = ::stat(rows.c_str(), &info) == 0 && info.st_size == 0;
      if (!seen_empty) {
        exited = ::waitpid(pid, &status, WNOHANG) == pid;
      }
    }
    if (!exited) {
      ASSERT_EQ(::kill(pid, SIGTERM), 0);
      ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    }
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), SIGTERM);
      ++stopped;
      std::error_code error;
      const bool there = fs::exists(rows, error);
      if (there) {
        // Stopped after the rename: the whole file.
        EXPECT_TRUE(contains(read_file(rows), ",fit,")) << attempt;
      }
    } else {
      EXPECT_EQ(WEXITSTATUS(status), 0) << attempt;
      EXPECT_TRUE(contains(read_file(rows), ",fit,")) << attempt;
    }
  }
  EXPECT_GT(stopped, 0) << "every append finished before its signal";
}

}  // namespace
