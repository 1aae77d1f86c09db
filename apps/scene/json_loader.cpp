#include "apps/scene/json_loader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/scene/area_light_emitters.h"
#include "apps/scene/environment_image.h"
#include "apps/scene/height_image.h"
#include "apps/scene/input_file.h"
#include "apps/scene/mesh_loader.h"
#include "apps/scene/sphereflake.h"
#include "apps/scene/texture_image.h"
#include "core/error.h"
#include "core/path_util.h"
#include "core/scene_limits.h"
#include "core/shapes/mesh_form.h"
#include "core/shapes/polygon_triangulation.h"
#include "shading/texture.h"

namespace rayo {
namespace {

using Json = nlohmann::json;

constexpr int kFormatVersion = 1;

// Deepest nesting of arrays and objects a scene file may have (docs/limits.md): far above any
// real scene (the deepest rayo format path is about 6 levels), and far below what would exhaust
// the stack of anything that walks the tree recursively.
constexpr int kMaxJsonDepth = 256;

// Most samples per side of a height field sampled from a texture (each sample is one evaluation
// of the texture, a few microseconds: 4096² takes about a minute); larger fields come from images.
constexpr int kMaxTextureHeightSide = 4096;

// Most voxels a voxel grid may have (1 GiB of floats, 2^28: 645³ or 4096 × 4096 × 16), and
// the most per side (docs/voxels.md).
constexpr uint64_t kMaxVoxels = uint64_t(1) << 28;
constexpr int kMaxVoxelSide = 1 << 16;

// A --stats line for an `auto` the reader decided by the size of an object's mesh
// (SceneDescription::method_choices): "voxels /objects/3 (auto): mesh, 42216 triangles (<=
// 671088, ~4 MB)".
std::string auto_choice_line(const std::string& type, const std::string& pointer,
                             const std::string& chosen, size_t triangles, size_t limit,
                             size_t bytes_per_triangle) {
    return type + " " + (pointer.empty() ? "/" : pointer) + " (auto): " + chosen + ", " +
           std::to_string(triangles) + " triangles " + (triangles <= limit ? "(<= " : "(> ") +
           std::to_string(limit) + ", ~" + std::to_string((triangles * bytes_per_triangle) >> 20) +
           " MB as a mesh)";
}

// ---- JSON syntax errors -> "file:line:column" ---------------------------------------------

// nlohmann's DOM builder, remembering where parsing failed: its exceptions carry a byte offset
// (parse_error) or none at all (out_of_range 406, a number such as 1e999 that overflows).
class PositionRecordingSax : public nlohmann::detail::json_sax_dom_parser<Json> {
  public:
    explicit PositionRecordingSax(Json& root)
        : nlohmann::detail::json_sax_dom_parser<Json>(root, /*allow_exceptions=*/false) {}

    template <class Exception>
    bool parse_error(std::size_t position, const std::string& last_token, const Exception& error) {
        m_failed = true;
        // `position` counts the bytes read, the failing one included (1-based index of the
        // last byte read). For an overflowing number, point at its first digit instead. (With
        // comments enabled, the token of a syntax error also holds the whitespace before it,
        // so it cannot be used the same way.)
        m_position = position;
        if (error.id == 406 && position >= last_token.size()) {
            m_position = position - last_token.size() + 1;
        }
        m_message = error.what();
        m_overflow = error.id == 406;
        return false;
    }

    // Nesting depth is counted as the tree is built; parsing stops at the first array or object
    // beyond kMaxJsonDepth (its place is found afterwards: SAX events carry no position).
    bool start_object(std::size_t elements) {
        return enter() && nlohmann::detail::json_sax_dom_parser<Json>::start_object(elements);
    }
    bool end_object() {
        --m_depth;
        return nlohmann::detail::json_sax_dom_parser<Json>::end_object();
    }
    bool start_array(std::size_t elements) {
        return enter() && nlohmann::detail::json_sax_dom_parser<Json>::start_array(elements);
    }
    bool end_array() {
        --m_depth;
        return nlohmann::detail::json_sax_dom_parser<Json>::end_array();
    }
    bool too_deep() const { return m_too_deep; }

    bool failed() const { return m_failed; }
    std::size_t position() const { return m_position; }
    bool overflow() const { return m_overflow; }
    const std::string& message() const { return m_message; }

  private:
    bool enter() {
        if (++m_depth <= kMaxJsonDepth) return true;
        m_too_deep = m_failed = true;
        return false;
    }

    int m_depth = 0;
    bool m_too_deep = false;
    bool m_failed = false;
    bool m_overflow = false;
    std::size_t m_position = 0;
    std::string m_message;
};

// Drops nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: ".
std::string syntax_message(const std::string& what) {
    std::string message = what;
    const size_t bracket = message.find("] ");
    if (message.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos) {
        message = message.substr(bracket + 2);
    }
    const size_t column = message.find(", column ");
    if (message.rfind("parse error", 0) == 0 && column != std::string::npos) {
        const size_t colon = message.find(": ", column);
        if (colon != std::string::npos) message = message.substr(colon + 2);
    }
    return message;
}

// Byte offset of the first '[' or '{' nested deeper than `limit`, outside strings and comments
// (the parse stopped there, so the text before it is valid JSON up to that point).
size_t first_too_deep_bracket(const std::string& text, int limit) {
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*')) {
            const bool line_comment = text[i + 1] == '/';
            const size_t end = text.find(line_comment ? "\n" : "*/", i + 2);
            if (end == std::string::npos) break;
            i = line_comment ? end : end + 1;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return text.size();
}

Json parse_text(const std::string& text, const std::string& source_name) {
    Json root;
    PositionRecordingSax sax(root);
    const bool ok = Json::sax_parse(text, &sax, nlohmann::detail::input_format_t::json,
                                    /*strict=*/true, /*ignore_comments=*/true);
    if (ok && !sax.failed()) return root;
    // 1-based line and column of the byte at the recorded (1-based) position.
    const size_t offset = sax.too_deep()
                              ? first_too_deep_bracket(text, kMaxJsonDepth)
                              : std::min(sax.position() > 0 ? sax.position() - 1 : 0, text.size());
    size_t line = 1, line_start = 0;
    for (size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            line_start = i + 1;
        }
    }
    const size_t column = offset - line_start + 1;
    std::string message = sax.too_deep() ? "arrays and objects nested deeper than " +
                                               std::to_string(kMaxJsonDepth) + " levels"
                                         : syntax_message(sax.message());
    if (sax.overflow()) message += " (expected a finite number that fits a double)";
    throw InputError(source_name + ":" + std::to_string(line) + ":" + std::to_string(column),
                     "invalid JSON: " + message);
}

// ---- Values -------------------------------------------------------------------------------

std::string child(const std::string& pointer, const std::string& key) {
    std::string escaped;  // RFC 6901: '~' -> "~0", '/' -> "~1"
    for (char c : key) {
        if (c == '~') {
            escaped += "~0";
        } else if (c == '/') {
            escaped += "~1";
        } else {
            escaped += c;
        }
    }
    return pointer + "/" + escaped;
}

std::string child(const std::string& pointer, size_t index) {
    return pointer + "/" + std::to_string(index);
}

// A short rendering of a value for "got ..." in messages.
std::string describe(const Json& value) {
    // Containers are described, never dumped: dump() recurses through the whole value.
    if (value.is_object()) return "an object";
    if (value.is_array()) return "an array of " + std::to_string(value.size());
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    if (value.is_string()) return "the string " + text;
    return text;
}

// Whether T has a finish() to call once its fields are read (core/shapes/shape_fields.h).
template <typename T, typename = void>
struct has_finish : std::false_type {};
template <typename T>
struct has_finish<T, std::void_t<decltype(std::declval<T&>().finish())>> : std::true_type {};

// A JSON value as a declared setting reads it (core/setting.h).
SettingValue setting_value(const Json& value) {
    SettingValue v;
    v.shown = describe(value);
    if (value.is_number_integer()) {
        v.type = SettingValue::Type::Integer;
        // Unsigned values above the long long range saturate (and fail any declared bound).
        v.integer = value.is_number_unsigned() && value.get<unsigned long long>() >
                                                      static_cast<unsigned long long>(
                                                          std::numeric_limits<long long>::max())
                        ? std::numeric_limits<long long>::max()
                        : value.get<long long>();
        v.number = value.get<double>();
    } else if (value.is_number()) {
        v.type = SettingValue::Type::Number;
        v.number = value.get<double>();
    } else if (value.is_string()) {
        v.type = SettingValue::Type::Text;
        v.text = value.get<std::string>();
    } else if (value.is_boolean()) {
        v.type = SettingValue::Type::Boolean;
        v.boolean = value.get<bool>();
    }
    return v;
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
    return out;
}

// "a, b or c".
std::string join_or(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) {
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    }
    return out;
}

enum class Bound { Any, NonNegative, Positive };

class SceneParser {
  public:
    SceneParser(std::string source, std::string base_dir, FileAccess access)
        : m_source(std::move(source)),
          m_base_dir(std::move(base_dir)),
          m_access(std::move(access)) {}

    SceneDescription parse(const Json& root);

