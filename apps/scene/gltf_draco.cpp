#include "apps/scene/gltf_draco.h"

#include <draco/compression/decode.h>
#include <tiny_gltf.h>

#include <cstring>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/error.h"

namespace rayo {
namespace {

// Index `i` of `items`, or an InputError naming what it indexes.
template <typename T>
T& at(std::vector<T>& items, int i, const std::string& path, const std::string& what) {
    if (i < 0 || static_cast<size_t>(i) >= items.size()) {
        throw InputError(path, what + " " + std::to_string(i) + " does not exist");
    }
    return items[static_cast<size_t>(i)];
}

std::unique_ptr<draco::Mesh> decode(tinygltf::Model& model, int view_index, const std::string& path,
                                    const std::string& what) {
    const tinygltf::BufferView& view =
        at(model.bufferViews, view_index, path, what + ": bufferView");
    const tinygltf::Buffer& buffer = at(model.buffers, view.buffer, path, what + ": buffer");
    if (view.byteOffset > buffer.data.size() ||
        view.byteLength > buffer.data.size() - view.byteOffset) {
        throw InputError(path, what + ": the Draco bufferView exceeds its buffer");
    }
    draco::DecoderBuffer bytes;
    bytes.Init(reinterpret_cast<const char*>(buffer.data.data() + view.byteOffset),
               view.byteLength);
    const auto type = draco::Decoder::GetEncodedGeometryType(&bytes);
    if (!type.ok()) {
        throw InputError(path,
                         what + ": not Draco data (" + type.status().error_msg_string() + ")");
    }
    if (type.value() != draco::TRIANGULAR_MESH) {
        throw InputError(path, what + ": the Draco data is a point cloud, not a triangle mesh");
    }
    draco::Decoder decoder;
    auto mesh = decoder.DecodeMeshFromBuffer(&bytes);
    if (!mesh.ok()) {
        throw InputError(path, what + ": Draco cannot decode the data (" +
                                   mesh.status().error_msg_string() + ")");
    }
    return std::move(mesh).value();
}

// A new buffer holding `bytes`, its bufferView and an accessor like `like` reading it.
int add_accessor(tinygltf::Model& model, std::vector<unsigned char> bytes, tinygltf::Accessor like,
                 size_t count) {
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteLength = bytes.size();
    model.buffers.emplace_back();
    model.buffers.back().data = std::move(bytes);
    like.bufferView = static_cast<int>(model.bufferViews.size());
    model.bufferViews.push_back(view);
    like.byteOffset = 0;
    like.count = count;
    like.sparse = {};
    like.minValues.clear();
    like.maxValues.clear();
    model.accessors.push_back(like);
    return static_cast<int>(model.accessors.size() - 1);
}

template <typename T>
std::vector<unsigned char> convert(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                                   int components, bool& ok) {
    std::vector<unsigned char> out(mesh.num_points() * components * sizeof(T));
    T value[4] = {};
    for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
        ok = ok && attribute.ConvertValue<T>(attribute.mapped_index(i),
                                             static_cast<int8_t>(components), value);
        std::memcpy(out.data() + i.value() * components * sizeof(T), value, components * sizeof(T));
    }
    return out;
}

// The attribute's values for every point, in the accessor's component type.
std::vector<unsigned char> attribute_bytes(const draco::Mesh& mesh,
                                           const draco::PointAttribute& attribute,
                                           const tinygltf::Accessor& accessor,
                                           const std::string& path, const std::string& what) {
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
    if (components < 1 || components > 4 || attribute.num_components() != components) {
        throw InputError(path, what + ": the Draco attribute has " +
                                   std::to_string(attribute.num_components()) +
                                   " components, its accessor " + std::to_string(components));
    }
    bool ok = true;
    std::vector<unsigned char> bytes;
    switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            bytes = convert<float>(mesh, attribute, components, ok);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            bytes = convert<uint8_t>(mesh, attribute, components, ok);
            break;
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            bytes = convert<int8_t>(mesh, attribute, components, ok);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            bytes = convert<uint16_t>(mesh, attribute, components, ok);
            break;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            bytes = convert<int16_t>(mesh, attribute, components, ok);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            bytes = convert<uint32_t>(mesh, attribute, components, ok);
            break;
        default:
            throw InputError(path, what + ": unsupported component type " +
                                       std::to_string(accessor.componentType));
    }
    if (!ok) throw InputError(path, what + ": Draco cannot convert the attribute's values");
    return bytes;
}

}  // namespace

