// Presets: loading every shipped file, the JSON round trip, error messages that name the file, the
// key and the problem, and the atomic save.
#include "core/io/preset.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include "temp_dir.hpp"

#include "core/io/io.hpp"
#include "core/model/parameters.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

// A complete, valid preset written out by hand (independent of preset_to_json), with every model
// setting away from its default.
const char* const kValidPresetText = R"({
  "foldlab_preset": 1,
  "name": "Test case",
  "description": "A preset written by the tests.",
  "source": "tests/test_preset.cpp",
  "fabric": {
    "thickness_mm": 0.3,
    "youngs_modulus_MPa": 120,
    "weight_N_per_mm2": 2.5e-06,
    "poisson_ratio": 0.25
  },
  "hanging": {
    "height_mm": 1200,
    "length_mm": 1400,
    "support_displacement_mm": 150
  },
  "model": {
    "method": "exact",
    "load_constant_c": 31.5,
    "span_rule": "L-2d",
    "int_rounding": "floor",
    "simpson_intervals": 16,
    "length_tolerance": 0.02,
    "max_iterations": 77
  },
  "published": {
    "n": 6,
    "z_max_mm": 51.5,
    "Q": 1.33
  }
})";

json valid_preset_json() {
  return json::parse(kValidPresetText);
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  ASSERT_TRUE(out.good()) << path;
}

std::vector<std::string> directory_entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  return names;
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

// Field-by-field comparison (no operator== exists on purpose: every field is named here).
void expect_same_parameters(const foldlab::Parameters& a, const foldlab::Parameters& b) {
  EXPECT_EQ(a.fabric.thickness_mm, b.fabric.thickness_mm);
  EXPECT_EQ(a.fabric.youngs_modulus_MPa, b.fabric.youngs_modulus_MPa);
  EXPECT_EQ(a.fabric.weight_N_per_mm2, b.fabric.weight_N_per_mm2);
  EXPECT_EQ(a.fabric.poisson_ratio, b.fabric.poisson_ratio);
  EXPECT_EQ(a.hanging.height_mm, b.hanging.height_mm);
  EXPECT_EQ(a.hanging.length_mm, b.hanging.length_mm);
  EXPECT_EQ(a.hanging.support_displacement_mm, b.hanging.support_displacement_mm);
  EXPECT_EQ(a.model.method, b.model.method);
  EXPECT_EQ(a.model.load_constant_c, b.model.load_constant_c);
  EXPECT_EQ(a.model.span_rule, b.model.span_rule);
  EXPECT_EQ(a.model.int_rounding, b.model.int_rounding);
  EXPECT_EQ(a.model.simpson_intervals, b.model.simpson_intervals);
  EXPECT_EQ(a.model.length_tolerance, b.model.length_tolerance);
  EXPECT_EQ(a.model.max_iterations, b.model.max_iterations);
}

void expect_same_preset(const foldlab::Preset& a, const foldlab::Preset& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.derived_from, b.derived_from);
  EXPECT_EQ(a.written_by, b.written_by);
  expect_same_parameters(a.parameters, b.parameters);
  EXPECT_EQ(a.published.n, b.published.n);
  EXPECT_EQ(a.published.z_max_mm, b.published.z_max_mm);
  EXPECT_EQ(a.published.Q, b.published.Q);
  EXPECT_EQ(a.calibration, b.calibration);
  EXPECT_EQ(a.appearance, b.appearance);
  EXPECT_EQ(a.outline, b.outline);
}

// A preset whose numbers need all 17 significant digits to survive a text round trip.
foldlab::Preset awkward_preset() {
  foldlab::Preset p;
  p.name = "Round trip \"quoted\" \u00e9";
  p.description = "line one\nline two";
  p.source = "tests";
  p.derived_from = "Cotton jersey knit";
  p.parameters.fabric.thickness_mm = 0.1 + 0.2;
  p.parameters.fabric.youngs_modulus_MPa = 1000.0 / 3.0;
  p.parameters.fabric.weight_N_per_mm2 = 1.2345678901234567e-6;
  p.parameters.fabric.poisson_ratio = 0.1 * 3.0;
  p.parameters.hanging.height_mm = 1234.5678901234567;
  p.parameters.hanging.length_mm = 987.65432109876543;
  p.parameters.hanging.support_displacement_mm = 2.0 / 3.0;
  p.parameters.model.method = foldlab::Method::exact;
  p.parameters.model.load_constant_c = 27.123456789012345;
  p.parameters.model.span_rule = foldlab::SpanRule::L_minus_2d;
  p.parameters.model.int_rounding = foldlab::IntRounding::floor;
  p.parameters.model.simpson_intervals = 34;
  p.parameters.model.length_tolerance = 0.0123456789;
  p.parameters.model.max_iterations = 321;
  p.published.n = 9;
  p.published.z_max_mm = 47.25;
  p.published.Q = 1.0 / 0.77;
  p.calibration = foldlab::CalibrationRecord{"Tables 1–2 \"quoted\"",
                                             foldlab::Method::paper,
                                             foldlab::WrinkleLawKind::cerda_mahadevan,
                                             {1.0 / 3.0, 0.1 * 7.0},
                                             6,
                                             {{0.1 + 0.2, 0.466}, {5.4458657092013, 2.0 / 3.0}},
                                             {{0.0123456789012345, 0.104}},
                                             {{-2.0, 0.1 + 0.2, std::nullopt}},
                                             "n 5/6 at a stated 67 %"};
  return p;
}

