// The explorer as a person sees it: `foldlab render` (EGL, no display) and `foldlab gui` in a real
// window under Xvfb, checked on the pictures they write.
#include <sys/stat.h>
#include <sys/types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image.h>
#include <nlohmann/json.hpp>

#include "json_output.hpp"
#include "process.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using foldlab::testing::RunResult;

const std::string kExecutable = FOLDLAB_EXECUTABLE;
const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  const std::uint8_t* at(int x, int y) const {
    return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
  }
};

Image load_png(const fs::path& path) {
  Image image;
  int channels = 0;
  std::uint8_t* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  if (data == nullptr) {
    ADD_FAILURE() << "cannot read " << path;
    return image;
  }
  image.rgb.assign(data, data + static_cast<std::size_t>(image.width) * image.height * 3);
  stbi_image_free(data);
  return image;
}

// Pixels within `tolerance` (per channel) of a colour, inside the rectangle given as fractions of
// the picture (the explorer's first-use layout is in fractions of the window).
int count_colour(const Image& image, std::array<int, 3> colour, double x0, double y0, double x1,
                 double y1, int tolerance = 24) {
  int count = 0;
  for (int y = static_cast<int>(y0 * image.height); y < static_cast<int>(y1 * image.height); ++y) {
    for (int x = static_cast<int>(x0 * image.width); x < static_cast<int>(x1 * image.width); ++x) {
      const std::uint8_t* p = image.at(x, y);
      bool near = true;
      for (int c = 0; c < 3; ++c) {
        near = near && std::abs(p[c] - colour[static_cast<std::size_t>(c)]) <= tolerance;
      }
      count += near;
    }
  }
  return count;
}

double fraction_different(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) {
    return 1.0;
  }
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    differ += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  }
  return static_cast<double>(differ) / static_cast<double>(a.rgb.size() / 3);
}

// The fold-line colours of the plot in the dark theme (fold_colours(false); negative folds red).
constexpr std::array<int, 3> kNegativeFold = {255, 140, 128};
constexpr std::array<int, 3> kPositiveFold = {140, 191, 255};
// The plot window's first-use place: x 30-65 %, y 0-56 % of the window.
constexpr double kPlotX0 = 0.30, kPlotY0 = 0.0, kPlotX1 = 0.65, kPlotY1 = 0.56;

// The fold lines as drawn: every fold line runs from one support to the other, so that together
// they make one connected shape of fold colours, apart from the legend's swatches under the axes.
struct DrawnFolds {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // its bounding box, inclusive
  std::vector<std::uint8_t> mask;        // 1 where the shape is, over the whole picture
  int width = 0;
  bool at(int x, int y) const { return mask[static_cast<std::size_t>(y) * width + x] != 0; }
};

bool near_colour(const std::uint8_t* p, std::array<int, 3> colour, int tolerance) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p[c] - colour[static_cast<std::size_t>(c)]) > tolerance) {
      return false;
    }
  }
  return true;
}

// The largest 8-connected shape of `colours` inside the rectangle (pixels).
DrawnFolds largest_shape(const Image& image, const std::vector<std::array<int, 3>>& colours,
                         int rx0, int ry0, int rx1, int ry1, int tolerance = 40) {
  const int w = image.width;
  std::vector<std::uint8_t> in(static_cast<std::size_t>(w) * image.height, 0);
  for (int y = std::max(ry0, 0); y < std::min(ry1, image.height); ++y) {
    for (int x = std::max(rx0, 0); x < std::min(rx1, w); ++x) {
      for (const auto& colour : colours) {
        if (near_colour(image.at(x, y), colour, tolerance)) {
          in[static_cast<std::size_t>(y) * w + x] = 1;
        }
      }
    }
  }
  std::vector<int> label(in.size(), 0);
  DrawnFolds best;
  best.width = w;
  best.mask.assign(in.size(), 0);
  std::size_t best_size = 0;
  int next = 0;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < in.size(); ++start) {
    if (!in[start] || label[start] != 0) {
      continue;
    }
    ++next;
    std::vector<std::size_t> members;
    stack.assign(1, start);
    label[start] = next;
    while (!stack.empty()) {
      const std::size_t at = stack.back();
      stack.pop_back();
      members.push_back(at);
      const int x = static_cast<int>(at % static_cast<std::size_t>(w));
      const int y = static_cast<int>(at / static_cast<std::size_t>(w));
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= image.height) {
            continue;
          }
          const std::size_t n = static_cast<std::size_t>(ny) * w + nx;
          if (in[n] && label[n] == 0) {
            label[n] = next;
            stack.push_back(n);
          }
        }
      }
    }
    if (members.size() > best_size) {
      best_size = members.size();
      std::fill(best.mask.begin(), best.mask.end(), 0);
      best.x0 = w;
      best.y0 = image.height;
      best.x1 = -1;
      best.y1 = -1;
      for (const std::size_t m : members) {
        best.mask[m] = 1;
        const int x = static_cast<int>(m % static_cast<std::size_t>(w));
        const int y = static_cast<int>(m / static_cast<std::size_t>(w));
        best.x0 = std::min(best.x0, x);
        best.x1 = std::max(best.x1, x);
        best.y0 = std::min(best.y0, y);
        best.y1 = std::max(best.y1, y);
      }
    }
  }
  return best;
}

// The centres of the runs of `colour` down one column of the picture between rows y0 and y1.
std::vector<double> run_centres(const Image& image, int x, int y0, int y1,
                                const std::vector<std::array<int, 3>>& colours,
                                int tolerance = 40) {
  std::vector<double> centres;
  int start = -1;
  for (int y = y0; y <= y1 + 1; ++y) {
    bool hit = false;
    if (y <= y1) {
      for (const auto& colour : colours) {
        hit = hit || near_colour(image.at(x, y), colour, tolerance);
      }
    }
    if (hit && start < 0) {
      start = y;
    } else if (!hit && start >= 0) {
      centres.push_back(0.5 * (start + y - 1));
      start = -1;
    }
  }
  return centres;
}

class GuiTest : public foldlab::testing::TempDirTest {
 protected:
  GuiTest() : TempDirTest("foldlab_gui_") {}

