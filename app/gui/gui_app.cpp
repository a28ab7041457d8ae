#include "app/gui/gui_app.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#endif
#include <imgui.h>
#include <imgui_internal.h>  // TempInputId: whether the typed field is a slider's value

#include "app/common/presets_dir.hpp"
#include "app/gui/background_job.hpp"
#include "app/gui/config_store.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/file_transfer.hpp"
#include "app/gui/frame_pacing.hpp"
#include "app/gui/input_player.hpp"
#include "app/gui/key_latency.hpp"
#include "app/gui/panels/analysis_panel.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/field_panel.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/scripted_run.hpp"
#include "app/gui/session.hpp"
#include "app/gui/surface.hpp"
#include "core/io/io.hpp"

namespace foldlab::gui {
namespace {

// ImGui's context with the platform side of `surface`, for the lifetime of a run. ImGui never
// touches imgui.ini itself (LayoutFile does): its fopen waits for ever on a FIFO and writes
// through a link to any file.
class ImGuiContextGuard {
 public:
  explicit ImGuiContextGuard(Surface& surface) : surface_(surface) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
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
};

// Whether `text` can be ImGui's settings: every line blank, a [Section][Name] header or a
// KEY=VALUE line. Someone's notes behind a link named imgui.ini are not, and are left alone.
bool looks_like_imgui_ini(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    end = end == std::string_view::npos ? text.size() : end;
    std::string_view line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
      line.remove_suffix(1);
    }
    if (!line.empty() && line.front() != '[' && line.find('=') == std::string_view::npos) {
      return false;
    }
    start = end + 1;
  }
  return true;
}

// The window layout, imgui.ini, under the session's rules: read only a regular file of the
// user's that reads as a layout, never saved over anything else, and replaced atomically when
// ImGui asks for a save and at exit.
class LayoutFile {
 public:
  LayoutFile(std::filesystem::path path, Explorer& explorer) : path_(std::move(path)) {
    ConfigFile file = read_config_file(path_, kMaxImguiIniBytes);
    if (file.text && !looks_like_imgui_ini(*file.text)) {
      file = ConfigFile{std::nullopt, path_.string() + " is not a window layout; not read", false};
    }
    if (!file.problem.empty()) {
      explorer.add_notice("The window layout " + file.problem + "; using the default layout.");
    }
    if (!file.may_save) {
      explorer.add_notice("The window layout will not be saved over " + path_.string() +
                          "; move it away to have the layout kept.");
    }
    may_save_ = file.may_save;
    if (file.text) {
      ImGui::LoadIniSettingsFromMemory(file.text->data(), file.text->size());
    }
  }
  // Before the ImGui context goes: the layout as the window is left.
  ~LayoutFile() { save(); }
  LayoutFile(const LayoutFile&) = delete;
  LayoutFile& operator=(const LayoutFile&) = delete;

  // After a frame: ImGui asks for a save a few seconds after a window moved or was resized.
  void save_when_asked() {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantSaveIniSettings) {
      io.WantSaveIniSettings = false;
      save();
    }
  }

  void save() noexcept {
    if (!may_save_) {
      return;
    }
    try {
      std::size_t size = 0;
      const char* text = ImGui::SaveIniSettingsToMemory(&size);
      write_file_atomically(path_, std::string_view(text, size));
    } catch (const std::exception&) {
      // The layout is a convenience: a read-only config folder must not stop the explorer.
    }
  }

  std::filesystem::path path_;
  bool may_save_ = true;
};

// KEY=VALUE view settings, in order; the problem of every one refused.
std::vector<std::string> view_problems(Explorer& explorer,
                                       const std::vector<std::string>& settings) {
  std::vector<std::string> problems;
  for (const std::string& setting : settings) {
    const std::size_t eq = setting.find('=');
    const std::optional<std::string> problem =
        eq == std::string::npos ? std::optional<std::string>("'" + setting + "' is not KEY=VALUE")
                                : explorer.set_view(std::string_view(setting).substr(0, eq),
                                                    std::string_view(setting).substr(eq + 1));
    if (problem) {
      problems.push_back(*problem);
    }
  }
  return problems;
}

