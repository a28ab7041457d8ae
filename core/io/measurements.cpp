#include "core/io/measurements.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/io/io.hpp"
#include "core/io/json_input.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/model/named_enum.hpp"
#include "core/model/settings.hpp"
#include "core/model/shape.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

using detail::shortest_number;
using nlohmann::json;

constexpr std::string_view kName = "name";
constexpr std::string_view kGroup = "group";
constexpr std::string_view kRole = "role";
constexpr std::string_view kShape = "shape";
constexpr std::string_view kCount = "n";
constexpr std::string_view kDepth = "z_max_mm";
constexpr std::string_view kRatio = "Q";

// The inputs a row must give: the input table's required rows (the cloth and its hanging). Their
// columns are named as validate() names its fields, so that a range problem names the column.
const std::vector<const InputSpec*>& row_inputs() {
  static const std::vector<const InputSpec*> rows = [] {
    std::vector<const InputSpec*> out;
    for (const InputSpec& spec : input_table()) {
      if (spec.required) {
        out.push_back(&spec);
      }
    }
    return out;
  }();
  return rows;
}

std::string required_columns() {
  std::vector<std::string_view> fields;
  for (const InputSpec* spec : row_inputs()) {
    fields.push_back(spec->field);
  }
  return detail::join(fields, ", ");
}

bool is_row_input(std::string_view column) {
  return std::any_of(row_inputs().begin(), row_inputs().end(),
                     [&](const InputSpec* spec) { return spec->field == column; });
}

std::string known_columns() {
  return detail::join(measurement_columns(), ", ");
}

