// Google Benchmark timing of the plot widget (build/tests/foldlab_gui_bench): the CPU of building
// a fold plot of 20 lines of 200 points, hover search included, in a headless ImGui context.
#include <benchmark/benchmark.h>
#include <imgui.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

#include "app/gui/plot_widget.hpp"
#include "headless_imgui.hpp"

namespace {

void BM_FoldPlotTwentyLines(benchmark::State& state) {
  ImGuiContext* context = foldlab::testing::create_headless_imgui(ImVec2(800, 600));
  ImGui::GetIO().MousePos = ImVec2(300, 200);  // the hover search runs every frame
  std::vector<std::vector<double>> xs(20), ys(20);
  for (std::size_t k = 0; k < 20; ++k) {
    for (int i = 0; i < 200; ++i) {
      xs[k].push_back(-700 + 7.0 * i);
      ys[k].push_back(1400.0 * i / 200 + 30 * std::sin(0.1 * i + static_cast<double>(k)));
    }
  }
  foldlab::gui::Plot plot;
  const foldlab::gui::PlotAxis x_axis{"x (mm)"};
  foldlab::gui::PlotAxis y_axis{"y (mm)"};
  y_axis.flipped = true;
  const ImU32 colours[2] = {IM_COL32(201, 17, 33, 255), IM_COL32(17, 99, 201, 255)};
  for (auto _ : state) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(800, 600));
    ImGui::Begin("bench", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    if (plot.begin("plot", ImVec2(600, 400), x_axis, y_axis)) {
      for (std::size_t k = 0; k < 20; ++k) {
        plot.line(k % 2 == 0 ? "positive fold" : "negative fold", xs[k], ys[k], colours[k % 2]);
      }
      plot.end();
    }
    ImGui::End();
    ImGui::Render();
    benchmark::DoNotOptimize(ImGui::GetDrawData()->TotalVtxCount);
  }
  ImGui::DestroyContext(context);
}
BENCHMARK(BM_FoldPlotTwentyLines)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
