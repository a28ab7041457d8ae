#include "app/gui/panels/parameters_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>
#include <nlohmann/json.hpp>

#include "app/gui/input_words.hpp"
#include "app/gui/panels/axis_inputs.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/analysis/sweep.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

// "ν (Poisson's ratio)": the paper's symbol, spelt out where the font has no Greek.
std::string slider_label(const InputSpec& spec) {
  return readable(std::string(input_symbol(spec)) + " (" + std::string(spec.name) + ")");
}

// Whether validation refused this input. K is derived: validation names the constant c it sets.
bool refused(const Document& document, const InputSpec& spec) {
  for (const ValidationIssue& issue : document.issues()) {
    if (issue.field == spec.field || (spec.kind == InputKind::stiffness_K && issue.field == "c")) {
      return true;
    }
  }
  return false;
}

bool logarithmic(const InputSpec& spec, const InputInterval& range) {
  return spec.scale == InputScale::logarithmic && range.lo > 0.0;
}

// Where a value sits on its slider, 0 at the left end and 1 at the right: on the exponent for a
// log row, so that every decade gets the same width.
double slider_fraction(const InputSpec& spec, const InputInterval& range, double value) {
  if (logarithmic(spec, range)) {
    return (std::log10(value) - std::log10(range.lo)) /
           (std::log10(range.hi) - std::log10(range.lo));
  }
  return (value - range.lo) / (range.hi - range.lo);
}

double slider_value(const InputSpec& spec, const InputInterval& range, double fraction) {
  const double value =
      logarithmic(spec, range)
          ? std::pow(10.0, std::log10(range.lo) +
                               fraction * (std::log10(range.hi) - std::log10(range.lo)))
          : range.lo + fraction * (range.hi - range.lo);
  return std::clamp(value, range.lo, range.hi);  // pow and rounding may step past an end
}

std::string trimmed(const char* text) {
  std::string out(text);
  out.erase(0, out.find_first_not_of(" \t"));
  out.erase(out.find_last_not_of(" \t") + 1);
  return out;
}

void choice_combo(Document& document, const InputSpec& spec, float width) {
  const std::string current(spec.choice(document.edited()));
  ImGui::SetNextItemWidth(width);
  if (begin_combo(std::string(spec.name).c_str(), current.c_str())) {
    std::string_view rest = spec.choices;
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      const std::string option(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      while (!rest.empty() && rest.front() == ' ') {
        rest.remove_prefix(1);
      }
      if (ImGui::Selectable(option.c_str(), option == current) && option != current) {
        document.apply(Edit::choose(std::string(spec.key), option));
      }
    }
    end_combo();
  }
  help_marker(std::string(spec.help).c_str());
}

// The laws by their titles; choosing one brings its published constants (c, p = 1) in the same
// undo step, since a law's constants mean nothing to another law.
void law_combo(Document& document, float width) {
  const WrinkleLaw& current = wrinkle_law(document.edited().model.law);
  ImGui::SetNextItemWidth(width);
  if (begin_combo("wrinkle law", std::string(current.title()).c_str())) {
    for (const WrinkleLaw* law : wrinkle_laws()) {
      if (ImGui::Selectable(std::string(law->title()).c_str(), law == &current) &&
          law != &current) {
        document.apply(Edit::assign({{"law", std::string(law->key())},
                                     {"c", law->published_load_constant_c()},
                                     {"p", 1.0}}));
      }
    }
    end_combo();
  }
  help_marker(
      "Which law counts the folds: Conci's critical stress (eq. 7, a ratio Q7 between "
      "neighbouring folds) or Cerda and Mahadevan's wrinkle wavelength (as many folds as fit a "
      "wavelength apart). Choosing one sets its published constants; K and p then tune it.");
}

}  // namespace

std::string shown_text(const InputSpec& spec, double value) {
  const InputUnit unit = shown_unit(spec);
  const double in_unit = value / unit.per_unit;
  std::string text = detail::printf_string(std::string(unit.format).c_str(), in_unit);
  // "15000 mm", not "1.5e+04 mm"; but a refused 1e308 reads as typed, not as 309 digits.
  if (text.find("e+") != std::string::npos) {
    text = std::abs(in_unit) < 1e15 ? detail::printf_string("%.0f", in_unit)
                                    : detail::message_number(in_unit);
  }
  return unit.symbol.empty() ? text : text + " " + std::string(unit.symbol);
}

