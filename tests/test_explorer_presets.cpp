// The Presets panel and the edits: switching, saving, the unsaved-edits dialog, undo and redo.
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

TEST_F(ExplorerTest, SwitchingPresetShowsTheNewPreset) {
  frame();
  explorer_->load_preset_file(kPresetsDir / "paper-table2-w54.json");
  const std::string text = frame();
  EXPECT_NE(text.find("Loaded Table 2, w = 550 g/m²."), std::string::npos) << text;
  EXPECT_EQ(explorer_->scene().parameters().fabric.weight_N_per_mm2, 54e-7);
  // Table 2's w = 54e-7 row: the paper printed n = 7, as the model gives.
  EXPECT_EQ(number_after(text, "number of wrinkles n "), 7.0) << text;
  EXPECT_EQ(text.find("Parameters *"), std::string::npos) << "a fresh preset has no edits";
}

// Hovering a preset showed its path: a designer wants to know what fabric it is.
TEST_F(ExplorerTest, HoveringAPresetShowsItsDescriptionAndThenItsPath) {
  const ImVec2 at = position_of("Cotton jersey knit");
  ImGui::GetIO().MousePos = ImVec2(at.x + 3.0f, at.y + 4.0f);
  frame();
  const std::string text = frame();
  const std::size_t description = text.find("Single-jersey weft-knitted cotton");
  const std::size_t path = text.find("fabric-cotton-jersey.json");
  ASSERT_NE(description, std::string::npos) << text;
  ASSERT_NE(path, std::string::npos) << text;
  EXPECT_LT(description, path);
}

// A saved preset kept the source preset's description and sources as if they were its own.
TEST_F(ExplorerTest, SaveAsRecordsWhatThePresetWasDerivedFrom) {
  explorer_->load_preset_file(kPresetsDir / "fabric-cotton-jersey.json");
  ASSERT_EQ(explorer_->set_input("w", 120 * kNPerMm2PerGramPerM2), std::nullopt);
  frame();
  press('S', true);
  ASSERT_EQ(status().modal_title(), "Save as");
  click("Save");
  const fs::path written = dir_ / "user-presets" / "cotton-jersey-knit-edited.json";
  ASSERT_TRUE(fs::exists(written)) << last_text_;
  const Preset saved = load_preset(written);
  const Preset source = cotton();
  EXPECT_EQ(saved.derived_from, "Cotton jersey knit");
  EXPECT_NE(saved.description, source.description);
  EXPECT_EQ(saved.description.find("Single-jersey"), std::string::npos) << saved.description;
  EXPECT_EQ(saved.source.find("Fistik"), std::string::npos) << saved.source;
  EXPECT_EQ(saved.parameters.fabric.weight_N_per_mm2, 120 * kNPerMm2PerGramPerM2);
  // Saving it again over itself keeps what it was derived from.
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  press('S', true);
  EXPECT_EQ(load_preset(written).derived_from, "Cotton jersey knit");
  // The listing's hover names the origin.
  const auto& entries = panel<PresetsPanel>().entries();
  const auto entry = std::find_if(entries.begin(), entries.end(), [](const auto& e) {
    return e.path.filename() == "cotton-jersey-knit-edited.json";
  });
  ASSERT_NE(entry, entries.end());
  EXPECT_NE(entry->description.find("Derived from \"Cotton jersey knit\"."), std::string::npos)
      << entry->description;
}

// Clicking a preset once replaced unsaved edits with no question.
TEST_F(ExplorerTest, APresetClickAsksBeforeReplacingUnsavedEditsAndCancelKeepsThem) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  EXPECT_EQ(status().modal_title(), "Unsaved changes");
  EXPECT_NE(last_text_.find("Discard"), std::string::npos) << last_text_;
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0) << "nothing replaced yet";
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);

  click("Cancel");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm");
  EXPECT_TRUE(document().unsaved());
  EXPECT_EQ(frame().find("Discard"), std::string::npos) << "the dialog is closed";
}