bool is_known_column(std::string_view name) {
  const auto& columns = measurement_columns();
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

// One cell of a row as the file gives it: absent or empty, text (every CSV cell, JSON strings),
// a JSON number, or some other JSON value (described for the message).
struct Cell {
  enum class Kind { missing, text, number, other } kind = Kind::missing;
  std::string text;
  double number = 0.0;
  bool number_is_integer = false;
};

// Turns the cells of one row into a Measurement, collecting every problem with its row and column.
class RowReader {
 public:
  // `typed`: the file has its own number type (JSON), so text where a number belongs is an error
  // rather than something to parse.
  RowReader(std::string where, std::map<std::string, Cell, std::less<>> cells, bool typed,
            std::vector<std::string>& problems)
      : where_(std::move(where)), cells_(std::move(cells)), typed_(typed), problems_(problems) {}

  void problem(std::string_view column, const std::string& what) {
    problems_.push_back(where_ + ", column " + std::string(column) + ": " + what);
  }

  const Cell& cell(std::string_view column) const {
    static const Cell missing;
    const auto it = cells_.find(column);
    return it == cells_.end() ? missing : it->second;
  }

  std::optional<double> number(std::string_view column, bool required) {
    const Cell& c = cell(column);
    switch (c.kind) {
      case Cell::Kind::missing:
        if (required) {
          problem(column, "missing (a number is required)");
        }
        return std::nullopt;
      case Cell::Kind::number:
        return c.number;
      case Cell::Kind::text:
        if (const std::optional<double> value = parse_number(c.text); value && !typed_) {
          return value;
        }
        problem(column, typed_ ? "expected a number, got text \"" + detail::cut(c.text) + "\""
                               : "'" + detail::cut(c.text) + "' is not a number");
        return std::nullopt;
      case Cell::Kind::other:
        problem(column, "expected a number, got " + c.text);
        return std::nullopt;
    }
    return std::nullopt;
  }

  std::optional<int> whole_number(std::string_view column) {
    const Cell& c = cell(column);
    const std::size_t before = problems_.size();
    const std::optional<double> value = number(column, false);
    if (!value || problems_.size() != before) {
      return std::nullopt;
    }
    const bool whole =
        c.kind == Cell::Kind::number ? c.number_is_integer : *value == std::floor(*value);
    if (!whole || std::abs(*value) > 1e9) {
      problem(column,
              "'" + (c.kind == Cell::Kind::text ? detail::cut(c.text) : shortest_number(*value)) +
                  "' is not a whole number");
      return std::nullopt;
    }
    return static_cast<int>(*value);
  }

  std::string text(std::string_view column) {
    const Cell& c = cell(column);
    if (c.kind == Cell::Kind::missing) {
      return "";
    }
    if (c.kind != Cell::Kind::text) {
      problem(column, "expected text, got " + (c.kind == Cell::Kind::number
                                                   ? "the number " + shortest_number(c.number)
                                                   : c.text));
      return "";
    }
    if (c.text.find_first_of("\r\n") != std::string::npos) {
      problem(column, "text must be one line");
      return "";
    }
    // The text goes on into JSON reports and files, which hold UTF-8 only.
    if (!detail::is_valid_utf8(c.text)) {
      problem(column, "'" + detail::cut(c.text) + "' is not UTF-8 text (save the file as UTF-8)");
      return "";
    }
    return c.text;
  }

  Measurement read(int row) {
    Measurement m;
    m.row = row;
    m.name = text(kName);
    m.group = text(kGroup);
    if (const std::string role = text(kRole);
        !role.empty() && !parse_measurement_role(role, m.role)) {
      problem(kRole, "'" + detail::cut(role) + "' is not one of: fit, check");
    }
    Parameters given;
    bool all_given = true;
    for (const InputSpec* spec : row_inputs()) {
      const std::optional<double> value = number(spec->field, true);
      all_given = all_given && value.has_value();
      if (value) {
        spec->access.set(given, *value);
      }
    }
    m.shape = text(kShape);
    if (ShapeKind kind{}; !m.shape.empty() && !parse_shape_kind(m.shape, kind)) {
      problem(kShape, "'" + detail::cut(m.shape) +
                          "' is not a shape FoldLab knows (cosine, rectangular, "
                          "strip, inclined); leave it empty if unsure");
    }
    const std::size_t before_observed = problems_.size();
    if (const std::optional<int> n = whole_number(kCount)) {
      m.observed.n = *n;
      if (*n < 0) {
        problem(kCount, "a number of wrinkles is >= 0");
      } else if (*n > kMaxObservedFolds) {
        problem(kCount, std::to_string(*n) + " folds: at most " +
                            std::to_string(kMaxObservedFolds) +
                            " can be observed on one cloth (a typing error?)");
      }
    }
    if (const std::optional<double> z = number(kDepth, false)) {
      m.observed.z_max_mm = *z;
      if (!(*z > 0.0)) {
        problem(kDepth,
                shortest_number(*z) + " must be > 0: an observed depth is compared by ratio");
      }
    }
    if (const std::optional<double> Q = number(kRatio, false)) {
      m.observed.Q = *Q;
      if (!(*Q > 1.0)) {
        problem(kRatio, shortest_number(*Q) +
                            " must be > 1: a ratio of consecutive amplitudes (leave out a "
                            "misprint)");
      } else if (*Q > kMaxObservedRatio) {
        problem(kRatio, shortest_number(*Q) + " must be at most " +
                            shortest_number(kMaxObservedRatio) +
                            ": folds that far apart in depth are not a series of folds");
      }
    }
    if (problems_.size() == before_observed && !m.observed.n && !m.observed.z_max_mm &&
        !m.observed.Q) {
      problems_.push_back(where_ + ": nothing observed: give at least one of n, z_max_mm, Q");
    }
    if (all_given) {
      m.inputs = given;
      const double half_length = 0.5 * given.hanging.length_mm;
      if (m.observed.z_max_mm && *m.observed.z_max_mm > 0.0 && *m.observed.z_max_mm > half_length) {
        problem(kDepth,
                shortest_number(*m.observed.z_max_mm) +
                    " is deeper than half the upper edge, L/2 = " + shortest_number(half_length) +
                    " mm, which no fold of this cloth can reach");
      }
      // The model's own ranges, with its reasons, for the inputs a row sets.
      for (const ValidationIssue& issue : validate(given)) {
        if (is_row_input(issue.field)) {
          problem(issue.field, issue.message);
        }
      }
    }
    return m;
  }

 private:
  std::string where_;
  std::map<std::string, Cell, std::less<>> cells_;
  bool typed_;
  std::vector<std::string>& problems_;
};

using detail::join_lines;

std::string_view trim(std::string_view s) {
  const std::size_t first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) {
    return {};
  }
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// One CSV line into fields (RFC 4180 quoting within one line). Returns an error sentence for an
// unterminated quote or text after a closing quote.
std::optional<std::string> split_csv_line(std::string_view line, std::vector<std::string>& fields) {
  fields.clear();
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
      ++i;
    }
    std::string field;
    if (i < line.size() && line[i] == '"') {
      ++i;
      bool closed = false;
      while (i < line.size()) {
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          closed = true;
          break;
        }
        field += line[i++];
      }
      if (!closed) {
        return "a quoted field is not closed (quotes inside a field are written \"\")";
      }
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
        ++i;
      }
      if (i < line.size() && line[i] != ',') {
        return "text after the closing quote of field " + std::to_string(fields.size() + 1);
      }
    } else {
      const std::size_t end = std::min(line.find(',', i), line.size());
      field = std::string(trim(line.substr(i, end - i)));
      i = end;
    }
    fields.push_back(std::move(field));
    if (i >= line.size()) {
      return std::nullopt;
    }
    ++i;  // the comma
  }
}

