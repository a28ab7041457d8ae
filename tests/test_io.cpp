// Reading and writing files as a stranger's machine presents them: hostile JSON (deep nesting,
// duplicate keys, huge values), symbolic links, FIFOs, devices, directories and stale temporaries
// where a save goes, and numbers that must never be written when they are not finite.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include "temp_dir.hpp"

#include "core/io/io.hpp"
#include "core/io/json_input.hpp"
#include "core/io/measurements.hpp"
#include "core/io/preset.hpp"
#include "core/io/report.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kPresetsDir = FOLDLAB_PRESETS_DIR;

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

std::string nested_arrays(std::size_t depth) {
  return std::string(depth, '[') + "1" + std::string(depth, ']');
}

// The shipped h = 900 mm preset with its thickness replaced by `value` (JSON text).
std::string preset_with_thickness(const std::string& value) {
  std::string text = read_bytes(kPresetsDir / "paper-table1-h900.json");
  const std::string key = "\"thickness_mm\": 0.25";
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  return text.replace(at, key.size(), "\"thickness_mm\": " + value);
}

// A process id that no process has: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) {
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

class IoTest : public foldlab::testing::TempDirTest {
 protected:
  IoTest() : TempDirTest("foldlab_io_") {}

  std::string write_error(const fs::path& path, const std::string& contents = "new\n") {
    try {
      foldlab::write_file_atomically(path, contents);
    } catch (const foldlab::WriteError& e) {
      return e.what();
    }
    ADD_FAILURE() << "write_file_atomically(" << path << ") did not throw";
    return "";
  }
};

// --- JSON input ---------------------------------------------------------------------------------

TEST(ParseJson, NestingUpToTheLimitIsAcceptedOneMoreIsNot) {
  EXPECT_EQ(foldlab::parse_json(nested_arrays(foldlab::kMaxJsonDepth), "x").dump().size(),
            2 * foldlab::kMaxJsonDepth + 1);
  try {
    (void)foldlab::parse_json(nested_arrays(foldlab::kMaxJsonDepth + 1), "deep.json");
    ADD_FAILURE() << "65 levels were accepted";
  } catch (const foldlab::JsonInputError& e) {
    EXPECT_TRUE(contains(e.what(), "deep.json")) << e.what();
    EXPECT_TRUE(contains(e.what(), "nested deeper than 64 levels")) << e.what();
  }
}

TEST(ParseJson, SixtyThousandLevelsAreRefusedWithoutExhaustingTheStack) {
  EXPECT_THROW((void)foldlab::parse_json(nested_arrays(60000), "deep.json"),
               foldlab::JsonInputError);
}

TEST(ParseJson, DuplicateKeyIsNamedByItsPointer) {
  try {
    (void)foldlab::parse_json(R"({"rows": [{"t_mm": 1}, {"E_MPa": 2, "t_mm": -5, "t_mm": 0.25}]})",
                              "m.json");
    ADD_FAILURE() << "a duplicate key was accepted";
  } catch (const foldlab::JsonInputError& e) {
    EXPECT_TRUE(contains(e.what(), "m.json: /rows/1/t_mm: duplicate key")) << e.what();
  }
  // The same key in two different objects is no duplicate.
  EXPECT_NO_THROW(
      (void)foldlab::parse_json(R"({"a": {"k": 1}, "b": {"k": 2}, "k": [{"k": 3}]})", "x"));
}

TEST(ParseJson, InvalidJsonAndHugeNumbersAreJsonInputErrors) {
  EXPECT_THROW((void)foldlab::parse_json("{\"a\": ", "x"), foldlab::JsonInputError);
  EXPECT_THROW((void)foldlab::parse_json("{\"a\": 1e400}", "x"), foldlab::JsonInputError);
}

TEST(DescribeJson, NeverPrintsAWholeLargeValue) {
  const std::string big(5'000'000, 'y');
  const std::string text = foldlab::describe_json(json(big));
  EXPECT_LT(text.size(), 80u);
  EXPECT_TRUE(contains(text, "string \"yyyy")) << text;
  EXPECT_TRUE(contains(text, "…")) << text;
  EXPECT_EQ(foldlab::describe_json(json::parse("[1, [2, 3], 4]")), "an array of 3 items");
  EXPECT_EQ(foldlab::describe_json(json::parse(R"({"a": 1})")), "an object with 1 key");
  EXPECT_EQ(foldlab::describe_json(json(nullptr)), "null");
}

