#include "app/gui/gui_app.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numeric>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/presets_dir.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/surface.hpp"
#include "backends/imgui_impl_opengl3.h"
#include "core/io/report.hpp"
#include "core/io/scene_report.hpp"

namespace foldlab::gui {
namespace {

// A scripted drag: the input moves back and forth across a typical range, one step a frame.
struct Sweep {
  const char* key;
  double lo;
  double hi;
  bool logarithmic;
};
constexpr Sweep kSweeps[] = {
    {"h", 900.0, 2350.0, false}, {"w", 5e-7, 5e-6, true},   {"E", 50.0, 500.0, true},
    {"t", 0.1, 0.5, true},       {"d", 20.0, 200.0, false}, {"L", 1000.0, 2000.0, false},
};

double sweep_value(const Sweep& sweep, int frame) {
  const double phase =
      std::abs(std::fmod(frame / 60.0, 2.0) - 1.0);  // 1 -> 0 -> 1, 60 frames a way
  return sweep.logarithmic ? sweep.lo * std::pow(sweep.hi / sweep.lo, 1.0 - phase)
                           : sweep.lo + (sweep.hi - sweep.lo) * (1.0 - phase);
}

struct ImGuiContextGuard {
  ImGuiContextGuard(Surface& surface, const std::string& ini_path) : surface_(surface) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    ini_path_ = ini_path;
    io.IniFilename = ini_path_.empty() ? nullptr : ini_path_.c_str();
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    // Square, opaque panels whose backgrounds fast_fill.hpp draws: ImGui draws none of its own.
    style.WindowRounding = 0.0f;
    style.Colors[ImGuiCol_WindowBg].w = 0.0f;
    surface_.init_imgui_platform();
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiContextGuard() {
    ImGui_ImplOpenGL3_Shutdown();
    surface_.shutdown_imgui_platform();
    ImGui::DestroyContext();
  }
  Surface& surface_;
  std::string ini_path_;
};

int run_frames(Surface& surface, const GuiRunOptions& options, bool interactive) {
  const Preset preset = app::resolve_inputs(options.inputs);
  const Sweep* sweep = nullptr;
  if (!options.animate_key.empty()) {
    for (const Sweep& s : kSweeps) {
      sweep = options.animate_key == s.key ? &s : sweep;
    }
    if (sweep == nullptr) {
      throw app::InputError("--animate " + options.animate_key + ": not one of h, w, E, t, d, L");
    }
  }
  const bool persist = interactive && !options.fresh;
  std::filesystem::create_directories(config_dir());
  ExplorerOptions explorer_options{app::find_presets_dir(), user_presets_dir(),
                                   persist ? config_dir() / "session.json" : "",
                                   options.analysis_tab};
  ImGuiContextGuard imgui(surface, persist ? (config_dir() / "imgui.ini").string() : "");
  // A preset named on the command line wins over the restored session.
  const bool restore =
      persist && options.inputs.preset_path.empty() && options.inputs.assignments.empty();
  Explorer explorer(preset, options.inputs.preset_path, restore, explorer_options);

  for (const std::string& setting : options.view_settings) {
    const std::size_t eq = setting.find('=');
    const std::optional<std::string> problem =
        eq == std::string::npos ? std::optional<std::string>("'" + setting + "' is not KEY=VALUE")
                                : explorer.set_view(std::string_view(setting).substr(0, eq),
                                                    std::string_view(setting).substr(eq + 1));
    if (problem) {
      throw app::InputError("--view " + *problem);
    }
  }
  std::vector<double> frame_ms;
  const int frames = options.frames;
  // A scripted run waits (up to 30 s) for background work before its last frame, so that the
  // picture shows a finished regime map.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  int extra_frames = 0;
  for (int frame = 0; (frames == 0 || frame < frames + extra_frames) && surface.open(); ++frame) {
    if (frames > 0 && frame + 1 == frames + extra_frames && explorer.busy() &&
        std::chrono::steady_clock::now() < deadline) {
      ++extra_frames;
    }
    const auto start = std::chrono::steady_clock::now();
    surface.new_frame();
    if (frames > 0) {
      // Scripted runs take no pointer input, so a stray cursor cannot change the picture.
      ImGuiIO& io = ImGui::GetIO();
      io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
      std::fill(std::begin(io.MouseDown), std::end(io.MouseDown), false);
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    if (sweep != nullptr) {
      explorer.set_input(sweep->key, sweep_value(*sweep, frame));
    }
    explorer.frame();
    ImGui::Render();
    const FrameSize size = surface.framebuffer_size();
    surface.bind_framebuffer();
    glViewport(0, 0, size.width, size.height);
    glClearColor(0.10f, 0.10f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    const bool last = frames > 0 && frame + 1 == frames + extra_frames;
    if (const std::optional<std::string> path = explorer.take_screenshot_request()) {
      surface.finish();
      try {
        write_png(path->c_str(), size, read_framebuffer_rgba(size));
        explorer.notify("Wrote " + std::filesystem::absolute(*path).string(), false);
      } catch (const SurfaceError& e) {
        explorer.notify(std::string("Not exported: ") + e.what(), true);
      }
    }
    if (last && !options.screenshot_path.empty()) {
      surface.finish();
      write_png(options.screenshot_path.c_str(), size, read_framebuffer_rgba(size));
    }
    surface.present();
    if (options.report) {
      surface.finish();
      frame_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
    }
  }
  if (options.report && !frame_ms.empty()) {
    std::vector<double> sorted = frame_ms;
    std::sort(sorted.begin(), sorted.end());
    const double mean =
        std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(sorted.size());
    const double p95 = sorted[std::min(
        sorted.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size())))];
    nlohmann::json report = {
        {"backend", interactive ? "window" : "headless"},
        {"frames", sorted.size()},
        {"mean_ms", mean},
        {"p95_ms", p95},
        {"max_ms", sorted.back()},
        {"grid", std::to_string(explorer.scene().grid_nx()) + "x" +
                     std::to_string(explorer.scene().grid_ny())},
        {"animate", options.animate_key},
        {"regime_map_ms", explorer.regime_map_ms()},
        {"stats", scene_stats_to_json(explorer.scene())},
        {"solution", solution_to_json(explorer.scene().solution(), explorer.scene().parameters())},
    };
    if (const RenderCounters* counters = explorer.renderer_counters()) {
      report["renderer"] = {{"mesh_uploads", counters->mesh_uploads},
                            {"fold_line_uploads", counters->fold_line_uploads},
                            {"frames", counters->frames}};
    }
    std::cout << report.dump(2) << "\n";
  }
  return app::kExitOk;
}

}  // namespace

int run_window(const GuiRunOptions& options) {
  SurfaceOptions surface_options{options.width, options.height, options.frames == 0};
  std::unique_ptr<Surface> surface = make_window_surface(surface_options);
  return run_frames(*surface, options, true);
}

int run_headless(const GuiRunOptions& options) {
  SurfaceOptions surface_options{options.width, options.height, false};
  std::unique_ptr<Surface> surface = make_headless_surface(surface_options);
  return run_frames(*surface, options, false);
}

}  // namespace foldlab::gui
