// The explorer in a test process: an ImGui context with no platform and no GL (fonts built, a
// display size set), the null renderer, and Explorer::frame() between NewFrame and Render. What a
// frame shows is read back from the glyphs in ImGui's draw data, so the checks see the words and
// numbers a user would read.
#include <gtest/gtest.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/gui/appearance.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/input_player.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/scripted_run.hpp"
#include "core/io/preset.hpp"
#include "core/model/settings.hpp"
#include "temp_dir.hpp"

namespace foldlab::gui {
namespace {

namespace fs = std::filesystem;
const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

class ExplorerTest : public foldlab::testing::TempDirTest {
 protected:
  ExplorerTest() : TempDirTest("foldlab_explorer_") {}

  void SetUp() override {
    TempDirTest::SetUp();
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 800);
    io.DeltaTime = 1.0f / 60.0f;
    io.KeyMap[ImGuiKey_Escape] = kEscape;
    unsigned char* pixels = nullptr;
    int w = 0;
    int h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(1)));
    open_explorer("equations");
  }

  // The explorer on Table 1's h = 1400 mm row, with `tab` shown in the Analysis panel.
  void open_explorer(const std::string& tab, const fs::path& font_file = {},
                     const fs::path& session_file = {}, bool restore = false) {
    explorer_.reset();
    explorer_ = std::make_unique<Explorer>(
        load_preset(kPresetsDir / "paper-table1-h1400.json"),
        (kPresetsDir / "paper-table1-h1400.json").string(), restore,
        ExplorerOptions{kPresetsDir, dir_ / "user-presets", session_file, tab, font_file},
        renderer_);
    // ImGui sizes tables and child windows from what the previous frame held.
    frame();
    frame();
  }

  void TearDown() override {
    explorer_.reset();
    ImGui::DestroyContext(context_);
    TempDirTest::TearDown();
  }

  // One frame; returns every text it drew, in drawing order.
  std::string frame() {
    explorer_->prepare_frame();
    ImGui::NewFrame();
    explorer_->frame();
    ImGui::Render();
    last_text_ = drawn_text(*ImGui::GetDrawData(), &last_positions_);
    return last_text_;
  }

  // Where the last frame drew `label` (the top left of its first glyph); fails the test when it
  // did not draw it.
  ImVec2 position_of(const std::string& label) {
    const std::size_t at = last_text_.rfind(label);
    EXPECT_NE(at, std::string::npos) << label << " is not shown:\n" << last_text_;
    return at == std::string::npos ? ImVec2(-100.0f, -100.0f) : last_positions_[at];
  }

  // A left click as a hand makes it: press, then release on the next frame.
  void click_at(ImVec2 at) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = at;
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
    frame();  // what the click opened is drawn
  }
  void click(const std::string& label) {
    const ImVec2 at = position_of(label);
    click_at(ImVec2(at.x + 3.0f, at.y + 4.0f));
  }

  // A key with Ctrl and Shift as given (letters by their upper-case ASCII code, as GLFW sends
  // them; Escape by the code the key map names).
  void press(int key, bool ctrl = false, bool shift = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    io.KeysDown[key] = true;
    frame();
    io.KeysDown[key] = false;
    io.KeyCtrl = false;
    io.KeyShift = false;
    frame();
  }
  static constexpr int kEscape = 256;  // GLFW_KEY_ESCAPE

  const Parameters& shown() { return explorer_->scene().parameters(); }
  static Preset cotton() { return load_preset(kPresetsDir / "fabric-cotton-jersey.json"); }
  double height_mm() { return explorer_->edited().hanging.height_mm; }
  Document& document() { return explorer_->document(); }

  static void append_utf8(std::string& text, unsigned codepoint) {
    if (codepoint < 0x80) {
      text += static_cast<char>(codepoint);
    } else if (codepoint < 0x800) {
      text += static_cast<char>(0xC0 | (codepoint >> 6));
      text += static_cast<char>(0x80 | (codepoint & 0x3F));
    } else {
      text += static_cast<char>(0xE0 | (codepoint >> 12));
      text += static_cast<char>(0x80 | ((codepoint >> 6) & 0x3F));
      text += static_cast<char>(0x80 | (codepoint & 0x3F));
    }
  }

  // The text in the draw data: a glyph is a quad whose corners carry its UV rectangle in the font
  // atlas. A space draws nothing, so a gap wider than a glyph's advance becomes one space and a
  // move to another baseline a new line.
  static std::string drawn_text(const ImDrawData& data, std::vector<ImVec2>* positions) {
    const ImFont* font = ImGui::GetFont();
    const float advance = font->FindGlyph('a')->AdvanceX;
    std::string text;
    float last_x = -1e9f;
    float last_y = -1e9f;
    for (int l = 0; l < data.CmdListsCount; ++l) {
      const ImVector<ImDrawVert>& v = data.CmdLists[l]->VtxBuffer;
      for (int i = 0; i + 3 < v.Size; ++i) {
        const ImFontGlyph* glyph = nullptr;
        for (const ImFontGlyph& g : font->Glyphs) {
          if (g.Visible && v[i].uv.x == g.U0 && v[i].uv.y == g.V0 && v[i + 2].uv.x == g.U1 &&
              v[i + 2].uv.y == g.V1 && v[i + 1].uv.x == g.U1 && v[i + 3].uv.y == g.V1) {
            glyph = &g;
            break;
          }
        }
        if (glyph == nullptr) {
          continue;
        }
        const float x = v[i].pos.x - glyph->X0;
        const float y = v[i].pos.y - glyph->Y0;
        if (std::abs(y - last_y) > 1.0f) {
          text += '\n';
        } else if (x - last_x > 1.5f * advance) {
          text += ' ';
        }
        positions->resize(text.size(), ImVec2(x, y));
        append_utf8(text, glyph->Codepoint);
        positions->resize(text.size(), ImVec2(x, y));
        last_x = x;
        last_y = y;
        i += 3;
      }
    }
    return text;
  }

  // The number after `label` in a frame's text (NaN when the label is not shown).
  static double number_after(const std::string& text, const std::string& label) {
    const std::size_t at = text.find(label);
    if (at == std::string::npos) {
      return std::nan("");
    }
    return std::strtod(text.c_str() + at + label.size(), nullptr);
  }

  std::uint64_t evaluations(Stage stage) { return explorer_->scene().stats(stage).evaluations; }

  std::string last_text_;
  std::vector<ImVec2> last_positions_;  // where each byte of last_text_ was drawn
  ImGuiContext* context_ = nullptr;
  NullRenderer renderer_;
  std::unique_ptr<Explorer> explorer_;
};