class PresetTest : public foldlab::testing::TempDirTest {
 protected:
  PresetTest() : TempDirTest("foldlab_preset_") {}

  // Writes `j` to a file and expects load_preset to reject it; returns the message, which must
  // name the file.
  std::string load_error(const json& j, const std::string& file_name = "bad.json") {
    const fs::path path = dir_ / file_name;
    write_bytes(path, j.dump(2));
    return load_error_from(path);
  }
  std::string load_error_from(const fs::path& path) {
    try {
      (void)foldlab::load_preset(path);
    } catch (const foldlab::PresetError& e) {
      const std::string message = e.what();
      EXPECT_TRUE(contains(message, path.string())) << message;
      return message;
    }
    ADD_FAILURE() << "load_preset(" << path << ") did not throw PresetError";
    return "";
  }
};

TEST_F(PresetTest, EveryShippedPresetLoadsAndValidates) {
  std::set<std::string> loaded;
  for (const fs::directory_entry& entry : fs::directory_iterator(kPresetsDir)) {
    if (entry.path().extension() != ".json") {
      continue;
    }
    SCOPED_TRACE(entry.path().string());
    foldlab::Preset preset;
    ASSERT_NO_THROW(preset = foldlab::load_preset(entry.path()));
    EXPECT_FALSE(preset.name.empty());
    const auto issues = foldlab::validate(preset.parameters);
    EXPECT_TRUE(issues.empty()) << foldlab::format_issues(issues);
    loaded.insert(entry.path().filename().string());
  }
  for (const char* name : {"paper-fig4.json", "paper-table1-h900.json", "paper-table1-h1400.json",
                           "paper-table1-h2350.json", "paper-table2-w10.json",
                           "paper-table2-w33.json", "paper-table2-w54.json"}) {
    EXPECT_EQ(loaded.count(name), 1u) << name << " was not found in " << kPresetsDir;
  }
}

TEST_F(PresetTest, ReadsEveryFieldOfAHandWrittenFile) {
  const fs::path path = dir_ / "valid.json";
  write_bytes(path, kValidPresetText);
  const foldlab::Preset p = foldlab::load_preset(path);
  EXPECT_EQ(p.name, "Test case");
  EXPECT_EQ(p.description, "A preset written by the tests.");
  EXPECT_EQ(p.source, "tests/test_preset.cpp");
  EXPECT_EQ(p.parameters.fabric.thickness_mm, 0.3);
  EXPECT_EQ(p.parameters.fabric.youngs_modulus_MPa, 120.0);
  EXPECT_EQ(p.parameters.fabric.weight_N_per_mm2, 2.5e-6);
  EXPECT_EQ(p.parameters.fabric.poisson_ratio, 0.25);
  EXPECT_EQ(p.parameters.hanging.height_mm, 1200.0);
  EXPECT_EQ(p.parameters.hanging.length_mm, 1400.0);
  EXPECT_EQ(p.parameters.hanging.support_displacement_mm, 150.0);
  EXPECT_EQ(p.parameters.model.method, foldlab::Method::exact);
  EXPECT_EQ(p.parameters.model.load_constant_c, 31.5);
  EXPECT_EQ(p.parameters.model.span_rule, foldlab::SpanRule::L_minus_2d);
  EXPECT_EQ(p.parameters.model.int_rounding, foldlab::IntRounding::floor);
  EXPECT_EQ(p.parameters.model.simpson_intervals, 16);
  EXPECT_EQ(p.parameters.model.length_tolerance, 0.02);
  EXPECT_EQ(p.parameters.model.max_iterations, 77);
  EXPECT_EQ(p.published.n, 6);
  EXPECT_EQ(p.published.z_max_mm, 51.5);
  EXPECT_EQ(p.published.Q, 1.33);
}