TEST(Cut, KeepsShortTextAndCutsLongTextOnACharacterBoundary) {
  EXPECT_EQ(foldlab::detail::cut("short"), "short");
  // "é" is two bytes: a cut after 5 bytes would split the third one, so it keeps two.
  EXPECT_EQ(foldlab::detail::cut("\u00e9\u00e9\u00e9\u00e9", 5), "\u00e9\u00e9…");
  EXPECT_EQ(foldlab::detail::cut(std::string(100, 'x')), std::string(60, 'x') + "…");
}

TEST(Cut, EscapesControlCharactersAndBytesThatAreNotUtf8) {
  // An escape sequence in a key or value must not reach the terminal: ESC [ 2 J clears it.
  EXPECT_EQ(foldlab::detail::cut("a\x1b[2Jb"), "a\\x1b[2Jb");
  EXPECT_EQ(foldlab::detail::cut("tab\there\nnew\x7f"), "tab\\x09here\\x0anew\\x7f");
  EXPECT_EQ(foldlab::detail::cut("\xc2\x9b"
                                 "31m"),
            "\\xc2\\x9b31m");  // C1 CSI
  EXPECT_EQ(foldlab::detail::cut("bad \xff\xfe utf8 \xe9"), "bad \\xff\\xfe utf8 \\xe9");
  EXPECT_EQ(foldlab::detail::cut("\u00e9\u20ac\U0001F600"), "\u00e9\u20ac\U0001F600");
  // A right-to-left override and a line separator reorder or break what a terminal shows.
  EXPECT_EQ(foldlab::detail::escaped("a\u202eb\u2028c\u2066d"),
            "a\\xe2\\x80\\xaeb\\xe2\\x80\\xa8c\\xe2\\x81\\xa6d");
  EXPECT_EQ(foldlab::detail::escaped("\u2027\u202f\u2030"), "\u2027\u202f\u2030");  // neighbours
  // An escape is never cut in half.
  EXPECT_EQ(foldlab::detail::cut("ab\x01", 5), "ab…");
  EXPECT_TRUE(foldlab::detail::is_valid_utf8("\u00e9\u20ac\U0001F600"));
  EXPECT_FALSE(foldlab::detail::is_valid_utf8("\xc0\xaf"));          // overlong '/'
  EXPECT_FALSE(foldlab::detail::is_valid_utf8("\xed\xa0\x80"));      // a surrogate
  EXPECT_FALSE(foldlab::detail::is_valid_utf8("\xf4\x90\x80\x80"));  // above U+10FFFF
  EXPECT_FALSE(foldlab::detail::is_valid_utf8("\xe2\x82"));          // cut short
}

// --- Loaders through parse_json -----------------------------------------------------------------

TEST(PresetInput, DeepNestingIsAPresetErrorNotACrash) {
  try {
    (void)foldlab::preset_from_text(preset_with_thickness(nested_arrays(60000)), "deep.json");
    ADD_FAILURE() << "accepted";
  } catch (const foldlab::PresetError& e) {
    EXPECT_LT(std::string(e.what()).size(), 400u) << e.what();
    EXPECT_TRUE(contains(e.what(), "nested deeper than 64 levels")) << e.what();
  }
}

TEST(PresetInput, WrongTypeNestedWithinTheLimitIsDescribedShortly) {
  try {
    (void)foldlab::preset_from_text(preset_with_thickness(nested_arrays(60)), "p.json");
    ADD_FAILURE() << "accepted";
  } catch (const foldlab::PresetError& e) {
    EXPECT_TRUE(contains(e.what(),
                         "/fabric/thickness_mm: expected a number, got an array of 1 "
                         "item"))
        << e.what();
  }
}

