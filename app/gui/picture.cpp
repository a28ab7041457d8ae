#include "app/gui/picture.hpp"

#include "app/gui/panels/analysis_panel.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <imgui.h>

#include "app/gui/appearance.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/field_panel.hpp"
#include "app/gui/panels/fold_plot_panel.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/surface.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

// An ImGui context for one picture, current while it lives: display size `size`, no input, its
// own fonts at the picture's text size and the theme the background asks for. The window's
// context is current again afterwards.
class PictureContext {
 public:
  PictureContext(FrameSize size, const std::filesystem::path& font_file, bool light_theme)
      : outer_(ImGui::GetCurrentContext()) {
    const float scale = picture_text_px(size) / kUiFontPx;
    add_ui_font(atlas_, font_file, scale);
    atlas_.Build();
    context_ = ImGui::CreateContext(&atlas_);
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.BackendPlatformName = "foldlab_picture";
    io.DisplaySize = ImVec2(static_cast<float>(size.width), static_cast<float>(size.height));
    io.DeltaTime = 1.0f / 60.0f;
    ImGuiStyle style = theme_style(light_theme);
    style.ScaleAllSizes(scale);
    // The plot's data area shows the picture's background.
    style.Colors[ImGuiCol_FrameBg] = ImVec4(0, 0, 0, 0);
    ImGui::GetStyle() = style;
  }
  ~PictureContext() {
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(outer_);
  }
  PictureContext(const PictureContext&) = delete;
  PictureContext& operator=(const PictureContext&) = delete;

 private:
  ImGuiContext* outer_;
  ImFontAtlas atlas_;  // outlives the context, which borrows it
  ImGuiContext* context_ = nullptr;
};

ImVec4 background_colour(PictureBackground background) {
  switch (background) {
    case PictureBackground::white:
      return ImVec4(1, 1, 1, 1);
    case PictureBackground::transparent:
      return ImVec4(0, 0, 0, 0);
    case PictureBackground::dark:
      break;
  }
  const Eigen::Vector3f& dark = ClothStyle{}.background;
  return ImVec4(dark.x(), dark.y(), dark.z(), 1.0f);
}

// The camera as the 3D view first frames the cloth; further back in a picture taller than wide,
// whose narrower width would cut the cloth.
OrbitCamera framed_camera(Scene& scene, FrameSize size) {
  Eigen::Vector3f centre;
  float radius_mm = 1.0f;
  cloth_bounds(scene, centre, radius_mm);
  OrbitCamera camera;
  camera.frame(centre, radius_mm);
  const float aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
  camera.distance_mm /= std::min(aspect, 1.0f);
  return camera;
}

// The same for A and B side by side: one camera that frames both cloths, so that they are seen
// at one scale.
OrbitCamera framed_camera(Scene& a, Scene& b, FrameSize size) {
  Eigen::Vector3f centre;
  float radius_mm = 1.0f;
  cloth_bounds(a, centre, radius_mm);
  Eigen::Vector3f b_centre;
  float b_radius_mm = 1.0f;
  cloth_bounds(b, b_centre, b_radius_mm);
  enclose(centre, radius_mm, b_centre, b_radius_mm);
  OrbitCamera camera;
  camera.frame(centre, radius_mm);
  const float aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
  camera.distance_mm /= std::min(aspect, 1.0f);
  return camera;
}

// The 3D view's style for a picture: its background, and lines as wide as the picture's text
// asks.
ClothStyle picture_style(const PictureSource& source, const PictureSpec& spec) {
  ClothStyle style = source.style;
  const ImVec4 background = background_colour(spec.background);
  style.background = Eigen::Vector3f(background.x, background.y, background.z);
  style.background_alpha = background.w;
  style.line_width_px = picture_line_width_px(spec.size);
  return style;
}