TEST_F(ExplorerTest, EscapeClosesTheUnsavedEditsDialogAndKeepsTheEdits) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  ASSERT_EQ(status().modal_title(), "Unsaved changes");
  press(kEscape);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(frame().find("Discard"), std::string::npos) << "the dialog is closed";
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm");
}

TEST_F(ExplorerTest, DiscardLoadsThePresetClickedAndWithoutEditsNothingIsAsked) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Discard");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Cotton jersey knit");
  EXPECT_TRUE(shown() == cotton().parameters);
  EXPECT_FALSE(document().unsaved());

  // (One in sight: the default preset's long name, wrapped, takes two of the list's lines.)
  click("Wool suiting");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Wool suiting");
}

// "Save" on a shipped preset asks for a name, writes the user preset, then loads the one clicked.
TEST_F(ExplorerTest, SaveInTheDialogWritesTheEditsThenLoads) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Save");
  EXPECT_EQ(status().modal_title(), "Save as");
  click("Save");
  const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-edited.json";
  ASSERT_TRUE(fs::exists(written)) << last_text_;
  EXPECT_EQ(load_preset(written).parameters.hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Cotton jersey knit");
}

TEST_F(ExplorerTest, ThePapersCaseButtonsAskBeforeReplacingUnsavedEdits) {
  open_explorer("sweep");
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  click("Table 2 (w)");
  EXPECT_EQ(status().modal_title(), "Unsaved changes");
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  click("Discard");
  EXPECT_EQ(document().loaded().name, "Table 2, w = 336 g/m²");
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "w");
}

// With no session to bring them back (--fresh), closing the window lost the edits unasked.
TEST_F(ExplorerTest, ClosingTheWindowAsksWhenEditsWouldBeLost) {
  EXPECT_TRUE(explorer_->may_quit()) << "nothing to lose";
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  EXPECT_FALSE(explorer_->may_quit());
  frame();
  frame();  // a dialog sizes itself on its first frame and shows from the next
  EXPECT_EQ(status().modal_title(), "Unsaved changes");
  EXPECT_NE(last_text_.find("Closing the window loses them."), std::string::npos) << last_text_;
  press(kEscape);
  EXPECT_FALSE(explorer_->quit_confirmed());
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);

  EXPECT_FALSE(explorer_->may_quit());
  frame();
  frame();
  click("Discard");
  EXPECT_TRUE(explorer_->quit_confirmed());
}

TEST_F(ExplorerTest, UndoAndRedoRestoreTheExactValues) {
  ASSERT_EQ(explorer_->set_input("h", 912.345678901), std::nullopt);
  ASSERT_EQ(explorer_->set_input("d", 123.456789012), std::nullopt);
  frame();
  EXPECT_EQ(document().undo_depth(), 2u);
  press('Z', true);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 100.0);
  EXPECT_EQ(shown().hanging.height_mm, 912.345678901);
  press('Z', true);
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);
  EXPECT_FALSE(document().unsaved());
  EXPECT_EQ(document().undo_depth(), 0u);
  press('Z', true, true);  // Ctrl+Shift+Z
  EXPECT_EQ(shown().hanging.height_mm, 912.345678901);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 100.0);
  press('Y', true);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.456789012);
  EXPECT_EQ(document().undo_depth(), 2u);
}

TEST_F(ExplorerTest, UndoBringsBackTheEditsAPresetLoadReplaced) {
  ASSERT_EQ(explorer_->set_input("d", 123.0), std::nullopt);
  frame();
  click("Cotton jersey knit");
  click("Discard");
  ASSERT_TRUE(shown() == cotton().parameters);
  press('Z', true);
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm");
  EXPECT_EQ(shown().hanging.support_displacement_mm, 123.0);
  EXPECT_EQ(shown().fabric.weight_N_per_mm2, 15e-7);
  press('Y', true);
  EXPECT_TRUE(shown() == cotton().parameters);
}

