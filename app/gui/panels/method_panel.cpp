#include "app/gui/panels/method_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>  // GetActiveID: the field keeps what is being typed

#include "app/gui/panels/widgets.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

constexpr ImU32 kBandFill = IM_COL32(120, 200, 120, 40);

// z_max as the iteration has it: "0" when eq. 9's root is exactly zero (the first paper iterate),
// enough digits for a value below 0.01 mm, else two decimals.
std::string z_max_text(double z_max_mm) {
  if (z_max_mm == 0.0) {
    return "0";
  }
  return std::abs(z_max_mm) < 0.01 ? detail::printf_string("%.2g", z_max_mm)
                                   : detail::printf_string("%.2f", z_max_mm);
}

// Above this many n the map plot shows a window around the visits.
constexpr int kMapPoints = 60;

using detail::printf_string;

}  // namespace

void MethodPanel::step() {
  shown_ = std::min(shown_ + 1, std::max(iterates(), 1));
}
void MethodPanel::back() {
  shown_ = std::max(shown_ - 1, 1);
}
void MethodPanel::reset() {
  shown_ = 1;
}
void MethodPanel::run_to_end() {
  shown_ = std::max(iterates(), 1);
}

void MethodPanel::recompute(const Parameters& current) {
  model_method_ = current.model.method;
  Parameters p = current;
  p.model.method = method_;
  if (computed_ && p == computed_for_) {
    return;
  }
  trace_ = trace_iterations(p);
  map_.clear();
  if (method_ == Method::exact && !trace_.iterates.empty()) {
    int lo = trace_.iterates.front().n;
    int hi = lo;
    for (const Iterate& it : trace_.iterates) {
      lo = std::min({lo, it.n, it.next_n});
      hi = std::max({hi, it.n, it.next_n});
    }
    // From n = 1 when that fits, so the staircase reads against the whole map.
    lo = hi + 2 <= kMapPoints ? 1 : std::max(1, lo - 2);
    hi = std::min(hi + 2, lo + kMapPoints - 1);
    map_ = count_map(p, lo, hi);
  }
  computed_for_ = p;
  computed_ = true;
  shown_ = 1;  // new inputs: the iteration starts again
}

void MethodPanel::draw(Document& document) {
  const Parameters& current = document.scene().parameters();
  if (!following_ || current.model.method != followed_) {
    method_ = current.model.method;
    followed_ = current.model.method;
    following_ = true;
  }
  int choice = method_ == Method::paper ? 0 : 1;
  bool changed = ImGui::RadioButton("paper method", &choice, 0);
  same_line_if_fits(checkbox_width("exact method"));
  changed |= ImGui::RadioButton("exact method", &choice, 1);
  if (changed) {
    method_ = choice == 0 ? Method::paper : Method::exact;
  }
  ImGui::SameLine();
  const std::string count_formula(wrinkle_law(current.model.law).count_formula());
  help_marker(method_ == Method::paper
                  ? "a_0 = 1.01 h and a_n starts at 0.01 h, so on the first iterate the "
                    "a-differences a_0 − a_n alone make h and eq. 9 gives z_max = 0 exactly. Each "
                    "iterate: n from eq. 10, "
                    "Q = (a_0/a_n)^(1/n), z_max from eq. 9, L′ from eq. 8 (Simpson); stop when "
                    "|L′/L − 1| is within the tolerance, else a_n ← √(A² − z_max²), the a_n that "
                    "makes eq. 8 hold for this z_max."
                  : ("For each n, eqs. 8 and 9 give a_n(n) exactly; n moves to " + count_formula +
                     " at a_n(n) until it maps to itself. The plot is that map with its staircase "
                     "from the paper's start to the fixed point.")
                        .c_str());
  if (method_ != current.model.method) {
    const std::string model = "(model: " + std::string(to_string(current.model.method)) + ")";
    same_line_if_fits(ImGui::CalcTextSize(model.c_str()).x);
    ImGui::TextColored(kDimText, "%s", model.c_str());
  }
  if (method_ == Method::paper) {
    tolerance_field(document);
  }
  recompute(current);
  if (trace_.iterates.empty()) {
    wrapped_text("No iteration: %s", describe(trace_.solution, computed_for_).c_str());
    return;
  }
  draw_controls();
  draw_table();
  draw_change();
  // A key in words instead of a legend: in this small plot a legend would cover the data.
  const ImVec4 first = method_ == Method::paper ? ImVec4(kIterateLine) : ImVec4(kGuideLine);
  const ImVec4 second = method_ == Method::paper ? ImVec4(kToleranceBand) : ImVec4(kIterateLine);
  const ImVec4 third = kStairLine;
  if (method_ == Method::paper) {
    ImGui::TextColored(first, "L′/L per iterate");
    const std::string band =
        "the ±" + detail::shortest_number(100.0 * computed_for_.model.length_tolerance) + " % band";
    same_line_if_fits(ImGui::CalcTextSize(band.c_str()).x);
    ImGui::TextColored(second, "%s", band.c_str());
  } else {
    ImGui::TextColored(first, "next n = n");
    same_line_if_fits(ImGui::CalcTextSize("the map (squares: Int[·])").x);
    ImGui::TextColored(second, "the map (squares: Int[·])");
    same_line_if_fits(ImGui::CalcTextSize("the staircase").x);
    ImGui::TextColored(third, "the staircase");
  }
  const float height = std::max(ems(14.0f), ImGui::GetContentRegionAvail().y - 4.0f);
  if (method_ == Method::paper) {
    draw_ratio_plot(height);
  } else {
    draw_map_plot(height);
  }
}

