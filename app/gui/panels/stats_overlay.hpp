// "pipeline stats": a small overlay in the bottom-right corner with the scene's stage counters,
// the renderer's uploads and the frame time.
#pragma once

#include "app/gui/renderer.hpp"
#include "core/geometry/scene.hpp"

namespace foldlab::gui {

// Draws the overlay while `open`; its close button clears `open`.
void stats_overlay(bool& open, const Scene& scene, const RenderCounters& counters);

}  // namespace foldlab::gui
