#include "app/cli/compare.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace compare_command {
namespace {

using nlohmann::json;

// The presets named, else the presets folder's that can be read (those that cannot: in `notes`).
std::vector<std::string> preset_paths(const Options& options, std::vector<std::string>& notes) {
  if (!options.presets.empty()) {
    return options.presets;
  }
  const std::filesystem::path dir = find_presets_dir();
  if (dir.empty()) {
    throw InputError("no presets folder found: name presets with --preset");
  }
  const FolderPresets folder = readable_presets(dir);
  notes.insert(notes.end(), folder.skipped.begin(), folder.skipped.end());
  std::vector<std::string> paths;
  for (const auto& file : folder.files) {
    paths.push_back(file.string());
  }
  return paths;
}

std::string published_group(const std::string& preset_name) {
  return preset_name.substr(0, preset_name.find(','));
}

PublishedGroupAccuracy group_accuracy(const Result& result, const std::string& group) {
  PublishedGroupAccuracy accuracy;
  accuracy.group = group;
  std::array<std::vector<PublishedComparison>, kMethods.size()> in_group;
  for (std::size_t i = 0; i < result.names.size(); ++i) {
    if (published_group(result.names[i]) == group) {
      ++accuracy.rows;
      for (std::size_t m = 0; m < kMethods.size(); ++m) {
        in_group[m].push_back(result.rows[m][i]);
      }
    }
  }
  for (std::size_t m = 0; m < kMethods.size(); ++m) {
    accuracy.method[m] = summarize(in_group[m]);
  }
  return accuracy;
}

std::vector<PublishedGroupAccuracy> accuracy_by_group(const Result& result) {
  std::vector<std::string> groups;  // in the order the presets first name them
  for (const std::string& name : result.names) {
    const std::string group = published_group(name);
    if (std::find(groups.begin(), groups.end(), group) == groups.end()) {
      groups.push_back(group);
    }
  }
  std::vector<PublishedGroupAccuracy> out;
  for (const std::string& group : groups) {
    out.push_back(group_accuracy(result, group));
  }
  return out;
}

json solution_json(const Solution& s) {
  return {{"n", s.n}, {"n_capped", s.n_capped}, {"z_max_mm", s.z_max_mm}, {"Q", s.Q}};
}

json published_json(const PublishedResult& published) {
  return {{"n", optional_json(published.n)},
          {"z_max_mm", optional_json(published.z_max_mm)},
          {"Q", optional_json(published.Q)}};
}

json accuracy_json(const ComparisonSummary& s) {
  const auto error = [](int count, double median) { return count == 0 ? json() : json(median); };
  return {{"rows_with_n", s.rows_with_n},
          {"n_exact", s.n_exact},
          {"n_within_one", s.n_within_one},
          {"rows_with_z", s.rows_with_z},
          {"median_abs_z_error", error(s.rows_with_z, s.median_abs_z_error)},
          {"rows_with_Q", s.rows_with_Q},
          {"median_abs_Q_error", error(s.rows_with_Q, s.median_abs_Q_error)}};
}

void print_rows_table(const Result& result, std::ostream& out) {
  out << "| case | paper n | paper z_max (mm) | paper Q | paper method n | z_max (mm) | Q "
         "| exact method n | z_max (mm) | Q |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < result.names.size(); ++i) {
    const PublishedResult& pub = result.rows[0][i].published;
    out << "| " << detail::markdown_cell(result.names[i]) << " | " << optional_cell(pub.n, "%.0f")
        << " | " << optional_cell(pub.z_max_mm, "%g") << " | " << optional_cell(pub.Q, "%.2f");
    for (const std::vector<PublishedComparison>& method_rows : result.rows) {
      const PublishedComparison& c = method_rows[i];
      // "+" as in `sweep`: eq. 10 asked for more folds than the cap, which is shown.
      out << " | " << c.solution.n << (c.solution.n_capped ? "+ (capped)" : "") << " | "
          << value_with_error(c.solution.z_max_mm, c.z_error, "%.1f") << " | "
          << value_with_error(c.solution.Q, c.Q_error, "%.3f");
    }
    out << " |\n";
  }
}