// Input playback with the null renderer: the script's frames run in this process.
int play(Explorer& explorer, const nlohmann::json& script, const std::function<void()>& frame);

TEST_F(ExplorerTest, AFrameShowsTheResultsOfTheLoadedPreset) {
  const std::string text = frame();
  EXPECT_NE(text.find("Table 1, h = 1400 mm"), std::string::npos) << text;
  EXPECT_NE(text.find("Regime: wrinkled"), std::string::npos);
  // The model's n for Table 1's h = 1400 mm row (`foldlab compare`: 8; the paper printed 7).
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 8.0) << text;
}

TEST_F(ExplorerTest, ChangingAnInputChangesTheResultsShown) {
  frame();
  // Table 1's h = 900 mm row differs from the loaded h = 1400 mm only in h; the paper printed
  // n = 5 and Q = 1.31 for it, which the model reproduces.
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  const std::string text = frame();
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 5.0) << text;
  EXPECT_NEAR(number_after(text, "amplitude ratio Q "), 1.31, 0.005) << text;
  EXPECT_NE(text.find("Parameters *"), std::string::npos) << "the unsaved marker";
}

TEST_F(ExplorerTest, ARefusedValueKeepsTheLastValidStateAndSaysWhy) {
  frame();
  // d must stay below L/2 = 700 mm.
  ASSERT_EQ(explorer_->set_input("d", 800.0), std::nullopt);
  const std::string text = frame();
  EXPECT_EQ(explorer_->scene().parameters().hanging.support_displacement_mm, 100.0);
  EXPECT_EQ(explorer_->edited().hanging.support_displacement_mm, 800.0);
  EXPECT_NE(text.find("1 input(s) refused"), std::string::npos) << text;
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 8.0);
}

TEST_F(ExplorerTest, SwitchingPresetShowsTheNewPreset) {
  frame();
  explorer_->load_preset_file(kPresetsDir / "paper-table2-w54.json");
  const std::string text = frame();
  EXPECT_NE(text.find("Loaded Table 2, w = 54e-7 N/mm²."), std::string::npos) << text;
  EXPECT_EQ(explorer_->scene().parameters().fabric.weight_N_per_mm2, 54e-7);
  // Table 2's w = 54e-7 row: the paper printed n = 7, as the model gives.
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 7.0) << text;
  EXPECT_EQ(text.find("Parameters *"), std::string::npos) << "a fresh preset has no edits";
}