// The paper method's stopping rule, for a class to see the iteration settle over more steps: a
// typed tolerance goes through Document::apply as any input does (one undo step, validated, a
// refused value kept with its reason).
void MethodPanel::tolerance_field(Document& document) {
  const InputSpec& spec = *find_input(kToleranceKey);
  const double tolerance = document.edited().model.length_tolerance;
  ImGui::TextUnformatted("stop when |L′/L − 1| ≤");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ems(6.0f));
  const ImGuiID id = ImGui::GetID("##length tolerance");
  if (ImGui::GetActiveID() != id) {
    std::snprintf(tolerance_text_, sizeof tolerance_text_, "%s",
                  detail::shortest_number(tolerance).c_str());
  }
  const bool enter =
      ImGui::InputText("##length tolerance", tolerance_text_, sizeof tolerance_text_,
                       ImGuiInputTextFlags_AutoSelectAll | ImGuiInputTextFlags_EnterReturnsTrue);
  const int escape_key = ImGui::GetKeyIndex(ImGuiKey_Escape);
  const bool escape = escape_key >= 0 && ImGui::IsKeyPressed(escape_key, false);
  if ((enter || (ImGui::IsItemDeactivated() && !escape)) &&
      std::string(tolerance_text_) != detail::shortest_number(tolerance)) {
    tolerance_problem_ =
        document.apply(Edit::choose(std::string(kToleranceKey), tolerance_text_)).value_or("");
  }
  help_marker(std::string(spec.help).c_str());
  constexpr const char* kPaperButton = "the paper's 5 %";
  same_line_if_fits(button_width(kPaperButton));
  ImGui::BeginDisabled(tolerance == kPaperTolerance);
  if (small_button(kPaperButton)) {
    document.apply(Edit::input(std::string(kToleranceKey), kPaperTolerance));
    tolerance_problem_.clear();
  }
  ImGui::EndDisabled();
  for (const ValidationIssue& issue : document.issues()) {
    if (issue.field == spec.field) {
      ImGui::TextColored(kErrorText, "%s", issue.message.c_str());
    }
  }
  if (!tolerance_problem_.empty()) {
    ImGui::TextColored(kErrorText, "%s", tolerance_problem_.c_str());
  }
}

void MethodPanel::draw_controls() {
  const bool at_start = shown_ <= 1;
  const bool at_end = shown_ >= iterates();
  ImGui::BeginDisabled(at_end);
  if (ImGui::Button("Step")) {
    step();
  }
  ImGui::EndDisabled();
  same_line_if_fits(button_width("Back"));
  ImGui::BeginDisabled(at_start);
  if (ImGui::Button("Back")) {
    back();
  }
  same_line_if_fits(button_width("Reset"));
  if (ImGui::Button("Reset")) {
    reset();
  }
  ImGui::EndDisabled();
  same_line_if_fits(button_width("Run to end"));
  ImGui::BeginDisabled(at_end);
  if (ImGui::Button("Run to end")) {
    run_to_end();
  }
  ImGui::EndDisabled();
  const std::string where = printf_string("iterate %d of %d", shown_, iterates());
  same_line_if_fits(ImGui::CalcTextSize(where.c_str()).x);
  ImGui::TextUnformatted(where.c_str());
}

namespace {

// A coloured line that wraps in a narrow panel instead of running past its edge.
void wrapped(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrapped_text("%s", text.c_str());
  ImGui::PopStyleColor();
}

}  // namespace

// Whose answer the stepper's last iterate is, in words a class reads: Results shows the answer of
// the method the model is set to, which the stepper may or may not be following.
std::string answer_words(Method stepped, Method model) {
  const std::string name = stepped == Method::paper ? "the paper method's" : "the exact method's";
  if (stepped == model) {
    return "This is " + name + " answer, the one Results shows.";
  }
  return "This is " + name + " answer; Results shows " +
         (model == Method::paper ? "the paper method's" : "the exact method's") +
         ", the method set in Parameters.";
}

