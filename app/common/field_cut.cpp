#include "app/common/field_cut.hpp"

#include "app/common/inputs.hpp"
#include "core/io/io.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::app {
namespace {

// A designer's cut is a few hundred points at most; far above that is no outline.
constexpr std::uintmax_t kMaxOutlineFileBytes = 4u << 20;

}  // namespace

field::Outline read_field_cut(const FieldCutOptions& options, const Preset& preset,
                              std::string& name) {
  try {
    if (!options.outline_path.empty()) {
      name = detail::escaped(options.outline_path);
      return field::parse_outline_json(read_text_file(options.outline_path, kMaxOutlineFileBytes));
    }
    // A preset's own cut, checked when the preset was read, unless --shape asks for another.
    if (preset.outline && options.shape.empty()) {
      name = "the preset's own cut";
      return *preset.outline;
    }
    field::OutlineKind kind = field::outline_kind_of(preset.parameters.shape);
    if (!options.shape.empty() && !field::parse_outline_kind(options.shape, kind)) {
      throw InputError("--shape '" + options.shape +
                       "' is not one of: " + field::outline_kind_names());
    }
    name = std::string(field::to_string(kind));
    return field::make_outline(preset.parameters, kind);
  } catch (const field::OutlineError& e) {
    throw InputError((options.outline_path.empty()
                          ? ""
                          : "--outline " + detail::escaped(options.outline_path) + ": ") +
                     e.what());
  } catch (const ReadError& e) {
    throw InputError(std::string("--outline: ") + e.what());
  }
}

std::optional<Parameters> closed_form_of_cut(const field::Outline& cut,
                                             const Parameters& parameters) {
  const std::optional<Hanging> hanging =
      field::closed_form_hanging(cut, parameters.model.span_rule);
  if (!hanging) {
    return std::nullopt;
  }
  Parameters of_cut = parameters;
  of_cut.hanging = *hanging;
  if (!validate(of_cut).empty()) {
    return std::nullopt;
  }
  return of_cut;
}

}  // namespace foldlab::app
