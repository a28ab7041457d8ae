#include "app/gui/panels/regime_map_panel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <vector>

#include <imgui.h>

#include "app/gui/panels/axis_inputs.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/presentation_bar.hpp"
#include "core/model/hardware_threads.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {
namespace {

// A swatch's side: a frame's under the map, a text line's on the y title's row when presented
// (the row then stays a line tall, and the room is the map's).
float swatch_side(bool on_title_row) {
  return on_title_row ? ImGui::GetTextLineHeight() : ImGui::GetFrameHeight();
}

// Dark blue through teal to yellow, t in [0, 1]; our own ramp, ordered in lightness.
ImU32 ramp(double t) {
  static const float stops[][3] = {{0.13f, 0.09f, 0.35f},
                                   {0.15f, 0.35f, 0.60f},
                                   {0.12f, 0.60f, 0.58f},
                                   {0.45f, 0.80f, 0.35f},
                                   {0.98f, 0.90f, 0.20f}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const float f = static_cast<float>(t - i);
  float rgb[3];
  for (int c = 0; c < 3; ++c) {
    rgb[c] = stops[i][c] + f * (stops[i + 1][c] - stops[i][c]);
  }
  return IM_COL32(static_cast<int>(rgb[0] * 255), static_cast<int>(rgb[1] * 255),
                  static_cast<int>(rgb[2] * 255), 255);
}

// The colours of the cells that have no n to show, with the names the colour bar gives them.
constexpr ImU32 kInvalidColour = IM_COL32(0, 0, 0, 255);
constexpr ImU32 opaque(std::uint32_t rgb) {
  return IM_COL32((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff, 255);
}
struct Swatch {
  const char* name;
  ImU32 colour;
};
// The regime table's coloured regimes, then the refused inputs.
const std::vector<Swatch>& map_swatches() {
  static const std::vector<Swatch> swatches = [] {
    std::vector<Swatch> out;
    for (const RegimeInfo& info : kRegimes) {
      if (info.map_rgb) {
        out.push_back({info.label.data(), opaque(*info.map_rgb)});
      }
    }
    out.push_back({"invalid inputs", kInvalidColour});
    return out;
  }();
  return swatches;
}

// z_max from 0.1 mm to 1 m on a log scale.
double z_fraction(double z_max_mm) {
  return (std::log10(std::max(z_max_mm, 0.1)) + 1.0) / 4.0;
}
// n on a log scale up to 200.
double n_fraction(double n) {
  return std::log(n) / std::log(200.0);
}

ImU32 cell_colour(const MapCell& cell, bool show_z) {
  if (!cell.valid) {
    return kInvalidColour;
  }
  if (const std::optional<std::uint32_t> rgb = regime_info(cell.regime).map_rgb) {
    return opaque(*rgb);
  }
  if (show_z) {
    return ramp(z_fraction(cell.z_max_mm));
  }
  // Odd n a little darker so that every boundary shows.
  ImU32 c = ramp(n_fraction(static_cast<double>(cell.n)));
  if (cell.n % 2 == 1) {
    c = (c & 0xff000000u) | (((c & 0x00fefefeu) >> 1) + ((c & 0x00fcfcfcu) >> 2));
  }
  return c;
}

double axis_fraction(const SweepAxis& axis, double value) {
  return axis.logarithmic ? std::log(value / axis.from) / std::log(axis.to / axis.from)
                          : (value - axis.from) / (axis.to - axis.from);
}

}  // namespace

// The map's cells and which rows are done, shared by the job's threads and the panel, which
// shows the rows as they arrive.
struct RegimeMapPanel::Cells {
  SweepAxis x;
  SweepAxis y;
  Parameters base;
  std::vector<MapCell> cells;
  std::unique_ptr<std::atomic<bool>[]> row_done;
  std::atomic<int> next_row{0};
  std::atomic<int> rows_done{0};
};

RegimeMapPanel::RegimeMapPanel() = default;

RegimeMapPanel::~RegimeMapPanel() = default;  // the job cancels and joins its threads

void RegimeMapPanel::restart(const Parameters& base, const std::function<void()>& wake) {
  job_.stop();
  auto cells = std::make_shared<Cells>();
  cells->x = {x_key_, x_from_, x_to_, resolution_, natural_log_scale(x_key_)};
  cells->y = {y_key_, y_from_, y_to_, resolution_, natural_log_scale(y_key_)};
  cells->base = base;
  cells->cells.assign(static_cast<std::size_t>(resolution_) * resolution_, MapCell{});
  cells->row_done = std::make_unique<std::atomic<bool>[]>(static_cast<std::size_t>(resolution_));
  cells_ = cells;
  job_base_ = base;
  job_started_ = true;
  rows_shown_ = -1;
  pixels_.assign(cells->cells.size(), IM_COL32(25, 25, 30, 255));
  threads_ = static_cast<unsigned>(hardware_threads());
  // Rows are handed out one at a time (to every core where there are threads, a slice of frames
  // where not), so the map fills evenly and a cancel is honoured within one row.
  const auto start = std::chrono::steady_clock::now();
  JobSteps<double> steps;
  steps.parallel = threads_;
  steps.step = [cells](JobToken& token) {
    const int rows = cells->y.steps;
    const int columns = cells->x.steps;
    const int row = cells->next_row++;
    if (row >= rows) {
      return true;
    }
    map_rows(cells->base, cells->x, cells->y, row, row + 1,
             std::span<MapCell>(cells->cells)
                 .subspan(static_cast<std::size_t>(row) * static_cast<std::size_t>(columns),
                          static_cast<std::size_t>(columns)));
    cells->row_done[static_cast<std::size_t>(row)].store(true, std::memory_order_release);
    token.report(static_cast<double>(++cells->rows_done) / rows);
    return row + 1 >= rows;
  };
  steps.finish = [start] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
  };
  job_.start_slices(std::move(steps), wake);
}

void RegimeMapPanel::update_image(Renderer& renderer) {
  const int n = resolution_;
  if (image_ < 0) {
    image_ = renderer.create_image();
  }
  if (image_size_ != n) {
    image_size_ = n;
    rows_shown_ = -1;
  }
  if (!cells_ || rows_shown_ == n) {
    return;
  }
  bool changed = rows_shown_ < 0;
  int shown = 0;
  for (int row = 0; row < n; ++row) {
    if (!cells_->row_done[static_cast<std::size_t>(row)].load(std::memory_order_acquire)) {
      continue;
    }
    ++shown;
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(row) * n + i;
      const ImU32 c = cell_colour(cells_->cells[k], show_z_);
      changed |= pixels_[k] != c;
      pixels_[k] = c;
    }
  }
  if (changed) {
    renderer.update_image(image_, n, n, pixels_.data());
  }
  rows_shown_ = shown == n ? n : 0;
}

