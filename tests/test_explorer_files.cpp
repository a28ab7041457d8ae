// Files in and out: the save and open dialogs, "~" for the home folder, pictures and their size,
// and the page's downloads and file picker.
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

// HOME pointed at a test's temporary folder while it lives, so that "~/" never reaches the real
// home folder.
class HomeFolder {
 public:
  explicit HomeFolder(const fs::path& home) {
    if (const char* old = std::getenv("HOME")) {
      old_ = old;
    }
    ::setenv("HOME", home.c_str(), 1);
  }
  ~HomeFolder() {
    if (old_) {
      ::setenv("HOME", old_->c_str(), 1);
    } else {
      ::unsetenv("HOME");
    }
  }
  HomeFolder(const HomeFolder&) = delete;
  HomeFolder& operator=(const HomeFolder&) = delete;

 private:
  std::optional<std::string> old_;
};

TEST(ExpandHome, ReadsTildeAsTheHomeFolderOnlyAtTheStart) {
  HomeFolder home("/home/someone");
  EXPECT_EQ(expand_home("~"), fs::path("/home/someone"));
  EXPECT_EQ(expand_home("~/"), fs::path("/home/someone"));
  EXPECT_EQ(expand_home("~/photos/a.png"), fs::path("/home/someone/photos/a.png"));
  EXPECT_EQ(expand_home("~other/a.png"), fs::path("~other/a.png"));  // another user's: as typed
  EXPECT_EQ(expand_home("a/~/b.png"), fs::path("a/~/b.png"));
  EXPECT_EQ(expand_home("/tmp/x.png"), fs::path("/tmp/x.png"));
}

TEST(CropPixels, KeepsTheRectangleTopRowFirstAndCutsItToTheFrame) {
  // 4 x 3 pixels, each pixel's red channel its index.
  std::vector<std::uint8_t> rgba;
  for (std::uint8_t i = 0; i < 12; ++i) {
    rgba.insert(rgba.end(), {i, 0, 0, 255});
  }
  std::vector<std::uint8_t> part = rgba;
  const FrameSize kept = crop_pixels(part, FrameSize{4, 3}, 1, 1, 2, 2);
  EXPECT_EQ(kept.width, 2);
  EXPECT_EQ(kept.height, 2);
  ASSERT_EQ(part.size(), 16u);
  EXPECT_EQ((std::vector<int>{part[0], part[4], part[8], part[12]}),
            (std::vector<int>{5, 6, 9, 10}));
  part = rgba;
  const FrameSize cut = crop_pixels(part, FrameSize{4, 3}, 2, -5, 10, 7);
  EXPECT_EQ(cut.width, 2);
  EXPECT_EQ(cut.height, 2);
  EXPECT_EQ((std::vector<int>{part[0], part[4], part[8], part[12]}),
            (std::vector<int>{2, 3, 6, 7}));
}