std::string csv_text(const std::string& text) {
  if (text.find_first_of("\r\n") != std::string::npos) {
    throw MeasurementError("'" + detail::cut(text) + "': CSV text fields must be one line");
  }
  const bool quote =
      text.find_first_of(",\"") != std::string::npos ||
      (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.back() == ' ' ||
                         text.back() == '\t' || text.front() == '#'));
  if (!quote) {
    return text;
  }
  std::string out = "\"";
  for (char c : text) {
    out += c == '"' ? "\"\"" : std::string(1, c);
  }
  return out + "\"";
}

// The cells of one measurement by column, as the writers put them out.
std::vector<std::pair<std::string_view, std::string>> csv_cells(const Measurement& m) {
  auto optional_number = [](const auto& value, std::string_view field) {
    return value ? shortest_number(detail::finite_or_throw(static_cast<double>(*value), field))
                 : std::string();
  };
  std::vector<std::pair<std::string_view, std::string>> cells = {
      {kName, csv_text(m.name)},
      {kGroup, csv_text(m.group)},
      {kRole, std::string(to_string(m.role))},
      {kShape, csv_text(m.shape)},
      {kCount, m.observed.n ? std::to_string(*m.observed.n) : std::string()},
      {kDepth, optional_number(m.observed.z_max_mm, kDepth)},
      {kRatio, optional_number(m.observed.Q, kRatio)}};
  std::vector<std::pair<std::string_view, std::string>> input_cells;
  for (const InputSpec* spec : row_inputs()) {
    input_cells.emplace_back(
        spec->field, shortest_number(detail::finite_or_throw(*spec->value(m.inputs), spec->field)));
  }
  cells.insert(cells.begin() + 3, input_cells.begin(), input_cells.end());
  return cells;
}

// Without an extension that decides, text that opens a JSON object is read as JSON, any other
// text as CSV.
constexpr char kJsonObjectOpen = '{';

bool opens_json_object(std::string_view text) {
  const std::string_view content = trim(text);
  return !content.empty() && content.front() == kJsonObjectOpen;
}

void throw_if_any(const std::vector<std::string>& problems) {
  if (!problems.empty()) {
    throw MeasurementError(join_lines(problems));
  }
}

// A CSV line as its content: without the CR of a CRLF ending, and the first line without the
// UTF-8 byte order mark that spreadsheets write.
void strip_line_ending(std::string& line, bool first_line) {
  if (!line.empty() && line.back() == '\r') {
    line.pop_back();
  }
  if (first_line && line.rfind("\xEF\xBB\xBF", 0) == 0) {
    line.erase(0, 3);
  }
}

bool is_blank_or_comment(std::string_view line) {
  const std::string_view content = trim(line);
  return content.empty() || content.front() == '#';
}