TEST(PresetInput, DuplicateKeyIsRejectedNamingIt) {
  try {
    (void)foldlab::preset_from_text(preset_with_thickness("-5, \"thickness_mm\": 0.25"),
                                    "dup.json");
    ADD_FAILURE() << "the last of two thickness_mm keys won";
  } catch (const foldlab::PresetError& e) {
    EXPECT_TRUE(contains(e.what(), "dup.json: /fabric/thickness_mm: duplicate key")) << e.what();
  }
}

TEST(PresetInput, TypeAndRangeProblemsAreReportedTogether) {
  std::string text = preset_with_thickness("\"thin\"");
  const std::string height = "\"height_mm\": 900";
  ASSERT_NE(text.find(height), std::string::npos);
  text.replace(text.find(height), height.size(), "\"height_mm\": -3");
  try {
    (void)foldlab::preset_from_text(text, "two.json");
    ADD_FAILURE() << "accepted";
  } catch (const foldlab::PresetError& e) {
    EXPECT_TRUE(contains(e.what(), "/fabric/thickness_mm: expected a number, got string \"thin\""))
        << e.what();
    EXPECT_TRUE(
        contains(e.what(), "/hanging/height_mm: height h = −3 mm must be between 1 and 100,000 mm"))
        << e.what();
  }
}

TEST(PresetInput, AHugeBadValueIsEchoedCut) {
  try {
    (void)foldlab::preset_from_text(
        preset_with_thickness("\"" + std::string(5'000'000, 'y') + "\""), "big.json");
    ADD_FAILURE() << "accepted";
  } catch (const foldlab::PresetError& e) {
    EXPECT_LT(std::string(e.what()).size(), 300u);
    EXPECT_TRUE(contains(e.what(), "…")) << e.what();
  }
}

TEST(MeasurementInput, DeepNestingAndDuplicateKeysAreMeasurementErrors) {
  const std::string deep =
      R"({"foldlab_measurements": 1, "rows": [{"t_mm": )" + nested_arrays(60000) + "}]}";
  EXPECT_THROW((void)foldlab::measurements_from_text(deep, "deep.json", ".json"),
               foldlab::MeasurementError);
  try {
    (void)foldlab::measurements_from_text(
        R"({"foldlab_measurements": 1, "rows": [{"t_mm": 1, "t_mm": 0.25, "E_MPa": 165,
            "w_N_per_mm2": 1.5e-6, "h_mm": 900, "L_mm": 1400, "d_mm": 100, "n": 5}]})",
        "dup.json", ".json");
    ADD_FAILURE() << "accepted";
  } catch (const foldlab::MeasurementError& e) {
    EXPECT_TRUE(contains(e.what(), "dup.json: /rows/0/t_mm: duplicate key")) << e.what();
  }
}

TEST(MeasurementInput, AHugeBadCellIsEchoedCut) {
  const std::string csv = "t_mm,E_MPa,w_N_per_mm2,h_mm,L_mm,d_mm,n\n" +
                          std::string(1'000'000, 'z') + ",165,1.5e-6,900,1400,100,5\n";
  try {
    (void)foldlab::measurements_from_csv(csv, "big.csv");
    ADD_FAILURE() << "accepted";
  } catch (const foldlab::MeasurementError& e) {
    EXPECT_LT(std::string(e.what()).size(), 300u);
    EXPECT_TRUE(contains(e.what(), "is not a number")) << e.what();
  }
}

// --- Reading files ------------------------------------------------------------------------------

TEST_F(IoTest, ReadErrorsGiveTheSystemsReason) {
  write_bytes(dir_ / "plain", "x");
  try {
    (void)foldlab::read_text_file(dir_ / "plain" / "p.json", foldlab::kMaxPresetFileBytes);
    ADD_FAILURE() << "read through a plain file";
  } catch (const foldlab::ReadError& e) {
    EXPECT_TRUE(contains(e.what(), "(Not a directory)")) << e.what();
  }
  fs::create_symlink("loop.json", dir_ / "loop.json");
  try {
    (void)foldlab::read_text_file(dir_ / "loop.json", foldlab::kMaxPresetFileBytes);
    ADD_FAILURE() << "read a symlink loop";
  } catch (const foldlab::ReadError& e) {
    EXPECT_TRUE(contains(e.what(), "(Too many levels of symbolic links)")) << e.what();
  }
}

