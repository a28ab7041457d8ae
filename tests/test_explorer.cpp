// The explorer in a test process: an ImGui context with no platform and no GL (fonts built, a
// display size set), the null renderer, and Explorer::frame() between NewFrame and Render. What a
// frame shows is read back from the glyphs in ImGui's draw data, so the checks see the words and
// numbers a user would read.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <imgui.h>
#include <imgui_internal.h>  // which windows scroll sideways

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/common/version.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/frame_pacing.hpp"
#include "app/gui/input_player.hpp"
#include "app/gui/menu_bar.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/analysis_panel.hpp"
#include "app/gui/panels/calibration_panel.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/fold_plot_panel.hpp"
#include "app/gui/panels/intro_window.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/photo_overlay.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/picture.hpp"
#include "app/gui/play_script.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/presentation_bar.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/scripted_run.hpp"
#include "app/gui/surface.hpp"
#include "core/analysis/sweep.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/io/measurements.hpp"
#include "core/io/preset.hpp"
#include "core/model/settings.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"
#include "fold_photo.hpp"
#include "headless_imgui.hpp"
#include "process.hpp"
#include "temp_dir.hpp"

namespace foldlab::gui {
namespace {

namespace fs = std::filesystem;
const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

// Input playback with the null renderer: the script's frames run in this process.
int play(Explorer& explorer, const nlohmann::json& script, const std::function<void()>& frame);

class ExplorerTest : public foldlab::testing::TempDirTest {
 protected:
  ExplorerTest() : TempDirTest("foldlab_explorer_") {}

  void SetUp() override {
    TempDirTest::SetUp();
    context_ = foldlab::testing::create_headless_imgui(ImVec2(1280, 800));
    ImGui::GetIO().KeyMap[ImGuiKey_Escape] = kEscape;
    open_explorer("equations");
  }

  // The explorer on Table 1's h = 1400 mm row, with `tab` shown in the Analysis panel.
  void open_explorer(const std::string& tab, const fs::path& font_file = {},
                     const fs::path& session_file = {}, bool restore = false) {
    explorer_.reset();
    explorer_ =
        std::make_unique<Explorer>(load_preset(kPresetsDir / "paper-table1-h1400.json"),
                                   (kPresetsDir / "paper-table1-h1400.json").string(), restore,
                                   ExplorerOptions{kPresetsDir, dir_ / "user-presets", session_file,
                                                   tab, font_file, dir_ / "measurements.csv", dir_},
                                   renderer_);
    // ImGui sizes tables and child windows from what the previous frame held.
    frame();
    frame();
  }

  // The explorer's panel of type P.
  template <class P>
  P& panel() const {
    return find_panel<P>(explorer_->panels());
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
  // h = 900 mm saved with Ctrl+S under the name "Save as" suggests: from then on the loaded preset
  // is the user's own file, which this returns.
  fs::path save_h900_as_the_users() {
    EXPECT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
    press('S', true);
    click("Save");
    const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-edited.json";
    EXPECT_TRUE(fs::exists(written));
    return written;
  }
  UiStatus& status() { return explorer_->status(); }

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

  // Whether every `needle` in a frame's text is on the line under w's slider that gives w in
  // oz/yd² and N/mm² (the one place the model's unit is shown on purpose).
  static bool only_beside_w_slider(const std::string& text, const std::string& needle) {
    for (std::size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + 1)) {
      const std::size_t line_start = text.rfind('\n', at);
      const std::size_t line_end = text.find('\n', at);
      const std::string line =
          text.substr(line_start == std::string::npos ? 0 : line_start,
                      line_end == std::string::npos ? std::string::npos : line_end - line_start);
      if (line.find("oz/yd²") == std::string::npos) {
        return false;
      }
    }
    return true;
  }

  // Whether `text` holds `wanted`, spaces aside (a glyph run's gaps read as spaces or not).
  static bool shows(std::string text, std::string wanted) {
    std::erase(text, ' ');
    std::erase(wanted, ' ');
    return text.find(wanted) != std::string::npos;
  }

  // Types `text` into the field that has the keyboard and presses Enter, as a played script; the
  // script's exit status.
  int type_and_enter(const std::string& text) {
    return play(*explorer_, {{"steps", {{{"type", text}}, {{"key", "enter"}}, {{"frames", 2}}}}},
                [&] { frame(); });
  }

  // The window resized to `size`, and the frames that refit the panels to it.
  void show_at(ImVec2 size) {
    ImGui::GetIO().DisplaySize = size;
    for (int i = 0; i < 3; ++i) {
      frame();
    }
  }

  // Text without its spaces and line breaks: a wrapped sentence reads as one.
  static std::string squeezed(std::string text) {
    std::erase_if(text, [](char c) { return c == ' ' || c == '\n'; });
    return text;
  }

  // w's values in N/mm² are 1e-7..1e-5: written in e-notation, they end in e-0[5-8].
  static bool w_in_e_notation_only_beside_its_slider(const std::string& text) {
    for (const char* exponent : {"e-05", "e-06", "e-07", "e-08"}) {
      if (!only_beside_w_slider(text, exponent)) {
        return false;
      }
    }
    return true;
  }

  std::uint64_t evaluations(Stage stage) { return explorer_->scene().stats(stage).evaluations; }

  // The tiled panel `key`'s rectangle in the last frame (a zero one when it is not shown).
  PanelRect rect_of(const std::string& key) const {
    for (const auto& [name, rect] : explorer_->layout().panel_rects()) {
      if (name == key) {
        return rect;
      }
    }
    return PanelRect{};
  }

  // Scrolls the tiled panel `key` down (up when negative) by `notches` of the wheel, turned over
  // its scrollbar (not over a plot, which takes the wheel to zoom).
  void scroll_panel(const std::string& key, int notches) {
    const PanelRect r = rect_of(key);
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(r.pos.x + r.size.x - 0.5f * ImGui::GetStyle().ScrollbarSize,
                         r.pos.y + 0.5f * r.size.y);
    for (int i = 0; i < std::abs(notches); ++i) {
      io.MouseWheel = notches > 0 ? -1.0f : 1.0f;
      frame();
      io.MouseWheel = 0.0f;
      frame();
    }
  }

  // Glyphs of the last frame inside [min, max) that stick out of the clip rectangle they are
  // drawn with: text cut off by its table column or window. (ImGui leaves out a glyph wholly
  // outside; one across the edge is drawn and cut by the scissor.)
  static std::vector<std::string> cut_glyphs(ImVec2 min, ImVec2 max) {
    const ImDrawData& data = *ImGui::GetDrawData();
    const ImFont* font = ImGui::GetFont();
    // A table or child that scrolls sideways cuts at its edges what the scrollbar reaches.
    std::vector<float> scroll_edges;
    for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
      if (window->Active && window->ScrollMax.x > 0.0f) {
        scroll_edges.push_back(window->InnerClipRect.Min.x);
        scroll_edges.push_back(window->InnerClipRect.Max.x);
      }
    }
    // A tab bar too narrow for its tabs scrolls them with its arrows.
    std::vector<ImRect> scrolling_tabs;
    ImGuiContext& context = *ImGui::GetCurrentContext();
    for (int i = 0; i < context.TabBars.GetMapSize(); ++i) {
      const ImGuiTabBar* bar = context.TabBars.TryGetMapData(i);
      if (bar != nullptr && bar->WidthAllTabs > bar->BarRect.GetWidth()) {
        scrolling_tabs.push_back(bar->BarRect);
      }
    }
    const auto at_scroll_edge = [&](const ImVec4& clip) {
      return std::any_of(scroll_edges.begin(), scroll_edges.end(),
                         [&](float edge) {
                           return std::abs(edge - clip.x) <= 1.0f ||
                                  std::abs(edge - clip.z) <= 1.0f;
                         }) ||
             std::any_of(scrolling_tabs.begin(), scrolling_tabs.end(), [&](const ImRect& bar) {
               return clip.y >= bar.Min.y - 1.0f && clip.w <= bar.Max.y + 1.0f;
             });
    };
    std::vector<std::string> cut;
    for (int l = 0; l < data.CmdListsCount; ++l) {
      const ImDrawList& list = *data.CmdLists[l];
      for (const ImDrawCmd& cmd : list.CmdBuffer) {
        if (cmd.ElemCount == 0 || cmd.UserCallback != nullptr) {
          continue;
        }
        unsigned first = ~0u;
        unsigned last = 0;
        for (unsigned k = 0; k < cmd.ElemCount; ++k) {
          const unsigned v = cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + k)];
          first = std::min(first, v);
          last = std::max(last, v);
        }
        for (unsigned i = first; i + 3 <= last; ++i) {
          const ImDrawVert* v = &list.VtxBuffer[static_cast<int>(i)];
          for (const ImFontGlyph& g : font->Glyphs) {
            if (!g.Visible || v[0].uv.x != g.U0 || v[0].uv.y != g.V0 || v[2].uv.x != g.U1 ||
                v[2].uv.y != g.V1) {
              continue;
            }
            const bool inside = v[0].pos.x >= min.x && v[0].pos.y >= min.y && v[0].pos.x < max.x &&
                                v[0].pos.y < max.y;
            const bool sticks_out =
                v[2].pos.x > cmd.ClipRect.z + 0.5f || v[0].pos.x < cmd.ClipRect.x - 0.5f;
            // Lines cut at the panel's foot or head scroll into view: only sideways cuts count.
            const bool shown = v[2].pos.y > cmd.ClipRect.y && v[0].pos.y < cmd.ClipRect.w;
            if (inside && sticks_out && shown && !at_scroll_edge(cmd.ClipRect)) {
              std::string glyph;
              append_utf8(glyph, g.Codepoint);
              cut.push_back(glyph + " at " + std::to_string(v[0].pos.x) + "," +
                            std::to_string(v[0].pos.y));
            }
            i += 3;
            break;
          }
        }
      }
    }
    return cut;
  }

  std::string last_text_;
  std::vector<ImVec2> last_positions_;  // where each byte of last_text_ was drawn
  ImGuiContext* context_ = nullptr;
  NullRenderer renderer_;
  std::unique_ptr<Explorer> explorer_;
};

TEST_F(ExplorerTest, AFrameShowsTheResultsOfTheLoadedPreset) {
  const std::string text = frame();
  EXPECT_NE(text.find("Table 1, h = 1400 mm"), std::string::npos) << text;
  // A first start is a beginner's: the regime in plain words.
  EXPECT_NE(text.find("wrinkled: the cloth hangs in folds"), std::string::npos) << text;
  // The model's n for Table 1's h = 1400 mm row (`foldlab compare`: 8; the paper printed 7).
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 8.0) << text;
}

// A slider shows a large value in whole units ("15000 mm", not "1.5e+04 mm"), and a refused huge
// one as it was typed rather than as hundreds of digits.
TEST_F(ExplorerTest, ASliderShowsAHugeRefusedValueAsTypedAndALargeOneWhole) {
  ASSERT_EQ(explorer_->set_input("h", 15000.0), std::nullopt);
  ASSERT_EQ(explorer_->set_input("E", 1e308), std::nullopt);
  frame();
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), *find_input("h")), "15000 mm");
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), *find_input("E")), "1e308 MPa");
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

// A page that records what its address was set to.
class RecordingLink final : public PageLink {
 public:
  explicit RecordingLink(std::vector<std::string>& shown) : shown_(shown) {}
  bool follows() const override { return true; }
  void show(std::string_view fragment) override { shown_.emplace_back(fragment); }

 private:
  std::vector<std::string>& shown_;
};

TEST(LinkThrottle, WritesAChangeAtOnceThenAtMostFourTimesASecondAndTheLastAlways) {
  LinkThrottle throttle(0.25);
  EXPECT_EQ(throttle.due("h=1400", 0.0), std::nullopt) << "the address the page opened with";
  EXPECT_EQ(throttle.due("h=1400", 1.0), std::nullopt);
  EXPECT_EQ(throttle.due("h=1500", 1.0), "h=1500");
  EXPECT_FALSE(throttle.pending());
  EXPECT_EQ(throttle.due("h=1600", 1.1), std::nullopt);
  EXPECT_TRUE(throttle.pending());
  EXPECT_EQ(throttle.due("h=1700", 1.2), std::nullopt);
  EXPECT_EQ(throttle.due("h=1700", 1.25), "h=1700");
  EXPECT_FALSE(throttle.pending());
  // Back to what was written before its turn came: nothing to write, nothing pending.
  EXPECT_EQ(throttle.due("h=1800", 1.3), std::nullopt);
  EXPECT_EQ(throttle.due("h=1700", 1.4), std::nullopt);
  EXPECT_FALSE(throttle.pending());
  EXPECT_EQ(throttle.due("h=1700", 9.0), std::nullopt);
}

TEST_F(ExplorerTest, ThePagesAddressFollowsTheInputsWithoutADragRewritingItEveryFrame) {
  std::vector<std::string> shown;
  explorer_->set_page_link(std::make_unique<RecordingLink>(shown));
  frame();
  EXPECT_TRUE(shown.empty()) << shown.front();
  // A slider dragged over 60 frames (one second at 60 frames a second, the test's clock).
  for (int i = 1; i <= 60; ++i) {
    explorer_->document().apply(Edit::input("h", 1400.0 + 10.0 * i).open());
    frame();
  }
  // At once, then every 0.25 s: 1 + 4 writes (the frames' clock rounds), never one a frame.
  EXPECT_GE(shown.size(), 4u);
  EXPECT_LE(shown.size(), 5u);
  EXPECT_NE(shown.front().find("&h=1410&"), std::string::npos) << shown.front();
  // The last value reaches the address once its turn comes, though nothing moves any more.
  for (int i = 0; i < 20; ++i) {
    frame();
  }
  EXPECT_NE(shown.back().find("&h=2000&"), std::string::npos) << shown.back();
  EXPECT_EQ(shown.back(), explorer_->link());
  const std::size_t writes = shown.size();
  for (int i = 0; i < 30; ++i) {
    frame();
  }
  EXPECT_EQ(shown.size(), writes) << "an unchanged link is not written again";
}

TEST_F(ExplorerTest, TheLinkCarriesTheViewSetUpForARoom) {
  frame();
  const std::string fabric = explorer_->link();
  EXPECT_EQ(fabric.find("present="), std::string::npos) << fabric;
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("theme", "light"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("scale", "125"), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->link(), fabric + "&present=cloth&theme=light&scale=125");
  // Copied with the desktop's link and no page address: the fragment behind '#', said in full
  // with what opens it, and shown in the presentation's read-out, the status line being hidden.
  explorer_->copy_link();
  const std::string copied = "#" + explorer_->link();
  EXPECT_EQ(std::string(ImGui::GetClipboardText()), copied);
  const std::string said = explorer_->status().message();
  EXPECT_EQ(said, "Copied the fabric as a link's fragment alone, " + copied.substr(0, 40) +
                      "…, which only foldlab gui --link opens. FOLDLAB_PAGE_URL makes it a whole "
                      "address (docs/web.md).");
  frame();
  EXPECT_EQ(explorer_->presented_message(), said);
  ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->presented_message(), "");
}

TEST_F(ExplorerTest, SwitchingPresetShowsTheNewPreset) {
  frame();
  explorer_->load_preset_file(kPresetsDir / "paper-table2-w54.json");
  const std::string text = frame();
  EXPECT_NE(text.find("Loaded Table 2, w = 550 g/m²."), std::string::npos) << text;
  EXPECT_EQ(explorer_->scene().parameters().fabric.weight_N_per_mm2, 54e-7);
  // Table 2's w = 54e-7 row: the paper printed n = 7, as the model gives.
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 7.0) << text;
  EXPECT_EQ(text.find("Parameters *"), std::string::npos) << "a fresh preset has no edits";
}

// The colour bar beside the 3D view shows the range the shader maps: +-z_max of the solution.
TEST_F(ExplorerTest, ColourByZShowsABarOverTheSolutionsDepth) {
  std::string text = frame();
  const double z_max_mm = explorer_->scene().solution().z_max_mm;
  ASSERT_GT(z_max_mm, 1.0);
  char high[32];
  char low[32];
  std::snprintf(high, sizeof high, "+%.1f mm", z_max_mm);
  std::snprintf(low, sizeof low, "-%.1f mm", z_max_mm);
  EXPECT_EQ(text.find(high), std::string::npos) << "no bar while the cloth shows the fabric";

  ASSERT_EQ(explorer_->set_view("colour_by", "z"), std::nullopt);
  text = frame();
  EXPECT_EQ(panel<ClothViewPanel>().style().colour_by, ClothStyle::ColourBy::z);
  EXPECT_NE(text.find(high), std::string::npos) << text;
  EXPECT_NE(text.find(low), std::string::npos) << text;

  ASSERT_EQ(explorer_->set_view("colour_by", "fold_sign"), std::nullopt);
  text = frame();
  EXPECT_NE(text.find("z > 0"), std::string::npos) << text;
  EXPECT_NE(text.find("z < 0"), std::string::npos) << text;
  EXPECT_EQ(text.find(high), std::string::npos);

  const auto refused = explorer_->set_view("colour_by", "height");
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->find("none, z, fold_sign"), std::string::npos) << *refused;
  EXPECT_EQ(panel<ClothViewPanel>().style().colour_by, ClothStyle::ColourBy::fold_sign);
}

TEST_F(ExplorerTest, ASwatchPhotoBecomesThePrintAndABadFileIsRefusedByName) {
  const auto missing = explorer_->set_view("print_file", (dir_ / "none.png").string());
  ASSERT_TRUE(missing.has_value());
  EXPECT_NE(missing->find("none.png"), std::string::npos) << *missing;
  EXPECT_NE(missing->find("No such file"), std::string::npos) << *missing;
  // A device or a FIFO is named for what it is, not read forever or waited on.
  const auto device = explorer_->set_view("print_file", "/dev/zero");
  ASSERT_TRUE(device.has_value());
  EXPECT_NE(device->find("a character device, not a regular file"), std::string::npos) << *device;
  const fs::path fifo = dir_ / "swatch.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto pipe = explorer_->set_view("print_file", fifo.string());
  ASSERT_TRUE(pipe.has_value());
  EXPECT_NE(pipe->find("a FIFO, not a regular file"), std::string::npos) << *pipe;

  const auto garbage_path = dir_ / "swatch.jpg";
  std::FILE* garbage = std::fopen(garbage_path.c_str(), "wb");
  ASSERT_NE(garbage, nullptr);
  std::fputs("not a picture at all", garbage);
  std::fclose(garbage);
  const auto unreadable = explorer_->set_view("print_file", garbage_path.string());
  ASSERT_TRUE(unreadable.has_value());
  EXPECT_NE(unreadable->find("swatch.jpg"), std::string::npos) << *unreadable;
  EXPECT_NE(unreadable->find("not a PNG or JPEG file"), std::string::npos) << *unreadable;
  EXPECT_EQ(panel<ClothViewPanel>().style().print, ClothStyle::Print::plain);
  EXPECT_TRUE(explorer_->set_view("print", "photo").has_value()) << "no photo loaded yet";

  // A 3 x 2 swatch with a known pixel at each corner: the print holds them top row first.
  const std::vector<std::uint8_t> pixels = {
      255, 0,  0,  255, 0,  255, 0,  255, 0,  0,  255, 255,  //
      10,  20, 30, 255, 40, 50,  60, 255, 70, 80, 90,  255};
  const auto good_path = dir_ / "swatch.png";
  write_png(good_path.c_str(), FrameSize{3, 2}, pixels);
  ASSERT_EQ(explorer_->set_view("print_file", good_path.string()), std::nullopt);
  const ClothStyle& style = panel<ClothViewPanel>().style();
  EXPECT_EQ(style.print, ClothStyle::Print::photo);
  ASSERT_NE(style.photo, nullptr);
  EXPECT_EQ(style.photo->width, 3);
  EXPECT_EQ(style.photo->height, 2);
  EXPECT_EQ(style.photo->rgba, pixels);
  EXPECT_NE(frame().find("photo"), std::string::npos) << "the print combo shows the photo";
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
  const RenderCounters counters = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  for (int i = 0; i < 10; ++i) {
    frame();
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(evaluations(stages[k]), before[k]) << to_string(stages[k]);
  }
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).mesh_uploads,
            counters.mesh_uploads);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).frames,
            counters.frames + 10);

  explorer_->set_input("h", 1500.0);
  frame();
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(evaluations(stages[k]), before[k] + 1) << to_string(stages[k]);
  }
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).mesh_uploads,
            counters.mesh_uploads + 1);
}

// The analysis panels once chose inputs by their index in the input table, which moved when the
// table was reordered (index 3 became nu): Table 1 was swept over nu, the map's x axis was nu.
TEST_F(ExplorerTest, AnalysisPanelsSweepThePapersInputsByKey) {
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "h");
  EXPECT_EQ(panel<AnalysisPanel>().regime_map().x_key(), "h");
  EXPECT_EQ(panel<AnalysisPanel>().regime_map().y_key(), "w");

  ASSERT_EQ(explorer_->set_view("sweep", "table1"), std::nullopt);
  frame();                       // a tab selected now shows from the next frame on
  scroll_panel("analysis", 10);  // to the last plot, which has the x axis's title
  std::string text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "h");
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the sweep's x axis\n" << text;
  // The heights of the paper's Table 1 rows that ship as presets.
  std::vector<double> xs = panel<AnalysisPanel>().sweep().overlay_x();
  std::sort(xs.begin(), xs.end());
  EXPECT_EQ(xs, (std::vector<double>{900.0, 1400.0, 2350.0}));
  EXPECT_EQ(text.find("cannot be swept"), std::string::npos) << text;

  ASSERT_EQ(explorer_->set_view("sweep", "table2"), std::nullopt);
  text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "w");
  xs = panel<AnalysisPanel>().sweep().overlay_x();
  std::sort(xs.begin(), xs.end());
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_DOUBLE_EQ(xs[0], 10e-7);
  EXPECT_DOUBLE_EQ(xs[2], 54e-7);
  // The sweep shows w as its slider does, in g/m²: the range 5e-7..8e-6 N/mm² is
  // 5e-7 / 9.81e-9 = 50.97 to 8e-6 / 9.81e-9 = 815.5 g/m², in its fields and on the axis.
  scroll_panel("analysis", -10);  // back up to the fields
  text = frame();
  EXPECT_TRUE(only_beside_w_slider(text, "N/mm²")) << text;
  EXPECT_TRUE(w_in_e_notation_only_beside_its_slider(text)) << text;
  EXPECT_NE(text.find("50.97 g/m²"), std::string::npos) << "the range's first field\n" << text;
  EXPECT_NE(text.find("815.5 g/m²"), std::string::npos) << "the range's second field\n" << text;
  // The row wraps in the panel rather than push "log" and "steps" past its edge.
  const PanelRect analysis = rect_of("analysis");
  for (const char* label : {"log", "steps"}) {
    EXPECT_LE(position_of(label).x + ImGui::CalcTextSize(label).x,
              analysis.pos.x + analysis.size.x - ImGui::GetStyle().ScrollbarSize)
        << label;
  }
  const PlotView& sweep_view = panel<AnalysisPanel>().sweep().plot_view(0);
  EXPECT_LE(sweep_view.x_lo, 50.97);
  EXPECT_GE(sweep_view.x_hi, 815.5);
  EXPECT_GT(sweep_view.x_lo, 40.0) << "not in N/mm²";
  scroll_panel("analysis", 10);
  text = frame();
  EXPECT_NE(text.find("w (g/m²)"), std::string::npos) << "the sweep's x axis\n" << text;
  EXPECT_TRUE(only_beside_w_slider(text, "N/mm²")) << text;

  open_explorer("map");
  status().set_expert_mode(true);
  frame();
  text = frame();
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the map's x axis\n" << text;
  EXPECT_NE(text.find("w (g/m²)"), std::string::npos) << "the map's y axis";
  EXPECT_TRUE(only_beside_w_slider(text, "N/mm²")) << text;
  EXPECT_TRUE(w_in_e_notation_only_beside_its_slider(text)) << text;
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
    // The symbol as the paper writes it, spelt out in the test's font (ν: "nu").
    const std::string label =
        readable(std::string(input_symbol(*spec)) + " (" + std::string(spec->name) + ")");
    EXPECT_NE(text.find(label), std::string::npos) << label;
  }
}

