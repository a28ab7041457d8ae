#include "app/gui/panels/parameters_panel.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/gui/panels/widgets.hpp"
#include "core/analysis/sweep.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

constexpr double kGramsPerSquareMetrePerNPerMm2 = 1.0 / 9.81e-9;  // w in N/mm² -> g/m²

// The model settings a user may change here; the rest stay with presets and --set.
constexpr const char* kChoiceKeys[] = {"method", "span_rule", "int_rounding"};

std::string slider_label(const InputSpec& spec) {
  return std::string(spec.key) + " (" + std::string(spec.name) + ")";
}

// Whether validation refused this input. K is derived: validation names the constant c it sets.
bool refused(const Document& document, const InputSpec& spec) {
  for (const ValidationIssue& issue : document.issues()) {
    if (issue.field == spec.field || (spec.kind == InputKind::stiffness_K && issue.field == "c")) {
      return true;
    }
  }
  return false;
}

// Where a value sits on its slider, 0 at the left end and 1 at the right: on the exponent for a
// log row, so that every decade gets the same width.
double slider_fraction(const InputSpec& spec, double value) {
  if (spec.scale == InputScale::logarithmic) {
    return (std::log10(value) - std::log10(spec.typical_lo)) /
           (std::log10(spec.typical_hi) - std::log10(spec.typical_lo));
  }
  return (value - spec.typical_lo) / (spec.typical_hi - spec.typical_lo);
}

double slider_value(const InputSpec& spec, double fraction) {
  if (spec.scale == InputScale::logarithmic) {
    return std::pow(10.0, std::log10(spec.typical_lo) + fraction * (std::log10(spec.typical_hi) -
                                                                    std::log10(spec.typical_lo)));
  }
  return spec.typical_lo + fraction * (spec.typical_hi - spec.typical_lo);
}

// A slider for one row of the input table. It moves over [0, 1] and shows the value: ImGui's own
// logarithmic slider treats values below the format's precision as zero, which put all of w's
// range in its dead zone. Typed values (Ctrl+click) are neither mapped nor clamped, so that
// validation rather than the widget decides.
void input_slider(Document& document, const InputSpec& spec, float width,
                  std::map<std::string, SliderPlace, std::less<>>& places) {
  double value = spec.value(document.edited()).value_or(0.0);
  const std::string format =
      std::string(spec.format) + (spec.unit.empty() ? "" : " " + std::string(spec.unit));
  const std::string label = slider_label(spec);
  // A refused value reddens its slider; the reason goes to the foot of the panel, so that no
  // line appears between the sliders and moves the one under the mouse.
  const bool is_refused = refused(document, spec);
  if (is_refused) {
    ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.55f, 0.12f, 0.10f, 1.0f));
  }
  ImGui::SetNextItemWidth(width);
  bool changed = false;
  if (ImGui::TempInputIsActive(ImGui::GetID(label.c_str()))) {
    changed = ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &value, &spec.typical_lo,
                                  &spec.typical_hi, format.c_str());
  } else {
    // The shown text doubles as the text field's first contents on Ctrl+click, which parses
    // back to the value.
    std::string shown = detail::printf_string(format.c_str(), value);
    for (std::size_t at = shown.find('%'); at != std::string::npos; at = shown.find('%', at + 2)) {
      shown.insert(at, 1, '%');
    }
    // A typed value off the slider's scale (w <= 0) pins the handle to the left end.
    const double on_scale = slider_fraction(spec, value);
    const double fraction = std::isnan(on_scale) ? 0.0 : std::clamp(on_scale, 0.0, 1.0);
    double position = fraction;
    constexpr double kZero = 0.0;
    constexpr double kOne = 1.0;
    if (ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &position, &kZero, &kOne,
                            shown.c_str(), ImGuiSliderFlags_AlwaysClamp)) {
      value = slider_value(spec, position);
      changed = true;
    } else if (ImGui::IsItemFocused() && !ImGui::IsItemActive()) {
      // Arrow keys nudge a focused slider by 1 % of its width (Shift: 10 %).
      const double step = ImGui::GetIO().KeyShift ? 0.1 : 0.01;
      const int left = ImGui::GetKeyIndex(ImGuiKey_LeftArrow);
      const int right = ImGui::GetKeyIndex(ImGuiKey_RightArrow);
      const double nudge = (left >= 0 && ImGui::IsKeyPressed(left))     ? -step
                           : (right >= 0 && ImGui::IsKeyPressed(right)) ? step
                                                                        : 0.0;
      if (nudge != 0.0) {
        value = slider_value(spec, std::clamp(fraction + nudge, 0.0, 1.0));
        changed = true;
      }
    }
    // The item's rectangle includes its label; the slider's own frame is `width` wide.
    const ImVec2 min = ImGui::GetItemRectMin();
    places[std::string(spec.key)] =
        SliderPlace{min, ImVec2(min.x + width, min.y + ImGui::GetFrameHeight()), fraction};
  }
  if (changed) {
    set_numeric_setting(document.edited(), spec.key, value);
    document.commit();
  }
  if (is_refused) {
    ImGui::PopStyleColor();
  }
  help_marker(std::string(spec.help).c_str());
}

