#pragma once
// Storage for a list of shape types: one std::vector per type, addressed by type
// (`shapes.of<Sphere>()`), and visited in registry order by generic code (accel, validation,
// loaders, `rayo info`) so that none of them names a shape type.
#include <cstddef>
#include <cstdint>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace rayo {

template <typename... Shapes>
struct ShapeList {
    static constexpr size_t kCount = sizeof...(Shapes);
};

template <typename T, typename... Ts>
constexpr size_t index_in_pack() {
    constexpr bool matches[] = {std::is_same_v<T, Ts>...};
    for (size_t i = 0; i < sizeof...(Ts); ++i) {
        if (matches[i]) return i;
    }
    return sizeof...(Ts);
}

// The shape type of a vector that ShapeSet::for_each hands out: ShapeOf<decltype(shapes)>.
template <typename Vector>
using ShapeOf = typename std::decay_t<Vector>::value_type;

template <typename List>
class ShapeSet;

template <typename... Shapes>
class ShapeSet<ShapeList<Shapes...>> {
  public:
    // The type's index in the list (SurfaceHit::shape).
    template <typename S>
    static constexpr uint32_t index_of() {
        constexpr size_t i = index_in_pack<S, Shapes...>();
        static_assert(i < sizeof...(Shapes), "not a registered shape (core/shapes/registry.h)");
        return static_cast<uint32_t>(i);
    }

    template <typename S>
    std::vector<S>& of() {
        return std::get<index_of<S>()>(m_shapes);
    }
    template <typename S>
    const std::vector<S>& of() const {
        return std::get<index_of<S>()>(m_shapes);
    }

    // f(std::vector<S>&) for each registered type S, in registry order.
    template <typename F>
    void for_each(F&& f) {
        std::apply([&](auto&... vectors) { (f(vectors), ...); }, m_shapes);
    }
    template <typename F>
    void for_each(F&& f) const {
        std::apply([&](const auto&... vectors) { (f(vectors), ...); }, m_shapes);
    }

    // The scene-file names of the registered types (S::kName), in registry order.
    static std::vector<std::string> names() { return {Shapes::kName...}; }

    size_t size() const {
        size_t n = 0;
        for_each([&](const auto& v) { n += v.size(); });
        return n;
    }

  private:
    std::tuple<std::vector<Shapes>...> m_shapes;
};

}  // namespace rayo