// Every model setting was shown to a designer who has not met eq. 7.
TEST_F(ExplorerTest, BeginnersSeeTheClothAndExpertsTheModelTooRemembered) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(status().expert_mode()) << "a first start is a beginner's";
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
  EXPECT_EQ(panel<ParametersPanel>().slider_places().count("K"), 0u);
  click(ParametersPanel::kExpertLabel);
  text = frame();
  for (const char* shown : {"nu (Poisson's ratio)", "K (eq. 7", "p (eq. 7", "span rule", "Int[]",
                            "method", "per side", ParametersPanel::kPrintedEq7Label}) {
    EXPECT_NE(text.find(shown), std::string::npos) << shown << "\n" << text;
  }
  open_explorer("equations", {}, session, true);
  EXPECT_TRUE(status().expert_mode()) << "remembered in the session";
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
  ASSERT_EQ(status().modal_title(), "Save as");
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
  const auto& entries = panel<PresetsPanel>().entries();
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

// Typing 650 into d solved d = 6 and d = 65 on the way, each an undo step of its own: a typed
// value is read on Enter or when the field lets go, and Escape drops it.
// Typed text that is no number is said to be so, and the slider keeps its value; simple
// arithmetic is a number, with or without a unit.
TEST_F(ExplorerTest, TypedArithmeticIsAValueAndTypedWordsAreRefusedWithAReason) {
  const auto type_into = [&](const char* key, const std::string& typed) {
    return play(*explorer_,
                {{"steps",
                  {{{"click", key}, {"at", 0.5}, {"ctrl", true}},
                   {{"type", typed}},
                   {{"key", "enter"}},
                   {{"frames", 2}}}}},
                [&] { frame(); });
  };
  ASSERT_EQ(type_into("h", "2*700"), 0);
  EXPECT_EQ(document().edited().hanging.height_mm, 1400.0);
  ASSERT_EQ(type_into("h", "(1000 + 200)/2 cm"), 0);
  EXPECT_DOUBLE_EQ(document().edited().hanging.height_mm, 6000.0);
  ASSERT_EQ(type_into("w", "2*76.5 g/m2"), 0);
  EXPECT_DOUBLE_EQ(document().edited().fabric.weight_N_per_mm2, 153.0 * 9.81e-9);
  const std::size_t steps = document().undo_depth();
  for (const std::string typed : {"heavy", "2*"}) {
    ASSERT_EQ(type_into("w", typed), 0);
    EXPECT_DOUBLE_EQ(document().edited().fabric.weight_N_per_mm2, 153.0 * 9.81e-9) << typed;
    EXPECT_EQ(document().undo_depth(), steps) << typed;
    const std::string message = status().message();
    EXPECT_NE(message.find("\"" + typed + "\" is not a number with a unit (N/mm², g/m², oz/yd²)"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("the value stays 153 g/m²"), std::string::npos) << message;
  }
  // A unit is read in its own case, as on the command line: M is mega, not a metre.
  const double height_mm = document().edited().hanging.height_mm;
  ASSERT_EQ(type_into("h", "2.4M"), 0);
  EXPECT_EQ(document().edited().hanging.height_mm, height_mm);
  EXPECT_NE(status().message().find("height h: \"2.4M\": 'M' is not a unit of length (known: mm, "
                                    "cm, m); did you mean 'm'? The value stays"),
            std::string::npos)
      << status().message();
  ASSERT_EQ(type_into("w", "153 furlongs"), 0);
  EXPECT_NE(status().message().find("'furlongs' is not a unit of weight per area"),
            std::string::npos)
      << status().message();
  ASSERT_EQ(type_into("w", "150 GSM"), 0);
  EXPECT_DOUBLE_EQ(document().edited().fabric.weight_N_per_mm2, 150.0 * 9.81e-9);
}

// Typed text that is no value stays on the slider as typed, reddened, with the reason under the
// sliders, as a refused number does; any new value of the input clears it.
TEST_F(ExplorerTest, TypedTextThatIsNoValueIsKeptAsTypedWithItsReason) {
  const auto type_into_w = [&](const std::string& typed) {
    return play(*explorer_,
                {{"steps",
                  {{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                   {{"type", typed}},
                   {{"key", "enter"}},
                   {{"frames", 2}}}}},
                [&] { frame(); });
  };
  ASSERT_EQ(type_into_w("2*153"), 0);
  EXPECT_DOUBLE_EQ(document().edited().fabric.weight_N_per_mm2, 306.0 * 9.81e-9);
  EXPECT_NE(frame().find("306 g/m²"), std::string::npos) << last_text_;
  ASSERT_EQ(type_into_w("heavy"), 0);
  EXPECT_DOUBLE_EQ(document().edited().fabric.weight_N_per_mm2, 306.0 * 9.81e-9);
  const std::string text = frame();
  const std::string reason =
      "weight per area w: \"heavy\" is not a number with a unit (N/mm², g/m², oz/yd²), nor "
      "arithmetic such as 2*153; the value stays 306 g/m².";
  EXPECT_EQ(panel<ParametersPanel>().unread_reasons().at("w"), reason);
  // On the slider where the value was, and under the sliders (wrapped, so its first words).
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), *foldlab::find_input("w")), "heavy");
  EXPECT_NE(text.find("heavy"), std::string::npos) << text;
  EXPECT_NE(text.find("is not a number"), std::string::npos) << text;
  EXPECT_EQ(document().undo_depth(), 1u);
  // Undo takes w back to its preset value: the text typed for 306 g/m² goes.
  press('Z', true);
  frame();
  EXPECT_TRUE(panel<ParametersPanel>().unread_reasons().empty());
  EXPECT_EQ(frame().find("is not a number"), std::string::npos) << last_text_;
  // A value typed after the text that was none answers it: its reason ("the value stays
  // 153 g/m²") leaves the status line rather than contradict the slider for a minute.
  ASSERT_EQ(type_into_w("heavy"), 0);
  EXPECT_NE(status().message().find("is not a number"), std::string::npos) << status().message();
  ASSERT_EQ(type_into_w("2*153"), 0);
  frame();
  EXPECT_EQ(status().message().find("is not a number"), std::string::npos) << status().message();
  EXPECT_EQ(frame().find("is not a number"), std::string::npos) << last_text_;
}

// A typed value's field holds 32 characters (ImGui's Ctrl+click field, whose editing state ours
// carries on); more keys went nowhere without a word. Full, it says so, until Enter reads it.
TEST_F(ExplorerTest, ATypedValueThatFillsItsFieldSaysSo) {
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", std::string(70, '7')}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_NE(last_text_.find("at most 32 characters"), std::string::npos) << last_text_;
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"key", "enter"}}, {{"frames", 2}}}}}, [&] { frame(); }),
            0);
  EXPECT_EQ(last_text_.find("at most 32 characters"), std::string::npos) << last_text_;
}

// Shift slows a drag to a tenth: the same pixels moved with and without it, measured here, change
// the value (on the slider's own scale) in the ratio 0.1. A linear slider (h) and a log one (w).
TEST_F(ExplorerTest, ShiftDragsAtATenthOfThePlainSpeed) {
  const auto drag = [&](const char* key, double dx, bool shift) {
    return play(*explorer_,
                {{"steps", {{{"drag", key}, {"dx", dx}, {"shift", shift}}, {{"frames", 2}}}}},
                [&] { frame(); });
  };
  const double h0 = document().edited().hanging.height_mm;
  ASSERT_EQ(drag("h", 60.0, false), 0);
  const double plain_mm = document().edited().hanging.height_mm - h0;
  document().reset_to_loaded();
  frame();
  ASSERT_EQ(drag("h", 60.0, true), 0);
  const double fine_mm = document().edited().hanging.height_mm - h0;
  ASSERT_GT(plain_mm, 0.0);
  EXPECT_NEAR(fine_mm / plain_mm, 0.1, 0.005) << plain_mm << " mm plain, " << fine_mm << " fine";
  // Back by the same pixels, still with Shift: where it started, to the pixel's rounding.
  ASSERT_EQ(drag("h", -60.0, true), 0);
  EXPECT_NEAR(document().edited().hanging.height_mm, h0, 0.02 * plain_mm);

  document().reset_to_loaded();
  frame();
  const double w0 = document().edited().fabric.weight_N_per_mm2;
  ASSERT_EQ(drag("w", -50.0, false), 0);
  const double plain_decades = std::log10(document().edited().fabric.weight_N_per_mm2 / w0);
  document().reset_to_loaded();
  frame();
  ASSERT_EQ(drag("w", -50.0, true), 0);
  const double fine_decades = std::log10(document().edited().fabric.weight_N_per_mm2 / w0);
  ASSERT_LT(plain_decades, 0.0);
  EXPECT_NEAR(fine_decades / plain_decades, 0.1, 0.005);
}

// A click on a slider, wherever it lands, takes the focus for the arrow keys and leaves the value:
// a teacher's click "to focus" w, 20 px left of its handle, took w from 108 to 37.8 g/m² in front
// of the class. A drag still moves it from the point pressed.
TEST_F(ExplorerTest, AClickOnASliderFocusesItWithoutChangingTheValue) {
  const double w0 = document().edited().fabric.weight_N_per_mm2;
  for (const double at : {0.0, 0.2, 0.5, 1.0}) {
    ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "w"}, {"at", at}}, {{"frames", 2}}}}},
                   [&] { frame(); }),
              0);
    EXPECT_EQ(document().edited().fabric.weight_N_per_mm2, w0) << at;
    EXPECT_FALSE(document().unsaved()) << at;
  }
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"key", "right"}}, {{"frames", 2}}}}}, [&] { frame(); }),
            0);
  EXPECT_GT(document().edited().fabric.weight_N_per_mm2, w0) << "the click gave the focus";
}

// A beginner's w slider runs from 10.2 to 1000 g/m², an expert's over the whole typical range,
// 10.2 to 10,194 g/m²; a value typed beyond the beginner's slider is still taken.
TEST_F(ExplorerTest, BeginnerSlidersSpanRealFabricsAndTypedValuesGoBeyond) {
  // Dragged past an end, the slider stops at it.
  const auto drag_w = [&](float dx) {
    return play(*explorer_, {{"steps", {{{"drag", "w"}, {"dx", dx}}, {{"frames", 2}}}}},
                [&] { frame(); });
  };
  const double g_per_m2 = 9.81e-9;
  ASSERT_EQ(drag_w(2000.0f), 0);
  EXPECT_NEAR(document().edited().fabric.weight_N_per_mm2 / g_per_m2, 1000.0, 1.0);
  ASSERT_EQ(drag_w(-2000.0f), 0);
  EXPECT_NEAR(document().edited().fabric.weight_N_per_mm2, 1e-7, 1e-10);
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "5000"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_DOUBLE_EQ(document().edited().fabric.weight_N_per_mm2, 5000.0 * g_per_m2);
  EXPECT_TRUE(document().issues().empty());
  EXPECT_EQ(panel<ParametersPanel>().slider_places().at("w").fraction, 1.0);
  status().set_expert_mode(true);
  frame();
  frame();
  ASSERT_EQ(drag_w(2000.0f), 0);
  EXPECT_NEAR(document().edited().fabric.weight_N_per_mm2, 1e-4, 1e-7);
}

// A beginner's Results: n, Q and z_max with their ranges, the fold depths and the regime in one
// line; the solver's own numbers only for experts.
TEST_F(ExplorerTest, BeginnerResultsLeaveOutTheSolversDetail) {
  std::string text = frame();
  for (const char* shown : {"number of wrinkles", "amplitude ratio", "out-of-plane depth",
                            "fold depths a_i", "wrinkled: the cloth hangs in folds"}) {
    EXPECT_NE(text.find(shown), std::string::npos) << shown << "\n" << text;
  }
  for (const char* hidden :
       {"residual eq. 8", "iterations", "solve time", "root of eq. 7", "model: "}) {
    EXPECT_EQ(text.find(hidden), std::string::npos) << hidden << "\n" << text;
  }
  status().set_expert_mode(true);
  frame();
  text = frame();
  for (const char* shown : {"residual eq. 8", "iterations", "root of eq. 7", "model: "}) {
    EXPECT_NE(text.find(shown), std::string::npos) << shown << "\n" << text;
  }
}

TEST_F(ExplorerTest, ATypedValueIsAppliedOnEnterOnlyAsOneStep) {
  // Types into d's field, then ends with `last` (a key or a click); d is unchanged until then.
  const auto type_into_d = [&](const std::string& typed, const nlohmann::json& last) {
    return play(
        *explorer_,
        {{"steps",
          {{{"click", "d"}, {"at", 0.5}, {"ctrl", true}},
           {{"type", typed}},
           {{"expect", {{"parameters.d_mm", document().edited().hanging.support_displacement_mm}}}},
           last,
           {{"frames", 2}}}}},
        [&] { frame(); });
  };
  const std::uint64_t solves = evaluations(Stage::solution);
  ASSERT_EQ(type_into_d("650", {{"key", "enter"}}), 0);
  EXPECT_EQ(document().edited().hanging.support_displacement_mm, 650.0);
  EXPECT_EQ(evaluations(Stage::solution), solves + 1) << "d = 6 or 65 was solved on the way";
  EXPECT_EQ(document().undo_depth(), 1u);

  ASSERT_EQ(type_into_d("300", {{"key", "escape"}}), 0);
  EXPECT_EQ(document().edited().hanging.support_displacement_mm, 650.0);
  EXPECT_EQ(document().undo_depth(), 1u);
  EXPECT_EQ(evaluations(Stage::solution), solves + 1);

  // A click elsewhere takes the text cursor: the value typed so far is applied.
  ASSERT_EQ(type_into_d("250", {{"click", "Results"}}), 0);
  EXPECT_EQ(document().edited().hanging.support_displacement_mm, 250.0);
  EXPECT_EQ(document().undo_depth(), 2u);
  EXPECT_EQ(evaluations(Stage::solution), solves + 2);
  press('Z', true);
  EXPECT_EQ(document().edited().hanging.support_displacement_mm, 650.0);
}

// HOME pointed at a test's temporary folder while it lives, so that "~/" never reaches the real
// home folder.
class HomeFolder {
 public:
  explicit HomeFolder(const fs::path& home) {
    if (const char* old = std::getenv("HOME")) {
      old_ = old;
    }
    ::setenv("HOME", home.c_str(), 1);
  }
  ~HomeFolder() {
    if (old_) {
      ::setenv("HOME", old_->c_str(), 1);
    } else {
      ::unsetenv("HOME");
    }
  }
  HomeFolder(const HomeFolder&) = delete;
  HomeFolder& operator=(const HomeFolder&) = delete;

 private:
  std::optional<std::string> old_;
};

TEST(ExpandHome, ReadsTildeAsTheHomeFolderOnlyAtTheStart) {
  HomeFolder home("/home/someone");
  EXPECT_EQ(expand_home("~"), fs::path("/home/someone"));
  EXPECT_EQ(expand_home("~/"), fs::path("/home/someone"));
  EXPECT_EQ(expand_home("~/photos/a.png"), fs::path("/home/someone/photos/a.png"));
  EXPECT_EQ(expand_home("~other/a.png"), fs::path("~other/a.png"));  // another user's: as typed
  EXPECT_EQ(expand_home("a/~/b.png"), fs::path("a/~/b.png"));
  EXPECT_EQ(expand_home("/tmp/x.png"), fs::path("/tmp/x.png"));
}

TEST(CropPixels, KeepsTheRectangleTopRowFirstAndCutsItToTheFrame) {
  // 4 x 3 pixels, each pixel's red channel its index.
  std::vector<std::uint8_t> rgba;
  for (std::uint8_t i = 0; i < 12; ++i) {
    rgba.insert(rgba.end(), {i, 0, 0, 255});
  }
  std::vector<std::uint8_t> part = rgba;
  const FrameSize kept = crop_pixels(part, FrameSize{4, 3}, 1, 1, 2, 2);
  EXPECT_EQ(kept.width, 2);
  EXPECT_EQ(kept.height, 2);
  ASSERT_EQ(part.size(), 16u);
  EXPECT_EQ((std::vector<int>{part[0], part[4], part[8], part[12]}),
            (std::vector<int>{5, 6, 9, 10}));
  part = rgba;
  const FrameSize cut = crop_pixels(part, FrameSize{4, 3}, 2, -5, 10, 7);
  EXPECT_EQ(cut.width, 2);
  EXPECT_EQ(cut.height, 2);
  EXPECT_EQ((std::vector<int>{part[0], part[4], part[8], part[12]}),
            (std::vector<int>{2, 3, 6, 7}));
}

// Exports went to the working folder with no question, and "Window picture" took the Export
// menu itself into the picture.
// (The test's name holds no "Export": the status line shows the temporary folder, named after it,
// and a click on "Export" must find the menu.)
TEST_F(ExplorerTest, SavingAsksWhereAndAPictureIsTakenAfterTheMenuAndDialogClosed) {
  HomeFolder home(dir_);
  struct Taken {
    PictureRequest request;
    std::string frame_text;
  };
  std::vector<Taken> taken;
  const auto frame_and_take = [&] {
    frame();
    if (std::optional<PictureRequest> request = explorer_->take_screenshot_request()) {
      taken.push_back({*request, last_text_});
    }
  };
  const auto export_as = [&](const std::string& item, const std::string& typed) {
    return play(*explorer_,
                {{"steps",
                  {{{"click", "Export"}},
                   {{"frames", 1}},
                   {{"click", item}},
                   {{"frames", 2}},
                   {{"type", typed}},
                   {{"key", "enter"}},
                   {{"frames", 3}}}}},
                frame_and_take);
  };
  ASSERT_EQ(export_as("Window picture (.png)...", (dir_ / "window.png").string()), 0);
  ASSERT_EQ(taken.size(), 1u);
  EXPECT_EQ(taken[0].request.path, (dir_ / "window.png").string());
  EXPECT_FALSE(taken[0].request.crop.has_value());
  EXPECT_EQ(taken[0].frame_text.find("Window picture"), std::string::npos) << "the menu is shown";
  EXPECT_EQ(taken[0].frame_text.find("Export window picture"), std::string::npos)
      << "the dialog is shown";
  EXPECT_EQ(status().modal_title(), "");

  // "~/" is the home folder, and the extension is added: the 3D view alone, cut from the window.
  ASSERT_EQ(export_as("3D view picture (.png)...", "~/view"), 0);
  ASSERT_EQ(taken.size(), 2u);
  EXPECT_EQ(fs::path(taken[1].request.path), fs::weakly_canonical(dir_) / "view.png");
  ASSERT_TRUE(taken[1].request.crop.has_value());
  const PanelRect view = *taken[1].request.crop;
  for (const auto& [key, rect] : explorer_->layout().panel_rects()) {
    if (key == "cloth") {
      EXPECT_GE(view.pos.x, rect.pos.x);
      EXPECT_GT(view.pos.y, rect.pos.y) << "below the title and the view's settings";
      EXPECT_LE(view.pos.x + view.size.x, rect.pos.x + rect.size.x);
      EXPECT_LE(view.pos.y + view.size.y, rect.pos.y + rect.size.y);
      EXPECT_GT(view.size.x * view.size.y, 0.5f * rect.size.x * rect.size.y);
    }
  }

  // The folder last used is where the next dialog opens; a file there is replaced only when
  // the user says so.
  { std::ofstream(dir_ / "folds.svg") << "old"; }
  ASSERT_EQ(export_as("Fold lines (.svg)...", "folds"), 0);
  EXPECT_EQ(status().modal_title(), "Export fold lines as an SVG drawing");
  EXPECT_EQ(explorer_->file_dialog().folder(), fs::weakly_canonical(dir_));
  EXPECT_NE(last_text_.find("folds.svg is there already: write over it?"), std::string::npos)
      << last_text_;
  const auto read = [](const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(read(dir_ / "folds.svg"), "old");
  const auto& entries = explorer_->file_dialog().entries();
  EXPECT_TRUE(std::any_of(entries.begin(), entries.end(),
                          [](const FileDialog::Entry& e) { return e.name == "folds.svg"; }));
  EXPECT_TRUE(std::none_of(entries.begin(), entries.end(), [](const FileDialog::Entry& e) {
    return e.name == "window.png";
  })) << "an SVG's dialog lists SVG files";
  ASSERT_EQ(
      play(*explorer_, {{"steps", {{{"click", "Replace"}}, {{"frames", 2}}}}}, frame_and_take), 0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_NE(read(dir_ / "folds.svg").find("<svg"), std::string::npos);

  // Another name typed while the question is shown withdraws it: Save then writes the new name
  // and the file asked about is left as it was.
  { std::ofstream(dir_ / "folds.svg") << "old"; }
  ASSERT_EQ(export_as("Fold lines (.svg)...", "folds"), 0);
  ASSERT_TRUE(shows(last_text_, "folds.svg is there already")) << last_text_;
  ASSERT_EQ(
      play(*explorer_, {{"steps", {{{"type", "other-folds"}}, {{"frames", 2}}}}}, frame_and_take),
      0);
  EXPECT_FALSE(shows(last_text_, "is there already")) << last_text_;
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Save"}}, {{"frames", 2}}}}}, frame_and_take),
            0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(read(dir_ / "folds.svg"), "old");
  EXPECT_NE(read(dir_ / "other-folds.svg").find("<svg"), std::string::npos);

  // The name offered is the fabric's and what the file holds; Escape cancels: nothing is written.
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "Export"}},
                    {{"frames", 1}},
                    {{"click", "Fold lines (.csv)..."}},
                    {{"frames", 2}}}}},
                 frame_and_take),
            0);
  EXPECT_TRUE(shows(last_text_, "table-1-h-1400-mm-fold-lines.csv")) << last_text_;
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"key", "escape"}}, {{"frames", 2}}}}}, frame_and_take),
            0);
  EXPECT_EQ(status().modal_title(), "");
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_NE(entry.path().extension(), ".csv") << entry.path();
  }
  EXPECT_EQ(taken.size(), 2u);
}

// A FileTransfer that browses no folders, as the page's: what it delivers and was asked to pick.
class PageLikeTransfer : public FileTransfer {
 public:
  explicit PageLikeTransfer(fs::path outbox) : outbox_(std::move(outbox)) {}
  bool browses_folders() const override { return false; }
  fs::path outbox() const override { return outbox_; }
  bool deliver(const fs::path& path) override {
    std::ifstream in(path, std::ios::binary);
    delivered.emplace_back(path.filename().string(),
                           std::string(std::istreambuf_iterator<char>(in), {}));
    return true;
  }
  void pick(const std::vector<std::string>& extensions) override { asked.push_back(extensions); }
  std::optional<fs::path> take_picked() override { return std::exchange(picked, std::nullopt); }

  std::vector<std::pair<std::string, std::string>> delivered;  // name, bytes
  std::vector<std::vector<std::string>> asked;                 // extensions of each pick
  std::optional<fs::path> picked;                              // the next file the user picks

 private:
  fs::path outbox_;
};

