// The plot widget: tick helpers as plain functions, the widget driven through a headless ImGui
// context (no window, no GL) and judged by the vertices it leaves in ImGui's draw data.
#include <gtest/gtest.h>

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/gui/plot_widget.hpp"
#include "headless_imgui.hpp"

namespace foldlab::gui {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// True when step is 1, 2 or 5 times a power of ten.
bool is_nice_step(double step) {
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  return std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
         std::abs(mantissa - 5) < 1e-6;
}

TEST(PlotTicks, ZeroTo1400) {
  EXPECT_EQ(nice_ticks(0, 1400, 7), (std::vector<double>{0, 200, 400, 600, 800, 1000, 1200, 1400}));
}

TEST(PlotTicks, SymmetricRange) {
  EXPECT_EQ(nice_ticks(-650, 650, 7), (std::vector<double>{-600, -400, -200, 0, 200, 400, 600}));
}

TEST(PlotTicks, DecimalStepsAreExactDecimals) {
  // 3 * 0.2 would be 0.6000000000000001 and print as such.
  EXPECT_EQ(nice_ticks(0, 1, 5), (std::vector<double>{0, 0.2, 0.4, 0.6, 0.8, 1}));
}

TEST(PlotTicks, ReversedRangeGivesAscendingTicks) {
  EXPECT_EQ(nice_ticks(1400, 0, 7), nice_ticks(0, 1400, 7));
}

TEST(PlotTicks, EqualBoundsGiveOneTick) {
  EXPECT_EQ(nice_ticks(3.5, 3.5, 7), (std::vector<double>{3.5}));
}

TEST(PlotTicks, NonFiniteBoundsGiveNoTicks) {
  EXPECT_TRUE(nice_ticks(kNaN, 1, 5).empty());
  EXPECT_TRUE(nice_ticks(0, kInf, 5).empty());
}

TEST(PlotTicks, TinyAndHugeRanges) {
  const struct {
    double lo, hi;
    int target;
  } cases[] = {{0, 1e-9, 5},       {1.0, 1.0 + 1e-10, 5}, {-3e-7, -1e-7, 4},  {0, 3e12, 6},
               {-1e308, 1e308, 5}, {1399.9, 1400.3, 7},   {-0.013, 0.0021, 6}};
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::Message() << "[" << c.lo << ", " << c.hi << "] target " << c.target);
    const std::vector<double> t = nice_ticks(c.lo, c.hi, c.target);
    ASSERT_GE(t.size(), 2u);
    EXPECT_LE(t.size(), static_cast<std::size_t>(2 * c.target + 1));
    const double step = t[1] - t[0];
    EXPECT_TRUE(is_nice_step(step)) << step;
    for (std::size_t i = 0; i < t.size(); ++i) {
      EXPECT_TRUE(std::isfinite(t[i]));
      EXPECT_GE(t[i], c.lo - std::abs(c.lo) * 1e-12);
      EXPECT_LE(t[i], c.hi + std::abs(c.hi) * 1e-12);
      if (i > 0) {
        EXPECT_NEAR(t[i] - t[i - 1], step, step * 1e-6);
      }
    }
  }
  EXPECT_EQ(nice_ticks(0, 3e12, 6),
            (std::vector<double>{0, 5e11, 1e12, 1.5e12, 2e12, 2.5e12, 3e12}));
}

TEST(PlotTicks, LogAxisDecadesAndMantissas) {
  EXPECT_EQ(log_ticks(1, 1e6, 7), (std::vector<double>{1, 10, 100, 1e3, 1e4, 1e5, 1e6}));
  EXPECT_EQ(log_ticks(1, 100, 7), (std::vector<double>{1, 2, 5, 10, 20, 50, 100}));
  EXPECT_EQ(log_ticks(1, 1e30, 5), (std::vector<double>{1, 1e7, 1e14, 1e21, 1e28}));
  // Inside one decade a log axis is nearly linear.
  EXPECT_EQ(log_ticks(2, 4, 5), (std::vector<double>{2, 2.5, 3, 3.5, 4}));
  EXPECT_TRUE(log_ticks(-5, -1, 5).empty());
}

TEST(PlotTicks, Labels) {
  EXPECT_EQ(format_tick(1400, 200), "1400");
  EXPECT_EQ(format_tick(-600, 200), "-600");
  EXPECT_EQ(format_tick(0.6, 0.2), "0.6");
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(-1e-17, 0.2), "0");  // rounding noise around zero
  EXPECT_EQ(format_tick(-0.0, 1), "0");
  EXPECT_EQ(format_tick(0, 0.05), "0");  // not "0.00"
  EXPECT_EQ(format_tick(1.5e9, 5e8), "1.5e+09");
  EXPECT_EQ(format_tick(1e9, 1e9), "1e+09");
  EXPECT_EQ(format_tick(2e-6, 1e-6), "2e-06");
  EXPECT_EQ(format_tick(1.00000000002, 2e-11), "1.00000000002");
}

