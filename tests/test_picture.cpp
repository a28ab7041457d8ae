// `foldlab picture`: the 3D cloth or the fold plot alone, headless, read back as RGBA pixels and
// checked against what was asked for (size, background, caption) and against the fold lines'
// own millimetres from `foldlab export --csv`.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "process.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using foldlab::testing::RunResult;

const std::string kExecutable = FOLDLAB_EXECUTABLE;

struct Rgba {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
  const std::uint8_t* at(int x, int y) const {
    return &pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x)) *
                   4];
  }
};

Rgba load_rgba(const fs::path& path) {
  Rgba image;
  int channels = 0;
  std::uint8_t* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
  if (data == nullptr) {
    ADD_FAILURE() << "cannot read " << path;
    return image;
  }
  image.pixels.assign(data, data + static_cast<std::size_t>(image.width) * image.height * 4);
  stbi_image_free(data);
  return image;
}

// Pixels in [x0, x1) x [y0, y1) that differ from `background` (RGBA) in any channel.
int count_unlike(const Rgba& image, std::array<int, 4> background, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = image.at(x, y);
      for (std::size_t c = 0; c < 4; ++c) {
        if (p[c] != background[c]) {
          ++count;
          break;
        }
      }
    }
  }
  return count;
}

constexpr std::array<int, 4> kWhite = {255, 255, 255, 255};

class PictureTest : public foldlab::testing::TempDirTest {
 protected:
  PictureTest() : TempDirTest("foldlab_picture_") {}

  foldlab::testing::Environment environment() const {
    foldlab::testing::Environment env;
    env.set = {{"XDG_CONFIG_HOME", (dir_ / "config").string()}, {"HOME", dir_.string()}};
    return env;
  }
  RunResult run(std::vector<std::string> args) const {
    return foldlab::testing::run_process(kExecutable, args, dir_, environment());
  }
  Rgba picture(const std::string& name, std::vector<std::string> args) {
    const fs::path out = dir_ / (name + ".png");
    args.insert(args.begin(), "picture");
    args.insert(args.end(), {"--out", out.string()});
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_status, 0) << r.err;
    return load_rgba(out);
  }
};

TEST_F(PictureTest, TheClothPictureIsExactlyTheSizeAskedFor) {
  const Rgba image = picture("cloth", {"cloth", "--size", "640x400"});
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 400);
}

TEST_F(PictureTest, ATransparentBackgroundLeavesAlphaZeroAroundAnOpaqueCloth) {
  const Rgba image =
      picture("clear", {"cloth", "--size", "640x400", "--background", "transparent"});
  ASSERT_EQ(image.width, 640);
  for (const auto& [x, y] : {std::pair{0, 0}, {639, 0}, {0, 399}, {639, 399}}) {
    EXPECT_EQ(image.at(x, y)[3], 0) << x << "," << y;
  }
  // The cloth hangs in the middle of the picture: its centre fifth is mostly opaque cloth.
  int opaque = 0;
  for (int y = 160; y < 240; ++y) {
    for (int x = 256; x < 384; ++x) {
      opaque += image.at(x, y)[3] == 255;
    }
  }
  EXPECT_GT(opaque, 128 * 80 / 2);
}

TEST_F(PictureTest, AWhitePictureHasPureWhiteCornersAndNoInterfaceText) {
  const Rgba image = picture("white", {"cloth", "--size", "640x400"});
  ASSERT_EQ(image.height, 400);
  for (const auto& [x, y] : {std::pair{0, 0}, {639, 0}, {0, 399}, {639, 399}}) {
    const std::uint8_t* p = image.at(x, y);
    EXPECT_EQ((std::array<int, 4>{p[0], p[1], p[2], p[3]}), kWhite) << x << "," << y;
  }
  // Where the 3D view writes its mouse hint and the panel its title and settings: nothing.
  EXPECT_EQ(count_unlike(image, kWhite, 0, 0, 200, 40), 0);
}

TEST_F(PictureTest, ACaptionAddsTextRowsAtTheBottom) {
  // No ground grid, which would reach the picture's lower edge.
  const std::vector<std::string> base = {"cloth", "--size", "640x400", "--view", "ground=0"};
  const Rgba plain = picture("plain", base);
  std::vector<std::string> with_caption = base;
  with_caption.push_back("--caption");
  const Rgba captioned = picture("captioned", with_caption);
  ASSERT_EQ(plain.height, 400);
  ASSERT_EQ(captioned.height, 400);
  // The bottom 30 rows: the caption's last line (the inputs) at 15 px text.
  EXPECT_EQ(count_unlike(plain, kWhite, 0, 370, 640, 400), 0);
  EXPECT_GT(count_unlike(captioned, kWhite, 0, 370, 640, 400), 100);
}

