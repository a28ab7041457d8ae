#include "app/gui/panels/compare_table.hpp"

#include <optional>
#include <string>

#include <imgui.h>

#include "app/gui/appearance.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

QuantityTexts quantity_texts(const Solution& s, const ModelStanding& standing) {
  QuantityTexts texts{{detail::printf_string("%d", s.n), "", ""},
                      {detail::printf_string("%.4f", s.Q), "", ""},
                      {detail::printf_string("%.2f", s.z_max_mm), "", " mm"}};
  // The prediction's ranges are those of folds the law counts: outside the wrinkled regime (a
  // stiff cloth, no slack) they would bracket values the cloth does not take.
  const std::optional<PredictionRange>& range = standing.range;
  if (range && regime_info(s.regime).unremarkable) {
    texts.n.range = range_text(range->n_min, range->n_max, "%.0f");
    texts.Q.range = range_text(range->Q_min, range->Q_max, "%.4f");
    texts.z_max.range = range_text(range->z_max_min_mm, range->z_max_max_mm, "%.1f");
  }
  return texts;
}

std::string headline(const QuantityTexts& texts) {
  // A line too narrow for all three breaks between them, never inside one.
  return unbroken("n = " + texts.n.joined()) + "     " + unbroken("Q = " + texts.Q.joined()) +
         "     " + unbroken("z_max = " + texts.z_max.joined());
}

QuantityTexts difference_texts(const Solution& a, const Solution& b) {
  return {{detail::printf_string("%+d", a.n - b.n), "", ""},
          {detail::printf_string("%+.4f", a.Q - b.Q), "", ""},
          {detail::printf_string("%+.2f", a.z_max_mm - b.z_max_mm), "", " mm"}};
}

void draw_compare_names(Document& document) {
  // A preset's name can be a sentence: wrapped, never cut off.
  for (const auto& [colour, label] : {std::pair{&kSweepCurve, "A: " + fabric_label(document)},
                                      std::pair{&kCompareB, "B: " + document.compare().b().name}}) {
    ImGui::PushStyleColor(ImGuiCol_Text, static_cast<ImVec4>(*colour));
    wrapped_text("%s", label.c_str());
    ImGui::PopStyleColor();
  }
}

void compare_menu(Document& document, UiStatus& status) {
  const bool pinned = document.compare().pinned();
  if (ImGui::MenuItem("Pin as B")) {
    pin_as_b(document, status);
  }
  if (ImGui::MenuItem("Swap A and B", nullptr, false, pinned)) {
    swap_a_and_b(document, status);
  }
  if (ImGui::MenuItem("Clear B", nullptr, false, pinned)) {
    clear_b(document, status);
  }
  if (document.compare().pinned()) {  // not `pinned`: Clear B may have just cleared it
    ImGui::Separator();
    ImGui::TextDisabled("B: %s", document.compare().b().name.c_str());
  }
}

namespace {

// "Pin as B", and while B is pinned "Swap A and B" and "Clear B". True while B is still pinned.
bool compare_buttons(Document& document, UiStatus& status) {
  if (ImGui::Button("Pin as B")) {
    pin_as_b(document, status);
  }
  if (ImGui::IsItemHovered()) {
    wrapped_tooltip(
        "Keeps this fabric (its last valid inputs and model settings) as B, drawn beside A in "
        "the plots and the 3D view, while the sliders go on changing A.");
  }
  if (!document.compare().pinned()) {
    return false;
  }
  same_line_if_fits(button_width("Swap A and B"));
  if (ImGui::Button("Swap A and B")) {
    swap_a_and_b(document, status);
  }
  same_line_if_fits(button_width("Clear B"));
  if (ImGui::Button("Clear B")) {
    clear_b(document, status);
  }
  return document.compare().pinned();  // false when cleared just now
}

// One quantity's row of the table: its values and, dimmed on a row under them, their intervals
// when there are any (the columns stay narrow).
void quantity_row(const char* symbol, const QuantityText& a_text, const QuantityText& b_text,
                  const QuantityText& difference_text) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(symbol);
  for (const QuantityText* cell : {&a_text, &b_text, &difference_text}) {
    ImGui::TableNextColumn();
    ImGui::TextUnformatted((cell->value + cell->unit).c_str());
  }
  if (a_text.range.empty() && b_text.range.empty()) {
    return;
  }
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  for (const QuantityText* cell : {&a_text, &b_text}) {
    ImGui::TableNextColumn();
    if (!cell->range.empty()) {
      // " (lo–hi)" after a value; alone on its row, under the value: "lo–hi mm".
      ImGui::TextColored(kDimText, "%s",
                         (cell->range.substr(2, cell->range.size() - 3) + cell->unit).c_str());
    }
  }
}

// n, Q and z_max of A and B and A − B. A narrow Results panel scrolls the table sideways rather
// than cut off A − B: a header, and for each quantity its values and, when there are any, its
// intervals.
void quantity_table(const QuantityTexts& a_texts, const QuantityTexts& b_texts,
                    const QuantityTexts& difference) {
  const bool ranges = !a_texts.n.range.empty() || !b_texts.n.range.empty();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float row_height = ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y;
  const float table_height =
      static_cast<float>(1 + (ranges ? 6 : 3)) * row_height + style.ScrollbarSize + 2.0f;
  if (!ImGui::BeginTable("A and B", 4,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit |
                             ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollX,
                         ImVec2(0.0f, table_height))) {
    return;
  }
  // B is the fabric as it was when pinned, A is being changed: the last column is what the
  // change did (a heavier A with one more fold reads +1).
  for (const char* title : {"", "A", "B", "A − B\nsince pinned"}) {
    ImGui::TableSetupColumn(title);
  }
  ImGui::TableHeadersRow();
  if (ImGui::IsItemHovered()) {  // the last header drawn
    ImGui::SetTooltip("A − B: what the change made since B was pinned");
  }
  quantity_row("n", a_texts.n, b_texts.n, difference.n);
  quantity_row("Q", a_texts.Q, b_texts.Q, difference.Q);
  quantity_row("z_max", a_texts.z_max, b_texts.z_max, difference.z_max);
  ImGui::EndTable();
}

}  // namespace

void draw_compare_section(Document& document, UiStatus& status, const ModelStanding& standing_a) {
  if (!compare_buttons(document, status)) {
    return;
  }
  Comparison& compare = document.compare();
  draw_compare_names(document);
  const Solution& a = document.scene().solution();
  const Solution& b = compare.solution();
  quantity_table(quantity_texts(a, standing_a), quantity_texts(b, compare.standing()),
                 difference_texts(a, b));
  if (!regime_info(a.regime).unremarkable || !regime_info(b.regime).unremarkable) {
    ImGui::PushStyleColor(ImGuiCol_Text, kNoteText);
    wrapped_text("regimes: A %s, B %s", std::string(to_string(a.regime)).c_str(),
                 std::string(to_string(b.regime)).c_str());
    ImGui::PopStyleColor();
  }
  ImGui::Separator();
}

}  // namespace foldlab::gui