  foldlab::testing::Environment environment() const {
    foldlab::testing::Environment env;
    env.set = {{"XDG_CONFIG_HOME", (dir_ / "config").string()}, {"HOME", dir_.string()}};
    return env;
  }

  Image render(const std::string& name, std::vector<std::string> args) {
    const fs::path out = dir_ / (name + ".png");
    args.insert(args.begin(), {"render", "--out", out.string()});
    const RunResult r = foldlab::testing::run_process(kExecutable, args, dir_, environment());
    EXPECT_EQ(r.exit_status, 0) << r.err;
    return load_png(out);
  }

  // A picture with the run's --report (its layout and solution).
  std::pair<Image, nlohmann::json> render_reported(const std::string& name,
                                                   std::vector<std::string> args) {
    const fs::path out = dir_ / (name + ".png");
    args.insert(args.begin(), {"render", "--out", out.string(), "--report"});
    const nlohmann::json report = foldlab::testing::json_output(
        foldlab::testing::run_process(kExecutable, args, dir_, environment()));
    return {load_png(out), report};
  }

  // The fold lines drawn in the fold plot's panel of a reported picture.
  static DrawnFolds fold_shape(const Image& image, const nlohmann::json& report) {
    const nlohmann::json& r = report["layout"]["panels"]["fold_plot"];
    EXPECT_TRUE(r.is_object()) << report.dump();
    if (!r.is_object()) {
      return {};
    }
    const int x = static_cast<int>(r["x"].get<double>());
    const int y = static_cast<int>(r["y"].get<double>());
    return largest_shape(image, {kNegativeFold, kPositiveFold}, x, y,
                         x + static_cast<int>(r["w"].get<double>()),
                         y + static_cast<int>(r["h"].get<double>()));
  }
};

// The 3D view drawn with its level of detail and with every vertex (--view lod=0|1), and how far
// the two pictures differ inside the cloth panel (below its controls).
struct DetailComparison {
  nlohmann::json detail;  // --report of each run
  nlohmann::json every;
  double mean_difference = 0.0;  // per channel, of 255
  double far_fraction = 0.0;     // of the pixels, those differing by more than 32 in a channel
};

// A fine grid seen small: the view draws rows and columns a few pixels apart, not all 512 a side
// (core/geometry/level_of_detail.hpp), and the cloth looks as it does with every vertex drawn,
// at true depth and with z exaggerated (where a coarse lattice would cut through the pleats and
// hide fold lines).
class GuiDetailTest : public GuiTest {
 protected:
  DetailComparison compare(const std::string& name, std::vector<std::string> args) {
    args.insert(args.end(), {"--report", "--view", "grid=512"});
    DetailComparison result;
    Image pictures[2];
    for (int lod = 0; lod < 2; ++lod) {
      const fs::path out = dir_ / (name + std::to_string(lod) + ".png");
      std::vector<std::string> run_args = {"render", "--out", out.string(), "--view",
                                           "lod=" + std::to_string(lod)};
      run_args.insert(run_args.end(), args.begin(), args.end());
      (lod == 1 ? result.detail : result.every) = foldlab::testing::json_output(
          foldlab::testing::run_process(kExecutable, run_args, dir_, environment()));
      pictures[lod] = load_png(out);
    }
    const nlohmann::json& cloth = result.detail["layout"]["panels"]["cloth"];
    EXPECT_TRUE(cloth.is_object());
    EXPECT_EQ(pictures[0].width, pictures[1].width);
    if (!cloth.is_object() || pictures[0].width != pictures[1].width) {
      return result;
    }
    double total = 0.0;
    int far = 0;
    int pixels = 0;
    const int x0 = cloth["x"].get<int>(), y0 = cloth["y"].get<int>();
    for (int y = y0 + 60; y < std::min(y0 + cloth["h"].get<int>(), pictures[0].height); ++y) {
      for (int x = x0; x < std::min(x0 + cloth["w"].get<int>(), pictures[0].width); ++x) {
        int largest = 0;
        for (int c = 0; c < 3; ++c) {
          const int d = std::abs(pictures[1].at(x, y)[c] - pictures[0].at(x, y)[c]);
          total += d;
          largest = std::max(largest, d);
        }
        far += largest > 32;
        ++pixels;
      }
    }
    EXPECT_GT(pixels, 10000);
    result.mean_difference = total / (3.0 * std::max(pixels, 1));
    result.far_fraction = static_cast<double>(far) / std::max(pixels, 1);
    return result;
  }
};

TEST_F(GuiDetailTest, AFineGridIsDrawnWithCellsOfAFewPixelsAndLooksTheSame) {
  const DetailComparison c = compare("default", {});
  EXPECT_EQ(c.every["renderer"]["drawn_columns"], 512);
  EXPECT_EQ(c.every["renderer"]["drawn_rows"], 512);
  // The default cloth is about 200 px wide in a 1280 x 800 window.
  EXPECT_LT(c.detail["renderer"]["drawn_columns"].get<int>(), 80);
  EXPECT_LT(c.detail["renderer"]["drawn_rows"].get<int>(), 100);
  EXPECT_GE(c.detail["renderer"]["drawn_rows"].get<int>(), 6 * (1 + 7));  // n = 7 folds
  EXPECT_LT(c.mean_difference, 0.6);
  EXPECT_LT(c.far_fraction, 0.001);
  EXPECT_GT(c.mean_difference, 0.0);  // two pictures, not one drawn twice
}

TEST_F(GuiDetailTest, ExaggeratedPleatsKeepTheirRowsAndFoldLines) {
  const DetailComparison c =
      compare("chiffon", {"--preset", (kPresetsDir / "fabric-silk-chiffon.json").string(), "--view",
                          "z_exaggeration=3", "--view", "full=1"});
  EXPECT_LT(c.detail["renderer"]["drawn_rows"].get<int>(), 512);
  EXPECT_LT(c.mean_difference, 0.6);
  EXPECT_LT(c.far_fraction, 0.001);
}

