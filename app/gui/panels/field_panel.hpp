// "Tension field": the hung cloth as the relaxed membrane solves it (core/field): coloured by
// where it is taut, wrinkled or slack, or by its tension in N/mm, with the tension rays, the
// closed form's cosines on demand and the supports' reactions. A window of its own, opened from
// the View menu and presentable; it follows a drag on a coarser mesh, a slice of each frame, and
// refines when the hand rests. Closed, it solves nothing.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/gui/panel.hpp"
#include "app/gui/panels/view_toolbar.hpp"
#include "core/field/field_folds.hpp"
#include "core/field/live_field.hpp"
#include "core/geometry/geometry.hpp"

namespace foldlab::gui {

// How the field's triangles are coloured.
enum class FieldColouring { state, tension };
// The cut the field is solved on: the model's shape (cosine, rectangle, strip, inclined) or one of
// the paper's cuts that only the field solves.
enum class FieldCut { shape, triangle, pennant, wedge };

struct FieldDrawing {
  FieldColouring colouring = FieldColouring::state;
  bool rays = true;
  bool cosines = false;  // the closed form's fold lines over the field
  bool legend = true;
  bool stale = false;  // the inputs changed since: drawn faded, and said
  float text_px = 13.0f;
  float line_px = 1.0f;
  bool dark = true;  // over a dark background
  // The least extent fitted into the canvas, mm across and down: while an input moves, the largest
  // the cloth has had since it began, so that a cloth growing or shrinking is seen to, rather than
  // refitted to the same size every frame.
  Eigen::Vector2d least_extent_mm = Eigen::Vector2d::Zero();
};

// How a field was fitted into its canvas.
struct FieldFit {
  double px_per_mm = 0.0;
  Eigen::Vector2d extent_mm = Eigen::Vector2d::Zero();  // what was fitted: the cloth's or more
};

// The closed form's fold lines `cosines` (x from the middle between the outermost supports, y down
// from the line through them, as the scene lays them) where they hang on the field's cut from its
// pinned supports `targets`, mm: each line from support to support.
std::vector<std::vector<Eigen::Vector2d>> cosines_on_field(
    const FoldLines& cosines, const std::vector<Eigen::Vector2d>& targets);

// Draws `field` into `draw` within [origin, origin + size], millimetres alike across and down, y
// down; `cosines` are the closed form's fold lines (x from the middle between the supports, y down
// from their line), drawn over it when asked. Returns how it was fitted.
FieldFit draw_field(ImDrawList& draw, ImVec2 origin, ImVec2 size, const field::SolvedField& field,
                    const FoldLines* cosines, const FieldDrawing& style);

// The field's inputs for the model's parameters: the outline of their shape (or `cut`, or the
// preset's own cut `own_cut` when the cut is the shape's), their material and a mesh of `cells_x`
// across with as many cells down as keeps them square.
field::FieldInputs field_inputs(const Parameters& parameters, int cells_x,
                                FieldCut cut = FieldCut::shape,
                                const field::Outline* own_cut = nullptr);

// The folds read from the field as another view may take them (the 3D view's fold source, the
// Results' field column): the field's folds only when it has converged for the inputs shown now.
struct FieldFoldsNow {
  enum class State {
    not_solved,     // nobody asks for the field
    solving,        // the field of these inputs is still being solved
    not_converged,  // the solve gave up; `residual` says how far it got
    refused,        // the cut cannot be solved; `words` says why
    other_cut,      // the field view shows another cut than the cloth's and no view asks for
                    // the cloth's own
    converged,      // `folds` are the field's for the inputs shown now
  };
  State state = State::not_solved;
  const field::FieldFolds* folds = nullptr;
  // While solving: the folds of the last field that converged, which is of other inputs than
  // those shown (a view that draws them says so); null before the first.
  const field::FieldFolds* previous = nullptr;
  double residual = 0.0;
  std::string words;  // a short sentence for the views: why there are no folds from the field
};

// One cut's field as the explorer follows it, a slice of each frame: its live solve, the inputs
// asked for and those of the field on show, and the folds read from that field.
struct FieldSolve {
  field::LiveField live;
  std::string cut_refusal;  // why the inputs' cut cannot be meshed, or empty
  // The inputs of the last request: a field current for them is the field of the inputs shown.
  std::optional<Parameters> requested_parameters;
  // The inputs the field on show was solved for: the law its folds are read by while a newer
  // field is being solved.
  std::optional<Parameters> shown_parameters;
  std::uint64_t folds_of = 0;  // LiveField::shown_count() of the field the folds were read from
  std::optional<Parameters> folds_parameters;  // ... and the inputs whose law they were read by
  std::optional<field::FieldFolds> folds;
  bool own_cut = false;   // the last request was of the preset's own cut
  double slice_ms = 0.0;  // its share of the last frame
};

class FieldPanel : public Panel {
 public:
  FieldPanel() = default;
  // It holds references into itself.
  FieldPanel(const FieldPanel&) = delete;
  FieldPanel& operator=(const FieldPanel&) = delete;
  static constexpr const char* kTitle = "Tension field";
  const char* name() const override { return kTitle; }
  const char* key() const override { return "field"; }
  const char* introduction() const override {
    return "the cloth as tension field theory solves it: blue where it is taut both ways, orange "
           "where it carries tension along its rays only and wrinkles across them, grey where "
           "it is slack; the lines are the rays along which the weight reaches the supports.";
  }
  void draw(PanelContext& context) override;
  void presented_menu_items(PanelContext& /*context*/) override { toolbar_.menu_item(); }
  // While a field is being solved, and while the one on show is the coarse mesh of a move: the
  // frame loop keeps drawing until the finer one is shown, though nothing else moves.
  bool busy() const override {
    return !consumers_.empty() && ((view_solving_ && live_.working()) ||
                                   (cloth_solving_ && cloth_solve_.live.working()) || coarse_);
  }
  // Forgets who asked for the field this frame (ask_for_folds).
  void end_frame(PanelContext& context) override;
  bool* open_flag() override { return &open_; }
  bool is_open() const override { return open_; }
  bool presentable() const override { return true; }
  void view_settings(ViewSettings& settings, Document& document) override;
  // {"field": {open, current, working, refusal, converged, relative_residual, iterations,
  // slice_ms (its share of the last frame), mesh, regions, weight_N, thrust_N, pencil_thrust_N,
  // supports, rays, spans [{l_mm, thrust_N, pencil_thrust_N}], thrust_text (H as the view words
  // it)}}: the view's field; and under "fold_source_solve" the cloth's own cut's,
  // solved for the 3D view while the view shows another cut (null when there is none).
  void report(nlohmann::json& state, PanelContext& context) const override;
  static constexpr PictureOffer kPictures[] = {
      {PictureView::field, "field", "Export tension field picture",
       "Tension field picture (.png)...", "Tension field picture, any size (.png)...",
       "The tension field alone: where the cloth is taut, wrinkled or slack, its rays and the "
       "supports' reactions.",
       "tension-field"}};
  std::span<const PictureOffer> pictures() const override { return kPictures; }
  std::optional<std::string> picture_unavailable(PictureView view, const Document& document,
                                                 bool as_drawn) const override;
  std::optional<PanelRect> picture_rect(PictureView /*view*/) const override {
    return canvas_rect_;
  }
  bool draw_picture(PictureView view, ImVec2 size_px, Document& document,
                    const PictureStyle& style) override;
  // The cut's name, the weight, the thrust beside the cosine pencil's, the field's n, Q and
  // z_max as `foldlab field` prints them, how the solve ended, and why the closed form's cosines
  // asked for are not drawn.
  std::vector<std::string> picture_figures(PictureView view, Document& document) const override;
  // A picture's cut given on its command line (`foldlab picture field --outline FILE`, `--shape
  // S`, app/common/field_cut.hpp) in place of the view's: `name` as a report calls it, `kind`
  // the named cut it is (nullopt: a designer's own); `closed_form_of_cut`: the inputs are the
  // cut's own h, L and d (app::closed_form_of_cut), and the caption says so.
  void use_picture_cut(field::Outline outline, std::string name,
                       std::optional<field::OutlineKind> kind, bool closed_form_of_cut = false);
  // What the caption calls the closed form's figures beside the field's.
  std::string closed_form_words() const;
  // "field": the canvas the cut is drawn on.
  void drawing_areas(DrawingAreas& areas) const override {
    if (const std::optional<PanelRect> rect = drawn_.recent()) {
      areas.emplace_back(key(), *rect);
    }
  }

