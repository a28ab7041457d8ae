#include "core/io/link.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

// (memcmp rather than std::bit_cast, which the browser build's libc++ lacks)
bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Whether `text` is read back as exactly `stored`, by the reader `--set` uses.
bool reads_back(const InputSpec& spec, const std::string& text, double stored) {
  Parameters p;
  return !assign_text(p, spec.key, text) && same_bits(*spec.value(p), stored);
}

std::string number_text(const InputSpec& spec, double stored) {
  const std::vector<InputUnit> units = input_units(spec);
  if (spec.shown_unit != 0 && spec.shown_unit < units.size() && std::isfinite(stored)) {
    const InputUnit& unit = units[spec.shown_unit];
    const std::string name(unit.plain.empty() ? unit.symbol : unit.plain);
    const double shown = stored / unit.per_unit;
    // The fewest significant digits first: 150 g/m² stays "150gsm" when 150 × 9.81e-9 is the
    // stored value, rather than the 17 digits of stored / 9.81e-9.
    constexpr int kMaxDigits = 17;
    for (int digits = 1; digits <= kMaxDigits; ++digits) {
      const std::optional<double> rounded =
          parse_number(detail::printf_string("%.*g", digits, shown));
      if (!rounded) {
        break;
      }
      const std::string text = detail::shortest_number(*rounded) + name;
      if (reads_back(spec, text, stored)) {
        return text;
      }
    }
  }
  return detail::shortest_number(stored);
}

}  // namespace

std::string fabric_link(const Parameters& p) {
  return fabric_link(p, LinkWriting{});
}

std::string fabric_link(const Parameters& p, const LinkWriting& how) {
  const Parameters written = with_shown_digits(p, how.shown_digits_keys);
  std::string out;
  for (const InputSpec& spec : input_table()) {
    if (spec.preset.empty()) {
      continue;  // derived (K): its inputs are written
    }
    const std::optional<double> value = spec.value(written);
    if (how.base != nullptr) {
      const std::optional<double> base_value = spec.value(*how.base);
      const bool same = value ? base_value && same_bits(*value, *base_value)
                              : spec.choice(written) == spec.choice(*how.base);
      if (same) {
        continue;
      }
    }
    const std::string text = value ? number_text(spec, *value) : std::string(spec.choice(written));
    out += (out.empty() ? "" : "&") +
           percent_encode(std::string(how.key_prefix) + std::string(spec.key)) + "=" +
           percent_encode(text);
  }
  return out;
}

double shown_digits_value(const InputSpec& spec, double stored) {
  if (!std::isfinite(stored) || spec.kind == InputKind::choice) {
    return stored;
  }
  const InputUnit unit = shown_unit(spec);
  const std::string text =
      detail::printf_string(std::string(unit.format).c_str(), stored / unit.per_unit) +
      (spec.shown_unit == 0 ? std::string()
                            : std::string(unit.plain.empty() ? unit.symbol : unit.plain));
  Parameters p;
  if (assign_text(p, spec.key, text)) {
    return stored;
  }
  const std::optional<double> read = spec.value(p);
  return read && std::isfinite(*read) ? *read : stored;
}

namespace {

// K is c/(1-ν²) at the ν in force and is stored as c: after a drag of K, c with the fewest
// significant digits that still shows the K the slider showed (not the 17 of K's value times
// 1-ν²).
void round_c_to_shown_K(const InputSpec& k_spec, const Parameters& p, Parameters& out) {
  const std::optional<double> k = k_spec.value(p);
  const std::optional<double> c = find_input("c")->value(p);
  if (!k || !c || !std::isfinite(*k) || !std::isfinite(*c)) {
    return;
  }
  const std::string shown_k = detail::printf_string(std::string(k_spec.format).c_str(), *k);
  constexpr int kMaxDigits = 17;
  for (int digits = 1; digits <= kMaxDigits; ++digits) {
    const std::optional<double> rounded = parse_number(detail::printf_string("%.*g", digits, *c));
    Parameters trial = out;
    if (!rounded || assign_number(trial, "c", *rounded)) {
      continue;
    }
    const std::optional<double> trial_k = k_spec.value(trial);
    if (trial_k && detail::printf_string(std::string(k_spec.format).c_str(), *trial_k) == shown_k) {
      out = trial;
      return;
    }
  }
}

}  // namespace

Parameters with_shown_digits(const Parameters& p, const std::vector<std::string>& keys) {
  Parameters out = p;
  for (const InputSpec& spec : input_table()) {
    if (std::find(keys.begin(), keys.end(), std::string(spec.key)) == keys.end()) {
      continue;
    }
    if (spec.kind == InputKind::stiffness_K) {
      round_c_to_shown_K(spec, p, out);
    } else if (spec.preset.empty()) {
      continue;  // derived: nothing of its own is stored
    } else if (const std::optional<double> value = spec.value(p)) {
      assign_number(out, spec.key, shown_digits_value(spec, *value));
    }
  }
  return out;
}

std::string LinkAssignment::set_text() const {
  return has_value ? key + "=" + text : key;
}

std::vector<LinkAssignment> parse_fabric_link(std::string_view link) {
  const std::size_t hash = link.find('#');
  if (hash != std::string_view::npos) {
    link.remove_prefix(hash + 1);
  } else if (link.find("://") != std::string_view::npos) {
    return {};  // an address with no fragment: the page's own inputs
  }
  std::vector<LinkAssignment> out;
  while (!link.empty()) {
    const std::size_t amp = link.find('&');
    std::string_view piece = link.substr(0, amp);
    link.remove_prefix(amp == std::string_view::npos ? link.size() : amp + 1);
    // A link pasted through e-mail or a chat that escapes HTML has "&amp;" between its pieces
    // (or "&amp;amp;", escaped twice): it means the '&' it was. No key begins with "amp;".
    while (piece.starts_with("amp;")) {
      piece.remove_prefix(4);
    }
    if (piece.empty()) {
      continue;
    }
    const std::size_t eq = piece.find('=');
    LinkAssignment a;
    a.key = percent_decode(piece.substr(0, eq));
    a.has_value = eq != std::string_view::npos;
    if (a.has_value) {
      a.text = percent_decode(piece.substr(eq + 1));
    }
    out.push_back(std::move(a));
  }
  return out;
}

std::string percent_encode(std::string_view text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : text) {
    const bool unreserved = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                            (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_' || c == '~';
    if (unreserved) {
      out += c;
    } else {
      const auto byte = static_cast<unsigned char>(c);
      out += {'%', kHex[byte >> 4], kHex[byte & 0xF]};
    }
  }
  return out;
}

std::string percent_decode(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int high = text[i] == '%' && i + 2 < text.size() ? detail::hex_digit(text[i + 1]) : -1;
    const int low = high >= 0 ? detail::hex_digit(text[i + 2]) : -1;
    if (low >= 0) {
      out += static_cast<char>(high * 16 + low);
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

}  // namespace foldlab
