#pragma once
// The command line's side of the declared settings (core/setting.h): the flags of the render
// settings (RenderSettings::fields) and of every registered integrator
// (shading/integrators/integrator.h) are found, parsed and checked by their declarations, the
// same ones the scene reader uses, and their --help lines are written from them.
#include <optional>
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"

namespace rayo {

// A declared setting's flag as given, in argv order.
struct SettingFlag {
    std::string flag;
    std::string text;  // its value; empty for a toggle
};

enum class FlagArity { None, Toggle, Value };
// Whether `flag` is a declared setting's (of the render or of any integrator), and whether it
// takes a value.
FlagArity setting_flag_arity(const std::string& flag);

// Checks the value of a declared setting's flag against its declaration (for every integrator
// that declares it): a UsageError "--spp: expected an integer in [1, 65536], got 'x'".
void check_setting_flag(const SettingFlag& flag);
// --integrator NAME: the integrator's defaults, or a UsageError naming the registered ones.
IntegratorSettings integrator_flag(const std::string& name);

// Applies --integrator (when given and not the scene's own) and then the flags, in order, to
// `settings` (the scene's): a flag of an integrator other than the render's is a UsageError
// naming both.
void apply_setting_flags(const std::optional<std::string>& integrator,
                         const std::vector<SettingFlag>& flags, RenderSettings& settings);

// The --help line(s) of the declared setting with this flag, its default in brackets (from the
// owner's default-constructed settings), wrapped at the help's columns.
std::string setting_help(const std::string& flag);
// The flags of the declared render settings (RenderSettings::fields), in declaration order.
std::vector<std::string> render_setting_flags();
// The flags of every registered integrator's declared settings, each once, in registration order.
std::vector<std::string> integrator_setting_flags();

// The help's layout: `flag_part` from column `indent`, `text` wrapped from column 27 to 96.
std::string help_lines(const std::string& flag_part, const std::string& text, size_t indent = 2);

// --integrator, then each registered integrator with its summary and its flags' lines.
std::string integrators_help();

// "whitted (max depth 5, min contribution 0.001, ...)": the integrator and its settings.
std::string integrator_summary(const IntegratorSettings& s);

// Each declared setting of the render and of its integrator as (label, value) ("max depth",
// "5"), the integrator's name first, for the resume fingerprint and the summary.
std::vector<std::pair<std::string, std::string>> describe_settings(const RenderSettings& s);

}  // namespace rayo
