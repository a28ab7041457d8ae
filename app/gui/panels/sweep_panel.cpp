#include "app/gui/panels/sweep_panel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <imgui.h>

#include "app/common/presets_dir.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/panels/axis_inputs.hpp"
#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/presentation_bar.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

// A sweep plot's least height, in font sizes: about four lines of data area besides its ticks
// and labels.
constexpr float kMinPlotHeightEms = 8.5f;

bool same_axis(const SweepAxis& a, const SweepAxis& b) {
  return a.key == b.key && a.from == b.from && a.to == b.to && a.steps == b.steps &&
         a.logarithmic == b.logarithmic;
}

}  // namespace

SweepPanel::SweepPanel(std::filesystem::path presets_dir) : presets_dir_(std::move(presets_dir)) {}

void SweepPanel::clear_overlay() {
  overlay_label_.clear();
  overlay_x_.clear();
  overlay_n_.clear();
  overlay_Q_.clear();
  overlay_z_.clear();
  overlay_Q_x_.clear();
  overlay_row_Q_.clear();
  overlay_shown_x_.clear();
  overlay_Q_shown_x_.clear();
}

void SweepPanel::load_overlay(const std::string& prefix, const std::string& label) {
  clear_overlay();
  overlay_label_ = label;
  overlay_key_ = key_;
  for (const auto& file : app::preset_files(presets_dir_)) {
    if (file.filename().string().rfind(prefix, 0) != 0) {
      continue;
    }
    try {
      const Preset p = load_preset(file);
      if (!p.published.n || !p.published.z_max_mm) {
        continue;
      }
      const double x = get_number(p.parameters, overlay_key_);
      overlay_x_.push_back(x);
      overlay_shown_x_.push_back(to_shown(overlay_key_, x));
      overlay_n_.push_back(*p.published.n);
      overlay_z_.push_back(*p.published.z_max_mm);
      overlay_row_Q_.push_back(p.published.Q.value_or(std::nan("")));
      if (p.published.Q) {
        overlay_Q_x_.push_back(x);
        overlay_Q_shown_x_.push_back(to_shown(overlay_key_, x));
        overlay_Q_.push_back(*p.published.Q);
      }
    } catch (const PresetError&) {
      // An unreadable file simply adds no point; the presets panel reports it.
    }
  }
}

void SweepPanel::recompute(const Parameters& current) {
  SweepAxis axis{key_, from_, to_, steps_, logarithmic_};
  if (check_axis(axis)) {
    return;
  }
  if (computed_ && current == computed_for_ && same_axis(axis, computed_axis_)) {
    return;
  }
  const std::vector<SweepPoint> points = sweep(current, axis);
  curves_ = sweep_curves(points);
  shown_x_.clear();
  for (const double x : curves_.x) {
    shown_x_.push_back(to_shown(axis.key, x));
  }
  bands_ = regime_bands(points, axis.logarithmic);
  computed_for_ = current;
  computed_axis_ = axis;
  computed_ = true;
}

void SweepPanel::recompute_compare(Document& document) {
  if (!document.compare().pinned()) {
    compare_computed_ = false;
    return;
  }
  const Parameters& b = document.compare().b().parameters;
  if (compare_computed_ && b == compare_computed_for_ && same_axis(computed_axis_, compare_axis_)) {
    return;
  }
  compare_curves_ = sweep_curves(sweep(b, computed_axis_));
  compare_computed_for_ = b;
  compare_axis_ = computed_axis_;
  compare_computed_ = true;
}

namespace {

// One click: the paper's case, its input swept, its printed rows overlaid.
struct PaperCase {
  const char* preset;
  const char* prefix;
  const char* key;
  double from, to;
  bool log;
};
const char* const kPaperCaseButtons[] = {"Table 1 (h)", "Table 2 (w)", "Fig. 4 (h)"};
const PaperCase kPaperCaseList[] = {
    {"paper-table1-h1400.json", "paper-table1-", "h", 500.0, 3000.0, false},
    {"paper-table2-w33.json", "paper-table2-", "w", 5e-7, 8e-6, true},
    {"paper-fig4.json", "paper-fig4", "h", 500.0, 3000.0, false},
};

}  // namespace

