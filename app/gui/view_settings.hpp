// The explorer's view settings, one row a setting, declared once where its member is: the one
// name that `--view KEY=VALUE`, the link, the session and `gui --report` all use, the values it
// may take, and which of those uses it has (as Dear ImGui's style table maps each key to its
// field). The explorer keeps one table built from every panel's rows: a scripted value is read
// and refused by its row, the "known keys" of a refusal are the table's, the session saves and
// loads the remembered rows, and a change however it was made (a checkbox writes its member
// directly) marks the session, so that it is saved a second later.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/gui/session.hpp"

namespace foldlab::gui {

// What a row is used for; a row may be any mix.
enum ViewUse : unsigned {
  kRemembered = 1u,  // kept in the session between runs
  kScripted = 2u,    // a `--view` key (and a play script's or a test's set_view)
  kReported = 4u,    // listed under "view" in `gui --report` and the play scripts' state
  kEveryUse = kRemembered | kScripted | kReported,
};

// A number's range and unit as its row and its slider read them.
template <class T>
struct ViewRange {
  T lo;
  T hi;
  const char* unit;  // appended to a refusal: " mm", " (times)"
};

class ViewSettings {
 public:
  // Rows refer to their table: it stays where it was built.
  ViewSettings() = default;
  ViewSettings(const ViewSettings&) = delete;
  ViewSettings& operator=(const ViewSettings&) = delete;
  // What a scripted value does: nullopt when it was taken, otherwise why not (the whole sentence).
  using Setter = std::function<std::optional<std::string>(std::string_view value)>;

  // A switch, 0 or 1 when scripted.
  void add_switch(const char* key, bool* value, unsigned uses);
  // A switch read and written through functions (a setting whose owner acts when it changes).
  void add_switch_by(const char* key, unsigned uses, std::function<bool()> read,
                     std::function<void(bool)> write);
  // A number within its range: a scripted value outside it is refused, not moved to the nearest
  // end, so that a typo shows rather than a different picture; a stored one outside it leaves
  // the member as it is. `on_set` runs after a scripted value is taken.
  template <class T>
  void add_number(const char* key, T* value, ViewRange<T> range, unsigned uses,
                  std::function<void()> on_set = {}) {
    Row row = number_row(key, static_cast<double>(range.lo), static_cast<double>(range.hi),
                         range.unit, uses);
    row.read = [value] { return static_cast<double>(*value); };
    row.write = [value](double stored) { *value = static_cast<T>(stored); };
    if (on_set) {
      row.on_set = std::move(on_set);
    }
    rows_.push_back(std::move(row));
  }
  // One of `names`, stored by its index (an enum in the names' order). `saved_while`, when given,
  // is asked before saving: false leaves the stored value as it was read. `check` may refuse a
  // scripted name that the state cannot take now.
  template <class E>
  void add_choice(const char* key, E* value, std::span<const std::string_view> names, unsigned uses,
                  std::function<bool()> saved_while = {},
                  std::function<std::optional<std::string>(E)> check = {}) {
    add_choice_by(
        key, names, uses, [value] { return static_cast<std::size_t>(*value); },
        [value](std::size_t index) { *value = static_cast<E>(index); }, std::move(saved_while),
        check ? std::function<std::optional<std::string>(std::size_t)>(
                    [check](std::size_t index) { return check(static_cast<E>(index)); })
              : nullptr);
  }
  // A choice read and written through functions (a setting whose member takes it at the next
  // frame).
  void add_choice_by(const char* key, std::span<const std::string_view> names, unsigned uses,
                     std::function<std::size_t()> read, std::function<void(std::size_t)> write,
                     std::function<bool()> saved_while = {},
                     std::function<std::optional<std::string>(std::size_t)> check = {});
  // A number read and written through functions; whole numbers only when `whole`.
  void add_number_by(const char* key, ViewRange<double> range, unsigned uses,
                     std::function<double()> read, std::function<void(double)> write,
                     bool whole = false);
  // A line of text kept as it is (an address), at most kMaxTextBytes: a scripted or stored one
  // longer is refused.
  void add_text(const char* key, std::string* value, unsigned uses);
  static constexpr std::size_t kMaxTextBytes = 2000;
  // A setting with words of its own: `set` reads the value, `report` (when given) says it.
  void add_action(const char* key, Setter set, std::function<nlohmann::json()> report = {});

  // A scripted value by key: nullopt when taken, otherwise the refusal, naming the known keys
  // when the key is none of them.
  std::optional<std::string> set(std::string_view key, std::string_view value) const;
  // The scripted keys, in the order declared ("sweep, present, theme, ...").
  std::string known_keys() const;
  bool knows(std::string_view key) const;
  // The reported rows' values by key.
  nlohmann::json report() const;

  // The session: every remembered row saved and loaded.
  void save(SessionSettings& settings) const;
  void load(const SessionSettings& settings);
  // True when any remembered value differs from what it was at the last call (or load).
  bool take_changed();

 private:
  struct Row {
    Row(const char* row_key, unsigned row_uses) : key(row_key), uses(row_uses) {}
    const char* key;
    unsigned uses;
    std::function<double()> read;       // remembered and reported rows
    std::function<void(double)> write;  // remembered rows
    double lo = 0.0;                    // a stored value outside [lo, hi] is not taken
    double hi = 0.0;
    bool is_bool = false;                  // stored as true or false
    std::function<bool()> saved_while;     // see add_choice
    Setter set;                            // scripted rows
    std::function<nlohmann::json()> say;   // reported rows: the value as the report says it
    std::function<void()> on_set;          // after a scripted value was taken
    std::function<bool(double)> loadable;  // may refuse a stored value within [lo, hi]
    double last = 0.0;
    std::string* text = nullptr;  // a text row's value (add_text); read and write unused
    std::string last_text;
  };
  Row number_row(const char* key, double lo, double hi, const char* unit, unsigned uses) const;
  const Row* find(std::string_view key) const;

  std::vector<Row> rows_;
};

}  // namespace foldlab::gui