// A and B, each in its half, named at its foot in the colours the plots give them.
void draw_compare(Renderer& renderer, const PictureSource& source, const PictureSpec& spec,
                  FrameSize area) {
  Document& document = source.document;
  Scene& a = document.scene();
  Scene& b = document.compare().scene(a.grid_nx());
  const ClothStyle style = in_fabric_colour(picture_style(source, spec), document.appearance());
  const ClothStyle b_style =
      in_fabric_colour(picture_style(source, spec), document.compare().b().appearance);
  const FrameSize a_size{std::max(16, area.width / 2), area.height};
  const FrameSize b_size{std::max(16, area.width - a_size.width), area.height};
  const OrbitCamera camera = source.camera ? *source.camera : framed_camera(a, b, a_size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 b_origin(static_cast<float>(a_size.width), 0.0f);
  renderer.draw_cloth(source.cloth_view, draw, ImVec2(0, 0), cloth_buffers(a, style), camera,
                      a_size, style);
  renderer.draw_cloth(source.compare_cloth_view, draw, b_origin, cloth_buffers(b, b_style), camera,
                      b_size, b_style);
  const float pad = std::round(0.6f * ImGui::GetFontSize());
  const auto name = [&](ImVec2 origin, FrameSize half, ImU32 colour, const std::string& text) {
    const float wrap = static_cast<float>(half.width) - 2.0f * pad;
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const ImVec2 at(origin.x + pad, origin.y + static_cast<float>(half.height) - size.y - pad);
    // On a plate of the background: the ground's grid lines run under the names.
    const ImVec4 plate = background_colour(spec.background);
    if (plate.w > 0.0f) {
      draw->AddRectFilled(ImVec2(at.x - 0.3f * pad, at.y - 0.2f * pad),
                          ImVec2(at.x + size.x + 0.3f * pad, at.y + size.y + 0.2f * pad),
                          ImGui::GetColorU32(ImVec4(plate.x, plate.y, plate.z, 0.85f)));
    }
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, colour, text.c_str(), nullptr, wrap);
  };
  name(ImVec2(0, 0), a_size, kSweepCurve.u32(), "A: " + fabric_label(document));
  name(b_origin, b_size, kCompareB.u32(), "B: " + document.compare().b().name);
}

// The Sweep tab's keys and its three plots, stacked over the area.
void draw_sweep(const PictureSource& source, FrameSize area, float pad, SweepPlots& plots) {
  ImGui::SetCursorPos(ImVec2(pad, pad));
  const ImVec2 size(static_cast<float>(area.width) - 2.0f * pad,
                    static_cast<float>(area.height) - 2.0f * pad);
  ImGui::BeginChild(
      "sweep", size, false,
      ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoInputs);
  source.sweep->draw_keys(source.document);
  const float spacing = ImGui::GetStyle().ItemSpacing.y;
  const float height = std::max(4.0f * ImGui::GetFontSize(),
                                (ImGui::GetContentRegionAvail().y - 2.0f * spacing) / 3.0f);
  source.sweep->draw_plots(source.document, plots, height);
  ImGui::EndChild();
}

// The panel that offers `view`, when the source has the panels.
Panel* picture_panel(const PictureSource& source, PictureView view) {
  for (const std::unique_ptr<Panel>& panel : source.panels) {
    for (const PictureOffer& offer : panel->pictures()) {
      if (offer.view == view) {
        return panel.get();
      }
    }
  }
  return nullptr;
}