// In the page there is no folder to browse: saving names a file, which is written into the
// outbox and delivered (downloaded) once it is there, a picture a frame later; opening asks the
// picker and takes the copy it brings, through the desktop dialog's own callbacks.
TEST_F(ExplorerTest, WithoutFoldersAFileIsNamedAndDeliveredAndAPickedOneIsOpened) {
  auto owned = std::make_unique<PageLikeTransfer>(dir_ / "outbox");
  PageLikeTransfer& transfer = *owned;
  explorer_->set_file_transfer(std::move(owned));
  std::optional<PictureRequest> picture;
  const auto frame_and_take = [&] {
    frame();
    if (std::optional<PictureRequest> request = explorer_->take_screenshot_request()) {
      picture = request;
    }
  };
  const auto export_as = [&](const std::string& item, const std::string& typed) {
    return play(*explorer_,
                {{"steps",
                  {{{"click", "Export"}},
                   {{"frames", 1}},
                   {{"click", item}},
                   {{"frames", 2}},
                   {{"type", typed}},
                   {{"click", "Download"}},
                   {{"frames", 2}}}}},
                frame_and_take);
  };
  // A name with folders keeps its name alone, and the format's extension is added.
  ASSERT_EQ(export_as("Fold lines (.svg)...", "some/folder/folds"), 0);
  ASSERT_EQ(transfer.delivered.size(), 1u);
  EXPECT_EQ(transfer.delivered[0].first, "folds.svg");
  EXPECT_NE(transfer.delivered[0].second.find("<svg"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "outbox" / "folds.svg")) << "the browser holds its own copy";
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(status().message(), "Downloaded folds.svg (" +
                                    std::to_string(transfer.delivered[0].second.size()) +
                                    " bytes): the browser keeps it with its downloads.");

  // The fabric as a preset, named after the file, which opens as the fabric it was.
  ASSERT_EQ(export_as("Preset (.json)...", "my fabric"), 0);
  ASSERT_EQ(transfer.delivered.size(), 2u);
  EXPECT_EQ(transfer.delivered[1].first, "my fabric.json");
  { std::ofstream(dir_ / "copy.json") << transfer.delivered[1].second; }
  const Preset exported = load_preset(dir_ / "copy.json");
  EXPECT_EQ(exported.name, "my fabric");
  EXPECT_EQ(exported.parameters.hanging.height_mm, 1400.0);  // Table 1's row
  EXPECT_EQ(exported.parameters.fabric.thickness_mm, 0.25);

  // A picture is delivered once the frame loop has written it.
  ASSERT_EQ(export_as("Window picture (.png)...", "window"), 0);
  ASSERT_TRUE(picture.has_value());
  EXPECT_EQ(fs::path(picture->path), dir_ / "outbox" / "window.png");
  EXPECT_EQ(transfer.delivered.size(), 2u) << "not written yet";
  write_png(picture->path.c_str(), FrameSize{2, 1}, {1, 2, 3, 255, 4, 5, 6, 255});
  frame();
  ASSERT_EQ(transfer.delivered.size(), 3u);
  EXPECT_EQ(transfer.delivered[2].first, "window.png");
  EXPECT_EQ(transfer.delivered[2].second.substr(1, 3), "PNG");

  // Opening: the picker is asked for a preset; the copy it brings loads as a listed preset does.
  Preset other = load_preset(kPresetsDir / "paper-table1-h1400.json");
  other.name = "From a colleague";
  other.parameters.hanging.height_mm = 1234.0;
  save_preset(other, dir_ / "uploads-colleague.json");
  click("Open file...");
  EXPECT_EQ(status().modal_title(), PresetsPanel::kOpenFileModal);
  ASSERT_EQ(transfer.asked.size(), 1u);
  EXPECT_EQ(transfer.asked[0], std::vector<std::string>{".json"});
  transfer.picked = dir_ / "uploads-colleague.json";
  frame();
  frame();
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().edited().hanging.height_mm, 1234.0);
  EXPECT_EQ(document().loaded().name, "From a colleague");

  // A file that is no preset is refused in the words a listed one's refusal has; nothing changes.
  { std::ofstream(dir_ / "notes.json") << "these are my notes"; }
  click("Open file...");
  transfer.picked = dir_ / "notes.json";
  frame();
  frame();
  EXPECT_EQ(document().edited().hanging.height_mm, 1234.0);
  EXPECT_EQ(status().message().rfind("Not loaded; the current state is kept.\n", 0), 0u)
      << status().message();
  EXPECT_NE(status().message().find("not valid JSON at line 1"), std::string::npos)
      << status().message();

  // Cancelled: a file picked afterwards is not taken.
  click("Open file...");
  click("Cancel");
  EXPECT_EQ(status().modal_title(), "");
  transfer.picked = dir_ / "uploads-colleague.json";
  frame();
  EXPECT_FALSE(transfer.picked.has_value());
  EXPECT_EQ(status().modal_title(), "");
}

// Where the config folder is the explorer's alone (the page's storage), a session that does not
// read is said so, set aside and replaced; it is left in place on the desktop.
TEST_F(ExplorerTest, AnUnreadableSessionIsSetAsideWhereTheConfigFolderIsTheExplorers) {
  const fs::path session = dir_ / "session.json";
  for (const bool owned : {false, true}) {
    { std::ofstream(session) << "{not a session"; }
    fs::remove(dir_ / "session.json.unread");
    ExplorerOptions options{kPresetsDir, dir_ / "user-presets",     session, "equations",
                            {},          dir_ / "measurements.csv", dir_};
    options.owns_config_folder = owned;
    explorer_.reset();
    explorer_ = std::make_unique<Explorer>(load_preset(kPresetsDir / "paper-table1-h1400.json"),
                                           (kPresetsDir / "paper-table1-h1400.json").string(), true,
                                           options, renderer_);
    frame();
    const std::vector<std::string>& notices = explorer_->notices();
    ASSERT_GE(notices.size(), 2u);
    EXPECT_EQ(notices[0].rfind("the saved session " + session.string() + " could not be read", 0),
              0u)
        << notices[0];
    if (owned) {
      EXPECT_EQ(notices[1], "The session that did not read is kept as " + session.string() +
                                ".unread; a new session is saved in its place.");
    } else {
      EXPECT_NE(notices[1].find("move it away"), std::string::npos) << notices[1];
    }
    explorer_.reset();  // saves the session, where it may
    std::string error;
    bool may_save = true;
    EXPECT_EQ(load_session(session, error, may_save).has_value(), owned) << error;
    EXPECT_EQ(fs::exists(dir_ / "session.json.unread"), owned);
  }
  open_explorer("equations");
}

// "~/" was not read in the 3D view's photo path nor in the fold plot's, and neither had a file
// browser.
TEST_F(ExplorerTest, APhotoIsChosenInTheOpenDialogOrTypedWithTilde) {
  HomeFolder home(dir_);
  fs::create_directories(dir_ / "photos" / "old");
  const std::vector<std::uint8_t> pixels = {255, 0, 0,   255, 0, 255, 0, 255,
                                            0,   0, 255, 255, 9, 9,   9, 255};
  write_png((dir_ / "photos" / "swatch.png").c_str(), FrameSize{2, 2}, pixels);
  { std::ofstream(dir_ / "photos" / "notes.txt") << "not a picture"; }

  // The 3D view's print: typed with "~/".
  click("plain");
  click("photo");
  click("swatch PNG");
  ASSERT_EQ(type_and_enter("~/photos/swatch.png"), 0);
  ASSERT_NE(panel<ClothViewPanel>().style().photo, nullptr);
  EXPECT_EQ(panel<ClothViewPanel>().style().photo->width, 2);

  // Browsed: a folder typed is entered, and only folders and pictures are listed.
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "browse..."}},
                    {{"frames", 2}},
                    {{"expect", {{"modal", "Load swatch photo"}}}},
                    {{"type", "~/photos"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_EQ(explorer_->file_dialog().folder(), fs::weakly_canonical(dir_ / "photos"));
  std::vector<std::string> names;
  for (const FileDialog::Entry& entry : explorer_->file_dialog().entries()) {
    names.push_back(entry.name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"..", "old", "swatch.png"}));
  ASSERT_EQ(
      play(*explorer_, {{"steps", {{{"click", "swatch.png"}}, {{"frames", 1}}}}}, [&] { frame(); }),
      0);
  click("Load");  // the dialog's button, drawn after "Load photo..." in the fold plot
  EXPECT_EQ(status().modal_title(), "");

  // The fold plot's photo: the dialog opens in the folder last used. ("Load photo...", the
  // only "Load" before the dialog opens: the test's font clips the p of its small button.)
  click("Load");
  EXPECT_EQ(status().modal_title(), PhotoOverlay::kLoadModal);
  ASSERT_EQ(type_and_enter("swatch.png"), 0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(fs::path(panel<PhotoOverlay>().photo_file()),
            fs::weakly_canonical(dir_ / "photos") / "swatch.png");

  // Typed with "~/" in the same dialog, from anywhere.
  click("Load");
  ASSERT_EQ(type_and_enter("~/photos/swatch.png"), 0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(fs::path(panel<PhotoOverlay>().photo_file()), dir_ / "photos" / "swatch.png");
}

// A play button sweeps one input while everything re-solves; pause leaves the value.
TEST_F(ExplorerTest, ThePlayButtonSweepsOneInputAndPauseLeavesItAsOneUndoStep) {
  EXPECT_FALSE(explorer_->animating());
  const std::uint64_t solves = evaluations(Stage::solution);
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "play"}}}}}, [&] { frame(); }), 0);
  EXPECT_TRUE(explorer_->animating()) << "the frame loop must keep drawing";
  std::vector<double> heights;
  for (int i = 0; i < 30; ++i) {
    frame();
    heights.push_back(height_mm());
  }
  // h's slider: 100 to 5000 mm, all valid with L = 1400 mm; one way in 4 s, at 60 frames a
  // second 240 frames, so (5000 - 100) / 240 = 20.4 mm a frame.
  for (std::size_t i = 1; i < heights.size(); ++i) {
    // (ImGui's frame time is a float: 1/60 s to 7 digits.)
    EXPECT_NEAR(heights[i] - heights[i - 1], 4900.0 / 240.0, 1e-4) << i;
  }
  EXPECT_GE(evaluations(Stage::solution), solves + 30) << "the results re-solve every frame";
  EXPECT_EQ(document().undo_depth(), 0u) << "one step, closed at pause";
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "pause"}}}}}, [&] { frame(); }), 0);
  EXPECT_FALSE(explorer_->animating());
  const double paused = height_mm();
  EXPECT_GT(paused, heights.back());
  frame();
  frame();
  EXPECT_EQ(height_mm(), paused);
  EXPECT_EQ(shown().hanging.height_mm, paused);
  EXPECT_EQ(document().undo_depth(), 1u);
  press('Z', true);
  EXPECT_EQ(height_mm(), 1400.0);

  // The range fields show their unit; a typed "to" narrows the next play to 100..1500 mm.
  EXPECT_TRUE(shows(frame(), "100 mm to 5000 mm")) << last_text_;
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "5000 mm"}},
                    {{"key", "ctrl+a"}},
                    {{"type", "1500"}},
                    {{"key", "enter"}},
                    {{"frames", 2}},
                    {{"click", "play"}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_TRUE(shows(frame(), "100 mm to 1500 mm")) << last_text_;
  double highest = 0.0;
  // While it plays the views hold their frame: the fold plot's range and the camera's distance
  // only grow, so the class sees the cloth shrink as h goes down.
  double y_span = 0.0;
  float distance = 0.0f;
  // 1400 to 1500 mm and down towards 100 mm again.
  for (int i = 0; i < 3000 && !(highest > 1450.0 && height_mm() < 300.0); ++i) {
    frame();
    highest = std::max(highest, height_mm());
    const PlotView& fold = panel<FoldPlotPanel>().plot_view();
    EXPECT_GE(fold.y_hi - fold.y_lo, y_span) << "at h = " << height_mm() << " mm";
    EXPECT_GE(panel<ClothViewPanel>().camera().distance_mm, distance) << height_mm();
    y_span = fold.y_hi - fold.y_lo;
    distance = panel<ClothViewPanel>().camera().distance_mm;
  }
  EXPECT_LT(height_mm(), 300.0) << "it came back down";
  EXPECT_NEAR(highest, 1500.0, 1400.0 / 240.0 + 1e-6);
  EXPECT_LE(highest, 1500.0);
}

// A class watches the presented cloth while h plays: the Parameters panel that holds the play
// button is out of sight, and the animation goes on all the same.
TEST_F(ExplorerTest, AnAnimationGoesOnWhileAnotherViewIsPresented) {
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "play"}}}}}, [&] { frame(); }), 0);
  for (const char* presented : {"cloth", "fold_plot"}) {
    ASSERT_EQ(explorer_->set_view("present", presented), std::nullopt);
    frame();
    const double before = height_mm();
    for (int i = 0; i < 10; ++i) {
      frame();
    }
    // One way of 4900 mm in 4 s at 60 frames a second: 20.4 mm a frame.
    EXPECT_NEAR(height_mm() - before, 10.0 * 4900.0 / 240.0, 1e-3) << presented;
    EXPECT_EQ(shown().hanging.height_mm, height_mm()) << presented;
  }
}

// Results presented on a wide screen: each value is read beside its name, not across the room.
TEST_F(ExplorerTest, PresentedResultsKeepEachValueBesideItsName) {
  show_at(ImVec2(1920, 1080));
  ASSERT_EQ(explorer_->set_view("present", "results"), std::nullopt);
  frame();
  frame();
  const float name_x = position_of("out-of-plane depth").x;
  const std::string value =
      detail::printf_string("%.2f mm", explorer_->scene().solution().z_max_mm);
  const float value_x = position_of(value).x;
  EXPECT_GT(value_x, name_x);
  // The name is about 18 characters: its value starts within 40 font sizes of it, not at the
  // far edge of a 1920 px window.
  EXPECT_LT(value_x - name_x, 40.0f * ImGui::GetFontSize()) << last_text_;
  // The fold depths likewise: a depth beside its fold's sign.
  const float depth_x = position_of("a_i (mm)").x;
  const float sign_x = position_of("negative").x;
  EXPECT_GT(sign_x, depth_x);
  EXPECT_LT(sign_x - depth_x, 20.0f * ImGui::GetFontSize()) << last_text_;
}

// The introduction for a class: from the menu bar or the View menu, closed by Escape or Close.
TEST_F(ExplorerTest, TheIntroductionOpensFromTheMenuAndClosesWithEscapeOrClose) {
  EXPECT_EQ(frame().find("A cloth hangs"), std::string::npos);
  click(IntroWindow::kTitle);
  EXPECT_TRUE(panel<IntroWindow>().is_open());
  EXPECT_NE(last_text_.find("A cloth hangs"), std::string::npos) << last_text_;
  // What it says of the folds is what the model draws: going up (i = 0 is the lowest fold line,
  // eq. 6), each arch's depth a_i is the one below's over Q.
  EXPECT_NE(squeezed(last_text_).find("eacharchisshallowerthantheonebelowitbythesameratioQ"),
            std::string::npos)
      << last_text_;
  const Solution& s = explorer_->scene().solution();
  ASSERT_GE(s.a_mm.size(), 3u);
  for (std::size_t i = 0; i + 1 < s.a_mm.size(); ++i) {
    EXPECT_NEAR(s.a_mm[i] / s.a_mm[i + 1], s.Q, 1e-9 * s.Q) << i;
  }
  press(kEscape);
  EXPECT_FALSE(panel<IntroWindow>().is_open());
  EXPECT_EQ(frame().find("A cloth hangs"), std::string::npos);

  click("View");
  click(IntroWindow::kTitle);  // the last drawn: the View menu's item
  EXPECT_TRUE(panel<IntroWindow>().is_open());
  EXPECT_NE(frame().find("A cloth hangs"), std::string::npos);
  click("Close");
  EXPECT_FALSE(panel<IntroWindow>().is_open());
  EXPECT_EQ(frame().find("A cloth hangs"), std::string::npos);
}

// The window's loop after input (gui_app.cpp): frames until the frames after input have settled
// and nothing animates, each frame's input noted as the loop notes it.
int frames_until_rest(FramesAfterInput& pacing, Explorer& explorer,
                      const std::function<void()>& frame) {
  int drawn = 0;
  while ((!pacing.settled() || explorer.animating()) && drawn < 100) {
    frame();
    pacing.frame_drawn(frame_saw_input(ImGui::GetIO()));
    ++drawn;
  }
  return drawn;
}

// The introduction's text scrolls in a child window, whose height ImGui knows only from the frame
// before: its first frame shows no scrollbar and the text cut at "Results". Opened by a click
// whose release comes in the last frame after the press, it still gets the frames that bring the
// scrollbar before the window rests.
TEST_F(ExplorerTest, TheIntroductionShowsItsScrollbarBeforeTheWindowRests) {
  ImGuiIO& io = ImGui::GetIO();
  frame();
  const ImVec2 at = position_of(IntroWindow::kTitle);
  FramesAfterInput pacing;
  pacing.woken(true);  // the press woke the window
  io.MousePos = ImVec2(at.x + 3.0f, at.y + 4.0f);
  io.MouseDown[0] = true;
  frame();
  pacing.frame_drawn(frame_saw_input(io));
  frame();
  pacing.frame_drawn(frame_saw_input(io));
  io.MouseDown[0] = false;  // the release, in the third frame after the press
  frame();
  pacing.frame_drawn(frame_saw_input(io));
  ASSERT_TRUE(panel<IntroWindow>().is_open());
  EXPECT_GE(frames_until_rest(pacing, *explorer_, [&] { frame(); }), 2);
  const ImGuiWindow* text = nullptr;
  for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
    if (window->Active &&
        std::string_view(window->Name).find("##intro text") != std::string_view::npos) {
      text = window;
    }
  }
  ASSERT_NE(text, nullptr);
  EXPECT_TRUE(text->ScrollbarY) << "the frame the window rests on shows the scrollbar";
  EXPECT_GT(text->ScrollMax.y, 0.0f);
}

// Ctrl+0 at 150 %: the frame that reads the key is still laid out with the old font, which the
// next frame replaces. The window's loop draws that next frame at once, before it reads more
// input, so that a click made at once lands on the widget drawn where it was made: "play", not
// the "shape" list the new layout put there.
TEST_F(ExplorerTest, AClickRightAfterCtrl0LandsOnTheWidgetDrawnThere) {
  open_explorer("equations", kDejaVuSans);
  ASSERT_EQ(explorer_->set_view("scale", "150"), std::nullopt);
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const ImVec2 hint_at_150 = position_of("(thickness)");
  ImGuiIO& io = ImGui::GetIO();
  io.KeyCtrl = true;
  io.KeysDown['0'] = true;
  frame();
  io.KeyCtrl = false;
  io.KeysDown['0'] = false;
  ASSERT_TRUE(explorer_->layout_pending()) << "the smaller font waits for the next frame";
  EXPECT_EQ(position_of("(thickness)").y, hint_at_150.y) << "this frame shows the old layout";
  int settling = 0;
  while (explorer_->layout_pending() && settling < 5) {
    frame();
    ++settling;
  }
  EXPECT_EQ(settling, 1);
  EXPECT_FALSE(explorer_->layout_pending());
  EXPECT_NE(position_of("(thickness)").y, hint_at_150.y) << "the layout at 100 % moved";
  // A click where the screen now shows "play" (the played click's press comes at once).
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "play"}}}}}, [&] { frame(); }), 0);
  EXPECT_TRUE(explorer_->animating()) << "play was hit";
  EXPECT_FALSE(ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) << "no list was opened";
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "pause"}}}}}, [&] { frame(); }), 0);
}

// Clicking a preset once replaced unsaved edits with no question.
TEST_F(ExplorerTest, APresetClickAsksBeforeReplacingUnsavedEditsAndCancelKeepsThem) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  EXPECT_EQ(status().modal_title(), "Unsaved changes");
  EXPECT_NE(last_text_.find("Discard"), std::string::npos) << last_text_;
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0) << "nothing replaced yet";
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);

  click("Cancel");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm");
  EXPECT_TRUE(document().unsaved());
  EXPECT_EQ(frame().find("Discard"), std::string::npos) << "the dialog is closed";
}

TEST_F(ExplorerTest, EscapeClosesTheUnsavedEditsDialogAndKeepsTheEdits) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  ASSERT_EQ(status().modal_title(), "Unsaved changes");
  press(kEscape);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(frame().find("Discard"), std::string::npos) << "the dialog is closed";
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm");
}

TEST_F(ExplorerTest, DiscardLoadsThePresetClickedAndWithoutEditsNothingIsAsked) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Discard");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Cotton jersey knit");
  EXPECT_TRUE(shown() == cotton().parameters);
  EXPECT_FALSE(document().unsaved());

  click("Fig. 4, h = L = 1400 mm");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Fig. 4, h = L = 1400 mm");
}

// "Save" on a shipped preset asks for a name, writes the user preset, then loads the one clicked.
TEST_F(ExplorerTest, SaveInTheDialogWritesTheEditsThenLoads) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Save");
  EXPECT_EQ(status().modal_title(), "Save as");
  click("Save");
  const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-edited.json";
  ASSERT_TRUE(fs::exists(written)) << last_text_;
  EXPECT_EQ(load_preset(written).parameters.hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Cotton jersey knit");
}

TEST_F(ExplorerTest, ThePapersCaseButtonsAskBeforeReplacingUnsavedEdits) {
  open_explorer("sweep");
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  click("Table 2 (w)");
  EXPECT_EQ(status().modal_title(), "Unsaved changes");
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  click("Discard");
  EXPECT_EQ(document().loaded().name, "Table 2, w = 336 g/m²");
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "w");
}

// With no session to bring them back (--fresh), closing the window lost the edits unasked.
TEST_F(ExplorerTest, ClosingTheWindowAsksWhenEditsWouldBeLost) {
  EXPECT_TRUE(explorer_->may_quit()) << "nothing to lose";
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  EXPECT_FALSE(explorer_->may_quit());
  frame();
  frame();  // a dialog sizes itself on its first frame and shows from the next
  EXPECT_EQ(status().modal_title(), "Unsaved changes");
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
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm");
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
  EXPECT_EQ(status().modal_title(), "Save as") << "a shipped preset is never overwritten";
  click("Save");
  const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-edited.json";
  ASSERT_TRUE(fs::exists(written));
  EXPECT_EQ(status().message(), "Saved to " + written.string());
  EXPECT_NE(frame().find("Saved to"), std::string::npos) << last_text_;
  EXPECT_FALSE(document().unsaved());

  // Now the loaded preset is the user's: Ctrl+S writes over it without asking.
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  press('S', true);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
}

// A preset holds only accepted values: with a refused value on screen neither Ctrl+S nor the
// "Save" of the unsaved-edits question writes the file (which would hold the last valid value
// while the slider shows another), the edits stay and still read as unsaved.
TEST_F(ExplorerTest, RefusedInputsAreNeverSavedAndTheEditsStayUnsaved) {
  const fs::path written = save_h900_as_the_users();
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  ASSERT_EQ(explorer_->set_input("t", -0.5), std::nullopt);  // refused: a thickness is > 0
  ASSERT_FALSE(document().issues().empty());
  EXPECT_TRUE(document().unsaved());
  press('S', true);
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 900.0) << "the file is kept";
  EXPECT_EQ(status().message_kind(), MessageKind::error);
  EXPECT_EQ(status().message().rfind("Not saved: a preset holds only accepted values", 0), 0u)
      << status().message();
  EXPECT_NE(status().message().find("thickness"), std::string::npos) << status().message();

  click("Cotton jersey knit");
  ASSERT_EQ(status().modal_title(), "Unsaved changes");
  click("Save");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm (edited)") << "nothing was loaded";
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 900.0);
  EXPECT_EQ(shown().hanging.height_mm, 950.0);
  EXPECT_EQ(document().edited().fabric.thickness_mm, -0.5);
  EXPECT_TRUE(document().unsaved());
}

