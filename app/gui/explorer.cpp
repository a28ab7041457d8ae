#include "app/gui/explorer.hpp"

#include <exception>
#include <utility>

#include <imgui.h>

#include "app/gui/panels/stats_overlay.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/session.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

Explorer::Explorer(const Preset& initial, const std::string& initial_path, bool restore_session,
                   ExplorerOptions options, Renderer& renderer)
    : options_(std::move(options)),
      renderer_(renderer),
      document_(initial, initial_path),
      presets_(options_.presets_dir, options_.user_presets_dir),
      analysis_(options_.presets_dir, options_.analysis_tab) {
  if (restore_session && !options_.session_file.empty()) {
    std::string error;
    if (std::optional<Session> s = load_session(options_.session_file, error)) {
      document_.adopt(s->loaded, s->loaded_preset_path);
      document_.edited() = s->current.parameters;
      document_.commit();
      document_.scene().set_grid_resolution(s->grid_resolution, s->grid_resolution);
      ClothStyle& style = cloth_view_.style();
      style.wireframe = s->wireframe;
      style.fold_lines = s->fold_lines_3d;
      style.ground = s->ground;
      session_message_ = "Restored the last session.";
      for (const std::string& notice : s->notices) {
        document_.add_notice(notice);
      }
    } else if (!error.empty()) {
      document_.add_notice(error);  // present but unusable: say why the defaults are shown
    }
  }
  for (const std::string& notice : presets_.notices()) {
    document_.add_notice(notice);
  }
  document_.session_dirty = false;
}

Explorer::~Explorer() {
  try {
    save_session_now();
  } catch (const std::exception&) {
    // Leaving must not fail because the config folder is read-only; the session is a convenience.
  }
}

std::optional<std::string> Explorer::set_input(std::string_view key, double value) {
  return document_.set_input(key, value);
}

std::optional<std::string> Explorer::set_view(std::string_view key, std::string_view value) {
  if (key == "sweep") {
    static const char* const names[] = {"table1", "table2", "fig4"};
    for (int which = 0; which < SweepPanel::kPaperCases; ++which) {
      if (value == names[which]) {
        analysis_.show_paper_case(which, document_);
        return std::nullopt;
      }
    }
    return "sweep = '" + detail::cut(value) + "' is not one of: table1, table2, fig4";
  }
  return cloth_view_.set_view(key, value);
}

void Explorer::save_session_now() {
  if (options_.session_file.empty()) {
    return;
  }
  Session s;
  s.current = document_.loaded();
  s.current.parameters = document_.scene().parameters();  // the last valid state
  s.loaded = document_.loaded();
  s.loaded_preset_path = document_.loaded_path();
  s.grid_resolution = document_.scene().grid_nx();
  s.wireframe = cloth_view_.style().wireframe;
  s.fold_lines_3d = cloth_view_.style().fold_lines;
  s.ground = cloth_view_.style().ground;
  save_session(options_.session_file, s);
  document_.session_dirty = false;
}

// Keeps the session on disk a second after the last change, so that a crash loses little.
void Explorer::save_session_when_idle() {
  const double now = ImGui::GetTime();
  if (document_.session_dirty && now - last_session_save_time_ > 1.0) {
    last_session_save_time_ = now;
    try {
      save_session_now();
    } catch (const std::exception& e) {
      session_message_ = std::string("Could not save the session: ") + e.what();
      document_.session_dirty = false;
    }
  }
}

void Explorer::frame() {
  parameters_.draw(document_, renderer_);
  presets_.draw(document_, renderer_, [this] {
    if (!session_message_.empty()) {
      ImGui::TextColored(kDimText, "%s", session_message_.c_str());
    }
    ImGui::Checkbox("pipeline stats", &show_stats_);
    ImGui::SameLine();
    calibration_.open_button(document_.scene().parameters());
    export_.draw(document_, cloth_view_.style());
  });
  fold_plot_.draw(document_, renderer_);
  cloth_view_.draw(document_, renderer_);
  results_.draw(document_, renderer_);
  analysis_.draw(document_, renderer_);
  if (calibration_.draw(document_.edited(), document_.loaded(), renderer_)) {
    document_.commit();  // the fitted constants, applied as a slider would
  }
  stats_overlay(show_stats_, document_.scene(), renderer_.counters());
  save_session_when_idle();
}

}  // namespace foldlab::gui