// Hand-computed: labels 7 px a character with 6 px between them. 0..3000 over 300 px: steps of
// 200 put "1000" and "1200" (28 px each) 20 px apart, short of 34; steps of 500 are 50 px apart.
TEST(PlotTicks, FittedTicksAreRoundAndTheirLabelsNeverOverlap) {
  const auto seven_px = [](const std::string& label) {
    return 7.0f * static_cast<float>(label.size());
  };
  AxisTicks t = fitted_ticks(0, 3000, false, 300, seven_px, 6, 12);
  EXPECT_EQ(t.values, (std::vector<double>{0, 500, 1000, 1500, 2000, 2500, 3000}));
  EXPECT_EQ(t.labels.back(), "3000");  // written out, not 3e+03
  // Over 100 px, 1000 apart is 33.3 px, short of 34: two ticks, 2000 apart.
  EXPECT_EQ(fitted_ticks(0, 3000, false, 100, seven_px, 6, 12).values,
            (std::vector<double>{0, 2000}));
  // Over 30 px no two neighbours fit (0 and 2000 are 20 px apart, short of 23.5), but the ends
  // 0 and 3000 are 30 px apart: the axis still says from where to where.
  t = fitted_ticks(0, 3000, false, 30, seven_px, 6, 12);
  EXPECT_EQ(t.values, (std::vector<double>{0, 3000}));
  EXPECT_EQ(t.labels, (std::vector<std::string>{"0", "3000"}));
  // Over 20 px not even the ends fit: 2000 alone, nearer the middle (13.3 px).
  t = fitted_ticks(0, 3000, false, 20, seven_px, 6, 12);
  EXPECT_EQ(t.values, (std::vector<double>{2000}));
  // A font twice as large over 300 px: 500 apart (50 px) is short of 62, 1000 apart fits.
  const auto fourteen_px = [](const std::string& label) {
    return 14.0f * static_cast<float>(label.size());
  };
  EXPECT_EQ(fitted_ticks(0, 3000, false, 300, fourteen_px, 12, 12).values,
            (std::vector<double>{0, 1000, 2000, 3000}));
  // A log axis over 100..10000 g/m², 150 px a decade: 1, 2 and 5 fit (100 to 200 is 45 px).
  t = fitted_ticks(100, 10000, true, 300, seven_px, 6, 12);
  EXPECT_EQ(t.values, (std::vector<double>{100, 200, 500, 1000, 2000, 5000, 10000}));
  EXPECT_EQ(t.labels,
            (std::vector<std::string>{"100", "200", "500", "1000", "2000", "5000", "10000"}));
  // 40 px a decade: 100 to 200 is 12 px, so decades only ("1000" to "10000" needs 37.5 px).
  EXPECT_EQ(fitted_ticks(100, 10000, true, 80, seven_px, 6, 12).values,
            (std::vector<double>{100, 1000, 10000}));
  // Every label reads back as its tick, a lone one too: a Q axis over 1.23..1.6 a few lines high
  // once labelled its only tick, 1.4, "1" (read as Q = 1 by a class).
  const auto line_px = [](const std::string&) { return 14.0f; };
  int lone = 0;
  for (const auto& [lo, hi] : {std::pair{1.23, 1.6}, std::pair{0.011, 0.0165},
                               std::pair{1210.0, 1480.0}, std::pair{-2.6, -1.3}}) {
    for (double length_px = 8; length_px <= 200; length_px += 1) {
      t = fitted_ticks(lo, hi, false, length_px, line_px, 4, 12);
      lone += t.values.size() == 1 ? 1 : 0;
      for (std::size_t i = 0; i < t.values.size(); ++i) {
        EXPECT_NEAR(std::strtod(t.labels[i].c_str(), nullptr), t.values[i],
                    1e-9 * std::abs(t.values[i]))
            << t.labels[i] << " over " << lo << ".." << hi << " in " << length_px << " px";
      }
    }
  }
  EXPECT_GT(lone, 10) << "short axes show one tick";
}

TEST(WholeTicks, AtLeastThreeWholeNumbersWhereTheyFit) {
  const auto line_px = [](const std::string&) { return 14.0f; };
  // n from 2 to 8 (autoscaled to 1.7..8.3) over 100 px: a step of 1 is 15.2 px apart, short of
  // 14 + 4; 2 apart (30.3 px) fits.
  EXPECT_EQ(whole_ticks(1.7, 8.3, 100, line_px, 4, 12), (std::vector<double>{2, 4, 6, 8}));
  // Over 40 px, 2 apart is 12.1 px and 5 apart leaves 5 alone: the ends and the middle, 2, 5 and
  // 8, 18.2 px apart, fit.
  EXPECT_EQ(whole_ticks(1.7, 8.3, 40, line_px, 4, 12), (std::vector<double>{2, 5, 8}));
  // n from 1 to 30 over 200 px with at most 12: 5 apart (34.5 px) is the densest that fits.
  EXPECT_EQ(whole_ticks(1, 30, 200, line_px, 4, 12), (std::vector<double>{5, 10, 15, 20, 25, 30}));
  // Never between whole numbers, however long the axis.
  EXPECT_EQ(whole_ticks(2.2, 3.8, 500, line_px, 4, 12), (std::vector<double>{3}));
  // Too short for three: the densest that fits.
  EXPECT_EQ(whole_ticks(1.7, 8.3, 20, line_px, 4, 12), (std::vector<double>{5}));
}

// --- the widget, headless ---------------------------------------------------------------------

constexpr ImU32 kColA = IM_COL32(201, 17, 33, 255);
constexpr ImU32 kColB = IM_COL32(17, 99, 201, 255);
constexpr ImU32 kColC = IM_COL32(33, 201, 17, 255);
const ImVec2 kPlotSize{600, 400};

struct Vertex {
  ImVec2 pos;
  ImVec4 clip;
};

class PlotWidget : public ::testing::Test {
 protected:
  void SetUp() override {
    context_ = foldlab::testing::create_headless_imgui(ImVec2(800, 600));
    ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  }
  void TearDown() override { ImGui::DestroyContext(context_); }

