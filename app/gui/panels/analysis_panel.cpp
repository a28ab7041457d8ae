#include "app/gui/panels/analysis_panel.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <imgui.h>
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

void AnalysisPanel::draw(PanelContext& context) {
  Document& document = context.document;
  sweep_shown_ = false;
  if (!begin(context.renderer)) {
    ImGui::End();
    return;
  }
  stale_mark(document);
  // A narrow panel scrolls its tabs rather than shortening their names to "Met…".
  if (ImGui::BeginTabBar("analysis tabs", ImGuiTabBarFlags_FittingPolicyScroll)) {
    // The tab named at start is selected once, at the first frame.
    auto flags_for = [this](const char* name) {
      return !tab_selected_ && initial_tab_ == name ? ImGuiTabItemFlags_SetSelected
                                                    : ImGuiTabItemFlags_None;
    };
    const ImGuiTabItemFlags equations_flags = flags_for("equations");
    const ImGuiTabItemFlags method_flags = flags_for("method");
    const ImGuiTabItemFlags sweep_flags = flags_for("sweep");
    const ImGuiTabItemFlags map_flags = flags_for("map");
    tab_selected_ = true;
    if (ImGui::BeginTabItem("Equations", nullptr, equations_flags)) {
      ImGui::BeginChild("equations");
      // A pixel in: a glyph's left bearing (DejaVu's "T") reaches past where its text starts,
      // and the child cuts at its own edge.
      ImGui::Indent(1.0f);
      equations_.draw(document);
      ImGui::Unindent(1.0f);
      ImGui::EndChild();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Method", nullptr, method_flags)) {
      ImGui::BeginChild("method");
      method_.draw(document);
      ImGui::EndChild();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Sweep", nullptr, sweep_flags)) {
      sweep_.draw(document, context.presented == this);
      sweep_shown_ = true;
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Regime map", nullptr, map_flags)) {
      regime_map_.draw(context, context.presented == this);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
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
