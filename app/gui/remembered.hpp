// The settings the session keeps between runs, each declared once, where its member is: the key,
// the member and the range it may take (as Dear ImGui's style table maps each key to its field).
// The list saves and loads every one, and notices a change however it was made (a checkbox writes
// its member directly), so that the session is saved after any of them changes.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "app/gui/session.hpp"

namespace foldlab::gui {

class RememberedSettings {
 public:
  void add(const char* key, bool* value) {
    entries_.push_back({key,
                        [value] { return *value ? 1.0 : 0.0; },
                        [value](double stored) { *value = stored != 0.0; },
                        0.0,
                        1.0,
                        true,
                        {}});
  }
  // A number or an enum, kept within [lo, hi]: a stored value outside it (or of another type)
  // leaves the member as it is. `saved_while`, when given, is asked before saving: false leaves
  // the stored value as it was read.
  template <class T>
  void add(const char* key, T* value, T lo, T hi, std::function<bool()> saved_while = {}) {
    entries_.push_back({key, [value] { return static_cast<double>(*value); },
                        [value](double stored) { *value = static_cast<T>(stored); },
                        static_cast<double>(lo), static_cast<double>(hi), false,
                        std::move(saved_while)});
  }

  void save(SessionSettings& settings) const {
    for (const Entry& e : entries_) {
      if (e.saved_while && !e.saved_while()) {
        continue;
      }
      if (e.is_bool) {
        settings.set(e.key, e.read() != 0.0);
      } else {
        settings.set(e.key, e.read());
      }
    }
  }
  void load(const SessionSettings& settings) {
    for (Entry& e : entries_) {
      // Read as doubles: a stored 1e308 is refused, not converted to int or float first.
      const double stored = e.is_bool ? (settings.get(e.key, e.read() != 0.0) ? 1.0 : 0.0)
                                      : settings.get(e.key, e.read());
      if (stored >= e.lo && stored <= e.hi) {
        e.write(stored);
      }
    }
    take_changed();
  }
  // True when any value differs from what it was at the last call (or load).
  bool take_changed() {
    bool changed = false;
    for (Entry& e : entries_) {
      const double now = e.read();
      changed |= now != e.last;
      e.last = now;
    }
    return changed;
  }

 private:
  struct Entry {
    const char* key;
    std::function<double()> read;
    std::function<void(double)> write;
    double lo;
    double hi;
    bool is_bool;
    std::function<bool()> saved_while;
    double last = 0.0;
  };
  std::vector<Entry> entries_;
};

}  // namespace foldlab::gui
