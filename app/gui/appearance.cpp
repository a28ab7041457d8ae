#include "app/gui/appearance.hpp"

#include <algorithm>
#include <cmath>
#include <system_error>

namespace foldlab::gui {
namespace {

double linear(double srgb) {
  return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4);
}

// Latin-1 for text and units (², ³, ×, °), Greek for the paper's symbols, and the punctuation,
// arrows and operators the equations use (′, −, …, ↦, ≥, √, Σ).
const ImWchar kGlyphRanges[] = {
    0x0020, 0x00FF,  // Basic Latin, Latin-1 Supplement
    0x0370, 0x03FF,  // Greek
    0x2010, 0x205E,  // general punctuation: dashes, primes, ellipsis
    0x2190, 0x21FF,  // arrows
    0x2200, 0x22FF,  // mathematical operators
    0,
};

constexpr float kDefaultFontSizePx = 13.0f;  // ImGui's built-in ProggyClean

// A slider's handle: the least width of the notches that mark it (notched_slider), and translucent
// where ImGui draws a whole handle over a value (a colour picker's sliders).
constexpr float kGrabWidthPx = 4.0f;
constexpr float kGrabAlpha = 0.45f;
constexpr float kFrameBorderAlpha = 0.55f;

}  // namespace

bool add_ui_font(ImFontAtlas& atlas, const std::filesystem::path& font_file, float scale) {
  if (!font_file.empty()) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(font_file, ec) &&
        atlas.AddFontFromFileTTF(font_file.string().c_str(), std::round(kUiFontPx * scale), nullptr,
                                 kGlyphRanges) != nullptr) {
      return true;
    }
  }
  // ProggyClean is a bitmap font: whole multiples stay sharp, others are still better than
  // FontGlobalScale's stretched texture.
  ImFontConfig config;
  config.SizePixels = std::round(kDefaultFontSizePx * scale);
  atlas.AddFontDefault(&config);
  return false;
}

ImGuiStyle theme_style(bool light_theme) {
  ImGuiStyle style;
  if (light_theme) {
    ImGui::StyleColorsLight(&style);
  } else {
    ImGui::StyleColorsDark(&style);
  }
  // Square, opaque panels whose backgrounds the renderer fills: ImGui draws none of its own.
  style.WindowRounding = 0.0f;
  style.Colors[ImGuiCol_WindowBg].w = 0.0f;
  // Menus, lists and tooltips hide what is under them: panel text showing through a menu reads
  // as one of its items.
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;
  // ImGui's greys for hints and disabled text read at 2.4:1 on the light theme's background.
  style.Colors[ImGuiCol_TextDisabled] = kDimText.get(light_theme);
  // An unchecked checkbox or an empty field barely differs from the panel (near-white on the
  // light grey, a dim blue on the dark): an outline keeps its edge at 3:1 or more (WCAG 1.4.11,
  // non-text contrast).
  style.FrameBorderSize = 1.0f;
  style.Colors[ImGuiCol_Border] = light_theme ? ImVec4(0.0f, 0.0f, 0.0f, kFrameBorderAlpha)
                                              : ImVec4(1.0f, 1.0f, 1.0f, kFrameBorderAlpha);
  style.GrabMinSize = kGrabWidthPx;
  if (light_theme) {
    // ImGui's pale blue handle at any alpha is under 2:1 on the white field: from the back of a
    // room the handles vanish. An opaque middle blue reads at 3:1 on the field and still carries
    // the black value over it at 4.5:1.
    style.Colors[ImGuiCol_SliderGrab] = ImVec4(0.20f, 0.52f, 0.95f, 1.0f);
    style.Colors[ImGuiCol_SliderGrabActive] = ImVec4(0.24f, 0.56f, 1.0f, 1.0f);
  } else {
    style.Colors[ImGuiCol_SliderGrab].w = kGrabAlpha;
    style.Colors[ImGuiCol_SliderGrabActive].w = kGrabAlpha + 0.15f;
  }
  return style;
}

