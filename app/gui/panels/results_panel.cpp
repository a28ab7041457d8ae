#include "app/gui/panels/results_panel.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/gui/appearance.hpp"

#include "app/gui/input_words.hpp"
#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/field_panel.hpp"
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
    // The scene's are always valid, and its solution is this frame's anyway.
    standing_ = model_standing(scene.parameters(), record, scene.solution());
  }
  return standing_;
}

// The unit follows the range ("48.96 (40.1–57.8) mm"), as `solve` prints it.
std::string ResultsPanel::Row::one_line() const {
  if (range.empty()) {
    return value;
  }
  const std::size_t unit = value.find(' ');
  return unit == std::string::npos ? value + " " + range
                                   : value.substr(0, unit) + " " + range + value.substr(unit);
}

std::vector<ResultsPanel::Row> ResultsPanel::rows(Document& document, bool expert) {
  Scene& scene = document.scene();
  const Solution& s = scene.solution();
  const StageStats& timing = scene.stats(Stage::solution);
  auto fmt = [](const char* format, double v) { return detail::printf_string(format, v); };
  const QuantityTexts shown = quantity_texts(s, standing(document));
  // The range in its own column, without the space quantity_texts puts before it.
  auto row = [](const char* name, const char* symbol, const QuantityText& text) {
    return Row{name, symbol, text.value + text.unit,
               text.range.empty() ? std::string() : text.range.substr(1)};
  };
  std::vector<Row> out;
  out.push_back(row("number of wrinkles", "n", shown.n));
  out.push_back(row("amplitude ratio", "Q", shown.Q));
  if (!expert) {
    // A beginner sees what the cloth does; how the solver got there is for experts.
    out.push_back(row("out-of-plane depth", "z_max", shown.z_max));
    return out;
  }
  if (s.count_rule && s.count_rule->spacing == FoldSpacing::even) {
    out.push_back({"fold spacing", readable("λ"), fmt("%.1f mm", s.count_rule->step), ""});
  } else {
    out.push_back({"root of eq. 7", "Q7", s.Q7 ? fmt("%.4f", *s.Q7) : "none (s >= 1)", ""});
  }
  out.push_back({"stress ratio", "s", fmt("%.4g", s.stress_ratio), ""});
  out.push_back(row("out-of-plane depth", "z_max", shown.z_max));
  out.push_back({"span", "l", fmt("%.1f mm", s.span_mm), ""});
  out.push_back({"sag of the upper edge", "A", fmt("%.2f mm", s.sag_amplitude_mm), ""});
  out.push_back({"iterations", "", fmt("%.0f", s.iterations), ""});
  out.push_back({"residual eq. 8", "L'/L-1", fmt("%.2e", s.residual_length), ""});
  out.push_back({"residual eq. 9", "fibre/h-1", fmt("%.2e", s.residual_height), ""});
  // A browser's clock steps by up to 0.1 ms, longer than a solve: zero means too short to see.
  out.push_back({"solve time", "",
                 timing.last_ms > 0.0 ? fmt("%.1f µs", timing.last_ms * 1000.0)
                                      : std::string("below the clock's step"),
                 ""});
  return out;
}

namespace {

// A headline read from the back of a room names the regime when it is not the wrinkled one:
// "stiff: n = 1 ..." says why there is no fold to count.
std::string regime_headline(const Solution& s, const ModelStanding& standing) {
  const RegimeInfo& regime = regime_info(s.regime);
  const std::string line = headline(quantity_texts(s, standing));
  return regime.unremarkable ? line : std::string(regime.label) + ":     " + line;
}

}  // namespace

