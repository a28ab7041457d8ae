#include "app/gui/panels/regime_map_panel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <span>

#include <imgui.h>

#include "app/gui/panels/axis_inputs.hpp"

namespace foldlab::gui {
namespace {

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

ImU32 cell_colour(const MapCell& cell, bool show_z) {
  if (!cell.valid) {
    return IM_COL32(0, 0, 0, 255);
  }
  switch (cell.regime) {
    case Regime::no_slack:
      return IM_COL32(60, 60, 60, 255);
    case Regime::short_cloth:
      return IM_COL32(120, 30, 30, 255);
    case Regime::negligible_slack:
      return IM_COL32(90, 90, 120, 255);
    default:
      break;
  }
  if (show_z) {
    // z_max from 0.1 mm to 1 m on a log scale.
    return ramp((std::log10(std::max(cell.z_max_mm, 0.1f)) + 1.0) / 4.0);
  }
  // n on a log scale up to 200; odd n a little darker so that every boundary shows.
  ImU32 c = ramp(std::log(static_cast<double>(cell.n)) / std::log(200.0));
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

struct RegimeMapPanel::Job {
  SweepAxis x;
  SweepAxis y;
  Parameters base;
  std::vector<MapCell> cells;
  std::unique_ptr<std::atomic<bool>[]> row_done;
  std::atomic<int> next_row{0};
  std::atomic<int> rows_done{0};
  std::atomic<bool> cancel{false};
  std::chrono::steady_clock::time_point start;
  std::atomic<double> elapsed_ms{0.0};
};

RegimeMapPanel::RegimeMapPanel() = default;

RegimeMapPanel::~RegimeMapPanel() {
  stop();
}

bool RegimeMapPanel::computing() const {
  return job_ && job_->rows_done.load() < job_->y.steps && !job_->cancel;
}

void RegimeMapPanel::stop() {
  if (job_) {
    job_->cancel = true;
  }
  for (std::thread& t : workers_) {
    t.join();
  }
  workers_.clear();
}

void RegimeMapPanel::restart(const Parameters& base) {
  stop();
  auto job = std::make_shared<Job>();
  job->x = {x_key_, x_from_, x_to_, resolution_, natural_log_scale(x_key_)};
  job->y = {y_key_, y_from_, y_to_, resolution_, natural_log_scale(y_key_)};
  job->base = base;
  job->cells.assign(static_cast<std::size_t>(resolution_) * resolution_, MapCell{});
  job->row_done = std::make_unique<std::atomic<bool>[]>(static_cast<std::size_t>(resolution_));
  job->start = std::chrono::steady_clock::now();
  job_ = job;
  job_base_ = base;
  job_started_ = true;
  rows_shown_ = -1;
  pixels_.assign(job->cells.size(), IM_COL32(25, 25, 30, 255));
  // Rows are handed out one at a time to every core, so the map fills evenly and a cancel is
  // honoured within one row.
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  for (unsigned t = 0; t < threads; ++t) {
    workers_.emplace_back([job] {
      const int rows = job->y.steps;
      const int columns = job->x.steps;
      for (int row = job->next_row++; row < rows && !job->cancel; row = job->next_row++) {
        map_rows(job->base, job->x, job->y, row, row + 1,
                 std::span<MapCell>(job->cells)
                     .subspan(static_cast<std::size_t>(row) * columns,
                              static_cast<std::size_t>(columns)));
        job->row_done[static_cast<std::size_t>(row)].store(true, std::memory_order_release);
        if (++job->rows_done == rows) {
          job->elapsed_ms = std::chrono::duration<double, std::milli>(
                                std::chrono::steady_clock::now() - job->start)
                                .count();
        }
      }
    });
  }
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
  if (!job_ || rows_shown_ == n) {
    return;
  }
  bool changed = rows_shown_ < 0;
  int shown = 0;
  for (int row = 0; row < n; ++row) {
    if (!job_->row_done[static_cast<std::size_t>(row)].load(std::memory_order_acquire)) {
      continue;
    }
    ++shown;
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(row) * n + i;
      const ImU32 c = cell_colour(job_->cells[k], show_z_);
      changed |= pixels_[k] != c;
      pixels_[k] = c;
    }
  }
  if (changed) {
    renderer.update_image(image_, n, n, pixels_.data());
  }
  rows_shown_ = shown == n ? n : 0;
}

void RegimeMapPanel::draw(Document& document, Renderer& renderer) {
  const Parameters& current = document.scene().parameters();
  bool restart_needed = !job_started_;
  ImGui::TextUnformatted("x");
  ImGui::SameLine();
  if (key_combo("##x key", x_key_)) {
    default_range(x_key_, get_number(current, x_key_), x_from_, x_to_);
    restart_needed = true;
  }
  ImGui::SameLine();
  restart_needed |= range_inputs("x range", x_from_, x_to_);
  ImGui::TextUnformatted("y");
  ImGui::SameLine();
  if (key_combo("##y key", y_key_)) {
    default_range(y_key_, get_number(current, y_key_), y_from_, y_to_);
    restart_needed = true;
  }
  ImGui::SameLine();
  restart_needed |= range_inputs("y range", y_from_, y_to_);
  ImGui::SetNextItemWidth(90.0f);
  static const int sizes[] = {64, 128, 256, 512};
  if (ImGui::BeginCombo("cells", (std::to_string(resolution_) + "²").c_str())) {
    for (int s : sizes) {
      if (ImGui::Selectable((std::to_string(s) + "²").c_str(), s == resolution_)) {
        restart_needed |= s != resolution_;
        resolution_ = s;
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Checkbox("show z_max instead of n", &show_z_)) {
    rows_shown_ = -1;
  }
  // The map depends on every input except its two axes.
  Parameters base_now = current;
  Parameters base_job = job_base_;
  set_number(base_now, x_key_, 1.0);
  set_number(base_now, y_key_, 1.0);
  set_number(base_job, x_key_, 1.0);
  set_number(base_job, y_key_, 1.0);
  restart_needed |= !(base_now == base_job);
  const SweepAxis x_check{x_key_, x_from_, x_to_, resolution_, natural_log_scale(x_key_)};
  const SweepAxis y_check{y_key_, y_from_, y_to_, resolution_, natural_log_scale(y_key_)};
  for (const SweepAxis* axis : {&x_check, &y_check}) {
    if (auto problem = check_axis(*axis)) {
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", problem->c_str());
      return;
    }
  }
  if (x_key_ == y_key_) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "choose two different inputs");
    return;
  }
  if (restart_needed) {
    restart(current);
  }
  update_image(renderer);
  const int done = job_->rows_done.load();
  if (done < resolution_) {
    ImGui::ProgressBar(static_cast<float>(done) / static_cast<float>(resolution_),
                       ImVec2(-1.0f, 0.0f));
  } else {
    last_map_ms_ = job_->elapsed_ms.load();
    ImGui::TextDisabled("%d x %d solves in %.0f ms on %zu threads; click to move the sliders there",
                        resolution_, resolution_, last_map_ms_, workers_.size());
  }

  const ImVec2 available = ImGui::GetContentRegionAvail();
  const float side = std::max(64.0f, std::min(available.x - 60.0f, available.y - 24.0f));
  const ImVec2 origin(ImGui::GetCursorScreenPos().x + 50.0f, ImGui::GetCursorScreenPos().y);
  ImGui::SetCursorScreenPos(origin);
  // Row 0 is the lowest y: the texture's first row goes to the bottom.
  ImGui::Image(renderer.texture(image_), ImVec2(side, side), ImVec2(0, 1), ImVec2(1, 0));
  const bool hovered = ImGui::IsItemHovered();
  const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const Job& job = *job_;
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", job.y.to);
  draw->AddText(ImVec2(origin.x - 48.0f, origin.y), IM_COL32(200, 200, 200, 255), text);
  std::snprintf(text, sizeof text, "%.3g", job.y.from);
  draw->AddText(ImVec2(origin.x - 48.0f, origin.y + side - 14.0f), IM_COL32(200, 200, 200, 255),
                text);
  draw->AddText(ImVec2(origin.x - 48.0f, origin.y + side * 0.5f - 7.0f),
                IM_COL32(200, 200, 200, 255), axis_label(job.y.key).c_str());
  std::snprintf(text, sizeof text, "%.3g", job.x.from);
  draw->AddText(ImVec2(origin.x, origin.y + side + 2.0f), IM_COL32(200, 200, 200, 255), text);
  std::snprintf(text, sizeof text, "%.3g", job.x.to);
  draw->AddText(ImVec2(origin.x + side - 40.0f, origin.y + side + 2.0f),
                IM_COL32(200, 200, 200, 255), text);
  draw->AddText(ImVec2(origin.x + side * 0.5f - 20.0f, origin.y + side + 2.0f),
                IM_COL32(200, 200, 200, 255), axis_label(job.x.key).c_str());
  // The current point.
  const double fx = axis_fraction(job.x, get_number(current, job.x.key));
  const double fy = axis_fraction(job.y, get_number(current, job.y.key));
  if (fx >= 0.0 && fx <= 1.0 && fy >= 0.0 && fy <= 1.0) {
    const ImVec2 p(origin.x + static_cast<float>(fx) * side,
                   origin.y + static_cast<float>(1.0 - fy) * side);
    draw->AddCircle(p, 6.0f, IM_COL32(255, 255, 255, 255), 16, 2.0f);
    draw->AddCircle(p, 8.0f, IM_COL32(0, 0, 0, 255), 16, 1.0f);
  }
  if (hovered) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const double u = std::clamp((mouse.x - origin.x) / side, 0.0f, 1.0f);
    const double v = std::clamp(1.0f - (mouse.y - origin.y) / side, 0.0f, 1.0f);
    const int i = std::min(resolution_ - 1, static_cast<int>(u * resolution_));
    const int j = std::min(resolution_ - 1, static_cast<int>(v * resolution_));
    const double x_value = job.x.value(i);
    const double y_value = job.y.value(j);
    const MapCell& cell = job.cells[static_cast<std::size_t>(j) * resolution_ + i];
    if (job.row_done[static_cast<std::size_t>(j)].load()) {
      ImGui::SetTooltip("%s = %.4g, %s = %.4g\n%s\nn = %d, z_max = %.1f mm", job.x.key.c_str(),
                        x_value, job.y.key.c_str(), y_value,
                        cell.valid ? std::string(to_string(cell.regime)).c_str() : "invalid inputs",
                        cell.n, cell.z_max_mm);
    }
    if (clicked) {
      document.set_input(job.x.key, x_value);
      document.set_input(job.y.key, y_value);
    }
  }
}

}  // namespace foldlab::gui
