// The scene file's lights follow from the registration (shading/light.h): every registered kind,
// in every form it declares (an area light's shapes), is read back from the JSON its own
// declaration writes (its form and its required fields) as the light it was written from, by
// describe(); a new kind is covered by adding it to the Light variant.
#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "apps/scene/json_loader.h"
#include "core/error.h"
#include "shading/light.h"

namespace rayo {
namespace {

using Json = nlohmann::json;

template <typename L, typename = void>
struct has_form : std::false_type {};
template <typename L>
struct has_form<L, std::void_t<decltype(std::declval<L&>().form(std::declval<int&>()))>>
    : std::true_type {};

// Writes a light's form and required fields as a scene file's light object; the optional ones
// keep their defaults by being left out.
struct RequiredFieldsWriter {
    Json& object;
    void operator()(const char* name, const Vec3& v, FieldKind) { object[name] = {v.x, v.y, v.z}; }
    void operator()(const char* name, float v, FieldKind) { object[name] = v; }
    template <typename T>
    void optional(const char*, const T&, FieldKind) {}
    template <typename E>
    void choice(const SettingInfo& info, const E& value, std::initializer_list<Choice<E>> choices) {
        object[info.name] = choice_name(choices, value);
    }
};

// Calls `take` once per choice of a form (the light's member set to it), then restores it.
struct EachForm {
    std::function<void()> take;
    template <typename E>
    void choice(const SettingInfo&, E& member, std::initializer_list<Choice<E>> choices) {
        const E saved = member;
        for (const Choice<E>& c : choices) {
            member = c.value;
            take();
        }
        member = saved;
    }
};

// The default light of kind L in each of its forms (itself when it has none).
template <typename L>
std::vector<L> every_form() {
    L light;
    std::vector<L> forms;
    if constexpr (has_form<L>::value) {
        EachForm each{[&] { forms.push_back(light); }};
        light.form(each);
    } else {
        forms.push_back(light);
    }
    return forms;
}

template <typename L>
std::string description(const L& light) {
    std::ostringstream text;
    text << L::kName;
    light.describe(text);
    return text.str();
}

TEST(LightRegistryScene, EveryKindInEveryFormIsReadFromItsDeclaration) {
    int kinds = 0, forms = 0;
    for_each_light([&](auto defaults) {
        using L = decltype(defaults);
        ++kinds;
        for (L light : every_form<L>()) {
            ++forms;
            Json object = {{"type", L::kName}};
            RequiredFieldsWriter writer{object};
            if constexpr (has_form<L>::value) light.form(writer);
            light.fields(writer);
            const Json scene = {{"rayo", 1}, {"lights", Json::array({object})}};
            SCOPED_TRACE(scene.dump());
            const SceneDescription d = load_json_string(scene.dump(), "scene.json", "");
            ASSERT_FALSE(d.shading.lights.empty());
            const L* read = std::get_if<L>(&d.shading.lights[0]);
            ASSERT_NE(read, nullptr);
            EXPECT_EQ(description(*read), description(light));
        }
    });
    EXPECT_EQ(kinds, static_cast<int>(std::variant_size_v<Light>));
    EXPECT_GT(forms, kinds);  // the area light's shapes
}

// The message of loading `light` as a scene's only light, and where it points.
std::pair<std::string, std::string> refusal(const std::string& light) {
    try {
        load_json_string(R"({"rayo": 1, "lights": [)" + light + "]}", "scene.json", "");
    } catch (const InputError& error) {
        return {error.where(), error.message()};
    }
    ADD_FAILURE() << "no InputError for " << light;
    return {};
}

TEST(LightRegistryScene, AnAreaLightsShapeIsRequiredAndDecidesItsKeys) {
    auto [where, message] = refusal(R"({"type": "area", "radius": 1})");
    EXPECT_EQ(where, "scene.json#/lights/0/shape");
    EXPECT_NE(message.find("missing required field \"shape\" (expected one of \"rectangle\", "
                           "\"disk\", \"sphere\")"),
              std::string::npos)
        << message;
    // A mesh is a form of the code (models' emissive triangles), not of the file.
    std::tie(where, message) = refusal(R"({"type": "area", "shape": "mesh"})");
    EXPECT_EQ(where, "scene.json#/lights/0/shape");
    EXPECT_NE(message.find("expected one of \"rectangle\", \"disk\", \"sphere\", got"),
              std::string::npos)
        << message;
    // A disk's normal is no key of a sphere, a sphere's centre none of a rectangle.
    std::tie(where, message) = refusal(
        R"({"type": "area", "shape": "sphere", "center": [0, 0, 0], "radius": 1,
            "normal": [0, 1, 0]})");
    EXPECT_EQ(where, "scene.json#/lights/0/normal");
    EXPECT_NE(message.find("unknown key \"normal\""), std::string::npos) << message;
    std::tie(where, message) = refusal(
        R"({"type": "area", "shape": "rectangle", "corner": [0, 0, 0], "edge1": [1, 0, 0],
            "edge2": [0, 0, 1], "center": [0, 0, 0]})");
    EXPECT_EQ(where, "scene.json#/lights/0/center");
    // A radius whose area underflows a float is refused, not a light that never lights.
    std::tie(where, message) =
        refusal(R"({"type": "area", "shape": "sphere", "center": [0, 0, 0], "radius": 1e-30})");
    EXPECT_EQ(where, "scene.json#/lights/0/radius");
    EXPECT_NE(message.find("area"), std::string::npos) << message;
    // The bound of "samples" is the area light's own (kMaxAreaLightSamples).
    std::tie(where, message) = refusal(R"({"type": "area", "shape": "sphere",
        "center": [0, 0, 0], "radius": 1, "samples": )" +
                                       std::to_string(kMaxAreaLightSamples + 1) + "}");
    EXPECT_EQ(where, "scene.json#/lights/0/samples");
    EXPECT_NE(message.find("[1, " + std::to_string(kMaxAreaLightSamples) + "]"), std::string::npos)
        << message;
}

}  // namespace
}  // namespace rayo