// Each header column must be a known one, named once.
void add_column_name_problems(const std::vector<std::string>& header, const std::string& where,
                              std::vector<std::string>& problems) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (!is_known_column(header[i])) {
      problems.push_back(where + " (header), column " + std::to_string(i + 1) + " '" +
                         detail::cut(header[i]) + "': unknown column (known: " + known_columns() +
                         ")");
    } else if (std::find(header.begin(), header.begin() + static_cast<std::ptrdiff_t>(i),
                         header[i]) != header.begin() + static_cast<std::ptrdiff_t>(i)) {
      problems.push_back(where + " (header), column " + std::to_string(i + 1) + " '" +
                         detail::cut(header[i]) + "': appears twice");
    }
  }
}

void add_missing_column_problem(const std::vector<std::string>& header, const std::string& where,
                                std::vector<std::string>& problems) {
  std::vector<std::string_view> missing_columns;
  for (const InputSpec* spec : row_inputs()) {
    if (std::find(header.begin(), header.end(), spec->field) == header.end()) {
      missing_columns.push_back(spec->field);
    }
  }
  const std::string missing = detail::join(missing_columns, ", ");
  if (!missing.empty()) {
    problems.push_back(where + " (header): missing column(s) " + missing +
                       " (required: " + required_columns() + ")");
  }
}

// The header line into `header`; false, with its problems added, when rows cannot be read by it.
bool read_csv_header(const std::string& line, const std::string& where,
                     std::vector<std::string>& header, std::vector<std::string>& problems) {
  if (const auto error = split_csv_line(line, header)) {
    problems.push_back(where + " (header): " + *error);
    return false;
  }
  const std::size_t before = problems.size();
  add_column_name_problems(header, where, problems);
  add_missing_column_problem(header, where, problems);
  return problems.size() == before;
}

// A data line's cells by the header's names, or nothing (with the problem added) when the line
// does not split into one field per column.
std::optional<std::map<std::string, Cell, std::less<>>> csv_row_cells(
    const std::string& line, const std::vector<std::string>& header, const std::string& row_where,
    std::vector<std::string>& problems) {
  std::vector<std::string> fields;
  if (const auto error = split_csv_line(line, fields)) {
    problems.push_back(row_where + ": " + *error);
    return std::nullopt;
  }
  if (fields.size() != header.size()) {
    problems.push_back(row_where + ": " + std::to_string(fields.size()) +
                       " fields, the header has " + std::to_string(header.size()));
    return std::nullopt;
  }
  std::map<std::string, Cell, std::less<>> cells;
  for (std::size_t i = 0; i < header.size(); ++i) {
    Cell cell;
    if (!fields[i].empty()) {
      cell.kind = Cell::Kind::text;
      cell.text = fields[i];
    }
    cells[header[i]] = std::move(cell);
  }
  return cells;
}

// A JSON value as a cell: an empty string is no value, as an empty CSV field is.
Cell json_cell(const json& value) {
  Cell cell;
  if (value.is_string()) {
    cell.kind = value.get<std::string>().empty() ? Cell::Kind::missing : Cell::Kind::text;
    cell.text = value.get<std::string>();
  } else if (value.is_number()) {
    cell.kind = Cell::Kind::number;
    cell.number = value.get<double>();
    cell.number_is_integer = value.is_number_integer();
  } else if (!value.is_null()) {
    cell.kind = Cell::Kind::other;
    cell.text = describe_json(value);
  }
  return cell;
}

}  // namespace

const std::vector<std::string_view>& measurement_columns() {
  static const std::vector<std::string_view> columns = [] {
    std::vector<std::string_view> out = {kName, kGroup, kRole};
    for (const InputSpec* spec : row_inputs()) {
      out.push_back(spec->field);
    }
    out.insert(out.end(), {kShape, kCount, kDepth, kRatio});
    return out;
  }();
  return columns;
}

