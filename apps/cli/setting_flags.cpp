#include "apps/cli/setting_flags.h"

#include <algorithm>
#include <sstream>

#include "apps/cli/flag_table.h"
#include "apps/cli/usage_error.h"

namespace rayo {
namespace {

// The arity of one flag among an owner's declared settings.
struct ArityFinder {
    const std::string& flag;
    FlagArity arity = FlagArity::None;
    void found(const SettingInfo& info, FlagArity a) {
        if (setting_flag(info) == flag) arity = a;
    }
    template <typename T, typename... Rest>
    void integer(const SettingInfo& info, T&, Rest...) {
        found(info, FlagArity::Value);
    }
    template <typename T, typename... Rest>
    void real(const SettingInfo& info, T&, Rest...) {
        found(info, FlagArity::Value);
    }
    void toggle(const SettingInfo& info, bool&) { found(info, FlagArity::Toggle); }
    template <typename E>
    void choice(const SettingInfo& info, E&, std::initializer_list<Choice<E>>) {
        found(info, FlagArity::Value);
    }
};

// Sets the member of the setting whose flag was given, checked by its declaration.
struct FlagApplier {
    const SettingFlag& given;
    bool applied = false;
    bool mine(const SettingInfo& info) { return setting_flag(info) == given.flag; }
    void check(const std::optional<std::string>& problem) {
        applied = true;
        if (problem) throw UsageError(given.flag + ": " + *problem);
    }
    void integer(const SettingInfo& info, int& member, long long min, long long max) {
        if (mine(info)) check(read_integer(SettingValue::from_text(given.text), min, max, member));
    }
    void real(const SettingInfo& info, float& member, double min, double max) {
        if (mine(info)) check(read_real(SettingValue::from_text(given.text), min, max, member));
    }
    void toggle(const SettingInfo& info, bool& member) {
        if (!mine(info)) return;
        member = true;
        applied = true;
    }
    template <typename E>
    void choice(const SettingInfo& info, E& member, std::initializer_list<Choice<E>> choices) {
        if (mine(info)) check(read_choice(SettingValue::from_text(given.text), choices, member));
    }
};

std::string number_text(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// One setting's help: flag and metavar, the text, its range and its default.
struct HelpEntry {
    std::string flag, metavar, text, range, default_value;
};

struct HelpCollector {
    std::vector<HelpEntry> entries;
    void integer(const SettingInfo& info, const int& member, long long min, long long max) {
        entries.push_back({setting_flag(info), "N", info.help, integer_range_text(min, max),
                           std::to_string(member)});
    }
    void real(const SettingInfo& info, const float& member, double min, double max) {
        // A default below the range is a setting that is off until given (time_limit).
        entries.push_back({setting_flag(info), "X", info.help, real_range_text(min, max),
                           member < min ? "off" : number_text(member)});
    }
    void toggle(const SettingInfo& info, const bool& member) {
        entries.push_back({setting_flag(info), "", info.help, "", member ? "on" : "off"});
    }
    template <typename E>
    void choice(const SettingInfo& info, const E& member,
                std::initializer_list<Choice<E>> choices) {
        std::string metavar;
        for (const Choice<E>& c : choices)
            metavar += (metavar.empty() ? "" : "|") + std::string(c.name);
        entries.push_back(
            {setting_flag(info), metavar, info.help, "", choice_name(choices, member)});
    }
};

std::string entry_help(const HelpEntry& e, const char* default_owner, size_t indent = 2) {
    std::string text = e.text;
    if (!e.range.empty()) text += ", " + e.range;
    text += " [" + std::string(default_owner) + "default " + e.default_value + "]";
    return help_lines(e.flag + (e.metavar.empty() ? "" : " " + e.metavar), text, indent);
}

template <typename Owner>
std::vector<HelpEntry> help_entries() {
    HelpCollector collector;
    Owner owner;
    owner.fields(collector);
    return collector.entries;
}

// Labels and values of an owner's settings ("max depth", "5").
struct Describer {
    std::vector<std::pair<std::string, std::string>>& out;
    static std::string label(const SettingInfo& info) {
        std::string text = info.name;
        for (char& c : text) {
            if (c == '_') c = ' ';
        }
        return text;
    }
    template <typename T, typename... Rest>
    void integer(const SettingInfo& info, const T& member, Rest...) {
        out.emplace_back(label(info), std::to_string(member));
    }
    template <typename T, typename... Rest>
    void real(const SettingInfo& info, const T& member, Rest...) {
        out.emplace_back(label(info), number_text(member));
    }
    void toggle(const SettingInfo& info, const bool& member) {
        out.emplace_back(label(info), member ? "on" : "off");
    }
    template <typename E>
    void choice(const SettingInfo& info, const E& member,
                std::initializer_list<Choice<E>> choices) {
        out.emplace_back(label(info), choice_name(choices, member));
    }
};

}  // namespace

// The help's layout: flags from column 2, their text from column 27, lines up to 100.
std::string help_lines(const std::string& flag_part, const std::string& text, size_t indent) {
    constexpr size_t kTextColumn = 27, kWidth = 96;
    std::string out = std::string(indent, ' ') + flag_part;
    std::string line;
    if (out.size() + 1 > kTextColumn) {
        out += "\n";
        line.assign(kTextColumn, ' ');
    } else {
        line = out + std::string(kTextColumn - out.size(), ' ');
        out.clear();
    }
    std::istringstream words(text);
    std::string word;
    bool first = true;
    while (words >> word) {
        if (!first && line.size() + 1 + word.size() > kWidth) {
            out += line + "\n";
            line.assign(kTextColumn, ' ');
            first = true;
        }
        line += (first ? "" : " ") + word;
        first = false;
    }
    return out + line + "\n";
}

std::vector<std::string> render_setting_flags() {
    std::vector<std::string> flags;
    for (const HelpEntry& e : help_entries<RenderSettings>()) flags.push_back(e.flag);
    return flags;
}

std::vector<std::string> integrator_setting_flags() {
    std::vector<std::string> flags;
    for_each_integrator([&](auto s) {
        for (const HelpEntry& e : help_entries<decltype(s)>()) {
            if (std::find(flags.begin(), flags.end(), e.flag) == flags.end()) {
                flags.push_back(e.flag);
            }
        }
    });
    return flags;
}

FlagArity setting_flag_arity(const std::string& flag) {
    ArityFinder finder{flag};
    RenderSettings().fields(finder);
    for_each_integrator([&](auto s) { s.fields(finder); });
    return finder.arity;
}

void check_setting_flag(const SettingFlag& flag) {
    FlagApplier applier{flag};
    RenderSettings render;
    render.fields(applier);
    if (applier.applied) {
        if (const std::optional<FieldProblem> problem = render.problem()) {
            throw UsageError(flag.flag + ": " + problem->message);
        }
    }
    // A flag several integrators declare (--max-depth) passes when one of them takes the value;
    // the render's own integrator checks it again against its bounds once the scene is known.
    std::optional<UsageError> refusal;
    bool accepted = false;
    for_each_integrator([&](auto s) {
        FlagApplier one{flag};
        try {
            s.fields(one);
            accepted = accepted || one.applied;
        } catch (const UsageError& e) {
            if (!refusal) refusal = e;
        }
    });
    if (!accepted && refusal) throw *refusal;
}

IntegratorSettings integrator_flag(const std::string& name) {
    const std::optional<IntegratorSettings> named = integrator_named(name);
    if (!named) {
        throw UsageError("--integrator: expected one of " + integrator_names() + ", got '" + name +
                         "'");
    }
    return *named;
}

void apply_setting_flags(const std::optional<std::string>& integrator,
                         const std::vector<SettingFlag>& flags, RenderSettings& settings) {
    if (integrator && *integrator != integrator_name(settings.integrator)) {
        settings.integrator = integrator_flag(*integrator);
    }
    for (const SettingFlag& flag : flags) {
        FlagApplier applier{flag};
        settings.fields(applier);
        if (applier.applied) {
            if (const std::optional<FieldProblem> problem = settings.problem()) {
                throw UsageError(flag.flag + ": " + problem->message);
            }
            continue;
        }
        std::visit([&](auto& s) { s.fields(applier); }, settings.integrator);
        if (applier.applied) continue;
        std::vector<std::string> owners;
        for_each_integrator([&](auto s) {
            ArityFinder finder{flag.flag};
            s.fields(finder);
            if (finder.arity != FlagArity::None) {
                owners.push_back(std::string("\"") + decltype(s)::kName + "\"");
            }
        });
        // "the "whitted" integrator", "the "whitted" and "path" integrators".
        std::string owner_text = owners.front();
        for (size_t i = 1; i < owners.size(); ++i) {
            owner_text += (i + 1 == owners.size() ? " and " : ", ") + owners[i];
        }
        owner_text += owners.size() > 1 ? " integrators" : " integrator";
        throw UsageError(flag.flag + ": a setting of the " + owner_text +
                         ", but this render's integrator is \"" +
                         integrator_name(settings.integrator) + "\" (--integrator chooses)");
    }
}

std::string setting_help(const std::string& flag) {
    for (const HelpEntry& e : help_entries<RenderSettings>()) {
        if (e.flag == flag) return entry_help(e, "scene's, ");
    }
    std::string text;
    for_each_integrator([&](auto s) {
        if (!text.empty()) return;
        for (const HelpEntry& e : help_entries<decltype(s)>()) {
            if (e.flag == flag) text = entry_help(e, "scene's, ");
        }
    });
    return text;
}

std::string integrators_help() {
    std::string out =
        "integrators (--integrator NAME, or in the scene \"render\": {\"integrator\":\n"
        "  {\"type\": NAME, ...}}; each one's flags below, docs/integrators.md):\n";
    for_each_integrator([&](auto s) {
        using S = decltype(s);
        out += help_lines(
            std::string(S::kName) +
                (std::is_same_v<S, std::variant_alternative_t<0, IntegratorSettings>> ? " (default)"
                                                                                      : ""),
            S::kSummary);
        for (const HelpEntry& e : help_entries<S>()) out += entry_help(e, "", 4);
    });
    return out;
}

std::string integrator_summary(const IntegratorSettings& s) {
    std::vector<std::pair<std::string, std::string>> entries;
    Describer describer{entries};
    IntegratorSettings copy = s;
    std::visit([&](auto& i) { i.fields(describer); }, copy);
    std::string text = integrator_name(s);
    for (size_t i = 0; i < entries.size(); ++i) {
        text += (i == 0 ? " (" : ", ") + entries[i].first + " " + entries[i].second;
    }
    return entries.empty() ? text : text + ")";
}

std::vector<std::pair<std::string, std::string>> describe_settings(const RenderSettings& s) {
    std::vector<std::pair<std::string, std::string>> out;
    out.emplace_back("integrator", integrator_name(s.integrator));
    Describer describer{out};
    RenderSettings copy = s;
    copy.fields(describer);
    std::visit([&](auto& i) { i.fields(describer); }, copy.integrator);
    return out;
}

}  // namespace rayo
