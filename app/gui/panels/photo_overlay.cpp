#include "app/gui/panels/photo_overlay.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <utility>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/version.hpp"
#include "app/gui/calibration_job.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/io/measurements.hpp"
#include "core/io/preset.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

using detail::printf_string;
using nlohmann::json;

// The provisional frame before the supports are placed: the photo a span and a fifth wide,
// centred, its top a little above the supports' line, so that the supports in a photo framed
// around the cloth are near the plot's.
constexpr double kProvisionalWidthSpans = 1.2;
constexpr double kProvisionalTopFraction = 0.08;

// The frame the two supports set: origin midway between them, x along their line (unit vector
// (c, s) in pixels), and their distance, which is the span.
struct SupportsFrame {
  double centre_x;
  double centre_y;
  double c;
  double s;
  double distance_px;
};

SupportsFrame supports_frame(const PixelPoint& a, const PixelPoint& b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double distance_px = std::hypot(dx, dy);
  return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), dx / distance_px, dy / distance_px, distance_px};
}

void coloured_text(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrapped_text("%s", text.c_str());
  ImGui::PopStyleColor();
}

}  // namespace

PhotoOverlay::PhotoOverlay(PhotoPaths paths) : paths_(std::move(paths)) {}

PhotoOverlay::~PhotoOverlay() = default;  // the fit's job waits for its thread

std::pair<double, double> PhotoOverlay::to_plot(double x_px, double y_px, double span_mm) const {
  if (supports_.size() == 2) {
    const SupportsFrame f = supports_frame(supports_[0], supports_[1]);
    const double mm_per_px = span_mm / f.distance_px;
    const double rx = x_px - f.centre_x;
    const double ry = y_px - f.centre_y;
    // Rotated by minus the supports' angle: their line becomes the plot's y = 0.
    return {mm_per_px * (f.c * rx + f.s * ry), mm_per_px * (-f.s * rx + f.c * ry)};
  }
  const double width = photo_->width_px;
  const double height = photo_->height_px;
  const double mm_per_px = kProvisionalWidthSpans * span_mm / width;
  return {mm_per_px * (x_px - 0.5 * width), mm_per_px * (y_px - kProvisionalTopFraction * height)};
}

std::pair<double, double> PhotoOverlay::to_pixel(double x_mm, double y_mm, double span_mm) const {
  if (supports_.size() == 2) {
    const SupportsFrame f = supports_frame(supports_[0], supports_[1]);
    const double px_per_mm = f.distance_px / span_mm;
    return {f.centre_x + px_per_mm * (f.c * x_mm - f.s * y_mm),
            f.centre_y + px_per_mm * (f.s * x_mm + f.c * y_mm)};
  }
  const double width = photo_->width_px;
  const double height = photo_->height_px;
  const double px_per_mm = width / (kProvisionalWidthSpans * span_mm);
  return {0.5 * width + px_per_mm * x_mm, kProvisionalTopFraction * height + px_per_mm * y_mm};
}

ImVec2 PhotoOverlay::screen_of_pixel(double x_px, double y_px) const {
  if (!photo_ || !have_view_) {
    return ImVec2(-1.0f, -1.0f);
  }
  const auto [x_mm, y_mm] = to_plot(x_px, y_px, last_span_mm_);
  return view_.to_screen(x_mm, y_mm);
}

bool PhotoOverlay::load(const std::filesystem::path& path, UiStatus& status, Renderer& renderer) {
  Image image;
  try {
    image = load_image(path);
  } catch (const ImageError& e) {
    load_error_ = e.what();
    status.notify(std::string("Photo not loaded: ") + e.what(), MessageKind::error);
    return false;
  }
  if (texture_ < 0) {
    texture_ = renderer.create_image();
  }
  renderer.update_photo(texture_, image.width_px, image.height_px, image.rgba.data());
  texture_id_ = renderer.texture(texture_);
  photo_ = std::move(image);
  photo_path_ = path.string();
  load_error_.clear();
  supports_.clear();
  folds_.clear();
  measured_.reset();
  measure_error_.clear();
  mode_ = Mode::supports;
  std::error_code error;
  if (std::filesystem::is_regular_file(paths_.measurements_file, error)) {
    try {
      rows_in_file_ = static_cast<int>(load_measurements(paths_.measurements_file).rows.size());
    } catch (const MeasurementError& e) {
      rows_message_ = e.what();
      rows_message_is_error_ = true;
    }
  }
  status.notify("Loaded " + photo_path_ + ": click the two supports on it.", MessageKind::info);
  return true;
}

