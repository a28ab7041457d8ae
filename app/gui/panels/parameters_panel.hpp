// The Parameters panel: one slider per input of the cloth, its hanging and eq. 7's K, each with
// the scale, format, unit and help of its row in the input table and a range that stops where
// validation would refuse; the shape; for experts also the model's choices and the 3D grid.
// Every change goes through Document::apply as it happens; a drag stays one open undo step.
#pragma once

#include <functional>
#include <map>

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/gui/animated_input.hpp"
#include "app/gui/document.hpp"
#include "app/gui/input_words.hpp"
#include "app/gui/panel.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {

// A value in the unit the slider shows, with the unit: "153 g/m²", "0.25 mm". Large numbers are
// written out rather than as 1.23e+03.
std::string shown_text(const InputSpec& spec, double value);

// Where a parameter slider was drawn in the last frame, for input playback: its frame and where
// its handle sits (0 at the left end, 1 at the right).
struct SliderPlace {
  ImVec2 min;
  ImVec2 max;
  double fraction = 0.0;
  // What of it can be seen: its window's clip rectangle (a panel scrolled, a window too small).
  ImVec2 clip_min;
  ImVec2 clip_max;
};

// Where ImGui 1.86 centres a float slider's handle for `fraction` (SliderBehaviorT's geometry).
float slider_handle_x(const SliderPlace& place, double fraction);

// A finger's drag on a slider, as a part of the finger's movement: the whole of it while the
// finger is within a slider's height of the slider's middle, less the farther it strays above or
// below (half at twice that height, a third at three times), and never less than `finest`.
double finger_drag_speed(float distance_px, float slider_height_px, double finest);

class ParametersPanel : public Panel {
 public:
  const char* name() const override { return "Parameters"; }
  const char* introduction() const override { return hint_words(Hint::parameters_intro); }
  const char* key() const override { return "parameters"; }
  void draw(PanelContext& context) override;
  // By input key; a slider hidden last frame keeps its older place.
  const std::map<std::string, SliderPlace, std::less<>>& slider_places() const { return places_; }

  // While playing: the next frame's value, one open edit for the whole animation. Called by the
  // explorer every frame, whether or not this panel is drawn (a presented view still plays).
  void begin_frame(PanelContext& context) override;
  // True while the play button sweeps an input: every frame shows new inputs.
  bool animating() const override { return playing_; }
  bool plays_input() const override { return playing_; }
  // Where each slider's handle is ("sliders": its frame, clip and handle, so that a test driving
  // the real window can press on it as a person would, and what it shows) and text typed into a
  // slider that is no value, with its reason ("unread").
  void report(nlohmann::json& state, PanelContext& context) const override;
  // The input the play button sweeps, and the sweep while it plays or is paused.
  const std::string& animated_key() const { return animate_key_; }
  const std::optional<AnimatedInput>& animation() const { return animation_; }
  static constexpr double kSecondsPerWay = 4.0;  // the play button: min to max in 4 s
  // The play button's click, also the presenting bar's: plays the chosen input from where it
  // paused (or from its low end), or pauses it where it is.
  void toggle_play(Document& document, UiStatus& status);
  // Why the last play could not start (the input has no valid range now), or empty.
  const std::string& animation_problem() const { return animation_problem_; }

  static constexpr const char* kExpertLabel = "Expert settings";
  static constexpr const char* kPlayLabel = "play";
  static constexpr const char* kPauseLabel = "pause";
  static constexpr const char* kPrintedEq7Label = "Conci's eq. 7 as printed";
  static constexpr double kFineDragSpeed = 0.1;
  // An arrow key moves a focused slider's handle by this part of its width (Shift: a tenth).
  static constexpr double kArrowStep = 0.01;

  // The strip over a presented view: the cloth inputs (cloth_inputs) as compact sliders (the
  // panel's own, with their typed values, units, keys and refusals), as many to a row as fit
  // `width`.
  void draw_strip(Document& document, UiStatus& status, float width);
  // The strip's height at `width`: its rows and the reasons for refused values under them.
  float strip_height(const Document& document, float width) const;
  // No slider is shown (a presented view without the strip): playback presses none.
  void forget_slider_places() { places_.clear(); }

  // What a slider shows: its value in the shown unit, or text typed into it that is no value.
  std::string shown(const Document& document, const InputSpec& spec) const;
  // The reasons typed text was refused, by input key.
  std::map<std::string, std::string> unread_reasons() const;