// Builds the picture's one window, every frame of it.
void build_picture(Renderer& renderer, const PictureSource& source, const PictureSpec& spec,
                   const std::vector<std::string>& caption, Plot& plot, FoldLineSeries& series,
                   SweepPlots& sweep_plots) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float pad = std::round(0.6f * ImGui::GetFontSize());
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(display);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin("picture", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoInputs);
  ImGui::PopStyleVar(2);
  // Broken at spaces only: ImGui's own wrapping would also break a number after its '.'.
  std::vector<std::string> lines;
  float caption_height = 0.0f;
  for (const std::string& line : caption) {
    lines.push_back(wrap_at_spaces(line, display.x - 2.0f * pad));
    caption_height += ImGui::CalcTextSize(lines.back().c_str()).y;
  }
  if (!caption.empty()) {
    caption_height +=
        2.0f * pad + static_cast<float>(caption.size() - 1) * ImGui::GetStyle().ItemSpacing.y;
  }
  const FrameSize area{spec.size.width,
                       std::max(16, spec.size.height - static_cast<int>(caption_height))};
  Scene& scene = source.document.scene();
  Panel* own = picture_panel(source, spec.view);
  ImGui::SetCursorPos(ImVec2(pad, pad));
  const ImVec2 inner(static_cast<float>(area.width) - 2.0f * pad,
                     static_cast<float>(area.height) - (caption.empty() ? 2.0f : 1.0f) * pad);
  if (own != nullptr &&
      own->draw_picture(spec.view, inner, source.document,
                        PictureStyle{ImGui::GetFontSize(), picture_line_width_px(spec.size),
                                     spec.legend, spec.background == PictureBackground::dark})) {
  } else if (spec.view == PictureView::cloth) {
    const ClothStyle style =
        in_fabric_colour(picture_style(source, spec), source.document.appearance());
    Scene& cloth = source.cloth_scene != nullptr ? *source.cloth_scene : scene;
    const OrbitCamera camera = source.camera ? *source.camera : framed_camera(cloth, area);
    renderer.draw_cloth(source.cloth_view, ImGui::GetWindowDrawList(), ImVec2(0, 0),
                        cloth_buffers(cloth, style), camera, area, style);
  } else if (spec.view == PictureView::compare) {
    draw_compare(renderer, source, spec, area);
  } else if (spec.view == PictureView::sweep) {
    draw_sweep(source, area, pad, sweep_plots);
  } else {
    if (plot.begin("fold lines", inner, kFoldPlotX, kFoldPlotY)) {
      plot.equal_scales();
      series.lines(plot, scene, false, spec.legend);
      series.outline_and_supports(plot, scene, spec.legend);
      plot.end();
    }
  }
  if (!caption.empty()) {
    ImGui::SetCursorPosY(static_cast<float>(area.height) + pad);
    for (const std::string& line : lines) {
      ImGui::SetCursorPosX(pad);
      ImGui::TextUnformatted(line.c_str());
    }
  }
  ImGui::End();
}

}  // namespace

std::optional<PictureBackground> parse_picture_background(std::string_view name) {
  if (name == "white") {
    return PictureBackground::white;
  }
  if (name == "transparent") {
    return PictureBackground::transparent;
  }
  if (name == "dark") {
    return PictureBackground::dark;
  }
  return std::nullopt;
}

std::optional<std::string> picture_size_problem(FrameSize size) {
  if (size.width < kMinFrameSize.width || size.width > kMaxFrameSize.width ||
      size.height < kMinFrameSize.height || size.height > kMaxFrameSize.height) {
    return std::to_string(size.width) + "x" + std::to_string(size.height) + " must be " +
           frame_size_rule();
  }
  if (std::int64_t{size.width} * size.height > kMaxPicturePixels) {
    return std::to_string(size.width) + "x" + std::to_string(size.height) +
           " is more pixels than a picture may have: 8192x4096 (33.5 megapixels)";
  }
  return std::nullopt;
}