void PhotoOverlay::toolbar(PanelContext& context) {
  if (small_button("Load photo...")) {
    load_error_.clear();
    UiStatus* status = &context.status;
    Renderer* renderer = &context.renderer;
    context.files.open(
        {FileDialog::Mode::open, kLoadModal, "", kImageExtensions,
         [this, status, renderer](const std::filesystem::path& path) -> std::optional<std::string> {
           if (load(path, *status, *renderer)) {
             return std::nullopt;
           }
           return load_error_;
         }},
        context.status);
  }
  if (!photo_) {
    ImGui::SameLine();
    help_marker(
        "Compare the predicted folds with a front photo of a real cloth (PNG or JPEG), and "
        "measure its folds for a calibration.");
    return;
  }
  ImGui::SameLine();
  if (small_button("Place supports")) {
    mode_ = Mode::supports;
    supports_.clear();
    folds_.clear();
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(supports_.size() < 2);
  if (small_button("Click folds")) {
    mode_ = Mode::folds;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (small_button("Remove photo")) {
    photo_.reset();
    mode_ = Mode::none;
    supports_.clear();
    folds_.clear();
    measured_.reset();
    return;
  }
  if (mode_ == Mode::supports) {
    ImGui::TextColored(kNoteText, "Click the %s support on the photo (%zu of 2).",
                       supports_.empty() ? "first" : "second", supports_.size() + 1);
  } else if (mode_ == Mode::folds) {
    ImGui::TextColored(kNoteText, "Click each fold where it crosses the centre line (%zu clicked).",
                       folds_.size());
  }
}

void PhotoOverlay::plot_items(Plot& plot, const Document& document) {
  if (!photo_) {
    return;
  }
  const double span = span_mm(document.scene().parameters());
  last_span_mm_ = span;
  plot.backdrop([this, span](ImDrawList* draw_list, const PlotView& view) {
    const double w = photo_->width_px;
    const double h = photo_->height_px;
    auto corner = [&](double x_px, double y_px) {
      const auto [x_mm, y_mm] = to_plot(x_px, y_px, span);
      return view.to_screen(x_mm, y_mm);
    };
    draw_list->AddImageQuad(texture_id_, corner(0, 0), corner(w, 0), corner(w, h), corner(0, h));
  });
  marker_xs_.clear();
  marker_ys_.clear();
  for (const PixelPoint& support : supports_) {
    const auto [x_mm, y_mm] = to_plot(support.x, support.y, span);
    marker_xs_.push_back(x_mm);
    marker_ys_.push_back(y_mm);
  }
  plot.markers("clicked supports", marker_xs_, marker_ys_, IM_COL32(255, 140, 0, 255),
               MarkerShape::Plus, 7.0f);
  centre_xs_.clear();
  centre_ys_.clear();
  if (supports_.size() == 2) {
    // The centre line from the supports' line to the photo's lowest corner.
    double lowest_mm = 0.0;
    for (const auto& [x_px, y_px] :
         {std::pair{0.0, 0.0}, std::pair{1.0, 0.0}, std::pair{0.0, 1.0}, std::pair{1.0, 1.0}}) {
      lowest_mm = std::max(lowest_mm,
                           to_plot(x_px * photo_->width_px, y_px * photo_->height_px, span).second);
    }
    centre_xs_ = {0.0, 0.0};
    centre_ys_ = {0.0, lowest_mm};
    plot.line("centre line", centre_xs_, centre_ys_, IM_COL32(255, 140, 0, 150), 1.0f);
  }
  fold_xs_.clear();
  fold_ys_.clear();
  for (const PixelPoint& fold : folds_) {
    const auto [x_mm, y_mm] = to_plot(fold.x, fold.y, span);
    fold_xs_.push_back(x_mm);
    fold_ys_.push_back(y_mm);
  }
  plot.markers("clicked folds", fold_xs_, fold_ys_, IM_COL32(255, 140, 0, 255), MarkerShape::Cross,
               6.0f);
}

void PhotoOverlay::handle_click(const Plot& plot, const UiStatus& status) {
  view_ = plot.view();
  have_view_ = true;
  if (!photo_ || mode_ == Mode::none || !status.modal_title().empty() ||
      // The press makes the plot's own button active (it pans on a drag).
      !ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem) ||
      !ImGui::IsMouseClicked(0)) {
    return;
  }
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (mouse.x < view_.min.x || mouse.x > view_.max.x || mouse.y < view_.min.y ||
      mouse.y > view_.max.y) {
    return;
  }
  const auto [x_mm, y_mm] = view_.to_data(mouse);
  const auto [x_px, y_px] = to_pixel(x_mm, y_mm, last_span_mm_);
  if (!(x_px >= 0.0 && x_px <= photo_->width_px && y_px >= 0.0 && y_px <= photo_->height_px)) {
    return;  // beside the photo
  }
  if (mode_ == Mode::supports) {
    supports_.push_back({x_px, y_px});
    if (supports_.size() == 2) {
      if (supports_[1].x < supports_[0].x) {
        std::swap(supports_[0], supports_[1]);  // left to right, so the photo is not upside down
      }
      mode_ = Mode::folds;
      folds_.clear();
    }
  } else {
    folds_.push_back({x_px, y_px});
  }
}

void PhotoOverlay::remeasure(const Document& document) {
  measured_.reset();
  measure_error_.clear();
  if (supports_.size() < 2 || folds_.size() < 2) {
    return;
  }
  std::vector<double> rows_px;
  for (const PixelPoint& fold : folds_) {
    rows_px.push_back(fold.y);
  }
  // Lowest first, as measure_folds wants, whatever order they were clicked in.
  std::sort(rows_px.begin(), rows_px.end(), std::greater<>());
  try {
    measured_ = measure_folds(depths_from_pixels(supports_[0], supports_[1], rows_px,
                                                 span_mm(document.scene().parameters())));
  } catch (const FoldMeasurementError& e) {
    measure_error_ = e.what();
  }
}

void PhotoOverlay::add_row(const Document& document) {
  std::optional<double> z_max_mm;
  if (z_max_field_[0] != '\0') {
    z_max_mm = parse_number(z_max_field_);
    if (!z_max_mm || !(*z_max_mm >= 0.0) || !std::isfinite(*z_max_mm)) {
      rows_message_ = std::string("z_max = \"") + z_max_field_ +
                      "\" is not a depth in mm (a number >= 0); leave it empty if not measured.";
      rows_message_is_error_ = true;
      return;
    }
  }
  const std::string name = name_field_[0] != '\0'
                               ? std::string(name_field_)
                               : "photo " + std::filesystem::path(photo_path_).filename().string();
  const Measurement row =
      measurement_row(document.scene().parameters(), *measured_, z_max_mm, name);
  try {
    if (paths_.measurements_file.empty()) {
      throw MeasurementError("there is no config folder to keep a measurements file in");
    }
    std::filesystem::create_directories(paths_.measurements_file.parent_path());
    append_measurement(paths_.measurements_file, row);
    rows_in_file_ = static_cast<int>(load_measurements(paths_.measurements_file).rows.size());
    rows_message_ = "Added \"" + name + "\" as row " + std::to_string(rows_in_file_) + ".";
    rows_message_is_error_ = false;
  } catch (const std::exception& e) {
    rows_message_ = std::string("Not added: ") + e.what();
    rows_message_is_error_ = true;
  }
}

void PhotoOverlay::start_fit(const Document& document) {
  MeasurementSet data;
  try {
    data = load_measurements(paths_.measurements_file);
    fit_user_rows_ = static_cast<int>(data.rows.size());
    if (with_shipped_rows_ && !paths_.shipped_data_file.empty()) {
      for (Measurement& row : load_measurements(paths_.shipped_data_file).rows) {
        data.rows.push_back(std::move(row));
      }
    }
  } catch (const MeasurementError& e) {
    fit_message_ = std::string("The fit did not run: ") + e.what();
    fit_message_is_error_ = true;
    return;
  }
  fit_base_ = document.scene().parameters();
  CalibrationOptions options;
  options.fit = FitConstants::K_and_p;
  fit_message_ = "Fitting K and p to " + std::to_string(data.rows.size()) + " rows...";
  fit_message_is_error_ = false;
  // The calibration in steps (as the calibration window's), then the coverage check in one more.
  auto calibration = std::make_shared<CalibrationJob>(data, fit_base_, options);
  auto coverage = std::make_shared<std::string>();
  JobSteps<FitOutcome> steps;
  steps.step = [calibration, coverage, data, base = fit_base_, options](JobToken& token) {
    if (!calibration->finished()) {
      calibration->step(token);
      return false;
    }
    if (const auto checks = cross_validated_coverage(data, base, options)) {
      *coverage = describe_coverage(*checks);
    }
    return true;
  };
  steps.finish = [calibration, coverage] { return FitOutcome{calibration->report(), *coverage}; };
  fit_.start_slices(std::move(steps), wake_);
}

void PhotoOverlay::collect_fit(const Document& document, UiStatus& status) {
  if (!fit_.finished()) {
    return;
  }
  try {
    const FitOutcome outcome = *fit_.take_result();
    const CalibrationReport& report = outcome.report;
    const FittedConstants& f = report.fitted;
    const std::string data_label = with_shipped_rows_ && !paths_.shipped_data_file.empty()
                                       ? "my measurements and " + std::string(kConciTables12)
                                       : std::string("my measurements");
    Preset out = document.loaded();
    out.parameters = with_constants(fit_base_, f.K, f.p);
    out.name = "Fitted to " + std::to_string(report.fit_row_count) +
               " measured rows (K = " + printf_string("%.4g", f.K) +
               ", p = " + printf_string("%.4g", f.p) + ")";
    out.description = "Eq. 7's K and p fitted in the explorer on " + data_label + " (" +
                      std::to_string(report.fit_row_count) + " fit rows, " +
                      std::to_string(fit_user_rows_) + " of them mine; " +
                      std::string(to_string(fit_base_.model.method)) + " method): in-sample " +
                      summary_text(report.in_sample) + "; leave-one-out " +
                      summary_text(report.leave_one_out) + ".";
    out.published = {};
    out.calibration = calibration_record(report, data_label, outcome.coverage);
    out.written_by = app::version_line();
    const std::filesystem::path path =
        paths_.user_presets_dir / (preset_slug("fitted to my measurements") + ".json");
    std::filesystem::create_directories(path.parent_path());
    save_preset(out, path);
    saved_preset_ = path;
    unreported_preset_ = path;
    fit_message_ = "K = " + printf_string("%.4g", f.K) + ", p = " + printf_string("%.4g", f.p) +
                   " on " + std::to_string(report.fit_row_count) + " rows; in-sample " +
                   summary_text(report.in_sample) + "; held out (leave-one-out) " +
                   summary_text(report.leave_one_out) + ". Saved as preset \"" + out.name + "\" (" +
                   path.string() + ").";
    fit_message_is_error_ = false;
    status.notify("Saved the fitted preset to " + path.string(), MessageKind::success);
  } catch (const std::exception& e) {
    fit_message_ = std::string("The fit did not run: ") + e.what();
    fit_message_is_error_ = true;
  }
}

std::optional<std::filesystem::path> PhotoOverlay::take_saved_preset() {
  return std::exchange(unreported_preset_, std::nullopt);
}

void PhotoOverlay::draw_windows(Document& document, UiStatus& status, Renderer& renderer) {
  collect_fit(document, status);
  if (photo_) {
    remeasure(document);
    measurement_window(document, status, renderer);
  }
}

void PhotoOverlay::measurement_window(Document& document, UiStatus& status, Renderer& renderer) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0.65f * display.x, 0.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(0.35f * display.x, 0.56f * display.y), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin(window_label().c_str())) {
    ImGui::End();
    return;
  }
  renderer.fill_window_background();
  wrapped_text("Photo: %s (%d x %d px)", photo_path_.c_str(), photo_->width_px, photo_->height_px);
  draw_scale();
  section("Measured");
  draw_measured(document.scene().solution());
  section("Add to measurements");
  draw_add_row(document);
  draw_rows_file(status);
  section("Fit");
  draw_fit(document);
  ImGui::End();
}

