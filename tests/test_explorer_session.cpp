// The session kept between starts and the page's address: what is remembered, what is set aside
// when it cannot be read, and the link that follows the inputs.
#include <cstdio>
#include <string>

#include "app/gui/compare.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "core/io/link.hpp"
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

// A page that records what its address was set to.
class RecordingLink final : public PageLink {
 public:
  explicit RecordingLink(std::vector<std::string>& shown) : shown_(shown) {}
  bool follows() const override { return true; }
  void show(std::string_view fragment) override { shown_.emplace_back(fragment); }

 private:
  std::vector<std::string>& shown_;
};

TEST(LinkThrottle, WritesAChangeAtOnceThenAtMostFourTimesASecondAndTheLastAlways) {
  LinkThrottle throttle(0.25);
  EXPECT_EQ(throttle.due("h=1400", 0.0), std::nullopt) << "the address the page opened with";
  EXPECT_EQ(throttle.due("h=1400", 1.0), std::nullopt);
  EXPECT_EQ(throttle.due("h=1500", 1.0), "h=1500");
  EXPECT_FALSE(throttle.pending());
  EXPECT_EQ(throttle.due("h=1600", 1.1), std::nullopt);
  EXPECT_TRUE(throttle.pending());
  EXPECT_EQ(throttle.due("h=1700", 1.2), std::nullopt);
  EXPECT_EQ(throttle.due("h=1700", 1.25), "h=1700");
  EXPECT_FALSE(throttle.pending());
  // Back to what was written before its turn came: nothing to write, nothing pending.
  EXPECT_EQ(throttle.due("h=1800", 1.3), std::nullopt);
  EXPECT_EQ(throttle.due("h=1700", 1.4), std::nullopt);
  EXPECT_FALSE(throttle.pending());
  EXPECT_EQ(throttle.due("h=1700", 9.0), std::nullopt);
}

TEST_F(ExplorerTest, ThePagesAddressFollowsTheInputsWithoutADragRewritingItEveryFrame) {
  std::vector<std::string> shown;
  explorer_->set_page_link(std::make_unique<RecordingLink>(shown));
  frame();
  EXPECT_TRUE(shown.empty()) << shown.front();
  // A slider dragged over 60 frames (one second at 60 frames a second, the test's clock).
  for (int i = 1; i <= 60; ++i) {
    explorer_->document().apply(Edit::input("h", 1400.0 + 10.0 * i).open());
    frame();
  }
  // At once, then every 0.25 s: 1 + 4 writes (the frames' clock rounds), never one a frame.
  EXPECT_GE(shown.size(), 4u);
  EXPECT_LE(shown.size(), 5u);
  EXPECT_EQ(shown.front(), "preset=paper-table1-h1400&h=1410");
  // The last value reaches the address once its turn comes, though nothing moves any more.
  for (int i = 0; i < 20; ++i) {
    frame();
  }
  EXPECT_EQ(shown.back(), "preset=paper-table1-h1400&h=2000");
  EXPECT_EQ(shown.back(), explorer_->link());
  const std::size_t writes = shown.size();
  for (int i = 0; i < 30; ++i) {
    frame();
  }
  EXPECT_EQ(shown.size(), writes) << "an unchanged link is not written again";
}

TEST_F(ExplorerTest, TheLinkCarriesTheViewSetUpForARoomAndTheLookOnlyWhenChosen) {
  frame();
  const std::string fabric = explorer_->link();
  EXPECT_EQ(fabric, "preset=paper-table1-h1400") << "nothing differs from the preset";
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("theme", "light"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("scale", "125"), std::nullopt);
  frame();
  // The sender's theme and text size are the sender's: a student's phone keeps its own.
  EXPECT_EQ(explorer_->link(), fabric + "&present=cloth");
  ASSERT_EQ(explorer_->set_view("link_look", "1"), std::nullopt);
  EXPECT_EQ(explorer_->link(), fabric + "&present=cloth&theme=light&scale=125");
  ASSERT_EQ(explorer_->set_view("link_look", "0"), std::nullopt);
  // Copied with the desktop's link and no page address: a foldlab: link, said in a toast that
  // lies in the window, and in the presentation's read-out, the status line being hidden.
  ASSERT_EQ(explorer_->set_view("page_address", ""), std::nullopt);
  explorer_->copy_link();
  const std::string copied = "foldlab:#" + explorer_->link();
  EXPECT_EQ(std::string(ImGui::GetClipboardText()), copied);
  const std::string said = explorer_->status().message();
  EXPECT_EQ(said, "Copied the fabric as a foldlab: link, " + copied +
                      ", which opens in an installed FoldLab. Export > Page address makes it a "
                      "web address anyone can open.");
  EXPECT_EQ(explorer_->status().toast(), said);
  frame();
  EXPECT_EQ(explorer_->presented_message(), said);
  ASSERT_TRUE(explorer_->toast_rect().has_value());
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  EXPECT_GE(explorer_->toast_rect()->pos.y, 0.0f);
  EXPECT_LE(explorer_->toast_rect()->pos.y + explorer_->toast_rect()->size.y, display.y);
  ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->presented_message(), "");
  // With the page's address set once: a whole address, its own fragment dropped.
  ASSERT_EQ(explorer_->set_view("page_address", "https://example.org/foldlab/index.html#old"),
            std::nullopt);
  explorer_->copy_link();
  EXPECT_EQ(std::string(ImGui::GetClipboardText()),
            "https://example.org/foldlab/index.html#" + explorer_->link());
  EXPECT_EQ(explorer_->report()["view"]["page_address"],
            "https://example.org/foldlab/index.html#old");
}