// Exports went to the working folder with no question, and "Window picture" took the Export
// menu itself into the picture.
// (The test's name holds no "Export": the status line shows the temporary folder, named after it,
// and a click on "Export" must find the menu.)
TEST_F(ExplorerTest, SavingAsksWhereAndAPictureIsTakenAfterTheMenuAndDialogClosed) {
  HomeFolder home(dir_);
  struct Taken {
    PictureRequest request;
    std::string frame_text;
  };
  std::vector<Taken> taken;
  const auto frame_and_take = [&] {
    frame();
    if (std::optional<PictureRequest> request = explorer_->take_screenshot_request()) {
      taken.push_back({*request, last_text_});
    }
  };
  const auto export_as = [&](const std::string& item, const std::string& typed) {
    return play(*explorer_,
                {{"steps",
                  {{{"click", "Export"}},
                   {{"frames", 1}},
                   {{"click", item}},
                   {{"frames", 2}},
                   {{"type", typed}},
                   {{"key", "enter"}},
                   {{"frames", 3}}}}},
                frame_and_take);
  };
  ASSERT_EQ(export_as("Window picture (.png)...", (dir_ / "window.png").string()), 0);
  ASSERT_EQ(taken.size(), 1u);
  EXPECT_EQ(taken[0].request.path, (dir_ / "window.png").string());
  EXPECT_FALSE(taken[0].request.crop.has_value());
  EXPECT_EQ(taken[0].frame_text.find("Window picture"), std::string::npos) << "the menu is shown";
  EXPECT_EQ(taken[0].frame_text.find("Export window picture"), std::string::npos)
      << "the dialog is shown";
  EXPECT_EQ(status().modal_title(), "");

  // "~/" is the home folder, and the extension is added: the 3D view alone, cut from the window.
  ASSERT_EQ(export_as("3D view picture (.png)...", "~/view"), 0);
  ASSERT_EQ(taken.size(), 2u);
  EXPECT_EQ(fs::path(taken[1].request.path), fs::weakly_canonical(dir_) / "view.png");
  ASSERT_TRUE(taken[1].request.crop.has_value());
  const PanelRect view = *taken[1].request.crop;
  for (const auto& [key, rect] : explorer_->layout().panel_rects()) {
    if (key == "cloth") {
      EXPECT_GE(view.pos.x, rect.pos.x);
      EXPECT_GT(view.pos.y, rect.pos.y) << "below the title and the view's settings";
      EXPECT_LE(view.pos.x + view.size.x, rect.pos.x + rect.size.x);
      EXPECT_LE(view.pos.y + view.size.y, rect.pos.y + rect.size.y);
      EXPECT_GT(view.size.x * view.size.y, 0.5f * rect.size.x * rect.size.y);
    }
  }

  // The folder last used is where the next dialog opens; a file there is replaced only when
  // the user says so.
  { std::ofstream(dir_ / "folds.svg") << "old"; }
  ASSERT_EQ(export_as("Fold lines (.svg)...", "folds"), 0);
  EXPECT_EQ(status().modal_title(), "Export fold lines as an SVG drawing");
  EXPECT_EQ(explorer_->file_dialog().folder(), fs::weakly_canonical(dir_));
  EXPECT_NE(last_text_.find("folds.svg is there already: write over it?"), std::string::npos)
      << last_text_;
  const auto read = [](const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(read(dir_ / "folds.svg"), "old");
  const auto& entries = explorer_->file_dialog().entries();
  EXPECT_TRUE(std::any_of(entries.begin(), entries.end(),
                          [](const FileDialog::Entry& e) { return e.name == "folds.svg"; }));
  EXPECT_TRUE(std::none_of(entries.begin(), entries.end(), [](const FileDialog::Entry& e) {
    return e.name == "window.png";
  })) << "an SVG's dialog lists SVG files";
  ASSERT_EQ(
      play(*explorer_, {{"steps", {{{"click", "Replace"}}, {{"frames", 2}}}}}, frame_and_take), 0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_NE(read(dir_ / "folds.svg").find("<svg"), std::string::npos);

  // Another name typed while the question is shown withdraws it: Save then writes the new name
  // and the file asked about is left as it was.
  { std::ofstream(dir_ / "folds.svg") << "old"; }
  ASSERT_EQ(export_as("Fold lines (.svg)...", "folds"), 0);
  ASSERT_TRUE(shows(last_text_, "folds.svg is there already")) << last_text_;
  ASSERT_EQ(
      play(*explorer_, {{"steps", {{{"type", "other-folds"}}, {{"frames", 2}}}}}, frame_and_take),
      0);
  EXPECT_FALSE(shows(last_text_, "is there already")) << last_text_;
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Save"}}, {{"frames", 2}}}}}, frame_and_take),
            0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(read(dir_ / "folds.svg"), "old");
  EXPECT_NE(read(dir_ / "other-folds.svg").find("<svg"), std::string::npos);

  // The name offered is the fabric's and what the file holds; Escape cancels: nothing is written.
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "Export"}},
                    {{"frames", 1}},
                    {{"click", "Fold lines (.csv)..."}},
                    {{"frames", 2}}}}},
                 frame_and_take),
            0);
  EXPECT_TRUE(shows(last_text_, "table-1-h-1400-mm-fold-lines.csv")) << last_text_;
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"key", "escape"}}, {{"frames", 2}}}}}, frame_and_take),
            0);
  EXPECT_EQ(status().modal_title(), "");
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_NE(entry.path().extension(), ".csv") << entry.path();
  }
  EXPECT_EQ(taken.size(), 2u);
}