std::string expert_mode_help() {
  std::string cloth;
  std::string model;
  for (const InputSpec& spec : input_table()) {
    if (spec.cloth) {
      cloth += (cloth.empty() ? "" : ", ") + std::string(input_symbol(spec));
    } else if (spec.expert && (spec.place == InputPlace::list || spec.place == InputPlace::after)) {
      const std::string_view named =
          spec.kind == InputKind::choice ? spec.name : input_symbol(spec);
      model += (model.empty() ? "" : ", ") + std::string(named);
    }
  }
  return "Beginners see the cloth (" + cloth +
         ") and its shape; experts also the model's settings (" + model + ") and the 3D grid.";
}

const std::vector<Assignment>& printed_eq7() {
  // Built once: every frame asks whether it is in use.
  static const std::vector<Assignment> assignments = {
      {"method", std::string(to_string(Method::paper))},
      {"law", std::string(to_string(WrinkleLawKind::conci))},
      {"p", 1.0},
      {"K", kCalibratedLoadConstantC / (1.0 - kDefaultPoissonRatio * kDefaultPoissonRatio)}};
  return assignments;
}

bool is_printed_eq7(const Parameters& p) {
  Parameters printed = p;
  for (const Assignment& a : printed_eq7()) {
    apply_assignment(printed, a);
  }
  return printed.model == p.model;
}

// A slider for one row of the input table. It moves over [0, 1] of the part of the row's typical
// range that validation accepts with the other inputs, and shows the value in the row's shown
// unit (w in g/m²): ImGui's own logarithmic slider treats values below the format's precision as
// zero, which put all of w's range in its dead zone. Typed values (Ctrl+click) are read with a
// unit, neither mapped nor clamped, so that validation rather than the widget decides.
const InputInterval& ParametersPanel::interval(const InputSpec& spec, const Parameters& p,
                                               SliderReach reach) {
  const std::string key = std::string(spec.key) + (reach == SliderReach::beginner ? "/b" : "/e");
  const auto found = intervals_.find(key);
  if (found != intervals_.end() && found->second.at == p) {
    return found->second.range;
  }
  CachedInterval& entry = intervals_[key];
  entry = {p, slider_interval(spec, p, reach)};
  return entry.range;
}

std::string ParametersPanel::shown(const Document& document, const InputSpec& spec) const {
  const double value = spec.value(document.edited()).value_or(0.0);
  const auto unread = unread_.find(spec.key);
  if (unread != unread_.end() && unread->second.value == value) {
    return unread->second.text;
  }
  return shown_text(spec, value);
}

std::map<std::string, std::string> ParametersPanel::unread_reasons() const {
  std::map<std::string, std::string> out;
  for (const auto& [key, unread] : unread_) {
    out[key] = unread.reason;
  }
  return out;
}

void ParametersPanel::input_slider(Document& document, UiStatus& status, const InputSpec& spec,
                                   float width, SliderLook look) {
  const double value = spec.value(document.edited()).value_or(0.0);
  const std::string key(spec.key);
  // In the strip the symbol goes before the slider and the label is only its id.
  const std::string label =
      look == SliderLook::panel ? slider_label(spec) : "##" + slider_label(spec);
  if (look == SliderLook::strip) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(readable(input_symbol(spec)).c_str());
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
  } else if (look == SliderLook::stacked) {
    ImGui::TextUnformatted(slider_label(spec).c_str());
    help_marker(std::string(spec.help).c_str());
  }
  // A refused value reddens its slider; the reason goes to the foot of the panel (or the strip),
  // so that no line appears between the sliders and moves the one under the mouse.
  const bool is_refused = refused(document, spec) || unread_.contains(key);
  if (is_refused) {
    ImGui::PushStyleColor(ImGuiCol_FrameBg, kRefusedFrame);
  }
  ImGui::SetNextItemWidth(width);
  const ImGuiID id = ImGui::GetID(label.c_str());
  const bool typing = ImGui::TempInputIsActive(id);
  const std::optional<double> changed =
      typing ? typed_field(document, status, spec, label, id, value)
             : slider_field(document, status, spec, label, id, width, value);
  if (changed) {
    // The last text typed here that was no value, and its reason on the status line, no longer
    // hold.
    if (const auto unread = unread_.find(key); unread != unread_.end()) {
      status.withdraw(unread->second.reason);
      unread_.erase(unread);
    }
    // A drag stays open until the slider lets go (the frame closes the step); a typed value or
    // an arrow key's nudge is a step of its own.
    Edit edit = Edit::input(key, *changed);
    if (!typing) {
      edit = std::move(edit).by_slider();
    }
    document.apply(ImGui::IsItemActive() ? std::move(edit).open() : edit);
  }
  if (is_refused) {
    ImGui::PopStyleColor();
  }
  if (look == SliderLook::panel) {
    help_marker(std::string(spec.help).c_str());
  } else if (look == SliderLook::strip && ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
    wrapped_tooltip("%s\n%s", readable(slider_label(spec)).c_str(), readable(spec.help).c_str());
  }
}