TEST_F(IoTest, ReadingAFifoIsRefusedWithoutWaitingForAWriter) {
  const fs::path fifo = dir_ / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  try {
    (void)foldlab::read_text_file(fifo, foldlab::kMaxPresetFileBytes);
    ADD_FAILURE() << "read a FIFO";
  } catch (const foldlab::ReadError& e) {
    EXPECT_TRUE(contains(e.what(), "a FIFO, not a regular file")) << e.what();
  }
  try {
    (void)foldlab::read_text_file("/dev/zero", foldlab::kMaxPresetFileBytes);
    ADD_FAILURE() << "read a device";
  } catch (const foldlab::ReadError& e) {
    EXPECT_TRUE(contains(e.what(), "a character device, not a regular file")) << e.what();
  }
}

// A file over its kind's cap is refused from its size alone, before a byte is read: a 2 GiB
// sparse file costs no memory and no time.
TEST_F(IoTest, AFileOverItsCapIsRefusedBeforeItIsRead) {
  const fs::path big = dir_ / "big.csv";
  write_bytes(big, "");
  fs::resize_file(big, std::uintmax_t{2} << 30);
  try {
    (void)foldlab::read_text_file(big, foldlab::kMaxMeasurementsFileBytes);
    ADD_FAILURE() << "read 2 GiB";
  } catch (const foldlab::ReadError& e) {
    EXPECT_TRUE(contains(e.what(), "2.0 GB, more than the 4.0 MB such a file may have"))
        << e.what();
  }
  write_bytes(big, std::string(1000, 'x'));
  EXPECT_EQ(foldlab::read_text_file(big, 1000).size(), 1000u);  // the cap itself is allowed
  EXPECT_THROW((void)foldlab::read_text_file(big, 999), foldlab::ReadError);
}

// --- Writing files ------------------------------------------------------------------------------

TEST_F(IoTest, SavingThroughASymlinkReplacesItsTargetAndKeepsTheLink) {
  fs::create_directory(dir_ / "real");
  write_bytes(dir_ / "real" / "preset.json", "old\n");
  fs::create_symlink("real/preset.json", dir_ / "link.json");
  foldlab::write_file_atomically(dir_ / "link.json", "new\n");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
  EXPECT_EQ(read_bytes(dir_ / "real" / "preset.json"), "new\n");
  // A dangling link gets its target created, as an editor would.
  fs::create_symlink("real/fresh.json", dir_ / "dangling.json");
  foldlab::write_file_atomically(dir_ / "dangling.json", "fresh\n");
  EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.json"));
  EXPECT_EQ(read_bytes(dir_ / "real" / "fresh.json"), "fresh\n");
}

TEST_F(IoTest, ReplacingAFileKeepsItsPermissions) {
  const fs::path path = dir_ / "private.json";
  write_bytes(path, "old\n");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  foldlab::write_file_atomically(path, "new\n");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
}

TEST_F(IoTest, AFifoIsRefusedAndLeftInPlace) {
  const fs::path fifo = dir_ / "out.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const std::string message = write_error(fifo);
  EXPECT_TRUE(contains(message, "a FIFO, not a regular file")) << message;
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(IoTest, ADirectoryIsRefused) {
  fs::create_directory(dir_ / "out.obj");
  const std::string message = write_error(dir_ / "out.obj");
  EXPECT_TRUE(contains(message, "a directory, not a regular file")) << message;
  EXPECT_TRUE(fs::is_directory(dir_ / "out.obj"));
}

TEST_F(IoTest, ADeviceIsRefusedAndLeftInPlace) {
  // A private copy of /dev/full (character device 1, 7): making one needs CAP_MKNOD.
  const fs::path device = dir_ / "full";
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    GTEST_SKIP() << "cannot make a device node here";
  }
  const std::string message = write_error(device);
  EXPECT_TRUE(contains(message, "a character device, not a regular file")) << message;
  EXPECT_TRUE(fs::is_character_file(device));
}