// How close the model gets to each of the paper's tables: what the model is worth against the
// paper, not a tolerance that any test was fitted to.
void print_accuracy_table(const Result& result, std::ostream& out) {
  out << "\nPaper accuracy by table:\n\n"
         "| table | rows | paper method n exact | n within ±1 | median \\|z_max error\\| "
         "| exact method n exact | n within ±1 | median \\|z_max error\\| |\n"
         "|---|---|---|---|---|---|---|---|\n";
  for (const PublishedGroupAccuracy& group : result.accuracy_by_table) {
    out << "| " << detail::markdown_cell(group.group) << " | " << group.rows;
    for (const ComparisonSummary& s : group.method) {
      out << " | " << s.n_exact << "/" << s.rows_with_n << " | " << s.n_within_one << "/"
          << s.rows_with_n << " | "
          << (s.rows_with_z == 0 ? std::string("–")
                                 : detail::printf_string("%.1f %%", 100.0 * s.median_abs_z_error));
    }
    out << " |\n";
  }
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "compare", "both methods beside the published n, z_max and Q of presets that carry them");
  command->add_option("--preset", options.presets,
                      "preset files (default: every preset in the presets folder with published "
                      "results)");
  command->add_option("--set", options.assignments, "override an input of every preset, KEY=VALUE")
      ->type_name("KEY=VALUE");
  app::add_law_option(*command, options.law);
  command->add_flag("--json", options.json, "print JSON instead of a Markdown table");
}

Result run(const Options& options) {
  Result result;
  for (const std::string& path : preset_paths(options, result.notes)) {
    const Preset preset = app::resolve_named_inputs({path, options.assignments, "", options.law});
    const PublishedResult& pub = preset.published;
    if (!pub.n && !pub.z_max_mm && !pub.Q) {
      continue;
    }
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
      Parameters p = preset.parameters;
      p.model.method = kMethods[m];
      result.rows[m].push_back(compare_with_published(pub, p));
    }
    result.names.push_back(preset.name);
  }
  if (result.names.empty()) {
    throw InputError("none of the presets carries published results");
  }
  for (std::size_t m = 0; m < kMethods.size(); ++m) {
    result.totals[m] = summarize(result.rows[m]);
  }
  result.accuracy_by_table = accuracy_by_group(result);
  return result;
}

void print_markdown(const Result& result, std::ostream& out) {
  print_rows_table(result, out);
  out << "\n";
  for (std::size_t m = 0; m < kMethods.size(); ++m) {
    out << to_string(kMethods[m]) << " method: " << summary_text(result.totals[m]) << "\n";
  }
  print_accuracy_table(result, out);
}

json print_json(const Result& result) {
  json out = {{"rows", json::array()}, {"accuracy_by_table", json::array()}};
  for (std::size_t i = 0; i < result.names.size(); ++i) {
    json row = {{"name", result.names[i]}};
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
      row[std::string(to_string(kMethods[m]))] = solution_json(result.rows[m][i].solution);
    }
    row["published"] = published_json(result.rows[0][i].published);
    out["rows"].push_back(row);
  }
  for (const PublishedGroupAccuracy& group : result.accuracy_by_table) {
    out["accuracy_by_table"].push_back({{"table", group.group},
                                        {"rows", group.rows},
                                        {"paper", accuracy_json(group.method[0])},
                                        {"exact", accuracy_json(group.method[1])}});
  }
  return out;
}

int execute(const Options& options) {
  const Result result = run(options);
  write_notes(result.notes, std::cerr);
  print_result(result, options.json, &print_markdown);
  return kExitOk;
}

}  // namespace compare_command

Command add_compare_command(CLI::App& app) {
  return make_command(app, compare_command::declare, compare_command::execute);
}

}  // namespace foldlab::cli
