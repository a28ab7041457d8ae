#include "app/gui/compare.hpp"

#include <utility>

#include "app/gui/document.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/model/parameters.hpp"

namespace foldlab::gui {

Scene& Comparison::scene(int grid_nx) {
  if (scene_.grid_nx() != grid_nx) {
    scene_.set_grid_resolution(grid_nx, grid_nx);
  }
  return scene_;
}

const ModelStanding& Comparison::standing() {
  if (!standing_) {
    standing_ = model_standing(b_->parameters, b_->calibration);
  }
  return *standing_;
}

void Comparison::pin(Preset b) {
  scene_.set_parameters(b.parameters);
  b_ = std::move(b);
  standing_.reset();
  ++changes_;
}

void Comparison::clear() {
  b_.reset();
  standing_.reset();
  ++changes_;
}

void Comparison::name_a(std::string label, const Parameters& parameters) {
  a_label_ = std::move(label);
  a_label_parameters_ = parameters;
}

std::optional<std::string> Comparison::a_name_for(const Parameters& parameters) const {
  if (a_label_parameters_ && *a_label_parameters_ == parameters) {
    return a_label_;
  }
  return std::nullopt;
}

std::string fabric_label(const Document& document) {
  const Parameters& parameters = document.scene().parameters();
  if (std::optional<std::string> swapped = document.compare.a_name_for(parameters)) {
    return *swapped;
  }
  const std::string& name = document.loaded().name;
  return parameters == document.loaded().parameters ? name : name + " (edited)";
}

Preset current_fabric(const Document& document) {
  Preset fabric = document.loaded();
  fabric.name = fabric_label(document);
  fabric.parameters = document.scene().parameters();  // the last valid state
  return fabric;
}

void pin_as_b(Document& document) {
  Preset b = current_fabric(document);
  const std::string label = b.name;
  document.end_step();  // a drag still open is a step of its own
  document.compare.pin(std::move(b));
  document.end_step();
  document.session_dirty = true;
  document.notify("Pinned \"" + label + "\" as B; A keeps changing with the sliders.",
                  MessageKind::info);
}

void swap_a_and_b(Document& document) {
  if (!document.compare.pinned()) {
    return;
  }
  const Preset former_b = document.compare.b();
  const Preset former_a = current_fabric(document);
  document.end_step();
  // B first, so that the edit of A closes one undo step holding both changes.
  document.compare.pin(former_a);
  if (const std::optional<std::string> problem =
          document.apply(Edit::replace(former_b.parameters))) {
    document.compare.pin(former_b);
    document.notify("Not swapped: " + *problem, MessageKind::error);
    return;
  }
  document.compare.name_a(former_b.name, former_b.parameters);
  document.session_dirty = true;
  document.notify("Swapped: A is \"" + former_b.name + "\", B is \"" + former_a.name + "\".",
                  MessageKind::info);
}

void clear_b(Document& document) {
  if (!document.compare.pinned()) {
    return;
  }
  document.end_step();
  document.compare.clear();
  document.end_step();
  document.session_dirty = true;
  document.notify("Cleared B (Ctrl+Z brings it back).", MessageKind::info);
}

}  // namespace foldlab::gui
