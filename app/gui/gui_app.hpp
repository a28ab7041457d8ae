// Running the explorer: in a window until closed, for a scripted number of frames (tests and
// frame-time measurements), or headless into a PNG.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/common/field_cut.hpp"
#include "app/common/inputs.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/picture.hpp"
#include "core/analysis/sweep.hpp"

namespace foldlab::gui {

struct GuiRunOptions {
  app::InputOptions inputs;
  int width = 1280;
  int height = 800;
  int frames = 0;               // 0: until the window is closed
  std::string screenshot_path;  // written after the last frame
  std::string animate_key;      // moves this input every frame, as a dragged slider would
  bool report = false;          // print frame times and pipeline counters as JSON
  bool fresh = false;           // neither restore nor save the session
  std::string play_path;        // input playback script (see InputPlayer)
  std::string analysis_tab;     // equations, sweep or map: the tab shown at start
  std::vector<std::string> view_settings;  // KEY=VALUE, see Explorer::set_view
  // The link's view keys (present, theme, scale), applied before view_settings: a problem in one
  // is named as the link's, and with inputs.forgiving_link is a notice rather than an error.
  std::vector<std::string> link_view_settings;
  // The link's fabric keys (core/io/link.hpp): A's name, and B's name and inputs (as --set takes
  // them, over A's preset) when the link pins a B.
  std::optional<std::string> link_name;
  std::optional<std::string> link_b_name;
  std::vector<std::string> link_b;
  // Said in the explorer from the start, as notices (the page's unknown ?preset=NAME).
  std::vector<std::string> start_notices;
  // The files the run reads (preset, script, swatches), which no picture may be written over.
  std::vector<app::NamedPath> input_files;
};

// The window. Returns an exit status (kExitOk, or kExitInternal when no window can be opened).
int run_window(const GuiRunOptions& options);
// No display, no X server: EGL surfaceless into an off-screen framebuffer, then a PNG.
int run_headless(const GuiRunOptions& options);
// What a picture shows besides A: the sweep's axis (none: the Sweep tab's, as --view sweep=...
// leaves it) and the fabric pinned as B.
struct PictureInputs {
  std::optional<SweepAxis> sweep_axis;
  std::optional<PinnedFabric> b;
  // A field picture's cut as `foldlab field` takes it (--shape, --outline), read against the
  // preset the picture resolves; none given: the field view's own.
  app::FieldCutOptions field_cut;
};
// The same with no window drawn at all: the explorer's picture `spec` (picture.hpp) into `out`,
// as the Export menu's picture dialog writes it.
int run_picture(const GuiRunOptions& options, const std::filesystem::path& out,
                const PictureSpec& spec, const PictureInputs& inputs = {});

}  // namespace foldlab::gui