  // One frame with `body` inside a borderless window covering the display. Input (io.MousePos,
  // io.MouseDown, io.MouseWheel, io.KeyShift/KeyCtrl) is set by the caller beforehand.
  void frame(const std::function<void()>& body) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(800, 600));
    ImGui::Begin(
        "test", nullptr,
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    body();
    ImGui::End();
    ImGui::Render();
  }

  // A frame with the standard two lines, A and B (or the given data).
  std::optional<PlotHit> frame_ab(const std::function<void(Plot&)>& extra = {}) {
    std::optional<PlotHit> hit;
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
      plot_.line("A", ax_, ay_, kColA);
      plot_.line("B", bx_, by_, kColB);
      if (extra)
        extra(plot_);
      hit = plot_.end();
    });
    return hit;
  }

  // Every vertex of the given colour that ImGui would render, with its command's clip rect.
  static std::vector<Vertex> vertices_of(ImU32 colour) {
    std::vector<Vertex> out;
    const ImDrawData* dd = ImGui::GetDrawData();
    for (int l = 0; l < dd->CmdListsCount; ++l) {
      const ImDrawList* list = dd->CmdLists[l];
      for (const ImDrawCmd& cmd : list->CmdBuffer) {
        for (unsigned k = cmd.IdxOffset; k < cmd.IdxOffset + cmd.ElemCount; ++k) {
          const ImDrawVert& v = list->VtxBuffer[static_cast<int>(cmd.VtxOffset) +
                                                list->IdxBuffer[static_cast<int>(k)]];
          if (v.col == colour)
            out.push_back({v.pos, cmd.ClipRect});
        }
      }
    }
    return out;
  }

  static ImVec2 centroid(const std::vector<Vertex>& vs) {
    ImVec2 c(0, 0);
    for (const Vertex& v : vs) {
      c.x += v.pos.x / static_cast<float>(vs.size());
      c.y += v.pos.y / static_cast<float>(vs.size());
    }
    return c;
  }

  static bool in_legend(const PlotView& v, ImVec2 p) {
    return p.x >= v.legend_min.x && p.x <= v.legend_max.x && p.y >= v.legend_min.y &&
           p.y <= v.legend_max.y;
  }

  static void move_mouse(ImVec2 p) { ImGui::GetIO().MousePos = p; }

  ImGuiContext* context_ = nullptr;
  Plot plot_;
  PlotAxis x_axis_{"x (mm)"};
  PlotAxis y_axis_{"y (mm)"};
  std::vector<double> ax_{0, 100, 200, 300}, ay_{0, 50, 20, 80};
  std::vector<double> bx_{0, 150, 300}, by_{100, 40, 10};
};

TEST_F(PlotWidget, AutoscalesToAllSeriesWithMargin) {
  frame_ab();
  const PlotView& v = plot_.view();
  EXPECT_TRUE(v.x_auto);
  EXPECT_TRUE(v.y_auto);
  EXPECT_NEAR(v.x_lo, -15, 1e-9);  // [0, 300] plus 5 % each side
  EXPECT_NEAR(v.x_hi, 315, 1e-9);
  EXPECT_NEAR(v.y_lo, -5, 1e-9);  // [0, 100]
  EXPECT_NEAR(v.y_hi, 105, 1e-9);
  // The data area lies inside the requested widget size, leaving room for labels.
  EXPECT_GT(v.min.x, 8.0f);
  EXPECT_LT(v.max.x, 8.0f + kPlotSize.x + 1);
  EXPECT_GT(v.max.y - v.min.y, kPlotSize.y * 0.7f);
  EXPECT_LT(v.max.y, 8.0f + kPlotSize.y + 1);
}

TEST_F(PlotWidget, LinesAreDrawnInTheirColoursInsideThePlotRect) {
  frame_ab();
  const PlotView& v = plot_.view();
  for (const ImU32 colour : {kColA, kColB}) {
    const std::vector<Vertex> vs = vertices_of(colour);
    ASSERT_GE(vs.size(), 8u) << std::hex << colour;
    for (const Vertex& vx : vs) {
      if (in_legend(v, vx.pos))
        continue;  // the legend's swatch, under the axes
      EXPECT_GE(vx.pos.x, v.min.x);
      EXPECT_LE(vx.pos.x, v.max.x);
      EXPECT_GE(vx.pos.y, v.min.y);
      EXPECT_LE(vx.pos.y, v.max.y);
      EXPECT_NEAR(vx.clip.x, v.min.x, 0.5f);  // scissored to the data area
      EXPECT_NEAR(vx.clip.y, v.min.y, 0.5f);
      EXPECT_NEAR(vx.clip.z, v.max.x, 0.5f);
      EXPECT_NEAR(vx.clip.w, v.max.y, 0.5f);
    }
  }
  // The line's end points are where the view maps them.
  const std::vector<Vertex> a = vertices_of(kColA);
  const ImVec2 first = v.to_screen(ax_.front(), ay_.front());
  EXPECT_TRUE(std::any_of(a.begin(), a.end(), [&](const Vertex& vx) {
    return std::abs(vx.pos.x - first.x) < 2 && std::abs(vx.pos.y - first.y) < 2;
  }));
}

// A line is as thick beside large text as beside the usual: at four times the text size (a
// room's 200 %, a picture's text) a 2 px fold line is no hair.
TEST_F(PlotWidget, LinesGrowWithTheTextSize) {
  const std::vector<double> xs{0, 300}, ys{50, 50};
  const auto drawn_height = [&](float font_scale) {
    frame([&] {
      ImGui::SetWindowFontScale(font_scale);
      ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
      plot_.line(nullptr, xs, ys, kColC, 2.0f);
      plot_.end();
    });
    // With the anti-aliased fringe, which has the line's colour at no opacity.
    float lo = FLT_MAX, hi = -FLT_MAX;
    for (const Vertex& v : vertices_of(kColC)) {
      lo = std::min(lo, v.pos.y);
      hi = std::max(hi, v.pos.y);
    }
    for (const Vertex& v : vertices_of(kColC & ~IM_COL32_A_MASK)) {
      lo = std::min(lo, v.pos.y);
      hi = std::max(hi, v.pos.y);
    }
    return hi - lo;
  };
  // ImGui's default font is 13 px: 13 x 4 = 52 px text draws a 2 px line 2 x 52 / 15 = 6.9 px.
  const float usual = drawn_height(1.0f);
  const float large = drawn_height(4.0f);
  EXPECT_GT(usual, 0.0f);
  EXPECT_NEAR(large - usual, 6.9f - 2.0f, 1.0f) << usual << " px at the usual size";
}