std::vector<std::pair<std::string, ImVec4>> ResultsPanel::headlines(Document& document,
                                                                    const Solution* drawn,
                                                                    std::string_view drawn_words) {
  std::string a;
  if (drawn != nullptr) {
    // The closed form's prediction ranges bracket its own values, not the field's.
    ModelStanding without_ranges = standing(document);
    without_ranges.range.reset();
    a = regime_headline(*drawn, without_ranges) + " (" + std::string(drawn_words) + ")";
  } else {
    a = regime_headline(document.scene().solution(), standing(document));
  }
  if (!document.compare().pinned()) {
    return {{a, ImGui::GetStyleColorVec4(ImGuiCol_Text)}};
  }
  Comparison& compare = document.compare();
  return {{"A: " + a, kSweepCurve},
          {"B: " + regime_headline(compare.solution(), compare.standing()), kCompareB}};
}

// The symbols and values are never cut: their columns are as wide as their widest text, and the
// names wrap into what is left. When that is too narrow, each range goes under its value, and
// then each symbol follows its name. In a wide panel (presented on a projector) the table is no
// wider than its longest line, so that a value is read beside its name, not half a screen away.
void ResultsPanel::draw_table(const std::vector<Row>& rows) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  float symbol_width = 0.0f;
  float one_line_width = 0.0f;
  float two_line_width = 0.0f;
  float word_width = 0.0f;  // the names' longest word: narrower, a name would be cut
  float name_width = 0.0f;  // the longest name on one line
  for (const Row& row : rows) {
    symbol_width = std::max(symbol_width, ImGui::CalcTextSize(row.symbol.c_str()).x);
    name_width = std::max(name_width, ImGui::CalcTextSize(row.name.c_str()).x);
    one_line_width = std::max(one_line_width, ImGui::CalcTextSize(row.one_line().c_str()).x);
    two_line_width = std::max({two_line_width, ImGui::CalcTextSize(row.value.c_str()).x,
                               ImGui::CalcTextSize(row.range.c_str()).x});
    std::size_t from = 0;
    while (from < row.name.size()) {
      const std::size_t to = std::min(row.name.find(' ', from), row.name.size());
      word_width =
          std::max(word_width, ImGui::CalcTextSize(row.name.data() + from, row.name.data() + to).x);
      from = to + 1;
    }
  }
  // Each column has its cell padding on both sides, and a word of slack for the rounding.
  const float available = ImGui::GetContentRegionAvail().x - ImGui::GetFontSize();
  const float padding = 2.0f * style.CellPadding.x;
  const bool two_lines = symbol_width + one_line_width + word_width + 3.0f * padding > available;
  const float value_width = two_lines ? two_line_width : one_line_width;
  const bool symbol_column = symbol_width + value_width + word_width + 3.0f * padding <= available;
  const float natural_width = name_width + (symbol_column ? symbol_width + padding : 0.0f) +
                              value_width + 2.0f * padding + ImGui::GetFontSize();
  const float table_width = std::min(ImGui::GetContentRegionAvail().x, natural_width);
  if (!ImGui::BeginTable("results", symbol_column ? 3 : 2,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit,
                         ImVec2(table_width, 0.0f))) {
    return;
  }
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
  if (symbol_column) {
    ImGui::TableSetupColumn("symbol", ImGuiTableColumnFlags_WidthFixed, symbol_width);
  }
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, value_width);
  for (const Row& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (symbol_column || row.symbol.empty()) {
      wrapped_text("%s", row.name.c_str());
    } else {
      wrapped_text("%s  %s", row.name.c_str(), row.symbol.c_str());
    }
    if (symbol_column) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.symbol.c_str());
    }
    ImGui::TableNextColumn();
    if (two_lines) {
      ImGui::TextUnformatted(row.value.c_str());
      if (!row.range.empty()) {
        ImGui::TextUnformatted(row.range.c_str());
      }
    } else {
      ImGui::TextUnformatted(row.one_line().c_str());
    }
  }
  ImGui::EndTable();
}