void SweepPanel::select_paper_case(int which, Document& document) {
  const PaperCase& c = kPaperCaseList[which];
  document.load_preset_file(presets_dir_ / c.preset);
  key_ = c.key;
  from_ = c.from;
  to_ = c.to;
  logarithmic_ = c.log;
  load_overlay(c.prefix, std::string("paper, ") + kPaperCaseButtons[which]);
  overlay_load_ = document.loads();
  plots_.plots[0].request_autoscale();
}

void SweepPanel::set_axis(const SweepAxis& axis) {
  key_ = axis.key;
  from_ = axis.from;
  to_ = axis.to;
  steps_ = axis.steps;
  logarithmic_ = axis.logarithmic;
  clear_overlay();
}

std::optional<std::string> SweepPanel::compute(Document& document) {
  // The paper's points describe the case they came with, not whatever is loaded next.
  if (!overlay_label_.empty() && document.loads() != overlay_load_) {
    clear_overlay();
  }
  if (std::optional<std::string> problem = check_axis(axis())) {
    return problem;
  }
  recompute(document.scene().parameters());
  recompute_compare(document);
  return std::nullopt;
}

void SweepPanel::draw(Document& document, bool side_by_side) {
  // Presented, the settings fold into the title bar: the room is the plots'. In a tile they stay
  // above the plots whatever its size (the tab scrolls instead).
  const bool settings_shown = toolbar_row_.begin(
      "sweep settings...", -std::numeric_limits<float>::infinity(), side_by_side);
  if (settings_shown) {
    draw_axis_controls(document);
    draw_paper_case_buttons(document);
  }
  const std::optional<std::string> problem = compute(document);
  // The paper's rows against the model's: folded by default, since the plots need the height.
  if (settings_shown && !problem && overlay_shown() &&
      ImGui::CollapsingHeader("Paper vs model (table)")) {
    draw_comparison(document.scene().parameters());
  }
  if (settings_shown) {
    toolbar_row_.end();
  }
  if (problem) {
    ImGui::TextColored(kErrorText, "%s", problem->c_str());
    return;
  }
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float plot_width_px =
      side_by_side ? std::floor((ImGui::GetContentRegionAvail().x - 2.0f * spacing) / 3.0f) : 0.0f;
  draw_keys(document, plot_width_px);
  // Each plot keeps room for its ticks, its title and a few lines of data at any UI scale: a
  // short panel scrolls rather than squeeze a plot under its own labels.
  if (side_by_side) {
    draw_plots(document, plots_,
               std::max(ems(kMinPlotHeightEms), ImGui::GetContentRegionAvail().y - 8.0f),
               plot_width_px);
  } else {
    const float height =
        std::max(ems(kMinPlotHeightEms), (ImGui::GetContentRegionAvail().y - 8.0f) / 3.0f);
    draw_plots(document, plots_, height);
  }
  ImVec2 lo(plot_view(0).min), hi(plot_view(0).max);
  for (int which = 1; which < 3; ++which) {
    lo = ImVec2(std::min(lo.x, plot_view(which).min.x), std::min(lo.y, plot_view(which).min.y));
    hi = ImVec2(std::max(hi.x, plot_view(which).max.x), std::max(hi.y, plot_view(which).max.y));
  }
  drawn_.mark(PanelRect{lo, ImVec2(hi.x - lo.x, hi.y - lo.y)});
}

void SweepPanel::draw_axis_controls(Document& document) {
  if (key_combo("input", key_)) {
    logarithmic_ = natural_log_scale(key_);
    default_range(key_, get_number(document.scene().parameters(), key_), from_, to_);
    clear_overlay();
  }
  // A narrow panel wraps the row rather than push "log" and "steps" out of sight.
  same_line_if_fits(range_inputs_width());
  range_inputs("range", key_, from_, to_);
  same_line_if_fits(checkbox_width("log"));
  ImGui::Checkbox("log", &logarithmic_);
  same_line_if_fits(labelled_width(ems(6.0f), "steps"));
  ImGui::SetNextItemWidth(ems(6.0f));
  notched_slider_int("steps", steps_, 10, 1000, "%d");
}