TEST_F(IoTest, ASymlinkLoopIsRefusedWithTheReason) {
  fs::create_symlink("b.json", dir_ / "a.json");
  fs::create_symlink("a.json", dir_ / "b.json");
  const std::string message = write_error(dir_ / "a.json");
  EXPECT_TRUE(contains(message, "Too many levels of symbolic links")) << message;
  EXPECT_TRUE(fs::is_symlink(dir_ / "a.json"));
}

TEST_F(IoTest, StaleTemporariesOfDeadProcessesAreRemovedOthersKept) {
  const fs::path path = dir_ / "preset.json";
  const std::string dead = std::to_string(dead_pid());
  const std::string alive = std::to_string(::getppid());
  write_bytes(dir_ / ("preset.json.tmp." + dead + ".0"), "stale");
  write_bytes(dir_ / ("preset.json.tmp." + alive + ".3"), "someone else's save in progress");
  write_bytes(dir_ / ("other.json.tmp." + dead + ".0"), "another file's");
  write_bytes(dir_ / ("preset.json.tmp." + dead + ".notanumber"), "not ours");
  foldlab::write_file_atomically(path, "new\n");
  EXPECT_EQ(read_bytes(path), "new\n");
  EXPECT_FALSE(fs::exists(dir_ / ("preset.json.tmp." + dead + ".0")));
  EXPECT_TRUE(fs::exists(dir_ / ("preset.json.tmp." + alive + ".3")));
  EXPECT_TRUE(fs::exists(dir_ / ("other.json.tmp." + dead + ".0")));
  EXPECT_TRUE(fs::exists(dir_ / ("preset.json.tmp." + dead + ".notanumber")));
}

// A placeholder goes unless kept, and only while its name holds the empty file it created: a file
// written over it, or one that replaced it, stays. The same rule holds in a signal handler
// (remove_pending_temporaries), which removes what is pending and nothing else.
TEST_F(IoTest, APlaceholderIsRemovedOnlyWhileItIsTheEmptyFileItCreated) {
  const fs::path dropped = dir_ / "dropped.csv";
  const fs::path kept = dir_ / "kept.csv";
  const fs::path replaced = dir_ / "replaced.csv";
  const fs::path signalled = dir_ / "signalled.csv";
  {
    foldlab::NewFilePlaceholder a;
    foldlab::NewFilePlaceholder b;
    foldlab::NewFilePlaceholder c;
    for (auto [placeholder, path] :
         {std::pair{&a, dropped}, std::pair{&b, kept}, std::pair{&c, replaced}}) {
      const int fd = placeholder->create(path, O_RDONLY | O_CLOEXEC);
      ASSERT_GE(fd, 0) << path;
      ::close(fd);
      EXPECT_TRUE(fs::exists(path));
    }
    b.keep();
    foldlab::write_file_atomically(replaced, "name,n\n");
  }
  EXPECT_FALSE(fs::exists(dropped));
  EXPECT_TRUE(fs::exists(kept));
  EXPECT_EQ(read_bytes(replaced), "name,n\n");

  foldlab::NewFilePlaceholder pending;
  const int fd = pending.create(signalled, O_RDONLY | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  ::close(fd);
  foldlab::remove_pending_temporaries();
  EXPECT_FALSE(fs::exists(signalled));
  EXPECT_TRUE(fs::exists(kept));
}

// The temporary of the longest name a file may have (255 bytes) fits the same limit.
TEST_F(IoTest, AFileWithTheLongestLegalNameIsWritten) {
  const fs::path path = dir_ / (std::string(251, 'a') + ".csv");
  foldlab::write_file_atomically(path, "x\n");
  EXPECT_EQ(read_bytes(path), "x\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(IoTest, WriteErrorsGiveTheSystemsReason) {
  write_bytes(dir_ / "plain", "x");
  const std::string message = write_error(dir_ / "plain" / "out.json");
  EXPECT_TRUE(contains(message, "(Not a directory)")) << message;
}

// --- Nothing non-finite is written --------------------------------------------------------------

TEST(FiniteOrThrow, PassesFiniteValuesAndNamesTheFieldOfOthers) {
  EXPECT_EQ(foldlab::detail::finite_or_throw(1.5, "Q"), 1.5);
  for (double bad :
       {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN()}) {
    try {
      (void)foldlab::detail::finite_or_throw(bad, "z_max_mm");
      ADD_FAILURE() << bad << " passed";
    } catch (const std::logic_error& e) {
      EXPECT_TRUE(contains(e.what(), "z_max_mm")) << e.what();
    }
  }
}

TEST(FiniteOrThrow, TheSolutionWritersRefuseANonFiniteNumber) {
  const foldlab::Parameters p;
  foldlab::Solution s = foldlab::solve(p);
  ASSERT_NO_THROW((void)foldlab::solution_to_json(s, p));
  s.Q = std::numeric_limits<double>::infinity();
  try {
    (void)foldlab::solution_to_json(s, p);
    ADD_FAILURE() << "solution_to_json wrote Q = inf (as null)";
  } catch (const std::logic_error& e) {
    EXPECT_TRUE(contains(e.what(), "Q")) << e.what();
  }
  EXPECT_THROW((void)foldlab::solution_table(s, p, "x"), std::logic_error);
  s = foldlab::solve(p);
  s.a_mm.back() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)foldlab::solution_to_json(s, p), std::logic_error);
}

