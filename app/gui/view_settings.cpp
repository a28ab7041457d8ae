#include "app/gui/view_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

std::string as_given(std::string_view key, std::string_view value) {
  return detail::cut(key) + " = '" + detail::cut(value) + "'";
}

// A whole number as one ("grid": 128), any other as it is.
nlohmann::json number_json(double value) {
  if (value == std::floor(value) && std::fabs(value) < 1e15) {
    return nlohmann::json(static_cast<std::int64_t>(value));
  }
  return nlohmann::json(value);
}

std::string names_list(std::span<const std::string_view> names) {
  std::string out;
  for (const std::string_view name : names) {
    out += (out.empty() ? "" : ", ") + std::string(name);
  }
  return out;
}

}  // namespace

ViewSettings::Row ViewSettings::number_row(const char* key, double lo, double hi, const char* unit,
                                           unsigned uses) const {
  Row row{key, uses};
  row.lo = lo;
  row.hi = hi;
  row.set = [key, lo, hi, unit, this](std::string_view value) -> std::optional<std::string> {
    const std::optional<double> number = parse_number(value);
    if (!number) {
      return as_given(key, value) + " is not a number";
    }
    if (!(*number >= lo && *number <= hi)) {
      return detail::cut(key) + " = " + detail::shortest_number(*number) + " must be in [" +
             detail::shortest_number(lo) + ", " + detail::shortest_number(hi) + "]" + unit;
    }
    const Row* self = find(key);
    self->write(*number);
    if (self->on_set) {
      self->on_set();
    }
    return std::nullopt;
  };
  row.say = [this, key] { return number_json(find(key)->read()); };
  return row;
}

void ViewSettings::add_switch(const char* key, bool* value, unsigned uses) {
  add_switch_by(
      key, uses, [value] { return *value; }, [value](bool on) { *value = on; });
}

void ViewSettings::add_switch_by(const char* key, unsigned uses, std::function<bool()> read,
                                 std::function<void(bool)> write) {
  Row row{key, uses};
  row.read = [read] { return read() ? 1.0 : 0.0; };
  row.write = [write](double stored) { write(stored != 0.0); };
  row.hi = 1.0;
  row.is_bool = true;
  row.set = [key, write](std::string_view text) -> std::optional<std::string> {
    const std::optional<double> number = parse_number(text);
    if (number != 0.0 && number != 1.0) {
      return as_given(key, text) + " must be 0 or 1";
    }
    write(number == 1.0);
    return std::nullopt;
  };
  row.say = [read] { return nlohmann::json(read()); };
  rows_.push_back(std::move(row));
}

void ViewSettings::add_choice_by(const char* key, std::span<const std::string_view> names,
                                 unsigned uses, std::function<std::size_t()> read,
                                 std::function<void(std::size_t)> write,
                                 std::function<bool()> saved_while,
                                 std::function<std::optional<std::string>(std::size_t)> check) {
  Row row{key, uses};
  row.read = [read] { return static_cast<double>(read()); };
  row.write = [write](double stored) { write(static_cast<std::size_t>(stored)); };
  row.hi = static_cast<double>(names.size() - 1);
  row.saved_while = std::move(saved_while);
  if (check) {
    row.loadable = [check](double stored) { return !check(static_cast<std::size_t>(stored)); };
  }
  row.set = [key, names, write, check](std::string_view text) -> std::optional<std::string> {
    const auto found = std::find(names.begin(), names.end(), text);
    if (found == names.end()) {
      return as_given(key, text) + " is not one of: " + names_list(names);
    }
    const auto index = static_cast<std::size_t>(found - names.begin());
    if (check) {
      if (std::optional<std::string> refused = check(index)) {
        return refused;
      }
    }
    write(index);
    return std::nullopt;
  };
  row.say = [names, read] {
    const std::size_t index = read();
    return index < names.size() ? nlohmann::json(std::string(names[index]))
                                : nlohmann::json(nullptr);
  };
  rows_.push_back(std::move(row));
}

