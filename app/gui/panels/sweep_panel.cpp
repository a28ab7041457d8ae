#include "app/gui/panels/sweep_panel.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <imgui.h>

#include "app/common/presets_dir.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/panels/axis_inputs.hpp"
#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/model/solver.hpp"

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
  n_plot_.request_autoscale();
}

void SweepPanel::draw(Document& document) {
  const Parameters& current = document.scene().parameters();
  // The paper's points describe the case they came with, not whatever is loaded next.
  if (!overlay_label_.empty() && document.loads() != overlay_load_) {
    clear_overlay();
  }
  if (key_combo("input", key_)) {
    logarithmic_ = natural_log_scale(key_);
    default_range(key_, get_number(current, key_), from_, to_);
    clear_overlay();
  }
  // A narrow panel wraps the row rather than push "log" and "steps" out of sight.
  same_line_if_fits(range_inputs_width());
  range_inputs("range", key_, from_, to_);
  same_line_if_fits(checkbox_width("log"));
  ImGui::Checkbox("log", &logarithmic_);
  same_line_if_fits(labelled_width(ems(6.0f), "steps"));
  ImGui::SetNextItemWidth(ems(6.0f));
  ImGui::SliderInt("steps", &steps_, 10, 1000, "%d", ImGuiSliderFlags_AlwaysClamp);

  for (int which = 0; which < kPaperCases; ++which) {
    if (ImGui::SmallButton(kPaperCaseButtons[which])) {
      document.replace_edits(
          std::string("Loading the paper's ") + kPaperCaseButtons[which] + " replaces them.",
          [this, which](Document& d) { select_paper_case(which, d); });
    }
    ImGui::SameLine();
  }
  ImGui::NewLine();

  SweepAxis check{key_, from_, to_, steps_, logarithmic_};
  if (auto problem = check_axis(check)) {
    ImGui::TextColored(kErrorText, "%s", problem->c_str());
    return;
  }
  recompute(current);
  recompute_compare(document);
  const std::string& key = computed_axis_.key;
  const double now = to_shown(key, get_number(current, key));
  const bool overlay = !overlay_label_.empty() && overlay_key_ == key;
  // The paper's rows against the model's: folded by default, since the plots need the height.
  if (overlay && ImGui::CollapsingHeader("Paper vs model (table)")) {
    draw_comparison(current);
  }
  // With B pinned, a line each names A's and B's colours for the three plots (a legend under
  // each would take the plots' height), wrapped rather than cut in a narrow panel; where the
  // paper's points need a legend, "A" and "B" stand for those names.
  const SweepCurves* b = compare_computed_ ? &compare_curves_ : nullptr;
  const std::string a_legend = b ? "A" : "model";
  const std::string b_legend = "B";
  if (b != nullptr) {
    draw_compare_names(document);
  }
  // Each plot keeps room for its ticks, its title and a few lines of data at any UI scale: a
  // short panel scrolls rather than squeeze a plot under its own labels.
  const float height =
      std::max(ems(kMinPlotHeightEms), (ImGui::GetContentRegionAvail().y - 8.0f) / 3.0f);
  struct Quantity {
    Plot& plot;
    const char* id;
    const char* label;
    const std::vector<double>& ys;
    const std::vector<double>& paper_x;
    const std::vector<double>& paper_y;
    bool steps;
    const std::vector<double>* compare_ys;  // B's, while pinned
  };
  const Quantity quantities[] = {
      {n_plot_, "sweep n", "n", curves_.n, overlay_shown_x_, overlay_n_, true, b ? &b->n : nullptr},
      {Q_plot_, "sweep Q", "Q", curves_.Q, overlay_Q_shown_x_, overlay_Q_, false,
       b ? &b->Q : nullptr},
      {z_plot_, "sweep z", "z_max (mm)", curves_.z_max_mm, overlay_shown_x_, overlay_z_, false,
       b ? &b->z_max_mm : nullptr},
  };
  // The three data areas start at one x, so that the current value's line is one line down all
  // three: each plot's tick labels take the widest's room (last frame's).
  float widest_labels = 0.0f;
  for (const Quantity& q : quantities) {
    // The x title only under the last plot; a legend only when the paper's points are shown.
    const bool last = &q == &quantities[2];
    q.plot.min_label_width(shared_label_width_);
    if (!q.plot.begin(q.id, ImVec2(0.0f, height),
                      PlotAxis{last ? axis_label(key) : std::string(), false, logarithmic_},
                      PlotAxis{q.label, false, false})) {
      continue;
    }
    if (!shown_x_.empty()) {
      q.plot.fit_x_to(shown_x_.front(), shown_x_.back());
    }
    const char* legend = overlay ? a_legend.c_str() : nullptr;
    const auto curve = [&](const char* name, const std::vector<double>& ys, ImU32 colour) {
      if (q.steps) {
        q.plot.steps(name, shown_x_, ys, colour, 2.0f);
      } else {
        q.plot.line(name, shown_x_, ys, colour, 2.0f);
      }
    };
    curve(legend, q.ys, kSweepCurve.u32());
    if (q.compare_ys != nullptr) {
      curve(overlay ? b_legend.c_str() : nullptr, *q.compare_ys, kCompareB.u32());
    }
    if (&q == &quantities[0]) {
      curves_drawn_ = q.compare_ys != nullptr ? 2 : 1;
    }
    if (overlay) {
      q.plot.markers(overlay_label_.c_str(), q.paper_x, q.paper_y, kPaperPoint.u32(),
                     MarkerShape::Diamond, 5.0f);
    }
    q.plot.vertical_line(now, kCurrentValue.u32());
    if (b != nullptr) {
      q.plot.vertical_line(to_shown(key, get_number(document.compare().b().parameters, key)),
                           kCompareB.u32());
    }
    q.plot.end();
    widest_labels = std::max(widest_labels, q.plot.label_width_needed());
    draw_bands(q.plot, key, &q == &quantities[0]);
  }
  shared_label_width_ = widest_labels;
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