// Saving is no step to undo, but a step undone after it compares with the file as saved: the
// state before the save differs from the file now, and reads as unsaved.
TEST_F(ExplorerTest, UndoPastASaveShowsUnsavedEdits) {
  const fs::path written = save_h900_as_the_users();
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  frame();
  press('S', true);
  ASSERT_EQ(load_preset(written).parameters.hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
  press('Z', true);
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  EXPECT_TRUE(document().unsaved()) << "the file holds 950 mm";
  EXPECT_NE(frame().find("Parameters *"), std::string::npos) << last_text_;
  press('Y', true);
  EXPECT_EQ(shown().hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
}

// Two presets of one name in the list cannot be told apart: a shipped preset's name is refused
// and the dialog stays open with the name typed.
TEST_F(ExplorerTest, SaveAsRefusesTheNameOfAShippedPreset) {
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  press('S', true);
  ASSERT_EQ(status().modal_title(), "Save as");
  press('A', true);
  ImGui::GetIO().AddInputCharactersUTF8("cotton POPLIN");
  frame();
  click("Save");
  EXPECT_EQ(status().modal_title(), "Save as");
  EXPECT_EQ(status().message(),
            "\"cotton POPLIN\" is the name of a shipped preset; give yours another name.");
  EXPECT_FALSE(fs::exists(dir_ / "user-presets"));
  frame();
  ImGui::GetIO().AddInputCharactersUTF8(" 2");
  frame();
  click("Save");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_TRUE(fs::exists(dir_ / "user-presets" / "cotton-poplin-2.json")) << last_text_;
}

// The custom size of a picture: a long number typed in width showed -276447231 (ImGui's int
// field wrapped it around) and a message of WxH. Only digits get in, a few of them, and the
// range is said in words.
TEST_F(ExplorerTest, APicturesCustomSizeKeepsTypedDigitsBoundedAndSaysTheRange) {
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "Export"}},
                    {{"frames", 1}},
                    {{"click", "3D view picture, any size (.png)..."}},
                    {{"frames", 2}},
                    {{"click", "custom"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  ASSERT_NE(frame().find("height"), std::string::npos) << last_text_;
  // The width field ends where its label starts: the text cursor goes after "1920".
  const ImVec2 label = position_of("width");
  click_at(ImVec2(label.x - 12.0f, label.y + 4.0f));
  ImGui::GetIO().AddInputCharactersUTF8("abc-99999999999999");
  frame();
  const std::string text = frame();
  // The letters and the sign are kept out, the digits stop at five: 1920 and one 9.
  EXPECT_NE(text.find("19209 width"), std::string::npos) << text;
  EXPECT_NE(text.find("The width must be from 200 to 8192 pixels,"), std::string::npos) << text;
  EXPECT_NE(text.find("not 19209."), std::string::npos) << text;
  EXPECT_EQ(text.find("must be WxH"), std::string::npos) << text;
}

TEST(PictureSize, TypedSidesAreReadWholeAndTheRangeIsSaid) {
  using foldlab::gui::read_typed_picture_size;
  const auto typed = read_typed_picture_size("1600", "900");
  ASSERT_TRUE(typed.size.has_value()) << typed.problem;
  EXPECT_EQ(typed.size->width, 1600);
  EXPECT_EQ(typed.size->height, 900);
  EXPECT_EQ(read_typed_picture_size("99999999999999", "1080").problem,
            "The width must be from 200 to 8192 pixels, not 99999999999999.");
  EXPECT_EQ(read_typed_picture_size("99999999999999999999999", "1080").problem,
            "The width must be from 200 to 8192 pixels, not 99999999999999999999999.");
  EXPECT_EQ(read_typed_picture_size("abc-99999999999999", "0").problem,
            "The width must be a whole number of pixels from 200 to 8192, not "
            "\"abc-99999999999999\". The height must be from 150 to 8192 pixels, not 0.");
  EXPECT_EQ(read_typed_picture_size("", "1080").problem,
            "The width must be a whole number of pixels from 200 to 8192.");
  // Sides within their ranges, but more pixels than a picture may have.
  EXPECT_NE(read_typed_picture_size("8192", "8192").problem.find("33.5 megapixels"),
            std::string::npos);
}

TEST_F(ExplorerTest, NotSavingIsAWarningNotASuccess) {
  press('S', true);
  ASSERT_EQ(status().modal_title(), "Save as");
  press(kEscape);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(status().message(), "Not saved.");
  EXPECT_EQ(status().message_kind(), MessageKind::warning);
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
  status().set_expert_mode(true);  // K, the last slider
  frame();
  const ImVec2 before = position_of("K (");
  EXPECT_EQ(last_text_.find("stale"), std::string::npos);
  ASSERT_EQ(explorer_->set_input("d", 800.0), std::nullopt);
  const std::string text = frame();
  const ImVec2 after = position_of("K (");
  EXPECT_EQ(after.y, before.y);
  EXPECT_NE(text.find("must be below L/2 = 700 mm"), std::string::npos)
      << "the reason is still shown\n"
      << text;
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

// The text colours that read weakly on a light background before (yellow supports, the green
// success tag, amber notes): each at least 4.5:1 against what it is drawn on, in both themes.
TEST(Contrast, TextAndMarkerColoursReadInBothThemes) {
  const struct {
    const char* name;
    const ThemedColour* colour;
  } texts[] = {{"error", &kErrorText},
               {"success", &kOkText},
               {"note", &kNoteText},
               {"dim", &kDimText},
               {"section", &kSectionText}};
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    for (const auto& t : texts) {
      EXPECT_GE(contrast_ratio(t.colour->get(light), window_background(light)), 4.5) << t.name;
    }
    for (const ThemedColour* mark : {&kSupportMarker, &kSweepCurve, &kPaperPoint, &kCurrentValue}) {
      EXPECT_GE(contrast_ratio(mark->get(light), plot_background(light)), 4.5);
    }
  }
  // What the light theme showed before: the dark theme's amber on its 0.94 grey, about 1.6:1.
  EXPECT_LT(contrast_ratio(kNoteText.get(false), window_background(true)), 2.0);
  EXPECT_NEAR(relative_luminance(0.94, 0.94, 0.94), 0.8689, 1e-4);  // ((0.94 + 0.055) / 1.055)^2.4
  EXPECT_NEAR(window_background(true).x, 0.94f, 1e-6);
}

// Marks that are not text need 3:1 (WCAG 1.4.11). On the light theme the 3D view's yellow supports
// on its light grey backdrop were about 1.3:1, and an unchecked checkbox (near-white on the panel's
// grey) had no edge to see.
TEST(Contrast, NonTextMarksReadAtThreeToOneInBothThemes) {
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    const ImGuiStyle style = theme_style(light);
    const ImVec4 window = window_background(light);
    // A checkbox's edge: its outline against the panel, and against the box's own fill.
    const ImVec4 frame = blend_over(style.Colors[ImGuiCol_FrameBg], window);
    const ImVec4 edge =
        style.FrameBorderSize > 0.0f ? blend_over(style.Colors[ImGuiCol_Border], frame) : frame;
    EXPECT_GE(std::max(contrast_ratio(edge, window), contrast_ratio(frame, window)), 3.0);
  }
  // The 3D view's backdrops (ClothViewPanel) and the supports' colour drawn on them.
  const ImVec4 light_backdrop(0.90f, 0.91f, 0.93f, 1.0f);
  const ImVec4 dark_backdrop(0.16f, 0.17f, 0.20f, 1.0f);
  // A slider's handle on its field in the light theme (pale blue on white was 1.7:1 and hard to
  // find on a projector).
  {
    const ImGuiStyle style = theme_style(true);
    const ImVec4 field = blend_over(style.Colors[ImGuiCol_FrameBg], window_background(true));
    EXPECT_GE(contrast_ratio(blend_over(style.Colors[ImGuiCol_SliderGrab], field), field), 3.0);
    EXPECT_GE(contrast_ratio(blend_over(style.Colors[ImGuiCol_SliderGrabActive], field), field),
              3.0);
  }
  EXPECT_GE(contrast_ratio(kSupportMarker.get(true), light_backdrop), 3.0);
  EXPECT_GE(contrast_ratio(kSupportMarker.get(false), dark_backdrop), 3.0);
  // What it was: the dark theme's yellow on the light backdrop.
  EXPECT_LT(contrast_ratio(ImVec4(0.95f, 0.85f, 0.25f, 1.0f), light_backdrop), 1.5);
}

// Every themed colour a user must read, against what it is drawn on, in both themes; and
// ImGui's own hint grey and slider handle, which the themes change.
TEST(Contrast, EveryThemedColourReadsOnWhatItIsDrawnOn) {
  ASSERT_GE(themed_colours().size(), 14u);
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    const ImVec4 window = window_background(light);
    const ImVec4 plot = plot_background(light);
    const ImGuiStyle style = theme_style(light);
    const ImVec4 text = style.Colors[ImGuiCol_Text];
    for (const ThemedColourUse& use : themed_colours()) {
      const ImVec4 colour = use.colour->get(light);
      switch (use.on) {
        case Backdrop::window:
          EXPECT_GE(contrast_ratio(colour, window), 4.5) << use.name;
          break;
        case Backdrop::plot:
          EXPECT_GE(contrast_ratio(colour, plot), 4.5) << use.name;
          break;
        case Backdrop::window_and_plot:
          EXPECT_GE(contrast_ratio(colour, window), 4.5) << use.name;
          EXPECT_GE(contrast_ratio(colour, plot), 4.5) << use.name;
          break;
        case Backdrop::under_text:
          EXPECT_GE(contrast_ratio(text, blend_over(colour, window)), 4.5) << use.name;
          break;
        case Backdrop::under_dim_text:
          EXPECT_GE(contrast_ratio(kDimText.get(light), blend_over(colour, plot)), 4.5) << use.name;
          break;
      }
    }
    // Hints and help markers (ImGui's disabled text) on the window and on a plot.
    EXPECT_GE(contrast_ratio(style.Colors[ImGuiCol_TextDisabled], window), 4.5);
    EXPECT_GE(contrast_ratio(style.Colors[ImGuiCol_TextDisabled], plot), 4.5);
    // A slider's value over its handle: the handle blended over the frame over the window.
    const ImVec4 frame = blend_over(style.Colors[ImGuiCol_FrameBg], window);
    EXPECT_GE(contrast_ratio(text, blend_over(style.Colors[ImGuiCol_SliderGrab], frame)), 4.5);
    EXPECT_GE(contrast_ratio(text, blend_over(style.Colors[ImGuiCol_SliderGrabActive], frame)),
              4.5);
  }
  // What the light theme showed before, by hand: the staircase's orange (255, 120, 60) on the
  // 0.94 grey, L = 0.2126 × 1 + 0.7152 × 0.1878 + 0.0722 × 0.0452 = 0.3502, so
  // (0.8689 + 0.05) / (0.3502 + 0.05) = 2.30; ImGui's hint grey 0.6 (L = 0.3185): 2.49.
  const ImVec4 old_staircase(1.0f, 120 / 255.0f, 60 / 255.0f, 1.0f);
  EXPECT_NEAR(contrast_ratio(old_staircase, window_background(true)), 2.30, 0.01);
  EXPECT_NEAR(contrast_ratio(ImVec4(0.6f, 0.6f, 0.6f, 1.0f), window_background(true)), 2.49, 0.01);
}

// The handle is narrow, so that it covers at most a part of one character of the value: as drawn,
// w's handle (the fill in the handle's colour inside the slider) is narrower than the narrowest
// digit of the value drawn over it, in both themes and at 150 %.
TEST_F(ExplorerTest, ASlidersHandleIsNarrowerThanADigitOfItsValue) {
  for (const char* scale : {"100", "150"}) {
    for (const char* theme : {"dark", "light"}) {
      SCOPED_TRACE(std::string(theme) + " theme at " + scale + " %");
      ASSERT_EQ(explorer_->set_view("scale", scale), std::nullopt);
      ASSERT_EQ(explorer_->set_view("theme", theme), std::nullopt);
      frame();
      frame();
      const SliderPlace place = panel<ParametersPanel>().slider_places().at("w");
      const auto inside = [&](ImVec2 at) {
        return at.x >= place.min.x && at.x <= place.max.x && at.y >= place.min.y &&
               at.y <= place.max.y;
      };
      const ImU32 handle_rgb = ImGui::GetColorU32(ImGuiCol_SliderGrab) & ~IM_COL32_A_MASK;
      float left = 1e9f;
      float right = -1e9f;
      const ImDrawData& data = *ImGui::GetDrawData();
      for (int l = 0; l < data.CmdListsCount; ++l) {
        for (const ImDrawVert& v : data.CmdLists[l]->VtxBuffer) {
          if (inside(v.pos) && (v.col & ~IM_COL32_A_MASK) == handle_rgb) {
            left = std::min(left, v.pos.x);
            right = std::max(right, v.pos.x);
          }
        }
      }
      float narrowest_digit = 1e9f;
      for (std::size_t i = 0; i < last_text_.size(); ++i) {
        if (std::isdigit(static_cast<unsigned char>(last_text_[i])) && inside(last_positions_[i])) {
          narrowest_digit =
              std::min(narrowest_digit, ImGui::GetFont()->FindGlyph(last_text_[i])->AdvanceX);
        }
      }
      ASSERT_LT(left, right) << "no handle drawn in w's slider";
      ASSERT_LT(narrowest_digit, 1e9f) << "no value drawn in w's slider";
      EXPECT_LT(right - left, narrowest_digit);
    }
  }
}

// The paper's symbols where the font has them, their ASCII names where it has not (the built-in
// font of the headless tests): ν on its slider and in K's name, λ in the results.
// The Results panel's model line once read "p = 0." / "5216" at 150 %: ImGui wraps after a '.'.
TEST_F(ExplorerTest, WrappedTextBreaksOnlyAtSpacesSoNoNumberIsCutInTwo) {
  frame();
  const std::string text =
      "model: calibrated on Conci's Tables 1–2 (K = 1.686, p = 0.5216, 6 rows, exact method)";
  // From the widest word's width on: below it a word is cut, as ImGui cuts it.
  float widest_word = 0.0f;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find(' ', at), text.size());
    widest_word = std::max(widest_word, ImGui::CalcTextSize(text.substr(at, end - at).c_str()).x);
    at = end + 1;
  }
  int wraps = 0;
  for (float width = std::ceil(widest_word); width <= 700.0f; width += 1.0f) {
    const std::string wrapped = wrap_at_spaces(text, width);
    std::string joined = wrapped;
    std::replace(joined.begin(), joined.end(), '\n', ' ');
    ASSERT_EQ(joined, text) << "a break other than at a space, at " << width << " px";
    std::size_t start = 0;
    for (std::size_t end = wrapped.find('\n'); start <= wrapped.size();
         end = wrapped.find('\n', start)) {
      const std::string line = wrapped.substr(start, end == std::string::npos ? end : end - start);
      if (line.find(' ') != std::string::npos) {  // a lone word may be wider than the line
        EXPECT_LE(ImGui::CalcTextSize(line.c_str()).x, width) << line;
      }
      // Greedy: the next line's first word did not fit after this one.
      if (end != std::string::npos) {
        const std::size_t next_space = wrapped.find_first_of(" \n", end + 1);
        const std::string next_word = wrapped.substr(end + 1, next_space - end - 1);
        EXPECT_GT(ImGui::CalcTextSize((line + " " + next_word).c_str()).x, width) << line;
        ++wraps;
      }
      if (end == std::string::npos) {
        break;
      }
      start = end + 1;
    }
  }
  EXPECT_GT(wraps, 100);
  // Lines begin with their own spaces (the Equations tab indents its "= value" lines).
  EXPECT_EQ(wrap_at_spaces("  = 0.0012247\n  = 1.5", 1000.0f), "  = 0.0012247\n  = 1.5");
  // A word wider than the line is cut between characters, so that nothing sticks out.
  const float two_digits = ImGui::CalcTextSize("00").x;
  EXPECT_EQ(wrap_at_spaces("0123456789", two_digits), "01\n23\n45\n67\n89");
  // A path is cut after a folder's '/' ("Saved to …/presets/chiffon.js" over "on" was drawn).
  const float path_width = ImGui::CalcTextSize("/tmp/cfg/presets/chif").x;
  EXPECT_EQ(wrap_at_spaces("Saved to /tmp/cfg/presets/chiffon.json", path_width),
            "Saved to\n/tmp/cfg/presets/\nchiffon.json");
}

// A window squeezed below a word's width (a tiling window manager, xdotool, a phone) once made the
// cut of a long word step past its end: each character still gets a line of its own.
TEST_F(ExplorerTest, WrappingIntoNoWidthPutsEachCharacterOnALine) {
  frame();
  for (const float width : {-50.0f, 0.0f, 1.0f}) {
    EXPECT_EQ(wrap_at_spaces("ab c", width), "a\nb\nc") << width;
    EXPECT_EQ(wrap_at_spaces("", width), "") << width;
    EXPECT_EQ(wrap_at_spaces("ν", width), "ν") << width;  // one character: nothing to cut
  }
}

// Every panel, every analysis tab, presented or tiled, with B pinned and the expert's rows, at
// sizes below any useful one and at twice the text size, then back to a laptop's size: nothing
// faults (the sanitizer build checks every access) and the tiles fill the window again.
TEST_F(ExplorerTest, EveryPanelDrawsAtAnySizeDownToOnePixelAndComesBack) {
  for (const std::string tab : {"equations", "method", "sweep", "map"}) {
    open_explorer(tab);
    status().set_expert_mode(true);
    pin_as_b(document(), status());
    std::vector<std::string> presented = {"none"};
    for (const std::unique_ptr<Panel>& panel : explorer_->panels()) {
      if (Layout::tiled(*panel)) {
        presented.push_back(panel->key());
      }
    }
    for (const std::string& present : presented) {
      ASSERT_EQ(explorer_->set_view("present", present), std::nullopt);
      for (const char* scale : {"100", "200"}) {
        ASSERT_EQ(explorer_->set_view("scale", scale), std::nullopt);
        for (const ImVec2 size : {ImVec2(200, 150), ImVec2(60, 40), ImVec2(1, 1)}) {
          show_at(size);
        }
      }
    }
    ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
    ASSERT_EQ(explorer_->set_view("scale", "100"), std::nullopt);
    show_at(ImVec2(1280, 800));
    EXPECT_TRUE(explorer_->layout().fills_window()) << tab;
  }
}

TEST_F(ExplorerTest, GreekShowsWithDejaVuAndSpeltOutWithTheBuiltInFont) {
  status().set_expert_mode(true);
  frame();
  std::string text = frame();
  EXPECT_NE(text.find("nu (Poisson's ratio)"), std::string::npos) << text;
  EXPECT_NE(text.find("K (eq. 7 constant c/(1-nu²))"), std::string::npos) << text;
  EXPECT_EQ(readable("ν σ λ π Σ ∫ −"), "nu sigma lambda pi Sum Int -");

  open_explorer("map", kDejaVuSans);
  status().set_expert_mode(true);
  frame();
  text = frame();
  // (Spaces in DejaVu's proportional text are not told from narrow gaps: compared without.)
  EXPECT_NE(squeezed(text).find("ν(Poisson'sratio)"), std::string::npos) << text;
  EXPECT_NE(squeezed(text).find("K(eq.7constantc/(1-ν²))"), std::string::npos) << text;
  EXPECT_EQ(squeezed(text).find("nu("), std::string::npos) << text;
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  for (const unsigned used : {0x03BDu, 0x03C3u, 0x03BBu, 0x03C0u, 0x03A3u, 0x222Bu, 0x2212u}) {
    EXPECT_NE(font->FindGlyphNoFallback(static_cast<ImWchar>(used)), nullptr) << used;
  }
  EXPECT_EQ(readable("ν σ λ π Σ ∫ −"), "ν σ λ π Σ ∫ −");
}

// The breeze's slider is named with its unit.
TEST_F(ExplorerTest, TheBreezeSliderHasALabelWithItsUnit) {
  EXPECT_EQ(frame().find("sway (mm)"), std::string::npos) << "no breeze, no slider";
  ASSERT_EQ(explorer_->set_view("breeze", "1"), std::nullopt);
  frame();
  EXPECT_NE(frame().find("sway (mm)"), std::string::npos) << last_text_;
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

// A print chosen in the 3D view was kept only if the window closed normally: choosing it did not
// mark the session, so the save a second after a change never came and a killed window lost it.
TEST_F(ExplorerTest, AViewSettingChosenByHandIsOnDiskWithinSecondsAndComesBack) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  frame();
  explorer_->save_session_now();
  ASSERT_EQ(
      nlohmann::json::parse(foldlab::testing::read_file(session))["view"].value("print", -1.0),
      0.0);
  click("plain");
  click("woven checks");
  frame();
  ASSERT_EQ(panel<ClothViewPanel>().style().print, ClothStyle::Print::checks);
  // Two seconds of frames (ImGui's clock), with no save asked for.
  for (int i = 0; i < 120; ++i) {
    frame();
  }
  const nlohmann::json saved = nlohmann::json::parse(foldlab::testing::read_file(session));
  EXPECT_EQ(saved["view"].value("print", -1.0), 1.0) << saved.dump();
  open_explorer("equations", {}, session, true);
  EXPECT_EQ(panel<ClothViewPanel>().style().print, ClothStyle::Print::checks);
}

TEST_F(ExplorerTest, UiScaleIsClampedAndRememberedWithTheTheme) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  EXPECT_EQ(explorer_->appearance().scale_percent(), 100);
  // A script's --view asking for more is refused; a restored or requested scale is clamped.
  EXPECT_TRUE(explorer_->set_view("scale", "400").has_value());
  explorer_->appearance().request(400, false);
  frame();
  EXPECT_EQ(explorer_->appearance().scale_percent(), 250);
  // ImGui's 13 px font rebuilt at 2.5 times its size, not stretched.
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 33.0f);
  EXPECT_FLOAT_EQ(ImGui::GetIO().FontGlobalScale, 1.0f);
  explorer_->appearance().request(20, false);
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

// A session file the explorer could not read as its own (here a link to someone's notes) was
// reported unreadable and then saved over, through the link, on the next change and at exit.
TEST_F(ExplorerTest, ASessionFileThatCannotBeReadIsNeverSavedOver) {
  const fs::path notes = dir_ / "notes.txt";
  const fs::path session = dir_ / "session.json";
  std::ofstream(notes) << "my notes\n";
  fs::create_symlink(notes, session);
  for (const bool restore : {true, false}) {
    SCOPED_TRACE(restore ? "restored" : "a preset asked for");
    open_explorer("equations", {}, session, restore);
    std::size_t said = 0;
    for (const std::string& notice : explorer_->notices()) {
      said += notice.find("session will not be saved") != std::string::npos;
    }
    EXPECT_EQ(said, 1u);
    ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
    frame();
    explorer_->save_session_now();
    explorer_.reset();
    EXPECT_EQ(foldlab::testing::read_file(notes), "my notes\n");
    EXPECT_TRUE(fs::is_symlink(session));
  }
  // A session that reads back is still saved and restored.
  fs::remove(session);
  open_explorer("equations", {}, session);
  ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
  explorer_.reset();
  open_explorer("equations", {}, session, true);
  EXPECT_EQ(document().scene().parameters().hanging.height_mm, 1500.0);
}

// One bad value in a session (d = 1e308 in the fabric being edited) drops that part alone: the
// preset it came from, B and the view's switches are restored, the notices say what was dropped,
// and the file as it was is kept beside it before the next save replaces it.
TEST_F(ExplorerTest, ASessionWithOneBadValueKeepsTheRestAndTheFileAsItWas) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  ASSERT_EQ(explorer_->set_view("wireframe", "1"), std::nullopt);
  ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
  pin_as_b(document(), status());
  explorer_->save_session_now();
  explorer_.reset();
  nlohmann::json j = nlohmann::json::parse(foldlab::testing::read_file(session));
  const double loaded_h = j.at("loaded").at("hanging").at("height_mm").get<double>();
  j["current"]["hanging"]["d_mm"] = 1e308;
  j["view"]["grid_resolution"] = "big";  // one view setting of the wrong type drops it alone
  const std::string broken = j.dump(2);
  std::ofstream(session) << broken;

  open_explorer("equations", {}, session, true);
  std::string notices;
  for (const std::string& notice : explorer_->notices()) {
    notices += notice + "\n";
  }
  EXPECT_NE(notices.find("fabric being edited was not restored"), std::string::npos) << notices;
  EXPECT_NE(notices.find("d_mm"), std::string::npos) << notices;
  EXPECT_NE(notices.find("session.json.unread"), std::string::npos) << notices;
  EXPECT_NE(notices.find("view.grid_resolution must be true, false or a number, not string"),
            std::string::npos)
      << notices;
  EXPECT_TRUE(panel<ClothViewPanel>().style().wireframe) << "the view's switches are the user's";
  EXPECT_TRUE(document().compare().pinned()) << "B is the user's";
  EXPECT_EQ(shown().hanging.height_mm, loaded_h) << "the preset it came from";
  EXPECT_EQ(foldlab::testing::read_file(dir_ / "session.json.unread"), broken);
  explorer_->save_session_now();
  std::string error;
  const std::optional<Session> saved =
      session_from_text(foldlab::testing::read_file(session), "saved", error);
  ASSERT_TRUE(saved.has_value()) << error;
  EXPECT_TRUE(saved->complete);
}

TEST_F(ExplorerTest, ThePapersOverlayBelongsToItsCaseOnly) {
  ASSERT_EQ(explorer_->set_view("sweep", "table2"), std::nullopt);
  frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().overlay_x().size(), 3u) << "Table 2's printed rows";
  explorer_->load_preset_file(kPresetsDir / "paper-table1-h900.json");
  const std::string text = frame();
  EXPECT_TRUE(panel<AnalysisPanel>().sweep().overlay_x().empty());
  EXPECT_EQ(text.find("paper, Table 2"), std::string::npos) << text;
}