void PhotoOverlay::draw_scale() const {
  if (supports_.size() == 2) {
    const double distance_px =
        std::hypot(supports_[1].x - supports_[0].x, supports_[1].y - supports_[0].y);
    const double angle_deg =
        std::atan2(supports_[1].y - supports_[0].y, supports_[1].x - supports_[0].x) * 180.0 /
        std::numbers::pi;
    ImGui::TextColored(kDimText, "supports %.0f px apart = span l %.0f mm (%.3g mm/px), %+.1f°",
                       distance_px, last_span_mm_, last_span_mm_ / distance_px, angle_deg);
  } else {
    ImGui::TextColored(kNoteText, "Click the two supports on the photo: they set its scale.");
  }
}

void PhotoOverlay::draw_measured(const Solution& predicted) {
  if (measured_) {
    ImGui::Text("n = %d   Q = %.4g   fit residual %.3g", measured_->n, measured_->Q,
                measured_->fit_residual);
    std::vector<std::string> depths;
    for (double a : measured_->a_mm) {
      depths.push_back(printf_string("%.0f", a));
    }
    wrapped_text("a_i = %s mm", detail::join_comma(depths).c_str());
    ImGui::TextColored(kDimText, "predicted: n = %d   Q = %.4g", predicted.n, predicted.Q);
  } else if (!measure_error_.empty()) {
    coloured_text(kErrorText, measure_error_);
  } else {
    ImGui::TextColored(kDimText, "Click at least two folds (%zu so far).", folds_.size());
  }
  if (!folds_.empty() && small_button("Undo last fold")) {
    folds_.pop_back();
  }
}