TEST_F(ExplorerTest, TheLinkWritesDraggedValuesAtTheSlidersDigitsAndTypedOnesExactly) {
  frame();
  // As a slider leaves it (Edit::by_slider) and as a typed value does.
  explorer_->document().apply(Edit::input("t", 0.23761827878721103).by_slider());
  explorer_->document().apply(Edit::input("h", 2000.4999999999998));
  // t's slider shows three significant digits (0.238 mm); h was typed, and round-trips.
  EXPECT_EQ(explorer_->link(), "preset=paper-table1-h1400&t=0.238&h=2000.4999999999998");
  // Typed after the drag: exact again.
  explorer_->document().apply(Edit::input("t", 0.23761827878721103));
  EXPECT_EQ(explorer_->link(),
            "preset=paper-table1-h1400&t=0.23761827878721103&h=2000.4999999999998");
}

TEST_F(ExplorerTest, ASavedPresetHoldsDraggedValuesAtTheSlidersDigitsAndTypedOnesExactly) {
  frame();
  explorer_->document().apply(Edit::input("t", 0.23761827878721103).by_slider());
  explorer_->document().apply(Edit::input("h", 2000.4999999999998));
  const Preset saved = preset_to_save(explorer_->document(), "Mine");
  EXPECT_EQ(saved.parameters.fabric.thickness_mm, 0.238);
  EXPECT_EQ(saved.parameters.hanging.height_mm, 2000.4999999999998);
}

TEST_F(ExplorerTest, TheLinkCarriesTheNamesAndBWhenPinned) {
  frame();
  explorer_->document().apply(Edit::input("h", 2000.0));
  pin_as_b(explorer_->document(), explorer_->status());
  explorer_->document().apply(Edit::input("t", 0.4));
  // B is pinned with A's former values, named "... (edited)"; A keeps the preset's name, which
  // the link leaves out as it leaves out every value equal to the preset's.
  const std::string b_name = explorer_->document().compare().b().name;
  EXPECT_EQ(explorer_->link(), "preset=paper-table1-h1400&t=0.4&h=2000&b.name=" +
                                   foldlab::percent_encode(b_name) + "&b.h=2000");
}

// B pinned after a drag keeps the slider's digits in the link as A does; a dragged K writes c with
// the digits that show that K, and a c typed after it exactly.
TEST_F(ExplorerTest, TheLinkWritesBsDraggedValuesAndADraggedKAtTheSlidersDigits) {
  frame();
  explorer_->document().apply(Edit::input("t", 0.23761827878721103).by_slider());
  pin_as_b(explorer_->document(), explorer_->status());
  explorer_->document().apply(Edit::input("t", 0.4));
  const std::string link = explorer_->link();
  EXPECT_NE(link.find("&b.t=0.238"), std::string::npos) << link;
  // The preset's ν is 0.3 unless it says otherwise: K = c / (1 - ν²).
  const double nu = explorer_->document().edited().fabric.poisson_ratio;
  explorer_->document().apply(Edit::input("K", 37.123456789).by_slider());
  const std::string k_link = explorer_->link();
  const std::size_t c_at = k_link.find("&c=");
  ASSERT_NE(c_at, std::string::npos) << k_link;
  const std::string c_text = k_link.substr(c_at + 3, k_link.find('&', c_at + 1) - c_at - 3);
  char shown_k[32];
  std::snprintf(shown_k, sizeof shown_k, "%.3g", std::stod(c_text) / (1.0 - nu * nu));
  EXPECT_STREQ(shown_k, "37.1") << k_link;
  EXPECT_LE(c_text.size(), 6u) << k_link;
  explorer_->document().apply(Edit::input("c", 33.33371));
  EXPECT_NE(explorer_->link().find("&c=33.33371"), std::string::npos)
      << explorer_->link();
}

