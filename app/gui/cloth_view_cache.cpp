#include "app/gui/renderer.hpp"

namespace foldlab::gui {

bool ClothViewCache::reuse(const ClothBuffers& buffers, const OrbitCamera& camera, FrameSize size,
                           const ClothStyle& style, RenderCounters& counters) {
  Key key{buffers.normals_version,
          buffers.fold_lines_version,
          buffers.grid_version,
          camera,
          size,
          style};
  if (drawn_ && *drawn_ == key) {
    ++counters.view_cache_hits;
    return true;
  }
  drawn_ = std::move(key);
  ++counters.view_renders;
  return false;
}

}  // namespace foldlab::gui