// Each frames step is bounded, and so is their sum: 5000 steps of 1000 frames each once ran for
// hours.
TEST(PlayScript, ItsFramesAddUpToAtMostTheCap) {
  nlohmann::json steps = nlohmann::json::array();
  for (int i = 0; i < 100; ++i) {
    steps.push_back({{"frames", 1000}});
  }
  EXPECT_TRUE(play_script_problems({{"steps", steps}}).empty());
  steps.push_back({{"frames", 1}});
  const std::vector<std::string> problems = play_script_problems({{"steps", steps}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("add up to 100001, more than the 100000"), std::string::npos)
      << problems[0];
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
  if (!player.failure().empty()) {
    std::cerr << "play: " << player.failure() << "\n";
  }
  return player.exit_status();
}

TEST_F(ExplorerTest, DraggingTheWSliderFromItsHandleMovesWByItsShareOfTheSlidersDecades) {
  // ImGui 1.86 floats: the theme's 4 px handle inside 2 px of padding, so the handle's centre
  // travels W - 8 px over the beginner's slider: 1e-7 N/mm² (10.2 g/m²) to 1000 g/m², that is
  // log10(1000 x 9.81e-9 / 1e-7) = 1.99 decades.
  const double slider_decades = std::log10(1000.0 * 9.81e-9 / 1e-7);
  const double w0 = explorer_->edited().fabric.weight_N_per_mm2;
  const SliderPlace place = panel<ParametersPanel>().slider_places().at("w");
  ASSERT_EQ(ImGui::GetStyle().GrabMinSize, 4.0f);
  const double travel_px = place.max.x - place.min.x - 8.0;
  for (const double dx : {40.0, -40.0}) {
    explorer_->set_input("w", w0);
    frame();
    ASSERT_EQ(play(*explorer_, {{"steps", {{{"drag", "w"}, {"dx", dx}}}}}, [&] { frame(); }), 0);
    const double decades = std::log10(explorer_->edited().fabric.weight_N_per_mm2 / w0);
    // ImGui floors the mouse position: up to a pixel either way.
    EXPECT_NEAR(decades, slider_decades * dx / travel_px, slider_decades * 1.5 / travel_px)
        << "dx " << dx;
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

// A slider below the edge of a small window cannot be pressed by a person, so a script that drags
// or clicks it fails, saying where it is, rather than pass with the value unchanged.
TEST_F(ExplorerTest, APlayedScriptFailsOnASliderOutOfSight) {
  show_at(ImVec2(400, 300));
  for (const char* step : {"drag", "click"}) {
    SCOPED_TRACE(step);
    InputPlayer player(
        {{"steps",
          {{{"frames", 1}},
           {{"frames", 1}},
           step == std::string("drag") ? nlohmann::json{{"drag", "h"}, {"dx", 50}}
                                       : nlohmann::json{{"click", "h"}, {"at", 0.9}}}}},
        "test script");
    while (player.before_new_frame(ImGui::GetIO(), *explorer_)) {
      frame();
    }
    EXPECT_EQ(player.exit_status(), 1);
    EXPECT_NE(player.failure().find("step 3 "), std::string::npos) << player.failure();
    EXPECT_NE(player.failure().find("the slider h is out of sight"), std::string::npos)
        << player.failure();
    EXPECT_EQ(height_mm(), 1400.0);
  }
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

// The Method tab on Table 1's h = 1400 mm row (paper method). By hand: s = 0.02147 gives
// Q7 = 1.24499; the start a_0/a_n = 101 gives n = Int[log 101 / log Q7] = Int[21.06] = 21 and
// L'/L = 0.92884 (Simpson, 20 intervals), 7.12 % short; the next iterate's L'/L = 1.00229 is
// within 5 %, so the iteration stops at its second iterate.
TEST_F(ExplorerTest, TheMethodTabStepsThroughThePapersIteration) {
  open_explorer("method");
  std::string text = frame();
  EXPECT_NE(text.find("iterate 1 of 2"), std::string::npos) << text;
  EXPECT_NE(text.find("= 101, n = Int[21.06"), std::string::npos) << text;
  // (The test's font draws ′, − and ≤ as "?": the checks read around them.)
  EXPECT_NE(text.find("= 7.12 % > 5 %: iterate again."), std::string::npos) << text;
  EXPECT_NE(text.find("0.9288"), std::string::npos) << "L′/L in the table";
  // a_0 − a_n = 1.01 h − 0.01 h = h: the a-differences alone make h, so eq. 9's root on the first
  // iterate is exactly 0, shown as such (not as a rounded 0.00) and said to come from eq. 9.
  EXPECT_EQ(panel<AnalysisPanel>().method().trace().iterates.front().z_max_mm, 0.0);
  EXPECT_NE(squeezed(text).find(squeezed("so eq. 9 gives z_max = 0 mm.")), std::string::npos)
      << text;
  EXPECT_EQ(text.find("0.00 "), std::string::npos) << text;
  click("Step");
  text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 2);
  EXPECT_NE(text.find("iterate 2 of 2"), std::string::npos) << text;
  EXPECT_NE(text.find("= 0.229 % ? 5 %: stop. This is the answer."), std::string::npos) << text;
  click("Step");  // disabled at the end: nothing moves
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 2);
  click("Back");
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 1);
  click("Run to end");
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 2);
  click("Reset");
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 1);
  EXPECT_EQ(shown().model.method, Method::paper) << "viewing a method edits nothing";
}

// The exact method from the same start, n = 21: eqs. 8 and 9 at n = 21 give
// Int[log(a_0/a_n(21)) / log Q7] = 8, and n = 8 maps to itself.
// The paper method's tolerance was reachable only with --set. Table 2's w = 10e-7 row with a
// tolerance of 1e-5 takes 8 iterates (the same iteration by hand in Python, as play_method_stepper
// checks with --set).
TEST_F(ExplorerTest, TheMethodTabSetsThePaperMethodsToleranceAsOneValidatedStep) {
  open_explorer("method");
  explorer_->load_preset_file(kPresetsDir / "paper-table2-w10.json");
  frame();
  frame();
  const int iterates_at_5_percent = panel<AnalysisPanel>().method().iterates();
  const std::size_t depth = document().undo_depth();  // the preset load is a step
  const std::string text = frame();
  const ImVec2 field = last_positions_[text.find("0.05", text.find("stop when"))];
  click_at(ImVec2(field.x + 3.0f, field.y + 4.0f));
  ASSERT_EQ(type_and_enter("1e-5"), 0);
  EXPECT_EQ(explorer_->edited().model.length_tolerance, 1e-5);
  EXPECT_EQ(panel<AnalysisPanel>().method().iterates(), 8);
  EXPECT_EQ(document().undo_depth(), depth + 1);

  // Beyond 0.5 the tolerance is refused with its reason, the scene keeps the last valid one.
  click_at(ImVec2(field.x + 3.0f, field.y + 4.0f));
  ASSERT_EQ(type_and_enter("0.9"), 0);
  EXPECT_EQ(explorer_->edited().model.length_tolerance, 0.9);
  EXPECT_EQ(shown().model.length_tolerance, 1e-5);
  EXPECT_NE(last_text_.find("length_tolerance"), std::string::npos) << last_text_;
  press('Z', true);
  press('Z', true);
  EXPECT_EQ(shown().model.length_tolerance, 0.05);
  frame();
  EXPECT_EQ(panel<AnalysisPanel>().method().iterates(), iterates_at_5_percent);
}

TEST_F(ExplorerTest, TheMethodTabShowsTheExactMethodsStaircaseToItsFixedPoint) {
  open_explorer("method");
  click("exact method");
  std::string text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().method().method(), Method::exact);
  EXPECT_EQ(shown().model.method, Method::paper);
  EXPECT_NE(text.find("n = 21:"), std::string::npos) << text;
  EXPECT_NE(text.find("= Int[8.18"), std::string::npos) << text;
  EXPECT_NE(text.find("] = 8 is the next"), std::string::npos) << text;
  EXPECT_NE(text.find("n 21 ? 8: iterate again."), std::string::npos) << text;
  click("Run to end");
  text = frame();
  EXPECT_NE(text.find("n = 8 maps to itself: the fixed point."), std::string::npos) << text;
  EXPECT_EQ(panel<AnalysisPanel>().method().trace().solution.n, 8);
}

// At t = 0.9 mm, Table 1's cloth is stiff (s >= 1) below h = K E t³ / (w l²) =
// 29.56 × 165 × 0.9³ / (1.5e-6 × 1300²) = 1402.6 mm (by hand). The sweep over h shows that
// stretch as a named band, and Q's curve holds no single-fold value (a_0/a_1 = 101) there.
TEST_F(ExplorerTest, TheSweepShowsAStiffStretchAsABandNotASpike) {
  open_explorer("sweep");
  ASSERT_EQ(explorer_->set_input("t", 0.9), std::nullopt);
  frame();
  const std::string text = frame();
  const SweepPanel& sweep_panel = panel<AnalysisPanel>().sweep();
  ASSERT_EQ(sweep_panel.key(), "h");
  ASSERT_FALSE(sweep_panel.bands().empty());
  const RegimeBand& stiff = sweep_panel.bands().front();
  EXPECT_EQ(stiff.name, "stiff");
  EXPECT_DOUBLE_EQ(stiff.from, 500.0);
  EXPECT_NEAR(stiff.to, 1402.6, 2500.0 / 199.0);  // within one step of the sweep
  EXPECT_NE(text.find("stiff"), std::string::npos) << "the band's name is drawn\n" << text;
  // A key above the plots says what each shade is: a band one sample wide has no room for its
  // name.
  EXPECT_NE(squeezed(text).find(
                squeezed(std::string("stiff: ") + std::string(regime_info(Regime::stiff).plain))),
            std::string::npos)
      << text;
  // The largest Q with two or more folds, from the same sweep solved here.
  double wrinkled_max_Q = 0.0;
  double stiff_max_Q = 0.0;
  for (const SweepPoint& p : sweep(shown(), SweepAxis{"h", 500.0, 3000.0, 200, false})) {
    if (p.regime == Regime::wrinkled && p.n >= 2) {
      wrinkled_max_Q = std::max(wrinkled_max_Q, p.Q);
    } else if (p.regime == Regime::stiff) {
      stiff_max_Q = std::max(stiff_max_Q, p.Q);
    }
  }
  EXPECT_NEAR(stiff_max_Q, 101.0, 1e-9) << "the spike the Q curve used to show";
  ASSERT_GT(wrinkled_max_Q, 1.0);
  for (double Q : sweep_panel.curves().Q) {
    EXPECT_TRUE(std::isnan(Q) || Q <= wrinkled_max_Q) << Q;
  }
  // The three plots share the sweep's x range, so that the current value lines up in all three:
  // the Q plot, with no Q over the stiff band, once fitted its own. (The z_max plot is below
  // the panel's fold, not drawn.)
  for (int which = 0; which < 2; ++which) {
    EXPECT_LE(sweep_panel.plot_view(which).x_lo, 500.0) << which;
    EXPECT_GE(sweep_panel.plot_view(which).x_hi, 3000.0) << which;
    EXPECT_EQ(sweep_panel.plot_view(which).x_lo, sweep_panel.plot_view(0).x_lo) << which;
    EXPECT_EQ(sweep_panel.plot_view(which).x_hi, sweep_panel.plot_view(0).x_hi) << which;
  }
  // And their data areas start at one x: n's short tick labels ("2") left n's area 4 px left of
  // Q's ("1.25"), so the same value sat 4 px apart, as seen in the window.
  frame();
  const PlotView& n_view = sweep_panel.plot_view(0);
  const PlotView& Q_view = sweep_panel.plot_view(1);
  EXPECT_EQ(n_view.min.x, Q_view.min.x);
  EXPECT_EQ(n_view.max.x, Q_view.max.x);
}

// The paper's Table 1 beside the model: the printed n, Q, z_max of each row and the model's at
// the same h (the paper's form of eq. 7 in these presets gives n = 5, 8, 14).
TEST_F(ExplorerTest, TheSweepListsThePapersTableBesideTheModel) {
  ASSERT_EQ(explorer_->set_view("sweep", "table1"), std::nullopt);
  frame();
  frame();
  click("Paper vs model (table)");
  const std::string text = frame();
  for (const char* printed :
       {"n paper", "n model", "1.31", "1.29", "1.34", "54 mm", "48 mm", "60 mm"}) {
    EXPECT_NE(text.find(printed), std::string::npos) << printed << "\n" << text;
  }
  EXPECT_NE(text.find("43.4 mm"), std::string::npos) << "the model's z_max at h = 1400\n" << text;
}

// The 3D view's picture is kept while what it shows is unchanged: each of its inputs, changed
// alone, makes the next call draw again, and an unchanged call after it draws nothing.
TEST(ClothViewCacheTest, DrawsAgainExactlyWhenSceneCameraSizeOrStyleChange) {
  Scene scene(load_preset(kPresetsDir / "paper-table1-h1400.json").parameters);
  OrbitCamera camera;
  FrameSize size{400, 300};
  ClothStyle style;
  ClothViewCache cache;
  RenderCounters counters;
  const auto draws = [&] {
    return !cache.reuse(cloth_buffers(scene, style), camera, size, style, counters);
  };
  EXPECT_TRUE(draws()) << "nothing drawn yet";
  EXPECT_FALSE(draws());
  EXPECT_FALSE(draws());
  const std::vector<std::pair<const char*, std::function<void()>>> changes = {
      {"camera orbit", [&] { camera.orbit(5.0f, 0.0f); }},
      {"camera zoom", [&] { camera.zoom(1.0f); }},
      {"view size", [&] { size.height = 301; }},
      {"print", [&] { style.print = ClothStyle::Print::checks; }},
      {"z exaggeration", [&] { style.z_exaggeration = 4.0f; }},
      {"breeze time", [&] { style.time_s = 0.5f; }},
      {"background", [&] { style.background.x() = 0.5f; }},
      {"fold lines hidden", [&] { style.fold_lines = false; }},
      {"h",
       [&] {
         Parameters p = scene.parameters();
         p.hanging.height_mm = 1500.0;
         scene.set_parameters(p);
       }},
      {"grid resolution", [&] { scene.set_grid_resolution(64, 64); }},
  };
  for (const auto& [what, change] : changes) {
    change();
    EXPECT_TRUE(draws()) << what;
    EXPECT_FALSE(draws()) << what;
  }
  EXPECT_EQ(counters.view_renders, 1 + changes.size());
  EXPECT_EQ(counters.view_cache_hits, 2 + changes.size());
  cache.forget();
  EXPECT_TRUE(draws());
}

TEST_F(ExplorerTest, TheThreeDViewIsDrawnAgainOnlyWhenWhatItShowsChanges) {
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const RenderCounters before = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  for (int i = 0; i < 5; ++i) {
    frame();
  }
  RenderCounters now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  EXPECT_EQ(now.frames, before.frames + 5);
  EXPECT_EQ(now.view_renders, before.view_renders) << "idle frames show the kept picture";
  EXPECT_EQ(now.view_cache_hits, before.view_cache_hits + 5);

  explorer_->set_input("h", 1500.0);
  frame();
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_renders,
            now.view_renders + 1)
      << "a new h";

  now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  ASSERT_EQ(explorer_->set_view("z_exaggeration", "4"), std::nullopt);
  frame();
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_renders,
            now.view_renders + 1)
      << "z x4";

  // An orbit: a drag across the middle of the view (the panel's top right of the window).
  now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  const std::uint64_t solves = evaluations(Stage::solution);
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(1060.0f, 300.0f);
  frame();
  io.MouseDown[0] = true;
  frame();
  io.MousePos = ImVec2(1100.0f, 300.0f);
  frame();
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_EQ(evaluations(Stage::solution), solves) << "the drag moved the camera, not an input";
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_renders,
            now.view_renders + 1)
      << "camera moved";
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_cache_hits,
            now.view_cache_hits + 4);
}

TEST_F(ExplorerTest, TheGridViewSettingTakesTheSlidersWholeNumbersOnly) {
  ASSERT_EQ(explorer_->set_view("grid", "512"), std::nullopt);
  EXPECT_EQ(explorer_->scene().grid_nx(), 512);
  EXPECT_EQ(explorer_->scene().grid_ny(), 512);
  ASSERT_EQ(explorer_->set_view("grid", "8"), std::nullopt);
  EXPECT_EQ(explorer_->scene().grid_nx(), 8);
  for (const char* refused : {"7", "513", "64.5", "many", "nan"}) {
    const std::optional<std::string> problem = explorer_->set_view("grid", refused);
    ASSERT_TRUE(problem.has_value()) << refused;
    EXPECT_NE(problem->find("from 8 to 512"), std::string::npos) << *problem;
  }
  EXPECT_EQ(explorer_->scene().grid_nx(), 8) << "a refused value changes nothing";
}

// Every tiled panel, as the test reads it: ImGui's own window rectangles.
using Rects = std::vector<std::pair<std::string, PanelRect>>;

// The panels cover the display below the menu bar exactly: inside it, no two overlapping, and
// their areas summing to the whole, so there is neither a gap nor a margin.
void expect_tiles_fill(const Rects& rects, ImVec2 display, float menu_height) {
  ASSERT_EQ(rects.size(), 6u);
  double area = 0.0;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const PanelRect& a = rects[i].second;
    SCOPED_TRACE(rects[i].first);
    EXPECT_GE(a.pos.x, 0.0f);
    EXPECT_GE(a.pos.y, menu_height);
    EXPECT_LE(a.pos.x + a.size.x, display.x);
    EXPECT_LE(a.pos.y + a.size.y, display.y);
    area += static_cast<double>(a.size.x) * a.size.y;
    for (std::size_t j = i + 1; j < rects.size(); ++j) {
      const PanelRect& b = rects[j].second;
      const bool apart = a.pos.x + a.size.x <= b.pos.x || b.pos.x + b.size.x <= a.pos.x ||
                         a.pos.y + a.size.y <= b.pos.y || b.pos.y + b.size.y <= a.pos.y;
      EXPECT_TRUE(apart) << "overlaps " << rects[j].first;
    }
  }
  EXPECT_DOUBLE_EQ(area, static_cast<double>(display.x) * (display.y - menu_height));
}

TEST_F(ExplorerTest, PanelsRefitTheWindowAsItGrowsAndShrinks) {
  ImGuiIO& io = ImGui::GetIO();
  const float menu_height = ImGui::GetFrameHeight();  // the main menu bar: one frame high
  for (const ImVec2 size : {ImVec2(1024, 640), ImVec2(1920, 1080), ImVec2(1280, 800),
                            ImVec2(2560, 1440), ImVec2(1024, 640)}) {
    SCOPED_TRACE(::testing::Message() << size.x << "x" << size.y);
    io.DisplaySize = size;
    frame();
    frame();
    EXPECT_TRUE(explorer_->layout().automatic());
    expect_tiles_fill(explorer_->layout().panel_rects(), size, menu_height);
  }
}

// Widths in font sizes: the parameters column is 25 font sizes at 1024 px; at 200 % it would be
// twice as wide but stops at 40 % of the window, and the whole window is still tiled.
TEST_F(ExplorerTest, TheLayoutsWidthsFollowTheUiScale) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(1024, 640);
  frame();
  const auto width_of = [this](const std::string& name) {
    for (const auto& [n, r] : explorer_->layout().panel_rects()) {
      if (n == name) {
        return r.size.x;
      }
    }
    ADD_FAILURE() << name;
    return 0.0f;
  };
  EXPECT_FLOAT_EQ(width_of("parameters"), 25.0f * 13.0f);  // ProggyClean: 13 px
  ASSERT_EQ(explorer_->set_view("scale", "200"), std::nullopt);
  frame();
  frame();
  EXPECT_FLOAT_EQ(ImGui::GetFontSize(), 26.0f);
  // 25 font sizes would be 650 px: the column stops at 40 % of the window, 409 px (short of the
  // 20 font sizes that hold the longest label with a short slider), so that the views keep the
  // rest.
  EXPECT_FLOAT_EQ(width_of("parameters"), std::floor(0.40f * 1024.0f));
  expect_tiles_fill(explorer_->layout().panel_rects(), io.DisplaySize, ImGui::GetFrameHeight());
  io.DisplaySize = ImVec2(2560, 1440);
  frame();
  frame();
  // 30 % of 2560 px is 768 px, between 25 and 40 font sizes (650 and 1040 px).
  EXPECT_FLOAT_EQ(width_of("parameters"), 768.0f);
}

// A large UI scale in a small window: the fold plot keeps a data area of several font sizes (the
// panel scrolls) instead of drawing its axis labels and legend over a sliver.
TEST_F(ExplorerTest, TheFoldPlotKeepsItsSizeAtALargeUiScale) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(1280, 800);
  ASSERT_EQ(explorer_->set_view("scale", "250"), std::nullopt);
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const PlotView& view = panel<FoldPlotPanel>().plot_view();
  EXPECT_GT(view.max.y - view.min.y, 5.0f * ImGui::GetFontSize());
  EXPECT_GE(view.legend_min.y, view.max.y);  // the legend below the data, not over it
}

// At 200 % the views keep their share of the window: the fold plot's data and the 3D panel are
// each a sizeable part of it, on a laptop and on a projector's 1920 x 1080.
TEST_F(ExplorerTest, AtTwiceTheTextSizeThePlotsKeepTheirShareOfTheWindow) {
  open_explorer("equations", kDejaVuSans);
  ASSERT_EQ(explorer_->set_view("scale", "200"), std::nullopt);
  for (const ImVec2 size : {ImVec2(1280, 800), ImVec2(1920, 1080)}) {
    SCOPED_TRACE(::testing::Message() << size.x << "x" << size.y);
    show_at(size);
    const double window = static_cast<double>(size.x) * size.y;
    const PlotView& plot = panel<FoldPlotPanel>().plot_view();
    const double plot_share = (plot.max.x - plot.min.x) * (plot.max.y - plot.min.y) / window;
    const PanelRect cloth = rect_of("cloth");
    const double cloth_share = static_cast<double>(cloth.size.x) * cloth.size.y / window;
    EXPECT_GT(plot_share, 0.03) << "the fold plot's data";
    EXPECT_GT(cloth_share, 0.175) << "the 3D view's panel";
    EXPECT_TRUE(explorer_->layout().fills_window());
  }
}

// No number in Results or in the Method tab's table is cut off, from 100 % to 200 % and from
// 1024 x 640 to 1920 x 1080: the columns are as wide as their text, the names wrap, and a range
// goes under its value when the panel is narrow.
TEST_F(ExplorerTest, ResultsAndTheMethodTableCutNoTextAtAnyScaleOrSize) {
  open_explorer("method", kDejaVuSans);
  explorer_->load_preset_file(kPresetsDir / "default.json");  // a preset with ranges
  const Solution& s = explorer_->scene().solution();
  const PredictionRange range =
      *model_standing(explorer_->scene().parameters(), document().loaded().calibration).range;
  const std::string z_max = detail::printf_string("%.2f", s.z_max_mm);
  const std::string z_range =
      detail::printf_string("(%.1f–%.1f)", range.z_max_min_mm, range.z_max_max_mm);
  ImGuiIO& io = ImGui::GetIO();
  for (const char* scale : {"100", "150", "200"}) {
    for (const ImVec2 size : {ImVec2(1024, 640), ImVec2(1280, 800), ImVec2(1920, 1080)}) {
      SCOPED_TRACE(::testing::Message() << scale << " % at " << size.x << "x" << size.y);
      if (size.x == 1024.0f && std::string(scale) == "200") {
        continue;  // Results is a few lines high there: present it instead
      }
      ASSERT_EQ(explorer_->set_view("scale", scale), std::nullopt);
      io.DisplaySize = size;
      for (int i = 0; i < 3; ++i) {
        frame();
      }
      for (const char* panel : {"results", "analysis"}) {
        const PanelRect r = rect_of(panel);
        const ImVec2 max(r.pos.x + r.size.x, r.pos.y + r.size.y);
        const std::vector<std::string> cut = cut_glyphs(r.pos, max);
        EXPECT_TRUE(cut.empty()) << panel << ": " << cut.size() << " glyphs cut, first "
                                 << (cut.empty() ? "" : cut.front());
      }
      // No header or tab shortened; the z_max row whole once Results scrolls to it.
      EXPECT_EQ(last_text_.find("…"), std::string::npos) << "shortened\n" << last_text_;
      bool z_shown = false;
      for (int scroll = 0; scroll < 8 && !z_shown; ++scroll) {
        std::string text = last_text_;
        std::erase(text, ' ');
        z_shown = text.find(z_max) != std::string::npos && text.find(z_range) != std::string::npos;
        const PanelRect r = rect_of("results");
        const std::vector<std::string> cut =
            cut_glyphs(r.pos, ImVec2(r.pos.x + r.size.x, r.pos.y + r.size.y));
        EXPECT_TRUE(cut.empty()) << "results: " << cut.size() << " glyphs cut, first "
                                 << (cut.empty() ? "" : cut.front());
        scroll_panel("results", 1);
      }
      EXPECT_TRUE(z_shown) << z_max << " " << z_range << "\n" << last_text_;
      scroll_panel("results", -8);
    }
  }
}