std::span<const ThemedColourUse> themed_colours() {
  static const ThemedColourUse uses[] = {
      {"error text", &kErrorText, Backdrop::window},
      {"success text", &kOkText, Backdrop::window},
      {"note text", &kNoteText, Backdrop::window},
      {"dim text and hints", &kDimText, Backdrop::window_and_plot},
      {"section title", &kSectionText, Backdrop::window},
      {"supports", &kSupportMarker, Backdrop::plot},
      {"sweep curve, A's label", &kSweepCurve, Backdrop::window_and_plot},
      {"paper's points", &kPaperPoint, Backdrop::window_and_plot},
      {"current value", &kCurrentValue, Backdrop::plot},
      {"L'/L per iterate, next n = n", &kIterateLine, Backdrop::window_and_plot},
      {"tolerance band", &kToleranceBand, Backdrop::window_and_plot},
      {"guide", &kGuideLine, Backdrop::window_and_plot},
      {"staircase", &kStairLine, Backdrop::window_and_plot},
      {"refused slider", &kRefusedFrame, Backdrop::under_text},
      {"sweep band", &kRegimeBandFill, Backdrop::under_dim_text},
      {"refused sweep band", &kRefusedBandFill, Backdrop::under_dim_text},
      {"B's curve, folds and label", &kCompareB, Backdrop::window_and_plot},
      {"B's negative folds", &kCompareBNegative, Backdrop::plot},
  };
  return uses;
}

double relative_luminance(double r, double g, double b) {
  return 0.2126 * linear(r) + 0.7152 * linear(g) + 0.0722 * linear(b);
}