MeasurementSet measurements_from_csv(const std::string& text, const std::string& origin) {
  MeasurementSet set;
  set.origin = origin;
  std::vector<std::string> problems;
  std::vector<std::string> header;
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  int row = 0;
  while (std::getline(in, line)) {
    ++line_number;
    strip_line_ending(line, line_number == 1);
    if (is_blank_or_comment(line)) {
      continue;
    }
    const std::string where = origin + ": line " + std::to_string(line_number);
    if (header.empty()) {
      if (!read_csv_header(line, where, header, problems)) {
        break;  // every row would repeat the header's problem
      }
      continue;
    }
    ++row;
    const std::string row_where = where + " (row " + std::to_string(row) + ")";
    if (auto cells = csv_row_cells(line, header, row_where, problems)) {
      set.rows.push_back(RowReader(row_where, std::move(*cells), false, problems).read(row));
    }
  }
  if (problems.empty() && header.empty()) {
    problems.push_back(origin + ": no header line (expected the columns " + known_columns() + ")");
  } else if (problems.empty() && set.rows.empty()) {
    problems.push_back(origin + ": no rows after the header");
  }
  throw_if_any(problems);
  return set;
}

MeasurementSet measurements_from_json(const json& j, const std::string& origin) {
  MeasurementSet set;
  set.origin = origin;
  std::vector<std::string> problems;
  auto fail = [&](const std::string& what) {
    problems.push_back(origin + ": " + what);
    throw MeasurementError(join_lines(problems));
  };
  if (!j.is_object()) {
    fail("expected an object with \"foldlab_measurements\": 1 and \"rows\", got " +
         describe_json(j));
  }
  for (const auto& [key, value] : j.items()) {
    if (key != "foldlab_measurements" && key != "description" && key != "source" && key != "rows") {
      problems.push_back(origin + ": /" + detail::cut(key) +
                         ": unknown key (allowed: foldlab_measurements, description, source, "
                         "rows)");
    }
  }
  if (!j.contains("foldlab_measurements") || !j.at("foldlab_measurements").is_number_integer() ||
      j.at("foldlab_measurements").get<long long>() != kMeasurementsFormatVersion) {
    problems.push_back(origin + ": /foldlab_measurements: expected " +
                       std::to_string(kMeasurementsFormatVersion) +
                       " (the format version of a FoldLab measurements file)");
  }
  for (const char* key : {"description", "source"}) {
    if (j.contains(key) && !j.at(key).is_string()) {
      problems.push_back(origin + ": /" + key + ": expected text, got " + describe_json(j.at(key)));
    } else if (j.contains(key)) {
      (std::string(key) == "description" ? set.description : set.source) =
          j.at(key).get<std::string>();
    }
  }
  if (!j.contains("rows") || !j.at("rows").is_array()) {
    fail("/rows: expected an array of rows, one object per measured hanging");
  }
  const json& rows = j.at("rows");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int row = static_cast<int>(i) + 1;
    const std::string where =
        origin + ": row " + std::to_string(row) + " (/rows/" + std::to_string(i) + ")";
    const json& r = rows[i];
    if (!r.is_object()) {
      problems.push_back(where + ": expected an object, got " + describe_json(r));
      continue;
    }
    std::map<std::string, Cell, std::less<>> cells;
    for (const auto& [key, value] : r.items()) {
      if (!is_known_column(key)) {
        problems.push_back(where + ", column " + detail::cut(key) +
                           ": unknown column (known: " + known_columns() + ")");
        continue;
      }
      cells[key] = json_cell(value);
    }
    // Read even with an unknown key, so that every other problem of the row is reported too.
    set.rows.push_back(RowReader(where, std::move(cells), true, problems).read(row));
  }
  if (problems.empty() && set.rows.empty()) {
    problems.push_back(origin + ": /rows: no rows");
  }
  throw_if_any(problems);
  return set;
}

MeasurementSet measurements_from_text(const std::string& text, const std::string& origin,
                                      std::string_view extension) {
  const bool is_json = extension == ".json" || (extension != ".csv" && opens_json_object(text));
  if (!is_json) {
    return measurements_from_csv(text, origin);
  }
  json j;
  try {
    j = parse_json(text, origin);
  } catch (const JsonInputError& e) {
    throw MeasurementError(e.what());
  }
  return measurements_from_json(j, origin);
}