// The Equations tab at twice the text size and in a 1024 x 640 window: every equation wraps
// before an operator instead of running past the panel, so that each number is drawn whole
// (ImGui leaves out a glyph wholly past a clip edge: a cut line loses its last numbers).
TEST_F(ExplorerTest, TheEquationsCutNoNumberAtTwiceTheTextSizeOrInASmallWindow) {
  open_explorer("equations", kDejaVuSans);
  explorer_->load_preset_file(kPresetsDir / "default.json");  // calibrated: s^p, p != 1
  const Solution& s = explorer_->scene().solution();
  const double p = explorer_->scene().parameters().model.stress_exponent_p;
  ASSERT_NE(p, 1.0);
  ASSERT_TRUE(s.Q7.has_value());
  // As the tab writes them: what a reader must see whole, spaces and line breaks aside.
  const std::string s_power =
      detail::printf_string("s^p=%.5g^%.3g=%.5g", s.stress_ratio, p, std::pow(s.stress_ratio, p));
  const std::string q7 = detail::printf_string("->Q7=%.5f", *s.Q7);
  const std::string h_line = detail::printf_string("h=%.1fmm", 1400.0);
  const std::string q = detail::printf_string("Q=(a_0/a_n)^(1/n)=%.4f", s.Q);
  // At 200 % a 1024 x 640 window leaves the tiled panel a few lines high: there it is presented.
  struct Case {
    const char* scale;
    ImVec2 size;
    const char* present;
  };
  for (const Case c :
       {Case{"100", ImVec2(1024, 640), "none"}, Case{"150", ImVec2(1024, 640), "none"},
        Case{"200", ImVec2(1024, 640), "analysis"}, Case{"200", ImVec2(1280, 800), "none"},
        Case{"200", ImVec2(1920, 1080), "none"}}) {
    SCOPED_TRACE(::testing::Message() << c.scale << " % at " << c.size.x << "x" << c.size.y
                                      << ", presented: " << c.present);
    ASSERT_EQ(explorer_->set_view("present", c.present), std::nullopt);
    ASSERT_EQ(explorer_->set_view("scale", c.scale), std::nullopt);
    show_at(c.size);
    // The wheel over the equations (the tab's own child window scrolls, not the panel).
    const auto turn_wheel = [&](float notches) {
      const PanelRect r = rect_of("analysis");
      ImGuiIO& io = ImGui::GetIO();
      io.MousePos = ImVec2(r.pos.x + 0.5f * r.size.x, r.pos.y + 0.75f * r.size.y);
      io.MouseWheel = notches;
      frame();
      io.MouseWheel = 0.0f;
      frame();
    };
    turn_wheel(50.0f);
    bool seen[4] = {};
    const std::string wanted[4] = {s_power, q7, h_line, q};
    for (int scroll = 0; scroll < 30; ++scroll) {
      const PanelRect r = rect_of("analysis");
      const std::vector<std::string> cut =
          cut_glyphs(r.pos, ImVec2(r.pos.x + r.size.x, r.pos.y + r.size.y));
      EXPECT_TRUE(cut.empty()) << cut.size() << " glyphs cut, first "
                               << (cut.empty() ? "" : cut.front());
      const std::string text = squeezed(last_text_);
      for (int i = 0; i < 4; ++i) {
        seen[i] = seen[i] || text.find(wanted[i]) != std::string::npos;
      }
      turn_wheel(-1.0f);
    }
    for (int i = 0; i < 4; ++i) {
      EXPECT_TRUE(seen[i]) << wanted[i] << " never drawn whole\n" << last_text_;
    }
  }
}

// An equation breaks before "=" first, then before an arithmetic operator, then at a space; a
// line after a break is indented.
TEST_F(ExplorerTest, AnEquationWrapsBeforeItsOperators) {
  frame();
  const auto width = [](const char* text) { return ImGui::CalcTextSize(text).x; };
  EXPECT_EQ(wrap_equation("s^p = 0.0012247^0.522 = 0.030123", 1000.0f),
            "s^p = 0.0012247^0.522 = 0.030123");
  EXPECT_EQ(wrap_equation("s^p = 0.0012247^0.522 = 0.030123", width("s^p = 0.0012247^0.522")),
            "s^p = 0.0012247^0.522\n    = 0.030123");
  EXPECT_EQ(wrap_equation("a = 12 × 345 / 6789 = 2", width("    = 12 × 345")),
            "a\n    = 12 × 345\n    / 6789\n    = 2");
  // The leading spaces of a "  = value" line are its own, not a place to break.
  EXPECT_EQ(wrap_equation("  = 1.25", 1000.0f), "  = 1.25");
  // No operator left: at spaces, never inside a number.
  EXPECT_EQ(wrap_equation("check 0.0012247 0.522", width("    0.0012247")),
            "check\n    0.0012247\n    0.522");
}

// Each of the Sweep tab's three plots keeps a data area of a few lines at 150 % in a small
// window: the panel scrolls instead of squeezing a plot to a few pixels.
TEST_F(ExplorerTest, EachSweepPlotKeepsItsHeightAtALargeUiScale) {
  open_explorer("sweep", kDejaVuSans);
  ASSERT_EQ(explorer_->set_view("scale", "150"), std::nullopt);
  for (const ImVec2 size : {ImVec2(1280, 800), ImVec2(1024, 640)}) {
    SCOPED_TRACE(::testing::Message() << size.x << "x" << size.y);
    show_at(size);
    // The panel scrolls (the wheel over its tabs, not over a plot, which it would zoom) to show
    // each plot in turn.
    const PanelRect analysis = rect_of("analysis");
    bool seen[3] = {};
    for (int scroll = 0; scroll < 12; ++scroll) {
      for (int which = 0; which < 3; ++which) {
        const PlotView& view = panel<AnalysisPanel>().sweep().plot_view(which);
        if (view.max.y > analysis.pos.y && view.min.y < analysis.pos.y + analysis.size.y) {
          seen[which] = true;
          EXPECT_GE(view.max.y - view.min.y, 3.0f * ImGui::GetFontSize()) << "plot " << which;
        }
      }
      scroll_panel("analysis", 1);
    }
    EXPECT_TRUE(seen[0] && seen[1] && seen[2]);
  }
}

// The button at the right of a panel's title fills the window with that panel under a large
// read-out of n, Q and z_max; Escape (or the menu bar's button) brings the tiles back. A
// double-click on a title does the same as the button.
TEST_F(ExplorerTest, APanelIsPresentedByItsTitleButtonAndEscapeReturnsToTheTiles) {
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 display = io.DisplaySize;
  const float menu_height = ImGui::GetFrameHeight();
  const float title_height = ImGui::GetFontSize() + 2.0f * ImGui::GetStyle().FramePadding.y;
  const auto title_button = [&](const std::string& key) {
    const PanelRect r = rect_of(key);
    return ImVec2(r.pos.x + r.size.x - 0.5f * title_height, r.pos.y + 0.5f * title_height);
  };
  const auto expect_presented = [&](const std::string& key) {
    const Rects rects = explorer_->layout().panel_rects();
    ASSERT_EQ(rects.size(), 1u) << "the other tiles are hidden";
    EXPECT_EQ(rects[0].first, key);
    const PanelRect& r = rects[0].second;
    EXPECT_FLOAT_EQ(r.pos.x, 0.0f);
    EXPECT_FLOAT_EQ(r.size.x, display.x);
    EXPECT_FLOAT_EQ(r.pos.y + r.size.y, display.y);
    // Under the menu bar and the read-out: most of the window.
    EXPECT_GT(r.size.y, 0.85f * (display.y - menu_height));
  };
  click_at(title_button("fold_plot"));
  expect_presented("fold_plot");
  const Solution& s = explorer_->scene().solution();
  // Drawn larger, its glyphs' offsets no longer read as one line of text: compare without
  // spaces and line breaks.
  std::string text = frame();
  std::erase(text, ' ');
  std::erase(text, '\n');
  EXPECT_NE(text.find(detail::printf_string("n=%d", s.n)), std::string::npos) << text;
  EXPECT_NE(text.find(detail::printf_string("z_max=%.2fmm", s.z_max_mm)), std::string::npos)
      << text;
  EXPECT_FALSE(explorer_->layout().fills_window());
  press(kEscape);
  frame();
  expect_tiles_fill(explorer_->layout().panel_rects(), display, menu_height);
  EXPECT_TRUE(explorer_->layout().automatic());

  // A double-click on the 3D view's title, then the menu bar's button back.
  const PanelRect cloth = rect_of("cloth");
  io.MousePos = ImVec2(cloth.pos.x + 0.3f * cloth.size.x, cloth.pos.y + 0.5f * title_height);
  frame();
  for (int i = 0; i < 2; ++i) {
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
  }
  frame();
  expect_presented("cloth");
  click("Back to the tiles (Esc)");
  expect_tiles_fill(explorer_->layout().panel_rects(), display, menu_height);
  // A script names the panel.
  ASSERT_EQ(explorer_->set_view("present", "analysis"), std::nullopt);
  frame();
  frame();
  expect_presented("analysis");
  EXPECT_TRUE(explorer_->set_view("present", "nothing").has_value());
  // The introduction opened over a presented panel takes the first Escape; the next one returns
  // to the tiles.
  click(IntroWindow::kTitle);
  ASSERT_TRUE(panel<IntroWindow>().is_open());
  press(kEscape);
  EXPECT_FALSE(panel<IntroWindow>().is_open());
  frame();
  expect_presented("analysis");
  press(kEscape);
  frame();
  expect_tiles_fill(explorer_->layout().panel_rects(), display, menu_height);
}

// Presenting, a teacher answers "what if it were twice as heavy?" without leaving the view: the
// strip under the read-out holds t, E, w, h, L and d, driven as the panel's sliders are (a click,
// arrow keys with Shift for a tenth of the step, a value typed with its unit, a refused one with
// its reason under the strip), while the view stays presented. "Hide inputs" in the menu bar
// takes the strip away, and the choice is kept with the session.
TEST_F(ExplorerTest, ThePresentedViewsStripOfInputsChangesTheFabricWithoutLeavingIt) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  const auto script = [&](nlohmann::json steps) {
    return play(*explorer_, {{"steps", std::move(steps)}}, [&] { frame(); });
  };
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  frame();
  const PanelRect with_strip = rect_of("fold_plot");
  std::vector<std::string> keys;
  for (const auto& [key, place] : panel<ParametersPanel>().slider_places()) {
    keys.push_back(key);
    EXPECT_LE(place.max.y, with_strip.pos.y) << key << ": above the presented view";
    EXPECT_GE(place.max.x - place.min.x, 7.0f * ImGui::GetFontSize()) << key;
  }
  EXPECT_EQ(keys, (std::vector<std::string>{"E", "L", "d", "h", "t", "w"}));

  // A click focuses w; each arrow key moves it by 1 % of the slider, Shift+arrow by 0.1 %: of
  // the beginner's 1e-7 N/mm² (10.2 g/m²) to 1000 g/m², log10(1000 x 9.81e-9 / 1e-7) = 1.99
  // decades on a log scale.
  const double slider_decades = std::log10(1000.0 * 9.81e-9 / 1e-7);
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}}}), 0);
  const double w0 = explorer_->edited().fabric.weight_N_per_mm2;
  ASSERT_EQ(script({{{"key", "right"}}}), 0);
  const double w1 = explorer_->edited().fabric.weight_N_per_mm2;
  EXPECT_NEAR(std::log10(w1 / w0), 0.01 * slider_decades, 1e-9);
  ASSERT_EQ(script({{{"key", "shift+right"}}, {{"key", "shift+left"}}, {{"key", "shift+left"}}}),
            0);
  EXPECT_NEAR(std::log10(explorer_->edited().fabric.weight_N_per_mm2 / w1), -0.001 * slider_decades,
              1e-9);
  EXPECT_EQ(explorer_->presented(), "fold_plot");

  // Twice as heavy, typed with its unit.
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "306 gsm"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}),
            0);
  const InputSpec& w = *find_input("w");
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), w), "306 g/m²");
  EXPECT_TRUE(document().issues().empty());
  EXPECT_EQ(explorer_->presented(), "fold_plot");

  // Refused: the reason under the strip, above the view, as at the panel's foot.
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "-5 gsm"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}),
            0);
  ASSERT_FALSE(document().issues().empty());
  const PanelRect refused = rect_of("fold_plot");
  EXPECT_LE(position_of("must be between").y, refused.pos.y) << last_text_;
  EXPECT_GT(refused.pos.y, with_strip.pos.y) << "the strip grew by the reason's lines";
  EXPECT_EQ(explorer_->presented(), "fold_plot");
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "heavy"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}),
            0);
  EXPECT_LE(position_of("is not a number").y, rect_of("fold_plot").pos.y) << last_text_;
  press('Z', true);
  frame();
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), w), "306 g/m²");

  // Hidden from the menu bar: no slider to press, the view a strip taller, and so on the next
  // start.
  ASSERT_EQ(script({{{"click", MenuBar::kHideInputsLabel}}, {{"frames", 2}}}), 0);
  EXPECT_TRUE(panel<ParametersPanel>().slider_places().empty());
  EXPECT_LT(rect_of("fold_plot").pos.y, with_strip.pos.y);
  EXPECT_EQ(explorer_->presented(), "fold_plot");
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(explorer_->layout().presents_inputs());
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  frame();
  EXPECT_TRUE(panel<ParametersPanel>().slider_places().empty());
  ASSERT_EQ(script({{{"click", MenuBar::kShowInputsLabel}}, {{"frames", 2}}}), 0);
  EXPECT_EQ(panel<ParametersPanel>().slider_places().size(), 6u);
}

// A drag that missed w's handle and started on the line of text under it carried the whole
// Parameters panel away from its tile.
TEST_F(ExplorerTest, APanelMovesByItsTitleOnlyNotByADragInsideIt) {
  frame();
  const PanelRect before = rect_of("parameters");
  const ImVec2 start = position_of("oz/yd²");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = start;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (int i = 1; i <= 10; ++i) {
    io.MousePos =
        ImVec2(start.x + 10.0f * static_cast<float>(i), start.y + 5.0f * static_cast<float>(i));
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_EQ(rect_of("parameters").pos.x, before.pos.x);
  EXPECT_EQ(rect_of("parameters").pos.y, before.pos.y);
  EXPECT_TRUE(explorer_->layout().automatic());
  EXPECT_EQ(document().undo_depth(), 0u) << "nothing changed";
}

// Dragging the corner shared by the fold plot, the 3D view and the lower panels moves those
// edges: the neighbours follow, nothing overlaps and no hole opens. "Reset layout" puts the
// edges back.
TEST_F(ExplorerTest, DraggingAPanelsCornerMovesTheNeighboursEdgesWithIt) {
  ImGuiIO& io = ImGui::GetIO();
  io.BackendFlags |= ImGuiBackendFlags_HasMouseCursors;  // as the GLFW backend: edges resize
  frame();
  frame();
  const PanelRect fold = rect_of("fold_plot");
  const PanelRect cloth = rect_of("cloth");
  const PanelRect results = rect_of("results");
  // The resize grip in the fold plot's lower right corner, 80 px left and 40 px down.
  const ImVec2 grip(fold.pos.x + fold.size.x - 3.0f, fold.pos.y + fold.size.y - 3.0f);
  io.MousePos = grip;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (float step = 1.0f; step <= 4.0f; step += 1.0f) {
    io.MousePos = ImVec2(grip.x - 20.0f * step, grip.y + 10.0f * step);
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_TRUE(explorer_->layout().fills_window());
  expect_tiles_fill(explorer_->layout().panel_rects(), io.DisplaySize, ImGui::GetFrameHeight());
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.x, fold.size.x - 80.0f);
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.y, fold.size.y + 40.0f);
  EXPECT_FLOAT_EQ(rect_of("cloth").pos.x, cloth.pos.x - 80.0f);
  EXPECT_FLOAT_EQ(rect_of("cloth").size.y, cloth.size.y + 40.0f);
  EXPECT_FLOAT_EQ(rect_of("results").pos.y, results.pos.y + 40.0f);
  EXPECT_FLOAT_EQ(rect_of("results").size.x, results.size.x) << "the lower edge stays";
  // A bigger window keeps the user's proportions and still tiles it.
  io.DisplaySize = ImVec2(1600, 1000);
  frame();
  frame();
  EXPECT_TRUE(explorer_->layout().fills_window());
  click("Reset layout");
  frame();
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.x, rect_of("results").size.x);
  EXPECT_TRUE(explorer_->layout().fills_window());
}

// Escape closes an open menu and an open combo, as elsewhere on the desktop.
TEST_F(ExplorerTest, EscapeClosesAnOpenMenuOrCombo) {
  click("View");
  ASSERT_NE(frame().find("Larger text"), std::string::npos) << "the View menu is open";
  press(kEscape);
  EXPECT_EQ(frame().find("Larger text"), std::string::npos) << last_text_;
  click("fabric");  // the 3D view's "colour by" combo
  ASSERT_NE(frame().find("fold sign"), std::string::npos) << "the combo is open";
  press(kEscape);
  EXPECT_EQ(frame().find("fold sign"), std::string::npos) << last_text_;
}

TEST_F(ExplorerTest, APanelTheUserMovesStaysUntilResetLayout) {
  ImGuiIO& io = ImGui::GetIO();
  frame();
  const auto results_pos = [this] {
    for (const auto& [n, r] : explorer_->layout().panel_rects()) {
      if (n == "results") {
        return r.pos;
      }
    }
    return ImVec2(-1, -1);
  };
  const ImVec2 before = results_pos();
  // Drag the Results panel by its title bar, 60 px right and 40 px down.
  const ImVec2 title = position_of("Results");
  const ImVec2 grab(title.x + 80.0f, title.y + 4.0f);
  io.MousePos = grab;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (float step = 1.0f; step <= 4.0f; step += 1.0f) {
    io.MousePos = ImVec2(grab.x + 15.0f * step, grab.y + 10.0f * step);
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_FALSE(explorer_->layout().automatic());
  EXPECT_FLOAT_EQ(results_pos().x, before.x + 60.0f);
  EXPECT_FLOAT_EQ(results_pos().y, before.y + 40.0f);
  // A bigger window no longer moves the user's panel.
  io.DisplaySize = ImVec2(1600, 1000);
  frame();
  frame();
  EXPECT_FLOAT_EQ(results_pos().x, before.x + 60.0f);
  EXPECT_FLOAT_EQ(results_pos().y, before.y + 40.0f);
  // "Reset layout" stands in the menu bar while the user's arrangement is shown.
  click("Reset layout");
  EXPECT_TRUE(explorer_->layout().automatic());
  expect_tiles_fill(explorer_->layout().panel_rects(), io.DisplaySize, ImGui::GetFrameHeight());
  EXPECT_EQ(frame().find("Reset layout"), std::string::npos) << "only shown when it would act";
}

// A session remembers whether the user arranged the panels (imgui.ini keeps where), so that the
// next start does not tile over their arrangement.
TEST_F(ExplorerTest, TheUsersArrangementIsRememberedWithTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  EXPECT_TRUE(explorer_->layout().automatic());
  const ImVec2 title = position_of("Results");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(title.x + 80.0f, title.y + 4.0f);
  frame();
  io.MouseDown[0] = true;
  frame();
  io.MousePos.x += 50.0f;
  frame();
  io.MouseDown[0] = false;
  frame();
  ASSERT_FALSE(explorer_->layout().automatic());
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(explorer_->layout().automatic());
  explorer_->layout().reset();
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_TRUE(explorer_->layout().automatic());
}

// The session file says which FoldLab wrote it; a session from before it did still loads.
TEST_F(ExplorerTest, TheSessionFileRecordsTheVersionThatWroteIt) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session, true);
  explorer_->save_session_now();
  std::ifstream in(session);
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("written_by"), app::version_line());
  EXPECT_TRUE(j.at("written_by").get<std::string>().starts_with("FoldLab "));
  j.erase("written_by");
  std::string error;
  EXPECT_TRUE(session_from_text(j.dump(), "older session", error).has_value()) << error;
}

// The regime map's colours explained beside it: a colour bar with n's scale on the map's right
// and the regimes without n named under it.
TEST_F(ExplorerTest, TheRegimeMapHasAColourBarAndNamesItsRegimes) {
  open_explorer("map");
  while (explorer_->busy()) {
    frame();
  }
  const std::string text = frame();
  for (const char* name : {"no slack", "short cloth", "negligible slack", "invalid inputs"}) {
    EXPECT_NE(text.find(name), std::string::npos) << name << "\n" << text;
  }
  // The bar's scale, 1 at the bottom to 200 at the top, right of the map's x range (3000).
  const ImVec2 top = position_of("\n200\n");
  const ImVec2 bottom = position_of("\n1\n");
  const ImVec2 x_to = position_of("3000");
  EXPECT_LT(top.y, bottom.y);
  EXPECT_GT(top.x, x_to.x);
  EXPECT_GT(bottom.x, x_to.x);
  // The bar's title above it, clear of the x labels' line (under the bar "3000" ran into it).
  const ImVec2 title = position_of("\nn\n");
  EXPECT_LT(title.y + ImGui::GetFontSize(), top.y);
}

// The map's axes carry round ticks in the sliders' units: h over 300..3000 mm 1, 2 or 5 × 10^k
// apart, w over 3e-7..1e-5 N/mm² = 30.6..1019 g/m² (log scale) at 1, 2 or 5 × 10^k g/m², written
// out and no two labels overlapping.
TEST_F(ExplorerTest, TheRegimeMapsAxesHaveRoundTicksInTheSlidersUnits) {
  open_explorer("map");
  while (explorer_->busy()) {
    frame();
  }
  const std::string text = frame();
  // The x labels: the line above the x title, evenly spaced by a round step.
  const std::size_t title = text.find("\nh (mm)\n");
  ASSERT_NE(title, std::string::npos) << text;
  const std::size_t line = text.rfind('\n', title - 1) + 1;
  const std::string x_labels = text.substr(line, title - line);
  EXPECT_EQ(x_labels.find('e'), std::string::npos) << x_labels;
  std::vector<double> x_ticks;
  for (const char* at = x_labels.c_str(); *at != '\0';) {
    char* end = nullptr;
    x_ticks.push_back(std::strtod(at, &end));
    ASSERT_NE(end, at) << x_labels;
    at = end;
  }
  ASSERT_GE(x_ticks.size(), 2u) << x_labels;
  const double step = x_ticks[1] - x_ticks[0];
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
  EXPECT_TRUE(mantissa == 1.0 || mantissa == 2.0 || mantissa == 5.0) << x_labels;
  for (std::size_t k = 1; k < x_ticks.size(); ++k) {
    EXPECT_EQ(x_ticks[k] - x_ticks[k - 1], step) << x_labels;
    EXPECT_GE(x_ticks[k - 1], 300.0);
    EXPECT_LE(x_ticks[k], 3000.0);
    // Drawn apart: the next label starts right of where this one ends.
    const ImVec2 here = position_of(" " + format_tick(x_ticks[k], step));
    EXPECT_GT(here.x, 0.0f);
  }
  // The y labels: one a line between the y title and the x labels, 1, 2 or 5 × 10^k g/m² inside
  // 30.6..1019, ascending, each at least a line above the one before.
  const std::size_t y_title = text.find("\nw (g/m²)\n");
  ASSERT_NE(y_title, std::string::npos) << text;
  const std::size_t first_y = y_title + std::string("\nw (g/m²)\n").size();
  std::vector<double> y_ticks;
  float last_y = -1e9f;
  for (std::size_t at = first_y; at < line;) {
    const std::size_t end = text.find('\n', at);
    const std::string label = text.substr(at, end - at);
    const double value = std::strtod(label.c_str(), nullptr);
    EXPECT_EQ(label.find('e'), std::string::npos) << label;
    const double leading = value / std::pow(10.0, std::floor(std::log10(value) + 1e-9));
    EXPECT_TRUE(std::abs(leading - 1) < 1e-9 || std::abs(leading - 2) < 1e-9 ||
                std::abs(leading - 5) < 1e-9)
        << label;
    EXPECT_GT(value, 30.58);
    EXPECT_LT(value, 1019.4);
    if (!y_ticks.empty()) {  // drawn from the bottom up
      EXPECT_GT(value, y_ticks.back());
      EXPECT_GE(last_y - last_positions_[at].y, ImGui::GetFontSize()) << label;
    }
    y_ticks.push_back(value);
    last_y = last_positions_[at].y;
    at = end + 1;
  }
  ASSERT_GE(y_ticks.size(), 2u) << text;
  EXPECT_TRUE(w_in_e_notation_only_beside_its_slider(text)) << text;

  // The hover reads in the same units, at the ticks it is over.
  const ImVec2 w_100 = position_of("\n100\n");  // a decade on a log axis is always labelled
  const std::string x_tick = format_tick(x_ticks.back(), step);
  const ImVec2 x_at = position_of(x_tick);
  ImGui::GetIO().MousePos = ImVec2(x_at.x + 0.5f * ImGui::CalcTextSize(x_tick.c_str()).x - 2.0f,
                                   w_100.y + 0.5f * ImGui::GetFontSize());
  frame();
  const std::string hovered = frame();
  // Within a cell (2700 mm / 256 = 11 mm; a w cell is 1/256 of 1.52 decades, 1.4 %) and the
  // 2 px the mouse stays left of the map's edge.
  const std::string first_tick = format_tick(x_ticks.front(), step);
  const float first_centre =
      position_of(first_tick).x + 0.5f * ImGui::CalcTextSize(first_tick.c_str()).x;
  const float last_centre = x_at.x + 0.5f * ImGui::CalcTextSize(x_tick.c_str()).x;
  const double mm_per_px = (x_ticks.back() - x_ticks.front()) / (last_centre - first_centre);
  EXPECT_NEAR(number_after(hovered, ", w = "), 100.0, 3.0) << hovered;
  EXPECT_NEAR(number_after(hovered, "\nh = "), x_ticks.back(), 11.0 + 3.0 * mm_per_px) << hovered;
  EXPECT_NE(hovered.find(" g/m²\n"), std::string::npos) << hovered;
}