TEST_F(GuiTest, RenderDrawsTheWholeWindowWithFoldColoursInThePlot) {
  const Image image = render("default", {"--size", "1280x800"});
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(image.height, 800);
  // Not blank: many distinct colours (text, lines, shaded cloth).
  std::vector<bool> seen(1 << 15, false);
  int distinct = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    const int key =
        (image.rgb[i] >> 3) << 10 | (image.rgb[i + 1] >> 3) << 5 | image.rgb[i + 2] >> 3;
    distinct += !seen[static_cast<std::size_t>(key)];
    seen[static_cast<std::size_t>(key)] = true;
  }
  EXPECT_GT(distinct, 200);
  // The default preset has n = 8: four negative (red) and five positive (blue) fold lines.
  EXPECT_GT(count_colour(image, kNegativeFold, kPlotX0, kPlotY0, kPlotX1, kPlotY1), 500);
  EXPECT_GT(count_colour(image, kPositiveFold, kPlotX0, kPlotY0, kPlotX1, kPlotY1), 500);
}

// The light theme presented on a projector showed a dark frame a few pixels wide round the
// panel: what lay outside the panels' own fills was cleared in the dark theme's grey. Every
// pixel of the window's outermost columns is the light theme's panel grey now.
TEST_F(GuiTest, TheLightThemeHasNoDarkFrameRoundItsPanels) {
  const Image image = render(
      "light", {"--size", "800x500", "--view", "theme=light", "--view", "present=fold_plot"});
  ASSERT_EQ(image.width, 800);
  int dark = 0;
  for (int y = 60; y < image.height - 10; ++y) {
    for (const int x : {1, 2, 3, image.width - 4, image.width - 3, image.width - 2}) {
      const std::uint8_t* p = image.at(x, y);
      // The old frame was the dark theme's clear grey, (26, 26, 31); borders are (94, 94, 94).
      dark += (p[0] + p[1] + p[2]) < 3 * 60;
    }
  }
  EXPECT_EQ(dark, 0);
}

// The centres of the fold lines down the column through the middle of the span, top first: one
// run of a fold colour per line (neighbours alternate in colour, so that touching ones stay apart).
std::vector<double> lines_down_the_middle(const Image& image, const DrawnFolds& folds,
                                          std::array<int, 3> only = {-1, -1, -1}) {
  const int middle = (folds.x0 + folds.x1) / 2;
  std::vector<double> rows;
  for (const auto& colour : {kNegativeFold, kPositiveFold}) {
    if (only[0] >= 0 && colour != only) {
      continue;
    }
    const std::vector<double> runs = run_centres(image, middle, folds.y0, folds.y1, {colour});
    rows.insert(rows.end(), runs.begin(), runs.end());
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

TEST_F(GuiTest, AnotherPresetOrParameterGivesAnotherPicture) {
  const auto [base, base_report] = render_reported("default", {});
  const Image table1 =
      render("h900", {"--preset", (kPresetsDir / "paper-table1-h900.json").string()});
  const auto [taller, taller_report] = render_reported("h2350", {"--set", "h=2350"});
  EXPECT_GT(fraction_different(base, table1), 0.01);
  EXPECT_GT(fraction_different(base, taller), 0.01);
  // h = 2350 mm has 14 folds against 8: more negative (red) fold lines cross the middle of the
  // plot, one for each odd i up to n, however much room the taller cloth leaves each line.
  const int base_n = base_report["solution"]["n"].get<int>();
  const int taller_n = taller_report["solution"]["n"].get<int>();
  ASSERT_GT(taller_n, base_n);
  const auto negative_lines = [](const Image& image, const nlohmann::json& report) {
    return lines_down_the_middle(image, fold_shape(image, report), kNegativeFold).size();
  };
  EXPECT_EQ(negative_lines(base, base_report), static_cast<std::size_t>((base_n + 1) / 2));
  EXPECT_EQ(negative_lines(taller, taller_report), static_cast<std::size_t>((taller_n + 1) / 2));
}

// The fold plot draws a mm across as many pixels as a mm down, tiled and presented. Down the
// middle the lines cross at their depths a_i (the report's), which give the pixels per mm down
// and where y = 0 is; the deepest line, a cos(pi x / l), crosses a row y below the supports at
// x = ±(l / pi) acos(y / a), the outermost crossings of its colour on that row, which with the same
// pixels per mm must be as far apart as drawn, to a pixel and a half (each crossing's centre is
// read to half a pixel, and the row to a whole one).
TEST_F(GuiTest, TheFoldPlotDrawsAMillimetreAsLongAcrossAsDown) {
  const std::vector<std::vector<std::string>> runs = {
      {"--size", "1280x800"},
      {"--size", "1280x800", "--set", "h=2350"},
      // Presented, the plot fills the window unless its own true scale is asked for.
      {"--size", "1920x1080", "--view", "present=fold_plot", "--view",
       "fold_plot_presented_true_scale=1"},
      {"--size", "1280x800", "--view", "present=fold_plot", "--view",
       "fold_plot_presented_true_scale=1", "--set", "L=3000"}};
  int k = 0;
  for (const std::vector<std::string>& args : runs) {
    SCOPED_TRACE(::testing::PrintToString(args));
    const auto [image, report] = render_reported("scales" + std::to_string(k++), args);
    const DrawnFolds folds = fold_shape(image, report);
    std::vector<double> depths = report["solution"]["a_mm"].get<std::vector<double>>();
    std::sort(depths.begin(), depths.end());
    const double span_mm = report["solution"]["l_mm"].get<double>();
    const std::vector<double> rows = lines_down_the_middle(image, folds);
    ASSERT_EQ(rows.size(), depths.size());
    // Least squares: row = top + px_per_mm * depth.
    double mean_a = 0.0, mean_row = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      mean_a += depths[i] / static_cast<double>(rows.size());
      mean_row += rows[i] / static_cast<double>(rows.size());
    }
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      sxy += (depths[i] - mean_a) * (rows[i] - mean_row);
      sxx += (depths[i] - mean_a) * (depths[i] - mean_a);
    }
    const double px_per_mm = sxy / sxx;
    const double top = mean_row - px_per_mm * mean_a;
    ASSERT_GT(px_per_mm, 0.0);
    const int row = static_cast<int>(std::lround(top + 0.5 * px_per_mm * depths.back()));
    const double row_mm = (row - top) / px_per_mm;
    // The deepest line's runs along that row, in its own colour: its neighbours are drawn in the
    // other one.
    const std::vector<double> a_mm = report["solution"]["a_mm"].get<std::vector<double>>();
    const auto deepest = std::max_element(a_mm.begin(), a_mm.end()) - a_mm.begin();
    const std::array<int, 3> colour = deepest % 2 == 0 ? kPositiveFold : kNegativeFold;
    std::vector<double> across;
    int start = -1;
    for (int x = folds.x0; x <= folds.x1 + 1; ++x) {
      const bool hit =
          x <= folds.x1 && folds.at(x, row) && near_colour(image.at(x, row), colour, 40);
      if (hit && start < 0) {
        start = x;
      } else if (!hit && start >= 0) {
        across.push_back(0.5 * (start + x - 1));
        start = -1;
      }
    }
    ASSERT_GE(across.size(), 2u);
    const double half_width_mm = span_mm / std::numbers::pi * std::acos(row_mm / depths.back());
    EXPECT_NEAR(across.back() - across.front(), 2.0 * half_width_mm * px_per_mm, 1.5)
        << "px per mm down " << px_per_mm << ", across "
        << (across.back() - across.front()) / (2.0 * half_width_mm);
  }
}