// A drag changes h on every frame it moves; undo takes the whole drag back at once.
TEST_F(ExplorerTest, OneDragOfASliderIsOneUndoStep) {
  const ImVec2 label = position_of("h (height)");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(label.x - 60.0f, label.y + 4.0f);
  frame();
  io.MouseDown[0] = true;
  frame();
  std::vector<double> seen{height_mm()};
  for (int step = 1; step <= 8; ++step) {
    io.MousePos.x -= 5.0f;
    frame();
    seen.push_back(height_mm());
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  std::sort(seen.begin(), seen.end());
  EXPECT_GT(std::unique(seen.begin(), seen.end()) - seen.begin(), 3) << "h moved over the drag";
  EXPECT_NE(shown().hanging.height_mm, 1400.0);
  EXPECT_EQ(document().undo_depth(), 1u);
  press('Z', true);
  EXPECT_EQ(shown().hanging.height_mm, 1400.0);
  EXPECT_EQ(document().undo_depth(), 0u);
}

TEST_F(ExplorerTest, CtrlSSavesAsThenOverTheUsersPreset) {
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  press('S', true);
  EXPECT_EQ(status().modal_title(), "Save as") << "a shipped preset is never overwritten";
  click("Save");
  const fs::path written = dir_ / "user-presets" / "table-1-h-1400-mm-edited.json";
  ASSERT_TRUE(fs::exists(written));
  EXPECT_EQ(status().message(), "Saved to " + written.string());
  EXPECT_NE(frame().find("Saved to"), std::string::npos) << last_text_;
  EXPECT_FALSE(document().unsaved());

  // Now the loaded preset is the user's: Ctrl+S writes over it without asking.
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  press('S', true);
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
}

// A preset holds only accepted values: with a refused value on screen neither Ctrl+S nor the
// "Save" of the unsaved-edits question writes the file (which would hold the last valid value
// while the slider shows another), the edits stay and still read as unsaved.
TEST_F(ExplorerTest, RefusedInputsAreNeverSavedAndTheEditsStayUnsaved) {
  const fs::path written = save_h900_as_the_users();
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  ASSERT_EQ(explorer_->set_input("t", -0.5), std::nullopt);  // refused: a thickness is > 0
  ASSERT_FALSE(document().issues().empty());
  EXPECT_TRUE(document().unsaved());
  press('S', true);
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 900.0) << "the file is kept";
  EXPECT_EQ(status().message_kind(), MessageKind::error);
  EXPECT_EQ(status().message().rfind("Not saved: a preset holds only accepted values", 0), 0u)
      << status().message();
  EXPECT_NE(status().message().find("thickness"), std::string::npos) << status().message();

  click("Cotton jersey knit");
  ASSERT_EQ(status().modal_title(), "Unsaved changes");
  click("Save");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(document().loaded().name, "Table 1, h = 1400 mm (edited)") << "nothing was loaded";
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 900.0);
  EXPECT_EQ(shown().hanging.height_mm, 950.0);
  EXPECT_EQ(document().edited().fabric.thickness_mm, -0.5);
  EXPECT_TRUE(document().unsaved());
}