// The link's view keys, then --view: every one refused is named by the option it came with, one
// a line. A forgiving link's own problems are `link_notes` instead (the page's link).
void apply_view_settings(Explorer& explorer, const GuiRunOptions& options,
                         std::vector<std::string>& link_notes) {
  std::string problems;
  for (const std::string& problem : view_problems(explorer, options.link_view_settings)) {
    if (options.inputs.forgiving_link) {
      link_notes.push_back(problem + ", so it is left out");
    } else {
      problems += (problems.empty() ? "--link " : "\n--link ") + problem;
    }
  }
  for (const std::string& problem : view_problems(explorer, options.view_settings)) {
    problems += (problems.empty() ? "--view " : "\n--view ") + problem;
  }
  if (!problems.empty()) {
    throw app::InputError(problems);
  }
}

// One notice for every piece of the link that was left out: each in a line of its own, in words
// that name the link rather than an option nobody typed.
std::string link_notice(const std::vector<std::string>& notes) {
  std::string notice;
  for (const std::string& note : notes) {
    notice += (notice.empty() ? "" : "\n") + std::string("The link's ") + note + ".";
  }
  return notice;
}

// SIGTERM, SIGINT and SIGHUP (a desktop's log-out, Ctrl+C in the terminal, the terminal the
// explorer was started from closed) close the window as its close button does, so that the
// session is kept and --report still prints.
volatile std::sig_atomic_t close_requested = 0;
void request_close(int) {
  close_requested = 1;
}

// After an input event ImGui needs a few frames to settle (FramesAfterInput, frame_pacing.hpp).
// While something is due after a while (the text cursor, a message fading, the session's delayed
// save) the sleep ends after a short timeout with one frame; otherwise only after a long one, a
// safety net for anything timed that the explorer does not know of, so that a window left alone
// costs almost nothing. The long sleep is taken in short slices that draw nothing, since GLFW
// resumes its wait after a signal: a close request is seen within one slice.
constexpr double kTimedWakeup_s = 0.5;
constexpr double kRestTimeout_s = 10.0;

// Sleeps until an input event, a close request or `timeout_s`; true when the time ran out.
bool sleep_until_input(Surface& surface, double timeout_s) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  for (;;) {
    const double asleep_s = std::chrono::duration<double>(Clock::now() - start).count();
    const double slice_s = std::min(kTimedWakeup_s, timeout_s - asleep_s);
    if (slice_s <= 0.1 * kTimedWakeup_s) {
      return true;
    }
    const Clock::time_point slice_start = Clock::now();
    surface.wait_events(slice_s);
    const std::chrono::duration<double> slept = Clock::now() - slice_start;
    if (slept.count() < 0.9 * slice_s || close_requested != 0) {
      return false;  // woken early: an event arrived
    }
  }
}

// One frame of the loop, as plain as Dear ImGui's examples: poll, new frame, build, render,
// present; a scripted run plugs in before the frame and after it is drawn. False when the script
// ended the run.
#ifdef __EMSCRIPTEN__
EM_JS(void, performance_mark, (const char* name),
      { performance.mark('foldlab: ' + UTF8ToString(name)); });
#endif

// A step of the page's start, as a mark the page bench reads ("foldlab: ..."): where a cold
// load's time goes. Nothing on the desktop.
void page_mark(const char* name) {
#ifdef __EMSCRIPTEN__
  performance_mark(name);
#else
  (void)name;
#endif
}

