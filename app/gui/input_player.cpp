#include "app/gui/input_player.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <iterator>
#include <regex>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include <imgui_internal.h>  // the open popups, for a submenu over its parent

#include "app/common/inputs.hpp"
#include "app/gui/clipped_text.hpp"
#include "app/gui/drawn_glyphs.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/play_script.hpp"
#include "app/gui/surface.hpp"
#include "core/analysis/sweep.hpp"
#include "core/io/io.hpp"
#include "core/io/json_input.hpp"
#include "core/io/report.hpp"
#include "core/io/scene_report.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

using nlohmann::json;

// A field of the report by dotted path, or null when there is none.
const json* find_field(const json& report, const std::string& path) {
  const json* at = &report;
  std::string_view rest = path;
  while (true) {
    const std::size_t dot = rest.find('.');
    const std::string name(rest.substr(0, dot));
    if (at->is_array()) {  // "display.0": an element by its index
      std::size_t index = 0;
      const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), index);
      if (error != std::errc() || end != name.data() + name.size() || index >= at->size()) {
        return nullptr;
      }
      at = &(*at)[index];
    } else if (at->is_object() && at->contains(name)) {
      at = &(*at)[name];
    } else {
      return nullptr;
    }
    if (dot == std::string_view::npos) {
      return at;
    }
    rest.remove_prefix(dot + 1);
  }
}

bool holds(const json& got, const json& wanted) {
  if (wanted.is_array() && wanted.empty()) {
    return got == wanted;  // an empty list: "layout.clipped_text": []
  }
  if (wanted.is_array()) {
    return got.is_number() && got.get<double>() >= wanted[0].get<double>() &&
           got.get<double>() <= wanted[1].get<double>();
  }
  if (wanted.is_number() && got.is_number()) {
    const double a = got.get<double>();
    const double b = wanted.get<double>();
    return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
  }
  return got == wanted;
}

// The text one draw list shows, a line break where the baseline moves and a space where a gap
// after a glyph's advance is wider than half a space (a space draws nothing), with each byte's
// glyph box; it ends with a line break.
struct DrawnText {
  std::string text;
  std::vector<ImVec4> boxes;  // per byte of `text`
};

DrawnText drawn_text(const ImDrawList& list, const GlyphsByUv& glyphs, float space) {
  DrawnText out;
  const ImVector<ImDrawVert>& v = list.VtxBuffer;
  float last_x = -1e9f;
  float last_y = -1e9f;
  float last_advance = 0.0f;
  for (int i = 0; i + 3 < v.Size; ++i) {
    const ImFontGlyph* found = glyphs.find(v[i].uv);
    if (found == nullptr || v[i + 2].uv.x != found->U1 || v[i + 2].uv.y != found->V1) {
      continue;
    }
    const ImFontGlyph& glyph = *found;
    const float x = v[i].pos.x - glyph.X0;
    const float y = v[i].pos.y - glyph.Y0;
    const ImVec4 box(v[i].pos.x, v[i].pos.y, v[i + 2].pos.x, v[i + 2].pos.y);
    if (std::abs(y - last_y) > 1.0f) {
      out.text += '\n';
      out.boxes.push_back(box);
    } else if (x - (last_x + last_advance) > 0.5f * space) {
      out.text += ' ';
      out.boxes.push_back(box);
    }
    const std::size_t before = out.text.size();
    append_utf8(out.text, glyph.Codepoint);
    out.boxes.resize(out.boxes.size() + (out.text.size() - before), box);
    last_x = x;
    last_y = y;
    last_advance = glyph.AdvanceX;
    i += 3;
  }
  out.text += '\n';
  out.boxes.emplace_back();
  return out;
}

// What "in" names the main menu bar by: it is no panel.
constexpr std::string_view kMenuBarKey = "menu_bar";

// With a panel's key, whether the list is that panel's window or a window inside it (a scrolled
// table is a child window); without one, every list is.
bool drawn_in_panel(const ImDrawList& list, const std::string& panel_key) {
  if (panel_key.empty()) {
    return true;
  }
  const char* owner = list._OwnerName;
  const std::string_view name = owner == nullptr ? std::string_view() : owner;
  if (panel_key == kMenuBarKey) {
    return name == "##MainMenuBar";
  }
  const std::string id = "###" + panel_key;
  return name.ends_with(id) || name.find(id + "/") != std::string_view::npos;
}