TEST_F(ExplorerTest, IdleFramesRecomputeNothingAndADragRecomputesOnce) {
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const Stage stages[] = {Stage::solution, Stage::fold_lines, Stage::grid, Stage::normals};
  std::uint64_t before[4];
  for (int k = 0; k < 4; ++k) {
    before[k] = evaluations(stages[k]);
    EXPECT_GE(before[k], 1u) << to_string(stages[k]) << ": the views need every stage";
  }
  const RenderCounters counters = explorer_->renderer_counters();
  for (int i = 0; i < 10; ++i) {
    frame();
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(evaluations(stages[k]), before[k]) << to_string(stages[k]);
  }
  EXPECT_EQ(explorer_->renderer_counters().mesh_uploads, counters.mesh_uploads);
  EXPECT_EQ(explorer_->renderer_counters().frames, counters.frames + 10);

  explorer_->set_input("h", 1500.0);
  frame();
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(evaluations(stages[k]), before[k] + 1) << to_string(stages[k]);
  }
  EXPECT_EQ(explorer_->renderer_counters().mesh_uploads, counters.mesh_uploads + 1);
}

// The analysis panels once chose inputs by their index in the input table, which moved when the
// table was reordered (index 3 became nu): Table 1 was swept over nu, the map's x axis was nu.
TEST_F(ExplorerTest, AnalysisPanelsSweepThePapersInputsByKey) {
  EXPECT_EQ(explorer_->analysis().sweep().key(), "h");
  EXPECT_EQ(explorer_->analysis().regime_map().x_key(), "h");
  EXPECT_EQ(explorer_->analysis().regime_map().y_key(), "w");

  ASSERT_EQ(explorer_->set_view("sweep", "table1"), std::nullopt);
  frame();  // a tab selected now shows from the next frame on
  std::string text = frame();
  EXPECT_EQ(explorer_->analysis().sweep().key(), "h");
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the sweep's x axis\n" << text;
  // The heights of the paper's Table 1 rows that ship as presets.
  std::vector<double> xs = explorer_->analysis().sweep().overlay_x();
  std::sort(xs.begin(), xs.end());
  EXPECT_EQ(xs, (std::vector<double>{900.0, 1400.0, 2350.0}));
  EXPECT_EQ(text.find("cannot be swept"), std::string::npos) << text;

  ASSERT_EQ(explorer_->set_view("sweep", "table2"), std::nullopt);
  text = frame();
  EXPECT_EQ(explorer_->analysis().sweep().key(), "w");
  xs = explorer_->analysis().sweep().overlay_x();
  std::sort(xs.begin(), xs.end());
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_DOUBLE_EQ(xs[0], 10e-7);
  EXPECT_DOUBLE_EQ(xs[2], 54e-7);
  EXPECT_NE(frame().find("w (N/mm²)"), std::string::npos) << "the sweep's x axis";

  open_explorer("map");
  document().expert_mode = true;
  frame();
  text = frame();
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the map's x axis\n" << text;
  EXPECT_NE(text.find("w (N/mm²)"), std::string::npos) << "the map's y axis";
  EXPECT_EQ(text.find("nu"), text.find("nu (Poisson's ratio)")) << "nu only on its slider";
}

TEST_F(ExplorerTest, SlidersShowTheInputTablesFormatAndUnit) {
  click(ParametersPanel::kExpertLabel);
  const std::string text = frame();
  // w's slider in g/m²: 1.5e-6 N/mm² / 9.81e-9 = 152.9 g/m² = 4.510 oz/yd² (at 33.906 g/m²
  // each); h's row: "%.0f" in mm.
  EXPECT_NE(text.find("153 g/m²"), std::string::npos) << text;
  EXPECT_NE(text.find("= 4.51 oz/yd² = 1.5e-06 N/mm²"), std::string::npos) << text;
  EXPECT_NE(text.find("1400 mm"), std::string::npos) << text;
  for (const char* key : {"t", "E", "w", "nu", "h", "L", "d", "K"}) {
    const InputSpec* spec = find_input(key);
    const std::string label = std::string(key) + " (" + std::string(spec->name) + ")";
    EXPECT_NE(text.find(label), std::string::npos) << label;
  }
}

// Every model setting was shown to a designer who has not met eq. 7.
TEST_F(ExplorerTest, BeginnersSeeTheClothAndExpertsTheModelTooRemembered) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(document().expert_mode) << "a first start is a beginner's";
  std::string text = frame();
  for (const char* shown :
       {"t (thickness)", "E (Young's modulus)", "w (weight per area)", "h (height)", "L (width)",
        "d (support displacement)", "shape", ParametersPanel::kPrintedEq7Label}) {
    EXPECT_NE(text.find(shown), std::string::npos) << shown << "\n" << text;
  }
  for (const char* hidden : {"nu (Poisson's ratio)", "K (eq. 7", "p (eq. 7", "span rule", "Int[]",
                             "per side", "load-condition constant"}) {
    EXPECT_EQ(text.find(hidden), std::string::npos) << hidden;
  }
  EXPECT_EQ(explorer_->parameters_panel().slider_places().count("K"), 0u);
  click(ParametersPanel::kExpertLabel);
  text = frame();
  for (const char* shown : {"nu (Poisson's ratio)", "K (eq. 7", "p (eq. 7", "span rule", "Int[]",
                            "method", "per side", ParametersPanel::kPrintedEq7Label}) {
    EXPECT_NE(text.find(shown), std::string::npos) << shown << "\n" << text;
  }
  open_explorer("equations", {}, session, true);
  EXPECT_TRUE(document().expert_mode) << "remembered in the session";
}

