#include "app/gui/panels/calibration_panel.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/presets_dir.hpp"
#include "app/gui/calibration_job.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/renderer.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

std::filesystem::path shipped_measurements_file(std::filesystem::path presets) {
  if (presets.empty()) {
    return {};
  }
  if (!presets.has_filename()) {
    presets = presets.parent_path();  // "…/presets/" names the folder itself
  }
  const std::filesystem::path file = presets.parent_path() / "data" / "paper-measurements.csv";
  std::error_code error;
  return std::filesystem::is_regular_file(file, error) ? file : std::filesystem::path();
}

namespace {

using detail::printf_string;

// The tag beside the button (under it when even the short wording does not fit there), coloured
// by whether eq. 7 is the paper's: the longest wording that fits (the Presets panel is narrow at
// small window sizes).
void form_tag(const Parameters& p) {
  const ModelForm form = model_form(p.model);
  // Conci's law is "eq. 7"; another law goes by its key.
  const std::string law = p.model.law == WrinkleLawKind::conci
                              ? std::string("eq. 7")
                              : std::string(wrinkle_law(p.model.law).key());
  const std::string calibrated =
      printf_string("%s: calibrated, p = %.3g", law.c_str(), p.model.stress_exponent_p);
  const std::string printed =
      law + (p.model.law == WrinkleLawKind::conci ? ": paper's form" : ": as published");
  const std::string own_c = law + ": own c";
  const char* long_text = form == ModelForm::paper           ? printed.c_str()
                          : form == ModelForm::paper_other_c ? own_c.c_str()
                                                             : calibrated.c_str();
  const char* short_text = form == ModelForm::paper
                               ? (p.model.law == WrinkleLawKind::conci ? "paper's" : "published")
                           : form == ModelForm::paper_other_c ? "own c"
                                                              : "calibrated";
  // On the button's line when a wording fits there, else on a line of its own.
  const float line_right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  const float beside = line_right - ImGui::GetItemRectMax().x - ImGui::GetStyle().ItemSpacing.x;
  const bool same_line = ImGui::CalcTextSize(short_text).x <= beside;
  const float available = same_line ? beside : ImGui::GetContentRegionAvail().x;
  if (same_line) {
    ImGui::SameLine();
  }
  const char* text = ImGui::CalcTextSize(long_text).x <= available ? long_text : short_text;
  ImGui::TextColored(form == ModelForm::paper ? kOkText : kNoteText, "%s", text);
}

// A row of the totals table: how often n is right and how far z_max and Q land.
void totals_row(const char* label, const ComparisonSummary& s, bool has_z, bool has_Q) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(label);
  ImGui::TableSetColumnIndex(1);
  ImGui::Text("%d / %d", s.n_exact, s.rows_with_n);
  ImGui::TableSetColumnIndex(2);
  ImGui::Text("%d / %d", s.n_within_one, s.rows_with_n);
  auto percent = [](int column, bool present, double value) {
    ImGui::TableSetColumnIndex(column);
    if (present) {
      ImGui::Text("%.1f %%", 100.0 * value);
    } else {
      ImGui::TextDisabled("-");
    }
  };
  percent(3, has_z, s.median_abs_z_error);
  percent(4, has_z, s.max_abs_z_error);
  percent(5, has_Q, s.median_abs_Q_error);
  percent(6, has_Q, s.max_abs_Q_error);
}

// n, z_max and Q of one model prediction, with their errors against the observation.
void prediction_cells(int first_column, const PublishedComparison& c) {
  ImGui::TableSetColumnIndex(first_column);
  ImGui::Text("%d", c.solution.n);
  ImGui::TableSetColumnIndex(first_column + 1);
  if (c.z_error) {
    ImGui::Text("%.1f (%+.0f%%)", c.solution.z_max_mm, 100.0 * *c.z_error);
  } else {
    ImGui::Text("%.1f", c.solution.z_max_mm);
  }
  ImGui::TableSetColumnIndex(first_column + 2);
  if (c.Q_error) {
    ImGui::Text("%.3f (%+.0f%%)", c.solution.Q, 100.0 * *c.Q_error);
  } else {
    ImGui::Text("%.3f", c.solution.Q);
  }
}

}  // namespace