// The centre of the first match of `label` that is a whole line of `drawn`. The first match
// inside a longer line goes to `inside`, unless that holds one already.
std::optional<ImVec2> find_whole_line(const DrawnText& drawn, const std::string& label,
                                      std::optional<ImVec2>& inside) {
  const std::string& text = drawn.text;
  for (std::size_t at = text.find(label); at != std::string::npos; at = text.find(label, at + 1)) {
    const ImVec4 first = drawn.boxes[at];
    const ImVec4 last = drawn.boxes[at + label.size() - 1];
    const ImVec2 centre(0.5f * (first.x + last.z), 0.5f * (first.y + last.w));
    const bool whole = (at == 0 || text[at - 1] == '\n') &&
                       (at + label.size() == text.size() || text[at + label.size()] == '\n');
    if (whole) {
      return centre;
    }
    if (!inside) {
      inside = centre;
    }
  }
  return std::nullopt;
}

// Where a text is drawn in the last frame, read from the glyph quads of its draw data (the
// words a user sees, whichever widget drew them). Prefers a whole line (a button, tab, list
// entry or menu item has its label alone) over a match inside longer text. With a panel's key,
// only in that panel's window and the windows inside it.
std::optional<ImVec2> find_label(const std::string& label, const std::string& panel_key = {}) {
  const ImDrawData* data = ImGui::GetDrawData();
  if (data == nullptr || !data->Valid) {
    return std::nullopt;
  }
  const ImFont* font = ImGui::GetFont();
  const GlyphsByUv glyphs(*font);
  const float space = font->FindGlyph(' ')->AdvanceX;
  std::optional<ImVec2> inside;
  // Top window first, as a person sees it: an open menu's item over a panel's button alike.
  for (int l = data->CmdListsCount - 1; l >= 0; --l) {
    const ImDrawList& list = *data->CmdLists[l];
    if (!drawn_in_panel(list, panel_key)) {
      continue;
    }
    if (const std::optional<ImVec2> whole =
            find_whole_line(drawn_text(list, glyphs, space), label, inside)) {
      return whole;
    }
  }
  return inside;
}

}  // namespace

namespace {}  // namespace

namespace {

// Every row of the input table: a number by its field name with the unit ("t_mm"), a choice by
// its key ("method").
json parameters_json(const Parameters& p) {
  json out = json::object();
  for (const InputSpec& spec : input_table()) {
    if (const std::optional<double> value = spec.value(p)) {
      out[std::string(spec.field)] = *value;
    } else {
      out[std::string(spec.key)] = std::string(spec.choice(p));
    }
  }
  return out;
}

// B, the fabric pinned beside A: null while none is.
json compare_json(Document& document) {
  if (!document.compare().pinned()) {
    return nullptr;
  }
  const Preset& b = document.compare().b();
  return {{"label", b.name},
          {"parameters", parameters_json(b.parameters)},
          {"solution", solution_to_json(document.compare().solution(), b.parameters)}};
}

bool toast_in_window(const Explorer& explorer) {
  const std::optional<PanelRect>& rect = explorer.toast_rect();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  return rect && rect->pos.x >= 0.0f && rect->pos.y >= 0.0f &&
         rect->pos.x + rect->size.x <= display.x && rect->pos.y + rect->size.y <= display.y;
}

// The smallest target the last frame gave a finger, in the screen's pixels and in CSS pixels
// (the page's; on the desktop the two are one).
json smallest_target_json(Explorer& explorer) {
  const SmallestTarget& smallest = smallest_target();
  const float ratio = explorer.appearance().pixel_ratio();
  return {{"height_px", smallest.height_px},
          {"height_css_px", ratio > 0.0f ? smallest.height_px / ratio : smallest.height_px},
          {"what", smallest.what}};
}

// Whether an open menu covers part of the menu it opened from: a submenu with no room beside its
// parent (a phone) opens over it, under the finger whose lift then picks what lies there.
// Where the innermost open popup is (x, y, w, h), or null.
json open_popup_rect() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  if (g.OpenPopupStack.empty() || g.OpenPopupStack.back().Window == nullptr) {
    return nullptr;
  }
  const ImGuiWindow* popup = g.OpenPopupStack.back().Window;
  return {{"x", popup->Pos.x}, {"y", popup->Pos.y}, {"w", popup->Size.x}, {"h", popup->Size.y}};
}