// The fold lines' extent in mm, from the CSV `foldlab export` writes.
std::array<double, 2> fold_extent_mm(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string index, sign, x, y;
    std::getline(fields, index, ',');
    std::getline(fields, sign, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    x_lo = std::min(x_lo, std::stod(x));
    x_hi = std::max(x_hi, std::stod(x));
    y_lo = std::min(y_lo, std::stod(y));
    y_hi = std::max(y_hi, std::stod(y));
  }
  return {x_hi - x_lo, y_hi - y_lo};
}

TEST_F(PictureTest, TheFoldPlotDrawsMillimetresAlikeAcrossAndDown) {
  // The default preset: the paper's 1400 x 1400 mm cloth, on a picture three times as wide.
  const fs::path csv = dir_ / "lines.csv";
  const RunResult exported = run({"export", "--csv", csv.string()});
  ASSERT_EQ(exported.exit_status, 0) << exported.err;
  const std::array<double, 2> mm = fold_extent_mm(csv);
  ASSERT_GT(mm[0], 1000.0);
  ASSERT_GT(mm[1], 1000.0);
  const Rgba image = picture("plot", {"fold_plot", "--size", "1200x400"});
  ASSERT_EQ(image.width, 1200);
  // The light theme's fold colours (appearance.cpp), the lines' solid middles.
  const std::array<std::array<int, 3>, 2> folds = {{{26, 64, 166}, {191, 26, 26}}};
  int x_lo = image.width, x_hi = -1, y_lo = image.height, y_hi = -1;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      for (const std::array<int, 3>& colour : folds) {
        if (std::abs(p[0] - colour[0]) <= 30 && std::abs(p[1] - colour[1]) <= 30 &&
            std::abs(p[2] - colour[2]) <= 30) {
          x_lo = std::min(x_lo, x);
          x_hi = std::max(x_hi, x);
          y_lo = std::min(y_lo, y);
          y_hi = std::max(y_hi, y);
        }
      }
    }
  }
  ASSERT_GT(x_hi, x_lo);
  ASSERT_GT(y_hi, y_lo);
  const double pixel_ratio = static_cast<double>(x_hi - x_lo) / static_cast<double>(y_hi - y_lo);
  const double mm_ratio = mm[0] / mm[1];
  EXPECT_NEAR(pixel_ratio / mm_ratio, 1.0, 0.05)
      << "pixels " << x_hi - x_lo << " x " << y_hi - y_lo << ", mm " << mm[0] << " x " << mm[1];
}

// Pixels within `tolerance` of `rgb` in every channel, in [x0, x1) x [y0, y1).
int count_near(const Rgba& image, std::array<int, 3> rgb, int tolerance, int x0, int y0, int x1,
               int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = image.at(x, y);
      count += std::abs(p[0] - rgb[0]) <= tolerance && std::abs(p[1] - rgb[1]) <= tolerance &&
               std::abs(p[2] - rgb[2]) <= tolerance;
    }
  }
  return count;
}

// The light theme's colours (appearance.hpp), as 8-bit sRGB: A's sweep curve and name, B's.
constexpr std::array<int, 3> kCurveA = {13, 89, 191};
constexpr std::array<int, 3> kCurveB = {0, 107, 46};
// ImGui's light button, (0.26, 0.59, 0.98) at 40 % over white: any button, tab or combo arrow.
constexpr std::array<int, 3> kButtonOnWhite = {179, 213, 253};

// The lowest row holding `rgb`, -1 when none does.
int lowest_row_of(const Rgba& image, std::array<int, 3> rgb) {
  for (int y = image.height - 1; y >= 0; --y) {
    if (count_near(image, rgb, 12, 0, y, image.width, y + 1) > 0) {
      return y;
    }
  }
  return -1;
}

// The sweep's three plots stacked over the picture: the model's curve in each third, none of the
// tab's buttons or fields.
TEST_F(PictureTest, TheSweepPictureStacksItsThreePlotsWithNoWidgets) {
  const Rgba image = picture(
      "sweep", {"sweep", "--size", "900x1200", "--param", "h", "--from", "1000", "--to", "3000"});
  ASSERT_EQ(image.width, 900);
  ASSERT_EQ(image.height, 1200);
  for (int third = 0; third < 3; ++third) {
    EXPECT_GT(count_near(image, kCurveA, 12, 0, third * 400, 900, (third + 1) * 400), 100)
        << "plot " << third;
  }
  EXPECT_EQ(count_near(image, kButtonOnWhite, 6, 0, 0, 900, 1200), 0);
}