CalibrationPanel::CalibrationPanel() {
  const std::string path = shipped_measurements_file(app::find_presets_dir()).string();
  std::snprintf(data_path_, sizeof data_path_, "%s", path.c_str());
}

CalibrationPanel::~CalibrationPanel() = default;  // the job cancels and joins its thread

void CalibrationPanel::open_button(const Parameters& current) {
  if (small_button("Fit to measurements...")) {
    open_ = true;
    focus_on_open_ = true;
  }
  if (ImGui::IsItemHovered()) {
    wrapped_tooltip("Fit eq. 7's K (and p) to measured n, z_max and Q.\nNow: %s",
                    describe_model_form(current).c_str());
  }
  form_tag(current);
}

nlohmann::json CalibrationPanel::report() const {
  using nlohmann::json;
  return {{"calibration",
           {{"open", open_},
            {"data_path", std::string(data_path_)},
            {"data_rows", data_ ? json(data_->rows.size()) : json(nullptr)},
            {"data_message", data_message_},
            {"data_message_is_error", data_message_is_error_}}}};
}

void CalibrationPanel::load_data() {
  data_.reset();
  try {
    MeasurementSet set = load_measurements(data_path_);
    int fit = 0;
    std::set<std::string> groups;
    for (const Measurement& m : set.rows) {
      if (m.role == MeasurementRole::fit) {
        ++fit;
        groups.insert(m.group.empty() ? "(none)" : m.group);
      }
    }
    const std::string group_list = detail::join(groups, ", ");
    data_message_ =
        std::to_string(set.rows.size()) + " rows: " + std::to_string(fit) + " to fit (groups " +
        group_list + "), " + std::to_string(set.rows.size() - static_cast<std::size_t>(fit)) +
        (set.rows.size() - static_cast<std::size_t>(fit) == 1 ? " check row" : " check rows") +
        " (never fitted).";
    data_message_is_error_ = false;
    data_ = std::move(set);
  } catch (const MeasurementError& e) {
    data_message_ = std::string("Not loaded:\n") + e.what();
    data_message_is_error_ = true;
  }
}

void CalibrationPanel::start(const Parameters& base, const std::function<void()>& wake) {
  CalibrationOptions options;
  options.fit = fit_choice_ == 0 ? FitConstants::K : FitConstants::K_and_p;
  run_message_.clear();
  job_.start_slices(calibration_steps(*data_, base, options), wake);
}

void CalibrationPanel::collect_finished_run() {
  std::optional<CalibrationReport> finished;
  try {
    finished = job_.take_result();
  } catch (const std::exception& e) {
    run_message_ = std::string("The fit did not run: ") + e.what();
    run_message_is_error_ = true;
    return;
  }
  if (!finished) {
    return;
  }
  if (finished->cancelled) {
    run_message_ = "Cancelled; the previous result (if any) is kept.";
    run_message_is_error_ = false;
  } else {
    report_ = std::move(finished);
    run_message_.clear();
  }
}

// A floating window over the tiled panels: it opens on demand from the Presets panel.
void CalibrationPanel::place_window() {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0.14f * display.x, 0.06f * display.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(0.72f * display.x, 0.88f * display.y), ImGuiCond_FirstUseEver);
  if (focus_on_open_) {
    ImGui::SetNextWindowFocus();
    focus_on_open_ = false;
  }
}

void CalibrationPanel::constants_section(const Parameters& edited, const Preset& loaded) {
  section("The model's constants");
  ImGui::TextColored(kDimText, "now:");
  ImGui::SameLine();
  wrapped_text("%s", describe_model_form(edited).c_str());
  ImGui::TextColored(kDimText, "preset \"%s\" carries:", loaded.name.c_str());
  ImGui::SameLine();
  wrapped_text("%s", describe_model_form(loaded.parameters).c_str());
}

