// The cut a tension field is solved on, as `foldlab field` and `foldlab picture field` take it
// from the command line: a designer's outline file, one of the field's named cuts, or the
// preset's own.
#pragma once

#include <optional>
#include <string>

#include "core/field/outline.hpp"
#include "core/io/preset.hpp"

namespace foldlab::app {

struct FieldCutOptions {
  std::string shape;         // one of field::outline_kind_names(); empty: the preset's
  std::string outline_path;  // a designer's cut (JSON); replaces the shape
  bool given() const { return !shape.empty() || !outline_path.empty(); }
};

// The cut `options` ask for, of the preset's inputs: the outline file when given, else the
// preset's own cut unless --shape asks for another, else the cut of --shape or of the preset's
// shape. `name` is set to what the cut is called in a report: the file as given, "the preset's
// own cut" or the cut's name. Throws InputError naming the option and what is wrong (a file that
// cannot be read, an outline that cannot be meshed, a shape that is none of the cuts).
field::Outline read_field_cut(const FieldCutOptions& options, const Preset& preset,
                              std::string& name);

// `parameters` with the cloth the closed form sees in a cut of one's own (a designer's, a
// preset's): its height midway between its two supports, their distance as cut and how far they
// moved in (field::closed_form_hanging, by the model's span rule), when it hangs from two supports
// on its top edge and the model takes those inputs; nullopt otherwise (the inputs stand).
std::optional<Parameters> closed_form_of_cut(const field::Outline& cut,
                                             const Parameters& parameters);

}  // namespace foldlab::app