// At the smallest supported window the controls of each panel are drawn inside it, not cut off
// at its right edge: the rows wrap.
TEST_F(ExplorerTest, At1024x640NoControlIsCutOff) {
  ImGui::GetIO().DisplaySize = ImVec2(1024, 640);
  frame();
  frame();
  const Rects rects = explorer_->layout().panel_rects();
  const auto right_of = [&](const std::string& name) {
    for (const auto& [n, r] : rects) {
      if (n == name) {
        return r.pos.x + r.size.x;
      }
    }
    return 0.0f;
  };
  const struct {
    const char* label;
    const char* panel;
  } controls[] = {{"reset camera", "cloth"},   {"breeze", "cloth"},
                  {"z exaggeration", "cloth"}, {"Save as...", "presets"},
                  {"autoscale", "fold_plot"},  {"Reset to preset", "parameters"},
                  {"Regime map", "analysis"}};
  for (const auto& c : controls) {
    const ImVec2 at = position_of(c.label);
    EXPECT_LE(at.x + ImGui::CalcTextSize(c.label).x, right_of(c.panel)) << c.label;
  }
}

// At 200 % in a 1280 x 800 window the views' settings took most of their panels (the cloth was
// drawn 85 px high): they fold behind one button and the views keep the room; a click opens them,
// and they work as in the row. At 100 % they stay in the row.
TEST_F(ExplorerTest, AtALargeTextSizeTheViewsSettingsFoldAndTheViewsKeepTheirRoom) {
  ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
  frame();
  frame();
  EXPECT_FALSE(panel<ClothViewPanel>().toolbar_folded());
  EXPECT_FALSE(panel<FoldPlotPanel>().toolbar_folded());
  explorer_->appearance().request(200, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_TRUE(panel<ClothViewPanel>().toolbar_folded());
  EXPECT_TRUE(panel<FoldPlotPanel>().toolbar_folded());
  EXPECT_EQ(last_text_.find("wireframe"), std::string::npos) << last_text_;
  // The least useful height of the cloth: twelve lines of text.
  EXPECT_GE(panel<ClothViewPanel>().view_rect().size.y, 12.0f * ImGui::GetFontSize());
  const bool wireframe = panel<ClothViewPanel>().style().wireframe;
  click("view settings...");
  click("wireframe");
  EXPECT_NE(panel<ClothViewPanel>().style().wireframe, wireframe);
  EXPECT_TRUE(panel<ClothViewPanel>().toolbar_folded()) << "a setting does not unfold the row";
  press(kEscape);
  explorer_->appearance().request(100, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_FALSE(panel<ClothViewPanel>().toolbar_folded());
  EXPECT_NE(last_text_.find("wireframe"), std::string::npos) << last_text_;
}

// The preset's name over the sliders wraps rather than hide "(unsaved changes)"; that note must
// not add a line under the pointer when a drag makes the first edit: at 1920 x 1080 it did, and
// a Ctrl+click meant for w opened E. Each slider stays where it was drawn before the edit.
TEST_F(ExplorerTest, TheFirstEditDoesNotMoveTheSlidersUnderThePointer) {
  open_explorer("equations", kDejaVuSans);
  document().load_preset_file(kPresetsDir / "default.json");
  for (const ImVec2 size : {ImVec2(1024, 640), ImVec2(1280, 800), ImVec2(1920, 1080),
                            ImVec2(1600, 900), ImVec2(2560, 1440)}) {
    SCOPED_TRACE(size.x);
    show_at(size);
    ASSERT_FALSE(document().unsaved());
    const float before = panel<ParametersPanel>().slider_places().at("w").min.y;
    ASSERT_EQ(document().apply(Edit::input("h", 1500.0)), std::nullopt);
    frame();
    frame();
    ASSERT_TRUE(document().unsaved());
    EXPECT_TRUE(shows(last_text_, "(unsaved")) << last_text_;
    EXPECT_EQ(panel<ParametersPanel>().slider_places().at("w").min.y, before);
    document().reset_to_loaded();
    frame();
  }
}

// A slider's help is one long sentence: at 200 % its tooltip ran past the window's right edge
// ("denim (13 oz/yd²) 441 (p" was the last thing read). It wraps inside the window.
TEST_F(ExplorerTest, ASlidersHelpTooltipStaysInsideTheWindowAtTwiceTheTextSize) {
  open_explorer("equations", kDejaVuSans);
  ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
  explorer_->appearance().request(200, false);
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  const SliderPlace w = panel<ParametersPanel>().slider_places().at("w");
  ImGui::GetIO().MousePos = ImVec2(0.5f * (w.min.x + w.max.x), 0.5f * (w.min.y + w.max.y));
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const ImGuiWindow* tooltip = ImGui::FindWindowByName("##Tooltip_00");
  ASSERT_NE(tooltip, nullptr);
  ASSERT_TRUE(tooltip->Active);
  EXPECT_GE(tooltip->Pos.x, 0.0f);
  EXPECT_LE(tooltip->Pos.x + tooltip->Size.x, 1280.0f);
  EXPECT_TRUE(shows(last_text_, "441")) << last_text_;
}

// A message on the status line while a view is presented ("Undone.", a refusal) went between the
// read-out and the strip and moved the strip's sliders under the pointer; a typed text's reason
// was said twice, over and under the strip. The message goes under the strip, and once.
TEST_F(ExplorerTest, APresentedMessageNeverMovesTheStripAndIsSaidOnce) {
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  frame();
  const float w_y = panel<ParametersPanel>().slider_places().at("w").min.y;
  status().notify("Undone.", false);
  frame();
  EXPECT_NE(last_text_.find("Undone."), std::string::npos) << last_text_;
  EXPECT_EQ(panel<ParametersPanel>().slider_places().at("w").min.y, w_y);
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "heavy"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_EQ(panel<ParametersPanel>().slider_places().at("w").min.y, w_y);
  const std::size_t first = last_text_.find("is not a number");
  ASSERT_NE(first, std::string::npos) << last_text_;
  EXPECT_EQ(last_text_.find("is not a number", first + 1), std::string::npos) << last_text_;
}

// "Loaded Silk chiffon." coming and going moved the Presets panel's name field and buttons by a
// line or two, so that a click meant for the field loaded a preset. They stay where they are; the
// message shows at the panel's foot.
TEST_F(ExplorerTest, TheStatusLineNeverMovesThePresetsFieldOrButtons) {
  for (const ImVec2 size : {ImVec2(1280, 800), ImVec2(1024, 640), ImVec2(1920, 1080)}) {
    SCOPED_TRACE(size.x);
    show_at(size);
    const ImVec2 field = position_of("name of the ne");
    const ImVec2 save = position_of("Save as...");
    status().notify("Saved to /tmp/somewhere/rather/long/presets/chiffon-curtain-2-4m.json", false);
    frame();
    frame();
    EXPECT_TRUE(shows(last_text_, "chiffon-curtain")) << last_text_;
    EXPECT_EQ(position_of("name of the ne").y, field.y);
    EXPECT_EQ(position_of("Save as...").y, save.y);
    status().withdraw(status().message());
    frame();
    EXPECT_EQ(position_of("Save as...").y, save.y);
  }
}

// The regime map in its tile at 200 % in 1280 x 800: its axes and cells took the whole tile and
// the map was out of sight. They fold behind "map settings..." as the views' settings do, the
// line of timing goes with them, and they work from the popup.
TEST_F(ExplorerTest, AtALargeTextSizeTheRegimeMapsSettingsFoldAndStillWork) {
  open_explorer("map");
  ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
  frame();
  frame();
  const auto report = [&] { return panel<AnalysisPanel>().regime_map().report(); };
  EXPECT_FALSE(report().at("settings_folded").get<bool>());
  EXPECT_NE(last_text_.find("show z_max instead of n"), std::string::npos) << last_text_;
  explorer_->appearance().request(200, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_TRUE(report().at("settings_folded").get<bool>());
  EXPECT_EQ(last_text_.find("show z_max instead of n"), std::string::npos) << last_text_;
  EXPECT_EQ(last_text_.find("solves in"), std::string::npos) << last_text_;
  click("map settings...");
  EXPECT_NE(last_text_.find("solves in"), std::string::npos) << last_text_;
  EXPECT_EQ(report().at("shows"), "n");
  click("show z_max instead of n");
  EXPECT_EQ(report().at("shows"), "z_max");
  EXPECT_TRUE(report().at("settings_folded").get<bool>()) << "a setting does not unfold the row";
  press(kEscape);
  explorer_->appearance().request(100, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_FALSE(report().at("settings_folded").get<bool>());
}

// Presented at 200 % in 1024 x 640: the read-out wraps between n, Q and z_max, never inside one
// ("z_max = 48.96 (30.5–78." over "6) mm" was drawn), and the menu bar's last item stays on it.
TEST_F(ExplorerTest, APresentedReadOutWrapsBetweenItsValuesAndTheMenuBarKeepsItsItems) {
  open_explorer("equations", kDejaVuSans);  // the explorer's own font: the bar's widths are its
  // The default preset: its calibration gives each value a range, which makes the line long.
  document().load_preset_file(kPresetsDir / "default.json");
  ImGui::GetIO().DisplaySize = ImVec2(1024, 640);
  explorer_->appearance().request(200, false);
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  // (DejaVu's narrow gaps read as spaces or not: "z_m ax", "m m".)
  const std::size_t z = last_text_.find("z_");
  ASSERT_NE(z, std::string::npos) << last_text_;
  const std::size_t mm = last_text_.find('m', last_text_.find(')', z));
  ASSERT_NE(mm, std::string::npos) << last_text_;
  EXPECT_EQ(last_positions_[z].y, last_positions_[mm].y) << "z_max's value and unit on one line";
  const std::size_t q = last_text_.find("Q");
  ASSERT_LT(q, z);
  EXPECT_GT(last_positions_[z].y, last_positions_[q].y) << "this width needs two lines";
  const std::size_t range_end = last_text_.find(")", q);
  EXPECT_EQ(last_positions_[range_end].y, last_positions_[q].y) << "Q's range on Q's line";
  const float right =
      position_of(MenuBar::kHideInputsLabel).x + ImGui::CalcTextSize(MenuBar::kHideInputsLabel).x;
  EXPECT_LE(right, 1024.0f);
  EXPECT_TRUE(shows(last_text_, MenuBar::kBackToTilesShortLabel)) << last_text_;
  // At 100 % the bar has room for the long wording.
  explorer_->appearance().request(100, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_TRUE(shows(last_text_, MenuBar::kBackToTilesLabel)) << last_text_;
}

// The photo loop through real clicks: a PNG that FoldLab drew of the loaded preset's folds (turned
// 3° and scaled, as a camera might) is typed into the load dialog, its two supports and its folds
// are clicked where the geometry drew them, and the measurement must give back the solution's n
// and Q; "Add to measurements" writes the row to the measurements file, "Fit" saves a preset
// that rests on that row and the six fit rows of Tables 1-2.
TEST_F(ExplorerTest, APhotoOfKnownFoldsClickedGivesItsNAndQAndFeedsAFit) {
  const Parameters p = shown();
  const Solution s = explorer_->scene().solution();
  ASSERT_GE(s.n, 3);
  const fs::path png = dir_ / "cloth.png";
  const testing::FoldPhoto photo = testing::write_fold_photo(s, p, png);

  // Clicked on a projector's 1920 x 1080: drawn at true scale, the fold plot of this square
  // cloth tiled at 1280 x 800 leaves a screen pixel too many of the photo's for the measured Q
  // to tell this cloth from the next.
  show_at(ImVec2(1920, 1080));
  click("Load");  // "Load photo...", the only "Load" before the dialog opens
  EXPECT_EQ(status().modal_title(), PhotoOverlay::kLoadModal);
  ImGui::GetIO().AddInputCharactersUTF8(png.string().c_str());
  frame();
  frame();
  click("Load");
  EXPECT_EQ(status().modal_title(), "");
  nlohmann::json report = panel<PhotoOverlay>().report();
  ASSERT_TRUE(report.at("photo").is_object()) << last_text_;
  EXPECT_EQ(report.at("photo").at("width_px"), photo.width_px);
  EXPECT_EQ(report.at("photo").at("height_px"), photo.height_px);

  auto click_pixel = [&](PixelPoint at) {
    const ImVec2 screen = panel<PhotoOverlay>().screen_of_pixel(at.x, at.y);
    click_at(screen);
  };
  // ImGui floors the mouse position to whole screen pixels: a click lands within one screen
  // pixel (diagonal: sqrt 2) of its aim, which is this many photo pixels.
  auto photo_px_per_screen_px = [&] {
    const ImVec2 a = panel<PhotoOverlay>().screen_of_pixel(photo.left_support.x, 0.0);
    const ImVec2 b = panel<PhotoOverlay>().screen_of_pixel(photo.right_support.x, 0.0);
    return (photo.right_support.x - photo.left_support.x) / std::hypot(b.x - a.x, b.y - a.y);
  };
  const double before_px = std::sqrt(2.0) * photo_px_per_screen_px();
  click_pixel(photo.right_support);  // either order: the left one becomes the first
  click_pixel(photo.left_support);
  report = panel<PhotoOverlay>().report();
  ASSERT_EQ(report.at("photo").at("supports_px").size(), 2u);
  EXPECT_NEAR(report.at("photo").at("supports_px")[0][0].get<double>(), photo.left_support.x,
              before_px);
  EXPECT_NEAR(report.at("photo").at("supports_px")[1][1].get<double>(), photo.right_support.y,
              before_px);
  // Upper folds first: the order of the clicks does not matter.
  for (auto fold = photo.folds.rbegin(); fold != photo.folds.rend(); ++fold) {
    click_pixel(*fold);
  }
  report = panel<PhotoOverlay>().report();
  ASSERT_TRUE(report.at("measured").is_object()) << last_text_;
  EXPECT_EQ(report.at("measured").at("n"), s.n);
  // A depth is off by the rows of its click and of the supports' clicks (one screen pixel each,
  // now in the supports' frame: photo px times mm per photo px), and the span by the supports'.
  const double mm_per_photo_px =
      s.span_mm / (photo.right_support.x - photo.left_support.x) * std::cos(photo.angle_rad);
  const double depth_tolerance_mm =
      2.0 * std::sqrt(2.0) * photo_px_per_screen_px() * mm_per_photo_px +
      s.a_mm[0] * 2.0 * before_px / (photo.right_support.x - photo.left_support.x);
  for (std::size_t i = 0; i < s.a_mm.size(); ++i) {
    EXPECT_NEAR(report.at("measured").at("a_mm")[i].get<double>(), s.a_mm[i], depth_tolerance_mm)
        << i;
  }
  // ln a_i is off by at most tolerance / a_n; the fitted slope, a weighted sum of those, by no
  // more than the largest of them times sum |i - mean| / sum (i - mean)^2.
  double spread = 0.0;
  double squares = 0.0;
  for (int i = 0; i <= s.n; ++i) {
    spread += std::abs(i - 0.5 * s.n);
    squares += (i - 0.5 * s.n) * (i - 0.5 * s.n);
  }
  const double log_Q_tolerance = depth_tolerance_mm / s.a_mm.back() * spread / squares;
  EXPECT_NEAR(std::log(report.at("measured").at("Q").get<double>()), std::log(s.Q),
              log_Q_tolerance);
  EXPECT_LT(log_Q_tolerance, 0.2 * std::log(s.Q));  // tighter than the step to another cloth
  const std::string n_text = "n = " + std::to_string(s.n);
  EXPECT_NE(last_text_.find(n_text + " Q = "), std::string::npos) << last_text_;

  click("Add to measurements");
  const MeasurementSet rows = load_measurements(dir_ / "measurements.csv");
  ASSERT_EQ(rows.rows.size(), 1u);
  EXPECT_EQ(rows.rows[0].name, "photo cloth.png");
  EXPECT_EQ(rows.rows[0].observed.n, s.n);
  EXPECT_EQ(*rows.rows[0].observed.Q, report.at("measured").at("Q").get<double>());
  EXPECT_FALSE(rows.rows[0].observed.z_max_mm.has_value());
  EXPECT_EQ(rows.rows[0].inputs.hanging.height_mm, p.hanging.height_mm);
  EXPECT_EQ(rows.rows[0].inputs.fabric.thickness_mm, p.fabric.thickness_mm);
  EXPECT_NE(last_text_.find("1 row in"), std::string::npos) << last_text_;

  click("Fit K and p to my rows");
  // The fit's leave-one-out refits take tens of seconds on a loaded machine: a generous wall
  // clock, not a frame count, bounds the wait.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(8);
  while (panel<PhotoOverlay>().fitting() && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    frame();
  }
  ASSERT_FALSE(panel<PhotoOverlay>().fitting());
  frame();
  report = panel<PhotoOverlay>().report();
  ASSERT_TRUE(report.at("photo").at("fitted_preset").is_string()) << last_text_;
  const Preset fitted = load_preset(report.at("photo").at("fitted_preset").get<std::string>());
  ASSERT_TRUE(fitted.calibration.has_value());
  // Tables 1-2 hold six fit rows and one check row (Fig. 4); the photo adds one fit row.
  EXPECT_EQ(fitted.calibration->fit_rows, 7);
  EXPECT_EQ(fitted.calibration->leave_one_out.size(), 7u);
  EXPECT_EQ(fitted.calibration->calibrated_on, "my measurements and Conci's Tables 1–2");
  EXPECT_EQ(fitted.parameters.model.stress_exponent_p, fitted.calibration->fitted.p);
  EXPECT_NE(fitted.description.find("leave-one-out"), std::string::npos) << fitted.description;
  bool listed = false;
  for (const PresetsPanel::Entry& entry : panel<PresetsPanel>().entries()) {
    listed = listed || entry.name == fitted.name;
  }
  EXPECT_TRUE(listed) << fitted.name;
}

TEST_F(ExplorerTest, APhotoThatCannotBeReadIsRefusedWithItsReason) {
  const fs::path text = dir_ / "notes.png";
  { std::ofstream(text) << "not an image"; }
  click("Load");  // "Load photo...", the only "Load" before the dialog opens
  ImGui::GetIO().AddInputCharactersUTF8(text.string().c_str());
  frame();
  frame();
  click("Load");
  EXPECT_EQ(status().modal_title(), PhotoOverlay::kLoadModal);  // stays open to correct it
  EXPECT_NE(squeezed(last_text_).find("notaPNGorJPEGfile"), std::string::npos) << last_text_;
  EXPECT_TRUE(panel<PhotoOverlay>().report().at("photo").is_null());
  press(kEscape);
  EXPECT_EQ(status().modal_title(), "");
}

}  // namespace
}  // namespace foldlab::gui

namespace foldlab::gui {
namespace {

// The ranges of docs/default-model.md's table for the default model on Table 1's rows: n, Q and
// z_max carry the range of the stored calibration, and the printed form carries none.
TEST_F(ExplorerTest, ResultsShowTheRangeTheCalibrationAllows) {
  // The proportional font's gaps do not tell spaces apart: compare without them.
  open_explorer("equations", kDejaVuSans);
  EXPECT_FALSE(shows(frame(), "(7–7)")) << "the paper's preset has no range";
  explorer_->load_preset_file(kPresetsDir / "default.json");
  // The interval the core computes for this cloth (its own test checks it by hand), as shown.
  auto interval_of = [&](double h) {
    Parameters p = default_preset().parameters;
    p.hanging.height_mm = h;
    const ModelStanding standing = model_standing(p, default_preset().calibration);
    const PredictionRange& r = *standing.range;
    return std::pair{detail::printf_string("n %d (%d–%d)", solve(p).n, r.n_min, r.n_max),
                     detail::printf_string("%.1f–%.1f", r.z_max_min_mm, r.z_max_max_mm)};
  };
  ASSERT_EQ(explorer_->set_input("h", 2350.0), std::nullopt);
  frame();
  const std::string text = frame();
  const auto [n_2350, z_2350] = interval_of(2350.0);
  EXPECT_TRUE(shows(text, n_2350)) << n_2350 << "\n" << text;
  EXPECT_TRUE(shows(text, z_2350)) << z_2350 << "\n" << text;
  EXPECT_TRUE(shows(text, "calibrated on Conci's Tables 1–2")) << text;
  EXPECT_TRUE(shows(text, "71 % prediction intervals")) << text;
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  const auto [n_900, z_900] = interval_of(900.0);
  EXPECT_TRUE(shows(frame(), n_900)) << n_900 << "\n" << last_text_;
  EXPECT_TRUE(shows(last_text_, z_900)) << z_900 << "\n" << last_text_;
}

// A scripted picture's view settings are taken as given or refused with their range; none is
// moved to the nearest allowed value (README: values are never clamped).
TEST_F(ExplorerTest, ViewSettingsOutsideTheirRangeAreRefusedNotClamped) {
  for (const auto& [key, value] :
       std::vector<std::pair<const char*, const char*>>{{"z_exaggeration", "100"},
                                                        {"z_exaggeration", "-3"},
                                                        {"scale", "1000"},
                                                        {"scale", "99"},
                                                        {"breeze", "2"},
                                                        {"wireframe", "7"},
                                                        {"ground", "-1"},
                                                        {"time", "-5"},
                                                        {"breeze_mm", "1e9"},
                                                        {"print_mm", "5"}}) {
    SCOPED_TRACE(std::string(key) + "=" + value);
    const std::optional<std::string> problem = explorer_->set_view(key, value);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("must be"), std::string::npos) << *problem;
  }
  EXPECT_EQ(panel<ClothViewPanel>().style().z_exaggeration, 1.0f)
      << "a refused value changes nothing";
  EXPECT_EQ(explorer_->set_view("z_exaggeration", "20"), std::nullopt);
  EXPECT_EQ(panel<ClothViewPanel>().style().z_exaggeration, 20.0f);
  EXPECT_EQ(explorer_->set_view("wireframe", "1"), std::nullopt);
  EXPECT_TRUE(panel<ClothViewPanel>().style().wireframe);
  EXPECT_EQ(explorer_->set_view("scale", "250"), std::nullopt);
}

// One write path: a refused value stays as typed with its reason, the scene keeps the last valid
// state, and a key that cannot be applied at all changes nothing.
TEST_F(ExplorerTest, ApplyKeepsARefusedValueWithItsIssueAndTheSceneAtTheLastValidState) {
  const Parameters valid = shown();
  ASSERT_EQ(document().apply(Edit::input("h", -5.0)), std::nullopt);
  EXPECT_EQ(document().edited().hanging.height_mm, -5.0) << "kept as typed";
  ASSERT_EQ(document().issues().size(), 1u);
  EXPECT_EQ(document().issues()[0].field, "h_mm");
  EXPECT_TRUE(shown() == valid) << "the scene keeps the last valid state";
  const std::size_t depth = document().undo_depth();
  EXPECT_NE(document().apply(Edit::input("no_such_key", 1.0)), std::nullopt);
  EXPECT_NE(document().apply(Edit::inputs({{"d", 50.0}, {"supports", 2.5}})), std::nullopt);
  EXPECT_EQ(document().edited().hanging.height_mm, -5.0) << "a failed edit changes nothing";
  EXPECT_EQ(document().edited().hanging.support_displacement_mm,
            valid.hanging.support_displacement_mm);
  EXPECT_EQ(document().undo_depth(), depth);
  ASSERT_EQ(document().apply(Edit::choose("h", "1.2 m")), std::nullopt);
  EXPECT_EQ(shown().hanging.height_mm, 1200.0) << "text with a unit, as --set reads it";
  EXPECT_TRUE(document().issues().empty());
}

// Scripted --set and --animate take the same path: K is stored as c, and a K that puts c out of
// range is refused by validation naming both.
TEST_F(ExplorerTest, AScriptedKOutOfRangeShowsCsIssueNamingK) {
  const Parameters valid = shown();
  ASSERT_EQ(explorer_->set_input("K", 1e9), std::nullopt);
  const std::optional<std::string> refusal = document().refusal();
  ASSERT_TRUE(refusal.has_value());
  EXPECT_NE(refusal->find("load-condition constant c = 9.1e8 must be between 0.001 and 10,000"),
            std::string::npos)
      << *refusal;
  EXPECT_NE(refusal->find("(K = c / (1 − ν²) = 1e9)"), std::string::npos) << *refusal;
  EXPECT_TRUE(shown() == valid);
  const std::string text = frame();
  EXPECT_NE(text.find("1 input(s) refused"), std::string::npos) << text;
}

// Several inputs in one edit are one undo step.
TEST_F(ExplorerTest, OneEditOfSeveralInputsIsOneUndoStep) {
  const Parameters before = shown();
  ASSERT_EQ(document().apply(Edit::inputs({{"h", 900.0}, {"d", 120.0}})), std::nullopt);
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 120.0);
  EXPECT_EQ(document().undo_depth(), 1u);
  ASSERT_TRUE(document().undo());
  EXPECT_TRUE(shown() == before);
}

// A click on the regime map moves both of its inputs, and one undo brings both back.
TEST_F(ExplorerTest, ARegimeMapClickIsOneUndoStep) {
  open_explorer("map");
  while (explorer_->busy()) {
    frame();
  }
  frame();
  const Parameters before = shown();
  const std::size_t depth = document().undo_depth();
  // The map lies over its x labels (1000 to 3000 mm) and beside its y labels (50 to 1000 g/m²):
  // a click between them is inside it.
  const ImVec2 x_from = position_of("1000 2000");
  const ImVec2 x_to = position_of("3000\nh (mm)");
  const ImVec2 y_to = position_of("\n1000\n");
  const ImVec2 middle(0.5f * (x_from.x + x_to.x), 0.5f * (y_to.y + x_to.y));
  click_at(middle);
  EXPECT_NE(shown().hanging.height_mm, before.hanging.height_mm);
  EXPECT_NE(shown().fabric.weight_N_per_mm2, before.fabric.weight_N_per_mm2);
  EXPECT_EQ(document().undo_depth(), depth + 1) << "x and y in one step";
  ASSERT_TRUE(document().undo());
  EXPECT_EQ(shown().hanging.height_mm, before.hanging.height_mm);
  EXPECT_EQ(shown().fabric.weight_N_per_mm2, before.fabric.weight_N_per_mm2);
}

// The panels are one list: each has a title and a key of its own, and the report's panels are
// the tiled ones of that list, by key, in its order.
TEST_F(ExplorerTest, EveryPanelHasADistinctNameAndTheReportNamesComeFromTheList) {
  std::vector<std::string> names;
  std::vector<std::string> keys;
  std::vector<std::string> tiled;
  for (const std::unique_ptr<Panel>& panel : explorer_->panels()) {
    ASSERT_NE(panel->name(), nullptr);
    ASSERT_NE(panel->key(), nullptr);
    EXPECT_FALSE(std::string(panel->name()).empty());
    EXPECT_FALSE(std::string(panel->key()).empty());
    names.emplace_back(panel->name());
    keys.emplace_back(panel->key());
    if (Layout::tiled(*panel)) {
      tiled.emplace_back(panel->key());
    }
  }
  EXPECT_GE(names.size(), 8u);
  for (std::vector<std::string>* list : {&names, &keys}) {
    std::vector<std::string> sorted = *list;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  }
  EXPECT_EQ(tiled.size(), static_cast<std::size_t>(kTileCount));
  frame();
  std::vector<std::string> reported;
  for (const auto& [key, rect] : explorer_->layout().panel_rects()) {
    reported.push_back(key);
  }
  EXPECT_EQ(reported, tiled);
  const nlohmann::json state = explorer_state_json(*explorer_);
  for (const std::string& key : tiled) {
    EXPECT_TRUE(state.at("layout").at("panels").contains(key)) << key;
  }
  // Each title is the one its window shows.
  const std::string text = frame();
  for (const std::unique_ptr<Panel>& panel : explorer_->panels()) {
    if (Layout::tiled(*panel)) {
      EXPECT_NE(text.find(panel->name()), std::string::npos) << panel->name();
    }
  }
}

// A/B comparison. B is pinned with the Results panel's button and A is changed through a slider
// drag, as a designer would; every number B shows is checked against a direct solve of B's
// parameters, and A − B (the change since the pin) against two independent solves.
TEST_F(ExplorerTest, PinnedBKeepsItsNumbersWhileADragChangesAAndTheTableShowsTheChangeAMinusB) {
  open_explorer("equations", kDejaVuSans);
  explorer_->load_preset_file(kPresetsDir / "default.json");  // calibrated: intervals shown
  frame();
  frame();
  EXPECT_EQ(last_text_.find("A − B"), std::string::npos) << "no table before a pin";
  // The proportional font's spaces are found by the player's reading of the glyphs.
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Pin as B"}}}}}, [&] { frame(); }), 0);
  ASSERT_TRUE(document().compare().pinned());
  const Parameters b = shown();
  EXPECT_EQ(document().compare().b().parameters, b);
  const std::string default_name = load_preset(kPresetsDir / "default.json").name;
  EXPECT_EQ(document().compare().b().name, default_name);

  ASSERT_EQ(play(*explorer_, {{"steps", {{{"drag", "h"}, {"dx", 80}}}}}, [&] { frame(); }), 0);
  const Parameters a = shown();
  ASSERT_GT(a.hanging.height_mm, b.hanging.height_mm + 50.0) << "the drag moved h";
  EXPECT_EQ(document().compare().b().parameters, b) << "B is not an edit of A";
  const Solution solved_a = solve(a);
  const Solution solved_b = solve(b);
  const Solution& shown_b = document().compare().solution();
  EXPECT_EQ(shown_b.n, solved_b.n);
  EXPECT_DOUBLE_EQ(shown_b.Q, solved_b.Q);
  EXPECT_DOUBLE_EQ(shown_b.z_max_mm, solved_b.z_max_mm);
  ASSERT_NE(solved_a.z_max_mm, solved_b.z_max_mm);

  // Each quantity's row of the table: the symbol, A, B and A − B, and under A and B their
  // intervals, from the calibration the preset carries.
  frame();
  const std::string text = frame();
  const auto rows_of = [](const Parameters& p) {
    const Solution s = solve(p);
    const PredictionRange r = *model_standing(p, default_preset().calibration).range;
    return std::array<std::pair<std::string, std::string>, 3>{
        std::pair{detail::printf_string("%d", s.n),
                  detail::printf_string("%d–%d", r.n_min, r.n_max)},
        std::pair{detail::printf_string("%.4f", s.Q),
                  detail::printf_string("%.4f–%.4f", r.Q_min, r.Q_max)},
        std::pair{detail::printf_string("%.2f mm", s.z_max_mm),
                  detail::printf_string("%.1f–%.1f mm", r.z_max_min_mm, r.z_max_max_mm)}};
  };
  const auto a_cells = rows_of(a);
  const auto b_cells = rows_of(b);
  // The change since B was pinned: A − B.
  const std::array<std::string, 3> differences = {
      detail::printf_string("%+d", solved_a.n - solved_b.n),
      detail::printf_string("%+.4f", solved_a.Q - solved_b.Q),
      detail::printf_string("%+.2f mm", solved_a.z_max_mm - solved_b.z_max_mm)};
  const char* const symbols[] = {"n", "Q", "z_max"};
  for (int i = 0; i < 3; ++i) {
    const std::string rows = std::string("\n") + symbols[i] + a_cells[i].first + b_cells[i].first +
                             differences[i] + "\n" + a_cells[i].second + b_cells[i].second + "\n";
    EXPECT_TRUE(shows(text, rows)) << rows << "\n" << text;
  }
  EXPECT_TRUE(shows(text, "A − B\nsince pinned")) << text;
  // The labels wrap in the panel: read without the line breaks.
  std::string unwrapped = text;
  std::erase(unwrapped, '\n');
  EXPECT_TRUE(shows(unwrapped, "A: " + default_name + " (edited)")) << text;
  EXPECT_TRUE(shows(unwrapped, "B: " + default_name)) << text;
  EXPECT_FALSE(shows(unwrapped, "B: " + default_name + " (edited)")) << text;

  // Undo moves A back to where B was pinned and leaves B alone.
  press('Z', true);
  EXPECT_EQ(shown(), b);
  EXPECT_EQ(document().compare().b().parameters, b);
}

TEST_F(ExplorerTest, TheFoldPlotDrawsBsFoldLinesDashedBesideAs) {
  EXPECT_EQ(panel<FoldPlotPanel>().compare_lines_drawn(), 0);
  const int legend_without_b = panel<FoldPlotPanel>().plot_view().legend_entries;
  click("Pin as B");
  const Parameters b = shown();
  ASSERT_EQ(explorer_->set_input("h", 2350.0), std::nullopt);
  frame();
  // B's lines as the core lays them out, each sample a point (the gaps of a dash are NaN points).
  Scene direct(b);
  const FoldLines& lines = direct.fold_lines();
  std::size_t points = 0;
  for (const FoldLine& line : lines.lines) {
    points += line.points_mm.size();
  }
  ASSERT_GT(lines.lines.size(), 1u);
  EXPECT_EQ(panel<FoldPlotPanel>().compare_lines_drawn(), static_cast<int>(lines.lines.size()));
  EXPECT_EQ(panel<FoldPlotPanel>().compare_points_drawn(), points);
  // "A positive fold", "A negative fold", "B positive fold (dashed)", "B negative fold (dashed)"
  // in place of the two fold entries, none cut at the plot's edge.
  EXPECT_EQ(panel<FoldPlotPanel>().plot_view().legend_entries, legend_without_b + 2);
  const std::string text = frame();
  for (const char* entry : {"A positive fold", "A negative fold", "B positive fold (dashed)",
                            "B negative fold (dashed)"}) {
    EXPECT_NE(text.find(entry), std::string::npos) << entry << "\n" << text;
  }
  const PanelRect plot = rect_of("fold_plot");
  EXPECT_EQ(cut_glyphs(plot.pos, ImVec2(plot.pos.x + plot.size.x, plot.pos.y + plot.size.y)),
            std::vector<std::string>{});
  click("Clear B");
  EXPECT_FALSE(document().compare().pinned());
  EXPECT_EQ(panel<FoldPlotPanel>().compare_lines_drawn(), 0);
  EXPECT_EQ(panel<FoldPlotPanel>().plot_view().legend_entries, legend_without_b);
}

TEST_F(ExplorerTest, TheThreeDViewDrawsBBesideAOnlyWhilePinned) {
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames, 0u)
      << "no B: nothing drawn for it";
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).mesh_uploads, 0u);
  click("Pin as B");
  const RenderCounters pinned = renderer_.cloth_counters(panel<ClothViewPanel>().b_view());
  EXPECT_GE(pinned.mesh_uploads, 1u);
  EXPECT_GE(pinned.frames, 1u);
  const std::uint64_t a_frames = renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).frames;
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  // Both cloths every frame, and B's picture kept while nothing it shows changes.
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).frames, a_frames + 3);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames, pinned.frames + 3);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).view_cache_hits,
            pinned.view_cache_hits + 3);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).mesh_uploads,
            pinned.mesh_uploads);
  // Each half is named. In the tiled half view a preset's long name would wrap over the cloth
  // and its supports: the letter alone; presented, the view is wide enough for the name.
  const auto drawn_in_cloth_view = [&](const std::string& words) {
    const PanelRect view = rect_of("cloth");
    const auto boundary = [&](std::size_t at) {
      return at >= last_text_.size() || last_text_[at] == ' ' || last_text_[at] == '\n';
    };
    for (std::size_t at = last_text_.find(words); at != std::string::npos;
         at = last_text_.find(words, at + 1)) {
      const ImVec2 p = last_positions_[at];
      if ((at == 0 || boundary(at - 1)) && boundary(at + words.size()) && p.x >= view.pos.x &&
          p.x < view.pos.x + view.size.x && p.y >= view.pos.y && p.y < view.pos.y + view.size.y) {
        return true;
      }
    }
    return false;
  };
  click("Clear B");
  click("Default: the Table 1 cloth");
  click("Pin as B");
  ASSERT_EQ(explorer_->set_input("h", 2000.0), std::nullopt);
  frame();
  EXPECT_TRUE(drawn_in_cloth_view("A")) << last_text_;
  EXPECT_TRUE(drawn_in_cloth_view("B")) << last_text_;
  EXPECT_FALSE(drawn_in_cloth_view("B: Default:")) << last_text_;
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  frame();
  frame();
  EXPECT_TRUE(drawn_in_cloth_view("B: Default: the Table 1 cloth,")) << last_text_;
  // The read-out over the presented view gives both fabrics' numbers.
  // (Drawn larger, its glyphs' offsets no longer read as one line: compared squeezed.)
  const std::string read_out = squeezed(last_text_);
  EXPECT_NE(read_out.find(detail::printf_string("A:n=%d", explorer_->scene().solution().n)),
            std::string::npos)
      << last_text_;
  EXPECT_NE(read_out.find(detail::printf_string("B:n=%d", document().compare().solution().n)),
            std::string::npos)
      << last_text_;
  // At the view's foot, below the cloth and its supports.
  const PanelRect presented = rect_of("cloth");
  EXPECT_GT(position_of("B: Default: the Table 1 cloth,").y,
            presented.pos.y + 0.8f * presented.size.y);
  ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
  frame();
  click("Clear B");
  const std::uint64_t cleared = renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames;
  frame();
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames, cleared);
}