bool submenu_over_parent() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  for (int i = 1; i < g.OpenPopupStack.Size; ++i) {
    const ImGuiWindow* parent = g.OpenPopupStack[i - 1].Window;
    const ImGuiWindow* child = g.OpenPopupStack[i].Window;
    if (parent != nullptr && child != nullptr && parent->WasActive && child->WasActive &&
        parent->Rect().Overlaps(child->Rect())) {
      return true;
    }
  }
  return false;
}

json layout_json(Explorer& explorer) {
  const std::string presented = explorer.presented();
  json panels = json::object();
  for (const auto& [name, rect] : explorer.layout().panel_rects()) {
    panels[name] = {{"x", rect.pos.x}, {"y", rect.pos.y}, {"w", rect.size.x}, {"h", rect.size.y}};
  }
  // Each view's picture as drawn: how much of the window it really has, whatever its panel's size.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const double window_px2 = static_cast<double>(display.x) * display.y;
  DrawingAreas areas;
  for (const std::unique_ptr<Panel>& panel : explorer.panels()) {
    panel->drawing_areas(areas);
  }
  json drawing_areas = json::object();
  for (const auto& [name, rect] : areas) {
    drawing_areas[name] = {
        {"x", rect.pos.x},
        {"y", rect.pos.y},
        {"w", rect.size.x},
        {"h", rect.size.y},
        {"window_share",
         window_px2 > 0.0 ? static_cast<double>(rect.size.x) * rect.size.y / window_px2 : 0.0}};
  }
  json clipped = json::array();
  const ImDrawData* data = ImGui::GetDrawData();
  if (data != nullptr && !ImGui::GetIO().Fonts->Fonts.empty()) {
    for (const ClippedText& item : clipped_text(*data, *ImGui::GetIO().Fonts->Fonts[0])) {
      clipped.push_back({{"panel", item.panel}, {"text", item.text}, {"how", item.how}});
    }
  }
  const auto rects = [](const std::map<std::string, PanelRect>& named) {
    json out = json::object();
    for (const auto& [name, rect] : named) {
      out[name] = {{"x", rect.pos.x}, {"y", rect.pos.y}, {"w", rect.size.x}, {"h", rect.size.y}};
    }
    return out;
  };
  json tile_handles = json::array();
  for (const auto& [key, rect] : explorer.layout().handle_rects()) {
    tile_handles.push_back({{"edge", key},
                            {"x", rect.pos.x},
                            {"y", rect.pos.y},
                            {"w", rect.size.x},
                            {"h", rect.size.y}});
  }
  return {{"automatic", explorer.layout().automatic()},
          {"tile_handles", tile_handles},
          {"drawing_areas", drawing_areas},
          {"view_buttons", rects(explorer.view_buttons())},
          {"menu_bar_items", rects(explorer.menu_bar_items())},
          {"submenu_over_parent", submenu_over_parent()},
          {"clipped_text", clipped},
          {"smallest_target", smallest_target_json(explorer)},
          {"cramped", explorer.layout().cramped()},
          {"fills_window", explorer.layout().fills_window()},
          {"presented", presented.empty() ? json(nullptr) : json(presented)},
          {"presented_message", explorer.presented_message()},
          {"panels", panels}};
}

}  // namespace

