#include "app/gui/panels/analysis_panel.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include <imgui.h>
#include <imgui_internal.h>  // the window's title bar, where a presented panel's tabs go
#include <nlohmann/json.hpp>

#include "app/gui/panels/widgets.hpp"
#include "core/model/equations.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

namespace {

// Eq. 7 (or, for evenly spaced folds, Cerda-Mahadevan's wavelength): the stress ratio s and the
// step between folds it gives.
void draw_fold_step(const Solution& s, const Parameters& p, bool even) {
  const ImVec4 note = kNoteText;
  const ImVec4 dim = kDimText;
  const ImVec4 error = kErrorText;
  const double K = stiffness_constant_K(p);
  const double t = p.fabric.thickness_mm;
  section(even ? readable("Cerda-Mahadevan: the wrinkle wavelength λ").c_str()
               : "eq. 7: critical stress gives Q7");
  equation_text(nullptr, "s = K E t³ / (w h l²) = %.6g × %.6g × %.6g³ / (%.6g × %.6g × %.6g²)", K,
                p.fabric.youngs_modulus_MPa, t, p.fabric.weight_N_per_mm2, p.hanging.height_mm,
                s.span_mm);
  equation_text(nullptr, "  = %.5g", s.stress_ratio);
  // A calibrated eq. 7 uses s^p (p = 1 is the paper's form).
  const double exponent = p.model.stress_exponent_p;
  const double s_used = exponent == 1.0 ? s.stress_ratio : std::pow(s.stress_ratio, exponent);
  if (exponent != 1.0) {
    equation_text(&note, "calibrated form: s^p = %.5g^%.6g = %.5g", s.stress_ratio, exponent,
                  s_used);
  }
  if (even) {
    wrapped_text(
        "%s",
        readable(detail::printf_string(
                     "λ = l (%s)^(1/4) = %.5g × %.5g^(1/4) = %.2f mm: n counts the folds that fit "
                     "λ apart down the centre fibre; eq. 5 then lays them out",
                     exponent == 1.0 ? "s" : "s^p", s.span_mm, s_used, s.count_rule->step))
            .c_str());
  } else if (s.Q7) {
    const double q = *s.Q7;
    equation_text(nullptr, "(Q7 - 1)² = %s Q7 (Q7 + 1)  ->  Q7 = %.5f",
                  exponent == 1.0 ? "s" : "s^p", q);
    equation_text(&dim, "  check: %.6g = %.6g", (q - 1) * (q - 1), s_used * q * (q + 1));
  } else {
    equation_text(&error, "s >= 1: no root; at most one fold.");
  }
}

void draw_upper_edge(const Solution& s, const Parameters& p) {
  const double an = s.a_mm.back();
  section("eq. 8: the upper edge keeps its length L");
  const double A = std::hypot(an, s.z_max_mm);
  equation_text(nullptr, "A = √(a_n² + z_max²) = √(%.2f² + %.2f²) = %.2f mm", an, s.z_max_mm, A);
  equation_text(nullptr, "L′ = (2l/π) √(1+k²) E(k²/(1+k²)), k = π A/l = %.4f",
                std::numbers::pi * A / s.span_mm);
  equation_text(nullptr, "   = %.3f mm  vs  L = %.1f mm  (residual %.2e)",
                upper_edge_length_closed_form(A, s.span_mm), p.hanging.length_mm,
                s.residual_length);
}

void draw_centre_fibre(const Solution& s, const Parameters& p) {
  section("eq. 9: the centre fibre keeps its length h");
  equation_text(nullptr, "h′ = Σ √((a_i-1 − a_i)² + (2 z_max)²), i = 1…%d", s.n);
  equation_text(nullptr, "   = %.3f mm  vs  h = %.1f mm  (residual %.2e)",
                fibre_length(s.a_mm.front(), s.Q, s.n, s.z_max_mm), p.hanging.height_mm,
                s.residual_height);
}

}  // namespace

