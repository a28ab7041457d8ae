#include "app/gui/gui_app.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <imgui.h>

#include "app/common/presets_dir.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/scripted_run.hpp"
#include "app/gui/session.hpp"
#include "app/gui/surface.hpp"

namespace foldlab::gui {
namespace {

// ImGui's context with the platform side of `surface`, for the lifetime of a run.
class ImGuiContextGuard {
 public:
  ImGuiContextGuard(Surface& surface, const std::string& ini_path)
      : surface_(surface), ini_path_(ini_path) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = ini_path_.empty() ? nullptr : ini_path_.c_str();
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    // Square, opaque panels whose backgrounds the renderer fills: ImGui draws none of its own.
    style.WindowRounding = 0.0f;
    style.Colors[ImGuiCol_WindowBg].w = 0.0f;
    surface_.init_imgui_platform();
  }
  ~ImGuiContextGuard() {
    surface_.shutdown_imgui_platform();
    ImGui::DestroyContext();
  }
  ImGuiContextGuard(const ImGuiContextGuard&) = delete;
  ImGuiContextGuard& operator=(const ImGuiContextGuard&) = delete;

 private:
  Surface& surface_;
  std::string ini_path_;
};

// --view KEY=VALUE settings, in order.
void apply_view_settings(Explorer& explorer, const std::vector<std::string>& settings) {
  for (const std::string& setting : settings) {
    const std::size_t eq = setting.find('=');
    const std::optional<std::string> problem =
        eq == std::string::npos ? std::optional<std::string>("'" + setting + "' is not KEY=VALUE")
                                : explorer.set_view(std::string_view(setting).substr(0, eq),
                                                    std::string_view(setting).substr(eq + 1));
    if (problem) {
      throw app::InputError("--view " + *problem);
    }
  }
}

// The frame loop, as plain as Dear ImGui's examples: poll, new frame, build, render, present.
void run_frames(Surface& surface, Renderer& renderer, Explorer& explorer, ScriptedRun& script,
                FrameTimes& times, const std::string& screenshot_path) {
  for (int frame = 0; surface.open() && script.wants_frame(frame, explorer); ++frame) {
    times.start();
    surface.new_frame();
    script.before_new_frame(explorer, frame);
    renderer.new_frame();
    ImGui::NewFrame();
    explorer.frame();
    ImGui::Render();
    surface.bind_framebuffer();
    renderer.render_draw_data(surface.framebuffer_size());
    take_screenshots(explorer, renderer, surface.framebuffer_size(), screenshot_path,
                     script.is_last(frame));
    surface.present();
    times.stop(surface);
  }
}

int run(Surface& surface, const GuiRunOptions& options, bool interactive) {
  const Preset preset = app::resolve_inputs(options.inputs);
  std::optional<AnimatedInput> animation;
  if (!options.animate_key.empty()) {
    animation.emplace(options.animate_key, preset.parameters);
  }
  bool persist = interactive && !options.fresh;
  std::string config_problem;
  if (persist) {
    // A config folder that is a plain file or cannot be created costs the session, not the start.
    std::error_code error;
    std::filesystem::create_directories(config_dir(), error);
    if (error) {
      persist = false;
      config_problem = "The config folder " + config_dir().string() + " cannot be used (" +
                       error.message() +
                       "); the session and window layout are not kept until what is there is "
                       "moved away.";
    }
  }
  ExplorerOptions explorer_options{app::find_presets_dir(), user_presets_dir(),
                                   persist ? config_dir() / "session.json" : "",
                                   options.analysis_tab};
  const std::filesystem::path ini_path = config_dir() / "imgui.ini";
  ImGuiContextGuard imgui(surface, persist ? ini_path.string() : "");
  const std::unique_ptr<Renderer> renderer = make_gl_renderer();
  // A preset named on the command line wins over the restored session.
  const bool restore =
      persist && options.inputs.preset_path.empty() && options.inputs.assignments.empty();
  Explorer explorer(preset, options.inputs.preset_path, restore, explorer_options, *renderer);
  if (!config_problem.empty()) {
    explorer.add_notice(config_problem);
  }
  if (persist) {
    if (const std::optional<std::string> too_large = oversized_file(ini_path, kMaxImguiIniBytes)) {
      // Loading settings from memory marks them loaded, so the first frame reads no file; the
      // default layout is saved over the oversized one on exit.
      ImGui::LoadIniSettingsFromMemory("", 0);
      explorer.add_notice("The window layout " + *too_large + "; using the default layout.");
    }
  }
  apply_view_settings(explorer, options.view_settings);

  ScriptedRun script(options.frames, std::move(animation));
  FrameTimes times(options.report);
  run_frames(surface, *renderer, explorer, script, times, options.screenshot_path);
  times.print_report(interactive ? "window" : "headless", options.animate_key, explorer);
  return app::kExitOk;
}

}  // namespace

int run_window(const GuiRunOptions& options) {
  SurfaceOptions surface_options{options.width, options.height, options.frames == 0};
  std::unique_ptr<Surface> surface = make_window_surface(surface_options);
  return run(*surface, options, true);
}

int run_headless(const GuiRunOptions& options) {
  SurfaceOptions surface_options{options.width, options.height, false};
  std::unique_ptr<Surface> surface = make_headless_surface(surface_options);
  return run(*surface, options, false);
}

}  // namespace foldlab::gui