json explorer_state_json(Explorer& explorer) {
  Document& document = explorer.document();
  Scene& scene = document.scene();
  const std::optional<std::string> refused = document.refusal();
  const std::string& modal = explorer.status().modal_title();
  // The system's clipboard may hold any bytes.
  const char* clipboard = ImGui::GetClipboardText();
  json state = explorer.report();  // every panel's keys, and "view"
  state.update(json{
      {"grid", std::to_string(scene.grid_nx()) + "x" + std::to_string(scene.grid_ny())},
      {"stats", scene_stats_to_json(scene)},
      {"solution", solution_to_json(scene.solution(), scene.parameters())},
      {"parameters", parameters_json(document.edited())},
      {"label", fabric_label(document)},  // A's name, "(edited)" after it once edited
      {"compare", compare_json(document)},
      {"refused", refused ? json(*refused) : json(nullptr)},
      {"dirty", document.unsaved()},
      {"session_unsaved", explorer.status().session_dirty()},
      {"modal", modal.empty() ? json(nullptr) : json(modal)},
      {"undo_depth", document.undo_depth()},
      {"display", {ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y}},
      {"message", explorer.status().message()},
      {"link", explorer.link()},
      {"toast", explorer.status().toast()},
      // Whether the whole toast lies inside the window, where it is read.
      {"toast_in_window", toast_in_window(explorer)},
      {"clipboard", detail::escaped(clipboard != nullptr ? clipboard : "")},
      {"popup_open", ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)},
      {"popup_rect", open_popup_rect()},
      {"file_problem", explorer.file_dialog().problem()},
      {"layout", layout_json(explorer)},
      {"appearance",
       {{"scale_percent", explorer.appearance().scale_percent()},
        {"light_theme", explorer.appearance().light_theme()},
        {"pixel_ratio", explorer.appearance().pixel_ratio()},
        {"coarse_pointer", explorer.appearance().coarse_pointer()}}},
  });
  return state;
}

InputPlayer::InputPlayer(const std::filesystem::path& script_path) {
  std::string text;
  try {
    text = read_text_file(script_path, kMaxScriptFileBytes);
  } catch (const ReadError& e) {
    throw app::InputError(std::string("--play ") + e.what());
  }
  json script;
  try {
    script = parse_json(text, "--play " + script_path.string());
  } catch (const JsonInputError& e) {
    throw app::InputError(e.what());
  }
  try {
    parse(script);
  } catch (const app::InputError& e) {
    throw app::InputError("--play " + script_path.string() + ":\n" + e.what());
  }
}

InputPlayer::InputPlayer(const json& script, const std::string& name) {
  try {
    parse(script);
  } catch (const app::InputError& e) {
    throw app::InputError(name + ":\n" + e.what());
  }
}

void InputPlayer::parse(const json& script) {
  const std::vector<std::string> problems = play_script_problems(script);
  if (!problems.empty()) {
    std::vector<std::string> lines;
    for (const std::string& problem : problems) {
      lines.push_back("  " + problem);
    }
    throw app::InputError(detail::join_lines(lines));
  }
  for (const json& step : script["steps"]) {
    steps_.push_back(step);
  }
  // ImGui sizes tables and child windows from what the previous frames held.
  queue_.assign(3, FrameInput{});
}

void InputPlayer::fail(std::size_t index, const std::string& why) {
  failure_ = "step " + std::to_string(index + 1) + " (" + detail::cut(steps_[index].dump(), 200) +
             "): " + why;
}

int InputPlayer::exit_status() const {
  return failure_.empty() ? app::kExitOk : 1;
}

// Where the panel that has `target` on screen draws it (Panel::locate), or nullopt.
std::optional<ImVec2> locate(const Explorer& explorer, std::string_view target,
                             std::initializer_list<double> at) {
  const std::vector<double> args(at);
  for (const std::unique_ptr<Panel>& panel : explorer.panels()) {
    if (std::optional<ImVec2> found = panel->locate(target, args)) {
      return found;
    }
  }
  return std::nullopt;
}

void InputPlayer::queue_press(ImVec2 from, ImVec2 to, int moves) {
  FrameInput hover;
  hover.mouse = from;
  queue_.push_back(hover);
  FrameInput down = hover;
  down.mouse_down = true;
  queue_.push_back(down);
  for (int i = 1; i <= moves; ++i) {
    const float f = static_cast<float>(i) / static_cast<float>(moves);
    down.mouse = ImVec2(from.x + f * (to.x - from.x), from.y + f * (to.y - from.y));
    queue_.push_back(down);
  }
  FrameInput up = down;
  up.mouse_down = false;
  queue_.push_back(up);
  queue_.push_back(up);
}