// The paper's form of eq. 7 is one click away for a beginner too: p = 1 and K = 26.9 / 0.91.
TEST_F(ExplorerTest, ThePrintedEq7IsOneClickAwayInBothModes) {
  explorer_->load_preset_file(kPresetsDir / "default.json");
  frame();
  ASSERT_NE(document().edited().model.stress_exponent_p, 1.0) << "the default is calibrated";
  click(ParametersPanel::kPrintedEq7Label);
  const Parameters& p = document().edited();
  EXPECT_EQ(p.model.method, Method::paper);
  EXPECT_EQ(p.model.stress_exponent_p, 1.0);
  EXPECT_NEAR(stiffness_constant_K(p), 29.5604, 1e-4);
  EXPECT_TRUE(document().issues().empty());
}

TEST_F(ExplorerTest, TheShapeIsChosenInTheParametersPanel) {
  click("cosine");  // the combo shows the current shape
  click("strip");
  EXPECT_EQ(document().edited().shape.kind, ShapeKind::strip);
  EXPECT_EQ(shown().shape.kind, ShapeKind::strip) << "the views follow";
  EXPECT_NE(frame().find("supports"), std::string::npos) << last_text_;
  click("strip");
  click("inclined");
  EXPECT_EQ(shown().shape.kind, ShapeKind::inclined);
  EXPECT_NE(frame().find("incline_deg (incline)"), std::string::npos) << last_text_;
}

// Hovering a preset showed its path: a designer wants to know what fabric it is.
TEST_F(ExplorerTest, HoveringAPresetShowsItsDescriptionAndThenItsPath) {
  const ImVec2 at = position_of("Cotton jersey knit");
  ImGui::GetIO().MousePos = ImVec2(at.x + 3.0f, at.y + 4.0f);
  frame();
  const std::string text = frame();
  const std::size_t description = text.find("Single-jersey weft-knitted cotton");
  const std::size_t path = text.find("fabric-cotton-jersey.json");
  ASSERT_NE(description, std::string::npos) << text;
  ASSERT_NE(path, std::string::npos) << text;
  EXPECT_LT(description, path);
}

// A saved preset kept the source preset's description and sources as if they were its own.
TEST_F(ExplorerTest, SaveAsRecordsWhatThePresetWasDerivedFrom) {
  explorer_->load_preset_file(kPresetsDir / "fabric-cotton-jersey.json");
  ASSERT_EQ(explorer_->set_input("w", 120 * kNPerMm2PerGramPerM2), std::nullopt);
  frame();
  press('S', true);
  ASSERT_EQ(document().modal_title(), "Save as");
  click("Save");
  const fs::path written = dir_ / "user-presets" / "cotton-jersey-knit-edited.json";
  ASSERT_TRUE(fs::exists(written)) << last_text_;
  const Preset saved = load_preset(written);
  const Preset source = cotton();
  EXPECT_EQ(saved.derived_from, "Cotton jersey knit");
  EXPECT_NE(saved.description, source.description);
  EXPECT_EQ(saved.description.find("Single-jersey"), std::string::npos) << saved.description;
  EXPECT_EQ(saved.source.find("Fistik"), std::string::npos) << saved.source;
  EXPECT_EQ(saved.parameters.fabric.weight_N_per_mm2, 120 * kNPerMm2PerGramPerM2);
  // Saving it again over itself keeps what it was derived from.
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  press('S', true);
  EXPECT_EQ(load_preset(written).derived_from, "Cotton jersey knit");
  // The listing's hover names the origin.
  const auto& entries = explorer_->presets().entries();
  const auto entry = std::find_if(entries.begin(), entries.end(), [](const auto& e) {
    return e.path.filename() == "cotton-jersey-knit-edited.json";
  });
  ASSERT_NE(entry, entries.end());
  EXPECT_NE(entry->description.find("Derived from \"Cotton jersey knit\"."), std::string::npos)
      << entry->description;
}