TEST_F(PlotWidget, ZoomedInLinesAreCutToThePlotRect) {
  frame_ab();
  move_mouse(plot_.view().to_screen(150, 50));
  ImGui::GetIO().MouseWheel = 8;  // 1.25^8: about 6x in
  frame_ab();
  ImGui::GetIO().MouseWheel = 0;
  const PlotView& v = plot_.view();
  ASSERT_GT(v.x_lo, 0);  // the data now extends past the plot on both sides
  ASSERT_LT(v.x_hi, 300);
  const std::vector<Vertex> vs = vertices_of(kColA);
  ASSERT_FALSE(vs.empty());
  const float slack = 1.5f + 2.0f;  // line width and anti-aliasing around the cut
  for (const Vertex& vx : vs) {
    if (in_legend(v, vx.pos))
      continue;
    EXPECT_GE(vx.pos.x, v.min.x - slack);
    EXPECT_LE(vx.pos.x, v.max.x + slack);
    EXPECT_GE(vx.pos.y, v.min.y - slack);
    EXPECT_LE(vx.pos.y, v.max.y + slack);
  }
}

TEST_F(PlotWidget, FlippedYAxisPutsLargerValuesLower) {
  const double xs[] = {5}, y_small[] = {0}, y_large[] = {10};
  for (const bool flipped : {true, false}) {
    SCOPED_TRACE(flipped ? "flipped" : "not flipped");
    y_axis_.flipped = flipped;
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
      plot_.markers(nullptr, xs, y_small, kColA, MarkerShape::Square);
      plot_.markers(nullptr, xs, y_large, kColB, MarkerShape::Square);
      plot_.end();
    });
    const ImVec2 small = centroid(vertices_of(kColA)), large = centroid(vertices_of(kColB));
    ASSERT_FALSE(vertices_of(kColA).empty());
    ASSERT_FALSE(vertices_of(kColB).empty());
    if (flipped)
      EXPECT_GT(large.y, small.y + 100);
    else
      EXPECT_LT(large.y, small.y - 100);
    EXPECT_NEAR(large.x, small.x, 0.5f);
    EXPECT_NEAR(plot_.view().to_screen(5, 10).y, large.y, 1.0f);
  }
}

TEST_F(PlotWidget, LogAxisSpacesDecadesEvenly) {
  x_axis_.log = true;
  const double x1[] = {10}, x2[] = {100}, x3[] = {1000}, y[] = {1};
  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    plot_.markers(nullptr, x1, y, kColA, MarkerShape::Plus);
    plot_.markers(nullptr, x2, y, kColB, MarkerShape::Plus);
    plot_.markers(nullptr, x3, y, kColC, MarkerShape::Plus);
    plot_.end();
  });
  const float a = centroid(vertices_of(kColA)).x, b = centroid(vertices_of(kColB)).x,
              c = centroid(vertices_of(kColC)).x;
  EXPECT_GT(c - a, 300);
  EXPECT_NEAR(b, (a + c) / 2, 1.0f);
}

TEST_F(PlotWidget, HoverReturnsTheNearestPoint) {
  frame_ab();
  const PlotView v = plot_.view();
  const ImVec2 a2 = v.to_screen(ax_[2], ay_[2]);
  move_mouse(ImVec2(a2.x + 3, a2.y - 2));
  std::optional<PlotHit> hit = frame_ab();
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->series, 0);
  EXPECT_EQ(hit->index, 2);
  EXPECT_EQ(hit->x, ax_[2]);
  EXPECT_EQ(hit->y, ay_[2]);

  const ImVec2 b1 = v.to_screen(bx_[1], by_[1]);
  move_mouse(ImVec2(b1.x - 4, b1.y + 4));
  hit = frame_ab();
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->series, 1);
  EXPECT_EQ(hit->index, 1);

  // 13 px away from the nearest point (and further from all others): nothing.
  move_mouse(ImVec2(a2.x + 13, a2.y));
  for (const auto& [xs, ys] : {std::pair{&ax_, &ay_}, std::pair{&bx_, &by_}}) {
    for (std::size_t i = 0; i < xs->size(); ++i) {
      const ImVec2 p = v.to_screen((*xs)[i], (*ys)[i]);
      ASSERT_GE(std::hypot(p.x - a2.x - 13, p.y - a2.y), 13.0f);
    }
  }
  EXPECT_FALSE(frame_ab().has_value());
}

TEST_F(PlotWidget, WheelZoomsAroundTheCursor) {
  frame_ab();
  const PlotView before = plot_.view();
  const ImVec2 cursor(before.min.x + (before.max.x - before.min.x) * 0.3f,
                      before.min.y + (before.max.y - before.min.y) * 0.6f);
  const auto [dx, dy] = before.to_data(cursor);
  move_mouse(cursor);
  ImGui::GetIO().MouseWheel = 1;
  frame_ab();
  const PlotView after = plot_.view();
  EXPECT_NEAR(after.x_hi - after.x_lo, (before.x_hi - before.x_lo) / 1.25, 1e-9);
  EXPECT_NEAR(after.y_hi - after.y_lo, (before.y_hi - before.y_lo) / 1.25, 1e-9);
  const auto [ax, ay] = after.to_data(cursor);
  const double px_x = (after.x_hi - after.x_lo) / (after.max.x - after.min.x);
  const double px_y = (after.y_hi - after.y_lo) / (after.max.y - after.min.y);
  EXPECT_NEAR(ax, dx, px_x);  // the point under the cursor stays under it
  EXPECT_NEAR(ay, dy, px_y);
  EXPECT_FALSE(after.x_auto);
  EXPECT_FALSE(after.y_auto);

  // Wheel down zooms back out.
  ImGui::GetIO().MouseWheel = -1;
  frame_ab();
  EXPECT_NEAR(plot_.view().x_hi - plot_.view().x_lo, before.x_hi - before.x_lo, 1e-9);
}

