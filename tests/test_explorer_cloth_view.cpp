// The 3D view: colour by depth, a swatch photo as the print, its view settings and when it draws
// again.
#include "explorer_fixture.hpp"

#include "app/gui/appearance.hpp"
#include "app/gui/colour_map.hpp"

namespace foldlab::gui {
namespace {

// One meaning per colour across the views: +z is blue in colour-by-z as a positive fold (z > 0)
// is blue in the fold lines, and -z red as a negative fold is, in either theme.
TEST(ColourMeaning, PlusZIsBlueInEveryViewAndMinusZRed) {
  const auto bluer = [](float r, float b) { return b > r + 0.2f; };
  const Eigen::Vector3f plus_z = diverging_colour(1.0f);
  const Eigen::Vector3f minus_z = diverging_colour(0.0f);
  EXPECT_TRUE(bluer(plus_z.x(), plus_z.z()));
  EXPECT_TRUE(bluer(minus_z.z(), minus_z.x()));
  for (const bool light : {false, true}) {
    const FoldColours folds = fold_colours(light);
    EXPECT_TRUE(bluer(folds.positive.x, folds.positive.z)) << "positive fold, light " << light;
    EXPECT_TRUE(bluer(folds.negative.z, folds.negative.x)) << "negative fold, light " << light;
  }
}

// The colour bar beside the 3D view shows the range the shader maps: +-z_max of the solution.
TEST_F(ExplorerTest, ColourByZShowsABarOverTheSolutionsDepth) {
  std::string text = frame();
  const double z_max_mm = explorer_->scene().solution().z_max_mm;
  ASSERT_GT(z_max_mm, 1.0);
  char high[32];
  char low[32];
  std::snprintf(high, sizeof high, "+%.1f mm", z_max_mm);
  std::snprintf(low, sizeof low, "-%.1f mm", z_max_mm);
  EXPECT_EQ(text.find(high), std::string::npos) << "no bar while the cloth shows the fabric";

  ASSERT_EQ(explorer_->set_view("colour_by", "z"), std::nullopt);
  text = frame();
  EXPECT_EQ(panel<ClothViewPanel>().style().colour_by, ClothStyle::ColourBy::z);
  EXPECT_NE(text.find(high), std::string::npos) << text;
  EXPECT_NE(text.find(low), std::string::npos) << text;

  ASSERT_EQ(explorer_->set_view("colour_by", "fold_sign"), std::nullopt);
  text = frame();
  EXPECT_NE(text.find("z > 0"), std::string::npos) << text;
  EXPECT_NE(text.find("z < 0"), std::string::npos) << text;
  EXPECT_EQ(text.find(high), std::string::npos);

  const auto refused = explorer_->set_view("colour_by", "height");
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->find("none, z, fold_sign"), std::string::npos) << *refused;
  EXPECT_EQ(panel<ClothViewPanel>().style().colour_by, ClothStyle::ColourBy::fold_sign);
}

TEST_F(ExplorerTest, ASwatchPhotoBecomesThePrintAndABadFileIsRefusedByName) {
  const auto missing = explorer_->set_view("print_file", (dir_ / "none.png").string());
  ASSERT_TRUE(missing.has_value());
  EXPECT_NE(missing->find("none.png"), std::string::npos) << *missing;
  EXPECT_NE(missing->find("No such file"), std::string::npos) << *missing;
  // A device or a FIFO is named for what it is, not read forever or waited on.
  const auto device = explorer_->set_view("print_file", "/dev/zero");
  ASSERT_TRUE(device.has_value());
  EXPECT_NE(device->find("a character device, not a regular file"), std::string::npos) << *device;
  const fs::path fifo = dir_ / "swatch.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto pipe = explorer_->set_view("print_file", fifo.string());
  ASSERT_TRUE(pipe.has_value());
  EXPECT_NE(pipe->find("a FIFO, not a regular file"), std::string::npos) << *pipe;

  const auto garbage_path = dir_ / "swatch.jpg";
  std::FILE* garbage = std::fopen(garbage_path.c_str(), "wb");
  ASSERT_NE(garbage, nullptr);
  std::fputs("not a picture at all", garbage);
  std::fclose(garbage);
  const auto unreadable = explorer_->set_view("print_file", garbage_path.string());
  ASSERT_TRUE(unreadable.has_value());
  EXPECT_NE(unreadable->find("swatch.jpg"), std::string::npos) << *unreadable;
  EXPECT_NE(unreadable->find("not a PNG or JPEG file"), std::string::npos) << *unreadable;
  EXPECT_EQ(panel<ClothViewPanel>().style().print, ClothStyle::Print::plain);
  EXPECT_TRUE(explorer_->set_view("print", "photo").has_value()) << "no photo loaded yet";

  // A 3 x 2 swatch with a known pixel at each corner: the print holds them top row first.
  const std::vector<std::uint8_t> pixels = {
      255, 0,  0,  255, 0,  255, 0,  255, 0,  0,  255, 255,  //
      10,  20, 30, 255, 40, 50,  60, 255, 70, 80, 90,  255};
  const auto good_path = dir_ / "swatch.png";
  write_png(good_path.c_str(), FrameSize{3, 2}, pixels);
  ASSERT_EQ(explorer_->set_view("print_file", good_path.string()), std::nullopt);
  const ClothStyle& style = panel<ClothViewPanel>().style();
  EXPECT_EQ(style.print, ClothStyle::Print::photo);
  ASSERT_NE(style.photo, nullptr);
  EXPECT_EQ(style.photo->width, 3);
  EXPECT_EQ(style.photo->height, 2);
  EXPECT_EQ(style.photo->rgba, pixels);
  EXPECT_NE(frame().find("photo"), std::string::npos) << "the print combo shows the photo";
}

// The 3D view's picture is kept while what it shows is unchanged: each of its inputs, changed
// alone, makes the next call draw again, and an unchanged call after it draws nothing.
TEST(ClothViewCacheTest, DrawsAgainExactlyWhenSceneCameraSizeOrStyleChange) {
  Scene scene(load_preset(kPresetsDir / "paper-table1-h1400.json").parameters);
  OrbitCamera camera;
  FrameSize size{400, 300};
  ClothStyle style;
  ClothViewCache cache;
  RenderCounters counters;
  const auto draws = [&] {
    return !cache.reuse(cloth_buffers(scene, style), camera, size, style, counters);
  };
  EXPECT_TRUE(draws()) << "nothing drawn yet";
  EXPECT_FALSE(draws());
  EXPECT_FALSE(draws());
  const std::vector<std::pair<const char*, std::function<void()>>> changes = {
      {"camera orbit", [&] { camera.orbit(5.0f, 0.0f); }},
      {"camera zoom", [&] { camera.zoom(1.0f); }},
      {"view size", [&] { size.height = 301; }},
      {"print", [&] { style.print = ClothStyle::Print::checks; }},
      {"z exaggeration", [&] { style.z_exaggeration = 4.0f; }},
      {"breeze time", [&] { style.time_s = 0.5f; }},
      {"background", [&] { style.background.x() = 0.5f; }},
      {"fold lines hidden", [&] { style.fold_lines = false; }},
      {"h",
       [&] {
         Parameters p = scene.parameters();
         p.hanging.height_mm = 1500.0;
         scene.set_parameters(p);
       }},
      {"grid resolution", [&] { scene.set_grid_resolution(64, 64); }},
  };
  for (const auto& [what, change] : changes) {
    change();
    EXPECT_TRUE(draws()) << what;
    EXPECT_FALSE(draws()) << what;
  }
  EXPECT_EQ(counters.view_renders, 1 + changes.size());
  EXPECT_EQ(counters.view_cache_hits, 2 + changes.size());
  cache.forget();
  EXPECT_TRUE(draws());
}

TEST_F(ExplorerTest, TheThreeDViewIsDrawnAgainOnlyWhenWhatItShowsChanges) {
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const RenderCounters before = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  for (int i = 0; i < 5; ++i) {
    frame();
  }
  RenderCounters now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  EXPECT_EQ(now.frames, before.frames + 5);
  EXPECT_EQ(now.view_renders, before.view_renders) << "idle frames show the kept picture";
  EXPECT_EQ(now.view_cache_hits, before.view_cache_hits + 5);

  explorer_->set_input("h", 1500.0);
  frame();
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_renders,
            now.view_renders + 1)
      << "a new h";