// Typing "80 g/m2" was refused: a designer's unit. A bare number is g/m², as the slider shows.
TEST_F(ExplorerTest, AWeightIsTypedInGramsPerSquareMetreOrOuncesPerSquareYard) {
  const auto type_into_w = [&](const std::string& typed) {
    return play(
        *explorer_,
        {{"steps",
          {{{"click", "w"}, {"at", 0.5}, {"ctrl", true}}, {{"type", typed}}, {{"key", "enter"}}}}},
        [&] { frame(); });
  };
  ASSERT_EQ(type_into_w("80 g/m2"), 0);
  EXPECT_NEAR(document().edited().fabric.weight_N_per_mm2, 80 * 9.81e-9, 1e-18);
  EXPECT_NE(frame().find("80 g/m²"), std::string::npos) << last_text_;
  EXPECT_NE(last_text_.find("= 2.36 oz/yd²"), std::string::npos) << last_text_;  // 80 / 33.906
  ASSERT_EQ(type_into_w("2.4 oz/yd²"), 0);
  // 2.4 x 28.349523125 g / 0.83612736 m² = 81.3738 g/m², x 9.81e-9.
  EXPECT_NEAR(document().edited().fabric.weight_N_per_mm2, 7.9827692e-7, 1e-14);
  ASSERT_EQ(type_into_w("150"), 0);
  EXPECT_NEAR(document().edited().fabric.weight_N_per_mm2, 150 * 9.81e-9, 1e-18);
  EXPECT_TRUE(document().issues().empty());
}

// Clicking a preset once replaced unsaved edits with no question.
TEST_F(ExplorerTest, APresetClickAsksBeforeReplacingUnsavedEditsAndCancelKeepsThem) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  EXPECT_EQ(document().modal_title(), "Unsaved changes");
  EXPECT_NE(last_text_.find("Discard"), std::string::npos) << last_text_;
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0) << "nothing replaced yet";
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);

  click("Cancel");
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm (default)");
  EXPECT_TRUE(document().unsaved());
  EXPECT_EQ(frame().find("Discard"), std::string::npos) << "the dialog is closed";
}

TEST_F(ExplorerTest, EscapeClosesTheUnsavedEditsDialogAndKeepsTheEdits) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  ASSERT_EQ(document().modal_title(), "Unsaved changes");
  press(kEscape);
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(frame().find("Discard"), std::string::npos) << "the dialog is closed";
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm (default)");
}

TEST_F(ExplorerTest, DiscardLoadsThePresetClickedAndWithoutEditsNothingIsAsked) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Discard");
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Cotton jersey knit");
  EXPECT_TRUE(shown() == cotton().parameters);
  EXPECT_FALSE(document().unsaved());

  click("Fig. 4, h = L = 1400 mm");
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Fig. 4, h = L = 1400 mm");
}

// "Save" on a shipped preset asks for a name, writes the user preset, then loads the one clicked.
TEST_F(ExplorerTest, SaveInTheDialogWritesTheEditsThenLoads) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Save");
  EXPECT_EQ(document().modal_title(), "Save as");
  click("Save");
  const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-default-edited.json";
  ASSERT_TRUE(fs::exists(written)) << last_text_;
  EXPECT_EQ(load_preset(written).parameters.hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Cotton jersey knit");
}

TEST_F(ExplorerTest, ThePapersCaseButtonsAskBeforeReplacingUnsavedEdits) {
  open_explorer("sweep");
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  click("Table 2 (w)");
  EXPECT_EQ(document().modal_title(), "Unsaved changes");
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  click("Discard");
  EXPECT_EQ(document().loaded().name, "Table 2, w = 33e-7 N/mm²");
  EXPECT_EQ(explorer_->analysis().sweep().key(), "w");
}

// With no session to bring them back (--fresh), closing the window lost the edits unasked.
TEST_F(ExplorerTest, ClosingTheWindowAsksWhenEditsWouldBeLost) {
  EXPECT_TRUE(explorer_->may_quit()) << "nothing to lose";
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  EXPECT_FALSE(explorer_->may_quit());
  frame();
  frame();  // a dialog sizes itself on its first frame and shows from the next
  EXPECT_EQ(document().modal_title(), "Unsaved changes");
  EXPECT_NE(last_text_.find("Closing the window loses them."), std::string::npos) << last_text_;
  press(kEscape);
  EXPECT_FALSE(explorer_->quit_confirmed());
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);

  EXPECT_FALSE(explorer_->may_quit());
  frame();
  frame();
  click("Discard");
  EXPECT_TRUE(explorer_->quit_confirmed());
}