  private:
    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
        throw InputError(m_source + "#" + pointer, message);
    }

    void require_object(const Json& value, const std::string& pointer,
                        const std::string& what) const {
        if (!value.is_object()) fail(pointer, "expected " + what + ", got " + describe(value));
    }

    // Unknown keys are errors: they are almost always typos of a known one.
    void check_keys(const Json& object, const std::string& pointer,
                    std::initializer_list<const char*> allowed) const {
        check_keys(object, pointer, std::vector<std::string>(allowed.begin(), allowed.end()));
    }
    void check_keys(const Json& object, const std::string& pointer,
                    const std::vector<std::string>& allowed) const {
        for (const auto& item : object.items()) {
            bool known = false;
            for (const std::string& key : allowed) known |= item.key() == key;
            if (!known) {
                fail(child(pointer, item.key()),
                     "unknown key \"" + item.key() + "\" (expected one of: " + join(allowed) + ")");
            }
        }
    }

    const Json* find(const Json& object, const char* key) const {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    const Json& require(const Json& object, const std::string& pointer, const char* key,
                        const std::string& what) const {
        const Json* value = find(object, key);
        if (!value)
            fail(child(pointer, key),
                 "missing required field \"" + std::string(key) + "\" (expected " + what + ")");
        return *value;
    }

    // A number within the scene magnitude, in double (the quadric's coefficients keep it).
    double number(const Json& value, const std::string& pointer,
                  const char* expected = "a number") const {
        if (!value.is_number())
            fail(pointer, std::string("expected ") + expected + ", got " + describe(value));
        const double v = value.get<double>();
        if (!within_scene_magnitude(v)) {
            fail(pointer,
                 std::string("expected ") + kSceneMagnitudeRule + ", got " + describe(value));
        }
        return v;
    }

    float real(const Json& value, const std::string& pointer, Bound bound = Bound::Any) const {
        const char* expected = bound == Bound::Positive      ? "a number > 0"
                               : bound == Bound::NonNegative ? "a number >= 0"
                                                             : "a number";
        const double v = number(value, pointer, expected);
        if ((bound == Bound::Positive && !(v > 0.0)) ||
            (bound == Bound::NonNegative && !(v >= 0.0))) {
            fail(pointer, std::string("expected ") + expected + ", got " + describe(value));
        }
        // A positive number that rounds to float zero (1e-50) would still be zero.
        if (bound == Bound::Positive && !(static_cast<float>(v) > 0.0f)) {
            fail(pointer, std::string("expected ") + expected + " that fits a float, got " +
                              describe(value));
        }
        return static_cast<float>(v);
    }

    float real_or(const Json& object, const std::string& pointer, const char* key, float fallback,
                  Bound bound = Bound::Any) const {
        const Json* value = find(object, key);
        return value ? real(*value, child(pointer, key), bound) : fallback;
    }

    int integer(const Json& value, const std::string& pointer, long long min, long long max) const {
        const std::string expected =
            "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
        if (!value.is_number_integer())
            fail(pointer, "expected " + expected + ", got " + describe(value));
        // nlohmann stores non-negative integers as unsigned: compare without conversion.
        if (value.is_number_unsigned()) {
            const auto v = value.get<unsigned long long>();
            if (v > static_cast<unsigned long long>(max) ||
                (min > 0 && v < static_cast<unsigned long long>(min))) {
                fail(pointer, "expected " + expected + ", got " + describe(value));
            }
            return static_cast<int>(v);
        }
        const long long v = value.get<long long>();
        if (v < min || v > max) fail(pointer, "expected " + expected + ", got " + describe(value));
        return static_cast<int>(v);
    }

    Vec3 vec3(const Json& value, const std::string& pointer) const {
        if (!value.is_array() || value.size() != 3) {
            fail(pointer, "expected an array of 3 numbers, got " + describe(value));
        }
        return Vec3(real(value[0], child(pointer, size_t(0))),
                    real(value[1], child(pointer, size_t(1))),
                    real(value[2], child(pointer, size_t(2))));
    }

    // Colours: [r, g, b] or one number for grey, each >= 0 (values above 1 are allowed).
    Vec3 colour(const Json& value, const std::string& pointer) const {
        if (value.is_number()) return Vec3(real(value, pointer, Bound::NonNegative));
        if (!value.is_array() || value.size() != 3) {
            fail(pointer,
                 "expected a colour: [r, g, b] or a number (grey), got " + describe(value));
        }
        return Vec3(real(value[0], child(pointer, size_t(0)), Bound::NonNegative),
                    real(value[1], child(pointer, size_t(1)), Bound::NonNegative),
                    real(value[2], child(pointer, size_t(2)), Bound::NonNegative));
    }

    Vec3 colour_or(const Json& object, const std::string& pointer, const char* key,
                   const Vec3& fallback) const {
        const Json* value = find(object, key);
        return value ? colour(*value, child(pointer, key)) : fallback;
    }

    // The required "size" of a box-like object: [x, y, z], each > 0.
    Vec3 extent(const Json& object, const std::string& pointer) const {
        const std::string where = child(pointer, "size");
        const Json& size = require(object, pointer, "size", "[x, y, z], each > 0");
        if (!size.is_array() || size.size() != 3) {
            fail(where, "expected [x, y, z], each > 0, got " + describe(size));
        }
        return Vec3(real(size[0], child(where, size_t(0)), Bound::Positive),
                    real(size[1], child(where, size_t(1)), Bound::Positive),
                    real(size[2], child(where, size_t(2)), Bound::Positive));
    }

    Vec3 direction(const Json& value, const std::string& pointer) const {
        const Vec3 v = vec3(value, pointer);
        const float length = glm::length(v);
        if (!(length > 0.0f) || !std::isfinite(length)) {
            fail(pointer, "expected a non-zero direction vector, got " + describe(value));
        }
        return v / length;
    }

    std::string choice(const Json& value, const std::string& pointer,
                       const std::vector<std::string>& options) const {
        std::vector<std::string> names;
        for (const std::string& option : options) names.push_back("\"" + option + "\"");
        const std::string expected = "one of " + join(names);
        if (!value.is_string()) fail(pointer, "expected " + expected + ", got " + describe(value));
        const auto text = value.get<std::string>();
        for (const std::string& option : options) {
            if (text == option) return text;
        }
        fail(pointer, "expected " + expected + ", got " + describe(value));
    }

    // Reads a registered shape's fields (core/shapes/shape_fields.h) from a JSON object.
    struct FieldReader {
        const SceneParser& parser;
        const Json& object;
        const std::string& pointer;

        static const char* expected(FieldKind kind) {
            switch (kind) {
                case FieldKind::Point:
                    return "[x, y, z]";
                case FieldKind::Direction:
                    return "[x, y, z], non-zero";
                case FieldKind::Number:
                    return "a number";
                case FieldKind::Positive:
                    return "a number > 0";
                case FieldKind::NonNegative:
                    return "a number >= 0";
                case FieldKind::Integer:
                    return "an integer";
                case FieldKind::Flag:
                    return "true or false";
                case FieldKind::Numbers:
                    return "an array of numbers";
                case FieldKind::Box:
                    return "{\"min\": [x, y, z], \"max\": [x, y, z]}";
                case FieldKind::Records:
                    return "an array of objects";
                case FieldKind::Colour:
                    return "a colour: [r, g, b] or a number (grey)";
                case FieldKind::Attenuation:
                    return "an attenuation object";
            }
            return "a value";
        }
        void read(const Json& value, const std::string& where, Vec3& member, FieldKind kind) {
            member = kind == FieldKind::Direction ? parser.direction(value, where)
                     : kind == FieldKind::Colour  ? parser.colour(value, where)
                                                  : parser.vec3(value, where);
        }
        void read(const Json& value, const std::string& where, Attenuation& member, FieldKind) {
            member = parser.parse_attenuation(value, where);
        }
        void read(const Json& value, const std::string& where, float& member, FieldKind kind) {
            const Bound bound = kind == FieldKind::Positive      ? Bound::Positive
                                : kind == FieldKind::NonNegative ? Bound::NonNegative
                                                                 : Bound::Any;
            member = parser.real(value, where, bound);
        }
        void read(const Json& value, const std::string& where, int& member, FieldKind) {
            member = parser.integer(value, where, std::numeric_limits<int>::min(),
                                    std::numeric_limits<int>::max());
        }
        void read(const Json& value, const std::string& where, bool& member, FieldKind) {
            if (!value.is_boolean()) {
                parser.fail(where, "expected true or false, got " + describe(value));
            }
            member = value.get<bool>();
        }
        template <size_t N>
        void read(const Json& value, const std::string& where, std::array<double, N>& member,
                  FieldKind) {
            if (!value.is_array() || value.size() != N) {
                parser.fail(where, "expected an array of " + std::to_string(N) + " numbers, got " +
                                       describe(value));
            }
            for (size_t i = 0; i < N; ++i) member[i] = parser.number(value[i], child(where, i));
        }
        void read(const Json& value, const std::string& where, Bounds3& member, FieldKind kind) {
            parser.require_object(value, where, expected(kind));
            parser.check_keys(value, where, {"min", "max"});
            member.lower =
                parser.vec3(parser.require(value, where, "min", "[x, y, z]"), child(where, "min"));
            member.upper =
                parser.vec3(parser.require(value, where, "max", "[x, y, z]"), child(where, "max"));
        }
        // An array of records, each an object of T's own fields (blob elements).
        template <typename T>
        void read(const Json& value, const std::string& where, std::vector<T>& member,
                  FieldKind kind) {
            if (!value.is_array()) {
                parser.fail(where,
                            std::string("expected ") + expected(kind) + ", got " + describe(value));
            }
            member.clear();
            for (size_t i = 0; i < value.size(); ++i) {
                member.push_back(parser.read_record<T>(value[i], child(where, i), {}));
            }
        }
        template <typename T>
        void operator()(const char* name, T& member, FieldKind kind) {
            read(parser.require(object, pointer, name, expected(kind)), child(pointer, name),
                 member, kind);
        }
        // Declared settings (core/setting.h): checked by the declaration, as on the command line.
        const Json* setting(const SettingInfo& info) const {
            return parser.find(object, info.name);
        }
        void check(const SettingInfo& info, const std::optional<std::string>& problem) const {
            if (problem) parser.fail(child(pointer, info.name), *problem);
        }
        void integer(const SettingInfo& info, int& member, long long min, long long max) {
            if (const Json* v = setting(info))
                check(info, read_integer(setting_value(*v), min, max, member));
        }
        void real(const SettingInfo& info, float& member, double min, double max) {
            if (const Json* v = setting(info))
                check(info, read_real(setting_value(*v), min, max, member));
        }
        void toggle(const SettingInfo& info, bool& member) {
            if (const Json* v = setting(info)) check(info, read_toggle(setting_value(*v), member));
        }
        template <typename E>
        void choice(const SettingInfo& info, E& member, std::initializer_list<Choice<E>> choices) {
            if (const Json* v = setting(info))
                check(info, read_choice(setting_value(*v), choices, member));
        }
        template <typename T>
        void optional(const char* name, T& member, FieldKind kind) {
            if (const Json* value = parser.find(object, name)) {
                read(*value, child(pointer, name), member, kind);
            }
        }
    };
    // The scene-file names of a shape's fields.
    struct FieldNames {
        std::vector<std::string> names;
        template <typename T>
        void operator()(const char* name, T&, FieldKind) {
            names.push_back(name);
        }
        template <typename T>
        void optional(const char* name, T&, FieldKind) {
            names.push_back(name);
        }
        template <typename T, typename... Rest>
        void integer(const SettingInfo& info, T&, Rest...) {
            names.push_back(info.name);
        }
        template <typename T, typename... Rest>
        void real(const SettingInfo& info, T&, Rest...) {
            names.push_back(info.name);
        }
        template <typename T>
        void toggle(const SettingInfo& info, T&) {
            names.push_back(info.name);
        }
        template <typename E>
        void choice(const SettingInfo& info, E&, std::initializer_list<Choice<E>>) {
            names.push_back(info.name);
        }
    };

    // An object read by T's fields() and checked by its problem(); `extra_keys` are the other
    // keys it may have.
    template <typename T>
    T read_record(const Json& value, const std::string& pointer,
                  const std::vector<std::string>& extra_keys) const {
        require_object(value, pointer, "an object");
        static const std::vector<std::string> field_keys = [] {
            FieldNames names;
            T().fields(names);
            return names.names;
        }();
        std::vector<std::string> keys = extra_keys;
        keys.insert(keys.end(), field_keys.begin(), field_keys.end());
        check_keys(value, pointer, keys);
        T record;
        FieldReader reader{*this, value, pointer};
        record.fields(reader);
        if constexpr (has_finish<T>::value) record.finish();
        if (const std::optional<FieldProblem> problem = record.problem()) {
            // The field may be a path into a nested object ("bounds/max").
            std::string where = pointer;
            size_t from = 0;
            for (size_t slash; (slash = problem->field.find('/', from)) != std::string::npos;
                 from = slash + 1) {
                where = child(where, problem->field.substr(from, slash - from));
            }
            fail(child(where, problem->field.substr(from)), problem->message);
        }
        return record;
    }

    // A shape; `object` for the scene's and groups' objects, which may name a "method" (CSG
    // children may not).
    template <typename S>
    void parse_shape(const Json& value, const std::string& pointer, std::vector<S>& out,
                     bool object = false) const {
        S shape = read_record<S>(value, pointer,
                                 object ? std::vector<std::string>{"type", "material", "method"}
                                        : std::vector<std::string>{"type", "material"});
        shape.material = material_of(value, pointer);
        out.push_back(std::move(shape));
    }
    // The "method" of the object just read into `shapes` (core/shape_method.h).
    template <typename S>
    void read_shape_method(const Json& value, const std::string& pointer,
                           const std::vector<S>& shapes, bool in_group,
                           SceneDescription& out) const {
        const Json* v = find(value, "method");
        if (!v) return;
        const std::string where = child(pointer, "method");
        // The names --shape-method reads, by the same check.
        ShapeMethod method = ShapeMethod::Analytic;
        if (const std::optional<std::string> problem =
                read_choice(setting_value(*v), kShapeMethodChoices, method)) {
            fail(where, *problem);
        }
        if constexpr (std::is_same_v<S, Sphere>) {
            fail(where,
                 "a sphere's method is the render's: \"render\": {\"sphere_method\": ...} "
                 "or --sphere-method (docs/sphere-methods.md)");
        }
        if (!has_mesh_form(shapes.back())) {
            fail(where, std::string("a ") + S::kName +
                            " has no mesh form (no pieces): it is traced analytically only");
        }
        if (in_group) {
            fail(where,
                 "objects in groups are traced analytically: their size in pixels "
                 "depends on every instance (give \"method\" to top-level objects)");
        }
        out.shape_methods.push_back(
            {Shapes::index_of<S>(), static_cast<uint32_t>(shapes.size() - 1), method});
    }

    // A CSG object (core/shapes/csg.h): its tree, read into one Csg.
    void parse_shape(const Json& value, const std::string& pointer, std::vector<Csg>& out,
                     bool /*object*/ = false) const {
        Csg csg;
        parse_csg_operation(value, pointer, 1, csg);
        csg.material = material_of(value, pointer);
        out.push_back(std::move(csg));
    }
    // An operation at nesting `depth` (1 for the object itself); returns its node.
    int parse_csg_operation(const Json& value, const std::string& pointer, int depth,
                            Csg& csg) const {
        if (depth > kMaxCsgDepth) {
            fail(pointer, "expected CSG nested at most " + std::to_string(kMaxCsgDepth) +
                              " deep (core/shapes/csg.h)");
        }
        check_keys(value, pointer,
                   depth == 1 ? std::vector<std::string>{"type", "op", "children", "material"}
                              : std::vector<std::string>{"type", "op", "children"});
        const std::string op =
            choice(require(value, pointer, "op", "\"union\", \"intersection\" or \"difference\""),
                   child(pointer, "op"), {"union", "intersection", "difference"});
        const std::string where = child(pointer, "children");
        const Json& children = require(value, pointer, "children", "an array of 2 closed shapes");
        if (!children.is_array() || children.size() != 2) {
            fail(where, "expected an array of 2 closed shapes, got " + describe(children));
        }
        const int left = parse_csg_child(children[0], child(where, size_t(0)), depth, csg);
        const int right = parse_csg_child(children[1], child(where, size_t(1)), depth, csg);
        return csg.add_operation(op == "union"          ? CsgOp::Union
                                 : op == "intersection" ? CsgOp::Intersection
                                                        : CsgOp::Difference,
                                 left, right);
    }
    int parse_csg_child(const Json& value, const std::string& pointer, int depth, Csg& csg) const {
        // Any closed primitive shape (core/shapes/primitives.h) or another CSG.
        static const std::vector<std::string> types = [] {
            std::vector<std::string> names = ShapeSet<PrimitiveShapes>::names();
            names.push_back(Csg::kName);
            return names;
        }();
        static const std::string expected_type = [] {
            std::vector<std::string> quoted;
            for (const std::string& t : types) quoted.push_back("\"" + t + "\"");
            return join_or(quoted);
        }();
        require_object(value, pointer, "a closed shape");
        if (find(value, "material")) {
            fail(child(pointer, "material"),
                 "a CSG child takes the material of its CSG object: give \"material\" there");
        }
        const std::string type =
            choice(require(value, pointer, "type", expected_type), child(pointer, "type"), types);
        if (type == Csg::kName) return parse_csg_operation(value, pointer, depth + 1, csg);
        int node = -1;
        ShapeSet<PrimitiveShapes> one;
        one.for_each([&](auto& shapes) {
            if (type != ShapeOf<decltype(shapes)>::kName) return;
            parse_shape(value, pointer, shapes);
            if (!is_closed(shapes.back())) {
                fail(pointer,
                     "expected a closed shape (a solid) as a CSG child, got an open " + type);
            }
            node = csg.add_leaf(shapes.back());
        });
        if (csg.leaf_budget() > kMaxCsgCrossings) {
            fail(pointer, "expected a CSG whose children cross a line at most " +
                              std::to_string(kMaxCsgCrossings) +
                              " times in all (core/shapes/csg.h); this child makes it " +
                              std::to_string(csg.leaf_budget()));
        }
        return node;
    }

    void parse_camera(const Json& value, const std::string& pointer, CameraDesc& camera) const;
    void parse_render(const Json& value, const std::string& pointer, RenderSettings& s) const;
    IntegratorSettings parse_integrator(const Json& value, const std::string& pointer) const;
    void parse_materials(const Json& value, const std::string& pointer, ShadingScene& shading);
    void parse_textures(const Json& value, const std::string& pointer, ShadingScene& shading);
    Texture parse_texture(const Json& value, const std::string& pointer,
                          const std::string& name) const;
    ColorRamp parse_ramp(const Json& value, const std::string& pointer) const;
    void parse_fbm(const Json& value, const std::string& pointer, FbmParams& fbm) const;
    Vec3 colour_or_texture(const Json& object, const std::string& pointer, const char* key,
                           const Vec3& fallback, int32_t& texture) const;
    Material parse_material(const Json& value, const std::string& pointer,
                            const std::string& name) const;
    // An image texture {"image": file, "factor", "wrap", "colorspace", "scale", "offset"}
    // (docs/textures.md, "Image textures") when object[key] is an object; its factor in `factor`.
    bool image_map(const Json& object, const std::string& pointer, const char* key, ImageMap& map,
                   Vec3& factor) const;
    Light parse_light(const Json& value, const std::string& pointer) const;
    // A light read by its declaration (shading/light.h): its form first when it has one (an
    // area light's "shape"), which decides the fields it declares and so the keys it allows.
    template <typename L>
    L read_light(const Json& value, const std::string& pointer) const;
    // Reads a light's form(): each choice required, since it decides which fields follow.
    struct FormReader {
        const SceneParser& parser;
        const Json& object;
        const std::string& pointer;
        template <typename E>
        void choice(const SettingInfo& info, E& member, std::initializer_list<Choice<E>> choices) {
            std::string names;
            for (const Choice<E>& c : choices)
                names += std::string(names.empty() ? "" : ", ") + "\"" + c.name + "\"";
            const Json& v = parser.require(object, pointer, info.name, "one of " + names);
            if (const std::optional<std::string> problem =
                    read_choice(setting_value(v), choices, member)) {
                parser.fail(child(pointer, info.name), *problem);
            }
        }
    };
    // The environment light, at "/environment" or as a light of type "environment"
    // (`extra_keys`: {"type"}): its fields() and its "image".
    EnvironmentLight parse_environment(const Json& value, const std::string& pointer,
                                       const std::vector<std::string>& extra_keys) const;
    Fog parse_fog(const Json& value, const std::string& pointer) const;
    void parse_radiosity(const Json& value, const std::string& pointer, RadiositySettings& r) const;
    Attenuation parse_attenuation(const Json& value, const std::string& pointer) const;
    // Where objects go: the scene itself, or a group (core/instance.h), whose objects may not be
    // instances (kMaxInstanceLevels).
    struct ObjectSink {
        Shapes& shapes;
        std::vector<TriangleMesh>& meshes;
        TriangleMesh& polygons;  // every "triangle" and "polygon" object, one Embree geometry
        bool in_group;
    };
    void parse_object(const Json& value, const std::string& pointer, SceneDescription& out,
                      const ObjectSink& sink);
    void parse_mesh(const Json& value, const std::string& pointer, SceneDescription& out,
                    std::vector<TriangleMesh>& meshes);
    void parse_groups(const Json& value, const std::string& pointer, SceneDescription& out);
    Instance parse_instance(const Json& value, const std::string& pointer) const;
    // `matrix` allows an explicit affine matrix besides scale/rotate/translate (instances).
    glm::dmat4 parse_transform(const Json& value, const std::string& pointer,
                               bool matrix = false) const;
    void parse_heightfield(const Json& value, const std::string& pointer,
                           SceneDescription& out) const;
    void parse_voxels(const Json& value, const std::string& pointer, SceneDescription& out) const;
    VoxelTransfer parse_transfer(const Json& value, const std::string& pointer) const;
    uint32_t material_of(const Json& object, const std::string& pointer) const;

    std::string m_source;
    std::string m_base_dir;
    FileAccess m_access;
    std::map<std::string, uint32_t> m_material_ids;
    std::map<std::string, int32_t> m_texture_ids;  // name -> index in ShadingScene::textures
    mutable TextureImageCache m_images;            // image textures read so far, by path
    std::map<std::string, uint32_t> m_group_ids;   // name -> index in Scene::groups
};