void CalibrationPanel::measurements_section(FileDialog& files, UiStatus& status) {
  section("Measurements");
  if (!data_ && !data_message_is_error_ && data_message_.empty() && data_path_[0] != '\0') {
    load_data();  // the shipped paper data, on first opening
  }
  ImGui::SetNextItemWidth(-button_width("Load") - button_width("Choose...") -
                          2.0f * ImGui::GetStyle().ItemSpacing.x);
  ImGui::InputTextWithHint("##data", "measurements file, CSV or JSON", data_path_,
                           sizeof data_path_);
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    load_data();
  }
  ImGui::SameLine();
  if (ImGui::Button("Choose...")) {
    files.open({FileDialog::Mode::open,
                kChooseDataModal,
                "",
                {".csv", ".json"},
                [this](const std::filesystem::path& path) -> std::optional<std::string> {
                  std::snprintf(data_path_, sizeof data_path_, "%s", path.string().c_str());
                  load_data();
                  if (data_message_is_error_) {
                    return data_message_;
                  }
                  return std::nullopt;
                }},
               status);
  }
  if (!data_message_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, data_message_is_error_ ? kErrorText : kDimText);
    wrapped_text("%s", data_message_.c_str());
    ImGui::PopStyleColor();
  }
}

void CalibrationPanel::fit_section(const Parameters& edited, const std::function<void()>& wake) {
  section("Fit");
  ImGui::RadioButton("K alone (p as now)", &fit_choice_, 0);
  ImGui::SameLine();
  ImGui::RadioButton("K and p (s -> s^p)", &fit_choice_, 1);
  ImGui::TextColored(
      kDimText, "Every row is solved with the current model settings: %s method, l = %s, Int = %s.",
      std::string(to_string(edited.model.method)).c_str(),
      std::string(to_string(edited.model.span_rule)).c_str(),
      std::string(to_string(edited.model.int_rounding)).c_str());
  const bool valid = validate(edited).empty();
  if (job_.pending()) {
    ImGui::ProgressBar(static_cast<float>(job_.progress()), ImVec2(-ems(7.0f), 0.0f));
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      job_.cancel();
    }
  } else {
    ImGui::BeginDisabled(!data_ || !valid);
    if (ImGui::Button("Run the fit")) {
      start(edited, wake);
    }
    ImGui::EndDisabled();
    if (!valid) {
      ImGui::SameLine();
      ImGui::TextColored(kErrorText, "the current parameters are not valid");
    }
  }
  if (!run_message_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, run_message_is_error_ ? kErrorText : kNoteText);
    wrapped_text("%s", run_message_.c_str());
    ImGui::PopStyleColor();
  }
}

void CalibrationPanel::draw(PanelContext& context) {
  Document& document = context.document;
  collect_finished_run();
  if (!open_) {
    return;
  }
  place_window();
  if (ImGui::Begin(window_label().c_str(), &open_)) {
    context.renderer.fill_window_background();  // the style's window background is transparent
    constants_section(document.edited(), document.loaded());
    measurements_section(context.files, context.status);
    fit_section(document.edited(), context.wake);
    if (report_) {
      apply_section(document);
      results_section();
    }
  }
  ImGui::End();
}

void CalibrationPanel::apply_section(Document& document) {
  const FittedConstants& f = report_->fitted;
  const std::string label = "Apply K = " + printf_string("%.4g", f.K) +
                            ", p = " + printf_string("%.4g", f.p) + " to the current parameters";
  if (ImGui::Button(label.c_str())) {
    document.apply(Edit::assign({{"p", f.p}, {"K", f.K}}));
  }
  if (ImGui::IsItemHovered()) {
    wrapped_tooltip(
        "Sets c = K (1 − ν²) at the current ν, and p. Save a preset to keep them.\nThe "
        "paper's form is p = 1, c = 26.9.");
  }
}