TEST_F(ExplorerTest, UndoAndRedoRestoreTheExactValues) {
  ASSERT_EQ(explorer_->set_input("h", 912.345678901), std::nullopt);
  ASSERT_EQ(explorer_->set_input("d", 123.456789012), std::nullopt);
  frame();
  EXPECT_EQ(document().undo_depth(), 2u);
  press('Z', true);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 100.0);
  EXPECT_EQ(shown().hanging.height_mm, 912.345678901);
  press('Z', true);
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);
  EXPECT_FALSE(document().unsaved());
  EXPECT_EQ(document().undo_depth(), 0u);
  press('Z', true, true);  // Ctrl+Shift+Z
  EXPECT_EQ(shown().hanging.height_mm, 912.345678901);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 100.0);
  press('Y', true);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.456789012);
  EXPECT_EQ(document().undo_depth(), 2u);
}

TEST_F(ExplorerTest, UndoBringsBackTheEditsAPresetLoadReplaced) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Discard");
  ASSERT_TRUE(shown() == cotton().parameters);
  press('Z', true);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm (default)");
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(shown().fabric.weight_N_per_mm2, 15e-7);
  press('Y', true);
  EXPECT_TRUE(shown() == cotton().parameters);
}

// A drag changes h on every frame it moves; undo takes the whole drag back at once.
TEST_F(ExplorerTest, OneDragOfASliderIsOneUndoStep) {
  const ImVec2 label = position_of("h (height)");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(label.x - 60.0f, label.y + 4.0f);
  frame();
  io.MouseDown[0] = true;
  frame();
  std::vector<double> seen{height_mm()};
  for (int step = 1; step <= 8; ++step) {
    io.MousePos.x -= 5.0f;
    frame();
    seen.push_back(height_mm());
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  std::sort(seen.begin(), seen.end());
  EXPECT_GT(std::unique(seen.begin(), seen.end()) - seen.begin(), 3) << "h moved over the drag";
  EXPECT_NE(shown().hanging.height_mm, 1400.0);
  EXPECT_EQ(document().undo_depth(), 1u);
  press('Z', true);
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);
  EXPECT_EQ(document().undo_depth(), 0u);
}

TEST_F(ExplorerTest, CtrlSSavesAsThenOverTheUsersPreset) {
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  press('S', true);
  EXPECT_EQ(document().modal_title(), "Save as") << "a shipped preset is never overwritten";
  click("Save");
  const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-default-edited.json";
  ASSERT_TRUE(fs::exists(written));
  EXPECT_EQ(document().message(), "Saved to " + written.string());
  EXPECT_NE(frame().find("Saved to"), std::string::npos) << last_text_;
  EXPECT_FALSE(document().unsaved());

  // Now the loaded preset is the user's: Ctrl+S writes over it without asking.
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  press('S', true);
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
}

TEST_F(ExplorerTest, NotSavingIsAWarningNotASuccess) {
  press('S', true);
  ASSERT_EQ(document().modal_title(), "Save as");
  press(kEscape);
  EXPECT_EQ(document().modal_title(), "");
  EXPECT_EQ(document().message(), "Not saved.");
  EXPECT_EQ(document().message_kind(), MessageKind::warning);
  EXPECT_FALSE(fs::exists(dir_ / "user-presets"));
}

TEST_F(ExplorerTest, StatusMessagesExpire) {
  click("Cotton jersey knit");
  EXPECT_NE(frame().find("Loaded Cotton jersey knit."), std::string::npos);
  ImGui::GetIO().DeltaTime = 5.0f;
  frame();
  frame();
  ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
  EXPECT_EQ(frame().find("Loaded Cotton"), std::string::npos) << "10 s later";
}

// A refused value's reason once appeared under its slider and pushed every slider below it down.
TEST_F(ExplorerTest, ARefusedValueMovesNoSliderAndMarksTheViewsStale) {
  document().expert_mode = true;  // K, the last slider
  frame();
  const ImVec2 before = position_of("K (");
  EXPECT_EQ(last_text_.find("stale"), std::string::npos);
  ASSERT_EQ(explorer_->set_input("d", 800.0), std::nullopt);
  const std::string text = frame();
  const ImVec2 after = position_of("K (");
  EXPECT_EQ(after.y, before.y);
  EXPECT_NE(text.find("d_mm = 800"), std::string::npos) << "the reason is still shown\n" << text;
  EXPECT_NE(text.find("stale"), std::string::npos) << text;
}