void choice_combo(Document& document, const InputSpec& spec) {
  const std::string current(spec.choice(document.edited()));
  ImGui::SetNextItemWidth(ems(9.0f));
  if (ImGui::BeginCombo(std::string(spec.name).c_str(), current.c_str())) {
    std::string_view rest = spec.choices;
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      const std::string option(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      while (!rest.empty() && rest.front() == ' ') {
        rest.remove_prefix(1);
      }
      if (ImGui::Selectable(option.c_str(), option == current) && option != current) {
        spec.set_choice(document.edited(), option);
        document.commit();
      }
    }
    ImGui::EndCombo();
  }
  help_marker(std::string(spec.help).c_str());
}

}  // namespace

void ParametersPanel::draw(Document& document, Renderer& renderer) {
  const bool unsaved = document.unsaved();
  const std::string title = std::string("Parameters") + (unsaved ? " *" : "") + "###parameters";
  if (!begin_panel(title.c_str(), renderer)) {
    ImGui::End();
    return;
  }
  ImGui::TextColored(kDimText, "%s%s", document.loaded().name.c_str(),
                     unsaved ? " (unsaved changes)" : "");
  if (ImGui::Button("Reset to preset")) {
    document.reset_to_loaded();
  }
  hint_after("Ctrl+click a slider to type a value");
  ImGui::Separator();

  // Sliders leave room on their right for the longest label and its (?) marker.
  std::vector<const InputSpec*> sliders;
  float label_width = 0.0f;
  for (const std::string& key : sweepable_keys()) {
    const InputSpec* spec = find_input(key);
    sliders.push_back(spec);
    label_width = std::max(label_width, ImGui::CalcTextSize(slider_label(*spec).c_str()).x);
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = std::max(
      ems(6.0f), ImGui::GetContentRegionAvail().x - label_width - ImGui::CalcTextSize(" (?)").x -
                     2.0f * style.ItemInnerSpacing.x - style.ItemSpacing.x);
  for (const InputSpec* spec : sliders) {
    input_slider(document, *spec, width, places_);
    if (spec->key == "w") {
      ImGui::TextColored(
          kDimText, "    w = %.0f g/m²",
          document.edited().fabric.weight_N_per_mm2 * kGramsPerSquareMetrePerNPerMm2);
    }
  }
  ImGui::TextColored(kDimText, "    c = %.4g (load-condition constant)",
                     document.edited().model.load_constant_c);

  ImGui::Separator();
  for (const char* key : kChoiceKeys) {
    choice_combo(document, *find_input(key));
  }
  Scene& scene = document.scene();
  int grid = scene.grid_nx();
  ImGui::SetNextItemWidth(width);
  if (ImGui::SliderInt("grid", &grid, 8, 512, "%d per side", ImGuiSliderFlags_AlwaysClamp)) {
    scene.set_grid_resolution(grid, grid);
    document.session_dirty = true;
  }
  help_marker(
      "Resolution of the 3D cloth mesh (vertices per side). Changing it does not re-solve.");
  if (!document.issues().empty()) {
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("%zu input(s) refused: the views show the last valid state.",
                       document.issues().size());
    for (const ValidationIssue& issue : document.issues()) {
      ImGui::TextWrapped("%s", issue.message.c_str());
    }
    ImGui::PopStyleColor();
  }
  ImGui::End();
}

}  // namespace foldlab::gui