// Font 13 px (pad 5): the y title, the x labels and the x title take 18 px each and two lines of
// data 26 px, 80 px in all. A 90 px plot with a 20 px legend row has 70 px left: no legend, so
// that it cannot cover the x labels; 120 px keeps it.
// The Method tab's iterate axis once had ticks at 0.4, 0.6, ... 2.6 iterates.
TEST_F(PlotWidget, ACountsAxisHasTicksOnWholeNumbersOnly) {
  const std::vector<double> iterates = {1.0, 2.0};
  const std::vector<double> ratios = {1.02, 0.999};
  const auto ticks = [&](bool whole) {
    frame([&] {
      ASSERT_TRUE(
          plot_.begin("plot", ImVec2(600, 300), PlotAxis{"iterate", false, false, whole}, y_axis_));
      plot_.line("L'/L", iterates, ratios, kColA);
      plot_.end();
    });
    return plot_.x_ticks();
  };
  const auto fractional = [](const std::vector<double>& t) {
    return std::count_if(t.begin(), t.end(),
                         [](double v) { return std::abs(v - std::round(v)) > 1e-9; });
  };
  EXPECT_GT(fractional(ticks(false)), 0) << "a plain axis ticks between 1 and 2";
  const std::vector<double> whole = ticks(true);
  EXPECT_EQ(fractional(whole), 0);
  EXPECT_EQ(whole, (std::vector<double>{1.0, 2.0}));
}

TEST_F(PlotWidget, APlotTooShortForItsLegendDropsIt) {
  const auto legend_height = [&](float plot_height) {
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", ImVec2(600, plot_height), x_axis_, y_axis_));
      plot_.line("A", ax_, ay_, kColA);
      plot_.end();
    });
    return plot_.view().legend_max.y - plot_.view().legend_min.y;
  };
  EXPECT_EQ(legend_height(90.0f), 0.0f);
  EXPECT_GT(legend_height(120.0f), 0.0f);
  // The x labels stay inside the frame, above where the legend would be.
  EXPECT_LE(plot_.view().max.y + 13.0f, plot_.view().legend_min.y);
}

// In a window that scrolls, the wheel over a plot scrolls the window until the plot is clicked;
// after a click elsewhere it scrolls the window again.
TEST_F(PlotWidget, InAScrollingWindowTheWheelScrollsUntilThePlotIsClicked) {
  float scroll_y = 0.0f;
  const auto scrolling_frame = [&] {
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", ImVec2(600, 300), x_axis_, y_axis_));
      plot_.line("A", ax_, ay_, kColA);
      plot_.end();
      ImGui::Dummy(ImVec2(600, 900));  // the window's content is taller than the window
      scroll_y = ImGui::GetScrollY();
    });
  };
  scrolling_frame();
  scrolling_frame();
  const PlotView before = plot_.view();
  ImGuiIO& io = ImGui::GetIO();
  move_mouse(ImVec2((before.min.x + before.max.x) / 2, (before.min.y + before.max.y) / 2));
  scrolling_frame();
  io.MouseWheel = -1;
  scrolling_frame();
  io.MouseWheel = 0;  // one notch: the headless context does not clear it
  scrolling_frame();
  EXPECT_GT(scroll_y, 0.0f) << "the window scrolled";
  EXPECT_NEAR(plot_.view().x_hi - plot_.view().x_lo, before.x_hi - before.x_lo, 1e-9);
  EXPECT_TRUE(plot_.view().x_auto) << "the plot did not zoom";

  // Clicked, the plot takes the wheel and the window stays where it is.
  const PlotView now = plot_.view();
  move_mouse(ImVec2((now.min.x + now.max.x) / 2, (now.min.y + now.max.y) / 2));
  scrolling_frame();  // there before the press, which a move in the same frame would make a drag
  io.MouseDown[0] = true;
  scrolling_frame();
  io.MouseDown[0] = false;
  scrolling_frame();
  const float scrolled = scroll_y;
  io.MouseWheel = 1;
  scrolling_frame();
  io.MouseWheel = 0;  // one notch: the headless context does not clear it
  scrolling_frame();
  EXPECT_EQ(scroll_y, scrolled);
  EXPECT_NEAR(plot_.view().x_hi - plot_.view().x_lo, (now.x_hi - now.x_lo) / 1.25, 1e-9);

  // A click beside the plot gives the wheel back to the window.
  move_mouse(ImVec2(700, 500));
  scrolling_frame();
  io.MouseDown[0] = true;
  scrolling_frame();
  io.MouseDown[0] = false;
  scrolling_frame();
  const PlotView zoomed = plot_.view();
  move_mouse(ImVec2((zoomed.min.x + zoomed.max.x) / 2, (zoomed.min.y + zoomed.max.y) / 2));
  scrolling_frame();
  io.MouseWheel = 1;
  scrolling_frame();
  io.MouseWheel = 0;  // one notch: the headless context does not clear it
  scrolling_frame();
  EXPECT_LT(scroll_y, scrolled);
  EXPECT_NEAR(plot_.view().x_hi - plot_.view().x_lo, zoomed.x_hi - zoomed.x_lo, 1e-9);
}

TEST_F(PlotWidget, ShiftZoomsOnlyXAndCtrlOnlyY) {
  frame_ab();
  const PlotView before = plot_.view();
  move_mouse(before.to_screen(150, 50));
  ImGuiIO& io = ImGui::GetIO();
  io.KeyShift = true;
  io.MouseWheel = 2;
  frame_ab();
  io.KeyShift = false;
  EXPECT_LT(plot_.view().x_hi - plot_.view().x_lo, before.x_hi - before.x_lo);
  EXPECT_EQ(plot_.view().y_lo, before.y_lo);
  EXPECT_EQ(plot_.view().y_hi, before.y_hi);
  EXPECT_FALSE(plot_.view().x_auto);
  EXPECT_TRUE(plot_.view().y_auto);

  const PlotView mid = plot_.view();
  io.KeyCtrl = true;
  io.MouseWheel = 2;
  frame_ab();
  io.KeyCtrl = false;
  EXPECT_EQ(plot_.view().x_lo, mid.x_lo);
  EXPECT_EQ(plot_.view().x_hi, mid.x_hi);
  EXPECT_LT(plot_.view().y_hi - plot_.view().y_lo, mid.y_hi - mid.y_lo);
  EXPECT_FALSE(plot_.view().y_auto);
}

