#include "core/field/live_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace foldlab::field {
namespace {

// Two requests share a mesh when their flat cuts and resolutions do: only the supports' pinned
// places or the material changed (d, t, E, w, nu).
bool same_mesh(const FieldInputs& a, const FieldInputs& b) {
  if (a.resolution != b.resolution || a.outline.top_mm != b.outline.top_mm ||
      a.outline.bottom_mm != b.outline.bottom_mm ||
      a.outline.supports.size() != b.outline.supports.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.outline.supports.size(); ++i) {
    if (a.outline.supports[i].at_mm != b.outline.supports[i].at_mm) {
      return false;
    }
  }
  return true;
}

std::string gave_up(double residual, int iterations) {
  char text[160];
  std::snprintf(text, sizeof text,
                "the field did not converge: relative force residual %.1e after %d Newton steps",
                residual, iterations);
  return text;
}

bool finite(const Solution& s) {
  for (const Eigen::Vector2d& p : s.positions_mm) {
    if (!p.allFinite()) {
      return false;
    }
  }
  return std::isfinite(s.relative_residual);
}

}  // namespace

struct LiveField::Work {
  FieldInputs inputs;  // the mesh's cut and resolution; the rest may have moved on since
  Solver solver;
  std::optional<Solution> iterate;  // the latest, converged or not; none: start cold
  bool cold_tried = false;          // a cold start was made for the wanted field
  bool done = false;                // converged or given up for the wanted field
};

LiveField::LiveField() = default;
LiveField::~LiveField() = default;
LiveField::LiveField(LiveField&&) noexcept = default;
LiveField& LiveField::operator=(LiveField&&) noexcept = default;

void LiveField::request(const FieldInputs& inputs) {
  if (latest_ && *latest_ == inputs) {
    return;
  }
  latest_ = inputs;
  try {
    check_outline(inputs.outline);
  } catch (const OutlineError& e) {
    // Said at once, whatever is under way; the last field stays on show.
    refusal_ = e.what();
    wanted_ = inputs;
    work_.reset();
    return;
  }
  // Inputs that change every frame (played, animated, dragged fast) would restart the solve every
  // frame and none would end: the field on show would be of inputs seconds old. A solve under
  // way is finished first, unless it has taken long; the newest inputs are solved after it.
  if (working() && iterations_ > 0 && iterations_ < kFinishBeforeNewer) {
    return;
  }
  start(inputs);
}

void LiveField::start(const FieldInputs& inputs) {
  wanted_ = inputs;
  refusal_.clear();
  iterations_ = 0;
  if (work_ && same_mesh(work_->inputs, inputs)) {
    work_->done = false;
    work_->cold_tried = false;
    if (work_->iterate && !finite(*work_->iterate)) {
      work_->iterate.reset();
    }
    return;
  }
  try {
    Solver solver(make_mesh(inputs.outline, inputs.resolution));
    std::optional<Solution> start_from;
    // From the latest iterate when it is sound, else from the field on show.
    if (work_ && work_->iterate && finite(*work_->iterate)) {
      start_from = transferred_start(work_->solver.mesh(), *work_->iterate, solver.mesh());
    } else if (shown_) {
      start_from = transferred_start(shown_->mesh, shown_->report.solution, solver.mesh());
    }
    work_ = std::make_unique<Work>(
        Work{inputs, std::move(solver), std::move(start_from), false, false});
  } catch (const OutlineError& e) {
    refusal_ = e.what();
    work_.reset();
  }
}

bool LiveField::working() const {
  if (!latest_ || current() || !refusal_.empty()) {
    return false;
  }
  return (work_ && !work_->done) || !(wanted_ && *wanted_ == *latest_);
}

bool LiveField::current() const {
  return shown_ && latest_ && shown_->inputs == *latest_;
}

bool LiveField::step(double budget_ms, double first_budget_ms) {
  if (!working()) {
    return false;
  }
  // The solve under way ended (or was asked for before newer inputs and has taken long): on to
  // the newest.
  if (!(wanted_ && *wanted_ == *latest_) &&
      (!work_ || work_->done || iterations_ >= kFinishBeforeNewer)) {
    start(*latest_);
    if (!working()) {
      return false;
    }
  }
  Work& w = *work_;
  const FieldInputs& in = *wanted_;
  const std::vector<Eigen::Vector2d> targets = support_targets(in.outline);
  SolveOptions options;
  options.time_budget_ms = budget_ms;
  options.max_iterations = std::max(1, kMaxIterations - iterations_);
  Solution solution;
  const bool cold = !w.iterate;
  if (!cold && w.iterate->resume_stiffness_N_per_mm > 0.0) {
    solution = resume_cold(w.solver, in.outline, in.material, *w.iterate, options);
  } else if (!cold) {
    solution = w.solver.solve(in.material, targets, options, &*w.iterate);
  } else {
    // A cold start climbs the coarse-to-fine ladder: its first hundred damped steps are cheapest
    // on the coarse meshes. Within the slice, so that a stiff cloth's ladder does not hold a
    // frame for seconds; where the slice ends, the next ones go on from the finest mesh's iterate.
    options.max_iterations = kMaxIterations;
    if (!shown_ && budget_ms > 0.0) {
      options.time_budget_ms = std::max(budget_ms, first_budget_ms);
    }
    solution = solve_cold(w.solver, in.outline, in.material, in.resolution, options);
    w.cold_tried = true;
  }
  iterations_ += solution.iterations;
  residual_ = solution.relative_residual;
  if (solution.converged) {
    w.done = true;
    w.iterate = solution;
    auto solved = std::make_shared<SolvedField>();
    solved->inputs = in;
    solved->mesh = w.solver.mesh();
    solved->report = report_field(w.solver, std::move(solution), in.outline, in.material);
    shown_ = std::move(solved);
    ++shown_count_;
    return true;
  }
  // A cold start cut short by its slice goes on from where it stopped, softened if it was.
  const bool cut_short =
      (cold || solution.resume_stiffness_N_per_mm > 0.0) && budget_ms > 0.0 && finite(solution);
  const bool spent = (cold && !cut_short) || iterations_ >= kMaxIterations || !finite(solution);
  if (!spent) {
    w.iterate = std::move(solution);
    return false;
  }
  if (!w.cold_tried) {
    // A warm start can lie too far from the new field (a support moved a long way): once more
    // from the flat cut.
    w.iterate.reset();
    iterations_ = 0;
    return false;
  }
  w.iterate.reset();
  w.done = true;
  if (!(*wanted_ == *latest_)) {
    start(*latest_);  // given up for inputs already left behind: on to the newest
    return false;
  }
  refusal_ = gave_up(residual_, iterations_);
  return false;
}

std::optional<SolvedField> solve_field(const FieldInputs& inputs, std::string& refusal) {
  LiveField live;
  live.request(inputs);
  while (live.working()) {
    live.step(0.0);
  }
  refusal = live.refusal();
  if (!live.current()) {
    return std::nullopt;
  }
  return *live.shown();
}

}  // namespace foldlab::field