// A/B in the fold plot: towards the supports every fold line runs into its neighbours, and B's
// dashes there merged into a grey fence over A's lines. B is drawn only where its lines stand
// apart: beside each support (the outer twentieth of the span) hardly any of B's colours, in the
// middle of the span its dashes.
TEST_F(GuiTest, BsDashedFoldLinesStayClearOfTheSupports) {
  const fs::path shot = dir_ / "ab.png";
  const fs::path script = dir_ / "ab.json";
  // B: L = 4000 mm, h = 3000 mm (n = 17); A: h = 1400 mm, typed into the presented view's strip
  // after the pin.
  std::ofstream(script) << R"({"steps": [{"click": "Compare"}, {"click": "Pin as B"}, {"frames": 2},
      {"click": "h", "at": 0.5, "ctrl": true}, {"type": "1400 mm"}, {"key": "enter"},
      {"frames": 3}, {"expect": {"parameters.h_mm": 1400, "compare.parameters.h_mm": 3000}},
      {"screenshot": ")" << shot.string()
                        << R"("}]})";
  const nlohmann::json report = foldlab::testing::json_output(foldlab::testing::run_process(
      kExecutable,
      {"render", "--size", "1280x800", "--set", "L=4000", "--set", "h=3000", "--view",
       "present=fold_plot", "--play", script.string(), "--report"},
      dir_, environment()));
  const Image image = load_png(shot);
  ASSERT_EQ(image.width, 1280);
  const int b_lines = report["compare"]["solution"]["n"].get<int>() + 1;
  EXPECT_GE(b_lines, 15) << "a fence to thin out";
  // B's colours in the dark theme (kCompareB, kCompareBNegative).
  const std::vector<std::array<int, 3>> b_colours = {{115, 224, 140}, {245, 158, 245}};
  const DrawnFolds a = fold_shape(image, report);  // A and B share the span: A's ends are B's
  const int span_px = a.x1 - a.x0;
  ASSERT_GT(span_px, 200);
  const auto b_pixels = [&](double from, double to) {
    int count = 0;
    for (int y = a.y0; y <= a.y1; ++y) {
      for (int x = a.x0 + static_cast<int>(from * span_px);
           x < a.x0 + static_cast<int>(to * span_px); ++x) {
        for (const auto& colour : b_colours) {
          count += near_colour(image.at(x, y), colour, 40);
        }
      }
    }
    return count;
  };
  const int middle = b_pixels(0.30, 0.70);
  const int by_supports = b_pixels(0.0, 0.05) + b_pixels(0.95, 1.0);
  EXPECT_GT(middle, 50 * b_lines) << "B's dashes are drawn";
  // Per unit of width, a twentieth as much B beside the supports as in the middle at most.
  EXPECT_LT(by_supports / 0.10, 0.05 * middle / 0.40)
      << by_supports << " by the supports, " << middle << " in the middle";
}

TEST_F(GuiTest, NoSlackShowsNoFoldLines) {
  const Image flat = render("flat", {"--set", "d=0"});
  ASSERT_EQ(flat.width, 1280);
  EXPECT_LT(count_colour(flat, kNegativeFold, kPlotX0, kPlotY0, kPlotX1, kPlotY1), 20);
}

TEST_F(GuiTest, RenderRejectsBadInputWithExitTwo) {
  const fs::path out = dir_ / "x.png";
  const RunResult bad_set = foldlab::testing::run_process(
      kExecutable, {"render", "--out", out.string(), "--set", "d=700"}, dir_, environment());
  EXPECT_EQ(bad_set.exit_status, 2);
  EXPECT_NE(bad_set.err.find("support displacement d = 700 mm must be below"), std::string::npos)
      << bad_set.err;
  const RunResult bad_size = foldlab::testing::run_process(
      kExecutable, {"render", "--out", out.string(), "--size", "12x7"}, dir_, environment());
  EXPECT_EQ(bad_size.exit_status, 2);
  // A switch given a word is told what a switch takes.
  const RunResult bad_switch = foldlab::testing::run_process(
      kExecutable, {"render", "--out", out.string(), "--view", "lod=yes"}, dir_, environment());
  EXPECT_EQ(bad_switch.exit_status, 2);
  EXPECT_NE(bad_switch.err.find("lod = 'yes' must be 0 or 1"), std::string::npos) << bad_switch.err;
  // Every refused view setting is named, not only the first.
  const RunResult three =
      foldlab::testing::run_process(kExecutable,
                                    {"render", "--out", out.string(), "--view", "foo=1", "--view",
                                     "grid=1", "--view", "z_exaggeration=99"},
                                    dir_, environment());
  EXPECT_EQ(three.exit_status, 2);
  for (const char* named : {"'foo'", "grid = '1'", "z_exaggeration = 99"}) {
    EXPECT_NE(three.err.find(named), std::string::npos) << named << "\n" << three.err;
  }
  EXPECT_FALSE(fs::exists(out));
  // Bad inputs to the window are input errors even with no display to open it on.
  const RunResult no_display =
      foldlab::testing::run_process(kExecutable, {"gui", "--set", "t=-1"}, dir_, environment());
  EXPECT_EQ(no_display.exit_status, 2) << no_display.err;
  EXPECT_NE(no_display.err.find("thickness t = −1 mm must be between"), std::string::npos)
      << no_display.err;
}