double contrast_ratio(ImVec4 a, ImVec4 b) {
  const double la = relative_luminance(a.x, a.y, a.z);
  const double lb = relative_luminance(b.x, b.y, b.z);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

ImVec4 blend_over(ImVec4 over, ImVec4 under) {
  const float a = over.w;
  return ImVec4(over.x * a + under.x * (1 - a), over.y * a + under.y * (1 - a),
                over.z * a + under.z * (1 - a), 1.0f);
}

int clamp_ui_scale(int percent) {
  return std::clamp(percent, kMinUiScalePercent, kMaxUiScalePercent);
}

FoldColours fold_colours(bool light_theme) {
  if (light_theme) {
    return {ImVec4(0.10f, 0.25f, 0.65f, 1.0f), ImVec4(0.75f, 0.10f, 0.10f, 1.0f)};
  }
  return {ImVec4(0.55f, 0.75f, 1.00f, 1.0f), ImVec4(1.00f, 0.55f, 0.50f, 1.0f)};
}

bool style_is_light() {
  const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  return relative_luminance(bg.x, bg.y, bg.z) > 0.5;
}

ImVec4 plot_background(bool light_theme) {
  return blend_over(theme_style(light_theme).Colors[ImGuiCol_FrameBg],
                    window_background(light_theme));
}

ImVec4 window_background(bool light_theme) {
  ImVec4 window = theme_style(light_theme).Colors[ImGuiCol_WindowBg];
  window.w = 1.0f;  // the renderer fills it opaque
  return window;
}

void Appearance::request(int scale_percent, bool light_theme) {
  scale_percent_ = clamp_ui_scale(scale_percent);
  light_theme_ = light_theme;
}

void Appearance::set_pixel_ratio(float ratio) {
  constexpr float kMinPixelRatio = 0.25f;
  constexpr float kMaxPixelRatio = 8.0f;
  pixel_ratio_ = std::isfinite(ratio) ? std::clamp(ratio, kMinPixelRatio, kMaxPixelRatio) : 1.0f;
}

ImGuiStyle touch_style(ImGuiStyle style, float font_px, float target_px, float gap_px) {
  style.FramePadding.y = std::max(style.FramePadding.y, 0.5f * (target_px - font_px));
  style.ItemSpacing.y = std::max(style.ItemSpacing.y, gap_px);
  // A slider's handle as wide as a fingertip's contact is seen, the scrollbars as wide as a
  // target is tall.
  style.GrabMinSize = std::max(style.GrabMinSize, 0.5f * target_px);
  style.ScrollbarSize = std::max(style.ScrollbarSize, 0.5f * target_px);
  return style;
}

void Appearance::apply(Renderer& renderer) {
  if (!pending()) {
    return;
  }
  const float ratio = pixel_ratio();
  const bool coarse = coarse_pointer();
  const float scale = static_cast<float>(scale_percent_) / 100.0f * ratio;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  notice_.clear();
  if (!add_ui_font(*io.Fonts, font_file_, scale) && !font_file_.empty()) {
    notice_ = "The font " + font_file_.string() +
              " is missing (Debian package fonts-dejavu-core): Greek letters show as '?'.";
  }
  io.Fonts->Build();
  io.FontGlobalScale = 1.0f;
  ImGuiStyle style = theme_style(light_theme_);
  style.ScaleAllSizes(scale);
  // A double click's two clicks land within this (ImGui's 6 px): a finger's second tap lands
  // wider, and the screen's pixels are device pixels.
  constexpr float kMouseDoubleClickPx = 6.0f;
  constexpr float kFingerDoubleTapPx = 24.0f;
  if (coarse) {
    // The font built, which is ImGui's 13 px one when the TTF is missing.
    const float font_px =
        io.Fonts->Fonts.empty() ? kUiFontPx * scale : io.Fonts->Fonts[0]->FontSize;
    style = touch_style(style, font_px, kTouchTargetPx * ratio, kTouchRowGapPx * ratio);
    io.ConfigFlags |= ImGuiConfigFlags_IsTouchScreen;
    io.MouseDoubleClickMaxDist = kFingerDoubleTapPx * ratio;
  } else {
    io.ConfigFlags &= ~ImGuiConfigFlags_IsTouchScreen;
    io.MouseDoubleClickMaxDist = kMouseDoubleClickPx * ratio;
  }
  ImGui::GetStyle() = style;
  renderer.fonts_changed();
  applied_ = true;
  applied_scale_percent_ = scale_percent_;
  applied_light_theme_ = light_theme_;
  applied_pixel_ratio_ = ratio;
  applied_coarse_pointer_ = coarse;
}

void Appearance::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.KeyCtrl) {
    return;
  }
  // The window's key codes are GLFW's: printable keys are their ASCII codes, the keypad's are
  // 320 + digit, 333 (minus) and 334 (plus).
  constexpr int kKeypad0 = 320;
  constexpr int kKeypadMinus = 333;
  constexpr int kKeypadPlus = 334;
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed('=') || pressed(kKeypadPlus)) {
    request(scale_percent_ + kUiScaleStepPercent, light_theme_);
  } else if (pressed('-') || pressed(kKeypadMinus)) {
    request(scale_percent_ - kUiScaleStepPercent, light_theme_);
  } else if (pressed('0') || pressed(kKeypad0)) {
    request(kMinUiScalePercent, light_theme_);
  }
}

void Appearance::view_settings(ViewSettings& settings) {
  static constexpr std::string_view kThemeNames[] = {"dark", "light"};
  settings.add_choice_by(
      "theme", kThemeNames, kEveryUse, [this] { return light_theme_ ? 1u : 0u; },
      [this](std::size_t light) { request(scale_percent_, light == 1); });
  settings.add_number_by(
      "scale", {kMinUiScalePercent, kMaxUiScalePercent, " (percent)"}, kEveryUse,
      [this] { return scale_percent_; },
      [this](double percent) { request(static_cast<int>(std::lround(percent)), light_theme_); });
}

void Appearance::emulation_settings(ViewSettings& settings) {
  constexpr float kMaxEmulatedRatio = 8.0f;
  settings.add_number(
      "device_pixel_ratio", &emulated_pixel_ratio_,
      ViewRange<float>{0.0f, kMaxEmulatedRatio, " (device pixels per CSS pixel; 0: the screen's)"},
      kScripted | kReported);
  static constexpr std::string_view kPointerNames[] = {"screen", "fine", "coarse"};
  settings.add_choice("pointer", &emulated_pointer_, kPointerNames, kScripted | kReported);
}

}  // namespace foldlab::gui