TEST_F(PlotWidget, YFollowsTheVisibleDataWhenOnlyXIsZoomed) {
  frame_ab();
  // Zoom x around x = 0 until only the samples at x = 0 remain visible.
  move_mouse(plot_.view().to_screen(0, 50));
  ImGuiIO& io = ImGui::GetIO();
  io.KeyShift = true;
  io.MouseWheel = 8;
  frame_ab();
  io.KeyShift = false;
  frame_ab();  // y is fitted to what the zoomed x range shows
  const PlotView& v = plot_.view();
  ASSERT_LT(v.x_hi, 100);
  EXPECT_TRUE(v.y_auto);
  // Only A's (0, 0) and B's (0, 100) are inside; B's 10 at x = 300 no longer stretches the range.
  EXPECT_NEAR(v.y_lo, -5, 1e-9);
  EXPECT_NEAR(v.y_hi, 105, 1e-9);
  ay_[0] = 60;  // the lowest visible point moves: y follows, with x still fixed
  frame_ab();
  EXPECT_NEAR(plot_.view().y_lo, 60 - 2, 1e-9);
  EXPECT_NEAR(plot_.view().y_hi, 100 + 2, 1e-9);
}

TEST_F(PlotWidget, YKeepsAllDataWhenZoomedInBetweenSamples) {
  frame_ab();
  move_mouse(plot_.view().to_screen(50, 50));
  ImGuiIO& io = ImGui::GetIO();
  io.KeyShift = true;
  io.MouseWheel = 15;  // x narrows to about 12 mm around 50: no sample of A or B inside
  frame_ab();
  io.KeyShift = false;
  frame_ab();
  const PlotView& v = plot_.view();
  ASSERT_GT(v.x_lo, 0);
  ASSERT_LT(v.x_hi, 100);
  EXPECT_TRUE(v.y_auto);
  EXPECT_NEAR(v.y_lo, -5, 1e-9);  // rather than an empty fit
  EXPECT_NEAR(v.y_hi, 105, 1e-9);
}

TEST_F(PlotWidget, DragPansAndLeavesTheOtherAxisAuto) {
  frame_ab();
  const ImVec2 start = plot_.view().to_screen(100, 50);
  const auto [sx, sy] = plot_.view().to_data(start);
  ImGuiIO& io = ImGui::GetIO();
  move_mouse(start);
  frame_ab();
  io.MouseDown[0] = true;
  frame_ab();
  const ImVec2 end(start.x + 60, start.y);
  move_mouse(end);
  frame_ab();
  io.MouseDown[0] = false;
  const PlotView& v = plot_.view();
  const auto [ex, ey] = v.to_data(end);
  const double px = (v.x_hi - v.x_lo) / (v.max.x - v.min.x);
  EXPECT_NEAR(ex, sx, px);  // the grabbed point followed the mouse
  EXPECT_NEAR(v.x_lo, -15 - 60 * px, 2 * px);
  EXPECT_FALSE(v.x_auto);
  EXPECT_TRUE(v.y_auto);
  EXPECT_NEAR(ey, sy, 1e-9);
}

TEST_F(PlotWidget, ZoomStopsAutoscaleAndDoubleClickRestoresIt) {
  frame_ab();
  const ImVec2 centre = plot_.view().to_screen(150, 50);
  move_mouse(centre);
  ImGuiIO& io = ImGui::GetIO();
  io.MouseWheel = 3;
  frame_ab();
  const PlotView zoomed = plot_.view();

  for (double& x : ax_)
    x *= 2;  // new data: the zoomed view must not follow it
  for (double& x : bx_)
    x *= 2;
  frame_ab();
  EXPECT_EQ(plot_.view().x_lo, zoomed.x_lo);
  EXPECT_EQ(plot_.view().x_hi, zoomed.x_hi);

  for (const bool down : {true, false, true}) {
    io.MouseDown[0] = down;
    frame_ab();
  }
  io.MouseDown[0] = false;
  frame_ab();
  EXPECT_TRUE(plot_.view().x_auto);
  EXPECT_TRUE(plot_.view().y_auto);
  EXPECT_NEAR(plot_.view().x_lo, -30, 1e-9);  // [0, 600] now
  EXPECT_NEAR(plot_.view().x_hi, 630, 1e-9);
}

TEST_F(PlotWidget, RequestAutoscaleRefitsAfterZoom) {
  frame_ab();
  move_mouse(plot_.view().to_screen(150, 50));
  ImGui::GetIO().MouseWheel = 3;
  frame_ab();
  ASSERT_FALSE(plot_.view().x_auto);
  move_mouse(ImVec2(-FLT_MAX, -FLT_MAX));
  frame_ab([](Plot& p) { p.request_autoscale(); });
  EXPECT_TRUE(plot_.view().x_auto);
  EXPECT_NEAR(plot_.view().x_lo, -15, 1e-9);
  EXPECT_NEAR(plot_.view().x_hi, 315, 1e-9);
  frame_ab();  // and it stays on
  EXPECT_TRUE(plot_.view().x_auto);
}

TEST_F(PlotWidget, TwoPlotsKeepSeparateViews) {
  Plot other;
  const auto both = [&] {
    frame([&] {
      ASSERT_TRUE(plot_.begin("first", ImVec2(380, 300), x_axis_, y_axis_));
      plot_.line("A", ax_, ay_, kColA);
      plot_.end();
      ImGui::SameLine();
      ASSERT_TRUE(other.begin("second", ImVec2(380, 300), x_axis_, y_axis_));
      other.line("A", ax_, ay_, kColA);
      other.end();
    });
  };
  both();
  move_mouse(other.view().to_screen(150, 40));
  ImGui::GetIO().MouseWheel = 2;
  both();
  EXPECT_TRUE(plot_.view().x_auto);
  EXPECT_FALSE(other.view().x_auto);
  EXPECT_NEAR(plot_.view().x_lo, -15, 1e-9);
}

