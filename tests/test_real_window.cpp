// The explorer in a real X window, driven by xdotool as a person's mouse and keyboard would drive
// it: the events go through the X server and GLFW, not through the playback that --play uses.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "process.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using foldlab::testing::RunResult;
using nlohmann::json;

const std::string kExecutable = FOLDLAB_EXECUTABLE;
const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

bool have(const char* program) {
  return std::system(("command -v " + std::string(program) + " >/dev/null 2>&1").c_str()) == 0;
}

json read_json(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in);
}

std::string listing(const fs::path& folder) {
  std::string names = folder.string() + ":";
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    names += " " + entry.path().filename().string();
  }
  return names + "\n";
}

class RealWindowTest : public foldlab::testing::TempDirTest {
 protected:
  RealWindowTest() : TempDirTest("foldlab_real_window_") {}

  void SetUp() override {
    TempDirTest::SetUp();
    if (!have("xvfb-run") || !have("xdotool")) {
      GTEST_SKIP()
          << "xvfb-run or xdotool is not installed (scripts/install-deps.sh installs both)";
    }
    fs::copy_file(kPresetsDir / "default.json", fabric());
  }

  fs::path fabric() const { return dir_ / "fabric.json"; }
  fs::path config() const { return dir_ / "config"; }

  foldlab::testing::Environment environment() const {
    foldlab::testing::Environment env;
    env.set = {{"XDG_CONFIG_HOME", config().string()}, {"HOME", dir_.string()}};
    return env;
  }

  // The report of a few frames at this size: where the sliders' handles are. The window run
  // below lays out the same, as both start from the same preset with no saved layout.
  json locate(const std::string& size) {
    const RunResult r = foldlab::testing::run_process(
        "xvfb-run",
        {"-a", "-s", "-screen 0 1920x1080x24", kExecutable, "gui", "--fresh", "--size", size,
         "--preset", fabric().string(), "--frames", "3", "--report"},
        dir_, environment());
    EXPECT_EQ(r.exit_status, 0) << r.err;
    return json::parse(r.out);
  }

  // Opens the explorer in a window on a fresh X server, runs the xdotool commands of `actions`
  // (a shell fragment; $WID is the window), then asks it to close as a desktop would (SIGTERM,
  // or `signal`) and returns its --report.
  json run_window(const std::string& size, const std::string& actions,
                  const std::string& signal = "TERM") {
    const fs::path report = dir_ / "report.json";
    const fs::path errors = dir_ / "window-stderr.txt";
    const std::string script =
        "set -eu\n"
        "\"$0\" gui --size \"$1\" --preset \"$2\" --report > \"$3\" 2> \"$4\" &\n"
        "pid=$!\n"
        "WID=$(xdotool search --sync --onlyvisible --name '^FoldLab$' | head -n1)\n"
        // With no window manager nothing gives the window the keyboard; a person's click would.
        "xdotool windowfocus --sync $WID\n"
        "sleep 2\n" +
        actions +
        "\nsleep 1.5\n"  // the session is kept a second after the last change
        "kill -" +
        signal +
        " $pid\n"
        "wait $pid\n";
    const RunResult r = foldlab::testing::run_process(
        "xvfb-run",
        {"-a", "-s", "-screen 0 1920x1080x24", "bash", "-c", script, kExecutable, size,
         fabric().string(), report.string(), errors.string()},
        dir_, environment());
    EXPECT_EQ(r.exit_status, 0) << r.err;
    std::ifstream err_in(errors);
    const std::string err((std::istreambuf_iterator<char>(err_in)), {});
    EXPECT_EQ(err.find("internal error"), std::string::npos) << err;
    return read_json(report);
  }
};