TEST(FiniteOrThrow, ThePresetWriterRefusesANonFiniteNumber) {
  foldlab::Preset preset = foldlab::default_preset();
  preset.published.Q = std::numeric_limits<double>::infinity();
  try {
    (void)foldlab::preset_to_json(preset);
    ADD_FAILURE() << "preset_to_json wrote Q = inf";
  } catch (const std::logic_error& e) {
    EXPECT_TRUE(contains(e.what(), "/published/Q")) << e.what();
  }
}

// --- Messages -----------------------------------------------------------------------------------

TEST(StiffMessage, NamesSToThePWhenPIsNotOne) {
  foldlab::Parameters p;
  p.fabric.thickness_mm = 50.0;  // s = K E t^3 / (w h l^2) far above 1
  p.model.stress_exponent_p = 0.5;
  const foldlab::Solution s = foldlab::solve(p);
  ASSERT_EQ(s.regime, foldlab::Regime::stiff);
  const std::string message = foldlab::describe(s, p);
  EXPECT_TRUE(contains(message, "s^p = ")) << message;
  EXPECT_TRUE(contains(message, "^0.5 = ")) << message;
  // s^p by an independent pow of the reported s.
  const std::string expected =
      foldlab::detail::printf_string("%.3g >= 1", std::sqrt(s.stress_ratio));
  EXPECT_TRUE(contains(message, expected)) << message << " vs " << expected;
  p.model.stress_exponent_p = 1.0;
  EXPECT_TRUE(contains(foldlab::describe(foldlab::solve(p), p), "Stiff: s = "));
}

}  // namespace

// The table's columns line up as a terminal shows them: "c/(1-ν²)" and "Et³/12(1-ν²)" are more
// bytes than characters, and their rows' symbols stood two columns left of the others.
TEST(SolutionTable, ColumnsLineUpByCharactersNotBytes) {
  const foldlab::Parameters p;
  const std::string table = foldlab::solution_table(foldlab::solve(p), p, "x");
  const auto column_of = [&](const std::string& row_start, const std::string& symbol) {
    const std::size_t start = table.find(row_start);
    EXPECT_NE(start, std::string::npos) << row_start;
    const std::size_t at = table.find(" " + symbol + " ", start + row_start.size());
    std::size_t shown = 0;
    for (std::size_t i = table.rfind('\n', start) + 1; i <= at; ++i) {
      shown += (static_cast<unsigned char>(table[i]) & 0xC0) != 0x80 ? 1 : 0;
    }
    return shown;
  };
  const std::size_t thickness = column_of("  thickness", "t");
  EXPECT_EQ(column_of("  eq. 7 constant c/(1-ν²)", "K"), thickness);
  EXPECT_EQ(column_of("  bending stiffness Et³/12(1-ν²)", "B"), thickness);
  EXPECT_EQ(thickness, 2u + 34u + 1u);  // two spaces, the label's 34 columns, one space
}