SceneDescription SceneParser::parse(const Json& root) {
    require_object(root, "", "a JSON object at the top level");
    // The version comes first: a future version may add keys this reader does not know.
    const Json& version = require(root, "", "rayo", "the format version 1");
    if (!version.is_number_integer() || version.get<long long>() != kFormatVersion) {
        fail("/rayo", "unsupported format version: expected 1, got " + describe(version));
    }
    check_keys(root, "",
               {"rayo", "camera", "render", "background", "ambient_light", "fog", "textures",
                "materials", "lights", "environment", "groups", "objects", "radiosity"});

    SceneDescription out;
    out.source = m_source;
    CameraDesc& camera = out.scene.camera;
    camera = CameraDesc{};
    camera.width = 640;
    camera.height = 480;
    if (const Json* value = find(root, "camera")) {
        parse_camera(*value, "/camera", camera);
    }
    if (camera.projection == Projection::Perspective && !camera.hfov_degrees &&
        !camera.vfov_degrees) {
        camera.vfov_degrees = 45.0f;  // seed 002
    }
    Camera::create(camera, m_source + "#/camera");  // eye = look_at, up ∥ view, pixel limits

    if (const Json* value = find(root, "render")) parse_render(*value, "/render", out.settings);
    out.shading.background = colour_or(root, "", "background", Vec3(0.0f));
    out.shading.ambient_light = colour_or(root, "", "ambient_light", Vec3(1.0f));
    if (const Json* value = find(root, "fog")) out.shading.fog = parse_fog(*value, "/fog");
    if (const Json* value = find(root, "radiosity")) {
        parse_radiosity(*value, "/radiosity", out.settings.radiosity);
    }

    // Textures first: materials refer to them by name.
    if (const Json* value = find(root, "textures")) {
        parse_textures(*value, "/textures", out.shading);
    }
    parse_materials(find(root, "materials") ? *find(root, "materials") : Json::object(),
                    "/materials", out.shading);

    if (const Json* lights = find(root, "lights")) {
        if (!lights->is_array())
            fail("/lights", "expected an array of lights, got " + describe(*lights));
        for (size_t i = 0; i < lights->size(); ++i) {
            out.shading.lights.push_back(parse_light((*lights)[i], child("/lights", i)));
        }
    }
    const size_t listed_lights = out.shading.lights.size();
    if (const Json* value = find(root, "environment")) {
        out.shading.lights.push_back(parse_environment(*value, "/environment", {}));
    }
    for (size_t i = 0; i < out.shading.lights.size(); ++i) {
        if (!std::holds_alternative<EnvironmentLight>(out.shading.lights[i])) continue;
        if (out.shading.environment >= 0) {
            fail(i < listed_lights ? child("/lights", i) : "/environment",
                 "a second environment light: a scene has at most one");
        }
        out.shading.environment = static_cast<int32_t>(i);
    }

    // Groups before objects: instances name them.
    if (const Json* groups = find(root, "groups")) parse_groups(*groups, "/groups", out);
    TriangleMesh polygons;
    polygons.name = "polygons";
    if (const Json* objects = find(root, "objects")) {
        if (!objects->is_array())
            fail("/objects", "expected an array of objects, got " + describe(*objects));
        const ObjectSink sink{out.scene.shapes, out.scene.meshes, polygons, false};
        for (size_t i = 0; i < objects->size(); ++i) {
            parse_object((*objects)[i], child("/objects", i), out, sink);
        }
    }
    if (!polygons.triangles.empty()) out.scene.meshes.push_back(std::move(polygons));
    // After every object: the emitters' materials follow the file's and the meshes' materials.
    add_area_light_emitters(out);
    return out;
}

