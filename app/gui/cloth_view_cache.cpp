#include "app/gui/renderer.hpp"

namespace foldlab::gui {

bool ClothViewCache::reuse(Scene& scene, const OrbitCamera& camera, FrameSize size,
                           const ClothStyle& style, RenderCounters& counters) {
  scene.normals();
  if (style.fold_lines) {
    scene.fold_lines();
  }
  Key key{scene.version(Stage::normals),
          style.fold_lines ? scene.version(Stage::fold_lines) : 0,
          scene.version(Stage::grid),
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
