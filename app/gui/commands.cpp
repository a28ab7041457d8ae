#include "app/gui/commands.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/common/presets_dir.hpp"
#include "app/gui/gui_app.hpp"
#include "app/gui/page_link.hpp"
#include "app/gui/panel_list.hpp"
#include "app/gui/picture.hpp"
#include "app/gui/surface.hpp"
#include "core/analysis/sweep.hpp"
#include "core/io/link.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
using app::check_outputs;
using app::guarded;
using app::InputError;
using app::kExitInternal;

namespace {

void parse_size(const std::string& text, GuiRunOptions& options) {
  const std::optional<FrameSize> size = parse_frame_size(text);
  if (!size) {
    throw InputError("--size " + detail::cut(text) + " must be " + frame_size_rule());
  }
  options.width = size->width;
  options.height = size->height;
}

struct GuiCommandOptions {
  GuiRunOptions run;
  std::string size = "1280x800";
  std::string print_path;
  std::string link;
  std::optional<std::string> preset_name;  // the page's ?preset=NAME, as the address gives it
  std::string link_argument;               // `foldlab gui LINK`: a clicked foldlab: link
};

// A link's name, preset and B: the preset is where the inputs the link leaves out come from,
// unless --preset names one; B starts from the same preset.
void apply_link_fabric_key(const LinkAssignment& piece, GuiCommandOptions& options) {
  GuiRunOptions& run = options.run;
  if (piece.key == kLinkNameKey) {
    run.link_name = piece.text;
  } else if (piece.key == kLinkPresetKey) {
    if (run.inputs.preset_path.empty() && !options.preset_name) {
      options.preset_name = piece.text;
    }
  } else if (piece.key == std::string(kLinkBPrefix) + std::string(kLinkNameKey)) {
    run.link_b_name = piece.text;
  } else {
    LinkAssignment b = piece;
    b.key.erase(0, kLinkBPrefix.size());
    run.link_b.push_back(b.set_text());
  }
}

// --link: the inputs go the way of --set (before it), the view keys the way of --view (before
// it), so that the options given beside a link override it.
void apply_link_option(GuiCommandOptions& options) {
  std::vector<std::string> pieces;
  std::vector<std::string> view_keys_seen;
  for (const LinkAssignment& piece : parse_fabric_link(options.link)) {
    pieces.push_back(piece.set_text());
    if (is_link_fabric_key(piece.key)) {
      apply_link_fabric_key(piece, options);
    } else if (!is_link_view_key(piece.key)) {
      options.run.inputs.link.push_back(piece.set_text());
    } else if (!options.run.inputs.forgiving_link ||
               std::find(view_keys_seen.begin(), view_keys_seen.end(), piece.key) ==
                   view_keys_seen.end()) {
      // A forgiving link keeps a view key's first value (its inputs say so in a notice).
      view_keys_seen.push_back(piece.key);
      options.run.link_view_settings.push_back(piece.set_text());
    }
  }
  // The view keys too: `#theme=dark&theme=light` is as unclear as two values of t. A forgiving
  // link (the page's) leaves the repeats out instead of refusing the page.
  const std::vector<std::string> repeated = repeated_keys(pieces, "--link");
  if (!repeated.empty() && !options.run.inputs.forgiving_link) {
    throw InputError(detail::join_lines(repeated));
  }
}

// --preset-name NAME: a shipped preset by its name alone, so that no address reaches a file
// outside the presets folder. An unknown name opens the default preset, saying so and naming
// the ones there are.
void apply_preset_name_option(GuiCommandOptions& options) {
  if (!options.preset_name) {
    return;
  }
  const std::string& wanted = *options.preset_name;
  std::vector<std::string> names;
  std::string default_path;
  for (const std::filesystem::path& file : app::preset_files(app::find_presets_dir())) {
    if (file.stem().string() == wanted) {
      options.run.inputs.preset_path = file.string();
      return;
    }
    names.push_back(file.stem().string());
    if (file.stem() == "default") {
      default_path = file.string();
    }
  }
  // Named as a preset asked for, so that a stored session does not take its place.
  options.run.inputs.preset_path = default_path;
  options.run.start_notices.push_back(
      "The address asks for the preset '" + detail::cut(wanted) +
      "', which is not one of the presets here, so the explorer opened with the default preset. "
      "The presets here: " +
      (names.empty() ? std::string("none") : detail::join(names, ", ")) + ".");
}

// --print FILE is --view print_file=FILE, first so that a later --view print=... still applies.
void apply_print_option(GuiCommandOptions& options) {
  if (!options.print_path.empty()) {
    options.run.view_settings.insert(options.run.view_settings.begin(),
                                     "print_file=" + options.print_path);
  }
}

// The cloth a run shows and how its 3D view looks: the inputs, --view and --print.
void add_scene_options(CLI::App& command, GuiCommandOptions& options) {
  app::add_input_options(command, options.run.inputs);
  command
      .add_option("--link", options.link,
                  "a fabric as the page's address carries it, '#t=0.25&E=165&w=150gsm&...' (a "
                  "full address, the fragment or its pieces): the inputs as --set takes them, "
                  "applied before --set, and the view keys present, theme and scale as --view")
      ->type_name("LINK");
  command
      .add_option(
          "--view", options.run.view_settings,
          "view setting KEY=VALUE: print=plain|checks|stripes|photo, print_file, "
          "print_mm, colour=#RRGGBB|none (the fabric's colour), colour_by=none|z|fold_sign, "
          "breeze=0|1, breeze_mm, time (s), "
          "z_exaggeration (1-20), wireframe, lod=0|1 (0: every grid vertex drawn), fold_lines, "
          "ground, fold_source=closed_form|field (whose folds the cloth is drawn with), grid "
          "(vertices per side, 8-512), "
          "full=1 (the 3D view fills the window) (3D view); fold_plot_true_scale=0|1 (the fold "
          "plot), fold_plot_presented_true_scale=0|1 (the fold plot presented; 0: it fills the "
          "window); sweep=table1|table2|fig4 (the paper's case in the Sweep tab); field=0|1 (the "
          "tension field's window), field_colour=state|tension, "
          "field_cut=shape|triangle|pennant|wedge, "
          "field_rays, field_cosines (the "
          "closed form's cosines over the field), field_cells (mesh cells across at rest, 8-80; "
          "half while a value is dragged); "
          "present=fold_plot|cloth|results|analysis|parameters|presets|field|none (that panel "
          "fills the window); theme=dark|light; scale (UI scale, percent); expert=0|1 (the expert "
          "settings); link_look=0|1 (Copy link sends the theme and text size); page_address "
          "(where the page is served: Copy link gives a web address); device_pixel_ratio (0-8, "
          "0: the screen's), pointer=screen|fine|coarse (with device_pixel_ratio, a phone's or "
          "a tablet's screen: --size 1170x2532 --view device_pixel_ratio=3 --view "
          "pointer=coarse is a 390x844 phone)")
      ->type_name("KEY=VALUE");
  command
      .add_option("--print", options.print_path,
                  "a swatch photo (PNG or JPEG) printed on the 3D view's cloth, tiled every "
                  "print_mm (--view print_mm=..., default 60)")
      ->type_name("FILE")
      ->check(app::non_empty_path());
}

void add_common_gui_options(CLI::App& command, GuiCommandOptions& options) {
  add_scene_options(command, options);
  command.add_option("--size", options.size, "window or picture size WxH (default 1280x800)");
  command.add_option("--tab", options.run.analysis_tab, "analysis tab shown at start")
      ->check(app::one_of("tab", {"equations", "method", "sweep", "map"}));
}

void add_play_option(CLI::App& command, GuiRunOptions& options) {
  command
      .add_option("--play", options.play_path,
                  "feed the steps of SCRIPT.json to the explorer as mouse, keys and text; exit "
                  "0 when every expect holds, 1 naming the step that failed, 2 for a malformed "
                  "script (see docs/cli.md)")
      ->type_name("SCRIPT.json")
      ->check(app::non_empty_path());
}

// A played script sets its own frames, input and screenshots.
void check_play_options(const GuiRunOptions& options) {
  if (!options.play_path.empty() &&
      (options.frames != 0 || !options.animate_key.empty() || !options.screenshot_path.empty())) {
    throw InputError(
        "--play takes its frames, input and screenshots from the script: "
        "drop --frames, --animate, --screenshot and --out");
  }
}

// The files a run reads besides its settings: the preset, the script and every swatch given as
// --print or --view print_file (a picture written over one would destroy it).
std::vector<app::NamedPath> run_inputs(const GuiCommandOptions& options) {
  std::vector<app::NamedPath> inputs = {
      app::preset_input("--preset", options.run.inputs.preset_path),
      {"--play", options.run.play_path},
      {"--print", options.print_path}};
  constexpr std::string_view kPrintFile = "print_file=";
  for (const std::string& setting : options.run.view_settings) {
    if (setting.starts_with(kPrintFile) && setting != "print_file=" + options.print_path) {
      inputs.push_back({"--view print_file", setting.substr(kPrintFile.size())});
    }
  }
  return inputs;
}

// --print and the checks every command that writes files makes: the options in the order given,
// no output over an input.
void prepare_run(GuiCommandOptions& options, const std::vector<app::NamedPath>& outputs) {
  apply_link_option(options);  // its preset= is a --preset-name
  apply_preset_name_option(options);
  apply_print_option(options);
  check_outputs(outputs, run_inputs(options));
  options.run.input_files = run_inputs(options);
}

}  // namespace