 private:
  // How a slider is drawn: in the panel its label and (?) after it (stacked: on a line over it,
  // when the panel is too narrow for both); in the strip its symbol before it and its help when
  // hovered.
  enum class SliderLook { panel, stacked, strip };
  static constexpr float kMinSliderEms = 7.0f;  // shorter beside its label, a slider is stacked
  // The widest value a strip slider shows: each cell has room for it in the font as drawn.
  static constexpr const char* kStripWidestValue = "10194 g/m²";
  // One slider of the input table; a change goes to the document as an edit.
  void input_slider(Document& document, UiStatus& status, const InputSpec& spec, float width,
                    SliderLook look);
  // The steps of a slider: the text field a Ctrl+click opens, the slider itself, and the value
  // each gives when changed.
  std::optional<double> typed_field(Document& document, UiStatus& status, const InputSpec& spec,
                                    const std::string& label, ImGuiID id, double value);
  std::optional<double> slider_field(Document& document, UiStatus& status, const InputSpec& spec,
                                     const std::string& label, ImGuiID id, float width,
                                     double value);
  // The typed text read with its unit; text that is no value is kept and said, and gives none.
  std::optional<double> read_typed(UiStatus& status, const InputSpec& spec, double value);
  // Where a Shift drag, a finger's drag or an arrow key moves the handle (0 to 1 of the slider),
  // if anywhere.
  std::optional<double> relative_drag(double fraction, float width) const;
  std::optional<double> arrow_nudge(double fraction) const;

  // The panel's rows, top to bottom.
  void forget_unread_of_changed_values(const Document& document, UiStatus& status);
  void header_rows(Document& document, UiStatus& status);
  std::vector<const InputSpec*> shown_sliders(const UiStatus& status);
  // The room the longest label and its (?) take right of a slider, and the slider's width.
  float longest_label_width(const std::vector<const InputSpec*>& sliders) const;
  float slider_width(const std::vector<const InputSpec*>& sliders) const;
  void slider_rows(Document& document, UiStatus& status,
                   const std::vector<const InputSpec*>& sliders, float width, SliderLook look);
  void shape_rows(Document& document, UiStatus& status, float width);
  void expert_rows(Document& document, float width);
  // The reasons for refused inputs and unread text, at the panel's foot and under the strip.
  std::vector<std::string> refusal_lines(const Document& document) const;
  void draw_refusals(const Document& document) const;
  struct StripLayout {
    int columns = 1;
    float gap_px = 0.0f;  // between a slider and the next cell's symbol
  };
  StripLayout strip_layout(float width) const;
  float strip_symbol_width() const;
  float strip_slider_width() const;
  // The play row: which input, play/pause, and the range it sweeps.
  void animation_row(Document& document, UiStatus& status,
                     const std::vector<const InputSpec*>& sliders);

  std::map<std::string, SliderPlace, std::less<>> places_;
  // What is typed into a slider's text field (Ctrl+click), read with its unit on Enter or when
  // the field lets go; the field's first text, so that leaving it as it was keeps the exact value
  // rather than its rounded display.
  char typed_[64] = {};
  ImGuiID typing_id_ = 0;
  // Each slider's range for the inputs it was found at: the search runs validation many times, so
  // it is repeated only when an input changes, not every frame.
  struct CachedInterval {
    Parameters at;
    InputInterval range;
  };
  std::map<std::string, CachedInterval, std::less<>> intervals_;
  const InputInterval& interval(const InputSpec& spec, const Parameters& p, SliderReach reach);
  // Text typed into a slider that is no value: kept as typed on the slider, with the reason
  // under the sliders, until the input's value changes (`value` is the one it had).
  struct UnreadText {
    std::string text;
    std::string reason;
    double value = 0.0;
  };
  std::map<std::string, UnreadText, std::less<>> unread_;
  // Shift held during a drag moves the handle at kFineDragSpeed of the mouse. From the first
  // frame with Shift until the button is let go, the drag follows the mouse's movement rather
  // than its position, so that letting go of Shift does not make the handle jump.
  ImGuiID relative_drag_id_ = 0;
  std::string typing_initial_;

  std::string animate_key_ = "h";
  std::optional<AnimatedInput> animation_;
  double animation_ways_ = 0.0;  // one-way sweeps done: the animation's clock
  bool playing_ = false;
  double range_lo_ = 0.0;  // the from/to fields, in the input's unit
  double range_hi_ = 0.0;
  std::string animation_problem_;
};

// The Expert settings box's help: what a beginner sees (the cloth inputs) and what an expert sees
// besides (the model's settings the panel shows), from the input table.
std::string expert_mode_help();

// The paper's form of eq. 7 as inputs of the table: the paper method, Conci's law, p = 1 and
// K = 29.56 (c = 26.9 at nu = 0.3) at the Poisson ratio in force.
const std::vector<Assignment>& printed_eq7();
bool is_printed_eq7(const Parameters& p);

}  // namespace foldlab::gui