void ViewSettings::add_number_by(const char* key, ViewRange<double> range, unsigned uses,
                                 std::function<double()> read, std::function<void(double)> write,
                                 bool whole) {
  Row row = number_row(key, range.lo, range.hi, range.unit, uses);
  row.read = std::move(read);
  row.write = std::move(write);
  if (whole) {
    row.set = [key, range, this](std::string_view value) -> std::optional<std::string> {
      const std::optional<double> number = parse_number(value);
      if (!number || *number < range.lo || *number > range.hi || *number != std::floor(*number)) {
        return as_given(key, value) + " is not a whole number from " +
               detail::shortest_number(range.lo) + " to " + detail::shortest_number(range.hi) +
               range.unit;
      }
      find(key)->write(*number);
      return std::nullopt;
    };
  }
  rows_.push_back(std::move(row));
}

void ViewSettings::add_text(const char* key, std::string* value, unsigned uses) {
  Row row{key, uses};
  row.text = value;
  row.set = [key, value](std::string_view text) -> std::optional<std::string> {
    if (text.size() > kMaxTextBytes) {
      return detail::cut(key) + " is longer than " + std::to_string(kMaxTextBytes) + " bytes";
    }
    *value = std::string(text);
    return std::nullopt;
  };
  row.say = [value] { return nlohmann::json(*value); };
  rows_.push_back(std::move(row));
}

void ViewSettings::add_action(const char* key, Setter set, std::function<nlohmann::json()> report) {
  Row row{key, kScripted | (report ? kReported : 0u)};
  row.set = std::move(set);
  row.say = std::move(report);
  rows_.push_back(std::move(row));
}

const ViewSettings::Row* ViewSettings::find(std::string_view key) const {
  const auto found =
      std::find_if(rows_.begin(), rows_.end(), [key](const Row& row) { return key == row.key; });
  return found == rows_.end() ? nullptr : &*found;
}

bool ViewSettings::knows(std::string_view key) const {
  const Row* row = find(key);
  return row != nullptr && (row->uses & kScripted) != 0;
}

std::string ViewSettings::known_keys() const {
  std::string out;
  for (const Row& row : rows_) {
    if ((row.uses & kScripted) != 0) {
      out += (out.empty() ? "" : ", ") + std::string(row.key);
    }
  }
  return out;
}

std::optional<std::string> ViewSettings::set(std::string_view key, std::string_view value) const {
  if (!knows(key)) {
    return "unknown view key '" + detail::cut(key) + "' (known: " + known_keys() + ")";
  }
  return find(key)->set(value);
}

nlohmann::json ViewSettings::report() const {
  nlohmann::json out = nlohmann::json::object();
  for (const Row& row : rows_) {
    if ((row.uses & kReported) != 0 && row.say) {
      out[row.key] = row.say();
    }
  }
  return out;
}

void ViewSettings::save(SessionSettings& settings) const {
  for (const Row& row : rows_) {
    if ((row.uses & kRemembered) == 0 || (row.saved_while && !row.saved_while())) {
      continue;
    }
    if (row.text != nullptr) {
      settings.set(row.key, *row.text);
    } else if (row.is_bool) {
      settings.set(row.key, row.read() != 0.0);
    } else {
      settings.set(row.key, row.read());
    }
  }
}

void ViewSettings::load(const SessionSettings& settings) {
  for (Row& row : rows_) {
    if ((row.uses & kRemembered) == 0) {
      continue;
    }
    if (row.text != nullptr) {
      if (const std::optional<std::string> stored = settings.text(row.key);
          stored && stored->size() <= kMaxTextBytes) {
        *row.text = *stored;
      }
      continue;
    }
    // Read as doubles: a stored 1e308 is refused, not converted to int or float first.
    const double stored = row.is_bool ? (settings.get(row.key, row.read() != 0.0) ? 1.0 : 0.0)
                                      : settings.get(row.key, row.read());
    if (stored >= row.lo && stored <= row.hi && (!row.loadable || row.loadable(stored))) {
      row.write(stored);
    }
  }
  take_changed();
}

bool ViewSettings::take_changed() {
  bool changed = false;
  for (Row& row : rows_) {
    if ((row.uses & kRemembered) == 0) {
      continue;
    }
    if (row.text != nullptr) {
      changed |= *row.text != row.last_text;
      row.last_text = *row.text;
      continue;
    }
    const double now = row.read();
    changed |= now != row.last;
    row.last = now;
  }
  return changed;
}

}  // namespace foldlab::gui
