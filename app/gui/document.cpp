#include "app/gui/document.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/model/settings.hpp"

namespace foldlab::gui {

Document::Document(const Preset& initial, std::string initial_path)
    : loaded_(initial),
      loaded_path_(std::move(initial_path)),
      edited_(initial.parameters),
      scene_(initial.parameters) {
  commit();
}

void Document::commit() {
  issues_ = validate(edited_);
  if (issues_.empty() && !(edited_ == scene_.parameters())) {
    scene_.set_parameters(edited_);
    session_dirty = true;
  }
}

std::optional<std::string> Document::set_input(std::string_view key, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  if (auto error = apply_setting(edited_, key, text)) {
    return error;
  }
  commit();
  return std::nullopt;
}

void Document::reset_to_loaded() {
  edited_ = loaded_.parameters;
  commit();
}

void Document::load_preset_file(const std::filesystem::path& path) {
  try {
    Preset preset = load_preset(path);
    loaded_ = preset;
    loaded_path_ = path.string();
    edited_ = preset.parameters;
    commit();
    ++loads_;
    notify("Loaded " + preset.name + ".", false);
    session_dirty = true;
  } catch (const PresetError& e) {
    notify(std::string("Not loaded; the current state is kept.\n") + e.what(), true);
  }
}

void Document::adopt(const Preset& loaded, std::string path) {
  loaded_ = loaded;
  loaded_path_ = std::move(path);
  session_dirty = true;
}

bool Document::unsaved() const {
  return !(scene_.parameters() == loaded_.parameters);
}

void Document::notify(std::string message, bool is_error) {
  message_ = std::move(message);
  message_is_error_ = is_error;
}

void Document::add_notice(const std::string& notice) {
  if (std::find(notices_.begin(), notices_.end(), notice) == notices_.end()) {
    notices_.push_back(notice);
  }
}

}  // namespace foldlab::gui
