// The OpenGL 3.3 renderer: ImGui's OpenGL3 backend for the draw data, ClothRenderer for the 3D
// view, fast_fill.hpp for opaque backgrounds and the view's copy, textures for images.
#include "app/gui/gl/gl_api.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/gui/gl/cloth_renderer.hpp"
#include "app/gui/gl/fast_fill.hpp"
#include "app/gui/gl/gl_handles.hpp"
#include "app/gui/gl/mipmapped_texture.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/surface.hpp"
#include "backends/imgui_impl_opengl3.h"

namespace foldlab::gui {
namespace {

class GlRenderer final : public Renderer {
 public:
  GlRenderer() { ImGui_ImplOpenGL3_Init(gl::kImGuiGlslVersion); }
  ~GlRenderer() override {
    textures_.clear();
    views_.clear();
    ImGui_ImplOpenGL3_Shutdown();
  }
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  void new_frame() override {
    // The backend creates the atlas's texture at its first frame; later atlases replace it.
    ImGui_ImplOpenGL3_NewFrame();
    if (fonts_changed_) {
      ImGui_ImplOpenGL3_DestroyFontsTexture();
      ImGui_ImplOpenGL3_CreateFontsTexture();
      fonts_changed_ = false;
    }
    begin_fast_fill_frame();
  }

  void fonts_changed() override { fonts_changed_ = true; }

  void fill_window_background() override { fill_current_window_background(); }

  ClothView create_cloth_view() override {
    views_.push_back(std::make_unique<View>());
    return static_cast<ClothView>(views_.size()) - 1;
  }

  void draw_cloth(ClothView id, ImDrawList* draw_list, ImVec2 min, const ClothBuffers& buffers,
                  const OrbitCamera& camera, FrameSize size, const ClothStyle& style) override {
    View& view = *views_.at(static_cast<std::size_t>(id));
    if (!view.cloth) {
      view.cloth = std::make_unique<ClothRenderer>();  // GL objects only once a view is drawn
    }
    ++view.counters.frames;
    if (!view.cache.reuse(buffers, camera, size, style, view.counters)) {
      const auto start = std::chrono::steady_clock::now();
      view.cloth->render(buffers, camera, size, style);
      cloth_render_ms_ +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
    }
    add_framebuffer_blit(
        draw_list, view.cloth->framebuffer(), size, min,
        ImVec2(min.x + static_cast<float>(size.width), min.y + static_cast<float>(size.height)));
  }

  // The uploads' counts of a view's cloth joined to its view counters.
  const RenderCounters& cloth_counters(ClothView id) const override {
    static const RenderCounters kNone;
    if (id == kNoClothView) {
      return kNone;
    }
    const View& view = *views_.at(static_cast<std::size_t>(id));
    RenderCounters& out = view.joined;
    out = view.cloth ? view.cloth->counters() : RenderCounters{};
    out.frames = view.counters.frames;
    out.view_renders = view.counters.view_renders;
    out.view_cache_hits = view.counters.view_cache_hits;
    return out;
  }

  double cloth_render_ms_total() const override { return cloth_render_ms_; }

  int create_image() override {
    textures_.push_back(GlTexture::make());
    sizes_.push_back({});
    return static_cast<int>(textures_.size()) - 1;
  }

  void update_image(int image, int width, int height, const std::uint32_t* rgba) override {
    const auto i = static_cast<std::size_t>(image);
    glBindTexture(GL_TEXTURE_2D, textures_[i].get());
    if (sizes_[i].width != width || sizes_[i].height != height) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      sizes_[i] = {width, height};
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  }

  void update_photo(int image, int width, int height, const std::uint32_t* rgba) override {
    const auto i = static_cast<std::size_t>(image);
    upload_mipmapped(textures_[i].get(), width, height, rgba, false);
    sizes_[i] = {width, height};
  }

  ImTextureID texture(int image) const override {
    return reinterpret_cast<ImTextureID>(
        static_cast<std::intptr_t>(textures_[static_cast<std::size_t>(image)].get()));
  }

  void render_draw_data(FrameSize size) override {
    glViewport(0, 0, size.width, size.height);
    // The theme's panel colour: what shows between and at the edges of the panels' own fills
    // (a dark frame round every panel of the light theme).
    const ImVec4 panel = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    glClearColor(panel.x, panel.y, panel.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  std::vector<std::uint8_t> read_pixels(FrameSize size) override {
    std::vector<std::uint8_t> pixels = read_framebuffer(size);
    // The picture is opaque whatever ImGui's blending left in the alpha channel.
    for (std::size_t i = 3; i < pixels.size(); i += 4) {
      pixels[i] = 255;
    }
    return pixels;
  }

  std::vector<std::uint8_t> render_picture(FrameSize size, ImVec4 clear,
                                           const std::function<void()>& build) override {
    GLint window_framebuffer = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &window_framebuffer);
    // The backend's objects belong to the picture's context; made and released with it.
    struct Backend {
      Backend() { ImGui_ImplOpenGL3_Init(gl::kImGuiGlslVersion); }
      ~Backend() { ImGui_ImplOpenGL3_Shutdown(); }
      Backend(const Backend&) = delete;
      Backend& operator=(const Backend&) = delete;
    } backend;
    // Two frames: ImGui sizes some items from the frame before.
    for (int frame = 0; frame < 2; ++frame) {
      ImGui_ImplOpenGL3_NewFrame();
      begin_fast_fill_frame();
      ImGui::NewFrame();
      build();
      ImGui::Render();
    }
    const OffscreenTarget target = make_offscreen_target(size.width, size.height);
    std::vector<std::uint8_t> pixels;
    if (target.complete) {
      glViewport(0, 0, size.width, size.height);
      glDisable(GL_SCISSOR_TEST);
      glClearColor(clear.x, clear.y, clear.z, clear.w);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      pixels = read_framebuffer(size);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(window_framebuffer));
    if (pixels.empty()) {
      throw SurfaceError("the GL cannot draw a " + std::to_string(size.width) + "x" +
                         std::to_string(size.height) + " picture");
    }
    return pixels;
  }

 private:
  // The bound framebuffer's pixels, top row first, as drawn (alpha included).
  static std::vector<std::uint8_t> read_framebuffer(FrameSize size) {
    const auto row_bytes = static_cast<std::size_t>(size.width) * 4;
    std::vector<std::uint8_t> pixels(row_bytes * static_cast<std::size_t>(size.height));
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.width, size.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    // GL's first row is the bottom one; images start at the top.
    std::vector<std::uint8_t> top_down(pixels.size());
    for (int y = 0; y < size.height; ++y) {
      std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(row_bytes * (size.height - 1 - y)),
                  row_bytes, top_down.begin() + static_cast<std::ptrdiff_t>(row_bytes * y));
    }
    return top_down;
  }

  struct View {
    std::unique_ptr<ClothRenderer> cloth;
    ClothViewCache cache;
    RenderCounters counters;  // frames, view_renders, view_cache_hits
    mutable RenderCounters joined;
  };
  // By ClothView; each view stays where it was made while more are added: the web build showed
  // a null function call in draw_cloth right after a second view moved the first one.
  std::vector<std::unique_ptr<View>> views_;
  bool fonts_changed_ = false;
  double cloth_render_ms_ = 0.0;
  std::vector<GlTexture> textures_;
  std::vector<FrameSize> sizes_;
};

}  // namespace

std::unique_ptr<Renderer> make_gl_renderer() {
  return std::make_unique<GlRenderer>();
}

}  // namespace foldlab::gui
