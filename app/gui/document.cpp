#include "app/gui/document.hpp"

#include <algorithm>
#include <utility>

#include "core/io/link.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
Edit Edit::input(std::string key, double value) {
  return inputs({{std::move(key), value}});
}

Edit Edit::inputs(std::vector<std::pair<std::string, double>> values) {
  std::vector<Assignment> assignments;
  for (auto& [key, value] : values) {
    assignments.push_back({std::move(key), value});
  }
  return assign(std::move(assignments));
}

Edit Edit::choose(std::string key, std::string text) {
  return assign({{std::move(key), std::move(text)}});
}

Edit Edit::assign(std::vector<Assignment> assignments) {
  Edit e;
  e.kind = Kind::assign;
  e.assignments = std::move(assignments);
  return e;
}

Edit Edit::replace(Parameters parameters) {
  Edit e;
  e.kind = Kind::replace;
  e.parameters = std::move(parameters);
  return e;
}

Document::Document(const Preset& initial, std::string initial_path, UiStatus& status)
    : loaded_(initial),
      loaded_path_(std::move(initial_path)),
      edited_(initial.parameters),
      appearance_(initial.appearance),
      scene_(initial.parameters),
      status_(status) {
  commit();
  step_base_ = snapshot();
}

void Document::commit() {
  issues_ = validate(edited_);
  if (issues_.empty() && !(edited_ == scene_.parameters())) {
    scene_.set_parameters(edited_);
    status_.mark_session_dirty();
  }
}

std::optional<std::string> Document::apply(const Edit& edit) {
  Parameters next = edited_;
  switch (edit.kind) {
    case Edit::Kind::assign:
      for (const Assignment& a : edit.assignments) {
        if (const std::optional<InputRefusal> refusal = assign(next, a)) {
          return refusal_sentence(*refusal);
        }
      }
      break;
    case Edit::Kind::replace:
      next = edit.parameters;
      break;
  }
  if (edit.kind == Edit::Kind::replace) {
    dragged_keys_.clear();
  }
  for (const Assignment& a : edit.assignments) {
    // K and c are one stored value: whichever was set last says how it is written.
    const InputSpec* spec = find_input(a.key);
    if (a.key == "c" || (spec != nullptr && spec->kind == InputKind::stiffness_K)) {
      std::erase_if(dragged_keys_, [](const std::string& key) {
        const InputSpec* other = find_input(key);
        return key == "c" || (other != nullptr && other->kind == InputKind::stiffness_K);
      });
    }
    std::erase(dragged_keys_, a.key);
    if (edit.dragged) {
      dragged_keys_.push_back(a.key);
    }
  }
  edited_ = std::move(next);
  commit();
  if (edit.closes_step) {
    end_step();
  }
  return std::nullopt;
}

Parameters Document::edited_as_shown() const {
  return with_shown_digits(edited_, dragged_keys_);
}

void Document::set_appearance(const foldlab::Appearance& appearance, bool closes_step) {
  if (!(appearance == appearance_)) {
    appearance_ = appearance;
    status_.mark_session_dirty();
  }
  if (closes_step) {
    end_step();
  }
}

void Document::reset_to_loaded() {
  appearance_ = loaded_.appearance;
  apply(Edit::replace(loaded_.parameters));
}

void Document::load_preset_file(const std::filesystem::path& path) {
  try {
    Preset preset = load_preset(path);
    end_step();  // an edit still open is a step of its own, before the load
    loaded_ = preset;
    loaded_path_ = path.string();
    ++loads_;
    appearance_ = preset.appearance;
    apply(Edit::replace(preset.parameters));
    status_.notify("Loaded " + preset.name + ".", MessageKind::success);
    status_.mark_session_dirty();
  } catch (const PresetError& e) {
    status_.notify(std::string("Not loaded; the current state is kept.\n") + e.what(),
                   MessageKind::error);
    // The status line sits at the Presets panel's foot, below its list: a load that does nothing
    // visible says why where it is seen.
    status_.toast(std::string("Not loaded: ") + e.what());
  }
}

void Document::adopt(const Preset& loaded, std::string path) {
  loaded_ = loaded;
  loaded_path_ = std::move(path);
  status_.mark_session_dirty();
  // Saving is no edit to undo: the history goes on from the state as saved, and a step undone
  // or redone compares its edits with the file as it now is.
  const auto saved_over = [this](Snapshot& step) {
    if (step.loaded_path == loaded_path_) {
      step.loaded = loaded_;
    }
  };
  step_base_.loaded_path = loaded_path_;
  step_base_.loaded = loaded_;
  std::for_each(undo_.begin(), undo_.end(), saved_over);
  std::for_each(redo_.begin(), redo_.end(), saved_over);
}