TEST(Contrast, MatchesHandComputedWcagRatios) {
  const ImVec4 black(0, 0, 0, 1);
  const ImVec4 white(1, 1, 1, 1);
  EXPECT_NEAR(contrast_ratio(black, white), 21.0, 1e-9);
  EXPECT_NEAR(contrast_ratio(white, black), 21.0, 1e-9);
  EXPECT_NEAR(contrast_ratio(white, white), 1.0, 1e-12);
  // #767676 on white: 118/255 = 0.46275 -> ((0.46275 + 0.055) / 1.055)^2.4 = 0.18116 (grey, so
  // that is L), and 1.05 / 0.23116 = 4.542: the lightest grey that passes 4.5:1 on white.
  const float grey = 118.0f / 255.0f;
  EXPECT_NEAR(contrast_ratio(ImVec4(grey, grey, grey, 1), white), 4.542, 0.001);
  // Pure red: L = 0.2126, so 1.05 / 0.2626 = 3.998 on white and 0.2626 / 0.05 = 5.252 on black.
  EXPECT_NEAR(contrast_ratio(ImVec4(1, 0, 0, 1), white), 3.998, 0.001);
  EXPECT_NEAR(contrast_ratio(ImVec4(1, 0, 0, 1), black), 5.252, 0.001);
  // Half-transparent white over black is the grey 0.5: L = 0.21404, 0.26404 / 0.05 = 5.281.
  EXPECT_NEAR(contrast_ratio(blend_over(ImVec4(1, 1, 1, 0.5f), black), black), 5.281, 0.001);
}

TEST(Contrast, FoldColoursReadOnThePlotBackgroundInBothThemes) {
  for (const bool light : {false, true}) {
    const ImVec4 background = plot_background(light);
    const FoldColours colours = fold_colours(light);
    EXPECT_GE(contrast_ratio(colours.positive, background), 4.5) << "light " << light;
    EXPECT_GE(contrast_ratio(colours.negative, background), 4.5) << "light " << light;
  }
  // The blue the plot used before on the dark theme's plot: the 1.3:1 a projector washes out.
  const ImVec4 old_blue(31 / 255.0f, 58 / 255.0f, 147 / 255.0f, 1.0f);
  EXPECT_NEAR(contrast_ratio(old_blue, plot_background(false)), 1.3, 0.1);
}

TEST_F(ExplorerTest, TheFontHasGreekAndFallsBackWhenMissing) {
  constexpr ImWchar kNu = 0x03BD;
  constexpr ImWchar kCapitalSigma = 0x03A3;
  open_explorer("equations", kDejaVuSans);
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  EXPECT_NE(font->FindGlyphNoFallback(kNu), nullptr);
  EXPECT_NE(font->FindGlyphNoFallback(kCapitalSigma), nullptr);
  EXPECT_NE(font->FindGlyphNoFallback(0x03C0), nullptr);  // π
  EXPECT_TRUE(explorer_->appearance().notice().empty()) << explorer_->appearance().notice();
  // The equations read as in the paper, drawn with the font's own glyphs.
  EXPECT_NE(frame().find("(2l/π)"), std::string::npos);

  open_explorer("equations", dir_ / "no-such-font.ttf");
  EXPECT_NE(explorer_->appearance().notice().find("no-such-font.ttf"), std::string::npos);
  EXPECT_NE(frame().find("is missing"), std::string::npos) << "the notice is shown";
  EXPECT_NE(ImGui::GetIO().Fonts->Fonts[0]->FindGlyphNoFallback('a'), nullptr);
}

TEST_F(ExplorerTest, UiScaleIsClampedAndRememberedWithTheTheme) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  EXPECT_EQ(explorer_->appearance().scale_percent(), 100);
  ASSERT_EQ(explorer_->set_view("scale", "400"), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->appearance().scale_percent(), 250);
  // ImGui's 13 px font rebuilt at 2.5 times its size, not stretched.
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 33.0f);
  EXPECT_FLOAT_EQ(ImGui::GetIO().FontGlobalScale, 1.0f);
  ASSERT_EQ(explorer_->set_view("scale", "20"), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->appearance().scale_percent(), 100);
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 13.0f);

  // Ctrl + (the '=' key) five times: 150 %; the style's sizes scale with it.
  const float padding_100 = ImGui::GetStyle().FramePadding.x;
  ImGuiIO& io = ImGui::GetIO();
  for (int i = 0; i < 5; ++i) {
    io.KeyCtrl = true;
    io.KeysDown['='] = true;
    frame();
    io.KeysDown['='] = false;
    frame();
  }
  io.KeyCtrl = false;
  EXPECT_EQ(explorer_->appearance().scale_percent(), 150);
  EXPECT_FLOAT_EQ(ImGui::GetStyle().FramePadding.x, 1.5f * padding_100);
  ASSERT_EQ(explorer_->set_view("theme", "light"), std::nullopt);
  frame();
  EXPECT_TRUE(style_is_light());
  explorer_->save_session_now();

  open_explorer("equations", {}, session, true);
  EXPECT_EQ(explorer_->appearance().scale_percent(), 150);
  EXPECT_TRUE(explorer_->appearance().light_theme());
  EXPECT_TRUE(style_is_light());
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 20.0f);  // round(13 * 1.5)
}