bool draw_frame(Surface& surface, Renderer& renderer, Explorer& explorer, ScriptedRun& script,
                FrameTimes& times, KeyLatency& latency, LayoutFile* layout, int frame,
                bool read_input = true) {
  using Clock = KeyLatency::Clock;
  times.start();
  latency.frame_started(Clock::now());
  if (read_input) {
    surface.new_frame();
  } else {
    surface.new_frame_without_input();
  }
  latency.input_read(Clock::now(), surface.key_presses_taken(), explorer.document().scene(),
                     renderer.cloth_render_ms_total());
  if (!script.before_frame(explorer, surface, frame)) {
    return false;
  }
  // Background work where there are no threads: a slice before the panels show its progress.
  run_job_slices();
  explorer.prepare_frame();
  renderer.new_frame();
  if (frame == 0) {
    page_mark("fonts and style ready");
  }
  ImGui::NewFrame();
  explorer.frame();
  ImGui::Render();
  if (frame == 0) {
    page_mark("panels built");
  }
  latency.built(Clock::now(), explorer.document().scene(), renderer.cloth_render_ms_total());
  if (layout != nullptr) {
    layout->save_when_asked();
  }
  const FrameSize size = surface.framebuffer_size();
  surface.bind_framebuffer();
  renderer.render_draw_data(size);
  if (frame == 0) {
    page_mark("panels drawn");
  }
  latency.drawn(Clock::now());
  write_requested_picture(explorer, renderer, size);
  script.after_render(explorer, renderer, size, frame);
  surface.present();
  times.stop(surface);
  latency.finished(Clock::now(), explorer.document().scene());
  return true;
}

// A script is checked before any window or context exists, so that a malformed one is reported
// as such wherever it runs.
std::optional<InputPlayer> read_script(const GuiRunOptions& options) {
  std::optional<InputPlayer> player;
  if (!options.play_path.empty()) {
    player.emplace(options.play_path);
  }
  return player;
}

// Everything a run of the explorer holds, from the first frame to the report: made once, then
// driven one frame at a time, by a loop that may sleep (the desktop) or by the browser's
// animation frames (the web build), which cannot block.
class ExplorerRun {
 public:
  ExplorerRun(Surface& surface, const GuiRunOptions& options, const app::StartInputs& start,
              bool interactive, std::optional<InputPlayer> player)
      : surface_(surface),
        options_(options),
        interactive_(interactive),
        persist_(interactive && !options.fresh),
        imgui_(surface),
        renderer_(make_gl_renderer()) {
    page_mark("renderer made");
    // Before the session, the layout or the user's presets are read.
    config_->restore(config_dir());
    const Preset& preset = start.preset;
    std::optional<AnimatedInput> animation;
    if (!options.animate_key.empty()) {
      animation.emplace(options.animate_key, preset.parameters);
    }
    std::string config_problem;
    if (persist_) {
      // A config folder that is a plain file or cannot be created costs the session, not the
      // start.
      std::error_code error;
      std::filesystem::create_directories(config_dir(), error);
      if (error) {
        persist_ = false;
        config_problem = "The config folder " + config_dir().string() + " cannot be used (" +
                         error.message() +
                         "); the session and window layout are not kept until what is there is "
                         "moved away.";
      }
    }
    const std::filesystem::path measurements = config_dir() / "measurements.csv";
    ExplorerOptions explorer_options{app::find_presets_dir(),
                                     user_presets_dir(),
                                     persist_ ? config_dir() / "session.json" : "",
                                     options.analysis_tab,
                                     kDejaVuSans,
                                     measurements,
                                     std::filesystem::current_path(),
                                     screen_preferences(),
                                     config_->owns_folder()};
    // A preset named on the command line wins over the restored session.
    const bool fabric_linked =
        !options.inputs.link.empty() || options.link_name || options.link_b_name;
    const bool restore = persist_ && options.inputs.preset_path.empty() &&
                         options.inputs.assignments.empty() && !fabric_linked;
    // A link's fabric is shown as an edit of its preset (the title's "*", A's "(edited)"): a
    // student who opens a shared link must not take it for the preset itself.
    const bool linked = !options.inputs.link.empty();
    // The link's name is A's, over the preset it is an edit of.
    Preset origin = linked ? start.origin : preset;
    if (options.link_name) {
      origin.name = *options.link_name;
    }
    // The file a preset's name stands for: Ctrl+S saves over it when it is the user's.
    explorer_.emplace(origin, start.preset_file, restore, explorer_options, *renderer_);
    explorer_->set_page_link(make_page_link());
    explorer_->set_file_transfer(make_file_transfer());
    if (linked || start.refused) {
      // A link's values, a refused one kept with its reason as a typed one is; the start, not an
      // edit to undo.
      explorer_->document().apply(
          Edit::replace(start.refused ? *start.refused : preset.parameters));
      explorer_->document().forget_history();
    }
    std::vector<std::string> link_notes = start.link_notes;
    pin_linked_b(options, start, link_notes);
    if (interactive) {
      // A background job that finishes while the window sleeps wakes it to show its result (the
      // regime map's last rows, a calibration's table). Thread-safe; the window outlives the
      // explorer, whose jobs end with it.
      explorer_->set_wake([] { glfwPostEmptyEvent(); });
    }
    if (!config_problem.empty()) {
      explorer_->add_notice(config_problem);
    }
    if (persist_) {
      layout_.emplace(config_dir() / "imgui.ini", *explorer_);
    }
    for (const std::string& notice : options.start_notices) {
      explorer_->add_notice(notice);
    }
    apply_view_settings(*explorer_, options, link_notes);
    if (!link_notes.empty()) {
      explorer_->add_notice(link_notice(link_notes));
    }

    if (interactive) {
      std::signal(SIGTERM, request_close);
      std::signal(SIGINT, request_close);
      std::signal(SIGHUP, request_close);
    }
    script_.emplace(options.frames, std::move(animation), std::move(player),
                    options.screenshot_path, options.input_files);
    page_mark("explorer made");
  }

