#pragma once
// A command's flags declared once (issue 26 item 5): each table entry holds a flag's spelling,
// the name of its value, its help and its rule (bounds or choices), and the command's --help
// lines, its parser and its error messages all follow from that entry. The checks are the
// declared settings' (core/setting.h), the ones the scene reader runs, so a flag whose rule is
// taken from a declaration (RuleFinder: --width from "camera": {"width"}) refuses what the
// scene file's field refuses, in the same words. `rayo render`'s declared settings (--spp,
// --max-depth, ...) are their owners' fields (apps/cli/setting_flags.h); this table holds the
// flags that are not settings of the render or of an integrator.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "apps/cli/setting_flags.h"
#include "apps/cli/usage_error.h"
#include "core/setting.h"

namespace rayo {

// What a flag's value must be: --help states it, the parser checks it before the entry's apply.
struct FlagRule {
    enum class Kind {
        Switch,   // no value
        Text,     // any text (a file, an OCIO name)
        Integer,  // an integer in [min, max]
        Real,     // a finite number in [min, max]
        Words,    // one of words()
        Custom    // a syntax of its own: the entry's apply checks it; expected() says it
    };
    Kind kind = Kind::Switch;
    double min = 0.0, max = 0.0;
    std::vector<std::string> (*words)() = nullptr;
    std::string (*expected)() = nullptr;
};

constexpr FlagRule switch_rule() {
    return {};
}
constexpr FlagRule text_rule() {
    return {FlagRule::Kind::Text};
}
constexpr FlagRule integer_rule(long long min, long long max) {
    return {FlagRule::Kind::Integer, static_cast<double>(min), static_cast<double>(max)};
}
constexpr FlagRule real_rule(double min, double max) {
    return {FlagRule::Kind::Real, min, max};
}
constexpr FlagRule words_rule(std::vector<std::string> (*words)()) {
    return {FlagRule::Kind::Words, 0.0, 0.0, words};
}
constexpr FlagRule custom_rule(std::string (*expected)()) {
    return {FlagRule::Kind::Custom, 0.0, 0.0, nullptr, expected};
}

// The names of a list of choices (core/setting.h), for words_rule: words_rule(choice_words<kX>).
template <const auto& kChoices>
std::vector<std::string> choice_words() {
    std::vector<std::string> words;
    for (const auto& c : kChoices) words.emplace_back(c.name);
    return words;
}

// The rule of the integer or real setting `name` among an owner's declared fields (unset if it
// has none): the flag of a scene-file field takes the field's bounds (--width:
// CameraDesc::resolution_fields).
struct RuleFinder {
    explicit RuleFinder(const char* setting) : name(setting) {}
    const char* name;
    std::optional<FlagRule> rule;
    template <typename T>
    void integer(const SettingInfo& info, T&, long long min, long long max) {
        if (std::string(info.name) == name) rule = integer_rule(min, max);
    }
    template <typename T>
    void real(const SettingInfo& info, T&, double min, double max) {
        if (std::string(info.name) == name) rule = real_rule(min, max);
    }
    // Toggles and choices have no bounds: an owner may declare them beside the numbers.
    void toggle(const SettingInfo&, bool&) {}
    template <typename E>
    void choice(const SettingInfo&, E&, std::initializer_list<Choice<E>>) {}
};

// A flag's value once its rule has passed it.
struct FlagValue {
    std::string flag;  // as given ("-o" or "--output")
    std::string text;  // empty for a switch
    int integer = 0;   // Integer
    float number = 0;  // Real
};

// Checks `text` against the rule: the value, or a UsageError "FLAG: expected an integer in
// [1, 4096], got 'x'" (core/setting.h's words).
FlagValue read_flag_value(const std::string& flag, const FlagRule& rule, const std::string& text);
// A Custom rule's check: `problem` (what was expected) as a UsageError naming the flag.
void refuse_flag(const FlagValue& value, const std::optional<std::string>& problem);

// The rule as --help states it: "1..4096", "a number in [0, 1e+06]", "a number >= 0", "one of
// a, b, c" (Words with a value name), a Custom rule's expected(); empty for the others.
std::string rule_text(const FlagRule& rule, const char* value_name);
// What follows the flag in --help: "a|b" for Words without a value name, else the value name.
std::string rule_metavar(const FlagRule& rule, const char* value_name);
// The bounds' wording, shared with the declared settings' lines (apps/cli/setting_flags.cpp).
std::string integer_range_text(long long min, long long max);
std::string real_range_text(double min, double max);

// One flag of a command's table. Entry types (CommandFlag, rayo render's RenderOption) have
// these members; the functions below read them.
template <typename Args>
struct CommandFlag {
    const char* flag;
    const char* alias;          // "-o", or null
    const char* value_name;     // "FILE"; null for a switch or for Words listed as "a|b"
    const char* help;           // null: shares the line of the entry before it
    const char* default_value;  // "[...]" after the rule in --help; null: none said
    FlagRule rule;
    void (*apply)(Args&, const FlagValue&);
};

// The --help text of an entry: its help, its rule, its default.
template <typename Entry>
std::string flag_help_text(const Entry& e) {
    std::string text = e.help ? e.help : "";
    const std::string rule = rule_text(e.rule, e.value_name);
    if (!rule.empty()) text += (text.empty() ? "" : ", ") + rule;
    if (e.default_value) text += std::string(" [") + e.default_value + "]";
    return text;
}

// "-o, --output FILE".
template <typename Entry>
std::string flag_spelling(const Entry& e) {
    std::string text = e.alias ? std::string(e.alias) + ", " : std::string();
    text += e.flag;
    const std::string metavar = rule_metavar(e.rule, e.value_name);
    return metavar.empty() ? text : text + " " + metavar;
}

// The --help lines of a table, in its order: an entry without help joins the line of the one
// before it ("--width W, --height H": joined entries share the first one's rule, said once);
// `other(entry)` writes an entry without
// apply (rayo render: a declared setting's place).
template <typename Entry, size_t N, typename Other>
std::string flags_help(const Entry (&table)[N], Other other) {
    std::string out;
    for (size_t i = 0; i < N; ++i) {
        if (!table[i].apply) {
            out += other(table[i]);
            continue;
        }
        auto joins = [&](size_t j) { return j < N && table[j].apply && !table[j].help; };
        const Entry& first = table[i];
        std::string spelling = flag_spelling(first);
        while (joins(i + 1)) spelling += ", " + flag_spelling(table[++i]);
        out += help_lines(spelling, flag_help_text(first));
    }
    return out;
}

// A table whose entries all have apply.
template <typename Entry, size_t N>
std::string flags_help(const Entry (&table)[N]) {
    return flags_help(table, [](const Entry&) { return std::string(); });
}

// The entry spelled `flag` (or its alias), or null.
template <typename Entry, size_t N>
const Entry* find_flag(const Entry (&table)[N], const std::string& flag) {
    for (const Entry& e : table) {
        if (e.apply && (flag == e.flag || (e.alias && flag == e.alias))) return &e;
    }
    return nullptr;
}

// Reads `args` from index `first` into `out` by the table; a word that is not a flag goes to
// `word(text)`; an unknown flag is "unknown option 'X' (see rayo COMMAND --help)".
template <typename Args, size_t N, typename Word>
void parse_flags(const CommandFlag<Args> (&table)[N], const std::vector<std::string>& args,
                 size_t first, const char* command, Args& out, Word word) {
    for (size_t i = first; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (const CommandFlag<Args>* e = find_flag(table, a)) {
            std::string text;
            if (e->rule.kind != FlagRule::Kind::Switch) {
                if (i + 1 >= args.size()) throw UsageError(a + ": missing value");
                text = args[++i];
            }
            e->apply(out, read_flag_value(a, e->rule, text));
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + a + "' (see rayo " + command + " --help)");
        } else {
            word(a);
        }
    }
}

}  // namespace rayo
