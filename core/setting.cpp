#include "core/setting.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rayo {

std::string setting_flag(const SettingInfo& info) {
    if (info.flag) return info.flag;
    std::string flag = std::string("--") + info.name;
    for (char& c : flag) {
        if (c == '_') c = '-';
    }
    return flag;
}

SettingValue SettingValue::from_text(const std::string& text) {
    SettingValue v;
    v.text = text;
    v.shown = "'" + text + "'";
    const char* end = text.data() + text.size();
    long long integer = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), end, integer);
    if (!text.empty() && ec == std::errc() && ptr == end) {
        v.type = Type::Integer;
        v.integer = integer;
        v.number = static_cast<double>(integer);
        return v;
    }
    char* number_end = nullptr;
    const double number = std::strtod(text.c_str(), &number_end);
    if (!text.empty() && number_end == text.c_str() + text.size()) {
        v.type = Type::Number;
        v.number = number;
        return v;
    }
    v.type = Type::Text;
    return v;
}

std::optional<std::string> read_integer(const SettingValue& value, long long min, long long max,
                                        int& out) {
    if (value.type == SettingValue::Type::Integer && value.integer >= min && value.integer <= max) {
        out = static_cast<int>(value.integer);
        return std::nullopt;
    }
    return "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
           "], got " + value.shown;
}

std::optional<std::string> read_real(const SettingValue& value, double min, double max,
                                     float& out) {
    const bool numeric =
        value.type == SettingValue::Type::Integer || value.type == SettingValue::Type::Number;
    if (numeric && std::isfinite(value.number) && value.number >= min && value.number <= max &&
        std::isfinite(static_cast<float>(value.number))) {
        out = static_cast<float>(value.number);
        return std::nullopt;
    }
    std::ostringstream expected;
    // An upper bound that only keeps the value finite is not worth saying.
    if (max >= 1e29) {
        expected << "expected a number >= " << min << ", got " << value.shown;
    } else {
        expected << "expected a number in [" << min << ", " << max << "], got " << value.shown;
    }
    return expected.str();
}

std::optional<std::string> read_toggle(const SettingValue& value, bool& out) {
    if (value.type == SettingValue::Type::Boolean) {
        out = value.boolean;
        return std::nullopt;
    }
    return "expected true or false, got " + value.shown;
}

}  // namespace rayo