// Why the shown iterate has its numbers, and why the iteration goes on or stops there; the table
// above shows what changed.
void MethodPanel::draw_change() const {
  const std::vector<Iterate>& all = trace_.iterates;
  const Iterate& it = all[static_cast<std::size_t>(shown_ - 1)];
  const bool last = shown_ == iterates();
  const Solution& s = trace_.solution;
  if (method_ == Method::paper) {
    std::string text;
    if (shown_ == 1) {
      text = s.count_rule ? printf_string(
                                "Start: a_0/a_n = 1.01 h / 0.01 h = 101, n = Int[%.3f] = %d; "
                                "the a-differences alone make h, so eq. 9 gives z_max = %s mm.",
                                it.count_argument, it.n, z_max_text(it.z_max_mm).c_str())
                          : printf_string("Start: no Q7 (stiff), so n = 1; z_max = %s mm.",
                                          z_max_text(it.z_max_mm).c_str());
    } else {
      text = printf_string("a_n ← √(A² − z_max²) = √(%.2f² − %.2f²) = %.2f mm, n = Int[%.3f] = %d.",
                           s.sag_amplitude_mm, all[static_cast<std::size_t>(shown_ - 2)].z_max_mm,
                           it.a_n_mm, it.count_argument, it.n);
    }
    wrapped_text("%s", text.c_str());
    const double miss_percent = 100.0 * std::abs(it.length_ratio - 1.0);
    const double tolerance_percent = 100.0 * computed_for_.model.length_tolerance;
    if (miss_percent <= tolerance_percent) {
      wrapped(kOkText,
              printf_string("|L′/L − 1| = %.3g %% ≤ %.3g %%: stop. %s", miss_percent,
                            tolerance_percent, answer_words(method_, model_method_).c_str()));
    } else if (last) {
      wrapped(kNoteText, printf_string("|L′/L − 1| = %.3g %% > %.3g %%, and the iteration cap is "
                                       "reached.",
                                       miss_percent, tolerance_percent));
    } else {
      wrapped(kNoteText, printf_string("|L′/L − 1| = %.3g %% > %.3g %%: iterate again.",
                                       miss_percent, tolerance_percent));
    }
    return;
  }
  wrapped_text("%sn = %d: %s = Int[%.3f] = %d is the next n.",
               shown_ == 1 && s.count_rule ? "Start at the paper's a_0/a_n = 101. " : "", it.n,
               std::string(wrinkle_law(computed_for_.model.law).count_formula()).c_str(),
               it.count_argument, it.next_n);
  if (!last) {
    wrapped(kNoteText, printf_string("n %d → %d: iterate again.", it.n, it.next_n));
  } else if (s.n_cycle.empty() && it.next_n == it.n) {
    wrapped(kOkText, printf_string("n = %d maps to itself: the fixed point. %s", it.n,
                                   answer_words(method_, model_method_).c_str()));
  } else {
    wrapped(kNoteText, describe(s, computed_for_));
  }
}

// Every iterate so far, scrolled to the newest; two rows show, so the last step's change reads
// row against row, with the numbers that changed in colour.
void MethodPanel::draw_table() {
  const float row_height = ImGui::GetTextLineHeightWithSpacing();
  // Each column as wide as its widest text (the unit under the symbol in the header), so that no
  // number is cut; a panel narrower than the table scrolls it sideways.
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_SizingFixedFit;
  const float scrollbar = ImGui::GetStyle().ScrollbarSize;
  if (!ImGui::BeginTable("iterates", 7, flags, ImVec2(0.0f, row_height * 4.3f + scrollbar))) {
    return;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* title : {"#", "n", "Q", "a_n\n(mm)", "z_max\n(mm)", "L′/L", "next\nn"}) {
    ImGui::TableSetupColumn(title);
  }
  ImGui::TableHeadersRow();
  for (int k = 0; k < shown_; ++k) {
    const Iterate& it = trace_.iterates[static_cast<std::size_t>(k)];
    const Iterate* before = k > 0 ? &trace_.iterates[static_cast<std::size_t>(k - 1)] : nullptr;
    const bool newest = k == shown_ - 1;
    auto cell = [&](const std::string& text, bool changed) {
      ImGui::TableNextColumn();
      if (newest && changed) {
        ImGui::TextColored(kNoteText, "%s", text.c_str());
      } else {
        ImGui::TextUnformatted(text.c_str());
      }
    };
    // Compared as shown: a change below the last digit is no change to the reader.
    auto number = [&](const char* format, double value, double previous) {
      const std::string text = printf_string(format, value);
      cell(text, before != nullptr && text != printf_string(format, previous));
    };
    cell(std::to_string(k + 1), false);
    cell(std::to_string(it.n), before != nullptr && before->n != it.n);
    number("%.4f", it.Q, before ? before->Q : 0.0);
    number("%.2f", it.a_n_mm, before ? before->a_n_mm : 0.0);
    cell(z_max_text(it.z_max_mm),
         before != nullptr && z_max_text(it.z_max_mm) != z_max_text(before->z_max_mm));
    number("%.4f", it.length_ratio, before ? before->length_ratio : 0.0);
    cell(std::to_string(it.next_n), before != nullptr && before->next_n != it.next_n);
    if (newest) {
      ImGui::SetScrollHereY(1.0f);
    }
  }
  ImGui::EndTable();
}