std::optional<SliderPlace> InputPlayer::find_slider(std::size_t index, const std::string& key,
                                                    Explorer& explorer) {
  const json sliders = explorer.report().value("sliders", json::object());
  if (!sliders.contains(key)) {
    fail(index, "the slider " + key + " is not shown");
    return std::nullopt;
  }
  const json& slider = sliders.at(key);
  const json& clip = slider.at("clip");
  return SliderPlace{ImVec2(slider.at("left").get<float>(), slider.at("top").get<float>()),
                     ImVec2(slider.at("right").get<float>(), slider.at("bottom").get<float>()),
                     slider.at("fraction").get<double>(),
                     ImVec2(clip.at(0).get<float>(), clip.at(1).get<float>()),
                     ImVec2(clip.at(2).get<float>(), clip.at(3).get<float>())};
}

// A person cannot press what the window does not show: a slider scrolled out of its panel or
// below a small window's edge. The point must be inside the slider's clip and the window.
bool InputPlayer::reachable(std::size_t index, const std::string& key, const SliderPlace& place,
                            ImVec2 at) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const ImVec2 lo(std::max(place.clip_min.x, 0.0f), std::max(place.clip_min.y, 0.0f));
  const ImVec2 hi(std::min(place.clip_max.x, display.x), std::min(place.clip_max.y, display.y));
  if (at.x >= lo.x && at.x < hi.x && at.y >= lo.y && at.y < hi.y) {
    return true;
  }
  fail(index,
       detail::printf_string("the slider %s is out of sight (its handle at x = %.0f, y = %.0f; "
                             "what can be seen of its panel: x %.0f to %.0f, y %.0f to %.0f)",
                             key.c_str(), at.x, at.y, lo.x, hi.x, lo.y, hi.y));
  return false;
}

bool InputPlayer::click_slider(std::size_t index, const json& step, Explorer& explorer) {
  const std::string key = step["click"].get<std::string>();
  const std::optional<SliderPlace> place = find_slider(index, key, explorer);
  if (!place) {
    return false;
  }
  // The frame's right edge itself is outside the item.
  const float x = place->min.x + step["at"].get<float>() * (place->max.x - place->min.x - 1.0f);
  const ImVec2 at(x, 0.5f * (place->min.y + place->max.y));
  if (!reachable(index, key, *place, at)) {
    return false;
  }
  queue_press(at, at, 0);
  // Ctrl+click opens the slider's text field, where a value is typed with its unit.
  const bool ctrl = step.value("ctrl", false);
  for (FrameInput& input : queue_) {
    input.ctrl = ctrl;
  }
  return true;
}

bool InputPlayer::click_label(std::size_t index, const std::string& label,
                              const std::string& panel_key) {
  const std::optional<ImVec2> at = find_label(label, panel_key);
  if (!at) {
    fail(index, "no visible \"" + label + "\"");
    return false;
  }
  queue_press(*at, *at, 0);
  return true;
}

void InputPlayer::queue_key(const Chord& chord, const ImGuiIO& io) {
  FrameInput mods;
  mods.mouse = mouse_;
  mods.ctrl = chord.ctrl;
  mods.shift = chord.shift;
  mods.alt = chord.alt;
  queue_.push_back(mods);
  FrameInput pressed = mods;
  pressed.key =
      chord.imgui >= 0 && io.KeyMap[chord.imgui] >= 0 ? io.KeyMap[chord.imgui] : chord.glfw;
  queue_.push_back(pressed);
  queue_.push_back(mods);
  FrameInput released;
  released.mouse = mouse_;
  queue_.push_back(released);
}

void InputPlayer::queue_text(const std::string& text) {
  // One character a frame, as hands type: a widget sees every text on the way.
  FrameInput typed;
  typed.mouse = mouse_;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t next = at + 1;
    while (next < text.size() && (static_cast<unsigned char>(text[next]) & 0xC0) == 0x80) {
      ++next;  // the continuation bytes of a UTF-8 character
    }
    typed.text = text.substr(at, next - at);
    queue_.push_back(typed);
    at = next;
  }
  typed.text.clear();
  queue_.push_back(typed);
}

bool InputPlayer::check_expect(std::size_t index, const json& expect, Explorer& explorer) {
  const json report = explorer_state_json(explorer);
  for (const auto& [path, wanted] : expect.items()) {
    const json* got = find_field(report, path);
    if (got == nullptr) {
      fail(index, "the report has no field " + path);
      return false;
    }
    if (!holds(*got, wanted)) {
      fail(index, path + " is " + got->dump() + ", expected " + wanted.dump());
      return false;
    }
  }
  return true;
}