// The --view help is written by hand while the keys the explorer takes come from its panels'
// tables: after z became z_exaggeration the help still offered `z`, which every run refused.
TEST_F(GuiTest, TheViewHelpNamesEveryKeyTheExplorerTakesAndNoOther) {
  const RunResult help =
      foldlab::testing::run_process(kExecutable, {"render", "--help"}, dir_, environment());
  ASSERT_EQ(help.exit_status, 0) << help.err;
  const std::string lead = "view setting KEY=VALUE:";
  const std::size_t start = help.out.find(lead);
  ASSERT_NE(start, std::string::npos) << help.out;
  // The description runs to the next option, however the help wraps it.
  const std::size_t end = help.out.find("\n  -", start);
  const std::string described = help.out.substr(start + lead.size(), end - start - lead.size());
  // The help's keys: each comma or semicolon separated piece up to its '=', with the
  // parenthesised remarks (which hold commas of their own) taken out first.
  std::string bare;
  int depth = 0;
  for (const char c : described) {
    depth += c == '(' ? 1 : 0;
    if (depth == 0) {
      bare += c;
    }
    depth -= c == ')' ? 1 : 0;
  }
  const auto keys_in = [](const std::string& text, const std::string& separators) {
    std::vector<std::string> keys;
    std::size_t from = 0;
    while (from <= text.size()) {
      const std::size_t to = std::min(text.find_first_of(separators, from), text.size());
      std::string piece = text.substr(from, to - from);
      piece = piece.substr(0, piece.find('='));
      const std::size_t first = piece.find_first_not_of(" \n");
      if (first != std::string::npos) {
        keys.push_back(piece.substr(first, piece.find_last_not_of(" \n") - first + 1));
      }
      from = to + 1;
    }
    std::sort(keys.begin(), keys.end());
    return keys;
  };
  const std::vector<std::string> helped = keys_in(bare, ",;");
  // The explorer's own list, as a refused key names it.
  const RunResult refused = foldlab::testing::run_process(
      kExecutable, {"render", "--out", (dir_ / "x.png").string(), "--view", "no_such_key=1"}, dir_,
      environment());
  ASSERT_EQ(refused.exit_status, 2) << refused.err;
  const std::string known_lead = "(known: ";
  const std::size_t known = refused.err.find(known_lead);
  ASSERT_NE(known, std::string::npos) << refused.err;
  const std::size_t known_end = refused.err.find(')', known);
  const std::vector<std::string> taken = keys_in(
      refused.err.substr(known + known_lead.size(), known_end - known - known_lead.size()), ",");
  // docs/cli.md names 20 keys: a refusal whose list was not read cannot make the check pass.
  ASSERT_GE(taken.size(), 18u) << refused.err;
  EXPECT_EQ(helped, taken) << "help: " << described << "\nrefusal: " << refused.err;
}

// `render --print swatch.png --out swatch.png` drew the window over the swatch it printed with;
// the same for --view print_file, gui --screenshot and a played script's screenshot step.
TEST_F(GuiTest, NoPictureIsWrittenOverAnInputOfTheRun) {
  render("swatch", {"--size", "320x240"});
  const fs::path swatch = dir_ / "swatch.png";
  const std::string before = foldlab::testing::read_file(swatch);
  ASSERT_FALSE(before.empty());
  const fs::path script = dir_ / "shot.json";
  std::ofstream(script) << R"({"steps": [{"frames": 1}, {"screenshot": ")" << swatch.string()
                        << R"("}]})";
  const std::string same = (dir_ / "." / "swatch.png").string();
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> runs = {
      {{"render", "--print", swatch.string(), "--out", same}, {"--out", "--print"}},
      {{"render", "--view", "print_file=" + swatch.string(), "--out", same},
       {"--out", "--view print_file"}},
      {{"gui", "--print", swatch.string(), "--frames", "1", "--screenshot", same},
       {"--screenshot", "--print"}},
      {{"render", "--print", swatch.string(), "--play", script.string()},
       {"screenshot step", "--print"}},
  };
  for (const auto& [args, named] : runs) {
    SCOPED_TRACE(args[0] + " " + args[1] + " ... " + args.back());
    const RunResult r = foldlab::testing::run_process(kExecutable, args, dir_, environment());
    EXPECT_EQ(r.exit_status, 2) << r.err;
    EXPECT_NE(r.err.find("would destroy the input"), std::string::npos) << r.err;
    for (const std::string& option : named) {
      EXPECT_NE(r.err.find(option), std::string::npos) << option << "\n" << r.err;
    }
    EXPECT_EQ(foldlab::testing::read_file(swatch), before);
  }
}