// Where the config folder is the explorer's alone (the page's storage), a session that does not
// read is said so, set aside and replaced; it is left in place on the desktop.
TEST_F(ExplorerTest, AnUnreadableSessionIsSetAsideWhereTheConfigFolderIsTheExplorers) {
  const fs::path session = dir_ / "session.json";
  for (const bool owned : {false, true}) {
    { std::ofstream(session) << "{not a session"; }
    fs::remove(dir_ / "session.json.unread");
    ExplorerOptions options{kPresetsDir, dir_ / "user-presets",     session, "equations",
                            {},          dir_ / "measurements.csv", dir_};
    options.owns_config_folder = owned;
    explorer_.reset();
    explorer_ = std::make_unique<Explorer>(load_preset(kPresetsDir / "paper-table1-h1400.json"),
                                           (kPresetsDir / "paper-table1-h1400.json").string(), true,
                                           options, renderer_);
    frame();
    const std::vector<std::string>& notices = explorer_->notices();
    ASSERT_GE(notices.size(), 2u);
    EXPECT_EQ(notices[0].rfind("the saved session " + session.string() + " could not be read", 0),
              0u)
        << notices[0];
    if (owned) {
      EXPECT_EQ(notices[1], "The session that did not read is kept as " + session.string() +
                                ".unread; a new session is saved in its place.");
    } else {
      EXPECT_NE(notices[1].find("move it away"), std::string::npos) << notices[1];
    }
    explorer_.reset();  // saves the session, where it may
    std::string error;
    bool may_save = true;
    EXPECT_EQ(load_session(session, error, may_save).has_value(), owned) << error;
    EXPECT_EQ(fs::exists(dir_ / "session.json.unread"), owned);
  }
  open_explorer("equations");
}

// A print chosen in the 3D view was kept only if the window closed normally: choosing it did not
// mark the session, so the save a second after a change never came and a killed window lost it.
TEST_F(ExplorerTest, AViewSettingChosenByHandIsOnDiskWithinSecondsAndComesBack) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  frame();
  explorer_->save_session_now();
  ASSERT_EQ(
      nlohmann::json::parse(foldlab::testing::read_file(session))["view"].value("print", -1.0),
      0.0);
  click("plain");
  click("woven checks");
  frame();
  ASSERT_EQ(panel<ClothViewPanel>().style().print, ClothStyle::Print::checks);
  // Two seconds of frames (ImGui's clock), with no save asked for.
  for (int i = 0; i < 120; ++i) {
    frame();
  }
  const nlohmann::json saved = nlohmann::json::parse(foldlab::testing::read_file(session));
  EXPECT_EQ(saved["view"].value("print", -1.0), 1.0) << saved.dump();
  open_explorer("equations", {}, session, true);
  EXPECT_EQ(panel<ClothViewPanel>().style().print, ClothStyle::Print::checks);
}

TEST_F(ExplorerTest, UiScaleIsClampedAndRememberedWithTheTheme) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  EXPECT_EQ(explorer_->appearance().scale_percent(), 100);
  // A script's --view asking for more is refused; a restored or requested scale is clamped.
  EXPECT_TRUE(explorer_->set_view("scale", "400").has_value());
  explorer_->appearance().request(400, false);
  frame();
  EXPECT_EQ(explorer_->appearance().scale_percent(), 250);
  // ImGui's 13 px font rebuilt at 2.5 times its size, not stretched.
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 33.0f);
  EXPECT_FLOAT_EQ(ImGui::GetIO().FontGlobalScale, 1.0f);
  explorer_->appearance().request(20, false);
  frame();
  EXPECT_EQ(explorer_->appearance().scale_percent(), 100);
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 13.0f);

  // Ctrl + (the '=' key) five times: 150 %; the style's sizes scale with it.
  const float padding_100 = ImGui::GetStyle().FramePadding.x;
  ImGuiIO& io = ImGui::GetIO();
  for (int i = 0; i < 5; ++i) {
    io.KeyCtrl = true;
    io.KeysDown['='] = true;
    frame();
    io.KeysDown['='] = false;
    frame();
  }
  io.KeyCtrl = false;
  EXPECT_EQ(explorer_->appearance().scale_percent(), 150);
  EXPECT_FLOAT_EQ(ImGui::GetStyle().FramePadding.x, 1.5f * padding_100);
  ASSERT_EQ(explorer_->set_view("theme", "light"), std::nullopt);
  frame();
  EXPECT_TRUE(style_is_light());
  explorer_->save_session_now();

  open_explorer("equations", {}, session, true);
  EXPECT_EQ(explorer_->appearance().scale_percent(), 150);
  EXPECT_TRUE(explorer_->appearance().light_theme());
  EXPECT_TRUE(style_is_light());
  EXPECT_FLOAT_EQ(ImGui::GetIO().Fonts->Fonts[0]->FontSize, 20.0f);  // round(13 * 1.5)
}