// Saving is no step to undo, but a step undone after it compares with the file as saved: the
// state before the save differs from the file now, and reads as unsaved.
TEST_F(ExplorerTest, UndoPastASaveShowsUnsavedEdits) {
  const fs::path written = save_h900_as_the_users();
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  frame();
  press('S', true);
  ASSERT_EQ(load_preset(written).parameters.hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
  press('Z', true);
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  EXPECT_TRUE(document().unsaved()) << "the file holds 950 mm";
  EXPECT_NE(frame().find("Parameters *"), std::string::npos) << last_text_;
  press('Y', true);
  EXPECT_EQ(shown().hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());
}

// Two presets of one name in the list cannot be told apart: a shipped preset's name is refused
// and the dialog stays open with the name typed.
TEST_F(ExplorerTest, SaveAsRefusesTheNameOfAShippedPreset) {
  ASSERT_EQ(explorer_->set_input("h", 900.0), std::nullopt);
  frame();
  press('S', true);
  ASSERT_EQ(status().modal_title(), "Save as");
  press('A', true);
  ImGui::GetIO().AddInputCharactersUTF8("cotton POPLIN");
  frame();
  click("Save");
  EXPECT_EQ(status().modal_title(), "Save as");
  EXPECT_EQ(status().message(),
            "\"cotton POPLIN\" is the name of a shipped preset; give yours another name.");
  EXPECT_FALSE(fs::exists(dir_ / "user-presets"));
  frame();
  ImGui::GetIO().AddInputCharactersUTF8(" 2");
  frame();
  click("Save");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_TRUE(fs::exists(dir_ / "user-presets" / "cotton-poplin-2.json")) << last_text_;
}

// "Loaded Silk chiffon." coming and going moved the Presets panel's name field and buttons by a
// line or two, so that a click meant for the field loaded a preset. They stay where they are; the
// message shows at the panel's foot.
TEST_F(ExplorerTest, TheStatusLineNeverMovesThePresetsFieldOrButtons) {
  for (const ImVec2 size : {ImVec2(1280, 800), ImVec2(1024, 640), ImVec2(1920, 1080)}) {
    SCOPED_TRACE(size.x);
    show_at(size);
    const ImVec2 field = position_of("name of the ne");
    const ImVec2 save = position_of("Save as...");
    status().notify("Saved to /tmp/somewhere/rather/long/presets/chiffon-curtain-2-4m.json", false);
    frame();
    frame();
    EXPECT_TRUE(shows(last_text_, "chiffon-curtain")) << last_text_;
    EXPECT_EQ(position_of("name of the ne").y, field.y);
    EXPECT_EQ(position_of("Save as...").y, save.y);
    status().withdraw(status().message());
    frame();
    EXPECT_EQ(position_of("Save as...").y, save.y);
  }
}

// Several inputs in one edit are one undo step.
TEST_F(ExplorerTest, OneEditOfSeveralInputsIsOneUndoStep) {
  const Parameters before = shown();
  ASSERT_EQ(document().apply(Edit::inputs({{"h", 900.0}, {"d", 120.0}})), std::nullopt);
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  EXPECT_EQ(shown().hanging.support_displacement_mm, 120.0);
  EXPECT_EQ(document().undo_depth(), 1u);
  ASSERT_TRUE(document().undo());
  EXPECT_TRUE(shown() == before);
}

// B pinned from the user's preset, A edited, Ctrl+S: saving over the file B came from asks first
// (Cancel keeps the file); saved anyway, a swap makes A the fabric B was, which its file no longer
// holds: it reads as unsaved.
TEST_F(ExplorerTest, ASaveOverThePinnedFabricsFileAsksAndASwapComparesWithTheFileNow) {
  const fs::path written = save_h900_as_the_users();
  click("Pin as B");
  ASSERT_TRUE(document().compare().pinned());
  ASSERT_EQ(explorer_->set_input("h", 950.0), std::nullopt);
  frame();
  press('S', true);
  EXPECT_EQ(status().modal_title(), PresetsPanel::kPinnedFileModal);
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 900.0) << "nothing written yet";
  click("Cancel");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 900.0);
  EXPECT_TRUE(document().unsaved());

  press('S', true);
  ASSERT_EQ(status().modal_title(), PresetsPanel::kPinnedFileModal);
  click("Save over it");
  EXPECT_EQ(status().modal_title(), "");
  EXPECT_EQ(load_preset(written).parameters.hanging.height_mm, 950.0);
  EXPECT_FALSE(document().unsaved());

  click("Swap A and B");
  EXPECT_EQ(shown().hanging.height_mm, 900.0);
  EXPECT_EQ(document().loaded_path(), written.string());
  EXPECT_TRUE(document().unsaved()) << "the file holds 950 mm, A shows 900 mm";
  EXPECT_NE(frame().find("Parameters *"), std::string::npos) << last_text_;
}

}  // namespace
}  // namespace foldlab::gui