// A FileTransfer that browses no folders, as the page's: what it delivers and was asked to pick.
class PageLikeTransfer : public FileTransfer {
 public:
  explicit PageLikeTransfer(fs::path outbox) : outbox_(std::move(outbox)) {}
  bool browses_folders() const override { return false; }
  fs::path outbox() const override { return outbox_; }
  bool deliver(const fs::path& path) override {
    std::ifstream in(path, std::ios::binary);
    delivered.emplace_back(path.filename().string(),
                           std::string(std::istreambuf_iterator<char>(in), {}));
    return true;
  }
  void pick(const std::vector<std::string>& extensions) override { asked.push_back(extensions); }
  std::optional<fs::path> take_picked() override { return std::exchange(picked, std::nullopt); }

  std::vector<std::pair<std::string, std::string>> delivered;  // name, bytes
  std::vector<std::vector<std::string>> asked;                 // extensions of each pick
  std::optional<fs::path> picked;                              // the next file the user picks

 private:
  fs::path outbox_;
};

// In the page there is no folder to browse: saving names a file, which is written into the
// outbox and delivered (downloaded) once it is there, a picture a frame later; opening asks the
// picker and takes the copy it brings, through the desktop dialog's own callbacks.
TEST_F(ExplorerTest, WithoutFoldersAFileIsNamedAndDeliveredAndAPickedOneIsOpened) {
  auto owned = std::make_unique<PageLikeTransfer>(dir_ / "outbox");
  PageLikeTransfer& transfer = *owned;
  explorer_->set_file_transfer(std::move(owned));
  std::optional<PictureRequest> picture;
  const auto frame_and_take = [&] {
    frame();
    if (std::optional<PictureRequest> request = explorer_->take_screenshot_request()) {
      picture = request;
    }
  };
  const auto export_as = [&](const std::string& item, const std::string& typed) {
    return play(*explorer_,
                {{"steps",
                  {{{"click", "Export"}},
                   {{"frames", 1}},
                   {{"click", item}},
                   {{"frames", 2}},
                   {{"type", typed}},
                   {{"click", "Download"}},
                   {{"frames", 2}}}}},
                frame_and_take);
  };
  // A name with folders keeps its name alone, and the format's extension is added.
  ASSERT_EQ(export_as("Fold lines (.svg)...", "some/folder/folds"), 0);
  ASSERT_EQ(transfer.delivered.size(), 1u);
  EXPECT_EQ(transfer.delivered[0].first, "folds.svg");
  EXPECT_NE(transfer.delivered[0].second.find("<svg"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "outbox" / "folds.svg")) << "the browser holds its own copy";
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(status().message(), "Downloaded folds.svg (" +
                                    std::to_string(transfer.delivered[0].second.size()) +
                                    " bytes): the browser keeps it with its downloads.");

  // The fabric as a preset, named after the file, which opens as the fabric it was.
  ASSERT_EQ(export_as("Preset (.json)...", "my fabric"), 0);
  ASSERT_EQ(transfer.delivered.size(), 2u);
  EXPECT_EQ(transfer.delivered[1].first, "my fabric.json");
  { std::ofstream(dir_ / "copy.json") << transfer.delivered[1].second; }
  const Preset exported = load_preset(dir_ / "copy.json");
  EXPECT_EQ(exported.name, "my fabric");
  EXPECT_EQ(exported.parameters.hanging.height_mm, 1400.0);  // Table 1's row
  EXPECT_EQ(exported.parameters.fabric.thickness_mm, 0.25);

  // A picture is delivered once the frame loop has written it.
  ASSERT_EQ(export_as("Window picture (.png)...", "window"), 0);
  ASSERT_TRUE(picture.has_value());
  EXPECT_EQ(fs::path(picture->path), dir_ / "outbox" / "window.png");
  EXPECT_EQ(transfer.delivered.size(), 2u) << "not written yet";
  write_png(picture->path.c_str(), FrameSize{2, 1}, {1, 2, 3, 255, 4, 5, 6, 255});
  frame();
  ASSERT_EQ(transfer.delivered.size(), 3u);
  EXPECT_EQ(transfer.delivered[2].first, "window.png");
  EXPECT_EQ(transfer.delivered[2].second.substr(1, 3), "PNG");

  // Opening: the picker is asked for a preset; the copy it brings loads as a listed preset does.
  Preset other = load_preset(kPresetsDir / "paper-table1-h1400.json");
  other.name = "From a colleague";
  other.parameters.hanging.height_mm = 1234.0;
  save_preset(other, dir_ / "uploads-colleague.json");
  click("Open file...");
  EXPECT_EQ(status().modal_title(), PresetsPanel::kOpenFileModal);
  ASSERT_EQ(transfer.asked.size(), 1u);
  EXPECT_EQ(transfer.asked[0], std::vector<std::string>{".json"});
  transfer.picked = dir_ / "uploads-colleague.json";
  frame();
  frame();
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().edited().hanging.height_mm, 1234.0);
  EXPECT_EQ(document().loaded().name, "From a colleague");

  // A file that is no preset is refused in the words a listed one's refusal has; nothing changes.
  { std::ofstream(dir_ / "notes.json") << "these are my notes"; }
  click("Open file...");
  transfer.picked = dir_ / "notes.json";
  frame();
  frame();
  EXPECT_EQ(document().edited().hanging.height_mm, 1234.0);
  EXPECT_EQ(status().message().rfind("Not loaded; the current state is kept.\n", 0), 0u)
      << status().message();
  EXPECT_NE(status().message().find("not valid JSON at line 1"), std::string::npos)
      << status().message();

  // Cancelled: a file picked afterwards is not taken.
  click("Open file...");
  click("Cancel");
  EXPECT_EQ(status().modal_title(), "");
  transfer.picked = dir_ / "uploads-colleague.json";
  frame();
  EXPECT_FALSE(transfer.picked.has_value());
  EXPECT_EQ(status().modal_title(), "");
}