AnalysisPanel::AnalysisPanel(std::filesystem::path presets_dir, std::string initial_tab)
    : initial_tab_(std::move(initial_tab)), sweep_(std::move(presets_dir)) {}

void AnalysisPanel::show_paper_case(int which, Document& document) {
  sweep_.select_paper_case(which, document);
  initial_tab_ = "sweep";
  tab_selected_ = false;
}

namespace {

struct AnalysisTab {
  const char* label;
  const char* key;  // as --tab names it
};
constexpr AnalysisTab kTabs[] = {
    {"Equations", "equations"}, {"Method", "method"}, {"Sweep", "sweep"}, {"Regime map", "map"}};

// Presented, the tabs are buttons at the right end of the window's title bar, after the title
// and the shown tab's "settings..." button: the row the tab bar would take is the picture's.
// False, drawing nothing, when the title bar is too short for them (a phone): then the tab bar
// stays.
bool title_bar_tabs(std::string& shown_tab) {
  ImGuiWindow* window = ImGui::GetCurrentWindow();
  const ImRect title = window->TitleBarRect();
  const ImGuiStyle& style = ImGui::GetStyle();
  float tabs_width = 0.0f;
  for (const AnalysisTab& tab : kTabs) {
    tabs_width += button_width(tab.label) + style.ItemInnerSpacing.x;
  }
  const float left =
      title.Min.x + style.FramePadding.x + ImGui::CalcTextSize(window->Name, nullptr, true).x +
      2.0f * style.ItemSpacing.x + button_width("sweep settings...") + style.ItemSpacing.x;
  // Room for the window's own buttons at the right end (undock, close).
  const float right = title.Max.x - 2.0f * ImGui::GetFrameHeight() - style.ItemSpacing.x;
  if (right - left < tabs_width) {
    return false;
  }
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  const ImVec2 cursor_max = window->DC.CursorMaxPos;
  ImGui::PushClipRect(title.Min, title.Max, false);
  ImGui::SetCursorScreenPos(ImVec2(right - tabs_width, title.Min.y));
  for (const AnalysisTab& tab : kTabs) {
    const bool selected = shown_tab == tab.key;
    ImGui::PushStyleColor(ImGuiCol_Button,
                          style.Colors[selected ? ImGuiCol_TabActive : ImGuiCol_Tab]);
    if (ImGui::Button(tab.label)) {
      shown_tab = tab.key;
    }
    ImGui::PopStyleColor();
    ImGui::SameLine(0.0f, style.ItemInnerSpacing.x);
  }
  ImGui::NewLine();
  ImGui::PopClipRect();
  ImGui::SetCursorScreenPos(cursor);
  window->DC.CursorMaxPos = cursor_max;
  return true;
}

}  // namespace