TEST_F(PresetTest, JsonRoundTripKeepsEveryField) {
  const foldlab::Preset original = awkward_preset();
  const foldlab::Preset back =
      foldlab::preset_from_json(foldlab::preset_to_json(original), "<round trip>");
  expect_same_preset(original, back);

  // Through text too, as a file would carry it.
  const foldlab::Preset from_text =
      foldlab::preset_from_text(foldlab::preset_to_json(original).dump(2), "<round trip text>");
  expect_same_preset(original, from_text);
}

TEST_F(PresetTest, JsonRoundTripKeepsAbsentPublishedValuesAbsent) {
  foldlab::Preset original = awkward_preset();
  original.published = {};
  original.published.n = 3;
  const foldlab::Preset back =
      foldlab::preset_from_json(foldlab::preset_to_json(original), "<round trip>");
  EXPECT_EQ(back.published.n, 3);
  EXPECT_FALSE(back.published.z_max_mm.has_value());
  EXPECT_FALSE(back.published.Q.has_value());

  original.published = {};
  const foldlab::Preset none =
      foldlab::preset_from_json(foldlab::preset_to_json(original), "<round trip>");
  EXPECT_FALSE(none.published.n.has_value());
  EXPECT_FALSE(none.published.z_max_mm.has_value());
  EXPECT_FALSE(none.published.Q.has_value());
}

// The program that saved a preset is kept as read and written back; a preset without it (every
// shipped one) writes no such key, so the files in presets/ stay as they are.
TEST_F(PresetTest, WrittenByIsKeptWhenPresentAndAbsentOtherwise) {
  foldlab::Preset original = awkward_preset();
  EXPECT_FALSE(foldlab::preset_to_json(original).contains("written_by"));
  original.written_by = "FoldLab 9.8.7 (abc1234)";
  const nlohmann::json j = foldlab::preset_to_json(original);
  EXPECT_EQ(j.at("written_by"), "FoldLab 9.8.7 (abc1234)");
  const foldlab::Preset back = foldlab::preset_from_json(j, "<round trip>");
  EXPECT_EQ(back.written_by, "FoldLab 9.8.7 (abc1234)");
  expect_same_preset(original, back);

  nlohmann::json wrong = j;
  wrong["written_by"] = 3;
  try {
    (void)foldlab::preset_from_json(wrong, "w.json");
    ADD_FAILURE() << "a written_by that is not text was accepted";
  } catch (const foldlab::PresetError& e) {
    EXPECT_NE(std::string(e.what()).find("/written_by"), std::string::npos) << e.what();
  }
}

TEST_F(PresetTest, SaveThenLoadGivesTheSamePreset) {
  const foldlab::Preset original = awkward_preset();
  const fs::path path = dir_ / "saved.json";
  foldlab::save_preset(original, path);
  ASSERT_TRUE(fs::exists(path));
  expect_same_preset(original, foldlab::load_preset(path));
  // The file is plain JSON carrying the format version.
  const json j = json::parse(read_bytes(path));
  EXPECT_EQ(j.at("foldlab_preset"), 1);
}

TEST_F(PresetTest, TruncatedJsonIsNotValidJson) {
  const std::string text = kValidPresetText;
  const fs::path path = dir_ / "truncated.json";
  write_bytes(path, text.substr(0, text.size() / 2));
  const std::string message = load_error_from(path);
  EXPECT_TRUE(contains(message, "not valid JSON")) << message;
}

// An empty file and a junk one are named in words, not in the JSON library's own
// ("[json.exception.parse_error.101] parse error at line 1, column 1: syntax error ...").
TEST_F(PresetTest, EmptyAndJunkFilesAreNamedInWords) {
  const fs::path empty = dir_ / "empty.json";
  write_bytes(empty, " \n");
  const std::string empty_message = load_error_from(empty);
  EXPECT_TRUE(contains(empty_message, "is empty")) << empty_message;
  const fs::path junk = dir_ / "junk.json";
  write_bytes(junk, "{\"fabric\": ]");
  const std::string junk_message = load_error_from(junk);
  EXPECT_TRUE(contains(junk_message, "not valid JSON at line 1, column 12")) << junk_message;
  EXPECT_FALSE(contains(junk_message, "json.exception")) << junk_message;
  EXPECT_FALSE(contains(junk_message, "syntax error while parsing")) << junk_message;
}

