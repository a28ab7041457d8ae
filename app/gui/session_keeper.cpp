#include "app/gui/session_keeper.hpp"

#include <exception>
#include <optional>
#include <string>
#include <system_error>

#include "app/gui/session.hpp"

namespace foldlab::gui {

void SessionKeeper::read(bool restore) {
  if (file_.empty()) {
    return;
  }
  std::string error;
  bool may_save = true;
  std::optional<Session> s = load_session(file_, error, may_save);
  if (!restore) {
    s.reset();
    error.clear();
  }
  if (s) {
    if (s->fabric_restored) {
      document_.adopt(s->loaded, s->loaded_preset_path);
      document_.set_appearance(s->current.appearance, false);
      document_.apply(Edit::replace(s->current.parameters));
    }
    document_.set_grid_resolution(s->grid_resolution);
    if (s->compare) {
      document_.compare().pin(
          {*s->compare, s->compare_origin.value_or(*s->compare), s->compare_origin_path});
    }
    settings_.load(s->view);
    status_.notify("Restored the last session.", MessageKind::info);
    for (const std::string& notice : s->notices) {
      status_.add_notice(notice);
    }
  } else if (!error.empty()) {
    status_.add_notice(error);  // present but unusable: say why the defaults are shown
  }
  std::filesystem::path set_aside = file_;
  set_aside += ".unread";
  std::error_code set_aside_error;
  if (!may_save && owns_folder_ &&
      (std::filesystem::rename(file_, set_aside, set_aside_error), !set_aside_error)) {
    status_.add_notice("The session that did not read is kept as " + set_aside.string() +
                       "; a new session is saved in its place.");
  } else if (!may_save) {
    status_.add_notice("The session will not be saved over " + file_.string() +
                       ", which is not a session file the explorer can read; move it away to "
                       "have the session kept.");
    file_.clear();  // nothing is saved, and closing asks about unsaved edits
  }
}

void SessionKeeper::save_now() {
  if (file_.empty()) {
    return;
  }
  Session s;
  s.current = document_.loaded();
  s.current.parameters = document_.scene().parameters();  // the last valid state
  s.current.appearance = document_.appearance();
  s.loaded = document_.loaded();
  s.loaded_preset_path = document_.loaded_path();
  s.grid_resolution = document_.scene().grid_nx();
  if (document_.compare().pinned()) {
    s.compare = document_.compare().b();
    s.compare_origin = document_.compare().b_origin();
    s.compare_origin_path = document_.compare().b_origin_path();
  }
  settings_.save(s.view);
  save_session(file_, s);
  status_.session_saved();
}

void SessionKeeper::keep() {
  if (!status_.session_dirty()) {
    return;
  }
  try {
    save_now();
  } catch (const std::exception& e) {
    status_.notify(std::string("Could not save the session: ") + e.what(), MessageKind::error);
    status_.session_saved();
  }
}

void SessionKeeper::keep_when_idle(double now_s) {
  if (settings_.take_changed()) {
    status_.mark_session_dirty();
  }
  if (status_.session_dirty() && now_s - last_save_s_ > 1.0) {
    last_save_s_ = now_s;
    keep();
  }
}

}  // namespace foldlab::gui