std::optional<double> ParametersPanel::read_typed(UiStatus& status, const InputSpec& spec,
                                                  double value) {
  typing_id_ = 0;
  const int escape_key = ImGui::GetKeyIndex(ImGuiKey_Escape);
  const bool escape = escape_key >= 0 && ImGui::IsKeyPressed(escape_key, false);
  const std::string text = trimmed(typed_);
  if (escape || text == typing_initial_) {
    return std::nullopt;
  }
  const std::string key(spec.key);
  const std::variant<double, InputRefusal> read =
      read_quantity(spec, text, shown_unit(spec).symbol);
  const InputRefusal* refusal = std::get_if<InputRefusal>(&read);
  if (refusal == nullptr) {
    return std::get<double>(read);
  }
  // Said, not dropped: the slider going back to its value with no word looks like a fault.
  // Kept as typed, as a refused number is, so that the person sees what was not understood.
  std::string units;
  for (const InputUnit& unit : input_units(spec)) {
    units += (units.empty() ? "" : ", ") + std::string(unit.symbol);
  }
  const std::string quoted = input_title(spec) + ": \"" + detail::cut(text) + "\"";
  const std::string value_now = shown_text(spec, value);
  // A unit, nesting or magnitude that is named is said as it is; anything else is no number at
  // all.
  const bool named = refusal->kind != RefusalKind::not_a_number;
  const std::string problem = refusal_reason(*refusal);
  const std::string reason =
      named ? quoted + problem + (problem.ends_with('?') ? " " : ". ") + "The value stays " +
                  value_now + "."
            : quoted + " is not a number" + (units.empty() ? "" : " with a unit (" + units + ")") +
                  ", nor arithmetic such as 2*153; the value stays " + value_now + ".";
  unread_[key] = {detail::cut(text), reason, value};
  status.notify(reason, MessageKind::error);
  return std::nullopt;
}

std::optional<double> ParametersPanel::typed_field(Document& document, UiStatus& status,
                                                   const InputSpec& spec, const std::string& label,
                                                   ImGuiID id, double value) {
  // ImGui opened its text field over the slider on the Ctrl+click, with the shown text; this
  // field, under the same id, carries on editing it without the digits-only filter, so that a
  // unit can be typed. What is typed is read when it is done (Enter, or the field losing the
  // text cursor), never keystroke by keystroke: typing 750 must not solve d = 7 and d = 75 on the
  // way. Escape cancels.
  if (typing_id_ != id) {
    typing_id_ = id;
    typing_initial_ = shown(document, spec);
    std::snprintf(typed_, sizeof typed_, "%s", typing_initial_.c_str());
  }
  const bool enter =
      ImGui::InputText(label.c_str(), typed_, sizeof typed_,
                       ImGuiInputTextFlags_AutoSelectAll | ImGuiInputTextFlags_EnterReturnsTrue);
  // The field stops taking characters when full (at the capacity of the field ImGui opened on
  // the Ctrl+click, whose editing state this one carries on): said, rather than keys seeming to go
  // nowhere.
  if (const ImGuiInputTextState* state = ImGui::GetInputTextState(id);
      ImGui::IsItemActive() && state != nullptr && state->CurLenW + 1 >= state->TextW.Size) {
    wrapped_tooltip("A typed value takes at most %d characters.", state->TextW.Size - 1);
  }
  if (enter || ImGui::IsItemDeactivated()) {
    return read_typed(status, spec, value);
  }
  return std::nullopt;
}