TEST_F(PlotWidget, DegenerateDataNeitherAssertsNorBreaksTheView) {
  const std::vector<double> empty;
  const std::vector<double> same_x{5, 5, 5}, same_y{7, 7, 7};
  const std::vector<double> bad_x{0, kNaN, 2, kInf, 4}, bad_y{0, 1, kInf, 3, 4};
  const auto check = [](const PlotView& v) {
    EXPECT_TRUE(std::isfinite(v.x_lo) && std::isfinite(v.x_hi) && v.x_lo < v.x_hi);
    EXPECT_TRUE(std::isfinite(v.y_lo) && std::isfinite(v.y_hi) && v.y_lo < v.y_hi);
  };
  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    plot_.end();  // no series at all
  });
  check(plot_.view());

  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    plot_.line("empty", empty, empty, kColA);
    plot_.steps("empty steps", empty, empty, kColB);
    plot_.line("one value", same_x, same_y, kColC);
    plot_.end();
  });
  check(plot_.view());
  EXPECT_LT(plot_.view().x_lo, 5);
  EXPECT_GT(plot_.view().x_hi, 5);
  EXPECT_LT(plot_.view().y_lo, 7);
  EXPECT_GT(plot_.view().y_hi, 7);
  EXPECT_FALSE(vertices_of(kColC).empty());  // its legend swatch at least

  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    plot_.line(nullptr, bad_x, bad_y, kColA);
    plot_.steps(nullptr, bad_x, bad_y, kColB);
    plot_.markers(nullptr, bad_x, bad_y, kColC);
    plot_.end();
  });
  check(plot_.view());
  EXPECT_NEAR(plot_.view().x_lo, -0.2, 1e-12);  // only (0, 0) and (4, 4) count
  EXPECT_NEAR(plot_.view().x_hi, 4.2, 1e-12);

  // Non-positive values on a log axis are skipped the same way.
  y_axis_.log = true;
  const std::vector<double> xs{0, 1, 2, 3}, ys{-1, 0, 10, 1000};
  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    plot_.line(nullptr, xs, ys, kColA);
    plot_.end();
  });
  check(plot_.view());
  EXPECT_NEAR(std::log10(plot_.view().y_lo), 1 - 0.1, 1e-9);
  EXPECT_NEAR(std::log10(plot_.view().y_hi), 3 + 0.1, 1e-9);
}

TEST_F(PlotWidget, LegendShowsEachLabelOnce) {
  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    for (int i = 0; i < 5; ++i)
      plot_.line("positive fold", ax_, ay_, kColA);
    plot_.line("negative fold", bx_, by_, kColB);
    plot_.line(nullptr, bx_, by_, kColC);
    plot_.markers("", bx_, by_, kColC);
    plot_.end();
  });
  EXPECT_EQ(plot_.view().legend_entries, 2);
}

// Presented, a plot keeps two rows for its data: the x title goes on the row of the x tick
// labels and the legend into the data area's bottom right corner; its width is unchanged.
TEST_F(PlotWidget, ACompactPlotGivesTheTitleAndLegendRowsToItsData) {
  const auto draw = [&](bool compact) {
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", ImVec2(600, 300), x_axis_, y_axis_));
      if (compact)
        plot_.compact();
      plot_.line("A", ax_, ay_, kColA);
      plot_.line("B", bx_, by_, kColB);
      plot_.end();
    });
    return plot_.view();
  };
  const PlotView loose = draw(false);
  const PlotView compact = draw(true);
  constexpr float kFontPx = 13.0f;
  EXPECT_GE((compact.max.y - compact.min.y) - (loose.max.y - loose.min.y), 2.0f * kFontPx);
  EXPECT_EQ(compact.max.x - compact.min.x, loose.max.x - loose.min.x);
  EXPECT_EQ(compact.legend_entries, 2);
  EXPECT_GE(compact.legend_min.x, compact.min.x);
  EXPECT_GE(compact.legend_min.y, compact.min.y);
  EXPECT_LE(compact.legend_max.x, compact.max.x);
  EXPECT_LE(compact.legend_max.y, compact.max.y);
  EXPECT_NEAR(compact.legend_max.x, compact.max.x, kFontPx);
  EXPECT_NEAR(compact.legend_max.y, compact.max.y, kFontPx);
  // The next frame without compact() lays the plot out as before.
  const PlotView again = draw(false);
  EXPECT_EQ(again.max.y - again.min.y, loose.max.y - loose.min.y);
  EXPECT_GE(again.legend_min.y, again.max.y);
}

// The fold plot's supports sit in the data's top corners and the sweep's paper point at its far
// right: wherever data lies, the legend's rectangle holds none of it (markers with their radius)
// and lies outside the data area, and the legend's swatches are drawn there.
TEST_F(PlotWidget, TheLegendCoversNoDataPointAtAnyWidth) {
  const std::vector<double> sx{-650, 650}, sy{0, 0};           // supports: top corners
  const std::vector<double> px{2350}, py{7};                   // a paper point: top right
  const std::vector<double> cx{-650, 0, 650}, cy{0, 1400, 0};  // a sag between the supports
  constexpr float kMarkerRadius = 5.0f;
  for (const float width : {600.0f, 240.0f, 130.0f}) {
    SCOPED_TRACE(::testing::Message() << "plot " << width << " px wide");
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", ImVec2(width, 300), x_axis_, y_axis_));
      plot_.line("positive fold", cx, cy, kColA);
      plot_.line("negative fold with a long name", cx, cy, kColB);
      plot_.markers("supports", sx, sy, kColC, MarkerShape::Triangle, kMarkerRadius);
      plot_.markers("paper, Table 2", px, py, kColC, MarkerShape::Circle, kMarkerRadius);
      plot_.end();
    });
    const PlotView& v = plot_.view();
    ASSERT_EQ(v.legend_entries, 4);
    ASSERT_LT(v.legend_min.x, v.legend_max.x);
    ASSERT_LT(v.legend_min.y, v.legend_max.y);
    // Below the data area: no overlap with it at all.
    EXPECT_GE(v.legend_min.y, v.max.y);
    const auto in_legend = [&](ImVec2 p, float r) {
      return p.x + r > v.legend_min.x && p.x - r < v.legend_max.x && p.y + r > v.legend_min.y &&
             p.y - r < v.legend_max.y;
    };
    for (const auto& [xs, ys] : {std::pair{&sx, &sy}, std::pair{&px, &py}, std::pair{&cx, &cy}}) {
      for (std::size_t i = 0; i < xs->size(); ++i) {
        const ImVec2 p = v.to_screen((*xs)[i], (*ys)[i]);
        EXPECT_FALSE(in_legend(p, kMarkerRadius)) << (*xs)[i] << ", " << (*ys)[i];
      }
    }
    // The swatch of line A is drawn in the legend, under the data area.
    const std::vector<Vertex> a = vertices_of(kColA);
    EXPECT_TRUE(std::any_of(a.begin(), a.end(), [&](const Vertex& vx) {
      return vx.pos.y > v.max.y && in_legend(vx.pos, 0.0f);
    }));
  }
}