void SceneParser::parse_camera(const Json& value, const std::string& pointer,
                               CameraDesc& camera) const {
    require_object(value, pointer, "a camera object");
    check_keys(value, pointer,
               {"eye", "look_at", "up", "distance", "hfov", "vfov", "width", "height", "projection",
                "fov", "lens_radius", "focus_distance"});
    if (const Json* v = find(value, "projection")) {
        camera.projection = *parse_projection(
            choice(*v, child(pointer, "projection"), {"perspective", "fisheye", "spherical"}));
    }
    const std::string projection = projection_name(camera.projection);
    // What the projection's angle is, for messages about the fields of another projection.
    const std::string its_angle =
        "the " + projection + " projection " +
        (camera.projection == Projection::Perspective ? "takes hfov or vfov"
         : camera.projection == Projection::Fisheye   ? "takes its angle from fov"
                                                      : "always covers 360 x 180 degrees");
    if (const Json* v = find(value, "eye")) camera.eye = vec3(*v, child(pointer, "eye"));
    if (const Json* v = find(value, "look_at")) {
        camera.look_at = vec3(*v, child(pointer, "look_at"));
    }
    if (const Json* v = find(value, "up")) camera.up = direction(*v, child(pointer, "up"));
    camera.distance = real_or(value, pointer, "distance", camera.distance, Bound::Positive);
    for (const char* key : {"hfov", "vfov"}) {
        const Json* v = find(value, key);
        if (!v) continue;
        if (camera.projection != Projection::Perspective) {
            fail(child(pointer, key),
                 "hfov and vfov apply to the perspective projection; " + its_angle);
        }
        const float degrees = real(*v, child(pointer, key), Bound::Positive);
        if (!(degrees < 180.0f)) {
            fail(child(pointer, key),
                 "expected a field of view in (0, 180) degrees, got " + describe(*v));
        }
        (std::string(key) == "hfov" ? camera.hfov_degrees : camera.vfov_degrees) = degrees;
    }
    if (const Json* v = find(value, "fov")) {
        if (camera.projection != Projection::Fisheye) {
            fail(child(pointer, "fov"), "fov is the fisheye's image-circle angle; " + its_angle);
        }
        const float degrees = real(*v, child(pointer, "fov"), Bound::Positive);
        if (!(degrees <= kMaxFisheyeFov)) {
            fail(child(pointer, "fov"),
                 "expected a fisheye angle in (0, 360] degrees, got " + describe(*v));
        }
        camera.fisheye_fov_degrees = degrees;
    }
    camera.lens_radius =
        real_or(value, pointer, "lens_radius", camera.lens_radius, Bound::NonNegative);
    if (camera.lens_radius > 0.0f && camera.projection != Projection::Perspective) {
        fail(child(pointer, "lens_radius"),
             "a thin lens needs the perspective projection, not " + projection);
    }
    if (const Json* v = find(value, "focus_distance")) {
        camera.focus_distance = real(*v, child(pointer, "focus_distance"), Bound::Positive);
    }
    // "width" and "height" by their declaration, the one --width and --height are checked by.
    FieldReader size_reader{*this, value, pointer};
    camera.resolution_fields(size_reader);
    if (glm::length(camera.look_at - camera.eye) == 0.0f) {
        fail(child(pointer, "look_at"), "expected look_at to differ from eye");
    }
}

void SceneParser::parse_render(const Json& value, const std::string& pointer,
                               RenderSettings& s) const {
    require_object(value, pointer, "a render settings object");
    // The declared settings (RenderSettings::fields), "sphere_method" (its own syntax), the
    // integrator, and the Whitted integrator's settings, which the render object also takes
    // directly (the form of scenes written before integrators were registered).
    static const std::vector<std::string> keys = [] {
        FieldNames names;
        RenderSettings().fields(names);
        WhittedSettings().fields(names);
        names.names.push_back("sphere_method");
        names.names.push_back("integrator");
        return names.names;
    }();
    check_keys(value, pointer, keys);
    FieldReader reader{*this, value, pointer};
    s.fields(reader);
    if (const std::optional<FieldProblem> problem = s.problem()) {
        fail(child(pointer, problem->field), problem->message);
    }
    const Json* integrator = find(value, "integrator");
    if (integrator) s.integrator = parse_integrator(*integrator, child(pointer, "integrator"));
    if (auto* whitted = std::get_if<WhittedSettings>(&s.integrator)) {
        // The direct keys, then the integrator object's, which win.
        whitted->fields(reader);
        if (integrator) {
            FieldReader object_reader{*this, *integrator, child(pointer, "integrator")};
            whitted->fields(object_reader);
        }
    } else {
        FieldNames whitted_names;
        WhittedSettings().fields(whitted_names);
        for (const std::string& key : whitted_names.names) {
            if (find(value, key.c_str())) {
                fail(child(pointer, key),
                     "a setting of the \"whitted\" integrator, but this render's integrator is \"" +
                         std::string(integrator_name(s.integrator)) + "\"");
            }
        }
    }
    if (const Json* v = find(value, "sphere_method")) {
        // The reader --sphere-method uses (core/sphere_method.h).
        if (const std::optional<std::string> problem =
                read_sphere_method(setting_value(*v), s.spheres)) {
            fail(child(pointer, "sphere_method"), *problem);
        }
    }
}

IntegratorSettings SceneParser::parse_integrator(const Json& value,
                                                 const std::string& pointer) const {
    require_object(value, pointer, "an integrator object {\"type\": ..., settings...}");
    const Json& type = require(value, pointer, "type", "an integrator name");
    const std::string where = child(pointer, "type");
    const std::optional<IntegratorSettings> named =
        type.is_string() ? integrator_named(type.get<std::string>()) : std::nullopt;
    if (!named) fail(where, "expected one of " + integrator_names() + ", got " + describe(type));
    return std::visit(
        [&](const auto& defaults) -> IntegratorSettings {
            using S = std::decay_t<decltype(defaults)>;
            return read_record<S>(value, pointer, {"type"});
        },
        *named);
}

// Material 0 is always "default": the scene's own when it defines one, else Material{}.
void SceneParser::parse_materials(const Json& value, const std::string& pointer,
                                  ShadingScene& shading) {
    require_object(value, pointer, "an object mapping material names to materials");
    Material fallback;
    fallback.name = "default";
    shading.materials.push_back(fallback);
    m_material_ids["default"] = 0;
    for (const auto& item : value.items()) {
        Material material = parse_material(item.value(), child(pointer, item.key()), item.key());
        if (item.key() == "default") {
            shading.materials[0] = material;
        } else {
            m_material_ids[item.key()] = static_cast<uint32_t>(shading.materials.size());
            shading.materials.push_back(material);
        }
    }
}

// A colour, or a string naming a texture of /textures (then `texture` gets its index).
Vec3 SceneParser::colour_or_texture(const Json& object, const std::string& pointer, const char* key,
                                    const Vec3& fallback, int32_t& texture) const {
    const Json* value = find(object, key);
    if (!value) return fallback;
    if (!value->is_string()) return colour(*value, child(pointer, key));
    const std::string name = value->get<std::string>();
    const auto it = m_texture_ids.find(name);
    if (it == m_texture_ids.end()) {
        std::vector<std::string> known;
        for (const auto& entry : m_texture_ids) known.push_back("\"" + entry.first + "\"");
        fail(child(pointer, key),
             "unknown texture \"" + name + "\" (expected a colour or a texture defined in " +
                 "/textures" + (known.empty() ? ", which defines none" : ": " + join(known)) + ")");
    }
    texture = it->second;
    return fallback;
}

// Textures (seed 003 ch. 3; docs/textures.md): name -> {type, scale, seed, ramp, parameters}.
void SceneParser::parse_textures(const Json& value, const std::string& pointer,
                                 ShadingScene& shading) {
    require_object(value, pointer, "an object mapping texture names to textures");
    for (const auto& item : value.items()) {
        m_texture_ids[item.key()] = static_cast<int32_t>(shading.textures.size());
        shading.textures.push_back(
            parse_texture(item.value(), child(pointer, item.key()), item.key()));
    }
}

void SceneParser::parse_fbm(const Json& value, const std::string& pointer, FbmParams& fbm) const {
    if (const Json* v = find(value, "octaves")) {
        fbm.octaves = integer(*v, child(pointer, "octaves"), 1, kMaxOctaves);
    }
    fbm.persistence = real_or(value, pointer, "persistence", fbm.persistence, Bound::Positive);
    fbm.lacunarity = real_or(value, pointer, "lacunarity", fbm.lacunarity, Bound::Positive);
}