void AnalysisPanel::draw(PanelContext& context) {
  Document& document = context.document;
  sweep_shown_ = false;
  if (!begin(context.renderer)) {
    ImGui::End();
    return;
  }
  stale_mark(document);
  const bool presented = context.presented == this;
  if (shown_tab_.empty()) {
    shown_tab_ = initial_tab_.empty() ? kTabs[0].key : initial_tab_;
  }
  if (!tab_selected_) {
    shown_tab_ = initial_tab_.empty() ? shown_tab_ : initial_tab_;
  }
  const bool titled = (ImGui::GetCurrentWindow()->Flags & ImGuiWindowFlags_NoTitleBar) == 0;
  // Without a title bar the tabs are items of the menu that stands for it.
  if (presented && (!titled || title_bar_tabs(shown_tab_))) {
    tab_selected_ = true;
    tabs_in_title_bar_ = true;
    draw_tab(context, shown_tab_, presented);
    ImGui::End();
    return;
  }
  // Back from the title bar, the tab bar opens on the tab that was shown there.
  if (tabs_in_title_bar_) {
    tabs_in_title_bar_ = false;
    initial_tab_ = shown_tab_;
    tab_selected_ = false;
  }
  // A narrow panel scrolls its tabs rather than shortening their names to "Met…".
  if (ImGui::BeginTabBar("analysis tabs", ImGuiTabBarFlags_FittingPolicyScroll)) {
    // The tab named at start is selected once, at the first frame.
    const bool select = !tab_selected_;
    tab_selected_ = true;
    for (const AnalysisTab& tab : kTabs) {
      const ImGuiTabItemFlags flags = select && initial_tab_ == tab.key
                                          ? ImGuiTabItemFlags_SetSelected
                                          : ImGuiTabItemFlags_None;
      if (ImGui::BeginTabItem(tab.label, nullptr, flags)) {
        shown_tab_ = tab.key;
        draw_tab(context, tab.key, presented);
        ImGui::EndTabItem();
      }
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

void AnalysisPanel::presented_menu_items(PanelContext& /*context*/) {
  for (const AnalysisTab& tab : kTabs) {
    if (ImGui::MenuItem(tab.label, nullptr, shown_tab_ == tab.key)) {
      shown_tab_ = tab.key;
      tab_selected_ = true;
    }
  }
  if (shown_tab_ == "sweep") {
    ImGui::Separator();
    sweep_.toolbar().menu_item();
  } else if (shown_tab_ == "map") {
    ImGui::Separator();
    regime_map_.toolbar().menu_item();
  }
}

void AnalysisPanel::draw_tab(PanelContext& context, std::string_view tab, bool presented) {
  Document& document = context.document;
  if (tab == "equations") {
    ImGui::BeginChild("equations");
    // A pixel in: a glyph's left bearing (DejaVu's "T") reaches past where its text starts,
    // and the child cuts at its own edge.
    ImGui::Indent(1.0f);
    equations_.draw(document);
    ImGui::Unindent(1.0f);
    ImGui::EndChild();
  } else if (tab == "method") {
    ImGui::BeginChild("method");
    method_.draw(document);
    ImGui::EndChild();
  } else if (tab == "sweep") {
    sweep_.draw(document, presented);
    sweep_shown_ = true;
  } else {
    regime_map_.draw(context, presented);
  }
}

void EquationsTab::draw(Document& document) {
  // Each line wraps before an operator rather than run past the panel's edge.
  const Solution& s = document.scene().solution();
  const Parameters& p = document.scene().parameters();
  wrapped_text("The model with today's numbers (mm, MPa, N/mm²).");
  const bool even = s.count_rule && s.count_rule->spacing == FoldSpacing::even;
  draw_fold_step(s, p, even);
  if (s.a_mm.empty()) {
    ImGui::Separator();
    wrapped_text("%s", describe(s, p).c_str());
    return;
  }
  draw_upper_edge(s, p);
  draw_centre_fibre(s, p);
  draw_fold_count(s, p, even);
  equation_text(nullptr, "Q = (a_0/a_n)^(1/n) = %.4f", s.Q);
}

void EquationsTab::draw_fold_count(const Solution& s, const Parameters& p, bool even) {
  section("eq. 10: the number of wrinkles");
  if (!s.count_rule) {
    equation_text(nullptr, "n = 1 (no Q7: stiff)");
    return;
  }
  const double a0 = s.a_mm.front();
  const double an = s.a_mm.back();
  const WrinkleLaw& law = wrinkle_law(p.model.law);
  const double argument = s.count_rule->argument(a0, an);
  if (even) {
    equation_text(nullptr, "n = %s = Int[(%.1f - %.2f) / %.2f]",
                  std::string(law.count_formula()).c_str(), a0, an, s.count_rule->step);
  } else {
    equation_text(nullptr, "n = %s = Int[log(%.1f/%.2f) / log %.4f]",
                  std::string(law.count_formula()).c_str(), a0, an, *s.Q7);
  }
  equation_text(nullptr, "  = Int[%.3f] = %d   (Int = %s)", argument, s.n,
                std::string(to_string(p.model.int_rounding)).c_str());
  follow(s);
  if (previous_n_ >= 0 && previous_n_ != s.n) {
    ImGui::PushStyleColor(ImGuiCol_Text, kOkText);
    wrapped_text("n changed from %d to %d: the argument of Int[] crossed %s.", previous_n_, s.n,
                 p.model.int_rounding == IntRounding::nearest ? "a half-integer" : "an integer");
    ImGui::PopStyleColor();
  }
}

void EquationsTab::follow(const Solution& s) {
  if (shown_n_ != s.n) {
    previous_n_ = shown_n_;
    shown_n_ = s.n;
  }
}

void AnalysisPanel::begin_frame(PanelContext& context) {
  equations_.follow(context.document.scene().solution());
}

namespace {

// The Method tab's stepper: how far it is and the iterate it shows.
nlohmann::json method_step_json(const MethodPanel& stepper) {
  if (stepper.iterates() == 0) {
    return {{"method", to_string(stepper.method())}, {"shown", 0}, {"of", 0}};
  }
  const Iterate& it = stepper.trace().iterates[static_cast<std::size_t>(stepper.shown() - 1)];
  return {{"method", to_string(stepper.method())},
          {"shown", stepper.shown()},
          {"of", stepper.iterates()},
          {"n", it.n},
          {"Q", it.Q},
          {"z_max_mm", it.z_max_mm},
          {"length_ratio", it.length_ratio}};
}

constexpr std::string_view kPaperCaseNames[] = {"table1", "table2", "fig4"};
static_assert(std::size(kPaperCaseNames) == SweepPanel::kPaperCases);

}  // namespace

void AnalysisPanel::view_settings(ViewSettings& settings, Document& document) {
  settings.add_action(
      "sweep", [this, &document](std::string_view value) -> std::optional<std::string> {
        for (int which = 0; which < SweepPanel::kPaperCases; ++which) {
          if (value == kPaperCaseNames[which]) {
            show_paper_case(which, document);
            return std::nullopt;
          }
        }
        return "sweep = '" + detail::cut(value) + "' is not one of: table1, table2, fig4";
      });
}

void AnalysisPanel::report(nlohmann::json& state, PanelContext& /*context*/) const {
  state["regime_map_ms"] = regime_map_.last_map_ms();
  state["regime_map"] = regime_map_.report();
  state["method_step"] = method_step_json(method_);
  // The ticks the Sweep tab's plots labelled last, n's on whole numbers.
  state["sweep_ticks"] = {{"n", sweep_.plot(0).y_ticks()},
                          {"x", sweep_.plot(0).x_ticks()},
                          {"side_by_side", sweep_.plot_view(1).min.y == sweep_.plot_view(0).min.y}};
}

void AnalysisPanel::drawing_areas(DrawingAreas& areas) const {
  if (const std::optional<PanelRect> rect = sweep_.drawn_area().recent()) {
    areas.emplace_back("sweep", *rect);
  }
  if (const std::optional<PanelRect> rect = regime_map_.drawn_area().recent()) {
    areas.emplace_back("regime_map", *rect);
  }
}

std::optional<std::string> AnalysisPanel::picture_unavailable(PictureView /*view*/,
                                                              const Document& /*document*/,
                                                              bool as_drawn) const {
  if (as_drawn && !sweep_shown_) {
    return "Open Analysis > Sweep to take its plots.";
  }
  return std::nullopt;
}

std::optional<ImVec2> AnalysisPanel::locate(std::string_view target,
                                            std::span<const double> at) const {
  constexpr std::string_view kPlots[] = {"sweep_n", "sweep_Q", "sweep_z_max"};
  for (int which = 0; which < 3; ++which) {
    if (target == kPlots[which] && sweep_shown_ && !at.empty()) {
      return sweep_.screen_point(which, at[0]);
    }
  }
  return std::nullopt;
}

}  // namespace foldlab::gui