app::Command add_gui_command(CLI::App& app, GuiCaller caller) {
  auto options = std::make_shared<GuiCommandOptions>();
  CLI::App* command = app.add_subcommand("gui", "open the explorer window");
  add_common_gui_options(*command, *options);
  if (caller == GuiCaller::page) {
    options->run.inputs.forgiving_link = true;
    command
        ->add_option("--preset-name", options->preset_name,
                     "a shipped preset by its name (the page's ?preset=NAME); an unknown one "
                     "opens the default preset with a notice")
        ->type_name("NAME");
  }
  command
      ->add_option("--frames", options->run.frames,
                   "run this many frames, then exit (scripted runs take no mouse input)")
      ->transform(app::whole_number_in(1, 1000000));
  command
      ->add_option("--screenshot", options->run.screenshot_path,
                   "with --frames: write the last frame as PNG")
      ->check(app::non_empty_path());
  command->add_option("--animate", options->run.animate_key,
                      "move this input every frame as a dragged slider would, over the slider's "
                      "range: " +
                          detail::join_comma(sweepable_keys()));
  command->add_flag("--report", options->run.report,
                    "print frame times (mean, 95th percentile) and pipeline counters as JSON");
  command
      ->add_option("LINK", options->link_argument,
                   "a link to open, as --link takes it: a foldlab: link (which the desktop "
                   "entry passes when one is clicked) or a page's address")
      ->type_name("LINK");
  command->add_flag("--fresh", options->run.fresh,
                    "do not restore or save the last session and window layout");
  add_play_option(*command, options->run);
  return [options] {
    return guarded([&] {
      parse_size(options->size, options->run);
      check_play_options(options->run);
      if (!options->link_argument.empty()) {
        if (!options->link.empty()) {
          throw InputError("--link " + detail::cut(options->link) + " and the link " +
                           detail::cut(options->link_argument) + ": which one is meant?");
        }
        options->link = options->link_argument;
      }
      prepare_run(*options, {{"--screenshot", options->run.screenshot_path}});
      app::check_output_extension("--screenshot", options->run.screenshot_path, ".png", "PNG");
      if (!options->run.screenshot_path.empty() && options->run.frames == 0) {
        throw InputError("--screenshot needs --frames N");
      }
      return run_window(options->run);
    });
  };
}