ColorRamp SceneParser::parse_ramp(const Json& value, const std::string& pointer) const {
    if (!value.is_array() || value.empty()) {
        fail(pointer, "expected a non-empty array of {\"position\": t, \"color\": c} stops, got " +
                          describe(value));
    }
    std::vector<ColorStop> stops;
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string stop_pointer = child(pointer, i);
        require_object(value[i], stop_pointer, "a ramp stop {\"position\": t, \"color\": c}");
        check_keys(value[i], stop_pointer, {"position", "color"});
        ColorStop stop;
        stop.position = real(require(value[i], stop_pointer, "position", "a number"),
                             child(stop_pointer, "position"));
        stop.color = colour(require(value[i], stop_pointer, "color", "a colour"),
                            child(stop_pointer, "color"));
        stops.push_back(stop);
    }
    return ColorRamp(std::move(stops));
}

Texture SceneParser::parse_texture(const Json& value, const std::string& pointer,
                                   const std::string& name) const {
    require_object(value, pointer, "a texture object");
    const std::string type = choice(require(value, pointer, "type", "a texture type"),
                                    child(pointer, "type"), texture_kind_names());
    Texture t = make_texture(type);
    t.name = name;
    if (type == "constant") {
        check_keys(value, pointer, {"type", "color"});
        std::get<ConstantMap>(t.map).color = colour_or(value, pointer, "color", Vec3(0.5f));
        return t;
    }
    // Features below 1e-6 or above 1e6 world units would alias to noise or overflow the lattice.
    t.scale = real_or(value, pointer, "scale", 1.0f, Bound::Positive);
    if (!(t.scale >= 1e-6f && t.scale <= 1e6f)) {
        fail(child(pointer, "scale"),
             "expected a number in [1e-6, 1e6], got " + describe(*find(value, "scale")));
    }
    if (const Json* v = find(value, "seed")) {
        t.seed = static_cast<uint32_t>(integer(*v, child(pointer, "seed"), 0, 2147483647));
    }
    if (const Json* v = find(value, "ramp")) t.ramp = parse_ramp(*v, child(pointer, "ramp"));
    if (type == "value" || type == "perlin" || type == "turbulence") {
        check_keys(value, pointer,
                   {"type", "scale", "seed", "ramp", "octaves", "persistence", "lacunarity"});
        FbmParams& fbm = type == "value"    ? std::get<ValueNoiseMap>(t.map).fbm
                         : type == "perlin" ? std::get<PerlinMap>(t.map).fbm
                                            : std::get<TurbulenceMap>(t.map).fbm;
        parse_fbm(value, pointer, fbm);
    } else if (type == "cellular") {
        check_keys(value, pointer, {"type", "scale", "seed", "ramp", "metric", "feature"});
        CellularMap& m = std::get<CellularMap>(t.map);
        if (const Json* v = find(value, "metric")) {
            const std::string metric =
                choice(*v, child(pointer, "metric"), {"euclidean", "manhattan", "chebyshev"});
            m.metric = metric == "manhattan"   ? DistanceMetric::Manhattan
                       : metric == "chebyshev" ? DistanceMetric::Chebyshev
                                               : DistanceMetric::Euclidean;
        }
        if (const Json* v = find(value, "feature")) {
            const std::string f = choice(*v, child(pointer, "feature"),
                                         {"f1", "f2", "f3", "f2-f1", "combination", "cell-id"});
            m.feature = f == "f1"        ? CellularFeature::F1
                        : f == "f2"      ? CellularFeature::F2
                        : f == "f3"      ? CellularFeature::F3
                        : f == "f2-f1"   ? CellularFeature::F2MinusF1
                        : f == "cell-id" ? CellularFeature::CellId
                                         : CellularFeature::Combination;
        }
    } else if (type == "marble") {
        check_keys(value, pointer,
                   {"type", "scale", "seed", "ramp", "octaves", "persistence", "lacunarity",
                    "frequency", "distortion"});
        MarbleMap& m = std::get<MarbleMap>(t.map);
        parse_fbm(value, pointer, m.fbm);
        m.frequency = real_or(value, pointer, "frequency", m.frequency);
        m.distortion = real_or(value, pointer, "distortion", m.distortion, Bound::NonNegative);
    } else if (type == "warped") {
        check_keys(
            value, pointer,
            {"type", "scale", "seed", "ramp", "octaves", "persistence", "lacunarity", "warp"});
        WarpedMap& m = std::get<WarpedMap>(t.map);
        parse_fbm(value, pointer, m.fbm);
        m.warp = real_or(value, pointer, "warp", m.warp, Bound::NonNegative);
    } else {  // pool-bottom
        check_keys(value, pointer, {"type", "scale", "seed", "ramp", "warp"});
        PoolBottomMap& m = std::get<PoolBottomMap>(t.map);
        m.warp = real_or(value, pointer, "warp", m.warp, Bound::NonNegative);
    }
    return t;
}

bool SceneParser::image_map(const Json& object, const std::string& pointer, const char* key,
                            ImageMap& map, Vec3& factor) const {
    const Json* value = find(object, key);
    if (!value || !value->is_object()) return false;
    const std::string at = child(pointer, key);
    check_keys(*value, at, {"image", "factor", "wrap", "colorspace", "scale", "offset"});
    const Json& file = require(*value, at, "image", "the path of an image file");
    if (!file.is_string() || file.get<std::string>().empty()) {
        fail(child(at, "image"), "expected the path of an image file, got " + describe(file));
    }
    const std::string path = join_path(m_base_dir, file.get<std::string>());
    map.image = load_texture_image(path, m_source + "#" + child(at, "image"), m_access, &m_images);
    factor = colour_or(*value, at, "factor", Vec3(1.0f));
    if (const Json* v = find(*value, "wrap")) {
        const std::string wrap = choice(*v, child(at, "wrap"), {"repeat", "clamp", "mirror"});
        map.wrap_s = map.wrap_t = wrap == "clamp"    ? TextureWrap::Clamp
                                  : wrap == "mirror" ? TextureWrap::Mirror
                                                     : TextureWrap::Repeat;
    }
    if (const Json* v = find(*value, "colorspace")) {
        const std::string space = choice(*v, child(at, "colorspace"), {"auto", "srgb", "linear"});
        map.encoding = space == "srgb"     ? TextureEncoding::Srgb
                       : space == "linear" ? TextureEncoding::Linear
                                           : TextureEncoding::Auto;
    }
    // (s, t) = scale·(u, v) + offset: repeats and shifts of the image across the surface.
    glm::vec2 scale(1.0f), offset(0.0f);
    auto pair = [&](const char* name, glm::vec2& out) {
        const Json* v = find(*value, name);
        if (!v) return;
        const std::string where = child(at, name);
        if (v->is_number()) {
            out = glm::vec2(real(*v, where));
        } else if (v->is_array() && v->size() == 2) {
            out = glm::vec2(real((*v)[0], child(where, "0")), real((*v)[1], child(where, "1")));
        } else {
            fail(where, std::string("expected a number or [u, v], got ") + describe(*v));
        }
    };
    pair("scale", scale);
    pair("offset", offset);
    map.transform = glm::mat3(scale.x, 0.0f, 0.0f, 0.0f, scale.y, 0.0f, offset.x, offset.y, 1.0f);
    return true;
}

Material SceneParser::parse_material(const Json& value, const std::string& pointer,
                                     const std::string& name) const {
    require_object(value, pointer, "a material object");
    check_keys(value, pointer,
               {"ka", "kd", "ks", "shininess", "specular", "reflect", "transmit", "ior", "fresnel",
                "translucency", "absorption", "emission", "bump", "double_sided"});
    Material m;
    m.name = name;
    // Each of kd, ka, ks is a colour or the name of a texture (seed 003 ch. 3); kd, ks and
    // emission may also be an image texture (kd = factor·texel; ka follows it by default).
    Vec3 factor(1.0f);
    const bool kd_image = image_map(value, pointer, "kd", m.images.base, factor);
    if (kd_image) {
        m.kd = factor;
        m.images.kd = ImageTerm{true, Vec3(0.0f), factor};
    } else {
        m.kd = colour_or_texture(value, pointer, "kd", Vec3(0.8f), m.textures.kd);  // seed 000 [22]
    }
    if (kd_image && !find(value, "ka")) {
        m.ka = 0.1f * m.kd;
        m.images.ka = ImageTerm{true, Vec3(0.0f), 0.1f * factor};
    } else if (find(value, "ka")) {
        m.ka = colour_or_texture(value, pointer, "ka", Vec3(0.1f), m.textures.ka);  // seed 000 [20]
    } else {
        m.ka = 0.1f * m.kd;
        if (m.textures.kd != kNoTexture) {  // the default ka = 0.1 × kd follows kd's texture
            m.textures.ka = m.textures.kd;
            m.textures.ka_scale = 0.1f;
        }
    }
    if (image_map(value, pointer, "ks", m.images.specular, factor)) {
        m.ks = factor;  // × the image (the specular slot multiplies ks)
    } else {
        m.ks = colour_or_texture(value, pointer, "ks", Vec3(0.0f), m.textures.ks);  // seed 000 [24]
    }
    if (const Json* v = find(value, "bump")) {  // seed 003's suggested extension
        const std::string bump_pointer = child(pointer, "bump");
        require_object(*v, bump_pointer, "a bump object {\"texture\": name, \"strength\": s}");
        check_keys(*v, bump_pointer, {"texture", "strength"});
        const Json& texture = require(*v, bump_pointer, "texture", "the name of a texture");
        if (!texture.is_string()) {
            fail(child(bump_pointer, "texture"),
                 "expected the name of a texture, got " + describe(texture));
        }
        int32_t id = kNoTexture;
        colour_or_texture(*v, bump_pointer, "texture", Vec3(0.0f), id);
        m.textures.bump = id;
        m.textures.bump_strength = real_or(*v, bump_pointer, "strength", 1.0f);
    }
    m.shininess = real_or(value, pointer, "shininess", 32.0f, Bound::NonNegative);
    if (const Json* v = find(value, "specular")) {
        m.specular_model = choice(*v, child(pointer, "specular"), {"phong", "blinn"}) == "blinn"
                               ? SpecularModel::Blinn   // seed 000 eq. [28]
                               : SpecularModel::Phong;  // seed 000 eq. [24]
    }
    m.reflect = colour_or(value, pointer, "reflect", Vec3(0.0f));    // seed 001 reflection
    m.transmit = colour_or(value, pointer, "transmit", Vec3(0.0f));  // seed 001 transmission
    m.ior = real_or(value, pointer, "ior", 1.0f, Bound::Positive);   // seed 001 Snell n21
    if (const Json* v = find(value, "fresnel")) {  // seed 000's W(θ): Fresnel weights
        if (!v->is_boolean()) {
            fail(child(pointer, "fresnel"), "expected true or false, got " + describe(*v));
        }
        m.fresnel = v->get<bool>();
        // The Fresnel reflection of a dielectric is untinted: reflect defaults to 1.
        if (m.fresnel && !find(value, "reflect")) m.reflect = Vec3(1.0f);
    }
    m.translucency = colour_or(value, pointer, "translucency", Vec3(0.0f));  // seed 001
    m.absorption = colour_or(value, pointer, "absorption", Vec3(0.0f));      // Beer–Lambert
    if (image_map(value, pointer, "emission", m.images.emission, factor)) {
        m.emission = factor;  // × the image
    } else {
        m.emission = colour_or(value, pointer, "emission", Vec3(0.0f));
    }
    // Both sides emit and, in the radiosity solve, receive (docs/radiosity.md) unless false.
    if (const Json* v = find(value, "double_sided")) {
        if (!v->is_boolean()) {
            fail(child(pointer, "double_sided"), "expected true or false, got " + describe(*v));
        }
        m.double_sided = v->get<bool>();
    }
    return m;
}

