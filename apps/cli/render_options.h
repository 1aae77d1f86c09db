#pragma once
// `rayo render`'s options for a caller that names them instead of writing argv (the Python
// module, apps/python/rayo_module.cpp): the command line's own list, parser and bounds
// (apps/cli/cli.cpp, kRenderOptions, and the declared settings of apps/cli/setting_flags.h),
// grouped by what each option configures. Options arrive as argv words ({"--spp", "4",
// "--single-rays"}); a bad one is a UsageError naming the flag, as on the command line.
#include <optional>
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"
#include "core/image/image_output.h"

namespace rayo {

// What an option configures: how the scene is read (Load), the render (Render: resolution,
// threads, the declared settings, the methods), how the image is encoded (Output), or what only
// the command line does (Command: the output file, streaming, the journal, what is printed).
enum class OptionUse { Load, Render, Output, Command };

struct RenderOptionInfo {
    std::string flag;  // "--sphere-method"
    OptionUse use = OptionUse::Render;
    bool takes_value = true;  // false: a switch ("--single-rays")
    std::string help;         // as `rayo render --help` prints it
};

// Every option of `rayo render`, the declared settings of every integrator included.
std::vector<RenderOptionInfo> render_option_list();

// SCENE (the built-in scene without one) read with the Load options among `words`, and the
// --environment they name applied, as `rayo render` reads it. A word of another use is refused.
SceneDescription load_scene_with_options(const std::optional<std::string>& path,
                                         const std::vector<std::string>& words);

// Applies the Render options among `words` to `d` as `rayo render` does (width/height keep the
// aspect ratio alone, --integrator, every setting's bounds); returns --threads (0: all cores).
int apply_render_options(const std::vector<std::string>& words, SceneDescription& d);

// The Output options among `words` as the writers take them.
OutputOptions output_options_from(const std::vector<std::string>& words);

// One line per light of a scene, as `rayo info` prints them: "point position 0 4 0 color 1 1 1
// intensity 1".
std::string describe_light(const Light& light);

}  // namespace rayo