app::Command add_render_command(CLI::App& app) {
  auto options = std::make_shared<GuiCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "render", "draw the full explorer window with no display (EGL surfaceless) into a PNG");
  add_common_gui_options(*command, *options);
  command->add_option("--out", options->run.screenshot_path, "PNG file to write")
      ->check(app::non_empty_path());
  command
      ->add_option("--frames", options->run.frames, "frames to run before the picture (default 3)")
      ->transform(app::whole_number_in(1, 100000));
  command->add_option("--animate", options->run.animate_key, "as for gui");
  command->add_flag("--report", options->run.report, "as for gui");
  add_play_option(*command, options->run);
  return [options] {
    return guarded([&] {
      parse_size(options->size, options->run);
      check_play_options(options->run);
      prepare_run(*options, {{"--out", options->run.screenshot_path}});
      if (options->run.screenshot_path.empty() && options->run.play_path.empty()) {
        throw InputError("render needs --out FILE.png (or --play SCRIPT.json)");
      }
      app::check_output_extension("--out", options->run.screenshot_path, ".png", "PNG");
      options->run.fresh = true;
      if (options->run.frames == 0 && options->run.play_path.empty()) {
        options->run.frames = 3;  // ImGui settles table and child sizes over the first frames
      }
      return run_headless(options->run);
    });
  };
}