// A designer drags w's handle 40 px to the right, saves with Ctrl+S under a new name (a preset
// that is not the user's own is saved as a new one) and closes the window.
TEST_F(RealWindowTest, DesignerDragsWeightSavesAndClosesKeepingTheValue) {
  const json before = locate("1280x800");
  const double w0 = before.at("parameters").at("w_N_per_mm2").get<double>();
  const json handle = before.at("sliders").at("w").at("handle");
  const int x = static_cast<int>(std::lround(handle[0].get<double>()));
  const int y = static_cast<int>(std::lround(handle[1].get<double>()));
  const std::string drag = "xdotool mousemove --window $WID " + std::to_string(x) + " " +
                           std::to_string(y) +
                           "\nsleep 0.3\nxdotool mousedown 1\n"
                           "for i in 1 2 3 4 5 6 7 8; do xdotool mousemove_relative 5 0; sleep "
                           "0.05; done\nsleep 0.3\nxdotool mouseup 1\nsleep 0.5\n"
                           "xdotool key ctrl+s\nsleep 2\n"
                           "xdotool key ctrl+a\nsleep 0.5\nxdotool key BackSpace\nsleep "
                           "0.5\nxdotool type --delay 120 'Heavier poplin'\n"
                           "xdotool key Return\n";
  const json after = run_window("1280x800", drag);
  const double w1 = after.at("parameters").at("w_N_per_mm2").get<double>();
  // Heavier, by a drag's worth: the slider spans decades, 40 px is a fraction of one.
  EXPECT_GT(w1, w0 * 1.05);
  EXPECT_LT(w1, w0 * 10.0);
  EXPECT_TRUE(after.at("refused").is_null()) << after.at("refused");
  EXPECT_FALSE(after.at("dirty").get<bool>()) << after.dump();  // Ctrl+S saved it
  // What the window showed is what was written: the preset file and the session.
  const fs::path saved_file = config() / "foldlab" / "presets" / "heavier-poplin.json";
  ASSERT_TRUE(fs::exists(saved_file)) << listing(saved_file.parent_path()) << after.dump();
  EXPECT_EQ(read_json(saved_file).at("name"), "Heavier poplin");
  const double saved = read_json(saved_file).at("fabric").at("weight_N_per_mm2").get<double>();
  EXPECT_NEAR(saved, w1, 1e-9 * w1);
  const json session = read_json(config() / "foldlab" / "session.json");
  EXPECT_NEAR(session.at("current").at("fabric").at("weight_N_per_mm2").get<double>(), w1,
              1e-9 * w1);
}

// A teacher enlarges the text twice for the back row and the window is made small, as on a
// projector's 1024 x 640; the scale is remembered for the next lesson.
TEST_F(RealWindowTest, TeacherScalesTheTextAndResizesTheWindow) {
  const json after = run_window("1280x800",
                                "xdotool key ctrl+plus\nsleep 1\nxdotool key ctrl+plus\n"
                                "sleep 0.3\nxdotool windowsize --sync $WID 1024 640\nsleep 1\n");
  EXPECT_EQ(after.at("display"), json::array({1024.0, 640.0}));
  const json session = read_json(config() / "foldlab" / "session.json");
  EXPECT_EQ(session.at("view").at("scale"), 120) << session.dump();
}

// A window dragged down to nothing by hand (no window manager here keeps GLFW's minimum size)
// and back: the explorer goes on and lays out the full window again.
// The report is of the window as closed, even when a loaded machine has not yet drawn a frame at
// the full size.
TEST_F(RealWindowTest, AWindowSqueezedToOnePixelAndBackKeepsRunning) {
  const json after = run_window("1280x800",
                                "xdotool windowsize $WID 140 140\nsleep 1\n"
                                "xdotool windowsize $WID 1 1\nsleep 1\n"
                                "xdotool windowsize --sync $WID 1280 800\n");
  EXPECT_EQ(after.at("display"), json::array({1280.0, 800.0}));
  EXPECT_TRUE(after.at("layout").at("fills_window").get<bool>()) << after.dump();
}

// Closing the terminal the explorer was started from hangs it up (SIGHUP): the session is kept as
// when the desktop asks the window to close.
TEST_F(RealWindowTest, ClosingTheTerminalKeepsTheSession) {
  const json after = run_window("1280x800", "xdotool key ctrl+plus\nsleep 0.5\n", "HUP");
  const json session = read_json(config() / "foldlab" / "session.json");
  EXPECT_EQ(session.at("view").at("scale"), 110) << session.dump();
  EXPECT_EQ(after.at("appearance").at("scale_percent"), 110);
}

}  // namespace