  // The link's B, pinned beside A: the preset A's link starts from with B's inputs over it. A B
  // that cannot be read or is refused stops a command line's link and is a note in the page's.
  void pin_linked_b(const GuiRunOptions& options, const app::StartInputs& start,
                    std::vector<std::string>& link_notes) {
    if (!options.link_b_name && options.link_b.empty()) {
      return;
    }
    app::InputOptions b_inputs;
    b_inputs.preset_path = start.preset_file;
    b_inputs.assignments = options.link_b;
    b_inputs.set_option = "--link b.";
    b_inputs.whose = "B's ";
    app::InputOptions b_origin;
    b_origin.preset_path = start.preset_file;
    try {
      const Preset origin = app::resolve_inputs(b_origin);
      Preset fabric = app::resolve_inputs(b_inputs);
      fabric.name = options.link_b_name.value_or(origin.name + " (B)");
      explorer_->document().compare().pin(PinnedFabric{fabric, origin, start.preset_file});
      explorer_->document().forget_history();
    } catch (const app::InputError& e) {
      if (!options.inputs.forgiving_link) {
        throw;
      }
      link_notes.push_back(std::string("B could not be pinned (") + e.what() + ")");
    }
  }

  // What the run leaves (the session and the layout saved as they go) is stored as well.
  ~ExplorerRun() {
    script_.reset();
    layout_.reset();
    explorer_.reset();
    config_->keep(config_dir());  // nobody is left to be told of a refusal
  }
  ExplorerRun(const ExplorerRun&) = delete;
  ExplorerRun& operator=(const ExplorerRun&) = delete;

  // A frame is due unless the user's window rests: nothing animating, no panel busy, and the
  // frames after the last input drawn.
  bool may_rest() const {
    return script_->may_wait_for_input() && !explorer_->animating() && after_input_.settled();
  }
  // Woken by input (true) or by a timeout (false), after a rest.
  void woken(bool by_input) { after_input_.woken(by_input); }
  // How long a rest may last before one frame for what is due.
  double rest_timeout_s() const {
    return explorer_->awaits_time() ? kTimedWakeup_s : kRestTimeout_s;
  }