  now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  ASSERT_EQ(explorer_->set_view("z_exaggeration", "4"), std::nullopt);
  frame();
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_renders,
            now.view_renders + 1)
      << "z x4";

  // An orbit: a drag across the middle of the view (the panel's top right of the window).
  now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  const std::uint64_t solves = evaluations(Stage::solution);
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(1060.0f, 300.0f);
  frame();
  io.MouseDown[0] = true;
  frame();
  io.MousePos = ImVec2(1100.0f, 300.0f);
  frame();
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_EQ(evaluations(Stage::solution), solves) << "the drag moved the camera, not an input";
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_renders,
            now.view_renders + 1)
      << "camera moved";
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).view_cache_hits,
            now.view_cache_hits + 4);
}

// The breeze sways the cloth in every frame, its settings in sight or not: presented, they are
// behind the view's menu, and the cloth stood still.
TEST_F(ExplorerTest, TheBreezeSwaysAPresentedCloth) {
  ASSERT_EQ(explorer_->set_view("breeze", "1"), std::nullopt);
  for (const char* present : {"none", "cloth"}) {
    ASSERT_EQ(explorer_->set_view("present", present), std::nullopt);
    frame();
    frame();
    const RenderCounters before = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
    for (int i = 0; i < 5; ++i) {
      frame();
    }
    const RenderCounters now = renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
    EXPECT_EQ(now.view_renders, before.view_renders + 5) << present;
    EXPECT_EQ(now.view_cache_hits, before.view_cache_hits) << present;
  }
}

