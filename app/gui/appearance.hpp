// How the explorer looks: the font (a TTF with Greek, so that ν, σ, π and Σ read as in the paper),
// the UI scale and the dark or light theme, and the colours whose contrast against their
// background must stay readable on a projector in either theme.
#pragma once

#include <algorithm>
#include <filesystem>
#include <span>
#include <string>

#include <imgui.h>

#include "app/gui/view_settings.hpp"

#include "app/gui/renderer.hpp"

namespace foldlab::gui {

// WCAG 2 relative luminance of an sRGB colour (components in [0, 1]) and the contrast ratio of
// two colours, (L_lighter + 0.05) / (L_darker + 0.05): 1 for equal colours, 21 for black on white.
double relative_luminance(double r, double g, double b);
double contrast_ratio(ImVec4 a, ImVec4 b);
// `over` composited onto an opaque `under` with over's alpha: what a translucent fill looks like.
ImVec4 blend_over(ImVec4 over, ImVec4 under);

// The debian fonts-dejavu-core font the window uses.
inline const std::filesystem::path kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The UI font's size at 100 %, in pixels.
inline constexpr float kUiFontPx = 15.0f;
// Adds the UI font to `atlas` at `scale` times its size at 100 %: `font_file` (a TTF), or ImGui's
// built-in font when that is empty or cannot be read (then false).
bool add_ui_font(ImFontAtlas& atlas, const std::filesystem::path& font_file, float scale);

// The least height of a target for a finger, in CSS pixels (WCAG 2.5.5's 44 px, Apple's 44 pt;
// Android asks 48 dp), and the least gap between two rows of targets.
inline constexpr float kTouchTargetPx = 44.0f;
inline constexpr float kTouchRowGapPx = 8.0f;
// A style for fingers: frames (sliders, buttons, checkboxes, combos) grown to `target_px` tall
// with text of `font_px`, and rows `gap_px` apart at least; all in the style's own pixels.
ImGuiStyle touch_style(ImGuiStyle style, float font_px, float target_px, float gap_px);

inline constexpr int kMinUiScalePercent = 100;
inline constexpr int kMaxUiScalePercent = 250;
inline constexpr int kUiScaleStepPercent = 10;
int clamp_ui_scale(int percent);

// The fold colours of the 2D plot and the results for a theme: each has at least 4.5:1 contrast
// against the plot's background in that theme.
struct FoldColours {
  ImVec4 positive;
  ImVec4 negative;
};
FoldColours fold_colours(bool light_theme);
// Whether the current ImGui style is a light one (by its window background's luminance).
bool style_is_light();
// The plot area's background as drawn: the theme's frame fill over its window background.
ImVec4 plot_background(bool light_theme);

// The window's background as the renderer fills it, opaque: what text is read against.
ImVec4 window_background(bool light_theme);

// The style of a theme before scaling: ImGui's dark or light colours with the explorer's changes
// (hints and handles that keep their text readable, square opaque panels).
ImGuiStyle theme_style(bool light_theme);

// A colour with one value per theme, each with at least 4.5:1 contrast against what it is drawn
// on in that theme. Converts to the current theme's value, so it reads like a plain ImVec4.
struct ThemedColour {
  ImVec4 dark;
  ImVec4 light;
  ImVec4 get(bool light_theme) const { return light_theme ? light : dark; }
  operator ImVec4() const { return get(style_is_light()); }  // NOLINT: used as an ImVec4
  ImU32 u32() const { return ImGui::ColorConvertFloat4ToU32(*this); }
};
// Text colours, against the window background: an error, a success, a warning or note, a dim
// remark, a section title.
inline const ThemedColour kErrorText{{1.00f, 0.45f, 0.40f, 1.0f}, {0.70f, 0.05f, 0.05f, 1.0f}};
inline const ThemedColour kOkText{{0.55f, 0.85f, 0.55f, 1.0f}, {0.05f, 0.45f, 0.10f, 1.0f}};
inline const ThemedColour kNoteText{{1.00f, 0.78f, 0.35f, 1.0f}, {0.60f, 0.30f, 0.00f, 1.0f}};
inline const ThemedColour kDimText{{0.65f, 0.65f, 0.70f, 1.0f}, {0.35f, 0.35f, 0.38f, 1.0f}};
inline const ThemedColour kSectionText{{0.55f, 0.75f, 1.00f, 1.0f}, {0.10f, 0.30f, 0.65f, 1.0f}};
// Marks on the plots, against the plot background: the supports on the fold plot; the model's
// curve, the paper's points and the current value on the sweeps.
inline const ThemedColour kSupportMarker{{0.94f, 0.78f, 0.24f, 1.0f}, {0.55f, 0.35f, 0.00f, 1.0f}};
inline const ThemedColour kSweepCurve{{0.35f, 0.67f, 1.00f, 1.0f}, {0.05f, 0.35f, 0.75f, 1.0f}};
inline const ThemedColour kPaperPoint{{1.00f, 0.47f, 0.24f, 1.0f}, {0.75f, 0.25f, 0.00f, 1.0f}};
inline const ThemedColour kCurrentValue{{0.94f, 0.86f, 0.35f, 1.0f}, {0.45f, 0.40f, 0.00f, 1.0f}};
// The Method tab's plots and their key in words beside them (so against both backgrounds): L′/L
// per iterate, the tolerance band's edges, the diagonal guide, the staircase and the map.
inline const ThemedColour kIterateLine{{0.35f, 0.67f, 1.00f, 1.0f}, {0.05f, 0.33f, 0.72f, 1.0f}};
inline const ThemedColour kToleranceBand{{0.47f, 0.80f, 0.47f, 1.0f}, {0.05f, 0.42f, 0.10f, 1.0f}};
inline const ThemedColour kGuideLine{{0.65f, 0.65f, 0.70f, 1.0f}, {0.35f, 0.35f, 0.38f, 1.0f}};
inline const ThemedColour kStairLine{{1.00f, 0.55f, 0.30f, 1.0f}, {0.70f, 0.25f, 0.00f, 1.0f}};
// A slider's frame while its value is refused; the theme's text is read on it.
inline const ThemedColour kRefusedFrame{{0.55f, 0.12f, 0.10f, 1.0f}, {1.00f, 0.78f, 0.76f, 1.0f}};

// The sweep's regime bands over the plot, named in dim text: one the model solves, one it refuses.
inline const ThemedColour kRegimeBandFill{{0.59f, 0.59f, 0.63f, 0.12f},
                                          {0.59f, 0.59f, 0.63f, 0.24f}};
inline const ThemedColour kRefusedBandFill{{0.90f, 0.35f, 0.31f, 0.20f},
                                           {0.90f, 0.35f, 0.31f, 0.24f}};

// What a themed colour is drawn on: the window, the plot's data area, either (a plot's line with
// its key in words beside the plot), under the theme's own text (a frame's fill), or over the
// plot under dim text (a band).
enum class Backdrop { window, plot, window_and_plot, under_text, under_dim_text };
struct ThemedColourUse {
  const char* name;
  const ThemedColour* colour;
  Backdrop on;
};
// Every themed colour a user must read, with what it is drawn on: the table the contrast test
// goes through.
std::span<const ThemedColourUse> themed_colours();
// The fabric pinned as B in an A/B comparison, against the plot background and, for its label,
// the window background: its sweep curve and its positive folds, and its negative folds. A keeps
// kSweepCurve and the fold colours.
inline const ThemedColour kCompareB{{0.45f, 0.88f, 0.55f, 1.0f}, {0.00f, 0.42f, 0.18f, 1.0f}};
inline const ThemedColour kCompareBNegative{{0.96f, 0.62f, 0.96f, 1.0f},
                                            {0.55f, 0.10f, 0.60f, 1.0f}};

// Builds the font atlas and the style for a scale and theme. Call outside a frame (between
// ImGui::Render and ImGui::NewFrame); the renderer re-uploads the atlas.
class Appearance {
 public:
  // `font_file` empty: ImGui's built-in font, with no notice (unit tests).
  explicit Appearance(std::filesystem::path font_file) : font_file_(std::move(font_file)) {}