// "~/" was not read in the 3D view's photo path nor in the fold plot's, and neither had a file
// browser.
TEST_F(ExplorerTest, APhotoIsChosenInTheOpenDialogOrTypedWithTilde) {
  HomeFolder home(dir_);
  fs::create_directories(dir_ / "photos" / "old");
  const std::vector<std::uint8_t> pixels = {255, 0, 0,   255, 0, 255, 0, 255,
                                            0,   0, 255, 255, 9, 9,   9, 255};
  write_png((dir_ / "photos" / "swatch.png").c_str(), FrameSize{2, 2}, pixels);
  { std::ofstream(dir_ / "photos" / "notes.txt") << "not a picture"; }

  // The 3D view's print: typed with "~/".
  click("plain");
  click("photo");
  click("swatch PNG");
  ASSERT_EQ(type_and_enter("~/photos/swatch.png"), 0);
  ASSERT_NE(panel<ClothViewPanel>().style().photo, nullptr);
  EXPECT_EQ(panel<ClothViewPanel>().style().photo->width, 2);

  // Browsed: a folder typed is entered, and only folders and pictures are listed.
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "browse..."}},
                    {{"frames", 2}},
                    {{"expect", {{"modal", "Load swatch photo"}}}},
                    {{"type", "~/photos"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_EQ(explorer_->file_dialog().folder(), fs::weakly_canonical(dir_ / "photos"));
  std::vector<std::string> names;
  for (const FileDialog::Entry& entry : explorer_->file_dialog().entries()) {
    names.push_back(entry.name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"..", "old", "swatch.png"}));
  ASSERT_EQ(
      play(*explorer_, {{"steps", {{{"click", "swatch.png"}}, {{"frames", 1}}}}}, [&] { frame(); }),
      0);
  click("Load");  // the dialog's button, drawn after "Load photo..." in the fold plot
  EXPECT_EQ(status().modal_title(), "");

  // The fold plot's photo: the dialog opens in the folder last used. ("Load photo...", the
  // only "Load" before the dialog opens: the test's font clips the p of its small button.)
  click("Load");
  EXPECT_EQ(status().modal_title(), PhotoOverlay::kLoadModal);
  ASSERT_EQ(type_and_enter("swatch.png"), 0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(fs::path(panel<PhotoOverlay>().photo_file()),
            fs::weakly_canonical(dir_ / "photos") / "swatch.png");

  // Typed with "~/" in the same dialog, from anywhere.
  click("Load");
  ASSERT_EQ(type_and_enter("~/photos/swatch.png"), 0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(fs::path(panel<PhotoOverlay>().photo_file()), dir_ / "photos" / "swatch.png");
}

// The custom size of a picture: a long number typed in width showed -276447231 (ImGui's int
// field wrapped it around) and a message of WxH. Only digits get in, a few of them, and the
// range is said in words.
TEST_F(ExplorerTest, APicturesCustomSizeKeepsTypedDigitsBoundedAndSaysTheRange) {
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "Export"}},
                    {{"frames", 1}},
                    {{"click", "3D view picture, any size (.png)..."}},
                    {{"frames", 2}},
                    {{"click", "custom"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  ASSERT_NE(frame().find("height"), std::string::npos) << last_text_;
  // The width field ends where its label starts: the text cursor goes after "1920".
  const ImVec2 label = position_of("width");
  click_at(ImVec2(label.x - 12.0f, label.y + 4.0f));
  ImGui::GetIO().AddInputCharactersUTF8("abc-99999999999999");
  frame();
  const std::string text = frame();
  // The letters and the sign are kept out, the digits stop at five: 1920 and one 9.
  EXPECT_NE(text.find("19209 width"), std::string::npos) << text;
  EXPECT_NE(text.find("The width must be from 200 to 8192 pixels,"), std::string::npos) << text;
  EXPECT_NE(text.find("not 19209."), std::string::npos) << text;
  EXPECT_EQ(text.find("must be WxH"), std::string::npos) << text;
}

TEST(PictureSize, TypedSidesAreReadWholeAndTheRangeIsSaid) {
  using foldlab::gui::read_typed_picture_size;
  const auto typed = read_typed_picture_size("1600", "900");
  ASSERT_TRUE(typed.size.has_value()) << typed.problem;
  EXPECT_EQ(typed.size->width, 1600);
  EXPECT_EQ(typed.size->height, 900);
  EXPECT_EQ(read_typed_picture_size("99999999999999", "1080").problem,
            "The width must be from 200 to 8192 pixels, not 99999999999999.");
  EXPECT_EQ(read_typed_picture_size("99999999999999999999999", "1080").problem,
            "The width must be from 200 to 8192 pixels, not 99999999999999999999999.");
  EXPECT_EQ(read_typed_picture_size("abc-99999999999999", "0").problem,
            "The width must be a whole number of pixels from 200 to 8192, not "
            "\"abc-99999999999999\". The height must be from 150 to 8192 pixels, not 0.");
  EXPECT_EQ(read_typed_picture_size("", "1080").problem,
            "The width must be a whole number of pixels from 200 to 8192.");
  // Sides within their ranges, but more pixels than a picture may have.
  EXPECT_NE(read_typed_picture_size("8192", "8192").problem.find("33.5 megapixels"),
            std::string::npos);
}

TEST_F(ExplorerTest, NotSavingIsAWarningNotASuccess) {
  press('S', true);
  ASSERT_EQ(status().modal_title(), "Save as");
  press(kEscape);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(status().message(), "Not saved.");
  EXPECT_EQ(status().message_kind(), MessageKind::warning);
  EXPECT_FALSE(fs::exists(dir_ / "user-presets"));
}

TEST_F(ExplorerTest, StatusMessagesExpire) {
  click("Cotton jersey knit");
  EXPECT_NE(frame().find("Loaded Cotton jersey knit."), std::string::npos);
  ImGui::GetIO().DeltaTime = 5.0f;
  frame();
  frame();
  ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
  EXPECT_EQ(frame().find("Loaded Cotton"), std::string::npos) << "10 s later";
}

}  // namespace
}  // namespace foldlab::gui