// A number literal too large for a double is a malformed file like any other: it must come out as
// a PresetError naming the file (the CLI turns only PresetError into "invalid input", exit 2).
TEST_F(PresetTest, NumberTooLargeForADoubleIsAPresetError) {
  std::string text = kValidPresetText;
  const std::string from = "\"thickness_mm\": 0.3";
  text.replace(text.find(from), from.size(), "\"thickness_mm\": 1e400");
  const fs::path path = dir_ / "overflow.json";
  write_bytes(path, text);
  try {
    (void)foldlab::load_preset(path);
    ADD_FAILURE() << "load_preset accepted 1e400";
  } catch (const foldlab::PresetError& e) {
    EXPECT_TRUE(contains(e.what(), path.string())) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected PresetError, got another exception: " << e.what();
  }
}

TEST_F(PresetTest, WrongTypeNamesTheKeyAndTheExpectedType) {
  json j = valid_preset_json();
  j["fabric"]["thickness_mm"] = "thin";
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/fabric/thickness_mm")) << message;
  EXPECT_TRUE(contains(message, "expected a number")) << message;
}

TEST_F(PresetTest, WholeNumberFieldRejectsAFraction) {
  json j = valid_preset_json();
  j["model"]["simpson_intervals"] = 20.5;
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/model/simpson_intervals")) << message;
  EXPECT_TRUE(contains(message, "whole number")) << message;
}

TEST_F(PresetTest, UnknownKeyIsNamed) {
  json j = valid_preset_json();
  j["fabric"]["thicknes_mm"] = j["fabric"]["thickness_mm"];
  j["fabric"].erase("thickness_mm");
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/fabric/thicknes_mm")) << message;
  EXPECT_TRUE(contains(message, "unknown key")) << message;
  // The misspelt key leaves the real one missing: both are reported.
  EXPECT_TRUE(contains(message, "/fabric/thickness_mm")) << message;
  EXPECT_TRUE(contains(message, "missing")) << message;
}

TEST_F(PresetTest, UnknownTopLevelKeyIsNamed) {
  json j = valid_preset_json();
  j["colour"] = "blue";
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/colour")) << message;
  EXPECT_TRUE(contains(message, "unknown key")) << message;
}

