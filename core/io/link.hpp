// A fabric as the fragment of a web address, "t=0.25&E=165&w=150gsm&h=1400&...", and back: the
// page's address carries the fabric it shows, the explorer's "Copy link" hands it on, and
// `foldlab gui --link` opens it. The keys and units are those of `--set`, and a link's values go
// the way of `--set` values (apply_assignments), so that a link says nothing `--set` cannot.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/parameters.hpp"

namespace foldlab {

// Every input a preset stores (every row of the input table with a place in a preset; K, which
// follows from c and ν, is left out), in the table's order, as KEY=VALUE joined by '&' and
// percent-encoded. A number is written in the unit the explorer shows ("w=150gsm") as the shortest
// text that `--set` reads back as the very same double; when no text in that unit does, in the
// stored unit, where the shortest text always does. A choice is written by its name.
std::string fabric_link(const Parameters& p);

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