std::optional<double> ParametersPanel::slider_field(Document& document, UiStatus& status,
                                                    const InputSpec& spec, const std::string& label,
                                                    ImGuiID id, float width, double value) {
  std::optional<double> changed;
  if (typing_id_ == id) {
    // A click elsewhere took the text cursor before this frame drew the field.
    changed = read_typed(status, spec, value);
    value = changed.value_or(value);
  }
  const SliderReach reach = status.expert_mode() ? SliderReach::expert : SliderReach::beginner;
  const InputInterval range = interval(spec, document.edited(), reach);
  // The shown text doubles as the text field's first contents on Ctrl+click, which parses
  // back to the value with its unit.
  std::string text = shown(document, spec);
  for (std::size_t at = text.find('%'); at != std::string::npos; at = text.find('%', at + 2)) {
    text.insert(at, 1, '%');
  }
  // A typed value off the slider's scale (w <= 0) pins the handle to the left end.
  const double on_scale = slider_fraction(spec, range, value);
  const double fraction = std::isnan(on_scale) ? 0.0 : std::clamp(on_scale, 0.0, 1.0);
  double position = fraction;
  constexpr double kZero = 0.0;
  constexpr double kOne = 1.0;
  const bool moved = notched_slider(
      [&] {
        return ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &position, &kZero, &kOne,
                                   text.c_str(), ImGuiSliderFlags_AlwaysClamp);
      },
      [&] { return position; });
  const ImGuiIO& io = ImGui::GetIO();
  // A press that has not yet moved past ImGui's drag threshold only takes the focus (for the
  // arrow keys): ImGui's slider would put the value where the pointer landed, and a click meant
  // to focus a slider in front of a class changed the fabric.
  const bool dragging =
      ImGui::IsItemActive() && !(io.MouseDown[0] && !ImGui::IsMouseDragPastThreshold(0));
  std::optional<double> to_position;
  // A finger covers the handle and lands a few pixels off: its drag moves the value by its own
  // movement, never to where it landed.
  const bool finger = (io.ConfigFlags & ImGuiConfigFlags_IsTouchScreen) != 0;
  if (dragging && (io.KeyShift || finger || relative_drag_id_ == id)) {
    relative_drag_id_ = id;
    to_position = relative_drag(fraction, width);
  } else if (moved && dragging) {
    to_position = position;
  } else if (ImGui::IsItemFocused() && !ImGui::IsItemActive()) {
    to_position = arrow_nudge(fraction);
  }
  if (to_position) {
    changed = slider_value(spec, range, *to_position);
  }
  if (relative_drag_id_ == id && !ImGui::IsItemActive()) {
    relative_drag_id_ = 0;
  }
  // The item's rectangle includes its label; the slider's own frame is `width` wide.
  const ImVec2 min = ImGui::GetItemRectMin();
  ImDrawList& drawn = *ImGui::GetWindowDrawList();
  places_[std::string(spec.key)] =
      SliderPlace{min, ImVec2(min.x + width, min.y + ImGui::GetFrameHeight()), fraction,
                  drawn.GetClipRectMin(), drawn.GetClipRectMax()};
  return changed;
}

double finger_drag_speed(float distance_px, float slider_height_px, double finest) {
  if (!(distance_px > slider_height_px) || !(slider_height_px > 0.0f)) {
    return 1.0;
  }
  return std::max(finest, static_cast<double>(slider_height_px) / distance_px);
}

std::optional<double> ParametersPanel::relative_drag(double fraction, float width) const {
  // ImGui's slider puts the handle under the mouse; a relative drag moves it by the mouse's
  // movement instead, over the pixels ImGui's handle travels: the frame less 2 px of padding
  // each side and the handle's own width.
  const ImGuiIO& io = ImGui::GetIO();
  const float travel_px = width - 4.0f - ImGui::GetStyle().GrabMinSize;
  // A finger has no Shift: it makes small changes by dragging away from the slider, as a media
  // player's scrubbing does, with no mode to enter and no timing to meet. The slider (the last
  // item) is the whole row's height.
  const float middle_y = 0.5f * (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y);
  const double speed = io.KeyShift ? kFineDragSpeed
                       : (io.ConfigFlags & ImGuiConfigFlags_IsTouchScreen) != 0
                           ? finger_drag_speed(std::abs(io.MousePos.y - middle_y),
                                               ImGui::GetItemRectSize().y, kFineDragSpeed)
                           : 1.0;
  const double position =
      std::clamp(fraction + speed * io.MouseDelta.x / std::max(1.0f, travel_px), 0.0, 1.0);
  return position != fraction ? std::optional<double>(position) : std::nullopt;
}