// A session file the explorer could not read as its own (here a link to someone's notes) was
// reported unreadable and then saved over, through the link, on the next change and at exit.
TEST_F(ExplorerTest, ASessionFileThatCannotBeReadIsNeverSavedOver) {
  const fs::path notes = dir_ / "notes.txt";
  const fs::path session = dir_ / "session.json";
  std::ofstream(notes) << "my notes\n";
  fs::create_symlink(notes, session);
  for (const bool restore : {true, false}) {
    SCOPED_TRACE(restore ? "restored" : "a preset asked for");
    open_explorer("equations", {}, session, restore);
    std::size_t said = 0;
    for (const std::string& notice : explorer_->notices()) {
      said += notice.find("session will not be saved") != std::string::npos;
    }
    EXPECT_EQ(said, 1u);
    ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
    frame();
    explorer_->save_session_now();
    explorer_.reset();
    EXPECT_EQ(foldlab::testing::read_file(notes), "my notes\n");
    EXPECT_TRUE(fs::is_symlink(session));
  }
  // A session that reads back is still saved and restored.
  fs::remove(session);
  open_explorer("equations", {}, session);
  ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
  explorer_.reset();
  open_explorer("equations", {}, session, true);
  EXPECT_EQ(document().scene().parameters().hanging.height_mm, 1500.0);
}

// One bad value in a session (d = 1e308 in the fabric being edited) drops that part alone: the
// preset it came from, B and the view's switches are restored, the notices say what was dropped,
// and the file as it was is kept beside it before the next save replaces it.
TEST_F(ExplorerTest, ASessionWithOneBadValueKeepsTheRestAndTheFileAsItWas) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  ASSERT_EQ(explorer_->set_view("wireframe", "1"), std::nullopt);
  ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
  pin_as_b(document(), status());
  explorer_->save_session_now();
  explorer_.reset();
  nlohmann::json j = nlohmann::json::parse(foldlab::testing::read_file(session));
  const double loaded_h = j.at("loaded").at("hanging").at("height_mm").get<double>();
  j["current"]["hanging"]["d_mm"] = 1e308;
  j["view"]["grid_resolution"] = "big";  // one view setting of the wrong type drops it alone
  const std::string broken = j.dump(2);
  std::ofstream(session) << broken;

  open_explorer("equations", {}, session, true);
  std::string notices;
  for (const std::string& notice : explorer_->notices()) {
    notices += notice + "\n";
  }
  EXPECT_NE(notices.find("fabric being edited was not restored"), std::string::npos) << notices;
  EXPECT_NE(notices.find("d_mm"), std::string::npos) << notices;
  EXPECT_NE(notices.find("session.json.unread"), std::string::npos) << notices;
  EXPECT_NE(notices.find("view.grid_resolution must be true, false or a number, not string"),
            std::string::npos)
      << notices;
  EXPECT_TRUE(panel<ClothViewPanel>().style().wireframe) << "the view's switches are the user's";
  EXPECT_TRUE(document().compare().pinned()) << "B is the user's";
  EXPECT_EQ(shown().hanging.height_mm, loaded_h) << "the preset it came from";
  EXPECT_EQ(foldlab::testing::read_file(dir_ / "session.json.unread"), broken);
  explorer_->save_session_now();
  std::string error;
  const std::optional<Session> saved =
      session_from_text(foldlab::testing::read_file(session), "saved", error);
  ASSERT_TRUE(saved.has_value()) << error;
  EXPECT_TRUE(saved->complete);
}

// The session file says which FoldLab wrote it; a session from before it did still loads.
TEST_F(ExplorerTest, TheSessionFileRecordsTheVersionThatWroteIt) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session, true);
  explorer_->save_session_now();
  std::ifstream in(session);
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("written_by"), app::version_line());
  EXPECT_TRUE(j.at("written_by").get<std::string>().starts_with("FoldLab "));
  j.erase("written_by");
  std::string error;
  EXPECT_TRUE(session_from_text(j.dump(), "older session", error).has_value()) << error;
}

}  // namespace
}  // namespace foldlab::gui
