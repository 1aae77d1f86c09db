#include "apps/cli/flag_table.h"

#include <algorithm>
#include <sstream>

namespace rayo {
namespace {

std::string number_text(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// "a", "b", "c" as core/setting.h's read_choice quotes them.
std::string quoted_list(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& w : words) text += (text.empty() ? "\"" : ", \"") + w + "\"";
    return text;
}

}  // namespace

std::string integer_range_text(long long min, long long max) {
    return std::to_string(min) + ".." + std::to_string(max);
}

std::string real_range_text(double min, double max) {
    // An upper bound that only keeps the value finite is not worth saying (read_real's rule).
    return max >= 1e29 ? "a number >= " + number_text(min)
                       : "a number in [" + number_text(min) + ", " + number_text(max) + "]";
}

FlagValue read_flag_value(const std::string& flag, const FlagRule& rule, const std::string& text) {
    FlagValue value{flag, text};
    std::optional<std::string> problem;
    const SettingValue given = SettingValue::from_text(text);
    switch (rule.kind) {
        case FlagRule::Kind::Integer:
            problem = read_integer(given, static_cast<long long>(rule.min),
                                   static_cast<long long>(rule.max), value.integer);
            break;
        case FlagRule::Kind::Real:
            problem = read_real(given, rule.min, rule.max, value.number);
            break;
        case FlagRule::Kind::Words: {
            const std::vector<std::string> words = rule.words();
            if (std::find(words.begin(), words.end(), text) == words.end()) {
                problem = "expected one of " + quoted_list(words) + ", got " + given.shown;
            }
            break;
        }
        case FlagRule::Kind::Switch:
        case FlagRule::Kind::Text:
        case FlagRule::Kind::Custom:
            break;
    }
    refuse_flag(value, problem);
    return value;
}

void refuse_flag(const FlagValue& value, const std::optional<std::string>& problem) {
    if (problem) throw UsageError(value.flag + ": " + *problem);
}

std::string rule_text(const FlagRule& rule, const char* value_name) {
    switch (rule.kind) {
        case FlagRule::Kind::Integer:
            return integer_range_text(static_cast<long long>(rule.min),
                                      static_cast<long long>(rule.max));
        case FlagRule::Kind::Real:
            return real_range_text(rule.min, rule.max);
        case FlagRule::Kind::Custom:
            return rule.expected();
        case FlagRule::Kind::Words:
            if (value_name) {  // a list too long for the metavar
                std::string text;
                for (const std::string& w : rule.words()) text += (text.empty() ? "" : ", ") + w;
                return "one of " + text;
            }
            break;
        case FlagRule::Kind::Switch:
        case FlagRule::Kind::Text:
            break;
    }
    return "";
}

std::string rule_metavar(const FlagRule& rule, const char* value_name) {
    if (value_name) return value_name;
    if (rule.kind != FlagRule::Kind::Words) return "";
    std::string text;
    for (const std::string& w : rule.words()) text += (text.empty() ? "" : "|") + w;
    return text;
}

}  // namespace rayo