std::optional<double> ParametersPanel::arrow_nudge(double fraction) const {
  // Shift gives the fine step, as it gives the fine drag.
  const double step = ImGui::GetIO().KeyShift ? kArrowStep * kFineDragSpeed : kArrowStep;
  const int left = ImGui::GetKeyIndex(ImGuiKey_LeftArrow);
  const int right = ImGui::GetKeyIndex(ImGuiKey_RightArrow);
  const double nudge = (left >= 0 && ImGui::IsKeyPressed(left))     ? -step
                       : (right >= 0 && ImGui::IsKeyPressed(right)) ? step
                                                                    : 0.0;
  if (nudge == 0.0) {
    return std::nullopt;
  }
  return std::clamp(fraction + nudge, 0.0, 1.0);
}

void ParametersPanel::begin_frame(PanelContext& context) {
  Document& document = context.document;
  if (!playing_) {
    return;
  }
  animation_ways_ += static_cast<double>(ImGui::GetIO().DeltaTime) / kSecondsPerWay;
  // Open, and left open by the frame while playing: the whole animation up to its pause is one
  // undo step, which takes the input back to where it was before play.
  document.apply(Edit::input(animate_key_, animation_->at(animation_ways_)).by_slider().open());
}

void ParametersPanel::toggle_play(Document& document, UiStatus& status) {
  if (playing_) {
    playing_ = false;
    document.end_step();  // the value reached stays, as one undo step
    return;
  }
  // The valid range afresh, since the other inputs may have changed while paused; the same
  // input carries on where it paused, over the range typed for it.
  const bool resuming = animation_ && animation_->key() == animate_key_;
  try {
    AnimatedInput fresh(animate_key_, document.edited(),
                        status.expert_mode() ? SliderReach::expert : SliderReach::beginner);
    if (resuming) {
      fresh.set_range(range_lo_, range_hi_);
    } else {
      animation_ways_ = 0.0;
    }
    animation_ = fresh;
    range_lo_ = animation_->lo();
    range_hi_ = animation_->hi();
    animation_problem_.clear();
  } catch (const std::exception& e) {
    animation_.reset();
    animation_problem_ = e.what();
  }
  playing_ = animation_.has_value();
}

void ParametersPanel::animation_row(Document& document, UiStatus& status,
                                    const std::vector<const InputSpec*>& sliders) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("animate");
  ImGui::SameLine();
  // A symbol's room beside the arrow, which is a frame's height wide (a finger's target).
  ImGui::SetNextItemWidth(ems(2.0f) + ImGui::GetFrameHeight());
  if (begin_combo("##animated input", animate_key_.c_str())) {
    for (const InputSpec* spec : sliders) {
      if (ImGui::Selectable(slider_label(*spec).c_str(), spec->key == animate_key_) &&
          spec->key != animate_key_) {
        if (playing_) {
          document.end_step();
        }
        animate_key_ = std::string(spec->key);
        animation_.reset();
        playing_ = false;
      }
    }
    end_combo();
  }
  ImGui::SameLine();
  if (ImGui::Button(playing_ ? kPauseLabel : kPlayLabel)) {
    toggle_play(document, status);
  }
  help_marker(
      "Sweeps the chosen input from the low end of its slider (or of the range typed beside) to "
      "the high end and back while everything re-solves; pause leaves the value where it is. The "
      "animation is one undo step.");
  if (animation_) {
    same_line_if_fits(range_inputs_width());
    if (range_inputs("animate range", animate_key_, range_lo_, range_hi_)) {
      animation_->set_range(range_lo_, range_hi_);
      range_lo_ = animation_->lo();
      range_hi_ = animation_->hi();
    }
  }
  if (!animation_problem_.empty()) {
    ImGui::TextColored(kErrorText, "%s", animation_problem_.c_str());
  }
}

