#pragma once
// The glTF files the scene tests write: one document and its binary buffer, filled accessor by
// accessor (each in its own bufferView, 4-byte aligned), written as a .gltf with a data-URI
// buffer, a .gltf beside an external .bin, or a .glb. Meshes, nodes, materials, textures and
// images are plain JSON through doc(); so are deliberate corruptions of the accessors.
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/scene/scene_test_files.h"

namespace rayo_test {

class GltfTestWriter {
  public:
    using Json = nlohmann::json;

    // glTF 2.0 with scene 0, whose root nodes node() adds.
    GltfTestWriter()
        : m_doc({{"asset", {{"version", "2.0"}}},
                 {"scene", 0},
                 {"scenes", Json::array({Json{{"nodes", Json::array()}}})}}) {}

    Json& doc() { return m_doc; }
    const Json& doc() const { return m_doc; }
    std::vector<uint8_t>& bin() { return m_bin; }

    // `bytes` appended to the buffer (then padded to 4 bytes) as a new bufferView; its index.
    int view(const void* data, size_t bytes) {
        const size_t offset = m_bin.size();
        const auto* p = static_cast<const uint8_t*>(data);
        m_bin.insert(m_bin.end(), p, p + bytes);
        while (m_bin.size() % 4 != 0) m_bin.push_back(0);
        return push("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    }
    // An accessor of `count` elements of `type` ("SCALAR", "VEC2", ...) with the component type
    // `component` (5121 unsigned byte, 5123 unsigned short, 5125 unsigned int, 5126 float) over
    // a new bufferView of `bytes`; its index.
    int accessor(const void* data, size_t bytes, int component, size_t count, const char* type) {
        return push("accessors", {{"bufferView", view(data, bytes)},
                                  {"componentType", component},
                                  {"count", count},
                                  {"type", type}});
    }
    // Floats as `type` ("SCALAR" or "VECn"): count = values / n.
    int accessor(const std::vector<float>& values, const char* type) {
        const size_t components = std::string(type) == "SCALAR" ? 1 : size_t(type[3] - '0');
        return accessor(values.data(), values.size() * sizeof(float), 5126,
                        values.size() / components, type);
    }
    // POSITION: VEC3 floats with the min and max glTF requires.
    int positions(const std::vector<float>& xyz) {
        const int a = accessor(xyz, "VEC3");
        Json lo = Json::array(), hi = Json::array();
        for (size_t c = 0; c < 3; ++c) {
            float l = xyz[c], h = xyz[c];
            for (size_t i = c; i < xyz.size(); i += 3)
                l = std::min(l, xyz[i]), h = std::max(h, xyz[i]);
            lo.push_back(l);
            hi.push_back(h);
        }
        m_doc["accessors"][a]["min"] = lo;
        m_doc["accessors"][a]["max"] = hi;
        return a;
    }
    // Triangle indices stored as `component` (5121, 5123 or 5125).
    int indices(const std::vector<uint32_t>& values, int component = 5123) {
        if (component == 5121) return narrowed<uint8_t>(values, component);
        if (component == 5123) return narrowed<uint16_t>(values, component);
        return accessor(values.data(), values.size() * 4, component, values.size(), "SCALAR");
    }

    // Appends `value` to the top-level array `key`; its index.
    int push(const char* key, Json value) {
        m_doc[key].push_back(std::move(value));
        return static_cast<int>(m_doc[key].size()) - 1;
    }
    // A mesh of one primitive; its index.
    int mesh(const Json& primitive) {
        return push("meshes", {{"primitives", Json::array({primitive})}});
    }
    // A node, a root of scene 0 unless `root` is false; its index.
    int node(Json n, bool root = true) {
        const int index = push("nodes", std::move(n));
        if (root) m_doc["scenes"][0]["nodes"].push_back(index);
        return index;
    }

    // The .gltf with the buffer as a data URI, at `path`.
    std::string write_embedded(const std::string& path) const {
        Json doc = m_doc;
        doc["buffers"] = {{{"byteLength", m_bin.size()},
                           {"uri", "data:application/octet-stream;base64," + base64(m_bin)}}};
        std::ofstream(path, std::ios::binary) << doc.dump();
        return path;
    }
    std::string write_embedded(const TempDir& dir, const std::string& name) const {
        return write_embedded(dir.file(name));
    }
    // The .gltf `name` and its buffer beside it as the file `bin_name`.
    std::string write_external(const TempDir& dir, const std::string& name,
                               const std::string& bin_name) const {
        dir.write(bin_name, std::string(m_bin.begin(), m_bin.end()));
        Json doc = m_doc;
        doc["buffers"] = {{{"byteLength", m_bin.size()}, {"uri", bin_name}}};
        return dir.write(name, doc.dump());
    }
    // The binary glTF: a JSON chunk and a BIN chunk, each padded to 4 bytes.
    std::string write_glb(const TempDir& dir, const std::string& name) const {
        return write_glb(dir.file(name));
    }
    // The same at `path`.
    std::string write_glb(const std::string& path) const {
        Json doc = m_doc;
        doc["buffers"] = {{{"byteLength", m_bin.size()}}};
        std::string json = doc.dump();
        while (json.size() % 4 != 0) json += ' ';
        std::string out;
        auto u32 = [&out](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
        out += "glTF";
        u32(2);
        u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + m_bin.size()));
        u32(static_cast<uint32_t>(json.size()));
        u32(0x4E4F534Au);  // "JSON"
        out += json;
        u32(static_cast<uint32_t>(m_bin.size()));
        u32(0x004E4942u);  // "BIN\0"
        out.append(reinterpret_cast<const char*>(m_bin.data()), m_bin.size());
        std::ofstream(path, std::ios::binary) << out;
        return path;
    }

  private:
    template <typename T>
    int narrowed(const std::vector<uint32_t>& values, int component) {
        const std::vector<T> v(values.begin(), values.end());
        return accessor(v.data(), v.size() * sizeof(T), component, v.size(), "SCALAR");
    }

    Json m_doc;
    std::vector<uint8_t> m_bin;
};

}  // namespace rayo_test
