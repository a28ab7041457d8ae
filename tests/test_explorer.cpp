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
#include <memory>
#include <string>
#include <vector>

#include "app/gui/appearance.hpp"
#include "app/gui/explorer.hpp"
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
    return drawn_text(*ImGui::GetDrawData());
  }

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
  static std::string drawn_text(const ImDrawData& data) {
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
        append_utf8(text, glyph->Codepoint);
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

  ImGuiContext* context_ = nullptr;
  NullRenderer renderer_;
  std::unique_ptr<Explorer> explorer_;
};

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
  text = frame();
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the map's x axis\n" << text;
  EXPECT_NE(text.find("w (N/mm²)"), std::string::npos) << "the map's y axis";
  EXPECT_EQ(text.find("nu"), text.find("nu (Poisson's ratio)")) << "nu only on its slider";
}

TEST_F(ExplorerTest, SlidersShowTheInputTablesFormatAndUnit) {
  const std::string text = frame();
  // w's row: "%.3e" in N/mm²; h's row: "%.0f" in mm.
  EXPECT_NE(text.find("1.500e-06 N/mm²"), std::string::npos) << text;
  EXPECT_NE(text.find("1400 mm"), std::string::npos) << text;
  for (const char* key : {"t", "E", "w", "nu", "h", "L", "d", "K"}) {
    const InputSpec* spec = find_input(key);
    const std::string label = std::string(key) + " (" + std::string(spec->name) + ")";
    EXPECT_NE(text.find(label), std::string::npos) << label;
  }
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

}  // namespace
}  // namespace foldlab::gui