void ParametersPanel::draw(PanelContext& context) {
  Document& document = context.document;
  UiStatus& status = context.status;
  forget_unread_of_changed_values(document, status);
  const bool unsaved = document.unsaved();
  if (!begin(context.renderer, unsaved ? " *" : "")) {
    ImGui::End();
    return;
  }
  header_rows(document, status);
  ImGui::Separator();
  const std::vector<const InputSpec*> sliders = shown_sliders(status);
  const float width = slider_width(sliders);
  // Where the longest label leaves a slider too short beside it (a large text size in a narrow
  // column), each label goes over its slider, which takes the whole width: no label is cut.
  const float beside = ImGui::GetContentRegionAvail().x - longest_label_width(sliders);
  const bool stacked = beside < ems(kMinSliderEms);
  slider_rows(document, status, sliders, stacked ? ImGui::GetContentRegionAvail().x : width,
              stacked ? SliderLook::stacked : SliderLook::panel);
  animation_row(document, status, sliders);
  ImGui::Separator();
  shape_rows(document, status, width);
  if (status.expert_mode()) {
    expert_rows(document, width);
  }
  if (!refusal_lines(document).empty()) {
    ImGui::Separator();
    draw_refusals(document);
  }
  ImGui::End();
}

void ParametersPanel::forget_unread_of_changed_values(const Document& document, UiStatus& status) {
  // Typed text that was no value stays on its slider, and its reason on the status line, until
  // the value changes by other means: a reason that says "the value stays 103 g/m²" under a
  // slider showing 306 g/m² contradicts it.
  std::erase_if(unread_, [&](const auto& entry) {
    const bool changed = find_input(entry.first)->value(document.edited()) != entry.second.value;
    if (changed) {
      status.withdraw(entry.second.reason);
    }
    return changed;
  });
}

void ParametersPanel::header_rows(Document& document, UiStatus& status) {
  const bool unsaved = document.unsaved();
  // Wrapped: cut at the panel's edge a long name would hide "(unsaved changes)". The rows keep
  // the height of the longer form, so that the first edit of a drag never moves the sliders
  // under the pointer by the line it adds.
  const float width = ImGui::GetContentRegionAvail().x;
  const std::string longer = wrap_at_spaces(document.loaded().name + " (unsaved changes)", width);
  const std::string drawn = unsaved ? longer : wrap_at_spaces(document.loaded().name, width);
  ImGui::TextColored(kDimText, "%s", drawn.c_str());
  ImGui::SetCursorPosY(ImGui::GetCursorPosY() + ImGui::CalcTextSize(longer.c_str()).y -
                       ImGui::CalcTextSize(drawn.c_str()).y);
  if (ImGui::Button("Reset to preset")) {
    document.reset_to_loaded();
  }
  // On a line of its own in a narrow panel (a large text size) rather than cut.
  same_line_if_fits(checkbox_width(kExpertLabel) + help_marker_width());
  if (bool expert = status.expert_mode(); ImGui::Checkbox(kExpertLabel, &expert)) {
    status.set_expert_mode(expert);
  }
  static const std::string expert_help = expert_mode_help();
  help_marker(expert_help.c_str());
  // The paper's own model stays one click away whatever is shown.
  const bool printed = is_printed_eq7(document.edited());
  ImGui::BeginDisabled(printed);
  if (ImGui::Button(kPrintedEq7Label)) {
    document.apply(Edit::assign(printed_eq7()));
  }
  ImGui::EndDisabled();
  help_marker(
      "The paper's method and Conci's eq. 7 as printed: p = 1, K = c/(1 − ν²) = 29.56 (c = 26.9 "
      "at ν = 0.3).");
  hint_after(printed ? "in use" : hint_words(Hint::type_value));
}

std::vector<const InputSpec*> ParametersPanel::shown_sliders(const UiStatus& status) {
  std::vector<const InputSpec*> sliders;
  for (const InputSpec& spec : input_table()) {
    if (spec.place != InputPlace::list || spec.kind == InputKind::choice) {
      continue;
    }
    if (spec.expert && !status.expert_mode()) {
      places_.erase(std::string(spec.key));  // playback must not press what is no longer there
      continue;
    }
    sliders.push_back(&spec);
  }
  return sliders;
}