bool RegimeMapPanel::controls(const Parameters& current) {
  bool restart_needed = false;
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("x");
  ImGui::SameLine();
  if (key_combo("##x key", x_key_)) {
    default_range(x_key_, get_number(current, x_key_), x_from_, x_to_);
    restart_needed = true;
  }
  same_line_if_fits(range_inputs_width());
  restart_needed |= range_inputs("x range", x_key_, x_from_, x_to_);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("y");
  ImGui::SameLine();
  if (key_combo("##y key", y_key_)) {
    default_range(y_key_, get_number(current, y_key_), y_from_, y_to_);
    restart_needed = true;
  }
  same_line_if_fits(range_inputs_width());
  restart_needed |= range_inputs("y range", y_key_, y_from_, y_to_);
  static const int sizes[] = {64, 128, 256, 512};
  std::vector<std::string> size_names;
  for (int s : sizes) {
    size_names.push_back(std::to_string(s) + "²");
  }
  ImGui::SetNextItemWidth(combo_width(size_names));
  if (begin_combo("cells", (std::to_string(resolution_) + "²").c_str())) {
    for (int s : sizes) {
      if (ImGui::Selectable((std::to_string(s) + "²").c_str(), s == resolution_)) {
        restart_needed |= s != resolution_;
        resolution_ = s;
      }
    }
    end_combo();
  }
  same_line_if_fits(checkbox_width("show z_max instead of n"));
  if (ImGui::Checkbox("show z_max instead of n", &show_z_)) {
    rows_shown_ = -1;
  }
  return restart_needed;
}

// The map depends on every input except its two axes.
bool RegimeMapPanel::other_inputs_changed(const Parameters& current) const {
  Parameters base_now = current;
  Parameters base_job = job_base_;
  set_number(base_now, x_key_, 1.0);
  set_number(base_now, y_key_, 1.0);
  set_number(base_job, x_key_, 1.0);
  set_number(base_job, y_key_, 1.0);
  return !(base_now == base_job);
}