bool InputPlayer::start_step(std::size_t index, ImGuiIO& io, Explorer& explorer) {
  const json& step = steps_[index];
  queue_.clear();
  queue_at_ = 0;
  switch (step_kind(step).id) {
    case StepKind::Id::drag:
      return drag_slider(index, step, explorer);
    case StepKind::Id::click:
      return step.contains("at") ? click_slider(index, step, explorer)
                                 : click_label(index, step["click"].get<std::string>(),
                                               step.value("in", std::string()));
    case StepKind::Id::click_photo:
      return click_photo(index, step, explorer);
    case StepKind::Id::key:
      queue_key(*parse_chord(step["key"].get<std::string>()), io);
      return true;
    case StepKind::Id::type:
      queue_text(step["type"].get<std::string>());
      return true;
    case StepKind::Id::resize:
      queue_resize(parse_frame_size(step["resize"].get<std::string>()));
      return true;
    case StepKind::Id::frames:
      queue_idle(step["frames"].get<std::size_t>(), step.value("until_idle", false));
      return true;
    case StepKind::Id::screenshot:
      queue_screenshot(step["screenshot"].get<std::string>());
      return true;
    case StepKind::Id::expect:
      return check_expect(index, step["expect"], explorer);
    case StepKind::Id::hover_sweep:
      return hover_sweep(index, step, explorer);
    case StepKind::Id::visible:
    case StepKind::Id::absent:
      return check_drawn(index, step);
  }
  return true;
}

bool InputPlayer::drag_slider(std::size_t index, const json& step, Explorer& explorer) {
  const std::string key = step["drag"].get<std::string>();
  if (key.starts_with(kTileEdgePrefix)) {
    return drag_tile_edge(index, step, explorer);
  }
  const std::optional<SliderPlace> place = find_slider(index, key, explorer);
  if (!place) {
    return false;
  }
  const ImVec2 from(slider_handle_x(*place, place->fraction), 0.5f * (place->min.y + place->max.y));
  if (!reachable(index, key, *place, from)) {
    return false;
  }
  queue_press(from, ImVec2(from.x + step["dx"].get<float>(), from.y), kDragMoves);
  // Shift held from the press to the release: the fine drag.
  for (FrameInput& input : queue_) {
    input.shift = step.value("shift", false);
  }
  return true;
}

bool InputPlayer::drag_tile_edge(std::size_t index, const json& step, Explorer& explorer) {
  const std::string edge = step["drag"].get<std::string>().substr(kTileEdgePrefix.size());
  for (const auto& [key, rect] : explorer.layout().handle_rects()) {
    if (key == edge) {
      // A finger pressed on the middle of the grip, as drawn in the last frame.
      const ImVec2 from(rect.pos.x + 0.5f * rect.size.x, rect.pos.y + 0.5f * rect.size.y);
      queue_press(from, ImVec2(from.x + step.value("dx", 0.0f), from.y + step.value("dy", 0.0f)),
                  kDragMoves);
      return true;
    }
  }
  fail(index, "the edge " + edge + " shows no grip (a coarse pointer's, between tiles)");
  return false;
}

bool InputPlayer::click_photo(std::size_t index, const json& step, Explorer& explorer) {
  const std::optional<ImVec2> at =
      locate(explorer, "photo_pixel",
             {step["click_photo"][0].get<double>(), step["click_photo"][1].get<double>()});
  if (!at) {
    fail(index, "no photo is loaded");
    return false;
  }
  queue_press(*at, *at, 0);
  return true;
}

void InputPlayer::queue_resize(std::optional<FrameSize> size) {
  FrameInput resized;
  resized.mouse = mouse_;
  resized.resize = size;
  queue_.push_back(resized);
  resized.resize.reset();
  queue_.insert(queue_.end(), 3, resized);
}

void InputPlayer::queue_idle(std::size_t frames, bool until_idle) {
  FrameInput idle;
  idle.mouse = mouse_;
  idle.until_idle = until_idle;
  queue_.assign(frames, idle);
}