float ParametersPanel::longest_label_width(const std::vector<const InputSpec*>& sliders) const {
  // Sliders leave room on their right for the longest label and its (?) marker.
  float label_width = ImGui::CalcTextSize("span rule").x;
  for (const InputSpec* spec : sliders) {
    label_width = std::max(label_width, ImGui::CalcTextSize(slider_label(*spec).c_str()).x);
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  return label_width + help_marker_width() + 2.0f * style.ItemInnerSpacing.x + style.ItemSpacing.x;
}

float ParametersPanel::slider_width(const std::vector<const InputSpec*>& sliders) const {
  return std::max(ems(6.0f), ImGui::GetContentRegionAvail().x - longest_label_width(sliders));
}

void ParametersPanel::slider_rows(Document& document, UiStatus& status,
                                  const std::vector<const InputSpec*>& sliders, float width,
                                  SliderLook look) {
  for (const InputSpec* spec : sliders) {
    input_slider(document, status, *spec, width, look);
    if (spec->key == "w") {
      const double w = document.edited().fabric.weight_N_per_mm2;
      ImGui::TextColored(kDimText, "    = %.3g oz/yd² = %.4g N/mm²",
                         w / input_units(*spec)[2].per_unit, w);
    }
  }
  // After the list, the model's constants: read out (c, which K sets) or a slider of their own.
  for (const InputSpec& spec : input_table()) {
    const bool readout = spec.place == InputPlace::readout;
    if (!readout && spec.place != InputPlace::after) {
      continue;
    }
    if (spec.expert && !status.expert_mode()) {
      places_.erase(std::string(spec.key));
    } else if (readout) {
      ImGui::TextColored(kDimText, "    %s = %.4g (%s)", std::string(spec.key).c_str(),
                         spec.value(document.edited()).value_or(0.0),
                         std::string(spec.name).c_str());
    } else {
      input_slider(document, status, spec, width, look);
    }
  }
}

void ParametersPanel::shape_rows(Document& document, UiStatus& status, float width) {
  const InputSpec& shape = *find_input("shape");
  choice_combo(document, shape, width);
  if (document.edited().shape.kind == ShapeKind::strip) {
    const InputSpec& supports = *find_input("supports");
    int count = document.edited().shape.supports;
    ImGui::SetNextItemWidth(width);
    if (notched_slider_int("supports", count, static_cast<int>(supports.typical_lo),
                           static_cast<int>(supports.typical_hi), "%d")) {
      document.apply(Edit::input("supports", count).open());
    }
    help_marker(std::string(supports.help).c_str());
  } else if (document.edited().shape.kind == ShapeKind::inclined) {
    input_slider(document, status, *find_input("incline_deg"), width, SliderLook::panel);
  }
}

void ParametersPanel::expert_rows(Document& document, float width) {
  // The law first: choosing one sets the constants the sliders above show.
  law_combo(document, width);
  for (const InputSpec& spec : input_table()) {
    if (spec.kind == InputKind::choice && spec.place == InputPlace::list && spec.key != "law") {
      choice_combo(document, spec, width);
    }
  }
  int grid = document.scene().grid_nx();
  ImGui::SetNextItemWidth(width);
  if (notched_slider_int("grid", grid, 8, 512, "%d per side")) {
    document.set_grid_resolution(grid);
  }
  help_marker(
      "Resolution of the 3D cloth mesh (vertices per side). Changing it does not re-solve.");
}

std::vector<std::string> ParametersPanel::refusal_lines(const Document& document) const {
  std::vector<std::string> lines;
  if (!document.issues().empty()) {
    lines.push_back(detail::printf_string(
        "%zu input(s) refused: the views show the last valid state.", document.issues().size()));
  }
  for (const ValidationIssue& issue : document.issues()) {
    lines.push_back(readable(issue.message));
  }
  for (const auto& [key, unread] : unread_) {
    lines.push_back(readable(unread.reason));
  }
  return lines;
}

void ParametersPanel::draw_refusals(const Document& document) const {
  ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
  for (const std::string& line : refusal_lines(document)) {
    wrapped_text("%s", line.c_str());
  }
  ImGui::PopStyleColor();
}

// The strip's cells: as many to a row as give each slider room for its value and unit, filled
// evenly (three and three rather than four and two). All six in one row where they fit with only
// the gap between a symbol and its slider between cells (each symbol still marks where its cell
// starts): a presented view keeps a row of its height.
ParametersPanel::StripLayout ParametersPanel::strip_layout(float width) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float cell = strip_symbol_width() + style.ItemInnerSpacing.x + strip_slider_width();
  const int count = static_cast<int>(cloth_inputs().size());
  const float narrow_gap = style.ItemInnerSpacing.x;
  if (static_cast<float>(count) * cell + static_cast<float>(count - 1) * narrow_gap <= width) {
    return {count, static_cast<float>(count) * cell +
                               static_cast<float>(count - 1) * style.ItemSpacing.x <=
                           width
                       ? style.ItemSpacing.x
                       : narrow_gap};
  }
  const float gap = style.ItemSpacing.x;
  const int fit = std::clamp(static_cast<int>((width + gap) / (cell + gap)), 1, count);
  const int rows = (count + fit - 1) / fit;
  return {(count + rows - 1) / rows, gap};
}