bool RegimeMapPanel::axes_refused() const {
  const SweepAxis x_check{x_key_, x_from_, x_to_, resolution_, natural_log_scale(x_key_)};
  const SweepAxis y_check{y_key_, y_from_, y_to_, resolution_, natural_log_scale(y_key_)};
  for (const SweepAxis* axis : {&x_check, &y_check}) {
    if (auto problem = check_axis(*axis)) {
      ImGui::TextColored(kErrorText, "%s", problem->c_str());
      return true;
    }
  }
  if (x_key_ == y_key_) {
    ImGui::TextColored(kErrorText, "choose two different inputs");
    return true;
  }
  return false;
}

void RegimeMapPanel::status_line() {
  if (std::optional<double> ms = job_.take_result()) {
    last_map_ms_ = *ms;
  }
  const int done = cells_->rows_done.load();
  if (job_.running() || done < resolution_) {
    ImGui::ProgressBar(static_cast<float>(done) / static_cast<float>(resolution_),
                       ImVec2(-1.0f, 0.0f));
  } else if (!toolbar_row_.folded()) {
    // Folded, the map keeps the room: the line is under the settings in their popup.
    timing_text();
  }
}

void RegimeMapPanel::timing_text() const {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  wrapped_text("%d x %d solves in %.0f ms on %u threads; click to move the sliders there",
               resolution_, resolution_, last_map_ms_, threads_);
  ImGui::PopStyleColor();
}

// The map with its axis labels (the y title above it, the x title under the x ticks), a colour
// bar on its right (the ramp with its scale) and, below, the regimes that have no n to show as
// swatches with their names. Every size follows the font, so the UI scale keeps it readable.
RegimeMapPanel::Placement RegimeMapPanel::place_map(bool compact) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  const ImVec2 available = ImGui::GetContentRegionAvail();
  Placement at;
  at.compact = compact;
  const float bar_area = style.ItemSpacing.x + ems(1.0f) + style.ItemInnerSpacing.x +
                         ImGui::CalcTextSize(show_z_ ? "1000 mm" : "200").x;
  float swatches_width = 0.0f;
  for (const Swatch& swatch : map_swatches()) {
    swatches_width += swatch_side(compact) + style.ItemInnerSpacing.x +
                      ImGui::CalcTextSize(swatch.name).x + style.ItemSpacing.x;
  }
  const std::string y_label = axis_label(cells_->y.key);
  // Presented, the swatches go on the y title's row where they fit between the title and the
  // colour bar's "n" (a swatch is a frame tall, more than the row's line: the row grows to it).
  const float title_width = ImGui::CalcTextSize(y_label.c_str()).x + 2.0f * style.ItemSpacing.x;
  at.swatches_on_title_row =
      compact &&
      title_width + swatches_width + bar_area + ImGui::CalcTextSize("n").x <= available.x;
  const float swatch_rows =
      at.swatches_on_title_row
          ? swatch_side(compact) - ImGui::GetTextLineHeight()
          : (swatches_width <= available.x ? 1.0f : 2.0f) * ImGui::GetFrameHeightWithSpacing();
  // Half a line under the y title, where the top label reaches up to; the x title's line under
  // the x ticks unless presented.
  const float tallest =
      std::max(ems(5.0f), available.y - (compact ? 2.5f : 3.5f) * font - swatch_rows);
  // The y labels' width at the tallest the map can be: as many labels or fewer fit a shorter one.
  at.left_margin = 0.0f;
  for (const std::string& label : map_ticks(cells_->y, tallest, false).labels) {
    at.left_margin = std::max(at.left_margin, ImGui::CalcTextSize(label.c_str()).x);
  }
  at.left_margin += style.ItemInnerSpacing.x;
  // As wide as the panel allows: presented, the map takes the screen's width, not a square.
  at.width = std::max(ems(5.0f), available.x - at.left_margin - bar_area);
  at.height = tallest;
  const ImVec2 title_at = ImGui::GetCursorScreenPos();
  if (at.swatches_on_title_row) {
    // The title on the swatches' middle line.
    ImGui::SetCursorScreenPos(ImVec2(
        title_at.x, title_at.y + 0.5f * (swatch_side(compact) - ImGui::GetTextLineHeight())));
  }
  ImGui::TextUnformatted(y_label.c_str());
  at.swatches_at = ImVec2(title_at.x + title_width, title_at.y);
  at.origin = ImVec2(ImGui::GetCursorScreenPos().x + at.left_margin,
                     ImGui::GetCursorScreenPos().y + 0.5f * font);
  if (at.swatches_on_title_row) {
    at.origin.y = title_at.y + swatch_side(compact) + 0.5f * font;
  }
  return at;
}