Attenuation SceneParser::parse_attenuation(const Json& value, const std::string& pointer) const {
    require_object(value, pointer, "an attenuation object");
    const std::string type =
        choice(require(value, pointer, "type", "\"none\", \"linear\" or \"quadratic\""),
               child(pointer, "type"), {"none", "linear", "quadratic"});
    Attenuation a;
    if (type == "none") {
        check_keys(value, pointer, {"type"});
    } else if (type == "linear") {  // seed 000: f(d) = 1/(d + d0)
        check_keys(value, pointer, {"type", "d0"});
        a.kind = Attenuation::Kind::Linear;
        a.d0 = real_or(value, pointer, "d0", 0.0f, Bound::NonNegative);
    } else {  // seed 003 eq. 2.8: f(d) = min(1, 1/(a0 + a1·d + a2·d²))
        check_keys(value, pointer, {"type", "a0", "a1", "a2"});
        a.kind = Attenuation::Kind::Quadratic;
        a.a0 = real_or(value, pointer, "a0", 1.0f, Bound::NonNegative);
        a.a1 = real_or(value, pointer, "a1", 0.0f, Bound::NonNegative);
        a.a2 = real_or(value, pointer, "a2", 0.0f, Bound::NonNegative);
        if (!(a.a0 + a.a1 + a.a2 > 0.0f)) {
            fail(pointer, "expected at least one of a0, a1, a2 to be > 0");
        }
    }
    return a;
}

Light SceneParser::parse_light(const Json& value, const std::string& pointer) const {
    require_object(value, pointer, "a light object");
    // The registered lights (shading/light.h), by their kName: each read by its own form() and
    // fields(), the environment with its "image" besides.
    std::vector<std::string> names;
    for_each_light([&](auto l) { names.push_back(decltype(l)::kName); });
    std::vector<std::string> quoted;
    for (const std::string& n : names) quoted.push_back("\"" + n + "\"");
    const std::string type =
        choice(require(value, pointer, "type", join_or(quoted)), child(pointer, "type"), names);
    std::optional<Light> light;
    for_each_light([&](auto l) {
        using L = decltype(l);
        if (type != L::kName) return;
        if constexpr (std::is_same_v<L, EnvironmentLight>) {
            light = parse_environment(value, pointer, {"type"});
        } else {
            light = read_light<L>(value, pointer);
        }
    });
    return *light;
}

// Whether a light has a form() (shading/light.h): a choice read before its fields.
template <typename L, typename = void>
struct has_form : std::false_type {};
template <typename L>
struct has_form<L, std::void_t<decltype(std::declval<L&>().form(std::declval<int&>()))>>
    : std::true_type {};

template <typename L>
L SceneParser::read_light(const Json& value, const std::string& pointer) const {
    L light;
    FieldNames keys;
    keys.names.push_back("type");
    if constexpr (has_form<L>::value) {
        FormReader form{*this, value, pointer};
        light.form(form);
        light.form(keys);
    }
    light.fields(keys);
    check_keys(value, pointer, keys.names);
    FieldReader reader{*this, value, pointer};
    light.fields(reader);
    if constexpr (has_finish<L>::value) light.finish();
    if (const std::optional<FieldProblem> problem = light.problem()) {
        fail(child(pointer, problem->field), problem->message);
    }
    return light;
}

EnvironmentLight SceneParser::parse_environment(const Json& value, const std::string& pointer,
                                                const std::vector<std::string>& extra_keys) const {
    std::vector<std::string> keys = extra_keys;
    keys.push_back("image");
    EnvironmentLight light = read_record<EnvironmentLight>(value, pointer, keys);
    if (const Json* image = find(value, "image")) {
        const std::string image_pointer = child(pointer, "image");
        if (!image->is_string() || image->get<std::string>().empty()) {
            fail(image_pointer, "expected a path to an image file, got " + describe(*image));
        }
        light.map = read_environment_image(join_path(m_base_dir, image->get<std::string>()),
                                           m_source + "#" + image_pointer, m_access);
    }
    return light;
}

// The radiosity pre-pass (docs/radiosity.md): used when render.gi is "radiosity".
void SceneParser::parse_radiosity(const Json& value, const std::string& pointer,
                                  RadiositySettings& r) const {
    require_object(value, pointer,
                   "a radiosity object {\"patch_size\", \"threshold\", \"max_shots\", "
                   "\"form_factors\", \"rays\"}");
    check_keys(value, pointer, {"patch_size", "threshold", "max_shots", "form_factors", "rays"});
    r.patch_size = real_or(value, pointer, "patch_size", r.patch_size, Bound::NonNegative);
    r.threshold =
        real_or(value, pointer, "threshold", static_cast<float>(r.threshold), Bound::NonNegative);
    if (const Json* v = find(value, "max_shots")) {
        r.max_shots = integer(*v, child(pointer, "max_shots"), 0, 100000000);
    }
    if (const Json* v = find(value, "rays")) r.rays = integer(*v, child(pointer, "rays"), 1, 65536);
    if (const Json* v = find(value, "form_factors")) {
        r.form_factors =
            choice(*v, child(pointer, "form_factors"), {"rays", "analytic"}) == "analytic"
                ? FormFactorMethod::Analytic
                : FormFactorMethod::Rays;
    }
}

Fog SceneParser::parse_fog(const Json& value, const std::string& pointer) const {
    require_object(value, pointer, "a fog object {\"color\": colour, \"density\": number}");
    check_keys(value, pointer, {"color", "density"});
    Fog fog;
    fog.color = colour_or(value, pointer, "color", Vec3(0.5f));
    fog.density = real(require(value, pointer, "density", "a number >= 0"),
                       child(pointer, "density"), Bound::NonNegative);
    return fog;
}

uint32_t SceneParser::material_of(const Json& object, const std::string& pointer) const {
    const Json* value = find(object, "material");
    if (!value) return 0;  // "default"
    const std::string where = child(pointer, "material");
    if (!value->is_string()) fail(where, "expected a material name, got " + describe(*value));
    const auto name = value->get<std::string>();
    const auto it = m_material_ids.find(name);
    if (it == m_material_ids.end()) {
        std::vector<std::string> known;
        for (const auto& entry : m_material_ids) known.push_back(entry.first);
        fail(where, "unknown material \"" + name + "\" (defined: " + join(known) + ")");
    }
    return it->second;
}

void SceneParser::parse_groups(const Json& value, const std::string& pointer,
                               SceneDescription& out) {
    require_object(value, pointer, "an object of named groups {\"name\": [objects]}");
    for (const auto& item : value.items()) {
        const std::string where = child(pointer, item.key());
        if (item.key().empty()) fail(where, "expected a non-empty group name");
        const Json& objects = item.value();
        if (!objects.is_array() || objects.empty()) {
            fail(where, "expected a non-empty array of objects, got " + describe(objects));
        }
        ShapeGroup group;
        group.name = item.key();
        TriangleMesh polygons;
        polygons.name = "polygons";
        const ObjectSink sink{group.shapes, group.meshes, polygons, true};
        for (size_t i = 0; i < objects.size(); ++i) {
            parse_object(objects[i], child(where, i), out, sink);
        }
        if (!polygons.triangles.empty()) group.meshes.push_back(std::move(polygons));
        m_group_ids[group.name] = static_cast<uint32_t>(out.scene.groups.size());
        out.scene.groups.push_back(std::move(group));
    }
}

Instance SceneParser::parse_instance(const Json& value, const std::string& pointer) const {
    check_keys(value, pointer, {"type", "of", "transform", "material"});
    const std::string of_pointer = child(pointer, "of");
    const Json& of = require(value, pointer, "of", "the name of a group");
    if (!of.is_string()) fail(of_pointer, "expected the name of a group, got " + describe(of));
    const auto it = m_group_ids.find(of.get<std::string>());
    if (it == m_group_ids.end()) {
        std::vector<std::string> known;
        for (const auto& entry : m_group_ids) known.push_back(entry.first);
        fail(of_pointer, "unknown group \"" + of.get<std::string>() + "\" (defined in /groups: " +
                             (known.empty() ? std::string("none") : join(known)) + ")");
    }
    Instance instance;
    instance.group = it->second;
    if (const Json* t = find(value, "transform")) {
        const std::string where = child(pointer, "transform");
        const glm::dmat4 m = parse_transform(*t, where, true);
        // The accel needs M and M⁻¹ in float: both finite, within the scene magnitude, and
        // det M ≠ 0 in float.
        const glm::mat4 f(m);
        if (glm::determinant(glm::mat3(f)) == 0.0f) {
            fail(where, "expected an invertible transform, got a singular one (determinant 0)");
        }
        const glm::mat4 inverse = glm::inverse(f);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                if (!within_scene_magnitude(m[c][r]) || !within_scene_magnitude(inverse[c][r])) {
                    fail(where, std::string("expected an invertible transform whose matrix and "
                                            "inverse fit in floats: every entry must be ") +
                                    kSceneMagnitudeRule);
                }
            }
        }
        instance.transform = f;
    }
    if (find(value, "material")) instance.material = material_of(value, pointer);
    return instance;
}