bool have_xvfb() {
  return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

RunResult run_in_xvfb(const fs::path& dir, const foldlab::testing::Environment& env,
                      std::vector<std::string> args) {
  args.insert(args.begin(), {"-a", "-s", "-screen 0 1280x800x24", kExecutable, "gui"});
  return foldlab::testing::run_process("xvfb-run", args, dir, env);
}

TEST_F(GuiTest, WindowUnderXvfbShowsTheSamePictureAsHeadless) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  const fs::path shot = dir_ / "window.png";
  const RunResult r =
      run_in_xvfb(dir_, environment(), {"--frames", "3", "--fresh", "--screenshot", shot.string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const Image window = load_png(shot);
  ASSERT_EQ(window.width, 1280);
  ASSERT_EQ(window.height, 800);
  const Image headless = render("headless", {});
  // Same frame code, same llvmpipe: the two backends draw the same picture.
  EXPECT_LT(fraction_different(window, headless), 0.001);
}

TEST_F(GuiTest, ScriptedDragResolvesEveryFrameAndBuildsTheGridOnlyWhenShown) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  const RunResult r =
      run_in_xvfb(dir_, environment(), {"--frames", "20", "--fresh", "--report", "--animate", "h"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report.at("frames").get<int>(), 20);
  // The slider moves every frame: one solve per frame (plus the first), one grid per solve.
  const nlohmann::json& stats = report.at("stats");
  EXPECT_GE(stats.at("solution").at("evaluations").get<int>(), 20);
  EXPECT_EQ(stats.at("grid").at("evaluations").get<int>(),
            stats.at("solution").at("evaluations").get<int>());
  EXPECT_GT(report.at("mean_ms").get<double>(), 0.0);
  EXPECT_GE(report.at("p95_ms").get<double>(), report.at("mean_ms").get<double>() * 0.5);
}

TEST_F(GuiTest, TheLastSessionIsRestored) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  const RunResult first =
      run_in_xvfb(dir_, environment(), {"--frames", "2", "--set", "h=1777", "--report"});
  ASSERT_EQ(first.exit_status, 0) << first.err;
  EXPECT_TRUE(fs::exists(dir_ / "config" / "foldlab" / "session.json"));
  const RunResult second = run_in_xvfb(dir_, environment(), {"--frames", "2", "--report"});
  ASSERT_EQ(second.exit_status, 0) << second.err;
  const nlohmann::json report = nlohmann::json::parse(second.out);
  EXPECT_EQ(report.at("solution").at("inputs").at("height_mm").get<double>(), 1777.0);
  EXPECT_TRUE(fs::exists(dir_ / "config" / "foldlab" / "imgui.ini"));
}
TEST_F(GuiTest, ALinkOpensTheFabricAndTheViewItCarries) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  // A full address as the page writes it, with a query the explorer leaves to the page.
  const RunResult r = run_in_xvfb(
      dir_, environment(),
      {"--frames", "2", "--report", "--link",
       "https://example.org/foldlab/index.html?preset=paper-fig4#h=2000&w=200%20g%2Fm%C2%B2"
       "&method=paper&theme=light&present=cloth&scale=150"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const nlohmann::json& inputs = report.at("parameters");
  EXPECT_EQ(inputs.at("h_mm").get<double>(), 2000.0);
  EXPECT_EQ(inputs.at("w_N_per_mm2").get<double>(), 200 * 9.81e-9);  // 200 g/m², g = 9.81
  EXPECT_EQ(inputs.at("method"), "paper");
  EXPECT_EQ(inputs.at("L_mm").get<double>(), 1400.0);  // the default preset's, not in the link
  EXPECT_EQ(report.at("solution").at("inputs").at("height_mm").get<double>(), 2000.0);
  EXPECT_TRUE(report.at("refused").is_null());
  // An edit of its preset, not the preset itself, and no undo step.
  EXPECT_EQ(report.at("dirty"), true);
  EXPECT_EQ(report.at("undo_depth"), 0);
  EXPECT_EQ(report.at("appearance").at("light_theme"), true);
  EXPECT_EQ(report.at("appearance").at("scale_percent"), 150);
  EXPECT_EQ(report.at("layout").at("presented"), "cloth");
  // The link the explorer gives back carries the same, in the shown units.
  // Only what differs from the preset, and the presenter's room but not their theme and text size
  // (sent only when they choose to).
  const std::string link = report.at("link").get<std::string>();
  EXPECT_EQ(link, "w=200gsm&h=2000&method=paper&present=cloth");
  // --set after the link wins, as it is applied after it.
  const RunResult both =
      run_in_xvfb(dir_, environment(),
                  {"--frames", "1", "--report", "--link", "#h=2000&E=300", "--set", "h=1500"});
  ASSERT_EQ(both.exit_status, 0) << both.err;
  const nlohmann::json both_report = nlohmann::json::parse(both.out);
  EXPECT_EQ(both_report.at("parameters").at("h_mm").get<double>(), 1500.0);
  EXPECT_EQ(both_report.at("parameters").at("E_MPa").get<double>(), 300.0);
}

// A foldlab: link as the desktop entry passes it when one is clicked (`foldlab gui %u`): the
// preset it starts from, A's name and inputs, and B pinned beside it with its own.
TEST_F(GuiTest, AClickedFoldlabLinkOpensItsFabricsAndNames) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  const RunResult r =
      run_in_xvfb(dir_, environment(),
                  {"--frames", "2", "--report",
                   "foldlab:#preset=fabric-denim-13oz&name=Velvet%20swag&h=2000&t=0.238"
                   "&b.name=Linen%20curtain&b.t=0.4"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report.at("parameters").at("h_mm").get<double>(), 2000.0);
  EXPECT_EQ(report.at("parameters").at("t_mm").get<double>(), 0.238);
  // Left out of the link: the preset's.
  EXPECT_EQ(report.at("parameters").at("E_MPa").get<double>(), 150.0);  // denim's, in its file
  EXPECT_EQ(report.at("label"), "Velvet swag (edited)");
  ASSERT_FALSE(report.at("compare").is_null());
  EXPECT_EQ(report.at("compare").at("label"), "Linen curtain");
  EXPECT_EQ(report.at("compare").at("parameters").at("t_mm").get<double>(), 0.4);
  EXPECT_EQ(report.at("compare").at("parameters").at("h_mm").get<double>(), 1400.0);
  EXPECT_EQ(report.at("undo_depth"), 0);
  // The link the explorer gives back says the same.
  EXPECT_EQ(report.at("link"),
            "preset=fabric-denim-13oz&name=Velvet%20swag&t=0.238&h=2000&b.name=Linen%20curtain&"
            "b.t=0.4");
  // A link given twice is unclear.
  const RunResult both =
      run_in_xvfb(dir_, environment(), {"--frames", "1", "--link", "#h=2000", "foldlab:#h=1500"});
  EXPECT_EQ(both.exit_status, 2);
  EXPECT_NE(both.err.find("which one is meant?"), std::string::npos) << both.err;
}

TEST_F(GuiTest, ALinksRefusedValueIsKeptWithItsReasonAndAWrongOneNamed) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  // d beyond L/2 = 700 mm: --set refuses to start, a link opens with the value kept as typed and
  // the same reason under the sliders, the cloth as it was before (d = 100 mm).
  const std::string reason = "support displacement d = 900 mm must be below L/2 = 700 mm";
  const RunResult set = run_in_xvfb(dir_, environment(), {"--frames", "1", "--set", "d=900"});
  EXPECT_EQ(set.exit_status, 2);
  EXPECT_NE(set.err.find(reason), std::string::npos) << set.err;
  const RunResult linked =
      run_in_xvfb(dir_, environment(), {"--frames", "2", "--report", "--link", "#d=900"});
  ASSERT_EQ(linked.exit_status, 0) << linked.err;
  const nlohmann::json report = nlohmann::json::parse(linked.out);
  EXPECT_EQ(report.at("parameters").at("d_mm").get<double>(), 900.0);
  EXPECT_NE(report.at("refused").get<std::string>().find(reason), std::string::npos)
      << report.at("refused");
  EXPECT_EQ(report.at("solution").at("inputs").at("support_displacement_mm").get<double>(), 100.0);
  EXPECT_EQ(report.at("undo_depth"), 0);
  EXPECT_EQ(report.at("dirty"), true) << "a refused value on screen is an edit the preset lacks";
  // What cannot be stored at all stops the start, named by the option it came with.
  const RunResult wrong =
      run_in_xvfb(dir_, environment(), {"--frames", "1", "--link", "#t=abc&zz=1"});
  EXPECT_EQ(wrong.exit_status, 2);
  for (const char* named : {"--link t = 'abc' is not a number", "--link unknown key 'zz'"}) {
    EXPECT_NE(wrong.err.find(named), std::string::npos) << named << "\n" << wrong.err;
  }
  // A view key the link carries is named after the link too, not after a --view nobody typed.
  const RunResult view =
      run_in_xvfb(dir_, environment(), {"--frames", "1", "--link", "#theme=pink"});
  EXPECT_EQ(view.exit_status, 2);
  EXPECT_NE(view.err.find("--link theme = 'pink' is not one of: dark, light"), std::string::npos)
      << view.err;
}

// A session saved by a first run, edited by `edit`, then read back by a second run's report.
class GuiConfigTest : public GuiTest {
 protected:
  fs::path config() const { return dir_ / "config" / "foldlab"; }

  nlohmann::json saved_session() {
    const RunResult first = run_in_xvfb(dir_, environment(), {"--frames", "1"});
    EXPECT_EQ(first.exit_status, 0) << first.err;
    std::ifstream in(config() / "session.json");
    return nlohmann::json::parse(in);
  }

  void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
  }

  nlohmann::json second_run() {
    const RunResult r = run_in_xvfb(dir_, environment(), {"--frames", "2", "--report"});
    EXPECT_EQ(r.exit_status, 0) << r.err;
    try {
      return nlohmann::json::parse(r.out);
    } catch (const nlohmann::json::exception& e) {
      ADD_FAILURE() << e.what() << "\n" << r.out << r.err;
      return nlohmann::json::object();
    }
  }

  static std::string notices_text(const nlohmann::json& report) {
    std::string text;
    for (const nlohmann::json& notice : report.value("notices", nlohmann::json::array())) {
      text += notice.get<std::string>() + "\n";
    }
    return text;
  }
};

