// What the explorer tells the person and remembers about itself, apart from the fabric: the
// status line, the notices, which modal dialog is open, whether the session needs saving and
// whether the panels show the model's settings. The fabric, its edits and their undo history are
// the Document's (document.hpp); this is everything else the panels share.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace foldlab::gui {

// How a status message reads: its colour, and how long it stays.
enum class MessageKind { info, success, warning, error };

class UiStatus {
 public:
  // The status line. A message expires after a time that depends on its kind (errors stay
  // longest), counted from the time given to tick().
  void notify(std::string message, MessageKind kind);
  void notify(std::string message, bool is_error) {
    notify(std::move(message), is_error ? MessageKind::error : MessageKind::success);
  }
  // The current message, empty once expired.
  const std::string& message() const;
  // Takes `message` off the status line if it is the one shown (a later edit has answered it).
  void withdraw(const std::string& message) {
    if (message_ == message) {
      message_.clear();
    }
  }
  MessageKind message_kind() const { return message_kind_; }
  bool message_is_error() const { return message_kind_ == MessageKind::error; }
  // The frame's clock in seconds (ImGui::GetTime()).
  void tick(double now_s) { now_s_ = now_s; }

  // A line shown over the foot of the window for kToastLifetime_s, whatever the layout: what an
  // action with no panel of its own did (Copy link), where the status line, at the foot of the
  // Presets panel, may be out of sight.
  void toast(std::string text) {
    toast_ = std::move(text);
    toast_time_s_ = now_s_;
  }
  // The toast, empty once expired.
  const std::string& toast() const;
  static constexpr double kToastLifetime_s = 8.0;

  // Lines shown in the Presets panel until the explorer closes, and listed by `gui --report`:
  // config files that were not used, values brought into range. Repeats are kept once.
  void add_notice(const std::string& notice);
  const std::vector<std::string>& notices() const { return notices_; }

  // The title of the open modal dialog, empty when none: the dialog that has it open closes it
  // with set_modal(""), and no other window takes keys or clicks meanwhile.
  const std::string& modal_title() const { return modal_title_; }
  void set_modal(std::string title) { modal_title_ = std::move(title); }
  static constexpr const char* kUnsavedModal = "Unsaved changes";

  // Set by every accepted change and every remembered choice; the explorer saves the session
  // and then calls session_saved().
  bool session_dirty() const { return session_dirty_; }
  void mark_session_dirty() { session_dirty_ = true; }
  void session_saved() { session_dirty_ = false; }

  // Whether the panels show the model's settings as well as the cloth; remembered in the session.
  // A first start shows the cloth alone, for a designer who has not met eq. 7.
  bool expert_mode() const { return expert_mode_; }
  void set_expert_mode(bool on) {
    session_dirty_ = session_dirty_ || on != expert_mode_;
    expert_mode_ = on;
  }

 private:
  std::string message_;
  MessageKind message_kind_ = MessageKind::info;
  double now_s_ = 0.0;
  double message_time_s_ = 0.0;
  std::string toast_;
  double toast_time_s_ = 0.0;
  std::vector<std::string> notices_;
  std::string modal_title_;
  bool session_dirty_ = false;
  bool expert_mode_ = false;
};

}  // namespace foldlab::gui