void SweepPanel::draw_paper_case_buttons(Document& document) {
  for (int which = 0; which < kPaperCases; ++which) {
    if (small_button(kPaperCaseButtons[which])) {
      document.replace_edits(
          std::string("Loading the paper's ") + kPaperCaseButtons[which] + " replaces them.",
          [this, which](Document& d) { select_paper_case(which, d); });
    }
    ImGui::SameLine();
  }
  ImGui::NewLine();
}

bool SweepPanel::overlay_shown() const {
  return !overlay_label_.empty() && overlay_key_ == computed_axis_.key;
}

void SweepPanel::draw_keys(Document& document, float title_row_px) const {
  // With B pinned, a line each names A's and B's colours for the three plots (a legend under
  // each would take the plots' height), wrapped rather than cut in a narrow panel.
  if (compare_computed_) {
    draw_compare_names(document);
  }
  if (!(title_row_px > 0.0f && band_key_on_title_row(title_row_px))) {
    draw_band_key();
  }
}

namespace {

std::string band_meaning(const RegimeBand& band) {
  return !band.valid ? std::string("the other inputs refuse these values")
         : regime_info(band.regime).unremarkable ? std::string("a single fold, so no ratio Q")
                                                 : std::string(regime_info(band.regime).plain);
}

}  // namespace

namespace {

// Each kind of band once (by name), in the order they lie along x.
std::vector<const RegimeBand*> band_kinds(const std::vector<RegimeBand>& bands) {
  std::vector<const RegimeBand*> kinds;
  for (const RegimeBand& band : bands) {
    if (std::none_of(kinds.begin(), kinds.end(),
                     [&](const RegimeBand* k) { return k->name == band.name; })) {
      kinds.push_back(&band);
    }
  }
  return kinds;
}

// A band's shade as its key shows it, a text line tall and 1.4 lines wide from `at`.
void draw_band_swatch(ImDrawList* draw, ImVec2 at, const RegimeBand& band) {
  const float side = ImGui::GetTextLineHeight();
  const ImVec2 low(at.x, at.y + 0.15f * side);
  const ImVec2 high(at.x + 1.4f * side, at.y + 0.85f * side);
  draw->AddRectFilled(low, high, ImGui::ColorConvertFloat4ToU32(plot_background(style_is_light())));
  draw->AddRectFilled(low, high, band.valid ? kRegimeBandFill.u32() : kRefusedBandFill.u32());
  draw->AddRect(low, high, kDimText.u32());
}

}  // namespace

void SweepPanel::draw_band_key() const {
  // A band one sample wide is too narrow for its name, so the key says what each shade is.
  const float side = ImGui::GetTextLineHeight();
  for (const RegimeBand* band : band_kinds(bands_)) {
    draw_band_swatch(ImGui::GetWindowDrawList(), ImGui::GetCursorScreenPos(), *band);
    ImGui::Dummy(ImVec2(1.4f * side, side));
    ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, static_cast<ImVec4>(kDimText));
    wrapped_text("%s: %s", band->name.c_str(), band_meaning(*band).c_str());
    ImGui::PopStyleColor();
  }
}

bool SweepPanel::band_key_on_title_row(float row_px) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float side = ImGui::GetTextLineHeight();
  const std::vector<const RegimeBand*> kinds = band_kinds(bands_);
  float width = 0.0f;
  for (const RegimeBand* band : kinds) {
    width += 1.4f * side + style.ItemInnerSpacing.x + ImGui::CalcTextSize(band->name.c_str()).x +
             style.ItemSpacing.x;
  }
  // Beside the first plot's title ("n") and clear of the tick labels' column under it.
  const float title_px = ImGui::CalcTextSize("n").x + 4.0f * ImGui::GetFontSize();
  if (kinds.empty() || width > row_px - title_px) {
    return kinds.empty();
  }
  const ImVec2 start = ImGui::GetCursorScreenPos();
  ImVec2 at(start.x + row_px - width + style.ItemSpacing.x, start.y);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const RegimeBand* band : kinds) {
    draw_band_swatch(draw, at, *band);
    const ImVec2 text_at(at.x + 1.4f * side + style.ItemInnerSpacing.x, at.y);
    draw->AddText(text_at, kDimText.u32(), band->name.c_str());
    const ImVec2 end(text_at.x + ImGui::CalcTextSize(band->name.c_str()).x, at.y + side);
    if (ImGui::IsMouseHoveringRect(at, end)) {
      ImGui::SetTooltip("%s: %s", band->name.c_str(), band_meaning(*band).c_str());
    }
    at.x = end.x + style.ItemSpacing.x;
  }
  ImGui::SetCursorScreenPos(start);
  return true;
}