bool strip_draco_indices(nlohmann::json& root) {
    bool any = false;
    const auto meshes = root.find("meshes");
    if (meshes == root.end() || !meshes->is_array()) return false;
    for (auto& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) {
            continue;
        }
        for (auto& primitive : mesh["primitives"]) {
            if (!primitive.is_object()) continue;
            const auto extensions = primitive.find("extensions");
            if (extensions == primitive.end() || !extensions->is_object() ||
                !extensions->contains(kDracoExtension)) {
                continue;
            }
            primitive.erase("indices");
            any = true;
        }
    }
    return any;
}

void decode_draco_primitives(tinygltf::Model& model, const std::string& path) {
    std::map<int, std::unique_ptr<draco::Mesh>> decoded;  // by bufferView: decoded once
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            const auto found = primitive.extensions.find(kDracoExtension);
            if (found == primitive.extensions.end()) continue;
            const std::string what = "mesh " + std::to_string(m) + " primitive " +
                                     std::to_string(p) + " (" + kDracoExtension + ")";
            const tinygltf::Value& extension = found->second;
            const tinygltf::Value& view = extension.Get("bufferView");
            const tinygltf::Value& attributes = extension.Get("attributes");
            if (!view.IsInt() || !attributes.IsObject()) {
                throw InputError(path, what +
                                           ": expected an integer bufferView and an object of "
                                           "attributes");
            }
            auto& mesh = decoded[view.Get<int>()];
            if (!mesh) mesh = decode(model, view.Get<int>(), path, what);

            std::vector<unsigned char> indices(mesh->num_faces() * 3 * sizeof(uint32_t));
            for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
                for (int k = 0; k < 3; ++k) {
                    const uint32_t index = mesh->face(f)[k].value();
                    if (index >= mesh->num_points()) {
                        throw InputError(
                            path, what + ": index " + std::to_string(index) + " out of range");
                    }
                    std::memcpy(indices.data() + (3 * f.value() + k) * sizeof index, &index,
                                sizeof index);
                }
            }
            tinygltf::Accessor scalar;
            scalar.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
            scalar.type = TINYGLTF_TYPE_SCALAR;
            primitive.indices =
                add_accessor(model, std::move(indices), scalar, mesh->num_faces() * 3);

            for (const std::string& name : attributes.Keys()) {
                const std::string attribute_what = what + " " + name;
                const tinygltf::Value& id = attributes.Get(name);
                const auto slot = primitive.attributes.find(name);
                if (!id.IsInt() || slot == primitive.attributes.end()) {
                    throw InputError(path, attribute_what +
                                               ": expected an integer Draco attribute id of an "
                                               "attribute the primitive has");
                }
                const draco::PointAttribute* attribute =
                    mesh->GetAttributeByUniqueId(static_cast<uint32_t>(id.Get<int>()));
                if (attribute == nullptr) {
                    throw InputError(path, attribute_what + ": the Draco data has no attribute " +
                                               std::to_string(id.Get<int>()));
                }
                const tinygltf::Accessor like =
                    at(model.accessors, slot->second, path, attribute_what + ": accessor");
                slot->second = add_accessor(
                    model, attribute_bytes(*mesh, *attribute, like, path, attribute_what), like,
                    mesh->num_points());
            }
        }
    }
}

}  // namespace rayo