// The appearance is written by hand here, so that the reader is checked against the format as
// presets/README.md states it rather than against the writer.
TEST_F(PresetTest, AppearanceColourIsReadFromAHandWrittenFile) {
  json j = valid_preset_json();
  j["appearance"] = json::parse(R"({"colour": "#8B1a2b"})");
  const foldlab::Preset p = foldlab::preset_from_json(j, "velvet.json");
  ASSERT_TRUE(p.appearance.colour.has_value());
  EXPECT_EQ(p.appearance.colour->r, 0x8b);
  EXPECT_EQ(p.appearance.colour->g, 0x1a);
  EXPECT_EQ(p.appearance.colour->b, 0x2b);
  // Written back in lower case, the form the shipped presets use.
  EXPECT_EQ(foldlab::preset_to_json(p).at("appearance"), json::parse(R"({"colour": "#8b1a2b"})"));
}

TEST_F(PresetTest, APresetWithoutAppearanceKeepsTheViewsColourAndWritesNone) {
  const foldlab::Preset p = foldlab::preset_from_json(valid_preset_json(), "plain.json");
  EXPECT_FALSE(p.appearance.colour.has_value());
  EXPECT_FALSE(foldlab::preset_to_json(p).contains("appearance"));
  // An empty appearance object is allowed and means the same.
  json j = valid_preset_json();
  j["appearance"] = json::object();
  EXPECT_FALSE(foldlab::preset_from_json(j, "empty.json").appearance.colour.has_value());
}

TEST_F(PresetTest, AppearanceColourSurvivesSaveAndLoad) {
  foldlab::Preset original = awkward_preset();
  original.appearance.colour = foldlab::ColourRgb8{0xd8, 0xcf, 0xbd};
  const fs::path path = dir_ / "coloured.json";
  foldlab::save_preset(original, path);
  const json on_disk = json::parse(read_bytes(path));
  EXPECT_EQ(on_disk.at("appearance").at("colour"), "#d8cfbd");
  expect_same_preset(original, foldlab::load_preset(path));
}

TEST_F(PresetTest, MalformedAppearanceColourIsRefusedNamingTheKey) {
  for (const char* bad : {R"("red")", R"("#8b1a2")", R"("#8b1a2bff")", R"("8b1a2b#")",
                          R"("#8g1a2b")", R"("")", R"(139)", R"(null)", R"([139, 26, 43])"}) {
    SCOPED_TRACE(bad);
    json j = valid_preset_json();
    j["appearance"] = {{"colour", json::parse(bad)}};
    const std::string message = load_error(j);
    EXPECT_TRUE(contains(message, "bad.json: /appearance/colour:")) << message;
    EXPECT_TRUE(contains(message, "#RRGGBB")) << message;
  }
  json j = valid_preset_json();
  j["appearance"] = {{"color", "#8b1a2b"}};
  std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/appearance/color")) << message;
  EXPECT_TRUE(contains(message, "unknown key")) << message;
  j["appearance"] = "#8b1a2b";
  message = load_error(j);
  EXPECT_TRUE(contains(message, "/appearance")) << message;
  EXPECT_TRUE(contains(message, "expected an object")) << message;
}

// A designer's cut in a preset: read as `field --outline` reads its file, saved back unchanged.
const char* const kPanelCut = R"({"top": [[0, 0], [600, 0]],
  "bottom": [[0, 400], [300, 500], [600, 400]],
  "supports": [{"at": [0, 0], "to": [30, 0]}, {"at": [600, 0], "to": [570, 0]}]})";

TEST_F(PresetTest, AnOutlineIsReadAndSurvivesSaveAndLoad) {
  json j = valid_preset_json();
  j["outline"] = json::parse(kPanelCut);
  const fs::path path = dir_ / "cut.json";
  write_bytes(path, j.dump(2));
  const foldlab::Preset read = foldlab::load_preset(path);
  ASSERT_TRUE(read.outline.has_value());
  ASSERT_EQ(read.outline->bottom_mm.size(), 3u);
  EXPECT_EQ(read.outline->bottom_mm[1], Eigen::Vector2d(300.0, 500.0));
  ASSERT_EQ(read.outline->supports.size(), 2u);
  EXPECT_EQ(read.outline->supports[1].to_mm, Eigen::Vector2d(570.0, 0.0));
  // 600 x 400 and the hem's triangle of base 600 and height 100 below it.
  EXPECT_DOUBLE_EQ(read.outline->area_mm2(), 600.0 * 400.0 + 0.5 * 600.0 * 100.0);

  const fs::path saved = dir_ / "saved.json";
  foldlab::save_preset(read, saved);
  EXPECT_EQ(json::parse(read_bytes(saved)).at("outline"), json::parse(kPanelCut));
  expect_same_preset(read, foldlab::load_preset(saved));

  // A preset without one writes none.
  EXPECT_FALSE(foldlab::preset_to_json(awkward_preset()).contains("outline"));
}

TEST_F(PresetTest, AnOutlineThatCannotBeMeshedIsRefusedNamingTheProblem) {
  struct Case {
    const char* outline;
    const char* says;
  };
  const Case cases[] = {
      // The top edge runs back to x = 300 and crosses its own first stretch on the way right.
      {R"({"top": [[0, 0], [600, 0], [300, -30], [400, 30], [900, 0]],
           "bottom": [[0, 400], [900, 400]], "supports": [{"at": [0, 0], "to": [0, 0]}]})",
       "the top edge turns back"},
      // A hook in the middle of the cloth, 200 mm below its top edge.
      {R"({"top": [[0, 0], [600, 0]], "bottom": [[0, 400], [600, 400]],
           "supports": [{"at": [0, 0], "to": [0, 0]}, {"at": [300, 200], "to": [300, 0]}]})",
       "support 2 at (300, 200) mm is off the outline"},
      // Beyond the cut's right end.
      {R"({"top": [[0, 0], [600, 0]], "bottom": [[0, 400], [600, 400]],
           "supports": [{"at": [0, 0], "to": [0, 0]}, {"at": [700, 0], "to": [650, 0]}]})",
       "is off the outline: the cut runs from x = 0 to 600 mm"},
      {R"({"top": [[0, 0], [600, 0]], "bottom": [[0, 400], [600, 400]], "supports": []})",
       "at least one support"},
      {R"([1, 2])", "must be a JSON object"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.outline);
    json j = valid_preset_json();
    j["outline"] = json::parse(c.outline);
    const std::string message = load_error(j);
    EXPECT_TRUE(contains(message, "bad.json: /outline: ")) << message;
    EXPECT_TRUE(contains(message, c.says)) << message;
  }
}