TEST_F(GuiConfigTest, StoredGridResolutionIsBroughtIntoTheSlidersRange) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  // 46341^2 vertices overflowed into std::bad_alloc on every start; 1e300 is no int at all.
  for (const double stored : {46341.0, 1e300, 2.0}) {
    SCOPED_TRACE(stored);
    nlohmann::json session = saved_session();
    session["view"]["grid_resolution"] = stored;
    write(config() / "session.json", session.dump());
    const nlohmann::json report = second_run();
    EXPECT_EQ(report.value("grid", ""), stored > 512 ? "512x512" : "8x8");
    EXPECT_NE(notices_text(report).find("outside the slider's 8 to 512"), std::string::npos)
        << notices_text(report);
  }
}

TEST_F(GuiConfigTest, SessionSettingsOutsideTheInputTableAreNotRestored) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  nlohmann::json session = saved_session();
  session["current"]["model"]["simpson_intervals"] = 1000000;
  session["current"]["model"]["max_iterations"] = 1000000;
  session["current"]["hanging"]["height_mm"] = 1777.0;
  write(config() / "session.json", session.dump());
  const nlohmann::json report = second_run();
  EXPECT_NE(notices_text(report).find(
                "quadrature intervals simpson_intervals = 1,000,000 must be between 2 and 10,000"),
            std::string::npos)
      << notices_text(report);
  // The default preset's height, not the session's.
  EXPECT_EQ(report.at("solution").at("inputs").at("height_mm").get<double>(), 1400.0);
}

TEST_F(GuiConfigTest, OversizedConfigFilesAreNotReadAndSaySo) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  nlohmann::json session = saved_session();
  session["current"]["hanging"]["height_mm"] = 1777.0;
  session["padding"] = std::string(1100 * 1024, 'x');  // valid JSON, above 1 MB
  write(config() / "session.json", session.dump());
  // 8000 windows, each a valid entry: above 256 KB.
  std::string ini;
  for (int i = 0; i < 8000; ++i) {
    ini += "[Window][w" + std::to_string(i) + "]\nPos=60,60\nSize=400,300\nCollapsed=0\n\n";
  }
  ASSERT_GT(ini.size(), 256u * 1024u);
  write(config() / "imgui.ini", ini);
  const nlohmann::json report = second_run();
  const std::string notices = notices_text(report);
  EXPECT_NE(notices.find("session.json is "), std::string::npos) << notices;
  EXPECT_NE(notices.find("imgui.ini is "), std::string::npos) << notices;
  EXPECT_EQ(report.at("solution").at("inputs").at("height_mm").get<double>(), 1400.0);
  // Neither was read, so neither is saved over: what the user has there stays theirs to move.
  EXPECT_EQ(foldlab::testing::read_file(config() / "imgui.ini"), ini);
  EXPECT_GT(fs::file_size(config() / "session.json"), 1024u * 1024u);
}