float ParametersPanel::strip_symbol_width() const {
  float widest = 0.0f;
  for (const InputSpec* spec : cloth_inputs()) {
    widest = std::max(widest, ImGui::CalcTextSize(readable(input_symbol(*spec)).c_str()).x);
  }
  return widest;
}

// Measured in the font as drawn rather than a guess in ems: the value and the frame's padding
// either side, so that the text never meets the frame's edge.
float ParametersPanel::strip_slider_width() const {
  const float width =
      ImGui::CalcTextSize(kStripWidestValue).x + 2.0f * ImGui::GetStyle().FramePadding.x;
  return std::ceil(width);
}

float ParametersPanel::strip_height(const Document& document, float width) const {
  const int count = static_cast<int>(cloth_inputs().size());
  const int columns = strip_layout(width).columns;
  const int rows = (count + columns - 1) / columns;
  const float spacing = ImGui::GetStyle().ItemSpacing.y;
  float height =
      static_cast<float>(rows) * ImGui::GetFrameHeight() + static_cast<float>(rows - 1) * spacing;
  for (const std::string& line : refusal_lines(document)) {
    height += spacing + ImGui::CalcTextSize(line.c_str(), nullptr, false, width).y;
  }
  return height;
}

void ParametersPanel::draw_strip(Document& document, UiStatus& status, float width) {
  forget_unread_of_changed_values(document, status);
  places_.clear();  // only the strip's sliders are there to press
  const std::vector<const InputSpec*> strip = cloth_inputs();
  const int count = static_cast<int>(strip.size());
  const auto [columns, gap] = strip_layout(width);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float cell = (width - static_cast<float>(columns - 1) * gap) / static_cast<float>(columns);
  const float symbol = strip_symbol_width();
  for (int i = 0; i < count; ++i) {
    const InputSpec& spec = *strip[static_cast<std::size_t>(i)];
    if (i % columns != 0) {
      ImGui::SameLine(0.0f, gap);
    }
    // The symbols right-aligned in their column, so that the sliders line up across rows.
    const float symbol_width = ImGui::CalcTextSize(readable(input_symbol(spec)).c_str()).x;
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + symbol - symbol_width);
    input_slider(document, status, spec, cell - symbol - style.ItemInnerSpacing.x,
                 SliderLook::strip);
  }
  draw_refusals(document);
}

float slider_handle_x(const SliderPlace& place, double fraction) {
  constexpr float kGrabPadding = 2.0f;
  const float slider_px = place.max.x - place.min.x - 2.0f * kGrabPadding;
  const float grab_px = std::min(ImGui::GetStyle().GrabMinSize, slider_px);
  return place.min.x + kGrabPadding + 0.5f * grab_px +
         static_cast<float>(fraction) * (slider_px - grab_px);
}

void ParametersPanel::report(nlohmann::json& state, PanelContext& context) const {
  nlohmann::json sliders = nlohmann::json::object();
  for (const auto& [key, place] : places_) {
    const float y = 0.5f * (place.min.y + place.max.y);
    sliders[key] = {
        {"handle", {slider_handle_x(place, place.fraction), y}},
        {"left", place.min.x},
        {"right", place.max.x},
        {"top", place.min.y},
        {"bottom", place.max.y},
        {"fraction", place.fraction},
        {"clip", {place.clip_min.x, place.clip_min.y, place.clip_max.x, place.clip_max.y}},
        {"shown", shown(context.document, *find_input(key))}};
  }
  state["sliders"] = sliders;
  nlohmann::json unread = nlohmann::json::object();
  for (const auto& [key, reason] : unread_reasons()) {
    unread[key] = reason;
  }
  state["unread"] = unread;
  state["animation"] = {{"key", animate_key_}, {"playing", playing_}};
}

}  // namespace foldlab::gui