namespace {

struct PictureOptions {
  GuiCommandOptions scene;
  std::string view;
  std::string size;
  std::string out;
  std::string background = "white";
  PictureSpec spec;
  // A sweep picture's axis, as `foldlab sweep` takes it; none: the Sweep tab's.
  std::string param;
  std::optional<std::string> from, to;
  std::optional<int> steps;
  bool log = false, linear = false;
  // B of a compare picture: a preset (default: A's) and its overrides.
  std::string b_preset;
  std::vector<std::string> b_sets;
  // A field picture's cut, as `foldlab field` takes it.
  app::FieldCutOptions field_cut;
};

// --param, --from, --to, --steps, --log and --linear: a sweep picture's axis, checked as `foldlab
// sweep` checks it; none without --param (the Sweep tab's own).
std::optional<SweepAxis> picture_sweep_axis(const PictureOptions& options, PictureView view) {
  const bool given = !options.param.empty() || options.from || options.to || options.steps ||
                     options.log || options.linear;
  if (!given) {
    return std::nullopt;
  }
  if (view != PictureView::sweep) {
    throw InputError(
        "--param, --from, --to, --steps, --log and --linear belong to a sweep picture");
  }
  if (options.param.empty() || !options.from || !options.to) {
    throw InputError("a sweep picture's axis needs --param, --from and --to together");
  }
  return app::read_sweep_axis(app::SweepAxisText{options.param, *options.from, *options.to,
                                                 options.steps.value_or(200), options.log,
                                                 options.linear});
}

// --b-preset and --b-set: B of a compare picture, its name marked "(edited)" when the
// overrides change it. A compare picture needs one of them.
std::optional<PinnedFabric> picture_b(const PictureOptions& options, PictureView view) {
  const bool given = !options.b_preset.empty() || !options.b_sets.empty();
  if (view != PictureView::compare) {
    if (given) {
      throw InputError("--b-preset and --b-set belong to a compare picture");
    }
    return std::nullopt;
  }
  if (!given) {
    throw InputError(
        "a compare picture needs B: --b-preset FILE, --b-set KEY=VALUE (B is A's preset with "
        "them), or both");
  }
  const app::InputOptions& a = options.scene.run.inputs;
  const std::string path = options.b_preset.empty() ? a.preset_path : options.b_preset;
  const app::InputOptions b{.preset_path = path,
                            .assignments = options.b_sets,
                            .method = a.method,
                            .law = a.law,
                            .set_option = "--b-set",
                            .whose = "B's "};
  const Preset origin = app::resolve_inputs(app::InputOptions{path, {}, a.method, a.law});
  Preset fabric = app::resolve_inputs(b);
  if (fabric.parameters != origin.parameters) {
    fabric.name += " (edited)";
  }
  return PinnedFabric{fabric, origin, path};
}

}  // namespace