  // The 3D view takes its folds from the field this frame: the field is solved though its own
  // view is closed. Asked before the panels draw (Panel::begin_frame).
  void ask_for_folds() { folds_asked_ = true; }
  // Who the field was solved for at the last frame: "view" (this panel open), "fold_source".
  const std::vector<std::string>& consumers() const { return consumers_; }
  // Requests the field of the inputs as they stand now and gives it this frame's slice of
  // solving, once a frame (again only when the inputs changed since within the frame, with what
  // is left of the slice). Whoever reads the field first in a frame calls it, before drawing: a
  // slider's value changes while the Parameters panel draws, after any step taken before the
  // panels draw, and a view drawn before this panel would otherwise show the field a frame late.
  void prepare(PanelContext& context);
  // The field's folds for the cloth's own cut (the shape's, or the preset's) at the inputs as
  // they stand now, after prepare().
  FieldFoldsNow folds_now(PanelContext& context);
  // Opens the view (Results offers it where no one has asked for the field).
  void open() { open_ = true; }

  // Mesh cells across the cut at rest; a drag solves on half as many.
  static constexpr int kDefaultCells = 32;

 private:
  void controls();
  void status_line(Document& document, bool side_by_side);
  void solve_line() const;
  void canvas(PanelContext& context);
  // A request of `cut` and a slice of solving on `solve`, at most `budget_ms`.
  void solve_slice(FieldSolve& solve, FieldCut cut, PanelContext& context, bool moving,
                   double budget_ms);
  static void update_folds(FieldSolve& solve, const Parameters& parameters);
  // The solve the 3D view's folds come from: the view's when it shows the cloth's own cut, else
  // the cloth's own.
  FieldSolve& fold_solve() { return cut_ == FieldCut::shape ? view_solve_ : cloth_solve_; }
  FieldDrawing drawing_style(const PanelContext& context) const;
  // The field of the document's inputs at rest, solved whole, for a picture.
  const field::SolvedField* picture_field(const Document& document, std::string& refusal) const;