void PhotoOverlay::draw_add_row(const Document& document) {
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  ImGui::InputTextWithHint("z_max (mm)", "optional", z_max_field_, sizeof z_max_field_);
  help_marker(
      "The largest out-of-plane depth, if you measured it: a front photo does not show it.");
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
  ImGui::InputTextWithHint("name", "photo file name", name_field_, sizeof name_field_);
  ImGui::BeginDisabled(!measured_);
  if (ImGui::Button("Add to measurements")) {
    add_row(document);
  }
  ImGui::EndDisabled();
}

void PhotoOverlay::draw_rows_file(UiStatus& status) {
  ImGui::PushStyleColor(ImGuiCol_Text, kDimText);
  wrapped_text("%d %s in %s", rows_in_file_, rows_in_file_ == 1 ? "row" : "rows",
               paths_.measurements_file.string().c_str());
  ImGui::PopStyleColor();
  ImGui::BeginDisabled(rows_in_file_ == 0 || files_ == nullptr);
  if (small_button("Save a copy...")) {
    const std::filesystem::path rows = paths_.measurements_file;
    files_->open({FileDialog::Mode::save,
                  kSaveRowsModal,
                  rows.filename().string(),
                  {".csv"},
                  [rows, &status](const std::filesystem::path& path) -> std::optional<std::string> {
                    std::error_code error;
                    std::filesystem::copy_file(
                        rows, path, std::filesystem::copy_options::overwrite_existing, error);
                    if (error) {
                      return "Not saved: " + error.message();
                    }
                    status.notify("Wrote " + path.string(), MessageKind::success);
                    return std::nullopt;
                  }},
                 status);
  }
  ImGui::EndDisabled();
  if (!rows_message_.empty()) {
    coloured_text(rows_message_is_error_ ? kErrorText : kOkText, rows_message_);
  }
}