void InputPlayer::queue_screenshot(const std::string& png_path) {
  FrameInput shot;
  shot.mouse = mouse_;
  shot.screenshot = png_path;
  queue_.push_back(shot);
}

bool InputPlayer::hover_sweep(std::size_t index, const json& step, Explorer& explorer) {
  const std::string plot = step["hover_sweep"].get<std::string>();
  const std::string target = plot == "n" ? "sweep_n" : plot == "Q" ? "sweep_Q" : "sweep_z_max";
  const std::optional<ImVec2> at = locate(explorer, target, {step["x"].get<double>()});
  if (!at) {
    fail(index, "the Sweep tab's " + plot + " plot shows no point to hover");
    return false;
  }
  // Held for a few frames: the plot sees the mouse, then its tooltip is drawn.
  FrameInput hover;
  hover.mouse = *at;
  queue_.assign(3, hover);
  return true;
}

bool InputPlayer::check_drawn(std::size_t index, const json& step) {
  // What a person reads, not what the report says: drawn glyphs, in one panel or anywhere.
  const bool wanted = step.contains("visible");
  const std::string text = step[wanted ? "visible" : "absent"].get<std::string>();
  const std::string panel = step.value("in", std::string());
  if (find_label(text, panel).has_value() != wanted) {
    fail(index, "\"" + text + "\" is " + (wanted ? "not shown" : "shown") +
                    (panel.empty() ? "" : " in " + panel));
    return false;
  }
  return true;
}

bool InputPlayer::before_new_frame(ImGuiIO& io, Explorer& explorer) {
  // The headless surface has no key map: give it the window's, so that chords read the same.
  for (const KeyName& key : named_keys()) {
    if (key.imgui >= 0 && io.KeyMap[key.imgui] < 0) {
      io.KeyMap[key.imgui] = key.glfw;
    }
  }
  // A wait for the panels ends, after one frame at least, as soon as none is busy: how many frames
  // a solve takes depends on the machine.
  if (queue_at_ > 0 && queue_at_ < queue_.size() && queue_[queue_at_].until_idle &&
      !explorer.busy()) {
    queue_at_ = queue_.size();
  }
  while (failure_.empty() && queue_at_ >= queue_.size()) {
    if (next_step_ >= steps_.size()) {
      return false;
    }
    const std::size_t index = next_step_++;
    if (!start_step(index, io, explorer)) {
      return false;
    }
  }
  if (!failure_.empty()) {
    return false;
  }
  const FrameInput& input = queue_[queue_at_++];
  mouse_ = input.mouse;
  // Left of the window is no pointer, except while a button is held (and on its release): a
  // window system keeps reporting a dragging pointer outside the window, at negative x too.
  const bool dragging = input.mouse_down || io.MouseDown[0];
  io.MousePos = input.mouse.x < 0.0f && !dragging ? ImVec2(-FLT_MAX, -FLT_MAX) : input.mouse;
  std::fill(std::begin(io.MouseDown), std::end(io.MouseDown), false);
  io.MouseDown[0] = input.mouse_down;
  io.MouseWheel = 0.0f;
  io.MouseWheelH = 0.0f;
  std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
  io.KeyCtrl = input.ctrl;
  io.KeyShift = input.shift;
  io.KeyAlt = input.alt;
  io.KeySuper = false;
  io.KeysDown[kLeftCtrl] = input.ctrl;
  io.KeysDown[kLeftShift] = input.shift;
  io.KeysDown[kLeftAlt] = input.alt;
  if (input.key >= 0) {
    io.KeysDown[input.key] = true;
  }
  io.InputQueueCharacters.resize(0);
  if (!input.text.empty()) {
    io.AddInputCharactersUTF8(input.text.c_str());
  }
  if (!input.screenshot.empty()) {
    screenshot_ = input.screenshot;
  }
  if (input.resize) {
    resize_ = input.resize;
  }
  return true;
}

std::optional<std::string> InputPlayer::take_screenshot_request() {
  return std::exchange(screenshot_, std::nullopt);
}

std::optional<FrameSize> InputPlayer::take_resize_request() {
  return std::exchange(resize_, std::nullopt);
}

}  // namespace foldlab::gui
