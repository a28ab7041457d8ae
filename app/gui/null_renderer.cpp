#include <cstdint>
#include <vector>

#include "app/gui/renderer.hpp"

namespace foldlab::gui {

void NullRenderer::draw_cloth(ImDrawList* draw_list, ImVec2 min, Scene& scene,
                              const OrbitCamera& camera, FrameSize size, const ClothStyle& style,
                              ClothSlot slot) {
  (void)draw_list;
  (void)min;
  const auto i = static_cast<std::size_t>(slot);
  RenderCounters& counters = counters_[i];
  ++counters.frames;
  if (view_cache_[i].reuse(scene, camera, size, style, counters)) {
    return;
  }
  const ClothBufferSources sources = cloth_buffer_sources(scene, camera, size, style);
  const ClothUploads uploads = upload_rule_[i].next(sources);
  if (uploads.mesh) {
    ++counters.mesh_uploads;
    counters.drawn_columns = sources.lattice.columns.size();
    counters.drawn_rows = sources.lattice.rows.size();
  }
  if (uploads.fold_lines) {
    ++counters.fold_line_uploads;
  }
}

void NullRenderer::update_image(int image, int width, int height, const std::uint32_t* rgba) {
  (void)image;
  (void)width;
  (void)height;
  (void)rgba;
  ++image_updates_;
}

void NullRenderer::fonts_changed() {
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0;
  int height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(1)));
}

ImTextureID NullRenderer::texture(int image) const {
  // Any non-null id: ImGui only passes it through to a backend, and there is none.
  return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(image + 1));
}

std::vector<std::uint8_t> NullRenderer::read_pixels(FrameSize size) {
  return std::vector<std::uint8_t>(
      static_cast<std::size_t>(size.width) * static_cast<std::size_t>(size.height) * 4, 0);
}

}  // namespace foldlab::gui