void PhotoOverlay::draw_fit(const Document& document) {
  ImGui::BeginDisabled(paths_.shipped_data_file.empty());
  ImGui::Checkbox("with Conci's Tables 1–2 rows", &with_shipped_rows_);
  ImGui::EndDisabled();
  ImGui::BeginDisabled(rows_in_file_ == 0 || fitting());
  if (ImGui::Button("Fit K and p to my rows")) {
    start_fit(document);
  }
  ImGui::EndDisabled();
  if (!fit_message_.empty()) {
    coloured_text(fit_message_is_error_ ? kErrorText : kDimText, fit_message_);
  }
}

json PhotoOverlay::report() const {
  json photo = nullptr;
  if (photo_) {
    json supports = json::array();
    for (const PixelPoint& p : supports_) {
      supports.push_back({p.x, p.y});
    }
    json folds = json::array();
    for (const PixelPoint& p : folds_) {
      folds.push_back(p.y);
    }
    photo = {{"path", photo_path_},
             {"width_px", photo_->width_px},
             {"height_px", photo_->height_px},
             {"supports_px", supports},
             {"folds_px", folds},
             {"measurements_file", paths_.measurements_file.string()},
             {"measurement_rows", rows_in_file_},
             {"fitted_preset", saved_preset_ ? json(saved_preset_->string()) : json(nullptr)}};
  }
  json measured = nullptr;
  if (measured_) {
    measured = {{"n", measured_->n},
                {"Q", measured_->Q},
                {"a_mm", measured_->a_mm},
                {"fit_residual", measured_->fit_residual}};
  }
  return {{"photo", photo}, {"measured", measured}};
}

void PhotoOverlay::report(nlohmann::json& state, PanelContext& /*context*/) const {
  state.update(report());  // "photo" and "measured"
}

std::optional<ImVec2> PhotoOverlay::locate(std::string_view target,
                                           std::span<const double> at) const {
  if (target != "photo_pixel" || at.size() < 2 || report().at("photo").is_null()) {
    return std::nullopt;
  }
  return screen_of_pixel(at[0], at[1]);
}

}  // namespace foldlab::gui