// An axis's round ticks in the unit its slider shows, as many as have room for their labels.
AxisTicks RegimeMapPanel::map_ticks(const SweepAxis& axis, float length_px, bool horizontal) {
  const float font = ImGui::GetFontSize();
  const auto extent = [&](const std::string& label) {
    return horizontal ? ImGui::CalcTextSize(label.c_str()).x : font;
  };
  return fitted_ticks(to_shown(axis.key, axis.from), to_shown(axis.key, axis.to), axis.logarithmic,
                      length_px, extent, 0.5f * font, 10);
}

void RegimeMapPanel::axis_labels(const Placement& at) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  const float tick_px = std::round(0.3f * font);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 text_colour = ImGui::GetColorU32(ImGuiCol_Text);
  const AxisTicks y_ticks = map_ticks(cells_->y, at.height, false);
  for (std::size_t k = 0; k < y_ticks.values.size(); ++k) {
    const double f = axis_fraction(cells_->y, from_shown(cells_->y.key, y_ticks.values[k]));
    const float y = at.origin.y + static_cast<float>(1.0 - f) * at.height;
    draw->AddLine(ImVec2(at.origin.x - tick_px, y), ImVec2(at.origin.x, y), text_colour);
    const char* label = y_ticks.labels[k].c_str();
    const float label_y = std::clamp(y - 0.5f * font, at.origin.y - 0.5f * font,
                                     at.origin.y + at.height - 0.5f * font);
    draw->AddText(
        ImVec2(at.origin.x - style.ItemInnerSpacing.x - ImGui::CalcTextSize(label).x, label_y),
        text_colour, label);
  }
  const AxisTicks x_ticks = map_ticks(cells_->x, at.width, true);
  const std::string x_label = axis_label(cells_->x.key);
  const float bottom = at.origin.y + at.height;
  // Compact: the title at the left end of the tick labels' row; a label it would meet is left
  // out.
  const float title_end = at.compact ? at.origin.x - at.left_margin +
                                           ImGui::CalcTextSize(x_label.c_str()).x + 0.5f * font
                                     : -std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k < x_ticks.values.size(); ++k) {
    const double f = axis_fraction(cells_->x, from_shown(cells_->x.key, x_ticks.values[k]));
    const float x = at.origin.x + static_cast<float>(f) * at.width;
    draw->AddLine(ImVec2(x, bottom), ImVec2(x, bottom + tick_px), text_colour);
    const char* label = x_ticks.labels[k].c_str();
    const float left = x - 0.5f * ImGui::CalcTextSize(label).x;
    if (left < title_end) {
      continue;
    }
    draw->AddText(ImVec2(left, bottom + tick_px), text_colour, label);
  }
  if (at.compact) {
    draw->AddText(ImVec2(at.origin.x - at.left_margin, bottom + tick_px), text_colour,
                  x_label.c_str());
  } else {
    draw->AddText(ImVec2(at.origin.x + 0.5f * (at.width - ImGui::CalcTextSize(x_label.c_str()).x),
                         bottom + tick_px + font),
                  text_colour, x_label.c_str());
  }
}