TEST_F(PresetTest, MissingRequiredKeyIsNamed) {
  json j = valid_preset_json();
  j["hanging"].erase("height_mm");
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/hanging/height_mm")) << message;
  EXPECT_TRUE(contains(message, "missing")) << message;

  json k = valid_preset_json();
  k.erase("name");
  const std::string name_message = load_error(k, "no_name.json");
  EXPECT_TRUE(contains(name_message, "/name")) << name_message;
  EXPECT_TRUE(contains(name_message, "missing")) << name_message;

  json m = valid_preset_json();
  m.erase("fabric");
  const std::string fabric_message = load_error(m, "no_fabric.json");
  EXPECT_TRUE(contains(fabric_message, "/fabric")) << fabric_message;
  EXPECT_TRUE(contains(fabric_message, "missing")) << fabric_message;
}

TEST_F(PresetTest, OptionalKeysMayBeLeftOut) {
  json j = valid_preset_json();
  j.erase("model");
  j.erase("published");
  j.erase("description");
  j.erase("source");
  j["fabric"].erase("poisson_ratio");
  const fs::path path = dir_ / "minimal.json";
  write_bytes(path, j.dump());
  const foldlab::Preset p = foldlab::load_preset(path);
  EXPECT_EQ(p.parameters.fabric.thickness_mm, 0.3);
  EXPECT_EQ(p.parameters.fabric.poisson_ratio, 0.3);  // the documented default nu
  EXPECT_EQ(p.parameters.model.load_constant_c, 26.9);
  // Every model setting left out keeps its default.
  foldlab::Parameters expected;
  expected.fabric = p.parameters.fabric;
  expected.hanging = p.parameters.hanging;
  expect_same_parameters(expected, p.parameters);
  EXPECT_FALSE(p.published.n.has_value());
}

TEST_F(PresetTest, OutOfRangeNamesTheKeyAndTheLimit) {
  json j = valid_preset_json();
  j["hanging"]["length_mm"] = 1400;
  j["hanging"]["support_displacement_mm"] = 700;
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/hanging/support_displacement_mm")) << message;
  EXPECT_TRUE(contains(message, "support displacement d = 700 mm must be below L/2 = 700 mm"))
      << message;
}

TEST_F(PresetTest, SeveralTypeProblemsAreAllReported) {
  json j = valid_preset_json();
  j["fabric"]["thickness_mm"] = "thin";
  j["hanging"]["height_mm"] = true;
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/fabric/thickness_mm")) << message;
  EXPECT_TRUE(contains(message, "/hanging/height_mm")) << message;
}

TEST_F(PresetTest, SeveralRangeProblemsAreAllReportedOneLineEach) {
  json j = valid_preset_json();
  j["fabric"]["thickness_mm"] = -1;
  j["hanging"]["support_displacement_mm"] = 700;
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/fabric/thickness_mm")) << message;
  EXPECT_TRUE(contains(message, "/hanging/support_displacement_mm")) << message;
  std::istringstream lines(message);
  int count = 0;
  for (std::string line; std::getline(lines, line);) {
    ++count;
  }
  EXPECT_EQ(count, 2) << message;
}

// A calibration block with its constants and a list of the given length.
json with_calibration(json list, double K = 30.0, double p = 0.5) {
  json j = valid_preset_json();
  j["calibration"] = {{"calibrated_on", "tests"},
                      {"method", "exact"},
                      {"K", K},
                      {"p", p},
                      {"equally_good", list},
                      {"fit_rows", 3},
                      {"leave_one_out", json::array()}};
  return j;
}

TEST_F(PresetTest, CalibrationListAboveTheEntryCapIsRefusedNamingTheIndex) {
  json list = json::array();
  for (int i = 0; i < 20'000; ++i) {
    list.push_back({30.0, 0.5});
  }
  const std::string message = load_error(with_calibration(list));
  EXPECT_TRUE(contains(message, "/calibration/equally_good/" +
                                    std::to_string(foldlab::kMaxCalibrationEntries) +
                                    ": 20000 "
                                    "entries, at most 64"))
      << message;
  // One line for the whole list, not one per entry.
  EXPECT_LT(message.size(), 400u) << message;

  json at_cap = json::array();
  for (std::size_t i = 0; i < foldlab::kMaxCalibrationEntries; ++i) {
    at_cap.push_back({30.0, 0.5});
  }
  const fs::path path = dir_ / "at_cap.json";
  write_bytes(path, with_calibration(at_cap).dump());
  EXPECT_EQ(foldlab::load_preset(path).calibration->equally_good.size(),
            foldlab::kMaxCalibrationEntries);
}