  static constexpr float kLeastCanvasEms = 14.0f;
  ViewToolbar toolbar_;
  bool open_ = false;
  bool was_open_ = false;  // in the last frame
  FieldColouring colouring_ = FieldColouring::state;
  FieldCut cut_ = FieldCut::shape;
  bool folds_asked_ = false;
  std::vector<std::string> consumers_;
  bool preset_cut_ = false;  // the preset loaded has a cut of its own
  bool rays_ = true;
  bool cosines_ = false;
  int cells_ = kDefaultCells;
  // When the inputs last changed: the field is solved on the coarser mesh until they rest this
  // long.
  static constexpr double kRestS = 0.3;
  std::optional<Parameters> last_parameters_;
  double last_change_s_ = -1e9;
  double slice_ms_ = 0.0;  // the fields' share of the last frame
  bool coarse_ = false;    // the last frame asked for the coarse mesh
  // The frame prepare() last ran in and the inputs it requested.
  int prepared_frame_ = -1;
  std::optional<Parameters> prepared_parameters_;
  // The field of the view's cut, and the cloth's own cut's for the 3D view's folds when the view
  // shows another: each solved only while it is asked for.
  FieldSolve view_solve_;
  FieldSolve cloth_solve_;
  // Which of them the last frame solved: one left unfinished when no longer asked for keeps no
  // frame busy.
  bool view_solving_ = false;
  bool cloth_solving_ = false;
  // The view's field by the names its drawing reads.
  field::LiveField& live_ = view_solve_.live;
  std::string& cut_refusal_ = view_solve_.cut_refusal;
  std::optional<field::FieldFolds>& folds_ = view_solve_.folds;
  std::optional<PanelRect> canvas_rect_;
  // How the canvas was last fitted: the extent is kept, or grown, while an input moves.
  FieldFit canvas_fit_;
  DrawnArea drawn_;
  struct GivenCut {
    field::Outline outline;
    std::string name;
    std::optional<field::OutlineKind> kind;
    bool closed_form_of_cut = false;
  };
  std::optional<GivenCut> picture_cut_;
  // Whether the closed form knows a picture's cut, and what the caption calls it.
  bool picture_cut_is_closed_forms() const;
  std::string picture_cut_words(const Document& document) const;
  // Under the figures: why the closed form's cosines asked for are not drawn.
  void cosines_line(Document& document) const;
  // A picture's field: solved once per set of inputs.
  mutable std::optional<field::FieldInputs> picture_inputs_;
  mutable std::optional<field::SolvedField> picture_field_;
  mutable std::string picture_refusal_;
};

}  // namespace foldlab::gui