std::optional<std::string> Document::take_fabric(const Preset& origin, std::string path,
                                                 const Parameters& parameters,
                                                 const foldlab::Appearance& appearance) {
  if (const std::vector<ValidationIssue> issues = validate(parameters); !issues.empty()) {
    return issues.front().message;
  }
  // The file as it is now, which a save since the fabric was pinned may have changed: the unsaved
  // marker compares with what the file holds, not with what it held then.
  Preset now = origin;
  if (!path.empty()) {
    try {
      now = load_preset(path);
    } catch (const PresetError&) {
      // Gone or unreadable: compared with the preset as pinned, as before.
    }
  }
  set_loaded(now, std::move(path));
  appearance_ = appearance;
  return apply(Edit::replace(parameters));
}

void Document::set_loaded(const Preset& origin, std::string path) {
  if (path != loaded_path_ || origin.name != loaded_.name) {
    ++loads_;
  }
  loaded_ = origin;
  loaded_path_ = std::move(path);
}

bool Document::unsaved() const {
  // A refused value on screen is an edit too: loading over it would drop what was typed.
  return !issues_.empty() || !(scene_.parameters() == loaded_.parameters) ||
         !(appearance_ == loaded_.appearance);
}

std::optional<std::string> Document::refusal() const {
  if (issues_.empty()) {
    return std::nullopt;
  }
  std::vector<std::string> messages;
  for (const ValidationIssue& issue : issues_) {
    messages.push_back(issue.message);
  }
  return detail::join_lines(messages);
}

Document::Snapshot Document::snapshot() const {
  return Snapshot{
      loaded_, loaded_path_, edited_, appearance_,
      compare_.pinned() ? std::optional<PinnedFabric>(compare_.pinned_fabric()) : std::nullopt};
}

namespace {

bool same_b(const std::optional<PinnedFabric>& a, const std::optional<PinnedFabric>& b) {
  return a.has_value() == b.has_value() &&
         (!a || (a->fabric.name == b->fabric.name && a->fabric.parameters == b->fabric.parameters &&
                 a->fabric.appearance == b->fabric.appearance && a->origin_path == b->origin_path &&
                 a->origin.name == b->origin.name && a->origin.parameters == b->origin.parameters));
}

}  // namespace

bool Document::same(const Snapshot& a, const Snapshot& b) {
  return a.edited == b.edited && a.appearance == b.appearance && a.loaded_path == b.loaded_path &&
         a.loaded.name == b.loaded.name && a.loaded.parameters == b.loaded.parameters &&
         a.loaded.appearance == b.loaded.appearance && a.loaded.outline == b.loaded.outline &&
         same_b(a.compare_b, b.compare_b);
}

void Document::restore(const Snapshot& s) {
  set_loaded(s.loaded, s.loaded_path);
  edited_ = s.edited;
  dragged_keys_.clear();  // written exactly: longer, never other than what the step held
  appearance_ = s.appearance;
  commit();
  if (!same_b(s.compare_b, snapshot().compare_b)) {
    if (s.compare_b) {
      compare_.pin(*s.compare_b);
    } else {
      compare_.clear();
    }
  }
  step_base_ = s;
  status_.mark_session_dirty();
}

void Document::end_step() {
  Snapshot now = snapshot();
  if (same(now, step_base_)) {
    return;
  }
  undo_.push_back(std::move(step_base_));
  redo_.clear();
  step_base_ = std::move(now);
}

bool Document::undo() {
  return step_through_history(undo_, redo_, "Undone.");
}

bool Document::redo() {
  return step_through_history(redo_, undo_, "Redone.");
}

// Undo and redo are the same move in opposite directions: the state now goes on one stack and
// the top of the other comes back.
bool Document::step_through_history(std::vector<Snapshot>& from, std::vector<Snapshot>& to,
                                    const char* message) {
  end_step();
  if (from.empty()) {
    return false;
  }
  to.push_back(snapshot());
  Snapshot back = std::move(from.back());
  from.pop_back();
  restore(back);
  status_.notify(message, MessageKind::info);
  return true;
}

void Document::forget_history() {
  undo_.clear();
  redo_.clear();
  step_base_ = snapshot();
}

void Document::replace_edits(std::string what, std::function<void(Document&)> replace) {
  end_step();
  if (!unsaved()) {
    replace(*this);
    return;
  }
  pending_what_ = std::move(what);
  pending_replace_ = std::move(replace);
  status_.set_modal(UiStatus::kUnsavedModal);
}

void Document::discard_and_replace() {
  status_.set_modal("");
  continue_replace();
}

void Document::cancel_replace() {
  status_.set_modal("");
  pending_what_.clear();
  pending_replace_ = nullptr;
}

void Document::continue_replace() {
  std::function<void(Document&)> replace = std::move(pending_replace_);
  pending_replace_ = nullptr;
  pending_what_.clear();
  if (replace) {
    replace(*this);
  }
}

}  // namespace foldlab::gui