MeasurementSet load_measurements(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_text_file(path, kMaxMeasurementsFileBytes);
  } catch (const ReadError& e) {
    throw MeasurementError(e.what());
  }
  return measurements_from_text(text, path.string(), path.extension().string());
}

namespace {

// An exclusive flock on the measurements file itself, held from reading it to replacing it, so
// that appends from several processes (the CLI, the explorer) never drop each other's rows. The
// replacement is a new file renamed into place, so a lock taken on the old one protects nothing
// once it is gone: the lock is only held once the locked file is still the one at `path`.
class AppendLock {
 public:
  explicit AppendLock(const std::filesystem::path& path) {
    for (;;) {
      bool creating = false;
      // Read-only is enough for flock, and keeps a read-only file appendable as before (it is
      // replaced, not written in place); O_NONBLOCK: a FIFO must not block the open.
      fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
      if (fd_ < 0 && errno == ENOENT) {
        creating = true;
        // Not O_EXCL: a dangling symbolic link gets its target created, as the write would.
        fd_ = placeholder_.create(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
      }
      if (fd_ < 0) {
        const int error = errno;
        struct stat there {};
        if (!creating && ::lstat(path.c_str(), &there) == 0) {
          throw MeasurementError(path.string() + ": cannot open for reading (" +
                                 std::strerror(error) + ")");
        }
        throw WriteError(path.string() + ": cannot write (" + std::strerror(error) + ")");
      }
      struct stat locked {};
      if (::fstat(fd_, &locked) != 0 || !S_ISREG(locked.st_mode)) {
        return;  // not a regular file: the reader and the writer name the problem
      }
      while (::flock(fd_, LOCK_EX) != 0) {
        if (errno != EINTR) {
          const int error = errno;
          ::close(fd_);
          throw WriteError(path.string() + ": cannot lock (" + std::strerror(error) + ")");
        }
      }
      struct stat current {};
      if (::stat(path.c_str(), &current) == 0 && current.st_dev == locked.st_dev &&
          current.st_ino == locked.st_ino) {
        return;
      }
      ::close(fd_);  // replaced while waiting: lock the new file
      fd_ = -1;
    }
  }
  ~AppendLock() {
    // Created only to lock it: a refused append leaves no empty file behind.
    placeholder_.remove_unless_kept();
    if (fd_ >= 0) {
      ::close(fd_);  // releases the lock
    }
  }
  AppendLock(const AppendLock&) = delete;
  AppendLock& operator=(const AppendLock&) = delete;
  void written() { placeholder_.keep(); }

 private:
  int fd_ = -1;
  // A new file, created to be locked: removed by SIGINT or SIGTERM too until the row is written.
  NewFilePlaceholder placeholder_;
};

}  // namespace

void append_measurement(const std::filesystem::path& path, const Measurement& row) {
  const std::string origin = path.string();
  AppendLock lock(path);
  std::string text;
  std::error_code error;
  bool exists = std::filesystem::exists(path, error);
  MeasurementSet set;
  if (exists) {
    try {
      text = read_text_file(path, kMaxMeasurementsFileBytes);
    } catch (const ReadError& e) {
      throw MeasurementError(e.what());
    }
    // An empty file (just created with `touch`, say) is a new one: it gets the header.
    exists = !trim(text).empty();
    if (exists) {
      set = measurements_from_text(text, origin, path.extension().string());
    }
  }
  std::string out;
  const bool is_json = path.extension() == ".json" || (exists && opens_json_object(text));
  if (is_json || !exists) {
    set.rows.push_back(row);
    out = is_json ? measurements_to_json(set).dump(2) + "\n" : measurements_to_csv(set);
  } else {
    // Append in the file's own column order, so that its comments and layout stay as they are.
    std::vector<std::string> header;
    std::istringstream lines(text);
    for (std::string line; header.empty() && std::getline(lines, line);) {
      if (!line.empty() && line.back() == '\r') {
        line.pop_back();
      }
      if (line.rfind("\xEF\xBB\xBF", 0) == 0) {
        line.erase(0, 3);
      }
      const std::string_view content = trim(line);
      if (!content.empty() && content.front() != '#') {
        split_csv_line(line, header);
      }
    }
    std::vector<std::string> cells(header.size());
    std::vector<std::string> problems;
    for (auto& [column, value] : csv_cells(row)) {
      const auto at = std::find(header.begin(), header.end(), column);
      if (at != header.end()) {
        cells[static_cast<std::size_t>(at - header.begin())] = std::move(value);
      } else if (!value.empty()) {
        problems.push_back(origin + ": no column " + std::string(column) + " for the value " +
                           value + " (add the column, or append to a new file)");
      }
    }
    if (!problems.empty()) {
      throw MeasurementError(detail::join_lines(problems));
    }
    out = text;
    if (!out.empty() && out.back() != '\n') {
      out += '\n';
    }
    out += detail::join(cells, ",") + "\n";
  }
  // The row is checked by the rules that will read it: a file this wrote must open again, or
  // every later append and calibration on it would be refused until edited by hand.
  (void)measurements_from_text(out, origin + " (the row was not added)",
                               is_json ? std::string_view(".json") : std::string_view(".csv"));
  write_file_atomically(path, out);  // WriteError: an I/O failure, not bad input
  lock.written();
}

std::string measurements_to_csv(const MeasurementSet& set) {
  std::string out;
  for (const auto& [label, text] :
       {std::pair{"description", &set.description}, std::pair{"source", &set.source}}) {
    std::istringstream lines(*text);
    for (std::string line; std::getline(lines, line);) {
      out += std::string("# ") + label + ": " + line + "\n";
    }
  }
  out += detail::join(measurement_columns(), ",") + "\n";
  for (const Measurement& m : set.rows) {
    std::vector<std::string> cells;
    for (auto& cell : csv_cells(m)) {
      cells.push_back(std::move(cell.second));
    }
    out += detail::join(cells, ",") + "\n";
  }
  return out;
}

json measurements_to_json(const MeasurementSet& set) {
  json rows = json::array();
  for (const Measurement& m : set.rows) {
    json r = json::object();
    auto put_text = [&r](std::string_view key, const std::string& value) {
      if (!value.empty()) {
        r[std::string(key)] = value;
      }
    };
    put_text(kName, m.name);
    put_text(kGroup, m.group);
    r[std::string(kRole)] = to_string(m.role);
    for (const InputSpec* spec : row_inputs()) {
      r[std::string(spec->field)] = detail::finite_or_throw(*spec->value(m.inputs), spec->field);
    }
    put_text(kShape, m.shape);
    r[std::string(kCount)] = m.observed.n ? json(*m.observed.n) : json(nullptr);
    r[std::string(kDepth)] = m.observed.z_max_mm
                                 ? json(detail::finite_or_throw(*m.observed.z_max_mm, kDepth))
                                 : json(nullptr);
    r[std::string(kRatio)] =
        m.observed.Q ? json(detail::finite_or_throw(*m.observed.Q, kRatio)) : json(nullptr);
    rows.push_back(std::move(r));
  }
  json j = {{"foldlab_measurements", kMeasurementsFormatVersion}};
  if (!set.description.empty()) {
    j["description"] = set.description;
  }
  if (!set.source.empty()) {
    j["source"] = set.source;
  }
  j["rows"] = std::move(rows);
  return j;
}

Parameters parameters_for(const Measurement& row, const Parameters& base) {
  Parameters p = base;
  for (const InputSpec* spec : row_inputs()) {
    spec->access.set(p, spec->access.get(row.inputs));
  }
  return p;
}

std::string_view to_string(MeasurementRole role) {
  return role == MeasurementRole::fit ? "fit" : "check";
}

bool parse_measurement_role(std::string_view s, MeasurementRole& out) {
  return parse_named(s, out, {MeasurementRole::fit, MeasurementRole::check});
}

}  // namespace foldlab