// Three quick taps, faster than a frame (4 ms between key events; a frame takes tens): each is
// seen, as a person's quick presses of Ctrl+plus or Ctrl+Z must be, though ImGui reads keys once
// a frame. (With no delay at all xdotool itself drops some of the events.)
TEST_F(RealWindowTest, QuickTapsAreEachSeen) {
  const json after =
      run_window("1280x800", "xdotool key --delay 4 ctrl+plus ctrl+plus ctrl+plus\n");
  EXPECT_EQ(after.at("appearance").at("scale_percent"), 130) << after.dump();
}

// A teacher clicks h's slider and nudges it with the arrow key, through the X server: the report
// times each key from the window's key callback to the end of the frame that shows the new value
// (`latency`, docs/performance.md), and its parts never add up to more than the whole. The
// figures depend on the machine and its load; only their presence and sums are checked here.
TEST_F(RealWindowTest, ArrowKeysOnAFocusedSliderAreTimedToTheFrameThatShowsThem) {
  const json before = locate("1280x800");
  const json handle = before.at("sliders").at("h").at("handle");
  const int x = static_cast<int>(std::lround(handle[0].get<double>()));
  const int y = static_cast<int>(std::lround(handle[1].get<double>()));
  constexpr int kPresses = 5;
  const json after = run_window("1280x800", "xdotool mousemove --window $WID " + std::to_string(x) +
                                                " " + std::to_string(y) +
                                                " click 1\nsleep 0.5\n"
                                                "for i in 1 2 3 4 5; do xdotool key Right; "
                                                "sleep 0.3; done\n");
  // Five nudges of 1 % of the slider each: h went up.
  EXPECT_GT(after.at("parameters").at("h_mm").get<double>(),
            before.at("parameters").at("h_mm").get<double>());
  const json& latency = after.at("latency");
  ASSERT_TRUE(latency.is_object()) << after.dump();
  EXPECT_EQ(latency.at("keys").get<int>(), kPresses) << latency.dump();
  const json& last = latency.at("last");
  const double whole_ms = last.at("key_to_frame_ms").get<double>();
  EXPECT_GT(whole_ms, 0.0);
  double parts_ms = 0.0;
  for (const char* part :
       {"wait_ms", "input_ms", "ui_ms", "solve_ms", "mesh_ms", "cloth_ms", "draw_ms", "swap_ms"}) {
    const double ms = last.at(part).get<double>();
    EXPECT_GE(ms, 0.0) << part;
    parts_ms += ms;
  }
  // Each part is rounded to a microsecond in the report.
  EXPECT_LE(parts_ms, whole_ms + 0.01) << last.dump();
  EXPECT_GT(latency.at("key_to_frame_ms").at("median").get<double>(), 0.0);
  EXPECT_GE(latency.at("key_to_frame_ms").at("p90").get<double>(),
            latency.at("key_to_frame_ms").at("median").get<double>());
}

// A teacher opens "What am I looking at?", closes it with Escape and at once clicks "Pin as B",
// which lay under it: the click pins B. Read in the frame after the Escape's, ImGui gave it to the
// window just closed (the one the frame before drew under the pointer), and read in the
// Escape's own frame, to the introduction still open there; both lost it. The introduction is
// opened again at the end, which shows that the menu bar's item was where it was clicked.
TEST_F(RealWindowTest, TheFirstClickAfterEscapeClosesTheIntroductionIsNotLost) {
  const json before = locate("1280x800");
  const json results = before.at("layout").at("panels").at("results");
  // "Pin as B" is the first item in Results, under its title bar; the introduction is centred
  // over the window and covers it at this size.
  const int pin_x = static_cast<int>(std::lround(results.at("x").get<double>() + 20.0));
  const int pin_y = static_cast<int>(std::lround(results.at("y").get<double>() + 37.0));
  // The menu bar's "What am I looking at?" at 100 % text.
  const std::string open_intro = "xdotool mousemove --window $WID 262 10 click 1\nsleep 1\n";
  const json after =
      run_window("1280x800", open_intro + "xdotool key Escape mousemove --window $WID " +
                                 std::to_string(pin_x) + " " + std::to_string(pin_y) +
                                 " click 1\nsleep 1\n" + open_intro);
  EXPECT_FALSE(after.at("compare").is_null()) << "the click on Pin as B was lost";
  EXPECT_TRUE(after.at("intro_open").get<bool>()) << "the introduction was never opened";
}
