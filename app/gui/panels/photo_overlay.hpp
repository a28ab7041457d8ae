// A photo of a real cloth behind the fold plot, and the loop it serves: the two supports clicked
// on the photo set its rotation and scale (their distance is the span l), so the predicted fold
// lines lie over it in photo coordinates and follow the sliders; the observed folds clicked on
// the centre line give the measured a_i, n and Q (core's measure_folds, as `foldlab measure`
// does); "Add to measurements" appends the row to the user's measurements file, and "Fit"
// calibrates eq. 7 on those rows and saves a fabric preset with the constants and their
// held-out figures.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/gui/background_job.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/renderer.hpp"
#include "core/analysis/calibration.hpp"
#include "core/analysis/fold_measurement.hpp"
#include "core/io/image.hpp"

namespace foldlab::gui {

struct PhotoPaths {
  std::filesystem::path measurements_file;  // "Add to measurements" appends here
  std::filesystem::path user_presets_dir;   // "Fit" saves its preset here
  std::filesystem::path shipped_data_file;  // Conci's Tables 1–2, empty when not found
};

class PhotoOverlay : public Panel {
 public:
  explicit PhotoOverlay(PhotoPaths paths);
  // Waits for a running fit (its job does).
  ~PhotoOverlay();
  PhotoOverlay(const PhotoOverlay&) = delete;
  PhotoOverlay& operator=(const PhotoOverlay&) = delete;

  static constexpr const char* kLoadModal = "Load photo";
  static constexpr const char* kSaveRowsModal = "Save a copy of the measurements";
  const char* name() const override { return "Photo measurement"; }
  const char* key() const override { return "photo"; }
  // The measurement window (the fold plot draws the rest).
  void draw(PanelContext& context) override {
    wake_ = context.wake;     // for the fit started from the window
    files_ = &context.files;  // for "Save a copy..." of the measurements file
    draw_windows(context.document, context.status, context.renderer);
  }
  bool busy() const override { return fitting(); }

  // The buttons above the fold plot: "Load photo..." (the open dialog), "Place supports",
  // "Click folds".
  void toolbar(PanelContext& context);
  // Between the plot's begin() and end(): the photo as its backdrop, the clicked points and the
  // centre line.
  void plot_items(Plot& plot, const Document& document);
  // After the plot's end(): a click in its data area places a support or a fold.
  void handle_click(const Plot& plot, const UiStatus& status);
  // The measurement window, outside the tiled panels.
  void draw_windows(Document& document, UiStatus& status, Renderer& renderer);

  // Loads a photo as the backdrop; on failure keeps the previous one and says why.
  bool load(const std::filesystem::path& path, UiStatus& status, Renderer& renderer);
  // A preset "Fit" saved since the last call, for the presets list to show.
  std::optional<std::filesystem::path> take_saved_preset();
  // From "Fit" until its result is collected.
  bool fitting() const { return fit_.pending(); }

  // The photo file loaded (empty: none).
  const std::string& photo_file() const { return photo_path_; }
  // Where photo pixel (x, y) is on screen in the last drawn plot (for tests and scripts).
  ImVec2 screen_of_pixel(double x_px, double y_px) const;
  // The photo, its supports and folds, the measurement and the files: for `gui --report`.
  nlohmann::json report() const;
  void report(nlohmann::json& state, PanelContext& /*context*/) const override;
  // "photo_pixel" at (at[0], at[1]): where the photo's pixel is on screen, while a photo is
  // loaded.
  std::optional<ImVec2> locate(std::string_view target, std::span<const double> at) const override;
  std::vector<app::NamedPath> files_in_use() const override {
    return {{"the fold plot's photo", photo_path_}};
  }

 private:
  enum class Mode { none, supports, folds };
  // Photo pixel -> plot millimetres and back: the supports' frame once both are placed, else a
  // provisional frame that shows the photo about a span and a fifth wide over the supports.
  std::pair<double, double> to_plot(double x_px, double y_px, double span_mm) const;
  std::pair<double, double> to_pixel(double x_mm, double y_mm, double span_mm) const;
  void remeasure(const Document& document);
  void add_row(const Document& document);
  void start_fit(const Document& document);
  void collect_fit(const Document& document, UiStatus& status);
  void measurement_window(Document& document, UiStatus& status, Renderer& renderer);
  // The measurement window's parts, top to bottom: the scale the supports set, the folds
  // measured (beside the `predicted` ones), the row to add, the measurements file, the fit.
  void draw_scale() const;
  void draw_measured(const Solution& predicted);
  void draw_add_row(const Document& document);
  void draw_rows_file(UiStatus& status);
  void draw_fit(const Document& document);

  PhotoPaths paths_;
  std::optional<Image> photo_;
  std::string photo_path_;
  int texture_ = -1;
  ImTextureID texture_id_ = nullptr;
  std::string load_error_;

  Mode mode_ = Mode::none;
  std::vector<PixelPoint> supports_;  // 0, 1 or 2 clicks; two fix the frame
  std::vector<PixelPoint> folds_;     // as clicked, any order; their rows are what counts
  std::optional<FoldMeasurement> measured_;
  std::string measure_error_;
  double last_span_mm_ = 0.0;
  PlotView view_;
  bool have_view_ = false;
  // The plot keeps pointers into these until end().
  std::vector<double> marker_xs_, marker_ys_, fold_xs_, fold_ys_, centre_xs_, centre_ys_;

  char z_max_field_[32] = {};
  char name_field_[128] = {};
  std::string rows_message_;
  bool rows_message_is_error_ = false;
  int rows_in_file_ = 0;

  bool with_shipped_rows_ = true;
  // The fit, and how often its prediction intervals covered rows they were not fitted to.
  struct FitOutcome {
    CalibrationReport report;
    std::string coverage;
  };
  BackgroundJob<FitOutcome> fit_;
  std::function<void()> wake_;
  FileDialog* files_ = nullptr;
  Parameters fit_base_;
  int fit_user_rows_ = 0;
  std::string fit_message_;
  bool fit_message_is_error_ = false;
  std::optional<std::filesystem::path> saved_preset_;
  std::optional<std::filesystem::path> unreported_preset_;
};

}  // namespace foldlab::gui