TypedPictureSize read_typed_picture_size(std::string_view width, std::string_view height) {
  TypedPictureSize out;
  // nullopt unless digits alone; 10 digits and more are beyond any side, read as such.
  const auto side = [](std::string_view text) -> std::optional<std::int64_t> {
    if (text.empty() ||
        !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      return std::nullopt;
    }
    if (text.size() > 9) {
      return std::numeric_limits<std::int64_t>::max();
    }
    return std::stoll(std::string(text));
  };
  const auto check = [&](const char* name, std::string_view text, int lo, int hi) {
    const std::string range = "from " + std::to_string(lo) + " to " + std::to_string(hi);
    const std::optional<std::int64_t> value = side(text);
    if (!value) {
      out.problem += std::string(out.problem.empty() ? "" : " ") + "The " + name +
                     " must be a whole number of pixels " + range +
                     (text.empty() ? "." : ", not \"" + detail::cut(text) + "\".");
      return 0;
    }
    if (*value < lo || *value > hi) {
      out.problem += std::string(out.problem.empty() ? "" : " ") + "The " + name + " must be " +
                     range + " pixels, not " + detail::cut(text) + ".";
      return 0;
    }
    return static_cast<int>(*value);
  };
  const int w = check("width", width, kMinFrameSize.width, kMaxFrameSize.width);
  const int h = check("height", height, kMinFrameSize.height, kMaxFrameSize.height);
  if (!out.problem.empty()) {
    return out;
  }
  if (std::optional<std::string> why = picture_size_problem({w, h})) {
    out.problem = *why;
    return out;
  }
  out.size = FrameSize{w, h};
  return out;
}

std::optional<FrameSize> parse_picture_size(std::string_view text, std::string& problem) {
  const std::optional<FrameSize> size = parse_frame_size(text);
  if (!size) {
    problem = detail::cut(std::string(text)) + " must be " + frame_size_rule();
    return std::nullopt;
  }
  if (std::optional<std::string> why = picture_size_problem(*size)) {
    problem = *why;
    return std::nullopt;
  }
  return size;
}

float picture_text_px(FrameSize size) {
  // 47 px at 3000x2000, 25 px at 1920x1080; a wide strip of a picture goes by its height.
  const float side =
      std::min(static_cast<float>(size.width), 1.5f * static_cast<float>(size.height));
  return std::clamp(std::round(side / 64.0f), 15.0f, 200.0f);
}

float picture_line_width_px(FrameSize size) {
  return picture_text_px(size) / kUiFontPx;
}

namespace {

// One fabric's caption lines: its name (after `letter`, when given), a view's own `figures`, n,
// Q and z_max (after `numbers_label`, when given), then its inputs.
void add_caption(std::vector<std::string>& lines, const std::string& letter,
                 const std::string& name, const Parameters& parameters, const Solution& solution,
                 const ModelStanding& standing, std::string_view source_words = {},
                 const std::vector<std::string>& figures = {},
                 std::string_view numbers_label = {}) {
  const std::string shown = detail::caption_text(name);
  std::string head = letter.empty() ? shown : letter + ": " + shown;
  if (!head.empty()) {
    lines.push_back(head);
  }
  lines.insert(lines.end(), figures.begin(), figures.end());
  // The closed form's prediction ranges bracket its own values, not the field's.
  ModelStanding shown_standing = standing;
  if (!source_words.empty()) {
    shown_standing.range.reset();
  }
  std::string numbers =
      std::string(numbers_label) + headline(quantity_texts(solution, shown_standing));
  if (!source_words.empty()) {
    numbers += " (" + std::string(source_words) + ")";
  }
  lines.push_back(numbers);
  std::string inputs;
  // The cloth inputs, in the Parameters panel's order.
  for (const InputSpec* spec : cloth_inputs()) {
    const std::optional<double> value = spec->value(parameters);
    if (!value) {
      continue;
    }
    // A line too long wraps between inputs.
    inputs += (inputs.empty() ? "" : "     ") +
              unbroken(std::string(input_symbol(*spec)) + " = " + shown_text(*spec, *value));
  }
  lines.push_back(inputs);
}

}  // namespace

std::vector<std::string> picture_caption(Document& document, bool with_b, const Solution* drawn,
                                         std::string_view drawn_words) {
  Scene& scene = document.scene();
  const Preset& loaded = document.loaded();
  std::vector<std::string> lines;
  Comparison& compare = document.compare();
  with_b = with_b && compare.pinned();
  add_caption(lines, with_b ? "A" : "", with_b ? fabric_label(document) : loaded.name,
              scene.parameters(), drawn != nullptr ? *drawn : scene.solution(),
              model_standing(scene.parameters(), loaded.calibration, scene.solution()),
              drawn != nullptr ? drawn_words : std::string_view());
  if (with_b) {
    const Preset& b = compare.b();
    add_caption(lines, "B", b.name, b.parameters, compare.scene(scene.grid_nx()).solution(),
                compare.standing());
  }
  return lines;
}

