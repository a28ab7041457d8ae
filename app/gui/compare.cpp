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
    standing_ = model_standing(b_->fabric.parameters, b_->fabric.calibration, solution());
  }
  return *standing_;
}

void Comparison::pin(PinnedFabric b) {
  scene_.set_parameters(b.fabric.parameters);
  b_ = std::move(b);
  standing_.reset();
  ++changes_;
}

void Comparison::clear() {
  b_.reset();
  standing_.reset();
  ++changes_;
}

std::string fabric_label(const Document& document) {
  const Parameters& parameters = document.scene().parameters();
  const std::string& name = document.loaded().name;
  const bool same = parameters == document.loaded().parameters &&
                    document.appearance() == document.loaded().appearance;
  return same ? name : name + " (edited)";
}

Preset current_fabric(const Document& document) {
  Preset fabric = document.loaded();
  fabric.name = fabric_label(document);
  fabric.parameters = document.scene().parameters();  // the last valid state
  fabric.appearance = document.appearance();
  return fabric;
}

namespace {

PinnedFabric fabric_a(const Document& document) {
  return {current_fabric(document), document.loaded(), document.loaded_path(),
          document.dragged_keys()};
}

}  // namespace

void pin_as_b(Document& document, UiStatus& status) {
  PinnedFabric b = fabric_a(document);
  const std::string label = b.fabric.name;
  document.end_step();  // a drag still open is a step of its own
  document.compare().pin(std::move(b));
  document.end_step();
  status.mark_session_dirty();
  status.notify("Pinned \"" + label + "\" as B; A keeps changing with the sliders.",
                MessageKind::info);
}

void swap_a_and_b(Document& document, UiStatus& status) {
  if (!document.compare().pinned()) {
    return;
  }
  const PinnedFabric former_b = document.compare().pinned_fabric();
  const PinnedFabric former_a = fabric_a(document);
  document.end_step();
  // B first, so that the edit of A closes one undo step holding both changes.
  document.compare().pin(former_a);
  if (const std::optional<std::string> problem =
          document.take_fabric(former_b.origin, former_b.origin_path, former_b.fabric.parameters,
                               former_b.fabric.appearance)) {
    document.compare().pin(former_b);
    status.notify("Not swapped: " + *problem, MessageKind::error);
    return;
  }
  status.mark_session_dirty();
  status.notify(
      "Swapped: A is \"" + fabric_label(document) + "\", B is \"" + former_a.fabric.name + "\".",
      MessageKind::info);
}

void clear_b(Document& document, UiStatus& status) {
  if (!document.compare().pinned()) {
    return;
  }
  document.end_step();
  document.compare().clear();
  document.end_step();
  status.mark_session_dirty();
  status.notify("Cleared B (Ctrl+Z brings it back).", MessageKind::info);
}

}  // namespace foldlab::gui