// A caption takes its lines from the bottom: the last plot's curve ends higher by at least the
// caption's three lines of text.
TEST_F(PictureTest, ASweepPictureHasACaptionOnlyWhenAskedFor) {
  const std::vector<std::string> base = {"sweep",  "--size", "900x600", "--param", "h",
                                         "--from", "1000",   "--to",    "3000"};
  const Rgba plain = picture("sweep-plain", base);
  std::vector<std::string> with_caption = base;
  with_caption.push_back("--caption");
  const Rgba captioned = picture("sweep-captioned", with_caption);
  const int plain_low = lowest_row_of(plain, kCurveA);
  const int captioned_low = lowest_row_of(captioned, kCurveA);
  ASSERT_GT(plain_low, 0);
  ASSERT_GT(captioned_low, 0);
  EXPECT_LT(captioned_low, plain_low - 3 * 15) << plain_low << " " << captioned_low;
}

TEST_F(PictureTest, ASweepAxisTheModelRefusesIsInvalidInput) {
  const RunResult r = run({"picture", "sweep", "--size", "640x400", "--param", "h", "--from", "-5",
                           "--to", "3000", "--out", "x.png"});
  EXPECT_EQ(r.exit_status, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// A and B side by side: a cloth in each half, each named at its foot in its colour.
TEST_F(PictureTest, TheComparePictureShowsAAndBSideBySide) {
  const Rgba image =
      picture("ab", {"compare", "--size", "1200x600", "--b-set", "w=300gsm", "--view", "ground=0"});
  ASSERT_EQ(image.width, 1200);
  ASSERT_EQ(image.height, 600);
  // The middle of each half is cloth, not the white background.
  EXPECT_GT(count_unlike(image, kWhite, 250, 250, 350, 350), 5000);
  EXPECT_GT(count_unlike(image, kWhite, 850, 250, 950, 350), 5000);
  // The names: A's colour only on the left, B's only on the right, in the lowest fifth.
  EXPECT_GT(count_near(image, kCurveA, 12, 0, 480, 600, 600), 20);
  EXPECT_EQ(count_near(image, kCurveA, 12, 600, 480, 1200, 600), 0);
  EXPECT_GT(count_near(image, kCurveB, 12, 600, 480, 1200, 600), 20);
  EXPECT_EQ(count_near(image, kCurveB, 12, 0, 480, 600, 600), 0);
}

TEST_F(PictureTest, AComparePictureNeedsB) {
  const RunResult r = run({"picture", "compare", "--size", "640x400", "--out", "x.png"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("--b-preset"), std::string::npos) << r.err;
  const RunResult misplaced =
      run({"picture", "cloth", "--size", "640x400", "--b-set", "h=900", "--out", "x.png"});
  EXPECT_EQ(misplaced.exit_status, 2);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// The fold lines grow with the picture: at 3000 px wide about three pixels wide, so that a
// picture three times as wide holds about nine times the fold lines' pixels, not three.
TEST_F(PictureTest, TheClothsFoldLinesWidenWithThePicture) {
  const std::vector<std::string> view = {"--view", "ground=0", "--view", "fold_lines=1"};
  std::vector<std::string> small = {"cloth", "--size", "1000x625"};
  std::vector<std::string> large = {"cloth", "--size", "3000x1875"};
  small.insert(small.end(), view.begin(), view.end());
  large.insert(large.end(), view.begin(), view.end());
  const Rgba small_image = picture("small", small);
  const Rgba large_image = picture("large", large);
  // ClothStyle's fold colours, drawn unlit.
  const std::array<std::array<int, 3>, 2> folds = {{{31, 59, 148}, {214, 38, 41}}};
  double small_px = 0.0;
  double large_px = 0.0;
  for (const std::array<int, 3>& colour : folds) {
    small_px += count_near(small_image, colour, 10, 0, 0, 1000, 625);
    large_px += count_near(large_image, colour, 10, 0, 0, 3000, 1875);
  }
  ASSERT_GT(small_px, 100.0);
  EXPECT_GT(large_px / small_px, 6.0) << small_px << " " << large_px;
}

TEST_F(PictureTest, ASizeBelowTheLimitIsRefused) {
  const RunResult r = run({"picture", "cloth", "--size", "10x10", "--out", "x.png"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("--size"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(PictureTest, APictureOverTheBudgetIsRefused) {
  const RunResult r = run({"picture", "cloth", "--size", "8192x8192", "--out", "x.png"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("8192x4096"), std::string::npos) << r.err;
}

TEST_F(PictureTest, AnUnknownViewIsRefusedByName) {
  const RunResult r = run({"picture", "teapot", "--size", "640x400", "--out", "x.png"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("teapot"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("fold_plot"), std::string::npos) << r.err;
}

TEST_F(PictureTest, AFolderAsTheOutputIsRefused) {
  const RunResult r = run({"picture", "cloth", "--size", "640x400", "--out", dir_.string()});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("folder"), std::string::npos) << r.err;
}

}  // namespace

// A field picture takes a cut of one's own as `foldlab field` does: the tension field of a
// curtain with a curved hem, drawn into a PNG of the size asked for, mostly cloth in its middle.
TEST_F(PictureTest, AFieldPictureTakesAnOutlineFile) {
  const fs::path outline = dir_ / "good.json";
  std::ofstream(outline) << R"({"top": [[0, 0], [1200, 0]],
    "bottom": [[0, 1000], [600, 1150], [1200, 1000]],
    "supports": [{"at": [0, 0], "to": [100, 0]}, {"at": [1200, 0], "to": [1100, 0]}]})";
  const Rgba image = picture(
      "field-outline", {"field", "--outline", outline.string(), "--size", "640x400", "--caption"});
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 400);
  EXPECT_GT(count_unlike(image, kWhite, 0, 0, 640, 400), 640 * 400 / 8);
  // The middle of the picture is the cloth, coloured by its state.
  EXPECT_GT(count_unlike(image, kWhite, 280, 120, 360, 200), 80 * 80 * 9 / 10);
}

// An outline the field cannot hang is refused as `foldlab field` refuses it: exit 2, naming the
// option, the file and what is wrong, and no picture written.
TEST_F(PictureTest, AFieldPictureRefusesABadOutlineAsTheFieldCommandDoes) {
  const fs::path outline = dir_ / "bad.json";
  std::ofstream(outline)
      << R"({"top": [[0, 0], [1200, 0]], "bottom": [[0, 1000], [1200, 1000]], "supports": []})";
  const fs::path png = dir_ / "bad.png";
  const RunResult r = run({"picture", "field", "--outline", outline.string(), "--size", "640x400",
                           "--out", png.string()});
  EXPECT_EQ(r.exit_status, 2) << r.err;
  EXPECT_NE(r.err.find("--outline " + outline.string() +
                       ": the outline needs at least one "
                       "support to hang from"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(png));
  const RunResult field = run({"field", "--outline", outline.string()});
  EXPECT_EQ(field.exit_status, 2);
  EXPECT_EQ(field.err, r.err);

  const RunResult missing = run({"picture", "field", "--outline", (dir_ / "none.json").string(),
                                 "--size", "640x400", "--out", png.string()});
  EXPECT_EQ(missing.exit_status, 2) << missing.err;
  EXPECT_NE(missing.err.find("--outline"), std::string::npos) << missing.err;
  const RunResult shape =
      run({"picture", "field", "--shape", "hexagon", "--size", "640x400", "--out", png.string()});
  EXPECT_EQ(shape.exit_status, 2) << shape.err;
  EXPECT_NE(shape.err.find("--shape 'hexagon' is not one of: rectangular"), std::string::npos)
      << shape.err;
  const RunResult other_view = run({"picture", "cloth", "--outline", (dir_ / "good.json").string(),
                                    "--size", "640x400", "--out", png.string()});
  EXPECT_EQ(other_view.exit_status, 2) << other_view.err;
  EXPECT_NE(other_view.err.find("--shape and --outline belong to a field picture"),
            std::string::npos)
      << other_view.err;
}

// --shape takes the field's cuts: the triangle, which the field view's cuts also offer, and the
// model's shapes.
TEST_F(PictureTest, AFieldPictureTakesTheFieldsCutsByName) {
  for (const char* shape : {"triangle", "rectangular"}) {
    const Rgba image =
        picture(std::string("field-") + shape, {"field", "--shape", shape, "--size", "640x400"});
    ASSERT_EQ(image.width, 640) << shape;
    EXPECT_GT(count_unlike(image, kWhite, 280, 120, 360, 200), 80 * 80 / 2) << shape;
  }
}
