#include "app/gui/ui_status.hpp"

#include <algorithm>

namespace foldlab::gui {
namespace {

// Long enough to read twice; an error stays until the user has surely seen it.
double lifetime_s(MessageKind kind) {
  switch (kind) {
    case MessageKind::info:
    case MessageKind::success:
      return 8.0;
    case MessageKind::warning:
      return 15.0;
    case MessageKind::error:
      return 60.0;
  }
  return 8.0;
}

}  // namespace

void UiStatus::notify(std::string message, MessageKind kind) {
  message_ = std::move(message);
  message_kind_ = kind;
  message_time_s_ = now_s_;
}

const std::string& UiStatus::message() const {
  static const std::string none;
  return now_s_ - message_time_s_ > lifetime_s(message_kind_) ? none : message_;
}

const std::string& UiStatus::toast() const {
  static const std::string none;
  return now_s_ - toast_time_s_ > kToastLifetime_s ? none : toast_;
}

void UiStatus::add_notice(const std::string& notice) {
  if (std::find(notices_.begin(), notices_.end(), notice) == notices_.end()) {
    notices_.push_back(notice);
  }
}

}  // namespace foldlab::gui
