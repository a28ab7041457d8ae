// The fold plot: its size at a large text size, and a photo of folds measured on it.
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

// A large UI scale in a small window: the fold plot keeps a data area of several font sizes (the
// panel scrolls) instead of drawing its axis labels and legend over a sliver.
TEST_F(ExplorerTest, TheFoldPlotKeepsItsSizeAtALargeUiScale) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(1280, 800);
  ASSERT_EQ(explorer_->set_view("scale", "250"), std::nullopt);
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const PlotView& view = panel<FoldPlotPanel>().plot_view();
  EXPECT_GT(view.max.y - view.min.y, 5.0f * ImGui::GetFontSize());
  EXPECT_GE(view.legend_min.y, view.max.y);  // the legend below the data, not over it
}

// The photo loop through real clicks: a PNG that FoldLab drew of the loaded preset's folds (turned
// 3° and scaled, as a camera might) is typed into the load dialog, its two supports and its folds
// are clicked where the geometry drew them, and the measurement must give back the solution's n
// and Q; "Add to measurements" writes the row to the measurements file, "Fit" saves a preset
// that rests on that row and the six fit rows of Tables 1-2.
TEST_F(ExplorerTest, APhotoOfKnownFoldsClickedGivesItsNAndQAndFeedsAFit) {
  const Parameters p = shown();
  const Solution s = explorer_->scene().solution();
  ASSERT_GE(s.n, 3);
  const fs::path png = dir_ / "cloth.png";
  const testing::FoldPhoto photo = testing::write_fold_photo(s, p, png);

  // Clicked on a projector's 1920 x 1080: drawn at true scale, the fold plot of this square
  // cloth tiled at 1280 x 800 leaves a screen pixel too many of the photo's for the measured Q
  // to tell this cloth from the next.
  show_at(ImVec2(1920, 1080));
  click("Load");  // "Load photo...", the only "Load" before the dialog opens
  EXPECT_EQ(status().modal_title(), PhotoOverlay::kLoadModal);
  ImGui::GetIO().AddInputCharactersUTF8(png.string().c_str());
  frame();
  frame();
  click("Load");
  EXPECT_EQ(status().modal_title(), "");
  nlohmann::json report = panel<PhotoOverlay>().report();
  ASSERT_TRUE(report.at("photo").is_object()) << last_text_;
  EXPECT_EQ(report.at("photo").at("width_px"), photo.width_px);
  EXPECT_EQ(report.at("photo").at("height_px"), photo.height_px);

  auto click_pixel = [&](PixelPoint at) {
    const ImVec2 screen = panel<PhotoOverlay>().screen_of_pixel(at.x, at.y);
    click_at(screen);
  };
  // ImGui floors the mouse position to whole screen pixels: a click lands within one screen
  // pixel (diagonal: sqrt 2) of its aim, which is this many photo pixels.
  auto photo_px_per_screen_px = [&] {
    const ImVec2 a = panel<PhotoOverlay>().screen_of_pixel(photo.left_support.x, 0.0);
    const ImVec2 b = panel<PhotoOverlay>().screen_of_pixel(photo.right_support.x, 0.0);
    return (photo.right_support.x - photo.left_support.x) / std::hypot(b.x - a.x, b.y - a.y);
  };
  const double before_px = std::sqrt(2.0) * photo_px_per_screen_px();
  click_pixel(photo.right_support);  // either order: the left one becomes the first
  click_pixel(photo.left_support);
  report = panel<PhotoOverlay>().report();
  ASSERT_EQ(report.at("photo").at("supports_px").size(), 2u);
  EXPECT_NEAR(report.at("photo").at("supports_px")[0][0].get<double>(), photo.left_support.x,
              before_px);
  EXPECT_NEAR(report.at("photo").at("supports_px")[1][1].get<double>(), photo.right_support.y,
              before_px);
  // Upper folds first: the order of the clicks does not matter.
  for (auto fold = photo.folds.rbegin(); fold != photo.folds.rend(); ++fold) {
    click_pixel(*fold);
  }
  report = panel<PhotoOverlay>().report();
  ASSERT_TRUE(report.at("measured").is_object()) << last_text_;
  EXPECT_EQ(report.at("measured").at("n"), s.n);
  // A depth is off by the rows of its click and of the supports' clicks (one screen pixel each,
  // now in the supports' frame: photo px times mm per photo px), and the span by the supports'.
  const double mm_per_photo_px =
      s.span_mm / (photo.right_support.x - photo.left_support.x) * std::cos(photo.angle_rad);
  const double depth_tolerance_mm =
      2.0 * std::sqrt(2.0) * photo_px_per_screen_px() * mm_per_photo_px +
      s.a_mm[0] * 2.0 * before_px / (photo.right_support.x - photo.left_support.x);
  for (std::size_t i = 0; i < s.a_mm.size(); ++i) {
    EXPECT_NEAR(report.at("measured").at("a_mm")[i].get<double>(), s.a_mm[i], depth_tolerance_mm)
        << i;
  }
  // ln a_i is off by at most tolerance / a_n; the fitted slope, a weighted sum of those, by no
  // more than the largest of them times sum |i - mean| / sum (i - mean)^2.
  double spread = 0.0;
  double squares = 0.0;
  for (int i = 0; i <= s.n; ++i) {
    spread += std::abs(i - 0.5 * s.n);
    squares += (i - 0.5 * s.n) * (i - 0.5 * s.n);
  }
  const double log_Q_tolerance = depth_tolerance_mm / s.a_mm.back() * spread / squares;
  EXPECT_NEAR(std::log(report.at("measured").at("Q").get<double>()), std::log(s.Q),
              log_Q_tolerance);
  EXPECT_LT(log_Q_tolerance, 0.2 * std::log(s.Q));  // tighter than the step to another cloth
  const std::string n_text = "n = " + std::to_string(s.n);
  EXPECT_NE(last_text_.find(n_text + " Q = "), std::string::npos) << last_text_;

  click("Add to measurements");
  const MeasurementSet rows = load_measurements(dir_ / "measurements.csv");
  ASSERT_EQ(rows.rows.size(), 1u);
  EXPECT_EQ(rows.rows[0].name, "photo cloth.png");
  EXPECT_EQ(rows.rows[0].observed.n, s.n);
  EXPECT_EQ(*rows.rows[0].observed.Q, report.at("measured").at("Q").get<double>());
  EXPECT_FALSE(rows.rows[0].observed.z_max_mm.has_value());
  EXPECT_EQ(rows.rows[0].inputs.hanging.height_mm, p.hanging.height_mm);
  EXPECT_EQ(rows.rows[0].inputs.fabric.thickness_mm, p.fabric.thickness_mm);
  EXPECT_NE(last_text_.find("1 row in"), std::string::npos) << last_text_;

  click("Fit K and p to my rows");
  // The fit's leave-one-out refits take tens of seconds on a loaded machine: a generous wall
  // clock, not a frame count, bounds the wait.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(8);
  while (panel<PhotoOverlay>().fitting() && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    frame();
  }
  ASSERT_FALSE(panel<PhotoOverlay>().fitting());
  frame();
  report = panel<PhotoOverlay>().report();
  ASSERT_TRUE(report.at("photo").at("fitted_preset").is_string()) << last_text_;
  const Preset fitted = load_preset(report.at("photo").at("fitted_preset").get<std::string>());
  ASSERT_TRUE(fitted.calibration.has_value());
  // Tables 1-2 hold six fit rows and one check row (Fig. 4); the photo adds one fit row.
  EXPECT_EQ(fitted.calibration->fit_rows, 7);
  EXPECT_EQ(fitted.calibration->leave_one_out.size(), 7u);
  EXPECT_EQ(fitted.calibration->calibrated_on, "my measurements and Conci's Tables 1–2");
  EXPECT_EQ(fitted.parameters.model.stress_exponent_p, fitted.calibration->fitted.p);
  EXPECT_NE(fitted.description.find("leave-one-out"), std::string::npos) << fitted.description;
  bool listed = false;
  for (const PresetsPanel::Entry& entry : panel<PresetsPanel>().entries()) {
    listed = listed || entry.name == fitted.name;
  }
  EXPECT_TRUE(listed) << fitted.name;
}

TEST_F(ExplorerTest, APhotoThatCannotBeReadIsRefusedWithItsReason) {
  const fs::path text = dir_ / "notes.png";
  { std::ofstream(text) << "not an image"; }
  click("Load");  // "Load photo...", the only "Load" before the dialog opens
  ImGui::GetIO().AddInputCharactersUTF8(text.string().c_str());
  frame();
  frame();
  click("Load");
  EXPECT_EQ(status().modal_title(), PhotoOverlay::kLoadModal);  // stays open to correct it
  EXPECT_NE(squeezed(last_text_).find("notaPNGorJPEGfile"), std::string::npos) << last_text_;
  EXPECT_TRUE(panel<PhotoOverlay>().report().at("photo").is_null());
  press(kEscape);
  EXPECT_EQ(status().modal_title(), "");
}

}  // namespace
}  // namespace foldlab::gui