TEST_F(PresetTest, StoredCalibrationConstantsAreRangeCheckedThroughTheInputTable) {
  // nu = 0.25 in the valid preset: K = 1e-12 is c ~ 1e-12, far below c's range; p = 50 is above
  // p's range.
  std::string message = load_error(with_calibration(json::array({{30.0, 0.5}, {1e-12, 0.5}})));
  EXPECT_TRUE(contains(message, "/calibration/equally_good/1: K = 1e-12")) << message;
  EXPECT_TRUE(contains(message, "c's range [0.001, 10000]")) << message;
  message = load_error(with_calibration(json::array({{30.0, 50.0}})));
  EXPECT_TRUE(contains(message, "/calibration/equally_good/0: p = 50 is outside [0.05, 5]"))
      << message;
  message = load_error(with_calibration(json::array(), 1e300, 0.5));
  EXPECT_TRUE(contains(message, "/calibration/K: K = 1e+300")) << message;
  message = load_error(with_calibration(json::array(), 30.0, 1e-9));
  EXPECT_TRUE(contains(message, "/calibration/p: p = 1e-09")) << message;
  // c's upper end at this nu: K = 1e4 / (1 - 0.25²) is in, a little more is out.
  const double K_max = 1e4 / (1.0 - 0.25 * 0.25);
  const fs::path path = dir_ / "edge.json";
  write_bytes(path, with_calibration(json::array({{K_max * 0.999, 5.0}})).dump());
  EXPECT_NO_THROW((void)foldlab::load_preset(path));
  message = load_error(with_calibration(json::array({{K_max * 1.001, 5.0}})));
  EXPECT_TRUE(contains(message, "/calibration/equally_good/0: K = ")) << message;
}

// Residuals are bounded so that every interval from them is finite: |n| <= 10,000 (the solver's
// fold cap) and |ln z_max|, |ln Q| <= ln 1e6. They were accepted up to 1e6 each, and ln 710 gave
// an infinite z_max range.
TEST_F(PresetTest, StoredResidualsAreBoundedSoThatIntervalsStayFinite) {
  json j = with_calibration(json::array(), 30.0, 0.5);
  j["calibration"]["leave_one_out"] = json::array({{30.0, 0.5}, {30.0, 0.5}, {30.0, 0.5}});
  j["calibration"]["residuals"] =
      json::array({{0, 710, 710}, {999999, nullptr, nullptr}, {-3, -13.8, 13.8}});
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/calibration/residuals/0/1: ln z_max residual 710")) << message;
  EXPECT_TRUE(contains(message, "/calibration/residuals/0/2: ln Q residual 710")) << message;
  EXPECT_TRUE(contains(message, "/calibration/residuals/1/0: n residual 999999")) << message;
  EXPECT_FALSE(contains(message, "/calibration/residuals/2")) << message;
  j["calibration"]["residuals"] =
      json::array({{10000, 13.8, -13.8}, {-10000, nullptr, 0.1}, {-3, -13.8, 13.8}});
  const fs::path path = dir_ / "bounded.json";
  write_bytes(path, j.dump());
  EXPECT_EQ(foldlab::load_preset(path).calibration->residuals.size(), 3u);
}

TEST_F(PresetTest, SaveRefusesACalibrationTheReaderWouldRefuse) {
  foldlab::Preset p = foldlab::preset_from_json(valid_preset_json(), "test");
  foldlab::CalibrationRecord record;
  record.calibrated_on = "tests";
  record.fitted = {30.0, 0.5};
  record.fit_rows = 65;
  record.leave_one_out.assign(65, {30.0, 0.5});
  p.calibration = record;
  const fs::path path = dir_ / "too_many.json";
  try {
    foldlab::save_preset(p, path);
    ADD_FAILURE() << "saved";
  } catch (const foldlab::PresetError& e) {
    EXPECT_TRUE(contains(e.what(), "/calibration/leave_one_out/64")) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(PresetTest, WrongFormatVersionIsRejected) {
  json j = valid_preset_json();
  j["foldlab_preset"] = 2;
  const std::string message = load_error(j);
  EXPECT_TRUE(contains(message, "/foldlab_preset")) << message;
  EXPECT_TRUE(contains(message, "format version")) << message;

  json k = valid_preset_json();
  k.erase("foldlab_preset");
  const std::string missing = load_error(k, "no_version.json");
  EXPECT_TRUE(contains(missing, "/foldlab_preset")) << missing;
  EXPECT_TRUE(contains(missing, "missing")) << missing;
}

TEST_F(PresetTest, EnumFieldsListTheAllowedNames) {
  json j = valid_preset_json();
  j["model"]["method"] = "fast";
  const std::string method = load_error(j, "method.json");
  EXPECT_TRUE(contains(method, "/model/method")) << method;
  EXPECT_TRUE(contains(method, "paper, exact")) << method;

  json k = valid_preset_json();
  k["model"]["span_rule"] = "L-3d";
  const std::string span = load_error(k, "span.json");
  EXPECT_TRUE(contains(span, "/model/span_rule")) << span;
  EXPECT_TRUE(contains(span, "L-d, L-2d")) << span;

  json m = valid_preset_json();
  m["model"]["int_rounding"] = "up";
  const std::string rounding = load_error(m, "rounding.json");
  EXPECT_TRUE(contains(rounding, "/model/int_rounding")) << rounding;
  EXPECT_TRUE(contains(rounding, "nearest, floor")) << rounding;
}

TEST_F(PresetTest, SaveReplacesAnExistingFileCompletely) {
  const fs::path path = dir_ / "preset.json";
  // Much longer than the preset, so that a write in place would leave a tail of it behind.
  write_bytes(path, std::string(100000, 'x'));
  const foldlab::Preset original = awkward_preset();
  foldlab::save_preset(original, path);

  const std::string bytes = read_bytes(path);
  EXPECT_LT(bytes.size(), 100000u);
  EXPECT_EQ(bytes.find('x' + std::string(10, 'x')), std::string::npos);
  EXPECT_TRUE(json::accept(bytes));
  expect_same_preset(original, foldlab::load_preset(path));

  const std::vector<std::string> entries = directory_entries(dir_);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0], "preset.json");
  for (const std::string& name : entries) {
    EXPECT_FALSE(contains(name, ".tmp.")) << name;
  }
}

