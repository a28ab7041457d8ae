// What the commands' printers share: how a JSON document and a note on stderr are written, and
// the table cells that every Markdown table of the commands spells the same way.
#pragma once

#include <iostream>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/model/text_format.hpp"

namespace foldlab::cli {

// `document` indented by two and a line break: every --json output.
void write_json(const nlohmann::json& document, std::ostream& out);

// A command's result on standard output: with --json its object (the command's print_json, found
// beside its Result), else its text or table.
template <class Result>
void print_result(const Result& result, bool as_json,
                  void (*print_words)(const Result&, std::ostream&)) {
  if (as_json) {
    write_json(print_json(result), std::cout);
  } else {
    print_words(result, std::cout);
  }
}

// "foldlab: NOTE", one line each: what a command says on stderr beside its output. A note may
// quote a path or a name the user gave: each is spelt by detail::escaped_lines.
void write_notes(const std::vector<std::string>& notes, std::ostream& err);

// "–" for a value not given, else the value by a printf `format` ("%.2f").
template <class T>
std::string optional_cell(const std::optional<T>& value, const char* format) {
  return value ? detail::printf_string(format, static_cast<double>(*value)) : "–";
}

// "43.4 (-9.6%)": a model's value by `format`, and its relative error when there is one.
std::string value_with_error(double value, const std::optional<double>& error, const char* format);

// JSON null for a value not given.
template <class T>
nlohmann::json optional_json(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace foldlab::cli