  // One frame; false once the run is over (the script ended, the user closed the window).
  bool frame() {
    if (explorer_->quit_confirmed() || !script_->wants_frame(frame_, *explorer_)) {
      return false;
    }
    if (!surface_.open() || close_requested != 0) {
      close_requested = 0;
      if (explorer_->may_quit()) {
        // The report describes the window as it was closed: a last frame takes what came just
        // before the close (a resize, on a machine too busy to have drawn it yet).
        if (options_.report) {
          draw_frame(surface_, *renderer_, *explorer_, *script_, times_, latency_,
                     layout_ ? &*layout_ : nullptr, frame_);
        }
        return false;
      }
      surface_.keep_open();  // the explorer asks first; its answer ends the loop or not
    }
    // The page's zoom or a move to another screen changes the ratio between frames.
    explorer_->appearance().set_pixel_ratio(screen_pixel_ratio());
    explorer_->appearance().set_coarse_pointer(screen_pointer_is_coarse());
    if (!draw_frame(surface_, *renderer_, *explorer_, *script_, times_, latency_,
                    layout_ ? &*layout_ : nullptr, frame_)) {
      return false;
    }
    after_input_.frame_drawn(frame_saw_input(ImGui::GetIO()));
    // A slider's typed value is ImGui's temporary input over the slider, and takes a number.
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    screen_wants_text_input(ImGui::GetIO().WantTextInput,
                            g.TempInputId != 0 && g.TempInputId == g.ActiveId);
    if (const std::optional<std::string> problem = config_->keep(config_dir())) {
      explorer_->add_notice(*problem);
    }
    ++frame_;
    // A frame that asked for another text size showed the old layout: the next is drawn at once,
    // before any more input is read, so that a click lands on what the screen shows.
    while (interactive_ && script_->may_wait_for_input() && explorer_->layout_pending()) {
      if (!draw_frame(surface_, *renderer_, *explorer_, *script_, times_, latency_,
                      layout_ ? &*layout_ : nullptr, frame_, false)) {
        return false;
      }
      ++frame_;
    }
    return true;
  }

  Explorer& explorer() { return *explorer_; }

  // The page is being left (closed, reloaded, or hidden where the browser may discard it):
  // what the delays would have kept a moment later is kept now.
  void keep_now() {
    explorer_->keep_session();
    if (layout_) {
      layout_->save();
    }
    config_->keep(config_dir());
  }

  // After the last frame: the report when asked for, and the exit status.
  int finish() {
    times_.print_report(interactive_ ? "window" : "headless", options_.animate_key, *explorer_,
                        latency_);
    return script_->exit_status();
  }

 private:
  Surface& surface_;
  GuiRunOptions options_;
  bool interactive_;
  bool persist_;
  std::unique_ptr<ConfigStore> config_ = make_config_store();
  ImGuiContextGuard imgui_;
  std::unique_ptr<Renderer> renderer_;
  std::optional<Explorer> explorer_;
  std::optional<LayoutFile> layout_;  // goes before the explorer and ImGui: it saves as it goes
  std::optional<ScriptedRun> script_;
  FrameTimes times_{options_.report};
  KeyLatency latency_;
  int frame_ = 0;
  FramesAfterInput after_input_;
};

int run(Surface& surface, const GuiRunOptions& options, const app::StartInputs& start,
        bool interactive, std::optional<InputPlayer> player) {
  ExplorerRun run(surface, options, start, interactive, std::move(player));
  for (;;) {
    if (run.may_rest()) {
      // A timeout brought no input: one frame for what is due, then sleep again.
      run.woken(!sleep_until_input(surface, run.rest_timeout_s()));
    }
    if (!run.frame()) {
      break;
    }
  }
  return run.finish();
}

#ifdef __EMSCRIPTEN__
// The browser build's loop: the page cannot block, so the browser calls web_frame at each
// animation frame, and a resting explorer draws nothing until an input event (seen by listeners
// on the page, which also see input meant for ImGui) or the rest's timeout.
EM_JS(int, take_input_seen, (), {
  if (!Module.foldlabInputListeners) {
    Module.foldlabInputListeners = true;
    [
      'pointerdown', 'pointermove', 'pointerup', 'wheel', 'keydown', 'keyup', 'touchstart',
      'touchmove', 'touchend', 'resize', 'focus', 'blur'
    ]
        .forEach(function(name) {
          window.addEventListener(
              name, function() { Module.foldlabInputSeen = true; }, true);
        });
  }
  const seen = Module.foldlabInputSeen ? 1 : 0;
  Module.foldlabInputSeen = false;
  return seen;
});