void SweepPanel::draw_plots(Document& document, SweepPlots& plots, float height_px,
                            float width_px) {
  const SweepCurves* b = compare_computed_ ? &compare_curves_ : nullptr;
  const Quantity quantities[] = {
      {"sweep n", "n", "n", "", curves_.n, overlay_shown_x_, overlay_n_, true, b ? &b->n : nullptr},
      {"sweep Q", "Q", "Q", "", curves_.Q, overlay_Q_shown_x_, overlay_Q_, false,
       b ? &b->Q : nullptr},
      {"sweep z", "z_max (mm)", "z_max", " mm", curves_.z_max_mm, overlay_shown_x_, overlay_z_,
       false, b ? &b->z_max_mm : nullptr},
  };
  // The three data areas start at one x, so that the current value's line is one line down all
  // three: each plot's tick labels take the widest's room (last frame's).
  float widest_labels = 0.0f;
  for (int which = 0; which < 3; ++which) {
    Plot& plot = plots.plots[which];
    const bool side_by_side = width_px > 0.0f;
    if (side_by_side && which > 0) {
      ImGui::SameLine();
    }
    plot.min_label_width(plots.shared_label_width);
    if (draw_quantity(document, plot, quantities[which], which == 2 || side_by_side,
                      ImVec2(width_px, height_px))) {
      widest_labels = std::max(widest_labels, plot.label_width_needed());
      draw_bands(plot, computed_axis_.key, which == 0);
      if (which == 0) {
        curves_drawn_ = b != nullptr ? 2 : 1;
      }
    }
  }
  plots.shared_label_width = widest_labels;
}

bool SweepPanel::draw_quantity(Document& document, Plot& plot, const Quantity& q, bool last,
                               ImVec2 size_px) const {
  const std::string& key = computed_axis_.key;
  // A hovered point reads in the input's own words and unit: "w = 213.9 g/m²", "n = 7".
  const auto x_text = [key](double shown) { return shown_value(key, from_shown(key, shown)); };
  const std::string symbol = q.symbol;
  const std::string unit = q.unit;
  const auto y_text = [symbol, unit](double y) {
    return symbol + " = " + detail::printf_string("%.4g", y) + unit;
  };
  // The x title only under the last plot.
  if (!plot.begin(
          q.id, size_px,
          PlotAxis{last ? axis_label(key) : std::string(), false, logarithmic_, false, x_text},
          PlotAxis{q.label, false, false, /*whole=*/q.steps, y_text})) {
    return false;
  }
  // Side by side (presented) to a room, each x title on its row of tick labels: the plots keep
  // the row. A phone's plots are too narrow to spare a tick label for it.
  if (size_px.x > 0.0f && !shows_one_view()) {
    plot.compact();
  }
  if (!shown_x_.empty()) {
    plot.fit_x_to(shown_x_.front(), shown_x_.back());
  }
  const auto curve = [&](const char* name, const std::vector<double>& ys, ImU32 colour) {
    if (q.steps) {
      plot.steps(name, shown_x_, ys, colour, 2.0f);
    } else {
      plot.line(name, shown_x_, ys, colour, 2.0f);
    }
  };
  // A legend only when the paper's points are shown; with B pinned, "A" and "B" stand for the
  // names above the plots.
  const bool overlay = overlay_shown();
  const bool pinned = q.compare_ys != nullptr;
  curve(overlay ? (pinned ? "A" : "model") : nullptr, q.ys, kSweepCurve.u32());
  if (pinned) {
    curve(overlay ? "B" : nullptr, *q.compare_ys, kCompareB.u32());
  }
  if (overlay) {
    plot.markers(overlay_label_.c_str(), q.paper_x, q.paper_y, kPaperPoint.u32(),
                 MarkerShape::Diamond, 5.0f);
  }
  plot.vertical_line(to_shown(key, get_number(document.scene().parameters(), key)),
                     kCurrentValue.u32());
  if (pinned) {
    plot.vertical_line(to_shown(key, get_number(document.compare().b().parameters, key)),
                       kCompareB.u32());
  }
  plot.end();
  return true;
}

