// A fabric as the fragment of a web address, "t=0.25&E=165&w=150gsm&h=1400&...", and back: the
// page's address carries the fabric it shows, the explorer's "Copy link" hands it on, and
// `foldlab gui --link` opens it. The keys and units are those of `--set`, and a link's values go
// the way of `--set` values (apply_assignments), so that a link says nothing `--set` cannot.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/parameters.hpp"
#include "core/model/settings.hpp"

namespace foldlab {

// Every input a preset stores (every row of the input table with a place in a preset; K, which
// follows from c and ν, is left out), in the table's order, as KEY=VALUE joined by '&' and
// percent-encoded. A number is written in the unit the explorer shows ("w=150gsm") as the shortest
// text that `--set` reads back as the very same double; when no text in that unit does, in the
// stored unit, where the shortest text always does. A choice is written by its name.
std::string fabric_link(const Parameters& p);

// The keys a link carries besides the inputs: the fabric's name, the shipped preset the inputs
// left out are read from, and the prefix of the inputs of the fabric pinned as B ("b.t=0.3").
inline constexpr std::string_view kLinkNameKey = "name";
inline constexpr std::string_view kLinkPresetKey = "preset";
inline constexpr std::string_view kLinkBPrefix = "b.";

// How fabric_link writes a fabric beyond the plain form above.
struct LinkWriting {
  // An input whose value (as written) equals this fabric's is left out: the preset the reader
  // starts from. None: every input is written.
  const Parameters* base = nullptr;
  // Inputs written with the digits the explorer's slider shows (a dragged value: its last digits
  // are where the mouse stopped, not what the user chose); the others exactly (typed or loaded).
  std::vector<std::string> shown_digits_keys{};
  // Put before every key: kLinkBPrefix for B.
  std::string_view key_prefix{};
};
std::string fabric_link(const Parameters& p, const LinkWriting& how);

// `stored` as the explorer's slider shows it (its shown unit's printf format), read back the way
// `--set` reads that text: what a dragged value is written and saved as. `stored` itself when the
// shown text does not read back (a value beyond the format's range).
double shown_digits_value(const InputSpec& spec, double stored);
// `p` with every input in `keys` at shown_digits_value.
Parameters with_shown_digits(const Parameters& p, const std::vector<std::string>& keys);

// One KEY=VALUE of a link, percent-decoded.
struct LinkAssignment {
  std::string key;
  std::string text;
  bool has_value = true;  // false: the piece had no '='

  // As `--set` takes it ("KEY=VALUE"; KEY alone when the piece had no '='), so that
  // apply_assignments names a problem in it as it names one typed after `--set`.
  std::string set_text() const;
};

// The pieces of a link, in order: the text after the first '#' (of a full address, "#..." or the
// fragment alone; an address with no '#' carries no inputs), split at '&' (an HTML-escaped
// "&amp;" read as the '&' it stands for), each at its first '=', then percent-decoded. Empty
// pieces are skipped and nothing else is checked: apply_assignments names an unknown key, a value
// that is no number and a refused one.
std::vector<LinkAssignment> parse_fabric_link(std::string_view link);

// Every byte but letters, digits and - . _ ~ as %XX (RFC 3986's unreserved characters stay), so
// that a value reads the same in any address and to URLSearchParams ('+' is %2B, never a space).
std::string percent_encode(std::string_view text);
// %XX as its byte; a '%' not followed by two hex digits, and everything else, as it is ('+' too).
std::string percent_decode(std::string_view text);

}  // namespace foldlab