// The page is told when the run ends (a played script, --frames), with the exit status.
void tell_page_finished(int status) {
  EM_ASM(
      {
        if (Module.foldlabFinished)
          Module.foldlabFinished($0);
      },
      status);
}

struct WebRun {
  std::unique_ptr<Surface> surface;
  std::unique_ptr<ExplorerRun> run;
  double rest_start_s = 0.0;
  bool first_frame_marked = false;
};
// The page's one run, for the state the page asks for (below); null once it ended.
WebRun* running_page = nullptr;

// What `gui --report` prints, at any time: the page's Module.foldlabState() (a test that drives
// the page with real input events reads the explorer through it).
extern "C" EMSCRIPTEN_KEEPALIVE const char* foldlab_state_json() {
  static std::string text;
  text = running_page != nullptr && running_page->run
             ? explorer_state_json(running_page->run->explorer()).dump()
             : std::string("null");
  return text.c_str();
}

// Whether the explorer has drawn everything the input so far asked for and waits for more (the
// frames after the last input are drawn, nothing animates): a test that drives the page waits
// for this rather than for a time.
extern "C" EMSCRIPTEN_KEEPALIVE int foldlab_resting() {
  return running_page != nullptr && running_page->run && running_page->run->may_rest() ? 1 : 0;
}

// Called by the page when it is hidden or left: a tab closed within a second of a drag keeps it.
extern "C" EMSCRIPTEN_KEEPALIVE void foldlab_page_leaving() {
  if (running_page != nullptr && running_page->run) {
    running_page->run->keep_now();
  }
}

// pagehide alone is not enough: a phone may discard a hidden tab without one.
EM_JS(void, save_when_page_leaves, (), {
  window.addEventListener(
      'pagehide', function() { _foldlab_page_leaving(); });
  document.addEventListener(
      'visibilitychange', function() {
        if (document.visibilityState == 'hidden')
          _foldlab_page_leaving();
      });
});

// What the page's touch handling needs of the explorer, and the state hooks.
EM_JS(void, tell_page_screen, (double zoom_per_wheel_step), {
  Module.foldlabZoomPerWheelStep = zoom_per_wheel_step;
  Module.foldlabState = function() {
    return JSON.parse(UTF8ToString(_foldlab_state_json()));
  };
  // Input seen by the page but not yet by a frame wakes the explorer at its next frame.
  Module.foldlabResting = function() {
    return _foldlab_resting() != 0 && !Module.foldlabInputSeen;
  };
});

EM_JS(void, mark_first_frame, (), { performance.mark('foldlab: first frame'); });

void web_frame(void* argument) {
  auto& web = *static_cast<WebRun*>(argument);
  const double now_s = emscripten_get_now() / 1000.0;
  if (web.run->may_rest()) {
    const bool input = take_input_seen() != 0;
    if (!input && now_s - web.rest_start_s < web.run->rest_timeout_s()) {
      return;
    }
    web.run->woken(input);
  }
  web.rest_start_s = now_s;
  const int status = app::guarded([&] { return web.run->frame() ? -1 : web.run->finish(); });
  if (!web.first_frame_marked) {
    // The page bench reads the first frame's time from this mark, not from polling the state.
    mark_first_frame();
    web.first_frame_marked = true;
  }
  if (status >= 0) {
    emscripten_cancel_main_loop();
    web.run.reset();
    running_page = nullptr;
    tell_page_finished(status);
  }
}
#endif

}  // namespace