std::optional<ImVec2> SweepPanel::screen_point(int which, double shown_x) const {
  const std::vector<double>& ys = which == 0   ? curves_.n
                                  : which == 1 ? curves_.Q
                                               : curves_.z_max_mm;
  std::optional<std::size_t> nearest;
  for (std::size_t i = 0; i < shown_x_.size() && i < ys.size(); ++i) {
    if (std::isfinite(ys[i]) &&
        (!nearest || std::abs(shown_x_[i] - shown_x) < std::abs(shown_x_[*nearest] - shown_x))) {
      nearest = i;
    }
  }
  if (!nearest) {
    return std::nullopt;
  }
  return plot_view(which).to_screen(shown_x_[*nearest], ys[*nearest]);
}

void SweepPanel::draw_bands(const Plot& plot, const std::string& key, bool label) const {
  const PlotView& view = plot.view();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(view.min, view.max, true);
  for (const RegimeBand& band : bands_) {
    float left = view.to_screen(to_shown(key, band.from), view.y_lo).x;
    float right = view.to_screen(to_shown(key, band.to), view.y_lo).x;
    if (left > right) {
      std::swap(left, right);
    }
    // A band of one sample still shows: at least 3 px wide.
    if (right - left < 3.0f) {
      const float middle = 0.5f * (left + right);
      left = middle - 1.5f;
      right = middle + 1.5f;
    }
    draw->AddRectFilled(ImVec2(left, view.min.y), ImVec2(right, view.max.y),
                        band.valid ? kRegimeBandFill.u32() : kRefusedBandFill.u32());
    const ImVec2 text_size = ImGui::CalcTextSize(band.name.c_str());
    if (label && text_size.x + 4.0f <= right - left) {
      draw->AddText(ImVec2(0.5f * (left + right - text_size.x), view.min.y + 2.0f), kDimText.u32(),
                    band.name.c_str());
    }
  }
  draw->PopClipRect();
}

void SweepPanel::draw_comparison(const Parameters& current) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame;
  if (!ImGui::BeginTable("paper vs model", 7, flags)) {
    return;
  }
  const std::string x_title = axis_label(overlay_key_);
  for (const char* title : {x_title.c_str(), "n paper", "n model", "Q paper", "Q model",
                            "z_max paper", "z_max model"}) {
    ImGui::TableSetupColumn(title);
  }
  ImGui::TableHeadersRow();
  for (std::size_t i = 0; i < overlay_x_.size(); ++i) {
    Parameters p = current;
    set_number(p, overlay_key_, overlay_x_[i]);
    if (!validate(p).empty()) {
      continue;
    }
    const Solution s = solve(p);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%.4g", to_shown(overlay_key_, overlay_x_[i]));
    ImGui::TableNextColumn();
    ImGui::Text("%.0f", overlay_n_[i]);
    ImGui::TableNextColumn();
    ImGui::Text("%d", s.n);
    ImGui::TableNextColumn();
    if (std::isnan(overlay_row_Q_[i])) {
      ImGui::TextUnformatted("–");
    } else {
      ImGui::Text("%.2f", overlay_row_Q_[i]);
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", s.Q);
    ImGui::TableNextColumn();
    ImGui::Text("%.0f mm", overlay_z_[i]);
    ImGui::TableNextColumn();
    ImGui::Text("%.1f mm", s.z_max_mm);
  }
  ImGui::EndTable();
}

}  // namespace foldlab::gui