TEST_F(PresetTest, SaveIntoAMissingDirectoryThrowsAndLeavesNothing) {
  const fs::path path = dir_ / "does-not-exist" / "preset.json";
  try {
    foldlab::save_preset(awkward_preset(), path);
    ADD_FAILURE() << "save_preset into a missing directory did not throw";
  } catch (const foldlab::WriteError& e) {
    // A WriteError (exit 1), not a PresetError (exit 2): the preset is fine, the disk is not.
    EXPECT_TRUE(contains(e.what(), path.string())) << e.what();
    EXPECT_TRUE(contains(e.what(), "No such file or directory")) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "does-not-exist"));
  EXPECT_TRUE(directory_entries(dir_).empty());
}

TEST_F(PresetTest, SaveOfInvalidParametersThrowsAndKeepsTheOldFile) {
  const fs::path path = dir_ / "keep.json";
  write_bytes(path, kValidPresetText);
  const std::string before = read_bytes(path);

  foldlab::Preset bad = awkward_preset();
  bad.parameters.hanging.length_mm = 1400.0;
  bad.parameters.hanging.support_displacement_mm = 700.0;
  try {
    foldlab::save_preset(bad, path);
    ADD_FAILURE() << "save_preset of invalid parameters did not throw";
  } catch (const foldlab::PresetError& e) {
    EXPECT_TRUE(contains(e.what(), path.string())) << e.what();
    EXPECT_TRUE(contains(e.what(), "support displacement d = 700 mm must be below")) << e.what();
  }
  EXPECT_EQ(read_bytes(path), before);
  const std::vector<std::string> entries = directory_entries(dir_);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0], "keep.json");
}

TEST_F(PresetTest, LoadingAMissingFileSaysCannotOpen) {
  const fs::path path = dir_ / "nowhere.json";
  const std::string message = load_error_from(path);
  EXPECT_TRUE(contains(message, "cannot open")) << message;
}

TEST_F(PresetTest, DefaultPresetIsTheDefaultFileOnTheTable1H1400Cloth) {
  const foldlab::Preset from_file = foldlab::load_preset(kPresetsDir / "default.json");
  const foldlab::Preset& built_in = foldlab::default_preset();
  expect_same_preset(from_file, built_in);
  // The numbers of the paper's Table 1, h = 1400 mm row.
  EXPECT_EQ(built_in.parameters.fabric.thickness_mm, 0.25);
  EXPECT_EQ(built_in.parameters.fabric.youngs_modulus_MPa, 165.0);
  EXPECT_EQ(built_in.parameters.fabric.weight_N_per_mm2, 1.5e-6);
  EXPECT_EQ(built_in.parameters.hanging.height_mm, 1400.0);
  EXPECT_EQ(built_in.parameters.hanging.length_mm, 1400.0);
  EXPECT_EQ(built_in.parameters.hanging.support_displacement_mm, 100.0);
  // A model, not a row of the paper: `compare` lists the paper presets, not this one.
  EXPECT_FALSE(built_in.published.n);
  EXPECT_TRUE(built_in.calibration);
}

}  // namespace