TEST_F(ExplorerTest, TheSweepDrawsBsCurveBesideAs) {
  open_explorer("sweep");
  EXPECT_EQ(panel<AnalysisPanel>().sweep().curves_drawn(), 1);
  EXPECT_EQ(panel<AnalysisPanel>().sweep().compare_curves(), nullptr);
  click("Pin as B");
  const Parameters b = shown();
  ASSERT_EQ(explorer_->set_input("w", 2.0 * b.fabric.weight_N_per_mm2), std::nullopt);
  frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().curves_drawn(), 2);
  const SweepCurves* drawn = panel<AnalysisPanel>().sweep().compare_curves();
  ASSERT_NE(drawn, nullptr);
  // The sweep's own axis (h from 500 to 3000 mm, 200 steps) over B's parameters, from the core.
  const SweepCurves direct = sweep_curves(sweep(b, SweepAxis{"h", 500.0, 3000.0, 200, false}));
  EXPECT_EQ(drawn->x, direct.x);
  EXPECT_EQ(drawn->n, direct.n);
  EXPECT_EQ(drawn->z_max_mm, direct.z_max_mm);
  EXPECT_NE(panel<AnalysisPanel>().sweep().curves().z_max_mm, direct.z_max_mm) << "A moved";
}

TEST_F(ExplorerTest, APlayedScriptPinsSwapsAndClearsB) {
  const nlohmann::json script = {
      {"steps",
       {{{"expect", {{"compare", nullptr}}}},
        {{"click", "Pin as B"}},
        {{"expect", {{"compare.parameters.h_mm", 1400}}}},
        {{"drag", "h"}, {"dx", 80}},
        {{"expect", {{"parameters.h_mm", {1500, 5000}}, {"compare.parameters.h_mm", 1400}}}},
        {{"click", "Swap A and B"}},
        {{"expect", {{"parameters.h_mm", 1400}, {"compare.parameters.h_mm", {1500, 5000}}}}},
        {{"expect", {{"renderer.compare.frames", {1, 1e9}}}}},
        {{"click", "Clear B"}},
        {{"expect", {{"compare", nullptr}, {"parameters.h_mm", 1400}}}}}}};
  InputPlayer player(script, "test script");
  while (player.before_new_frame(ImGui::GetIO(), *explorer_)) {
    frame();
  }
  EXPECT_EQ(player.exit_status(), 0) << player.failure() << "\n" << frame();
  // Each of pin, swap and clear is one undo step that restores A and B together: the first undo
  // brings B back, the second the fabrics as they were before the swap, the third A before the
  // drag, the fourth no B.
  EXPECT_FALSE(document().compare().pinned());
  EXPECT_EQ(height_mm(), 1400.0);
  press('Z', true);
  ASSERT_TRUE(document().compare().pinned());
  const double dragged = document().compare().b().parameters.hanging.height_mm;
  EXPECT_GT(dragged, 1500.0);
  EXPECT_EQ(height_mm(), 1400.0);
  press('Z', true);
  EXPECT_EQ(height_mm(), dragged);
  ASSERT_TRUE(document().compare().pinned());
  EXPECT_EQ(document().compare().b().parameters.hanging.height_mm, 1400.0) << "B as pinned";
  press('Z', true);
  EXPECT_EQ(height_mm(), 1400.0);
  EXPECT_TRUE(document().compare().pinned());
  press('Z', true);
  EXPECT_FALSE(document().compare().pinned());
  press('Y', true);  // redo
  EXPECT_TRUE(document().compare().pinned());
}

// Each fabric carries the preset it came from through pin, swap, reset, undo and the session: a
// swap once left A tied to B's preset (the header said "Silk chiffon" over linen's values, and
// "Reset to preset" then made A chiffon too).
TEST_F(ExplorerTest, EachFabricKeepsItsOwnPresetThroughPinSwapResetUndoAndTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  const Preset linen = load_preset(kPresetsDir / "fabric-linen-medium.json");
  const Preset chiffon = load_preset(kPresetsDir / "fabric-silk-chiffon.json");
  explorer_->load_preset_file(kPresetsDir / "fabric-linen-medium.json");
  frame();
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Pin as B"}}}}}, [&] { frame(); }), 0);
  explorer_->load_preset_file(kPresetsDir / "fabric-silk-chiffon.json");
  frame();
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Swap A and B"}}}}}, [&] { frame(); }), 0);
  const auto expect_a_is = [&](const Preset& a, const Preset& b, const char* when) {
    SCOPED_TRACE(when);
    EXPECT_EQ(document().loaded().name, a.name);
    EXPECT_EQ(fabric_label(document()), a.name);
    EXPECT_EQ(shown(), a.parameters);
    EXPECT_FALSE(document().unsaved());
    ASSERT_TRUE(document().compare().pinned());
    EXPECT_EQ(document().compare().b().name, b.name);
    EXPECT_EQ(document().compare().b_origin().name, b.name);
    EXPECT_EQ(document().compare().b().parameters, b.parameters);
  };
  expect_a_is(linen, chiffon, "after the swap");
  const std::string header = squeezed(frame());
  EXPECT_NE(header.find(squeezed(linen.name)), std::string::npos) << header;
  EXPECT_EQ(header.find(squeezed(chiffon.name + " (unsaved changes)")), std::string::npos);

  // Reset to preset, after a change, gives linen back, not chiffon.
  ASSERT_EQ(explorer_->set_input("h", 2400.0), std::nullopt);
  frame();
  EXPECT_EQ(fabric_label(document()), linen.name + " (edited)");
  click("Reset to preset");
  expect_a_is(linen, chiffon, "after reset");

  // Undo the reset, the change and the swap: chiffon is A again, with linen as B.
  press('Z', true);
  press('Z', true);
  press('Z', true);
  expect_a_is(chiffon, linen, "before the swap");
  press('Y', true);  // redo the swap
  expect_a_is(linen, chiffon, "redone");

  // The session keeps B's preset with it.
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  expect_a_is(linen, chiffon, "restored");
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Swap A and B"}}}}}, [&] { frame(); }), 0);
  expect_a_is(chiffon, linen, "swapped back after a restart");
}

// The 3D view's look is the user's, as its switches are: the print, its size, the colouring and
// the z exaggeration come back with the session (a woven print once came back plain).
TEST_F(ExplorerTest, TheThreeDViewsLookIsRestoredWithTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  for (const auto& [key, value] :
       {std::pair{"print", "checks"}, std::pair{"print_mm", "25"},
        std::pair{"colour_by", "fold_sign"}, std::pair{"z_exaggeration", "4"}}) {
    ASSERT_EQ(explorer_->set_view(key, value), std::nullopt) << key;
  }
  frame();
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  const ClothStyle& style = panel<ClothViewPanel>().style();
  EXPECT_EQ(style.print, ClothStyle::Print::checks);
  EXPECT_EQ(style.print_mm, 25.0f);
  EXPECT_EQ(style.colour_by, ClothStyle::ColourBy::fold_sign);
  EXPECT_EQ(style.z_exaggeration, 4.0f);
}

TEST_F(ExplorerTest, BIsRestoredWithTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  click("Pin as B");
  const Parameters b = shown();
  ASSERT_EQ(explorer_->set_input("h", 2000.0), std::nullopt);
  frame();
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  ASSERT_TRUE(document().compare().pinned());
  EXPECT_EQ(document().compare().b().parameters, b);
  EXPECT_EQ(shown().hanging.height_mm, 2000.0);
  click("Clear B");
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(document().compare().pinned());
}

// The colour that the last frame's untextured fills give the point `at`, blended in drawing
// order over `under` (what the renderer shows beneath ImGui). Text and other textured triangles
// are left out: the question is what the fills let through.
ImVec4 composited_fill(ImVec2 at, ImVec4 under) {
  const ImDrawData& data = *ImGui::GetDrawData();
  const ImVec2 white = ImGui::GetIO().Fonts->TexUvWhitePixel;
  ImVec4 out = under;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback != nullptr || at.x < cmd.ClipRect.x || at.y < cmd.ClipRect.y ||
          at.x >= cmd.ClipRect.z || at.y >= cmd.ClipRect.w) {
        continue;
      }
      for (unsigned k = 0; k + 2 < cmd.ElemCount; k += 3) {
        const ImDrawVert* v[3];
        bool textured = false;
        for (unsigned j = 0; j < 3; ++j) {
          v[j] = &list.VtxBuffer[static_cast<int>(
              cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + k + j)])];
          textured = textured || v[j]->uv.x != white.x || v[j]->uv.y != white.y;
        }
        // Barycentric coordinates of `at`; outside the triangle when any is negative.
        const auto cross = [](ImVec2 a, ImVec2 b, ImVec2 c) {
          return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        };
        const float area = cross(v[0]->pos, v[1]->pos, v[2]->pos);
        if (textured || area == 0.0f) {
          continue;
        }
        const float b0 = cross(v[1]->pos, v[2]->pos, at) / area;
        const float b1 = cross(v[2]->pos, v[0]->pos, at) / area;
        const float b2 = 1.0f - b0 - b1;
        if (b0 < 0.0f || b1 < 0.0f || b2 < 0.0f) {
          continue;
        }
        ImVec4 colour(0, 0, 0, 0);
        for (unsigned j = 0; j < 3; ++j) {
          const ImVec4 c = ImGui::ColorConvertU32ToFloat4(v[j]->col);
          const float b = j == 0 ? b0 : j == 1 ? b1 : b2;
          colour = ImVec4(colour.x + b * c.x, colour.y + b * c.y, colour.z + b * c.z,
                          colour.w + b * c.w);
        }
        out = ImVec4(colour.x * colour.w + out.x * (1.0f - colour.w),
                     colour.y * colour.w + out.y * (1.0f - colour.w),
                     colour.z * colour.w + out.z * (1.0f - colour.w), 1.0f);
      }
    }
  }
  return out;
}

// Menus hide what is under them: panel text showing through a menu reads as one of its items.
// The View menu, opened by a click, is drawn over the panels; a point of its background comes out
// the same colour whether black or white is under the whole frame, in both themes.
TEST_F(ExplorerTest, AnOpenMenuLetsNothingUnderItShowThrough) {
  for (const char* theme : {"dark", "light"}) {
    SCOPED_TRACE(std::string(theme) + " theme");
    ASSERT_EQ(explorer_->set_view("theme", theme), std::nullopt);
    frame();
    click("View");
    const ImGuiWindow* menu = nullptr;
    for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
      if (window->Active && (window->Flags & ImGuiWindowFlags_Popup) != 0) {
        menu = window;
      }
    }
    ASSERT_NE(menu, nullptr) << "the View menu did not open";
    // Beside its items' text, halfway down, and inside the panels' area below the menu bar.
    const ImVec2 at(menu->Pos.x + menu->Size.x - 3.0f, menu->Pos.y + 0.5f * menu->Size.y);
    const ImVec4 over_black = composited_fill(at, ImVec4(0, 0, 0, 1));
    const ImVec4 over_white = composited_fill(at, ImVec4(1, 1, 1, 1));
    for (const auto& [black, white] :
         {std::pair{over_black.x, over_white.x}, std::pair{over_black.y, over_white.y},
          std::pair{over_black.z, over_white.z}}) {
      EXPECT_NEAR(black, white, 1.0f / 255.0f);
    }
    press(kEscape);
  }
}

TEST(Contrast, TheComparedFabricsFoldsAreAnotherHueThanAs) {
  // Their contrast is in the table of themed colours, read by
  // EveryThemedColourReadsOnWhatItIsDrawnOn.
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    // B reads apart from A's folds of the same sign: another hue, not a shade of it.
    const FoldColours a = fold_colours(light);
    const auto apart = [](ImVec4 p, ImVec4 q) {
      return std::abs(p.x - q.x) + std::abs(p.y - q.y) + std::abs(p.z - q.z);
    };
    EXPECT_GT(apart(kCompareB.get(light), a.positive), 0.5f);
    EXPECT_GT(apart(kCompareBNegative.get(light), a.negative), 0.5f);
  }
}

}  // namespace
}  // namespace foldlab::gui