void SceneParser::parse_object(const Json& value, const std::string& pointer, SceneDescription& out,
                               const ObjectSink& sink) {
    require_object(value, pointer, "an object");
    // The registered shapes by name (core/shapes/registry.h), then the triangle-mesh kinds.
    static const std::vector<std::string> types = [] {
        std::vector<std::string> names = Shapes::names();
        for (const char* kind :
             {"triangle", "polygon", "mesh", "heightfield", "voxels", "sphereflake", "instance"}) {
            names.push_back(kind);
        }
        return names;
    }();
    static const std::string expected_type = [] {
        std::vector<std::string> quoted;
        for (const std::string& t : types) quoted.push_back("\"" + t + "\"");
        return join_or(quoted);
    }();
    const std::string type =
        choice(require(value, pointer, "type", expected_type), child(pointer, "type"), types);
    bool shape_read = false;
    sink.shapes.for_each([&](auto& shapes) {
        if (type == ShapeOf<decltype(shapes)>::kName) {
            parse_shape(value, pointer, shapes, true);
            read_shape_method(value, pointer, shapes, sink.in_group, out);
            shape_read = true;
        }
    });
    if (shape_read) {
        return;
    } else if (type == "triangle" || type == "polygon") {
        check_keys(value, pointer, {"type", "vertices", "normals", "material"});
        const std::string vertices_pointer = child(pointer, "vertices");
        const Json& vertices = require(value, pointer, "vertices", "an array of [x, y, z]");
        const bool triangle = type == "triangle";
        if (!vertices.is_array() || (triangle ? vertices.size() != 3 : vertices.size() < 3)) {
            fail(vertices_pointer, std::string("expected an array of ") +
                                       (triangle ? "3" : "at least 3") +
                                       " vertices [x, y, z], got " + describe(vertices));
        }
        if (vertices.size() > kMaxPolygonVertices) {
            fail(vertices_pointer, polygon_vertex_limit_text(vertices.size()));
        }
        std::vector<Vec3> points, normals;
        for (size_t i = 0; i < vertices.size(); ++i) {
            points.push_back(vec3(vertices[i], child(vertices_pointer, i)));
        }
        if (const Json* n = find(value, "normals")) {
            const std::string normals_pointer = child(pointer, "normals");
            if (!n->is_array() || n->size() != vertices.size()) {
                fail(normals_pointer, "expected an array of " + std::to_string(vertices.size()) +
                                          " normals (one per vertex), got " + describe(*n));
            }
            for (size_t i = 0; i < n->size(); ++i) {
                normals.push_back(direction((*n)[i], child(normals_pointer, i)));
            }
        }
        if (!sink.polygons.add_polygon(points, normals, material_of(value, pointer))) {
            fail(vertices_pointer, "expected a " + type + " with non-zero area");
        }
    } else if (type == "heightfield") {
        if (sink.in_group) {
            fail(child(pointer, "type"),
                 "a group may not contain height fields (they are placed directly only)");
        }
        parse_heightfield(value, pointer, out);
    } else if (type == "voxels") {
        if (sink.in_group) {
            fail(child(pointer, "type"),
                 "a group may not contain voxel grids (they are placed directly only)");
        }
        parse_voxels(value, pointer, out);
    } else if (type == "sphereflake") {
        // Spheres generated as the SPD "balls" scene places them (apps/scene/sphereflake.h):
        // a scene of many spheres without a file of them.
        check_keys(value, pointer, {"type", "center", "radius", "depth", "axis", "material"});
        const Vec3 center =
            vec3(require(value, pointer, "center", "[x, y, z]"), child(pointer, "center"));
        const float radius = real(require(value, pointer, "radius", "a positive number"),
                                  child(pointer, "radius"), Bound::Positive);
        const int depth = integer(require(value, pointer, "depth", "an integer"),
                                  child(pointer, "depth"), 0, kMaxSphereflakeDepth);
        Vec3 axis(0, 0, 1);
        if (const Json* v = find(value, "axis")) axis = direction(*v, child(pointer, "axis"));
        add_sphereflake(sink.shapes.of<Sphere>(), center, radius, axis, depth,
                        material_of(value, pointer));
    } else if (type == "instance") {
        if (sink.in_group) {
            fail(child(pointer, "type"),
                 "a group may not contain instances (of itself or of another group): instances "
                 "are one level deep, as this Embree build traces (RTC_MAX_INSTANCE_LEVEL_COUNT " +
                     std::to_string(kMaxInstanceLevels) + ")");
        }
        out.scene.instances.push_back(parse_instance(value, pointer));
    } else {
        parse_mesh(value, pointer, out, sink.meshes);
    }
}

// A height field (docs/heightfields.md): samples from an image or a named texture, laid over
// [origin.x, origin.x + size.x] × [origin.z, origin.z + size.z] at height origin.y + size.y·value.
void SceneParser::parse_heightfield(const Json& value, const std::string& pointer,
                                    SceneDescription& out) const {
    check_keys(value, pointer,
               {"type", "image", "texture", "resolution", "size", "origin", "method", "smooth",
                "material"});
    HeightField field;
    const std::string size_pointer = child(pointer, "size");
    field.size = extent(value, pointer);
    field.lower = Vec3(-0.5f * field.size.x, 0.0f, -0.5f * field.size.z);
    if (const Json* v = find(value, "origin")) field.lower = vec3(*v, child(pointer, "origin"));
    std::string method = "auto";
    if (const Json* v = find(value, "method")) {
        method = choice(*v, child(pointer, "method"), {"dda", "mesh", "auto"});
    }
    if (const Json* v = find(value, "smooth")) {
        if (!v->is_boolean()) {
            fail(child(pointer, "smooth"), "expected true or false, got " + describe(*v));
        }
        field.smooth = v->get<bool>();
    }
    field.material = material_of(value, pointer);

    const Json* image = find(value, "image");
    const Json* texture = find(value, "texture");
    if ((image != nullptr) == (texture != nullptr)) {
        fail(pointer, "expected exactly one of \"image\" (a file) and \"texture\" (a name)");
    }
    if (image) {
        if (find(value, "resolution")) {
            fail(child(pointer, "resolution"),
                 "resolution applies to \"texture\"; an image has its own");
        }
        const std::string image_pointer = child(pointer, "image");
        if (!image->is_string() || image->get<std::string>().empty()) {
            fail(image_pointer, "expected a path to an image file, got " + describe(*image));
        }
        HeightSamples samples = read_height_image(join_path(m_base_dir, image->get<std::string>()),
                                                  m_source + "#" + image_pointer, m_access);
        field.columns = samples.columns;
        field.rows = samples.rows;
        field.heights = std::move(samples.values);
    } else {
        int32_t id = kNoTexture;
        if (!texture->is_string()) {
            fail(child(pointer, "texture"),
                 "expected the name of a texture, got " + describe(*texture));
        }
        colour_or_texture(value, pointer, "texture", Vec3(0.0f), id);
        const Texture& map = out.shading.textures[size_t(id)];
        field.columns = field.rows = 257;
        if (const Json* v = find(value, "resolution")) {
            const std::string where = child(pointer, "resolution");
            if (!v->is_array() || v->size() != 2) {
                fail(where, "expected [columns, rows], each in [2, " +
                                std::to_string(kMaxTextureHeightSide) + "], got " + describe(*v));
            }
            field.columns = integer((*v)[0], child(where, size_t(0)), 2, kMaxTextureHeightSide);
            field.rows = integer((*v)[1], child(where, size_t(1)), 2, kMaxTextureHeightSide);
        }
        field.heights.resize(size_t(field.columns) * size_t(field.rows));
        for (int j = 0; j < field.rows; ++j) {
            for (int i = 0; i < field.columns; ++i) {
                // The texture's value at the sample's place on the base plane.
                const Vec3 p =
                    field.lower + Vec3(field.size.x * float(i) / float(field.columns - 1), 0.0f,
                                       field.size.z * float(j) / float(field.rows - 1));
                field.heights[size_t(j) * size_t(field.columns) + size_t(i)] = map.value(p);
            }
        }
    }
    for (float& h : field.heights) h *= field.size.y;  // sample value 1 -> size.y
    field.finish();
    for (const Vec3& corner : {field.bounds().lower, field.bounds().upper}) {
        if (!within_scene_magnitude(max_abs_component(corner))) {
            fail(size_pointer, std::string("the height field does not fit in floats: every "
                                           "coordinate must be ") +
                                   kSceneMagnitudeRule);
        }
    }
    const bool mesh =
        method == "mesh" || (method == "auto" && auto_prefers_mesh(field.cell_count()));
    if (method == "auto") {
        // Two triangles a cell (kMeshBytesPerCell is the cell's).
        out.method_choices.push_back(
            auto_choice_line("heightfield", pointer, mesh ? "mesh" : "dda", 2 * field.cell_count(),
                             2 * (kAutoMeshBytes / kMeshBytesPerCell), kMeshBytesPerCell / 2));
    }
    if (mesh) {
        out.scene.meshes.push_back(field.tessellate());
    } else {
        out.scene.heightfields.push_back(std::move(field));
    }
}

