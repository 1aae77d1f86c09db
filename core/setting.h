#pragma once
// One declaration per setting: a setting's scene-file name, its command-line flag, its help and
// its bounds or choices are declared once, in its owner's `fields(f)` (render settings,
// integrators), beside the shapes' fields (core/shapes/shape_fields.h). The JSON reader, the
// command line and `rayo render --help` all read that declaration, so a flag and the field it
// mirrors parse the same values with the same bounds (docs/architecture.md, "Settings"). An
// owner's `fields(f)` calls, for each setting,
//   f.integer(info, member, min, max)    // int in [min, max]
//   f.real(info, member, min, max)       // finite float in [min, max]
//   f.choice(info, member, {{"name", value}, ...})
//   f.toggle(info, member)               // bool: JSON true/false; the flag alone sets true
// with the member's current value as the default.
#include <initializer_list>
#include <optional>
#include <string>

namespace rayo {

struct SettingInfo {
    const char* name;            // the scene-file key (snake_case)
    const char* help;            // what --help says, one sentence or two
    const char* flag = nullptr;  // the command-line flag; null: "--" + name, '_' as '-'
};

// "--max-depth" for "max_depth", or the info's own flag.
std::string setting_flag(const SettingInfo& info);

template <typename E>
struct Choice {
    const char* name;
    E value;
};

// A value as a scene file or a command line gives it, before the declaration checks it.
struct SettingValue {
    enum class Type { Integer, Number, Text, Boolean, Other };
    Type type = Type::Other;
    long long integer = 0;
    double number = 0.0;
    std::string text;
    bool boolean = false;
    std::string shown;  // the value as error messages quote it

    // A command-line argument: an integer, else a number (strtod, whole text), else text.
    static SettingValue from_text(const std::string& text);
};

// The declaration's checks, shared by every reader: the value, or what was expected
// ("expected an integer in [1, 65536], got 'x'") for the reader to report at its place.
std::optional<std::string> read_integer(const SettingValue& value, long long min, long long max,
                                        int& out);
std::optional<std::string> read_real(const SettingValue& value, double min, double max, float& out);
std::optional<std::string> read_toggle(const SettingValue& value, bool& out);

template <typename E>
std::optional<std::string> read_choice(const SettingValue& value,
                                       std::initializer_list<Choice<E>> choices, E& out) {
    if (value.type == SettingValue::Type::Text) {
        for (const Choice<E>& c : choices) {
            if (value.text == c.name) {
                out = c.value;
                return std::nullopt;
            }
        }
    }
    std::string names;
    for (const Choice<E>& c : choices)
        names += std::string(names.empty() ? "" : ", ") + "\"" + c.name + "\"";
    return "expected one of " + names + ", got " + value.shown;
}

// The name of `value` among `choices` (for summaries and --help defaults); "?" if none.
template <typename E>
const char* choice_name(std::initializer_list<Choice<E>> choices, E value) {
    for (const Choice<E>& c : choices) {
        if (c.value == value) return c.name;
    }
    return "?";
}

}  // namespace rayo