TEST_F(GuiConfigTest, AnUnusableConfigFolderCostsTheSessionNotTheStart) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  // A symlink loop at session.json: the defaults, and the reason.
  fs::create_directories(config());
  fs::create_symlink("loop.json", config() / "session.json");
  fs::create_symlink("session.json", config() / "loop.json");
  const nlohmann::json looped = second_run();
  EXPECT_NE(notices_text(looped).find("session.json cannot be opened"), std::string::npos)
      << notices_text(looped);
  // The config folder is a plain file: "internal error", exit 1, before.
  fs::remove_all(config());
  write(config(), "not a folder");
  const nlohmann::json plain = second_run();
  EXPECT_NE(notices_text(plain).find("cannot be used"), std::string::npos) << notices_text(plain);
  EXPECT_EQ(plain.at("solution").at("inputs").at("height_mm").get<double>(), 1400.0);
}

// A FIFO where imgui.ini or session.json belongs blocked the start for ever: ImGui's fopen waits
// for a writer. Either is set aside, said so, and left as it is at exit.
TEST_F(GuiConfigTest, AFifoInTheConfigFolderDoesNotHangTheStart) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  fs::create_directories(config());
  for (const char* name : {"imgui.ini", "session.json"}) {
    ASSERT_EQ(::mkfifo((config() / name).c_str(), 0600), 0) << name;
  }
  // A hang is killed after a minute: the start takes a few seconds.
  std::vector<std::string> args = {
      "-k",        "5",   "60",       "xvfb-run", "-a",      "-s", "-screen 0 1280x800x24",
      kExecutable, "gui", "--frames", "2",        "--report"};
  const RunResult r = foldlab::testing::run_process("timeout", args, dir_, environment());
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::string notices = notices_text(nlohmann::json::parse(r.out));
  for (const char* name : {"imgui.ini", "session.json"}) {
    EXPECT_NE(notices.find(std::string(name) + " is a FIFO"), std::string::npos) << notices;
    struct stat info {};
    ASSERT_EQ(::lstat((config() / name).c_str(), &info), 0) << name;
    EXPECT_TRUE(S_ISFIFO(info.st_mode)) << name << " was replaced";
  }
  EXPECT_NE(notices.find("not be saved"), std::string::npos) << notices;
}

// session.json and imgui.ini linked to someone else's files: each was reported unreadable (or
// read as a layout) and then written over at exit. A file the explorer could not read as its own
// is never saved over, whether or not the session was to be restored.
TEST_F(GuiConfigTest, ConfigFilesLinkedToForeignFilesAreNeverOverwritten) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  fs::create_directories(config());
  const fs::path notes = dir_ / "notes.txt";
  const fs::path other = dir_ / "other.json";
  write(notes, "my notes, not a window layout\n");
  write(other, "{\"someone\": \"else\"}\n");
  fs::create_symlink(notes, config() / "imgui.ini");
  fs::create_symlink(other, config() / "session.json");
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{}, std::vector<std::string>{"--set", "h=1500"}}) {
    std::vector<std::string> args = {"--frames", "2", "--report"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_in_xvfb(dir_, environment(), args);
    ASSERT_EQ(r.exit_status, 0) << r.err;
    const std::string notices = notices_text(nlohmann::json::parse(r.out));
    EXPECT_NE(notices.find("session will not be saved"), std::string::npos) << notices;
    EXPECT_NE(notices.find("layout will not be saved"), std::string::npos) << notices;
    EXPECT_EQ(foldlab::testing::read_file(notes), "my notes, not a window layout\n");
    EXPECT_EQ(foldlab::testing::read_file(other), "{\"someone\": \"else\"}\n");
    EXPECT_TRUE(fs::is_symlink(config() / "imgui.ini"));
    EXPECT_TRUE(fs::is_symlink(config() / "session.json"));
  }
}

}  // namespace

// A config folder left in a bad state must not stop the explorer with a crash or an "internal
// error": an unusable session is set aside for the default preset, and a config folder that
// cannot exist says so.
TEST_F(GuiTest, AHostileSessionFileStartsFromTheDefaultPreset) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  const fs::path config = dir_ / "config" / "foldlab";
  fs::create_directories(config);
  // A preset value nested 60,000 levels deep, inside the session.
  std::ofstream(config / "session.json")
      << R"({"foldlab_session": 1, "current": {"fabric": {"thickness_mm": )"
      << std::string(60000, '[') << "1" << std::string(60000, ']') << "}}}";
  const RunResult deep = run_in_xvfb(dir_, environment(), {"--frames", "2", "--report"});
  EXPECT_EQ(deep.exit_status, 0) << deep.err;
  EXPECT_EQ(nlohmann::json::parse(deep.out).at("solution").at("inputs").at("height_mm"), 1400.0);

  fs::remove(config / "session.json");
  fs::create_symlink("session.json", config / "session.json");  // a loop
  const RunResult loop = run_in_xvfb(dir_, environment(), {"--frames", "2", "--report"});
  EXPECT_EQ(loop.exit_status, 0) << loop.err;
  EXPECT_EQ(loop.err.find("internal error"), std::string::npos) << loop.err;
}

TEST_F(GuiTest, AConfigFolderThatIsAFileIsNamedNotAnInternalError) {
  if (!have_xvfb()) {
    GTEST_SKIP() << "xvfb-run is not installed (scripts/install-deps.sh installs it)";
  }
  fs::create_directories(dir_ / "config");
  std::ofstream(dir_ / "config" / "foldlab") << "a file where the config folder belongs\n";
  // The explorer starts from the defaults without a session, and its notices name the folder.
  const RunResult r = run_in_xvfb(dir_, environment(), {"--frames", "2", "--report"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("The config folder " + (dir_ / "config" / "foldlab").string() +
                       " cannot be used (Not a directory)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  // --fresh needs no config folder at all.
  EXPECT_EQ(run_in_xvfb(dir_, environment(), {"--frames", "2", "--fresh"}).exit_status, 0);
}
