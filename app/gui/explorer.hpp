// The explorer: every panel of the FoldLab window, drawn once per frame with Dear ImGui. The same
// frame code serves the GLFW window and the headless EGL renderer.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/analysis_panels.hpp"
#include "app/gui/calibration_panel.hpp"
#include "app/gui/camera.hpp"
#include "app/gui/cloth_renderer.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/session.hpp"
#include "core/geometry/scene.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

struct ExplorerOptions {
  std::filesystem::path presets_dir;       // shipped presets (may be empty)
  std::filesystem::path user_presets_dir;  // "Save as..." writes here
  std::filesystem::path session_file;      // empty: nothing is restored or saved
  std::string analysis_tab;                // "equations", "sweep" or "map": selected at start
};

class Explorer {
 public:
  // `initial` is shown unless a saved session is restored (only when no preset was asked for).
  Explorer(const Preset& initial, const std::string& initial_path, bool restore_session,
           ExplorerOptions options);
  ~Explorer();

  // Builds every window for this frame; between ImGui::NewFrame and ImGui::Render. May draw the
  // 3D view into its own framebuffer (GL calls), so a GL context must be current.
  void frame();

  // Sets one input by its --set key, exactly as moving its slider does (for scripted runs).
  std::optional<std::string> set_input(std::string_view key, double value);
  Scene& scene() { return scene_; }
  const Parameters& edited() const { return edited_; }
  const RenderCounters* renderer_counters() const;
  void save_session_now();
  // A view setting by name (print=checks, breeze=1, breeze_mm=80, time=1.5, z=8, wireframe=1,
  // fold_lines=0, ground=0): for scripted pictures. Returns the problem, if any.
  std::optional<std::string> set_view(std::string_view key, std::string_view value);
  // A PNG the user asked for with the Export buttons, taken by the frame loop after drawing.
  std::optional<std::string> take_screenshot_request();
  // Shows a line in the Presets panel (the outcome of an export done by the frame loop).
  void notify(const std::string& message, bool is_error);
  // True while background work (the regime map) is still filling in what the window shows.
  bool busy() const;
  // The last finished regime map's wall time in ms (0 before one finishes).
  double regime_map_ms() const { return regime_map_panel_.last_map_ms(); }

 private:
  void parameters_panel();
  void results_panel();
  void plot_panel();
  void view3d_panel();
  void presets_panel();
  void teaching_panel();
  void equations_tab();
  void stats_overlay();
  void export_section();
  PanelActions panel_actions();
  DeformedGrid current_frame_mesh();

  // A slider for one model input: unit, log scale where the range spans decades, typed values
  // (Ctrl+click) not clamped, and the validation message of its field beside it.
  void input_slider(const char* label, const char* field, double& value, double lo, double hi,
                    const char* format, bool logarithmic, const char* help);
  void show_issue(const char* field);
  void commit_edits();
  void load_preset_file(const std::filesystem::path& path);
  void save_as(const std::string& name, bool overwrite);
  void refresh_preset_list();
  bool unsaved() const;

  ExplorerOptions options_;
  Preset loaded_;  // as loaded: "reset" returns here, the unsaved marker compares
  std::string loaded_path_;
  Parameters edited_;  // what the widgets show, possibly invalid
  std::vector<ValidationIssue> issues_;
  Scene scene_;  // always holds the last valid parameters
  std::unique_ptr<ClothRenderer> renderer_;
  OrbitCamera camera_;
  bool camera_framed_ = false;
  bool camera_user_moved_ = false;
  bool breeze_playing_ = true;
  char export_stem_[256] = "foldlab-export";
  std::optional<std::string> screenshot_request_;
  std::uint64_t camera_solution_version_ = 0;
  ClothStyle style_;
  int grid_resolution_ = 128;
  bool show_stats_ = false;
  bool plot_autoscale_ = false;
  SweepPanel sweep_panel_;
  RegimeMapPanel regime_map_panel_;
  bool analysis_tab_selected_ = false;
  Plot fold_plot_;
  std::uint64_t plot_lines_version_ = ~std::uint64_t{0};
  std::vector<std::vector<double>> plot_xs_;
  std::vector<std::vector<double>> plot_ys_;
  std::uint64_t plot_outline_version_ = ~std::uint64_t{0};
  std::vector<double> outline_xs_;
  std::vector<double> outline_ys_;

  struct PresetEntry {
    std::string name;
    std::filesystem::path path;
    bool user = false;
  };
  std::vector<PresetEntry> presets_;
  std::string preset_message_;  // the last load/save error or confirmation, shown in the panel
  bool preset_message_is_error_ = false;
  char save_name_[128] = {};
  std::string pending_overwrite_;  // name waiting for the user's "overwrite?" answer
  std::string session_message_;
  CalibrationPanel calibration_panel_;  // "Fit to measurements", opened from the Presets panel

  // For the teaching panel: what n was before the last change, and why it moved.
  int previous_n_ = -1;
  int shown_n_ = -1;
  double previous_count_argument_ = 0.0;
  double last_session_save_time_ = 0.0;
  bool session_dirty_ = false;
};

}  // namespace foldlab::gui
