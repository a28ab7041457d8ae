// The explorer in a test process: an ImGui context with no platform and no GL (fonts built, a
// display size set), the null renderer, and Explorer::frame() between NewFrame and Render. What a
// frame shows is read back from the glyphs in ImGui's draw data, so the checks see the words and
// numbers a user would read. Every test_explorer_*.cpp shares this fixture.
#pragma once

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

namespace fs = std::filesystem;
inline const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

// Input playback with the null renderer: the script's frames run in this process.
inline int play(Explorer& explorer, const nlohmann::json& script,
                const std::function<void()>& frame) {
  InputPlayer player(script, "test script");
  while (player.before_new_frame(ImGui::GetIO(), explorer)) {
    frame();
  }
  if (!player.failure().empty()) {
    std::cerr << "play: " << player.failure() << "\n";
  }
  return player.exit_status();
}

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

  // Text without its spaces, no-break spaces and line breaks: a wrapped sentence, or one read back
  // glyph by glyph with gaps of its own, reads as one.
  static std::string squeezed(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text.compare(i, 2, "\u00A0") == 0) {
        ++i;
      } else if (text[i] != ' ' && text[i] != '\n') {
        out += text[i];
      }
    }
    return out;
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

}  // namespace foldlab::gui