TEST_F(ExplorerTest, TheGridViewSettingTakesTheSlidersWholeNumbersOnly) {
  ASSERT_EQ(explorer_->set_view("grid", "512"), std::nullopt);
  EXPECT_EQ(explorer_->scene().grid_nx(), 512);
  EXPECT_EQ(explorer_->scene().grid_ny(), 512);
  ASSERT_EQ(explorer_->set_view("grid", "8"), std::nullopt);
  EXPECT_EQ(explorer_->scene().grid_nx(), 8);
  for (const char* refused : {"7", "513", "64.5", "many", "nan"}) {
    const std::optional<std::string> problem = explorer_->set_view("grid", refused);
    ASSERT_TRUE(problem.has_value()) << refused;
    EXPECT_NE(problem->find("from 8 to 512"), std::string::npos) << *problem;
  }
  EXPECT_EQ(explorer_->scene().grid_nx(), 8) << "a refused value changes nothing";
}

// A scripted picture's view settings are taken as given or refused with their range; none is
// moved to the nearest allowed value (README: values are never clamped).
TEST_F(ExplorerTest, ViewSettingsOutsideTheirRangeAreRefusedNotClamped) {
  for (const auto& [key, value] :
       std::vector<std::pair<const char*, const char*>>{{"z_exaggeration", "100"},
                                                        {"z_exaggeration", "-3"},
                                                        {"scale", "1000"},
                                                        {"scale", "99"},
                                                        {"breeze", "2"},
                                                        {"wireframe", "7"},
                                                        {"ground", "-1"},
                                                        {"time", "-5"},
                                                        {"breeze_mm", "1e9"},
                                                        {"print_mm", "5"}}) {
    SCOPED_TRACE(std::string(key) + "=" + value);
    const std::optional<std::string> problem = explorer_->set_view(key, value);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("must be"), std::string::npos) << *problem;
  }
  EXPECT_EQ(panel<ClothViewPanel>().style().z_exaggeration, 1.0f)
      << "a refused value changes nothing";
  EXPECT_EQ(explorer_->set_view("z_exaggeration", "20"), std::nullopt);
  EXPECT_EQ(panel<ClothViewPanel>().style().z_exaggeration, 20.0f);
  EXPECT_EQ(explorer_->set_view("wireframe", "1"), std::nullopt);
  EXPECT_TRUE(panel<ClothViewPanel>().style().wireframe);
  EXPECT_EQ(explorer_->set_view("scale", "250"), std::nullopt);
}

// The 3D view's look is the user's, as its switches are: the print, its size, the colouring and
// the z exaggeration come back with the session (a woven print once came back plain).
TEST_F(ExplorerTest, TheThreeDViewsLookIsRestoredWithTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  for (const auto& [key, value] :
       {std::pair{"print", "checks"}, std::pair{"print_mm", "25"},
        std::pair{"colour_by", "fold_sign"}, std::pair{"z_exaggeration", "4"}}) {
    ASSERT_EQ(explorer_->set_view(key, value), std::nullopt) << key;
  }
  frame();
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  const ClothStyle& style = panel<ClothViewPanel>().style();
  EXPECT_EQ(style.print, ClothStyle::Print::checks);
  EXPECT_EQ(style.print_mm, 25.0f);
  EXPECT_EQ(style.colour_by, ClothStyle::ColourBy::fold_sign);
  EXPECT_EQ(style.z_exaggeration, 4.0f);
}

}  // namespace
}  // namespace foldlab::gui