// The same ramp and scale as the cells, bottom to top.
void RegimeMapPanel::colour_bar(const Placement& at) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  const float side = at.height;
  const float bar_width = ems(1.0f);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 text_colour = ImGui::GetColorU32(ImGuiCol_Text);
  const ImVec2 bar_min(at.origin.x + at.width + style.ItemSpacing.x, at.origin.y);
  const ImVec2 bar_max(bar_min.x + bar_width, at.origin.y + side);
  constexpr int kBarSteps = 64;
  for (int k = 0; k < kBarSteps; ++k) {
    const float y0 = bar_max.y - side * static_cast<float>(k + 1) / kBarSteps;
    const float y1 = bar_max.y - side * static_cast<float>(k) / kBarSteps;
    draw->AddRectFilled(ImVec2(bar_min.x, std::floor(y0)), ImVec2(bar_max.x, std::ceil(y1)),
                        ramp((k + 0.5) / kBarSteps));
  }
  draw->AddRect(bar_min, bar_max, ImGui::GetColorU32(ImGuiCol_Border));
  static const double n_ticks[] = {1, 2, 5, 10, 20, 50, 100, 200};
  static const double z_ticks_mm[] = {0.1, 1, 10, 100, 1000};
  const std::span<const double> ticks =
      show_z_ ? std::span<const double>(z_ticks_mm) : std::span<const double>(n_ticks);
  const auto tick_y = [&](double tick) {
    return bar_max.y - side * static_cast<float>(show_z_ ? z_fraction(tick) : n_fraction(tick));
  };
  const auto label_y_at = [&](float y) {
    return std::clamp(y - 0.5f * font, bar_min.y, bar_max.y - font);
  };
  // Both ends of the scale are always labelled; ticks between only where their labels fit.
  const float top_label_y = label_y_at(tick_y(ticks.back()));
  float last_label_y = 1e9f;
  char text[64];
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    const double tick = ticks[k];
    const float y = tick_y(tick);
    draw->AddLine(ImVec2(bar_max.x - 0.3f * bar_width, y), ImVec2(bar_max.x, y), text_colour);
    const float label_y = label_y_at(y);
    const bool end = k == 0 || k + 1 == ticks.size();
    if (!end && (last_label_y - label_y < font || label_y - top_label_y < font)) {
      continue;  // no room for this label on a short bar
    }
    std::snprintf(text, sizeof text, show_z_ ? "%g mm" : "%g", tick);
    draw->AddText(ImVec2(bar_max.x + style.ItemInnerSpacing.x, label_y), text_colour, text);
    last_label_y = label_y;
  }
  // Above the bar, on the y title's line: under it the last x tick's label ran into it.
  draw->AddText(ImVec2(bar_min.x, bar_min.y - 1.5f * font), text_colour, show_z_ ? "z_max" : "n");

  if (ImGui::IsMouseHoveringRect(bar_min, bar_max)) {
    ImGui::SetTooltip(show_z_ ? "z_max of the wrinkled cells, log scale"
                              : "n of the wrinkled cells, log scale; odd n a little darker so "
                                "that every step shows");
  }
}

// Below the map and its x labels: the regimes drawn in their own colours.
void RegimeMapPanel::regime_swatches(const Placement& at) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  ImGui::SetCursorScreenPos(
      at.swatches_on_title_row
          ? at.swatches_at
          : ImVec2(at.origin.x - at.left_margin,
                   at.origin.y + at.height + 2.0f * font + std::round(0.3f * font) + 2.0f));
  bool first = true;
  const float side = swatch_side(at.swatches_on_title_row);
  for (const Swatch& swatch : map_swatches()) {
    const float width = side + style.ItemInnerSpacing.x + ImGui::CalcTextSize(swatch.name).x;
    if (!first) {
      same_line_if_fits(width);
    }
    first = false;
    // Outlined in the text's colour: the dark swatches alone hardly stand out from a dark theme.
    ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, std::max(1.0f, std::round(0.07f * font)));
    ImGui::PushStyleColor(ImGuiCol_Border, ImGui::GetStyle().Colors[ImGuiCol_Text]);
    ImGui::ColorButton(swatch.name, ImGui::ColorConvertU32ToFloat4(swatch.colour),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                       ImVec2(side, side));
    ImGui::PopStyleColor();
    ImGui::PopStyleVar();
    ImGui::SameLine(0.0f, style.ItemInnerSpacing.x);
    ImGui::TextUnformatted(swatch.name);
  }
}

void RegimeMapPanel::current_point(const Placement& at, const Parameters& current) const {
  const double fx = axis_fraction(cells_->x, get_number(current, cells_->x.key));
  const double fy = axis_fraction(cells_->y, get_number(current, cells_->y.key));
  if (fx >= 0.0 && fx <= 1.0 && fy >= 0.0 && fy <= 1.0) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p(at.origin.x + static_cast<float>(fx) * at.width,
                   at.origin.y + static_cast<float>(1.0 - fy) * at.height);
    draw->AddCircle(p, 6.0f, IM_COL32(255, 255, 255, 255), 16, 2.0f);
    draw->AddCircle(p, 8.0f, IM_COL32(0, 0, 0, 255), 16, 1.0f);
  }
}