app::Command add_picture_command(CLI::App& app) {
  auto options = std::make_shared<PictureOptions>();
  CLI::App* command = app.add_subcommand(
      "picture",
      "draw the 3D cloth, the fold plot, the sweep's plots, A and B side by side or the tension "
      "field, alone, with no interface, at any size, into a PNG (no display needed: EGL "
      "surfaceless)");
  command->add_option("VIEW", options->view, "what the picture shows: " + picture_view_names())
      ->required();
  add_scene_options(*command, options->scene);
  command
      ->add_option("--size", options->size,
                   "the picture's size WxH, " + frame_size_rule() + ", at most 8192x4096 pixels")
      ->required();
  command->add_option("--out", options->out, "PNG file to write")
      ->required()
      ->check(app::non_empty_path());
  command->add_option("--background", options->background,
                      std::string("white (default), transparent (alpha 0 around what is drawn) "
                                  "or dark"));
  command->add_flag("--caption", options->spec.caption,
                    "a strip at the bottom: the fabric, n, Q, z_max and the inputs (field: "
                    "also the cut, the weight, the thrust and the field's n, Q and z_max)");
  command->add_flag("--legend", options->spec.legend, "the fold plot's legend");
  command->add_option("--param", options->param,
                      "sweep: the input swept, " + detail::join_comma(sweepable_keys()) +
                          " (default: the Sweep tab's, h from 500 to 3000 mm)");
  command->add_option("--from", options->from,
                      "sweep: first value, in the input's unit or with a unit (as sweep)");
  command->add_option("--to", options->to, "sweep: last value");
  command->add_option("--steps", options->steps, "sweep: number of values (default 200)")
      ->transform(app::whole_number_in(2, 10000));
  command->add_flag(
      "--log", options->log,
      "sweep: logarithmic spacing (default for " + sweepable_keys_on_scale(true) + ")");
  command->add_flag("--linear", options->linear, "sweep: linear spacing");
  command
      ->add_option(
          "--b-preset", options->b_preset,
          "compare: B's preset; with --b-set alone, B is A's --preset with those overrides")
      ->type_name("FILE")
      ->check(app::non_empty_path());
  command->add_option("--b-set", options->b_sets, "compare: override one of B's inputs")
      ->type_name("KEY=VALUE");
  app::add_field_cut_options(*command, options->field_cut);
  return [options] {
    return guarded([&] {
      PictureSpec& spec = options->spec;
      const PictureOffer* view = picture_offer(std::string_view(options->view));
      if (view == nullptr) {
        throw InputError("VIEW '" + detail::cut(options->view) + "' must be one of " +
                         picture_view_names());
      }
      spec.view = view->view;
      const std::optional<PictureBackground> background =
          parse_picture_background(options->background);
      if (!background) {
        throw InputError("--background " + detail::cut(options->background) + " must be one of " +
                         kPictureBackgroundNames);
      }
      spec.background = *background;
      std::string problem;
      const std::optional<FrameSize> size = parse_picture_size(options->size, problem);
      if (!size) {
        throw InputError("--size " + problem);
      }
      spec.size = *size;
      std::error_code error;
      if (std::filesystem::is_directory(options->out, error)) {
        throw InputError("--out " + detail::cut(options->out) +
                         " is a folder; name the PNG file to write");
      }
      prepare_run(options->scene, {{"--out", options->out}});
      if (options->field_cut.given() && spec.view != PictureView::field) {
        throw InputError("--shape and --outline belong to a field picture");
      }
      check_outputs({{"--out", options->out}}, {app::preset_input("--b-preset", options->b_preset),
                                                {"--outline", options->field_cut.outline_path}});
      app::check_output_extension("--out", options->out, ".png", "PNG");
      PictureInputs inputs;
      inputs.sweep_axis = picture_sweep_axis(*options, spec.view);
      inputs.b = picture_b(*options, spec.view);
      inputs.field_cut = options->field_cut;
      return run_picture(options->scene.run, options->out, spec, inputs);
    });
  };
}

int run_default_window() {
  return guarded([] { return run_window(GuiRunOptions{}); });
}

}  // namespace foldlab::gui