void CalibrationPanel::results_section() {
  const CalibrationReport& r = *report_;
  const FittedConstants& f = r.fitted;
  section("Result");
  ImGui::Text("Fitted (%s, %s method): K = %.4g, p = %.4g   (c = %.4g at ν = %.3g)",
              std::string(to_string(r.fit)).c_str(),
              std::string(to_string(r.base.model.method)).c_str(), f.K, f.p,
              with_constants(r.base, f.K, f.p).model.load_constant_c, r.base.fabric.poisson_ratio);
  const std::string K_high = std::isinf(f.K_high) ? "inf" : printf_string("%.4g", f.K_high);
  wrapped_text(
      "The score stays the same for K in [%.4g, %s) at this p, and for p in [%.4g, %.4g] at this "
      "K: n misses %d (by more than one %d), mean capped error %.1f %%.",
      f.K_low, K_high.c_str(), f.p_low, f.p_high, f.score.n_missed,
      f.score.n_missed_by_more_than_one, 100.0 * f.score.mean_relative_error);

  bool fit_z = false, fit_Q = false, check_z = false, check_Q = false;
  for (const CalibrationRow& row : r.rows) {
    const bool fit = row.measurement.role == MeasurementRole::fit;
    (fit ? fit_z : check_z) |= row.measurement.observed.z_max_mm.has_value();
    (fit ? fit_Q : check_Q) |= row.measurement.observed.Q.has_value();
  }
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
  if (ImGui::BeginTable("totals", 7, flags)) {
    for (const char* heading :
         {"", "n exact", "n ±1", "z_max median", "z_max max", "Q median", "Q max"}) {
      ImGui::TableSetupColumn(heading);
    }
    ImGui::TableHeadersRow();
    totals_row("base constants (no fit)", r.baseline_fit_rows, fit_z, fit_Q);
    totals_row("in-sample fit", r.in_sample, fit_z, fit_Q);
    if (r.fit_row_count >= 2) {
      totals_row("held out: leave-one-out", r.leave_one_out, fit_z, fit_Q);
    }
    if (!r.group_splits.empty()) {
      totals_row("held out: fit on the other groups", r.group_split_test, fit_z, fit_Q);
    }
    if (r.check_row_count > 0) {
      totals_row("check rows (never fitted)", r.check_rows, check_z, check_Q);
    }
    ImGui::EndTable();
  }
  ImGui::TextColored(kDimText,
                     "Fit rows. Held out: each row predicted by a fit that never saw it. If the "
                     "held-out rows are much worse than in-sample, the fit is mostly noise.");

  if (ImGui::BeginTable("rows", 10, flags | ImGuiTableFlags_ScrollY)) {
    ImGui::TableSetupScrollFreeze(1, 1);
    for (const char* heading : {"row", "n", "z_max", "Q", "fitted n", "z_max (mm)", "Q",
                                "held-out n", "z_max (mm)", "Q"}) {
      ImGui::TableSetupColumn(heading);
    }
    ImGui::TableHeadersRow();
    for (const CalibrationRow& row : r.rows) {
      const Measurement& m = row.measurement;
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::Text("%s%s",
                  m.name.empty() ? ("row " + std::to_string(m.row)).c_str() : m.name.c_str(),
                  m.role == MeasurementRole::check ? " (check)" : "");
      ImGui::TableSetColumnIndex(1);
      m.observed.n ? ImGui::Text("%d", *m.observed.n) : ImGui::TextDisabled("-");
      ImGui::TableSetColumnIndex(2);
      m.observed.z_max_mm ? ImGui::Text("%g", *m.observed.z_max_mm) : ImGui::TextDisabled("-");
      ImGui::TableSetColumnIndex(3);
      m.observed.Q ? ImGui::Text("%.2f", *m.observed.Q) : ImGui::TextDisabled("-");
      prediction_cells(4, row.fitted);
      if (row.held_out) {
        prediction_cells(7, *row.held_out);
      }
    }
    ImGui::EndTable();
  }
}

void CalibrationPanel::report(nlohmann::json& state, PanelContext& /*context*/) const {
  state.update(report());
}

}  // namespace foldlab::gui