TEST_F(PlotWidget, StepsJumpHalfWayBetweenSamples) {
  const std::vector<double> xs{0, 1, 2}, ys{1, 1, 2};
  const auto draw = [&](bool as_steps) {
    frame([&] {
      ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
      if (as_steps)
        plot_.steps(nullptr, xs, ys, kColA);
      else
        plot_.line(nullptr, xs, ys, kColA);
      plot_.end();
    });
  };
  const auto has_vertex_near = [](ImVec2 p) {
    const std::vector<Vertex> vs = vertices_of(kColA);
    return std::any_of(vs.begin(), vs.end(), [&](const Vertex& v) {
      return std::abs(v.pos.x - p.x) < 2 && std::abs(v.pos.y - p.y) < 2;
    });
  };
  draw(true);
  const PlotView v = plot_.view();
  EXPECT_TRUE(has_vertex_near(v.to_screen(1.5, 1)));  // the riser's foot
  EXPECT_TRUE(has_vertex_near(v.to_screen(1.5, 2)));  // and its top
  EXPECT_FALSE(has_vertex_near(v.to_screen(1, 1)));   // mid-tread: no corner at the sample
  draw(false);  // the same samples as a line: corners at the samples, none half-way
  EXPECT_TRUE(has_vertex_near(v.to_screen(1, 1)));
  EXPECT_FALSE(has_vertex_near(v.to_screen(1.5, 2)));
}

TEST_F(PlotWidget, VerticalLineSpansThePlotAndJoinsTheXAutoscale) {
  frame_ab([](Plot& p) { p.vertical_line(500, kColC, "current"); });
  const PlotView& v = plot_.view();
  EXPECT_NEAR(v.x_hi, 500 + 0.05 * 500, 1e-9);
  const std::vector<Vertex> vs = vertices_of(kColC);
  ASSERT_FALSE(vs.empty());
  const float x = v.to_screen(500, 0).x;
  float top = FLT_MAX, bottom = -FLT_MAX;
  for (const Vertex& vx : vs) {
    if (std::abs(vx.pos.x - x) > 2)
      continue;  // its label is drawn in the same colour
    top = std::min(top, vx.pos.y);
    bottom = std::max(bottom, vx.pos.y);
  }
  EXPECT_NEAR(top, v.min.y, 1.5f);
  EXPECT_NEAR(bottom, v.max.y, 1.5f);
}

TEST_F(PlotWidget, ClippedPlotReturnsFalse) {
  bool shown = true;
  frame([&] {
    ImGui::SetCursorPosY(2000);  // far below the 600 px window
    shown = plot_.begin("plot", kPlotSize, x_axis_, y_axis_);
    if (shown)
      plot_.end();
  });
  EXPECT_FALSE(shown);
}

// A curve sampled far finer than the pixels is drawn from fewer segments than samples (a software
// rasterizer pays for each), without leaving the curve: every vertex stays within the line's
// half-width and the shortest kept segment (3 px) of it, and both ends are drawn.
TEST_F(PlotWidget, ADenseCurveIsDrawnFromFewerSegmentsAndStaysOnIt) {
  std::vector<double> xs, ys;
  for (int i = 0; i <= 2000; ++i) {
    xs.push_back(0.15 * i);
    ys.push_back(50.0 + 40.0 * std::sin(0.01 * i));
  }
  frame([&] {
    ASSERT_TRUE(plot_.begin("plot", kPlotSize, x_axis_, y_axis_));
    plot_.line("dense", xs, ys, kColA, 2.0f);
    plot_.end();
  });
  const PlotView& v = plot_.view();
  std::vector<Vertex> vs = vertices_of(kColA);
  vs.erase(
      std::remove_if(vs.begin(), vs.end(), [&](const Vertex& x) { return in_legend(v, x.pos); }),
      vs.end());
  // vertices_of lists each triangle's three corners; a segment is at least two triangles. Drawn
  // whole, the 2000 segments would be 12000 corners or more.
  ASSERT_GT(vs.size(), 100u);
  EXPECT_LT(vs.size() / 6, (xs.size() - 1) / 2);
  std::vector<ImVec2> curve;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    curve.push_back(v.to_screen(xs[i], ys[i]));
  }
  for (const Vertex& vertex : vs) {
    float nearest = FLT_MAX;
    for (const ImVec2& c : curve) {
      nearest = std::min(nearest, std::hypot(vertex.pos.x - c.x, vertex.pos.y - c.y));
    }
    ASSERT_LT(nearest, 1.0f + 1.0f + 3.0f) << vertex.pos.x << ", " << vertex.pos.y;
  }
  for (const ImVec2& end : {curve.front(), curve.back()}) {
    EXPECT_TRUE(std::any_of(vs.begin(), vs.end(), [&](const Vertex& x) {
      return std::hypot(x.pos.x - end.x, x.pos.y - end.y) < 3.0f;  // half-width + fringe
    }));
  }
}

}  // namespace
}  // namespace foldlab::gui