  int scale_percent() const { return scale_percent_; }
  bool light_theme() const { return light_theme_; }
  // Takes effect at the next apply(); the scale is clamped to 100-250 %.
  void request(int scale_percent, bool light_theme);
  // `theme` (dark, light) and `scale` (text size in percent), remembered, scripted and reported.
  void view_settings(ViewSettings& settings);
  // Device pixels per pixel of the layout the user sees (the page's devicePixelRatio, 1 on the
  // desktop): fonts and sizes are built at scale_percent times this, so that the window, sized in
  // device pixels, keeps the layout of a ratio-1 screen with crisp text. Takes effect at the next
  // apply(); kept within 0.25-8.
  void set_pixel_ratio(float ratio);
  // The ratio in use: the screen's, or the one `device_pixel_ratio` emulates.
  float pixel_ratio() const {
    return emulated_pixel_ratio_ > 0.0f ? std::max(emulated_pixel_ratio_, 0.25f) : pixel_ratio_;
  }
  // Whether the explorer is worked with fingers (the page's coarse pointer; never on the
  // desktop): then every frame, checkbox and slider is at least kTouchTargetPx tall, rows stand
  // further apart, a double tap may land a finger's width from the first tap, the hints speak
  // of fingers (hint_words: ImGuiConfigFlags_IsTouchScreen) and a slider's drag is finer the
  // farther the finger is from it. Takes effect at the next apply().
  void set_coarse_pointer(bool coarse) { coarse_pointer_ = coarse; }
  bool coarse_pointer() const {
    return emulated_pointer_ == EmulatedPointer::screen
               ? coarse_pointer_
               : emulated_pointer_ == EmulatedPointer::coarse;
  }
  // `device_pixel_ratio` and `pointer`: a phone's or a tablet's screen on any other (a laptop
  // draws what a class's phones show, a test checks it), scripted and reported, never
  // remembered. A ratio of 0 and the pointer `screen` take the screen's own.
  void emulation_settings(ViewSettings& settings);
  // Rebuilds the fonts and the style if a request changed them (or on the first call).
  void apply(Renderer& renderer);
  // A request that the next apply() will build: the frame just drawn is laid out with the old
  // fonts.
  bool pending() const {
    return !applied_ || applied_scale_percent_ != scale_percent_ ||
           applied_light_theme_ != light_theme_ || applied_pixel_ratio_ != pixel_ratio() ||
           applied_coarse_pointer_ != coarse_pointer();
  }
  // Ctrl + / Ctrl - / Ctrl 0 within a frame: requests the new scale.
  void handle_shortcuts();
  const std::filesystem::path& font_file() const { return font_file_; }
  // Why the TTF was not used (empty when it was, or when none was asked for).
  const std::string& notice() const { return notice_; }

 private:
  std::filesystem::path font_file_;
  int scale_percent_ = kMinUiScalePercent;
  bool light_theme_ = false;
  float pixel_ratio_ = 1.0f;
  enum class EmulatedPointer { screen, fine, coarse };
  float emulated_pixel_ratio_ = 0.0f;  // 0: the screen's
  EmulatedPointer emulated_pointer_ = EmulatedPointer::screen;
  bool applied_ = false;
  float applied_pixel_ratio_ = 1.0f;
  bool coarse_pointer_ = false;
  bool applied_coarse_pointer_ = false;
  int applied_scale_percent_ = 0;
  bool applied_light_theme_ = false;
  std::string notice_;
};

}  // namespace foldlab::gui