// The inputs and the script are checked before any window opens: a mistake in them is exit 2
// wherever the explorer runs, with or without a display.
int run_window(const GuiRunOptions& options) {
  std::optional<InputPlayer> player = read_script(options);
  const app::StartInputs start = app::resolve_start_inputs(options.inputs);
#ifdef __EMSCRIPTEN__
  // The page's canvas is the window; the browser paces the frames, so no swap interval.
  SurfaceOptions surface_options{options.width, options.height, false};
  // Lives as long as the page: the browser's loop calls into it after this returns.
  auto* web = new WebRun{make_window_surface(surface_options), nullptr};
  page_mark("window made");
  web->run = std::make_unique<ExplorerRun>(*web->surface, options, start, true, std::move(player));
  running_page = web;
  tell_page_screen(kZoomPerWheelStep);
  save_when_page_leaves();
  emscripten_set_main_loop_arg(web_frame, web, 0, false);
  if (options.frames > 0 || !options.play_path.empty()) {
    // A scripted run on timers rather than animation frames: as fast as it can, and driven by
    // `chromium --headless --virtual-time-budget`, whose clock does not send animation frames.
    emscripten_set_main_loop_timing(EM_TIMING_SETTIMEOUT, 0);
  }
  return app::kExitOk;
#else
  SurfaceOptions surface_options{options.width, options.height,
                                 options.frames == 0 && options.play_path.empty()};
  std::unique_ptr<Surface> surface = make_window_surface(surface_options);
  return run(*surface, options, start, true, std::move(player));
#endif
}

int run_headless(const GuiRunOptions& options) {
  std::optional<InputPlayer> player = read_script(options);
  const app::StartInputs start = app::resolve_start_inputs(options.inputs);
  SurfaceOptions surface_options{options.width, options.height, false};
  std::unique_ptr<Surface> surface = make_headless_surface(surface_options);
  return run(*surface, options, start, false, std::move(player));
}

int run_picture(const GuiRunOptions& options, const std::filesystem::path& out,
                const PictureSpec& spec, const PictureInputs& inputs) {
  // A picture shows a fabric the model accepts: a refused value, a link's too, is an error.
  // A sweep's inputs are judged along its range, as `foldlab sweep` judges them.
  app::StartInputs start = app::resolve_inputs_in_full(
      options.inputs, inputs.sweep_axis ? &*inputs.sweep_axis : nullptr);
  start.origin = start.preset;  // a picture's caption names the fabric it shows, link or not
  // A field picture's cut read as `foldlab field` reads it; a cut of one's own is the cloth the
  // closed form is solved for too, as `foldlab field` solves it, when it is hung as the closed
  // form's cloth is.
  std::optional<field::Outline> cut;
  std::string cut_name;
  std::optional<field::OutlineKind> cut_kind;
  bool closed_form_of_cut = false;
  if (inputs.field_cut.given()) {
    cut = app::read_field_cut(inputs.field_cut, start.preset, cut_name);
    if (inputs.field_cut.outline_path.empty()) {
      cut_kind.emplace();
      field::parse_outline_kind(cut_name, *cut_kind);
    } else if (const std::optional<Parameters> of_cut =
                   app::closed_form_of_cut(*cut, start.preset.parameters)) {
      start.preset.parameters = *of_cut;
      start.origin = start.preset;
      closed_form_of_cut = true;
    }
  }
  // The window is never drawn (the picture has a framebuffer of its own): the smallest one.
  SurfaceOptions surface_options{kMinFrameSize.width, kMinFrameSize.height, false};
  std::unique_ptr<Surface> surface = make_headless_surface(surface_options);
  ExplorerRun run(*surface, options, start, false, std::nullopt);
  Explorer& explorer = run.explorer();
  if (inputs.sweep_axis) {
    find_panel<AnalysisPanel>(explorer.panels()).sweep().set_axis(*inputs.sweep_axis);
  }
  if (inputs.b) {
    explorer.document().compare().pin(*inputs.b);
  }
  if (cut) {
    find_panel<FieldPanel>(explorer.panels())
        .use_picture_cut(std::move(*cut), cut_name, cut_kind, closed_form_of_cut);
  }
  // The 3D view's folds from the tension field are the folds it has drawn: a picture of it draws
  // the view until it has drawn them (one frame at rest, when the field converges), or until the
  // field has given up and the view says so.
  const ClothViewPanel& cloth = find_panel<ClothViewPanel>(explorer.panels());
  if (spec.view == PictureView::cloth && cloth.fold_source() == FoldSource::field) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (run.frame() && cloth.drawn_field_folds() == std::nullopt && explorer.busy() &&
           std::chrono::steady_clock::now() < deadline) {
    }
  }
  explorer.write_picture(out, spec);
  return app::kExitOk;
}

}  // namespace foldlab::gui
