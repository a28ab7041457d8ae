#include <cstdint>
#include <vector>

#include "app/gui/renderer.hpp"

namespace foldlab::gui {

ClothView NullRenderer::create_cloth_view() {
  views_.emplace_back();
  return static_cast<ClothView>(views_.size()) - 1;
}

void NullRenderer::draw_cloth(ClothView view, ImDrawList* draw_list, ImVec2 min,
                              const ClothBuffers& buffers, const OrbitCamera& camera,
                              FrameSize size, const ClothStyle& style) {
  (void)draw_list;
  (void)min;
  View& v = views_.at(static_cast<std::size_t>(view));
  ++v.counters.frames;
  if (v.cache.reuse(buffers, camera, size, style, v.counters)) {
    return;
  }
  const ClothBufferSources sources = cloth_buffer_sources(buffers, camera, size, style);
  const ClothUploads uploads = v.upload_rule.next(sources);
  if (uploads.mesh) {
    ++v.counters.mesh_uploads;
    v.counters.drawn_columns = sources.lattice.columns.size();
    v.counters.drawn_rows = sources.lattice.rows.size();
  }
  if (uploads.fold_lines) {
    ++v.counters.fold_line_uploads;
  }
}

const RenderCounters& NullRenderer::cloth_counters(ClothView view) const {
  static const RenderCounters kNone;
  return view == kNoClothView ? kNone : views_.at(static_cast<std::size_t>(view)).counters;
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

std::vector<std::uint8_t> NullRenderer::render_picture(FrameSize size, ImVec4,
                                                       const std::function<void()>& build) {
  ImGui::NewFrame();
  build();
  ImGui::Render();
  return read_pixels(size);
}

std::vector<std::uint8_t> NullRenderer::read_pixels(FrameSize size) {
  return std::vector<std::uint8_t>(
      static_cast<std::size_t>(size.width) * static_cast<std::size_t>(size.height) * 4, 0);
}

}  // namespace foldlab::gui