void ResultsPanel::draw(PanelContext& context) {
  Document& document = context.document;
  if (!begin(context.renderer)) {
    ImGui::End();
    return;
  }
  stale_mark(document);
  draw_refusal(document);
  const ModelStanding& model = standing(document);
  draw_compare_section(document, context.status, model);
  draw_regime(document, model, context.status.expert_mode());
  draw_range_note(model);
  draw_table(rows(document, context.status.expert_mode()));
  const Solution& s = document.scene().solution();
  if (s.n_capped) {
    ImGui::PushStyleColor(ImGuiCol_Text, kNoteText);
    wrapped_text("n is capped: eq. 10 asks for more.");
    ImGui::PopStyleColor();
  }
  draw_field_column(context);
  draw_amplitudes(s, context.status.expert_mode());
  ImGui::End();
}

namespace {

constexpr std::string_view kFieldStateNames[] = {"not_solved", "solving",   "not_converged",
                                                 "refused",    "other_cut", "converged"};

}  // namespace

void ResultsPanel::draw_field_column(PanelContext& context) {
  Document& document = context.document;
  FieldPanel& field_view = context.panel<FieldPanel>();
  const FieldFoldsNow now = field_view.folds_now(context);
  field_column_shown_ = !field_view.consumers().empty();
  field_state_ = kFieldStateNames[static_cast<std::size_t>(now.state)];
  field_words_ = now.words;
  field_rows_.clear();
  if (!field_column_shown_) {
    // Solving the field costs tens of milliseconds a change: only when asked.
    if (small_button("compare with the tension field")) {
      field_view.open();
    }
    help_marker(
        "Opens View > Tension field, which solves the cloth as tension field theory does; its "
        "folds are then shown here beside the closed form's. The 3D view's \"folds from\" "
        "setting solves it too.");
    return;
  }
  const Solution& s = document.scene().solution();
  const field::FieldFolds* f = now.folds;
  const std::string missing = f == nullptr ? now.words : std::string();
  const auto value = [&](const char* format, double v) { return detail::printf_string(format, v); };
  field_rows_.push_back({"n", value("%.0f", s.n), f ? value("%.0f", f->n) : missing});
  field_rows_.push_back({"Q", value("%.3f", s.Q), f ? value("%.3f", f->Q) : ""});
  field_rows_.push_back(
      {"z_max", value("%.1f mm", s.z_max_mm), f ? value("%.1f mm", f->z_max_mm) : ""});
  const std::size_t closed_count = s.a_mm.size();
  const std::size_t field_count = f ? f->a_mm.size() : 0;
  for (std::size_t i = 1; i < std::max(closed_count, field_count); ++i) {
    field_rows_.push_back({"a_" + std::to_string(i),
                           i < closed_count ? value("%.1f mm", s.a_mm[i]) : "",
                           i < field_count ? value("%.1f mm", f->a_mm[i]) : ""});
  }
  if (!ImGui::CollapsingHeader("closed form and tension field###field_column",
                               ImGuiTreeNodeFlags_DefaultOpen)) {
    return;
  }
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float height = std::min(static_cast<float>(field_rows_.size() + 1), 9.0f) * line +
                       ImGui::GetStyle().CellPadding.y * 2.0f;
  if (!ImGui::BeginTable("field_column", 3,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                             ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit,
                         ImVec2(ImGui::GetContentRegionAvail().x, height))) {
    return;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("");
  ImGui::TableSetupColumn("closed form");
  ImGui::TableSetupColumn("tension field", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(field_rows_.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const std::array<std::string, 3>& row = field_rows_[static_cast<std::size_t>(i)];
      ImGui::TableNextRow();
      for (int c = 0; c < 3; ++c) {
        ImGui::TableSetColumnIndex(c);
        if (c == 2 && f == nullptr) {
          ImGui::PushStyleColor(ImGuiCol_Text, kNoteText);
          wrapped_text("%s", row[2].c_str());
          ImGui::PopStyleColor();
        } else {
          ImGui::TextUnformatted(row[static_cast<std::size_t>(c)].c_str());
        }
      }
    }
  }
  ImGui::EndTable();
}

void ResultsPanel::report(nlohmann::json& state, PanelContext& /*context*/) const {
  nlohmann::json rows = nlohmann::json::array();
  for (const std::array<std::string, 3>& row : field_rows_) {
    rows.push_back({row[0], row[1], row[2]});
  }
  state["results"] = {
      {"field_column",
       {{"shown", field_column_shown_},
        {"state", field_state_},
        {"words", field_words_.empty() ? nlohmann::json(nullptr) : nlohmann::json(field_words_)},
        {"rows", std::move(rows)}}}};
}

void ResultsPanel::draw_refusal(const Document& document) const {
  // The reason for a refusal is also given at the foot of the Parameters panel, which a small
  // window or the expert settings may scroll out of view; here it is always at the top.
  if (const std::optional<std::string> refusal = document.refusal()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    wrapped_text("Refused, these results are for the last valid inputs: %s",
                 readable(*refusal).c_str());
    ImGui::PopStyleColor();
  }
}

void ResultsPanel::draw_regime(Document& document, const ModelStanding& model, bool expert) const {
  Scene& scene = document.scene();
  const Solution& s = scene.solution();
  if (!expert) {
    const RegimeInfo& regime = regime_info(s.regime);
    wrapped_text("%s: %s", std::string(regime.label).c_str(), std::string(regime.plain).c_str());
    return;
  }
  ImGui::Text("Regime: %s", std::string(to_string(s.regime)).c_str());
  if (const std::string message = describe(s, scene.parameters()); !message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, regime_info(s.regime).unremarkable ? kDimText : kNoteText);
    wrapped_text("%s", message.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kDimText);
  wrapped_text("model: %s", model.label.c_str());
  ImGui::PopStyleColor();
}

void ResultsPanel::draw_range_note(const ModelStanding& model) const {
  if (model.range) {
    ImGui::PushStyleColor(ImGuiCol_Text, kDimText);
    wrapped_text("(brackets: %.0f %% prediction intervals, %s)", 100.0 * model.range->level,
                 hint_words(Hint::interval_details));
    ImGui::PopStyleColor();
  }
  if (ImGui::IsItemHovered()) {
    wrapped_tooltip("intervals of n, Q and z_max: %s", model.range_basis.c_str());
  }
}

void ResultsPanel::draw_amplitudes(const Solution& s, bool expert) const {
  // The a_i are how far down each fold line reaches at the centre: a beginner's fold depths.
  if (s.a_mm.empty() || !ImGui::CollapsingHeader(expert ? "fold amplitudes a_i###amplitudes"
                                                        : "fold depths a_i###amplitudes",
                                                 ImGuiTreeNodeFlags_DefaultOpen)) {
    return;
  }
  // As the table above: no wider than its longest row (and the scroll bar), so that a depth is
  // read beside its fold on a wide screen.
  const ImGuiStyle& style = ImGui::GetStyle();
  // Measured on the widest texts a row can hold rather than on the rows, of which there may be
  // thousands (drawn through a clipper).
  const float natural_width =
      ImGui::CalcTextSize("10000 (upper edge)").x +
      std::max(ImGui::CalcTextSize("a_i (mm)").x, ImGui::CalcTextSize("000000.00").x) +
      ImGui::CalcTextSize("negative").x + 6.0f * style.CellPadding.x + style.ScrollbarSize +
      ImGui::GetFontSize();
  if (!ImGui::BeginTable(
          "amplitudes", 3,
          ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerV,
          ImVec2(std::min(ImGui::GetContentRegionAvail().x, natural_width),
                 std::max(80.0f, ImGui::GetContentRegionAvail().y)))) {
    return;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("i");
  ImGui::TableSetupColumn("a_i (mm)");
  ImGui::TableSetupColumn("fold");
  ImGui::TableHeadersRow();
  const FoldColours colours = fold_colours(style_is_light());
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
      ImGui::TextColored(negative ? colours.negative : colours.positive,
                         negative ? "negative" : "positive");
    }
  }
  ImGui::EndTable();
}

}  // namespace foldlab::gui