std::vector<std::string> picture_caption(const PictureSource& source, const PictureSpec& spec) {
  if (!spec.caption) {
    return {};
  }
  // A view with figures of its own (the tension field's) gives them first, and the closed form's
  // after them, said to be the closed form's.
  if (const Panel* own = picture_panel(source, spec.view)) {
    const std::vector<std::string> figures = own->picture_figures(spec.view, source.document);
    if (!figures.empty()) {
      const auto* field_panel = dynamic_cast<const FieldPanel*>(own);
      Document& document = source.document;
      Scene& scene = document.scene();
      std::vector<std::string> lines;
      add_caption(
          lines, "", document.loaded().name, scene.parameters(), scene.solution(),
          model_standing(scene.parameters(), document.loaded().calibration, scene.solution()), {},
          figures, field_panel != nullptr ? field_panel->closed_form_words() : "");
      return lines;
    }
  }
  const bool with_b = spec.view == PictureView::compare || spec.view == PictureView::sweep;
  // A's cloth drawn with the field's folds is captioned with them.
  const Solution* drawn = spec.view == PictureView::cloth && source.cloth_scene != nullptr
                              ? &source.cloth_scene->solution()
                              : nullptr;
  return picture_caption(source.document, with_b, drawn, source.cloth_scene_words);
}

std::optional<std::string> picture_problem(const PictureSource& source, const PictureSpec& spec) {
  if (spec.view == PictureView::compare && !source.document.compare().pinned()) {
    return "a picture of A and B needs a fabric pinned as B (Compare > Pin as B)";
  }
  if (spec.view == PictureView::sweep) {
    if (source.sweep == nullptr) {
      return "a sweep picture needs the Sweep tab";
    }
    if (std::optional<std::string> problem = source.sweep->compute(source.document)) {
      return "the sweep's axis: " + *problem;
    }
  }
  if (const Panel* own = picture_panel(source, spec.view)) {
    if (std::optional<std::string> why =
            own->picture_unavailable(spec.view, source.document, false)) {
      return why;
    }
  }
  return std::nullopt;
}

std::vector<std::uint8_t> draw_picture(Renderer& renderer, const PictureSource& source,
                                       const PictureSpec& spec) {
  if (std::optional<std::string> problem = picture_size_problem(spec.size)) {
    throw SurfaceError("the picture's size " + *problem);
  }
  if (std::optional<std::string> problem = picture_problem(source, spec)) {
    throw SurfaceError(*problem);
  }
  const std::vector<std::string> caption = picture_caption(source, spec);
  const PictureContext context(spec.size, source.font_file,
                               spec.background != PictureBackground::dark);
  Plot plot;
  FoldLineSeries series;
  SweepPlots sweep_plots;
  return renderer.render_picture(spec.size, background_colour(spec.background), [&] {
    build_picture(renderer, source, spec, caption, plot, series, sweep_plots);
  });
}

PictureSource picture_source(Document& document, std::span<const std::unique_ptr<Panel>> panels,
                             ClothView cloth_view, ClothView compare_cloth_view,
                             const std::filesystem::path& font_file) {
  ClothViewPanel& cloth = find_panel<ClothViewPanel>(panels);
  return PictureSource{
      document,
      cloth.style(),
      cloth.camera_framed() ? std::optional<OrbitCamera>(cloth.camera()) : std::nullopt,
      cloth_view,
      font_file,
      &find_panel<AnalysisPanel>(panels).sweep(),
      compare_cloth_view,
      panels,
      cloth.drawn_field_scene(),
      cloth.drawn_folds_words()};
}

}  // namespace foldlab::gui
