#include "app/gui/panels/results_panel.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include <imgui.h>

#include "app/gui/appearance.hpp"

#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/model/equations.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

const ModelStanding& ResultsPanel::standing(Document& document) {
  Scene& scene = document.scene();
  const std::optional<CalibrationRecord>& record = document.loaded().calibration;
  if (standing_version_ != scene.version(Stage::solution) || standing_record_ != record) {
    standing_version_ = scene.version(Stage::solution);
    standing_record_ = record;
    standing_ = model_standing(scene.parameters(), record);  // the scene's are always valid
  }
  return standing_;
}

void ResultsPanel::draw(PanelContext& context) {
  Document& document = context.document;
  if (!begin(context.renderer)) {
    ImGui::End();
    return;
  }
  stale_mark(document);
  // The reason for a refusal is also given at the foot of the Parameters panel, which a small
  // window or the expert settings may scroll out of view; here it is always at the top.
  if (const std::optional<std::string> refusal = document.refusal()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("Refused, these results are for the last valid inputs: %s",
                       refusal->c_str());
    ImGui::PopStyleColor();
  }
  const ModelStanding& model = standing(document);
  draw_compare_section(document, model);
  Scene& scene = document.scene();
  const Solution& s = scene.solution();
  const StageStats& timing = scene.stats(Stage::solution);
  ImGui::Text("Regime: %s", std::string(to_string(s.regime)).c_str());
  if (const std::string message = describe(s, scene.parameters()); !message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, s.regime == Regime::wrinkled ? kDimText : kNoteText);
    ImGui::TextWrapped("%s", message.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kDimText);
  ImGui::TextWrapped("model: %s", model.label.c_str());
  ImGui::PopStyleColor();
  if (model.range) {
    ImGui::PushStyleColor(ImGuiCol_Text, kDimText);
    ImGui::TextWrapped("(brackets: %.0f %% prediction intervals, hover for how often they held)",
                       100.0 * model.range->level);
    ImGui::PopStyleColor();
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("intervals of n, Q and z_max: %s", model.range_basis.c_str());
  }
  if (ImGui::BeginTable("results", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    auto row = [](const char* name, const char* symbol, const std::string& value) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(name);
      ImGui::TableSetColumnIndex(1);
      ImGui::TextUnformatted(symbol);
      ImGui::TableSetColumnIndex(2);
      ImGui::TextUnformatted(value.c_str());
    };
    auto fmt = [](const char* format, double v) { return detail::printf_string(format, v); };
    const QuantityTexts shown = quantity_texts(s, model);
    row("number of wrinkles", "n",
        shown.n.joined() + (s.n_capped ? " (capped: eq. 10 asks for more)" : ""));
    row("amplitude ratio", "Q", shown.Q.joined());
    if (s.count_rule && s.count_rule->spacing == FoldSpacing::even) {
      row("fold spacing", "lambda", fmt("%.1f mm", s.count_rule->step));
    } else {
      row("root of eq. 7", "Q7", s.Q7 ? fmt("%.4f", *s.Q7) : std::string("none (s >= 1)"));
    }
    row("stress ratio", "s", fmt("%.4g", s.stress_ratio));
    row("out-of-plane depth", "z_max", shown.z_max.joined());
    row("span", "l", fmt("%.1f mm", s.span_mm));
    row("sag of the upper edge", "A", fmt("%.2f mm", s.sag_amplitude_mm));
    row("iterations", "", fmt("%.0f", s.iterations));
    row("residual eq. 8", "L'/L-1", fmt("%.2e", s.residual_length));
    row("residual eq. 9", "fibre/h-1", fmt("%.2e", s.residual_height));
    row("solve time", "", fmt("%.1f µs", timing.last_ms * 1000.0));
    ImGui::EndTable();
  }
  if (!s.a_mm.empty() &&
      ImGui::CollapsingHeader("fold amplitudes a_i", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (ImGui::BeginTable(
            "amplitudes", 3,
            ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerV,
            ImVec2(0.0f, std::max(80.0f, ImGui::GetContentRegionAvail().y)))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("i");
      ImGui::TableSetupColumn("a_i (mm)");
      ImGui::TableSetupColumn("fold");
      ImGui::TableHeadersRow();
      ImGuiListClipper clipper;
      clipper.Begin(static_cast<int>(s.a_mm.size()));
      while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
          ImGui::TableNextRow();
          ImGui::TableSetColumnIndex(0);
          ImGui::Text("%d%s", i, i == 0 ? " (lower)" : (i == s.n ? " (upper edge)" : ""));
          ImGui::TableSetColumnIndex(1);
          ImGui::Text("%.2f", s.a_mm[static_cast<std::size_t>(i)]);
          ImGui::TableSetColumnIndex(2);
          const bool negative = fold_sign(i) < 0;
          const FoldColours colours = fold_colours(style_is_light());
          ImGui::TextColored(negative ? colours.negative : colours.positive,
                             negative ? "negative" : "positive");
        }
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace foldlab::gui