void RegimeMapPanel::hover_and_click(const Placement& at, Document& document, bool clicked) const {
  const Cells& job = *cells_;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const double u = std::clamp((mouse.x - at.origin.x) / at.width, 0.0f, 1.0f);
  const double v = std::clamp(1.0f - (mouse.y - at.origin.y) / at.height, 0.0f, 1.0f);
  const int i = std::min(resolution_ - 1, static_cast<int>(u * resolution_));
  const int j = std::min(resolution_ - 1, static_cast<int>(v * resolution_));
  const double x_value = job.x.value(i);
  const double y_value = job.y.value(j);
  const MapCell& cell = job.cells[static_cast<std::size_t>(j) * resolution_ + i];
  if (job.row_done[static_cast<std::size_t>(j)].load()) {
    const std::string x_text = shown_value(job.x.key, x_value);
    const std::string y_text = shown_value(job.y.key, y_value);
    ImGui::SetTooltip("%s, %s\n%s\nn = %d%s, z_max = %.1f mm", x_text.c_str(), y_text.c_str(),
                      cell.valid ? std::string(to_string(cell.regime)).c_str() : "invalid inputs",
                      cell.n, cell.n_capped ? " (capped: eq. 10 asks for more)" : "",
                      cell.z_max_mm);
  }
  if (clicked) {
    // Both axes at once: one undo step brings back the point before the click.
    document.apply(Edit::inputs({{job.x.key, x_value}, {job.y.key, y_value}}));
  }
}

nlohmann::json RegimeMapPanel::report() const {
  if (!cells_) {
    return nullptr;
  }
  // The cells' n, regime and flags hashed (FNV-1a), and z_max summed: two builds' maps compare
  // by these without the report carrying every cell.
  std::uint64_t hash = 14695981039346656037ull;
  const auto mix = [&hash](std::uint64_t value) {
    for (int byte = 0; byte < 8; ++byte) {
      hash ^= (value >> (8 * byte)) & 0xffu;
      hash *= 1099511628211ull;
    }
  };
  double z_sum_mm = 0.0;
  long long n_sum = 0;
  for (std::size_t row = 0; row < static_cast<std::size_t>(cells_->y.steps); ++row) {
    if (!cells_->row_done[row].load(std::memory_order_acquire)) {
      continue;
    }
    for (std::size_t i = 0; i < static_cast<std::size_t>(cells_->x.steps); ++i) {
      const MapCell& cell = cells_->cells[row * static_cast<std::size_t>(cells_->x.steps) + i];
      mix(static_cast<std::uint64_t>(cell.n));
      mix(static_cast<std::uint64_t>(cell.regime));
      mix((cell.valid ? 1u : 0u) | (cell.n_capped ? 2u : 0u));
      z_sum_mm += cell.z_max_mm;
      n_sum += cell.n;
    }
  }
  char digest[17];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(hash));
  return {{"x", cells_->x.key},
          {"y", cells_->y.key},
          {"cells", cells_->x.steps * cells_->y.steps},
          {"rows_done", cells_->rows_done.load()},
          {"computing", computing()},
          {"settings_folded", toolbar_row_.folded()},
          {"shows", show_z_ ? "z_max" : "n"},
          {"n_sum", n_sum},
          {"z_max_sum_mm", z_sum_mm},
          {"digest", digest}};
}

// The map, its axis titles, colour bar and swatches at the least size that still reads.
constexpr float kLeastMapHeightEms = 12.0f;

void RegimeMapPanel::draw(PanelContext& context, bool presented) {
  Document& document = context.document;
  const Parameters& current = document.scene().parameters();
  bool restart_needed = !job_started_ || other_inputs_changed(current);
  if (toolbar_row_.begin("map settings...", ems(kLeastMapHeightEms), presented)) {
    restart_needed |= controls(current);
    if (toolbar_row_.folded()) {
      timing_text();
    }
    toolbar_row_.end();
  }
  if (axes_refused()) {
    return;
  }
  if (restart_needed) {
    restart(current, context.wake);
  }
  update_image(context.renderer);
  status_line();
  // A phone has the height, and too narrow a row for the swatches beside the title.
  const Placement at = place_map(presented && !shows_one_view());
  ImGui::SetCursorScreenPos(at.origin);
  // Row 0 is the lowest y: the texture's first row goes to the bottom.
  drawn_.mark(PanelRect{at.origin, ImVec2(at.width, at.height)});
  ImGui::Image(context.renderer.texture(image_), ImVec2(at.width, at.height), ImVec2(0, 1),
               ImVec2(1, 0));
  const bool hovered = ImGui::IsItemHovered();
  const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  axis_labels(at);
  colour_bar(at);
  regime_swatches(at);
  current_point(at, current);
  if (hovered) {
    hover_and_click(at, document, clicked);
  }
}

}  // namespace foldlab::gui