// A voxel grid (docs/voxels.md): nx·ny·nz raw little-endian values from `file`, x fastest,
// filling the box [origin, origin + size] (by default centred on 0), traced to its iso-surface
// (`surface`) or composited through a transfer ramp (`composite`).
void SceneParser::parse_voxels(const Json& value, const std::string& pointer,
                               SceneDescription& out) const {
    check_keys(value, pointer,
               {"type", "file", "dims", "format", "size", "origin", "mode", "threshold", "transfer",
                "material", "method"});
    VoxelGrid grid;
    const std::string dims_pointer = child(pointer, "dims");
    const std::string side_range = "[2, " + std::to_string(kMaxVoxelSide) + "]";
    const Json& dims = require(value, pointer, "dims", "[nx, ny, nz], each in " + side_range);
    if (!dims.is_array() || dims.size() != 3) {
        fail(dims_pointer,
             "expected [nx, ny, nz], each in " + side_range + ", got " + describe(dims));
    }
    uint64_t count = 1;
    for (size_t a = 0; a < 3; ++a) {
        grid.dims[a] = integer(dims[a], child(dims_pointer, a), 2, kMaxVoxelSide);
        count *= uint64_t(grid.dims[a]);
    }
    if (count > kMaxVoxels) {
        fail(dims_pointer, "expected at most " + std::to_string(kMaxVoxels) +
                               " voxels in all, got " + std::to_string(count));
    }
    std::string format = "u8";
    if (const Json* v = find(value, "format")) {
        format = choice(*v, child(pointer, "format"), {"u8", "u16", "f32"});
    }
    const VoxelFormat voxel_format = format == "u8"    ? VoxelFormat::U8
                                     : format == "u16" ? VoxelFormat::U16
                                                       : VoxelFormat::F32;
    const std::string size_pointer = child(pointer, "size");
    grid.size = extent(value, pointer);
    grid.lower = -0.5f * grid.size;
    if (const Json* v = find(value, "origin")) grid.lower = vec3(*v, child(pointer, "origin"));
    for (int a = 0; a < 3; ++a) {
        // Voxels of a normal float size (a denormal one is flushed to zero) in a box that fits.
        if (!(grid.voxel_size()[a] >= std::numeric_limits<float>::min()) ||
            !within_scene_magnitude(grid.lower[a] + grid.size[a])) {
            fail(size_pointer, std::string("expected a box whose voxels have a size > 0 in floats "
                                           "and whose corners are ") +
                                   kSceneMagnitudeRule);
        }
    }
    std::string mode = "surface";
    if (const Json* v = find(value, "mode")) {
        mode = choice(*v, child(pointer, "mode"), {"surface", "composite"});
    }
    grid.mode = mode == "surface" ? VoxelMode::Surface : VoxelMode::Composite;
    // Each mode's own fields; the other mode's are refused (they would do nothing).
    for (const char* key : mode == "surface"
                               ? std::vector<const char*>{"transfer"}
                               : std::vector<const char*>{"threshold", "material", "method"}) {
        if (find(value, key)) {
            fail(child(pointer, key), std::string(key) + " applies to \"mode\": \"" +
                                          (mode == "surface" ? "composite" : "surface") +
                                          "\" only");
        }
    }
    grid.threshold = real_or(value, pointer, "threshold", 0.5f);
    // Surface mode: traced by the 3-D DDA (default) or as its marching-tetrahedra mesh, or
    // either by the mesh's size (auto_voxels_prefer_mesh).
    std::string method = "dda";
    if (const Json* v = find(value, "method")) {
        method = choice(*v, child(pointer, "method"), {"dda", "mesh", "auto"});
    }
    grid.material = material_of(value, pointer);
    if (const Json* v = find(value, "transfer")) {
        grid.transfer = parse_transfer(*v, child(pointer, "transfer"));
    }

    const std::string file_pointer = child(pointer, "file");
    const Json& file = require(value, pointer, "file", "a path to a raw voxel file");
    if (!file.is_string() || file.get<std::string>().empty()) {
        fail(file_pointer, "expected a path to a raw voxel file, got " + describe(file));
    }
    const std::string path = join_path(m_base_dir, file.get<std::string>());
    const std::string bytes = read_input_file(path, m_source + "#" + file_pointer, "voxel file",
                                              kMaxVoxelFileBytes, m_access);
    const uint64_t expected = count * voxel_bytes(voxel_format);
    if (bytes.size() != expected) {
        fail(dims_pointer, "expected dims that match the size of the voxel file '" + path +
                               "': " + std::to_string(grid.dims[0]) + " × " +
                               std::to_string(grid.dims[1]) + " × " + std::to_string(grid.dims[2]) +
                               " " + format + " voxels are " + std::to_string(expected) +
                               " bytes, the file has " + std::to_string(bytes.size()));
    }
    grid.values = decode_voxels(bytes, voxel_format);
    for (size_t i = 0; i < grid.values.size(); ++i) {
        if (!within_scene_magnitude(grid.values[i])) {
            const size_t nx = size_t(grid.dims[0]), ny = size_t(grid.dims[1]);
            fail(file_pointer,
                 "voxel (" + std::to_string(i % nx) + ", " + std::to_string(i / nx % ny) + ", " +
                     std::to_string(i / (nx * ny)) + ") of '" + path + "' is " +
                     std::to_string(grid.values[i]) + ": expected values " + kSceneMagnitudeRule);
        }
    }
    bool mesh = method == "mesh";
    if (method == "auto") {
        const size_t triangles = grid.mesh_triangles();
        mesh = auto_voxels_prefer_mesh(triangles);
        out.method_choices.push_back(auto_choice_line(
            "voxels", pointer, mesh ? "mesh" : "dda", triangles,
            kAutoVoxelMeshBytes / kVoxelMeshBytesPerTriangle, kVoxelMeshBytesPerTriangle));
    }
    if (!mesh) {
        out.scene.voxels.push_back(std::move(grid));
        return;
    }
    TriangleMesh triangles = grid.tessellate();
    if (triangles.triangles.empty()) {
        out.warnings.push_back(m_source + "#" + pointer +
                               ": the voxel grid's mesh is empty (no voxel crosses the threshold)");
        return;
    }
    out.scene.meshes.push_back(std::move(triangles));
}

// A transfer ramp: [{"value": v, "color": c, "density": σ}, ...], sorted by value.
VoxelTransfer SceneParser::parse_transfer(const Json& value, const std::string& pointer) const {
    const char* expected_stops =
        "a non-empty array of {\"value\": v, \"color\": c, \"density\": σ} stops sorted by "
        "value";
    if (!value.is_array() || value.empty()) {
        fail(pointer, std::string("expected ") + expected_stops + ", got " + describe(value));
    }
    VoxelTransfer transfer;
    transfer.stops.clear();
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string stop_pointer = child(pointer, i);
        require_object(value[i], stop_pointer,
                       "a transfer stop {\"value\": v, \"color\": c, \"density\": σ}");
        check_keys(value[i], stop_pointer, {"value", "color", "density"});
        TransferStop stop;
        stop.value = real(require(value[i], stop_pointer, "value", "a number"),
                          child(stop_pointer, "value"));
        stop.color = colour(require(value[i], stop_pointer, "color", "a colour"),
                            child(stop_pointer, "color"));
        stop.density = real(require(value[i], stop_pointer, "density", "a number >= 0"),
                            child(stop_pointer, "density"), Bound::NonNegative);
        if (i > 0 && stop.value < transfer.stops.back().value) {
            fail(child(stop_pointer, "value"),
                 "expected stops sorted by value: " + describe(value[i]["value"]) +
                     " comes after " + describe(value[i - 1]["value"]));
        }
        transfer.stops.push_back(stop);
    }
    return transfer;
}

glm::dmat4 SceneParser::parse_transform(const Json& value, const std::string& pointer,
                                        bool matrix) const {
    require_object(value, pointer, "a transform object");
    if (!matrix) {
        check_keys(value, pointer, {"scale", "rotate", "translate"});
    } else if (const Json* v = find(value, "matrix")) {
        check_keys(value, pointer, {"matrix"});  // not mixed with scale/rotate/translate
        // Rows of the affine matrix: 3 rows [a b c d] (the fourth is implied), or 4 rows whose
        // last is [0, 0, 0, 1].
        const std::string where = child(pointer, "matrix");
        const std::string expected = "3 or 4 rows of 4 numbers (an affine matrix, row by row)";
        if (!v->is_array() || v->size() < 3 || v->size() > 4) {
            fail(where, "expected " + expected + ", got " + describe(*v));
        }
        glm::dmat4 m(1.0);
        for (size_t r = 0; r < v->size(); ++r) {
            const Json& row = (*v)[r];
            const std::string row_pointer = child(where, r);
            if (!row.is_array() || row.size() != 4) {
                fail(row_pointer, "expected a row of 4 numbers, got " + describe(row));
            }
            for (size_t c = 0; c < 4; ++c) {
                const double x = real(row[c], child(row_pointer, c));
                if (r == 3 && x != (c == 3 ? 1.0 : 0.0)) {
                    fail(row_pointer,
                         "expected [0, 0, 0, 1] (an affine matrix), got " + describe(row));
                }
                m[static_cast<int>(c)][static_cast<int>(r)] = x;  // glm: m[column][row]
            }
        }
        return m;
    } else {
        check_keys(value, pointer, {"matrix", "scale", "rotate", "translate"});
    }
    glm::dvec3 scale(1.0), rotate(0.0), translate(0.0);
    if (const Json* v = find(value, "scale")) {
        const std::string where = child(pointer, "scale");
        scale = v->is_number() ? glm::dvec3(real(*v, where)) : glm::dvec3(vec3(*v, where));
        if (scale.x == 0.0 || scale.y == 0.0 || scale.z == 0.0) {
            fail(where, "expected a non-zero scale, got " + describe(*v));
        }
    }
    if (const Json* v = find(value, "rotate")) rotate = vec3(*v, child(pointer, "rotate"));
    if (const Json* v = find(value, "translate")) translate = vec3(*v, child(pointer, "translate"));
    // M = T · Rz · Ry · Rx · S: scale first, then rotate about x, y, z (degrees), then move.
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
    m = glm::rotate(m, glm::radians(rotate.z), glm::dvec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotate.y), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotate.x), glm::dvec3(1, 0, 0));
    return glm::scale(m, scale);
}

void SceneParser::parse_mesh(const Json& value, const std::string& pointer, SceneDescription& out,
                             std::vector<TriangleMesh>& meshes) {
    check_keys(value, pointer, {"type", "file", "material", "transform", "smooth"});
    const std::string file_pointer = child(pointer, "file");
    const std::string expected = std::string("a path to an ") + kMeshFileKinds + " file";
    const Json& file = require(value, pointer, "file", expected);
    if (!file.is_string() || file.get<std::string>().empty()) {
        fail(file_pointer, "expected " + expected + ", got " + describe(file));
    }
    const auto relative = file.get<std::string>();
    const std::string path = join_path(m_base_dir, relative);
    if (!is_mesh_file(path)) fail(file_pointer, "expected " + expected + ", got " + describe(file));
    require_input_file(path, m_source + "#" + file_pointer, "mesh file", kMaxMeshFileBytes,
                       m_access);
    const bool overridden = find(value, "material") != nullptr;
    const uint32_t override_id = material_of(value, pointer);
    MeshImportOptions options;
    options.where = m_source + "#" + file_pointer;
    options.access = m_access;
    if (const Json* t = find(value, "transform")) {
        options.transform = parse_transform(*t, child(pointer, "transform"));
        options.transform_where = m_source + "#" + child(pointer, "transform");
    }
    std::optional<bool> smooth;
    if (const Json* s = find(value, "smooth")) {
        if (!s->is_boolean())
            fail(child(pointer, "smooth"), "expected true or false, got " + describe(*s));
        smooth = s->get<bool>();
    }

    // With a material override the file's materials are read (and checked) but not kept.
    std::vector<Material> scratch = out.shading.materials;
    std::vector<Material>& materials = overridden ? scratch : out.shading.materials;
    ImportedMesh imported = import_mesh_file(path, materials, options);
    TriangleMesh& mesh = imported.mesh;
    if (overridden) std::fill(mesh.materials.begin(), mesh.materials.end(), override_id);
    if (overridden && mesh.uvs.empty() && out.shading.materials[override_id].images.any()) {
        fail(child(pointer, "material"),
             "material \"" + out.shading.materials[override_id].name +
                 "\" has an image texture but mesh '" + path +
                 "' has no texture coordinates (OBJ vt, glTF TEXCOORD_0)");
    }

    if (smooth.has_value()) {
        if (!*smooth) {
            mesh.normals.clear();  // flat: shade with the geometric normal
        } else if (mesh.normals.empty()) {
            compute_vertex_normals(mesh);
        }
    }
    out.warnings.insert(out.warnings.end(), imported.stats.warnings.begin(),
                        imported.stats.warnings.end());
    out.skipped_triangles += imported.stats.degenerate_triangles;
    meshes.push_back(std::move(mesh));
}

}  // namespace

SceneDescription load_json_string(const std::string& text, const std::string& source_name,
                                  const std::string& base_dir, const FileAccess& access) {
    const Json root = parse_text(text, source_name);
    return SceneParser(source_name, base_dir, access).parse(root);
}

SceneDescription load_json_file(const std::string& path, const FileAccess& access) {
    const std::string text = read_input_file(path, path, "scene file", kMaxSceneFileBytes);
    return load_json_string(text, path, parent_directory(path), access);
}

}  // namespace rayo
