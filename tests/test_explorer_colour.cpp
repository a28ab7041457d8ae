// The fabric's colour: an edit of the fabric (undo, the unsaved marker, the label), kept by the
// session, and each fabric's own beside the other when B is pinned.
#include "explorer_fixture.hpp"

#include "app/gui/compare.hpp"
#include "app/gui/session.hpp"

namespace foldlab::gui {
namespace {

constexpr ColourRgb8 kVelvetRed{0x7a, 0x15, 0x26};
constexpr ColourRgb8 kLinen{0xc9, 0xbc, 0x9c};

TEST_F(ExplorerTest, AColourIsAnEditOfTheFabricThatUndoTakesBack) {
  ASSERT_FALSE(document().appearance().colour.has_value()) << "the paper's case has none";
  ASSERT_FALSE(document().unsaved());
  const std::string name = document().loaded().name;
  EXPECT_EQ(explorer_->set_view("colour", "#7A1526"), std::nullopt);
  frame();
  EXPECT_EQ(document().appearance().colour, kVelvetRed);
  EXPECT_TRUE(document().unsaved());
  EXPECT_EQ(fabric_label(document()), name + " (edited)");
  EXPECT_EQ(document().undo_depth(), 1u);
  EXPECT_EQ(current_fabric(document()).appearance.colour, kVelvetRed) << "what Pin as B takes";

  ASSERT_TRUE(document().undo());
  EXPECT_FALSE(document().appearance().colour.has_value());
  EXPECT_FALSE(document().unsaved());
  EXPECT_EQ(fabric_label(document()), name);
  ASSERT_TRUE(document().redo());
  EXPECT_EQ(document().appearance().colour, kVelvetRed);

  // "none" gives the view's own colour back, as a step of its own.
  EXPECT_EQ(explorer_->set_view("colour", "none"), std::nullopt);
  EXPECT_FALSE(document().appearance().colour.has_value());
  EXPECT_EQ(document().undo_depth(), 2u);
}

TEST_F(ExplorerTest, AColourThatIsNoHexColourIsRefusedAndChangesNothing) {
  for (const char* bad : {"red", "#7a152", "7a1526", "#7a1526ff", "#7g1526"}) {
    const std::optional<std::string> refusal = explorer_->set_view("colour", bad);
    ASSERT_TRUE(refusal.has_value()) << bad;
    EXPECT_NE(refusal->find("#RRGGBB"), std::string::npos) << *refusal;
  }
  EXPECT_FALSE(document().appearance().colour.has_value());
  EXPECT_EQ(document().undo_depth(), 0u);
}

TEST_F(ExplorerTest, LoadingAPresetShowsItsColourAndResetBringsItBack) {
  explorer_->load_preset_file(kPresetsDir / "fabric-velvet-cotton.json");
  frame();
  EXPECT_EQ(document().appearance().colour, kVelvetRed);
  EXPECT_FALSE(document().unsaved());
  EXPECT_EQ(explorer_->report().at("view").at("colour"), "#7a1526");
  ASSERT_EQ(explorer_->set_view("colour", "#c9bc9c"), std::nullopt);
  EXPECT_TRUE(document().unsaved());
  document().reset_to_loaded();
  EXPECT_EQ(document().appearance().colour, kVelvetRed);
  EXPECT_FALSE(document().unsaved());
  // A preset with none draws the view's own colour again.
  explorer_->load_preset_file(kPresetsDir / "fabric-denim-13oz.json");
  EXPECT_FALSE(document().appearance().colour.has_value());
  EXPECT_EQ(explorer_->report().at("view").at("colour"), nullptr);
}

TEST_F(ExplorerTest, TheSessionKeepsTheColourWithTheFabricAndBsOwn) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session, false);
  explorer_->load_preset_file(kPresetsDir / "fabric-velvet-cotton.json");
  pin_as_b(document(), explorer_->status());
  explorer_->load_preset_file(kPresetsDir / "fabric-linen-medium.json");
  ASSERT_EQ(explorer_->set_view("colour", "#102030"), std::nullopt);
  frame();
  explorer_.reset();  // saves the session

  open_explorer("equations", {}, session, true);
  EXPECT_EQ(document().appearance().colour, (ColourRgb8{0x10, 0x20, 0x30}));
  EXPECT_EQ(document().loaded().appearance.colour, kLinen);
  EXPECT_TRUE(document().unsaved()) << "the colour differs from the linen's file";
  ASSERT_TRUE(document().compare().pinned());
  EXPECT_EQ(document().compare().b().appearance.colour, kVelvetRed);
}

}  // namespace
}  // namespace foldlab::gui