TEST_F(ExplorerTest, ThePapersOverlayBelongsToItsCaseOnly) {
  ASSERT_EQ(explorer_->set_view("sweep", "table2"), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->analysis().sweep().overlay_x().size(), 3u) << "Table 2's printed rows";
  explorer_->load_preset_file(kPresetsDir / "paper-table1-h900.json");
  const std::string text = frame();
  EXPECT_TRUE(explorer_->analysis().sweep().overlay_x().empty());
  EXPECT_EQ(text.find("paper, Table 2"), std::string::npos) << text;
}

TEST(AnimatedInput, MovesOverTheSlidersRangeWhereTheModelAcceptsIt) {
  const Parameters base = load_preset(kPresetsDir / "paper-table1-h1400.json").parameters;
  // h: the table's typical range, 100 to 5000 mm, all valid with L = 1400 mm.
  const AnimatedInput h("h", base);
  EXPECT_DOUBLE_EQ(h.lo(), 100.0);
  EXPECT_DOUBLE_EQ(h.hi(), 5000.0);
  EXPECT_DOUBLE_EQ(h.value(0), 100.0);    // the first frame starts at the low end
  EXPECT_DOUBLE_EQ(h.value(60), 5000.0);  // 60 frames a way
  // d: its slider reaches 2500 mm, but d < L/2 = 700 mm with L = 1400 mm.
  const AnimatedInput d("d", base);
  EXPECT_DOUBLE_EQ(d.lo(), 0.0);
  EXPECT_LT(d.hi(), 700.0);
  EXPECT_GT(d.hi(), 680.0);
  EXPECT_THROW(AnimatedInput("method", base), app::InputError);
}

// Input playback with the null renderer: the script's frames run in this process.
int play(Explorer& explorer, const nlohmann::json& script, const std::function<void()>& frame) {
  InputPlayer player(script, "test script");
  while (player.before_new_frame(ImGui::GetIO(), explorer)) {
    frame();
  }
  return player.exit_status();
}

TEST_F(ExplorerTest, DraggingTheWSliderFromItsHandleMovesWOneThirdOfADecadePer40Pixels) {
  // ImGui 1.86 floats: a 10 px handle inside 2 px of padding, so the handle's centre travels
  // W - 14 px over the slider's three decades (1e-7 to 1e-4 N/mm², the table's typical range).
  const double w0 = explorer_->edited().fabric.weight_N_per_mm2;
  const SliderPlace place = explorer_->parameters_panel().slider_places().at("w");
  const double travel_px = place.max.x - place.min.x - 14.0;
  for (const double dx : {40.0, -40.0}) {
    explorer_->set_input("w", w0);
    frame();
    ASSERT_EQ(play(*explorer_, {{"steps", {{{"drag", "w"}, {"dx", dx}}}}}, [&] { frame(); }), 0);
    const double decades = std::log10(explorer_->edited().fabric.weight_N_per_mm2 / w0);
    // ImGui floors the mouse position: up to a pixel either way.
    EXPECT_NEAR(decades, 3.0 * dx / travel_px, 3.0 * 1.5 / travel_px) << "dx " << dx;
    EXPECT_TRUE(explorer_->document().issues().empty());
  }
}

TEST_F(ExplorerTest, APlayedScriptFailsAtTheFirstExpectThatDoesNotHold) {
  InputPlayer player({{"steps",
                       {{{"expect", {{"parameters.h_mm", 1400}}}},
                        {{"expect", {{"parameters.h_mm", {100, 200}}}}},
                        {{"expect", {{"parameters.h_mm", 1400}}}}}}},
                     "test script");
  int frames = 0;
  while (player.before_new_frame(ImGui::GetIO(), *explorer_)) {
    frame();
    ++frames;
  }
  EXPECT_LT(frames, 10);
  EXPECT_EQ(player.exit_status(), 1);
  EXPECT_NE(player.failure().find("step 2 "), std::string::npos) << player.failure();
}

TEST_F(ExplorerTest, AMalformedScriptNamesEveryProblem) {
  try {
    InputPlayer player({{"steps",
                         {{{"drag", "q"}, {"dx", 1}},
                          {{"click", "w"}, {"at", 2}},
                          {{"frames", 3}},
                          {{"type", 5}}}}},
                       "test script");
    FAIL() << "accepted";
  } catch (const app::InputError& e) {
    const std::string message = e.what();
    for (const char* step : {"step 1:", "step 2:", "step 4:"}) {
      EXPECT_NE(message.find(step), std::string::npos) << message;
    }
    EXPECT_EQ(message.find("step 3:"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace foldlab::gui