void MethodPanel::draw_ratio_plot(float height) {
  const int count = iterates();
  const double tolerance = computed_for_.model.length_tolerance;
  step_x_.clear();
  ratio_y_.clear();
  for (int k = 0; k < shown_; ++k) {
    step_x_.push_back(k + 1);
    ratio_y_.push_back(trace_.iterates[static_cast<std::size_t>(k)].length_ratio);
  }
  // The band and the line at 1 span every iterate, so the x axis stays put while stepping.
  band_x_ = {0.5, count + 0.5};
  band_lo_ = {1.0 - tolerance, 1.0 - tolerance};
  band_hi_ = {1.0 + tolerance, 1.0 + tolerance};
  one_y_ = {1.0, 1.0};
  if (!ratio_plot_.begin("method L ratio", ImVec2(0.0f, height),
                         PlotAxis{"iterate", false, false, true}, PlotAxis{"L′/L"})) {
    return;
  }
  ratio_plot_.line(nullptr, band_x_, band_lo_, kToleranceBand.u32(), 1.0f);
  ratio_plot_.line(nullptr, band_x_, band_hi_, kToleranceBand.u32(), 1.0f);
  ratio_plot_.line(nullptr, band_x_, one_y_, kGuideLine.u32(), 1.0f);
  ratio_plot_.line(nullptr, step_x_, ratio_y_, kIterateLine.u32(), 2.0f);
  ratio_plot_.markers(nullptr, step_x_, ratio_y_, kIterateLine.u32(), MarkerShape::Circle, 4.0f);
  ratio_plot_.end();
  // The band's fill, under nothing that matters: translucent over the data area.
  const PlotView& view = ratio_plot_.view();
  const ImVec2 lo = view.to_screen(view.x_lo, 1.0 - tolerance);
  const ImVec2 hi = view.to_screen(view.x_hi, 1.0 + tolerance);
  const float top = std::clamp(std::min(lo.y, hi.y), view.min.y, view.max.y);
  const float bottom = std::clamp(std::max(lo.y, hi.y), view.min.y, view.max.y);
  if (bottom > top) {
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(view.min.x, top), ImVec2(view.max.x, bottom),
                                              kBandFill);
  }
}

void MethodPanel::draw_map_plot(float height) {
  map_n_.clear();
  map_count_.clear();
  map_argument_.clear();
  for (const CountMapPoint& point : map_) {
    map_n_.push_back(point.n);
    map_count_.push_back(point.count);
    map_argument_.push_back(point.argument);
  }
  diagonal_ = map_n_;
  // The staircase: from (n, n) on the diagonal up or down to (n, next), across to (next, next).
  stair_x_.clear();
  stair_y_.clear();
  visit_x_.clear();
  visit_y_.clear();
  for (int k = 0; k < shown_; ++k) {
    const Iterate& it = trace_.iterates[static_cast<std::size_t>(k)];
    stair_x_.insert(stair_x_.end(), {static_cast<double>(it.n), static_cast<double>(it.n)});
    stair_y_.insert(stair_y_.end(), {static_cast<double>(it.n), static_cast<double>(it.next_n)});
    visit_x_.push_back(it.n);
    visit_y_.push_back(it.next_n);
  }
  const Iterate& current = trace_.iterates[static_cast<std::size_t>(shown_ - 1)];
  stair_x_.push_back(current.next_n);
  stair_y_.push_back(current.next_n);
  const std::string next_n_axis =
      "next n = " + std::string(wrinkle_law(computed_for_.model.law).count_formula());
  if (!map_plot_.begin("method map", ImVec2(0.0f, height), PlotAxis{"n", false, false, true},
                       PlotAxis{next_n_axis})) {
    return;
  }
  map_plot_.line(nullptr, map_n_, diagonal_, kGuideLine.u32(), 1.0f);
  map_plot_.line(nullptr, map_n_, map_argument_, kIterateLine.u32(), 1.0f);
  map_plot_.markers(nullptr, map_n_, map_count_, kIterateLine.u32(), MarkerShape::Square, 3.0f);
  map_plot_.line(nullptr, stair_x_, stair_y_, kStairLine.u32(), 2.0f);
  map_plot_.markers(nullptr, visit_x_, visit_y_, kStairLine.u32(), MarkerShape::Circle, 4.5f);
  map_plot_.end();
}

}  // namespace foldlab::gui
