// The table of view settings: one row a setting, read by `--view`, the session and the report.
// The expected sentences and names are written out here as docs/cli.md states them.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "app/gui/session.hpp"
#include "app/gui/view_settings.hpp"

namespace foldlab::gui {
namespace {

enum class Print { plain, checks, stripes };
constexpr std::string_view kPrints[] = {"plain", "checks", "stripes"};

struct Members {
  bool wireframe = false;
  float z = 1.0f;
  Print print = Print::plain;
  int scripted_only_calls = 0;
};

void declare(ViewSettings& settings, Members& m) {
  settings.add_switch("wireframe", &m.wireframe, kEveryUse);
  settings.add_number("z_exaggeration", &m.z, ViewRange<float>{1.0f, 20.0f, " (times)"}, kEveryUse);
  settings.add_choice<Print>("print", &m.print, kPrints, kRemembered | kScripted);
  settings.add_action("sweep", [&m](std::string_view value) -> std::optional<std::string> {
    ++m.scripted_only_calls;
    if (value != "table1") {
      return "sweep = '" + std::string(value) + "' is not one of: table1";
    }
    return std::nullopt;
  });
}

TEST(ViewSettings, AScriptedValueIsTakenOrRefusedInTheRowsWords) {
  Members m;
  ViewSettings settings;
  declare(settings, m);
  EXPECT_EQ(settings.set("wireframe", "1"), std::nullopt);
  EXPECT_TRUE(m.wireframe);
  EXPECT_EQ(settings.set("wireframe", "yes"), "wireframe = 'yes' must be 0 or 1");
  EXPECT_EQ(settings.set("z_exaggeration", "8"), std::nullopt);
  EXPECT_EQ(m.z, 8.0f);
  // Refused, not moved to the nearest end: a typo shows rather than another picture.
  EXPECT_EQ(settings.set("z_exaggeration", "99"), "z_exaggeration = 99 must be in [1, 20] (times)");
  EXPECT_EQ(settings.set("z_exaggeration", "deep"), "z_exaggeration = 'deep' is not a number");
  EXPECT_EQ(m.z, 8.0f);
  EXPECT_EQ(settings.set("print", "checks"), std::nullopt);
  EXPECT_EQ(m.print, Print::checks);
  EXPECT_EQ(settings.set("print", "tartan"),
            "print = 'tartan' is not one of: plain, checks, stripes");
  EXPECT_EQ(settings.set("sweep", "table1"), std::nullopt);
  EXPECT_EQ(m.scripted_only_calls, 1);
}

TEST(ViewSettings, AnUnknownKeyIsRefusedNamingEveryScriptedKeyInTheOrderDeclared) {
  Members m;
  ViewSettings settings;
  declare(settings, m);
  EXPECT_EQ(settings.set("z", "4"),
            "unknown view key 'z' (known: wireframe, z_exaggeration, print, sweep)");
  bool remembered_only = false;
  settings.add_switch("automatic_layout", &remembered_only, kRemembered);
  EXPECT_FALSE(settings.knows("automatic_layout")) << "not a --view key";
}

TEST(ViewSettings, TheSessionKeepsTheRememberedRowsByTheirOneName) {
  Members m;
  ViewSettings settings;
  declare(settings, m);
  m.wireframe = true;
  m.z = 4.0f;
  m.print = Print::stripes;
  SessionSettings stored;
  settings.save(stored);
  EXPECT_EQ(stored.json(),
            (nlohmann::json{{"wireframe", true}, {"z_exaggeration", 4.0}, {"print", 2.0}}));
  Members fresh;
  ViewSettings reader;
  declare(reader, fresh);
  reader.load(stored);
  EXPECT_TRUE(fresh.wireframe);
  EXPECT_EQ(fresh.z, 4.0f);
  EXPECT_EQ(fresh.print, Print::stripes);
}

TEST(ViewSettings, AStoredValueOutsideItsRangeLeavesTheMemberAsItIs) {
  Members m;
  ViewSettings settings;
  declare(settings, m);
  SessionSettings stored;
  stored.set("z_exaggeration", 1e308);
  stored.set("print", 7.0);
  settings.load(stored);
  EXPECT_EQ(m.z, 1.0f);
  EXPECT_EQ(m.print, Print::plain);
}

TEST(ViewSettings, AChangeMadeByHandIsNoticedOnceHoweverItWasMade) {
  Members m;
  ViewSettings settings;
  declare(settings, m);
  EXPECT_TRUE(settings.take_changed()) << "the first look sees the members' values";
  EXPECT_FALSE(settings.take_changed());
  m.wireframe = true;  // as a checkbox writes it
  EXPECT_TRUE(settings.take_changed());
  EXPECT_FALSE(settings.take_changed());
}

TEST(ViewSettings, TheReportHoldsTheReportedRowsOnly) {
  Members m;
  ViewSettings settings;
  declare(settings, m);
  m.z = 3.0f;
  EXPECT_EQ(settings.report(), (nlohmann::json{{"wireframe", false}, {"z_exaggeration", 3.0}}));
}

}  // namespace
}  // namespace foldlab::gui
