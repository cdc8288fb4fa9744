// compression.cpp — EXT_meshopt_compression and KHR_draco_mesh_compression undone into plain buffers.
#include "core/gltf/compression.h"

#include "core/gltf/data_uri.h"
#include "core/io/safe_text.h"

#ifdef LAB_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif
#include "core/gltf/draco_decoder.h"

#include <cmath>
#include <cstring>
#include <optional>

namespace lab::gltf_detail {

bool meshoptSupported() {
#ifdef LAB_HAVE_MESHOPT
    return true;
#else
    return false;
#endif
}

bool dracoSupported() { return true; } // linked, or fetched by the page when a model needs it (draco_decoder.h)

// A placeholder for tinygltf: the bytes are the loader's (see gltf_glb.h for the same trick).
std::size_t ModelBuffers::add(nlohmann::json& doc, std::vector<unsigned char> data) {
    owned.push_back(std::move(data));
    bytes.push_back({owned.back().data(), owned.back().size()});
    if (!doc.contains("buffers") || !doc["buffers"].is_array()) {
        doc["buffers"] = nlohmann::json::array();
    }
    doc["buffers"].push_back({{"uri", kDecodedPlaceholder}, {"byteLength", 1}});
    return bytes.size() - 1;
}

namespace {

// The member `key` of `object` as an unsigned integer: `fallback` when absent, nullopt when
// present but not one.
[[maybe_unused]] std::optional<std::uint64_t> unsignedField(const nlohmann::json& object, const char* key,
                                           std::optional<std::uint64_t> fallback = std::nullopt) {
    auto it = object.find(key);
    if (it == object.end()) {
        return fallback;
    }
    return it->is_number_unsigned() ? std::optional<std::uint64_t>(it->get<std::uint64_t>()) : std::nullopt;
}

// The object at doc[list][i].extensions[name], or nullptr.
[[maybe_unused]] nlohmann::json* extensionOf(nlohmann::json& object, const char* name) {
    auto extensions = object.find("extensions");
    if (extensions == object.end() || !extensions->is_object()) {
        return nullptr;
    }
    auto ext = extensions->find(name);
    return ext != extensions->end() && ext->is_object() ? &*ext : nullptr;
}

[[maybe_unused]] void eraseExtension(nlohmann::json& object, const char* name) {
    nlohmann::json& extensions = object["extensions"];
    extensions.erase(name);
    if (extensions.empty()) {
        object.erase("extensions");
    }
}

// bytes [offset, offset + length) of buffer `index`, when they exist.
[[maybe_unused]] std::optional<BufferBytes> range(const ModelBuffers& buffers, std::uint64_t index, std::uint64_t offset,
                                 std::uint64_t length) {
    if (index >= buffers.bytes.size()) {
        return std::nullopt;
    }
    const BufferBytes& b = buffers.bytes[index];
    if (offset > b.size || length > b.size - offset) {
        return std::nullopt;
    }
    return BufferBytes{b.data + offset, static_cast<std::size_t>(length)};
}

[[maybe_unused]] bool fail(Diagnostics& diagnostics, const std::string& file, const std::string& where, const std::string& message) {
    diagnostics.push_back({file, where, message});
    return false;
}

#ifdef LAB_HAVE_MESHOPT
// A meshopt view's mode, byteStride, count and filter, as the library expects them together.
// False after a diagnostic.
bool meshoptFieldsFit(const std::string& mode, const std::string& filter, std::size_t stride, std::uint64_t count,
                      const std::string& file, const std::string& where, Diagnostics& diagnostics) {
    if (mode == "ATTRIBUTES") {
        if (stride == 0 || stride > 252 || stride % 4 != 0) { // 252: glTF's largest bufferView byteStride
            return fail(diagnostics, file, where + ".byteStride", std::to_string(stride) + ": vertex data needs a multiple of 4 up to 252");
        }
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) {
            return fail(diagnostics, file, where + ".byteStride", std::to_string(stride) + ": indices are 2 or 4 bytes");
        }
        if (mode == "TRIANGLES" && count % 3 != 0) {
            return fail(diagnostics, file, where + ".count", std::to_string(count) + " is not a multiple of 3 (mode TRIANGLES)");
        }
    } else {
        return fail(diagnostics, file, where + ".mode", inQuotes(mode) + " is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (filter != "NONE" && (mode != "ATTRIBUTES" || (filter == "OCTAHEDRAL" && stride != 4 && stride != 8) ||
                              (filter == "QUATERNION" && stride != 8) ||
                              (filter != "OCTAHEDRAL" && filter != "QUATERNION" && filter != "EXPONENTIAL"))) {
        return fail(diagnostics, file, where + ".filter", inQuotes(filter) + " does not fit mode " + mode + " and byteStride " + std::to_string(stride));
    }
    return true;
}

// One EXT_meshopt_compression bufferView decoded; its fields checked first (the library asserts
// on what it does not expect). Nullopt after a diagnostic.
std::optional<std::vector<unsigned char>> decodeMeshoptView(const nlohmann::json& ext, const ModelBuffers& buffers,
                                                            const DecodeLimits& limits, const std::string& file,
                                                            const std::string& where, Diagnostics& diagnostics,
                                                            bool& attributes, std::size_t& stride) {
    auto buffer = unsignedField(ext, "buffer"), offset = unsignedField(ext, "byteOffset", 0),
         length = unsignedField(ext, "byteLength"), byteStride = unsignedField(ext, "byteStride"),
         count = unsignedField(ext, "count");
    auto text = [&](const char* key, const char* fallback) -> std::optional<std::string> {
        auto it = ext.find(key);
        if (it == ext.end()) {
            return fallback ? std::optional<std::string>(fallback) : std::nullopt;
        }
        return it->is_string() ? std::optional<std::string>(it->get<std::string>()) : std::nullopt;
    };
    std::optional<std::string> mode = text("mode", nullptr), filter = text("filter", "NONE");
    for (auto [value, key] : {std::pair{buffer.has_value(), "buffer"}, {offset.has_value(), "byteOffset"},
                              {length.has_value(), "byteLength"}, {byteStride.has_value(), "byteStride"},
                              {count.has_value(), "count"}, {mode.has_value(), "mode"}, {filter.has_value(), "filter"}}) {
        if (!value) {
            fail(diagnostics, file, where + "." + key, "missing or of the wrong type");
            return std::nullopt;
        }
    }
    std::optional<BufferBytes> source = range(buffers, *buffer, *offset, *length);
    if (!source) {
        fail(diagnostics, file, where, "bytes [" + std::to_string(*offset) + ", +" + std::to_string(*length) +
                                           ") of buffer " + std::to_string(*buffer) + " do not exist");
        return std::nullopt;
    }
    stride = static_cast<std::size_t>(*byteStride);
    attributes = *mode == "ATTRIBUTES";
    if (!meshoptFieldsFit(*mode, *filter, stride, *count, file, where, diagnostics)) {
        return std::nullopt;
    }
    std::uint64_t size = 0;
    if (*count == 0 || __builtin_mul_overflow(*count, stride, &size) ||
        size > limits.maxDecodedBytes - std::min(limits.maxDecodedBytes, buffers.decoded)) {
        fail(diagnostics, file, where + ".count", std::to_string(*count) + " elements of " + std::to_string(stride) +
                                                      " bytes: more than the " + std::to_string(limits.maxDecodedBytes) +
                                                      " bytes the lab decodes for a file, all views together");
        return std::nullopt;
    }
    std::vector<unsigned char> out(static_cast<std::size_t>(size));
    const auto n = static_cast<std::size_t>(*count);
    int rc = attributes           ? meshopt_decodeVertexBuffer(out.data(), n, stride, source->data, source->size)
             : *mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), n, stride, source->data, source->size)
                                    : meshopt_decodeIndexSequence(out.data(), n, stride, source->data, source->size);
    if (rc != 0) {
        fail(diagnostics, file, where, "the meshopt-compressed data does not decode (error " + std::to_string(rc) +
                                           "): corrupt, or not " + std::to_string(*count) + " elements of " + std::to_string(stride) + " bytes");
        return std::nullopt;
    }
    if (*filter == "OCTAHEDRAL") {
        meshopt_decodeFilterOct(out.data(), n, stride);
    } else if (*filter == "QUATERNION") {
        meshopt_decodeFilterQuat(out.data(), n, stride);
    } else if (*filter == "EXPONENTIAL") {
        meshopt_decodeFilterExp(out.data(), n, stride);
    }
    return out;
}
#endif

} // namespace

bool decodeMeshopt(nlohmann::json& doc, ModelBuffers& buffers, const DecodeLimits& limits,
                   const std::string& displayName, Diagnostics& diagnostics) {
#ifdef LAB_HAVE_MESHOPT
    auto views = doc.find("bufferViews");
    if (views == doc.end() || !views->is_array()) {
        return true;
    }
    for (std::size_t i = 0; i < views->size(); ++i) {
        if (!(*views)[i].is_object()) {
            continue;
        }
        nlohmann::json* ext = extensionOf((*views)[i], "EXT_meshopt_compression");
        if (!ext) {
            continue;
        }
        const std::string where = "bufferViews[" + std::to_string(i) + "].extensions.EXT_meshopt_compression";
        bool attributes = false;
        std::size_t stride = 0;
        std::optional<std::vector<unsigned char>> decoded =
            decodeMeshoptView(*ext, buffers, limits, displayName, where, diagnostics, attributes, stride);
        if (!decoded) {
            return false;
        }
        const std::size_t size = decoded->size();
        buffers.decoded += size;
        const std::size_t index = buffers.add(doc, std::move(*decoded));
        nlohmann::json& view = (*views)[i];
        view["buffer"] = index;
        view["byteOffset"] = 0;
        view["byteLength"] = size;
        if (attributes) {
            view["byteStride"] = stride;
        } else {
            view.erase("byteStride");
        }
        eraseExtension(view, "EXT_meshopt_compression");
    }
#else
    (void)doc, (void)buffers, (void)limits, (void)displayName, (void)diagnostics;
#endif
    return true;
}

namespace {

// Where a Draco primitive's diagnostics point, and the file they name.
struct DracoSite {
    const std::string& file;
    std::string where; // "meshes[i].primitives[j].extensions.KHR_draco_mesh_compression"
    Diagnostics& diagnostics;
    bool fail(const std::string& message, const std::string& key = "") const {
        return gltf_detail::fail(diagnostics, file, where + key, message);
    }
};

// What the decoder is asked: which of POSITION and NORMAL the extension lists (with their ids)
// and the primitive uses, and the limits left for this file.
DracoQuery dracoQuery(const nlohmann::json& attributeIds, const nlohmann::json& prim, const ModelBuffers& buffers,
                      const DecodeLimits& limits) {
    auto attribute = [&](const char* name) {
        DracoAttributeQuery q;
        auto id = attributeIds.find(name);
        q.listed = id != attributeIds.end();
        if (q.listed && id->is_number_unsigned() && id->get<std::uint64_t>() <= 0xFFFFFFFFu) {
            q.id = static_cast<std::int64_t>(id->get<std::uint64_t>());
        }
        q.used = prim.contains("attributes") && prim["attributes"].is_object() && prim["attributes"].contains(name);
        return q;
    };
    DracoQuery query;
    query.position = attribute("POSITION");
    query.normal = attribute("NORMAL");
    query.maxPoints = limits.maxVertices;
    query.maxFaces = limits.maxTriangles;
    query.maxBytes = limits.maxDecodedBytes - std::min(limits.maxDecodedBytes, buffers.decoded);
    return query;
}

// One primitive's KHR_draco_mesh_compression decoded into a new buffer, a view and an accessor
// for each attribute it uses and for the indices; the extension removed. False after a diagnostic.
bool decodeDracoPrimitive(nlohmann::json& doc, nlohmann::json& prim, const nlohmann::json& ext, ModelBuffers& buffers,
                          const DecodeLimits& limits, const DracoSite& site) {
    auto views = doc.find("bufferViews");
    std::optional<std::uint64_t> viewIndex = unsignedField(ext, "bufferView");
    if (!viewIndex || views == doc.end() || !views->is_array() || *viewIndex >= views->size() ||
        !(*views)[*viewIndex].is_object()) {
        return site.fail("missing, or no such bufferView", ".bufferView");
    }
    const nlohmann::json& view = (*views)[*viewIndex];
    auto buffer = unsignedField(view, "buffer"), offset = unsignedField(view, "byteOffset", 0),
         length = unsignedField(view, "byteLength");
    std::optional<BufferBytes> source = buffer && offset && length ? range(buffers, *buffer, *offset, *length) : std::nullopt;
    if (!source) {
        return fail(site.diagnostics, site.file, "bufferViews[" + std::to_string(*viewIndex) + "]",
                    "its byte range does not lie inside its buffer");
    }
    auto attributeIds = ext.find("attributes");
    if (attributeIds == ext.end() || !attributeIds->is_object()) {
        return site.fail("missing or not an object", ".attributes");
    }
    DracoResult result = runDracoDecoder(source->data, source->size, dracoQuery(*attributeIds, prim, buffers, limits));
    if (const auto* failure = std::get_if<DracoFailure>(&result)) {
        return site.fail(shortened(failure->message, 1100), failure->where);
    }
    const DracoMesh& decoded = std::get<DracoMesh>(result);
    // The accessors' own counts are not checked against what was decoded: the new accessors
    // below take the decoded counts (Draco may split or merge points; readers such as
    // three.js go by the decoded data too).
    const std::size_t points = decoded.points, faces = decoded.faces;
    std::vector<unsigned char> data;
    nlohmann::json newAttributes = nlohmann::json::object();
    auto append = [&data](const void* values, std::size_t bytes) {
        const std::size_t at = data.size();
        data.resize(at + bytes);
        std::memcpy(data.data() + at, values, bytes);
        return at;
    };
    if (!decoded.positions.empty()) {
        newAttributes["POSITION"] = append(decoded.positions.data(), points * 12);
    }
    if (!decoded.normals.empty()) {
        newAttributes["NORMAL"] = append(decoded.normals.data(), points * 12);
    }
    const std::size_t indicesAt = append(decoded.indices.data(), faces * 12);
    // The decoded arrays as one new buffer, a view and an accessor each.
    buffers.decoded += data.size();
    const std::size_t bufferIndex = buffers.add(doc, std::move(data));
    nlohmann::json& accessors = doc["accessors"];
    auto addAccessor = [&](std::size_t byteOffset, std::size_t byteLength, std::size_t count, int componentType,
                           const char* type) {
        views->push_back({{"buffer", bufferIndex}, {"byteOffset", byteOffset}, {"byteLength", byteLength}});
        if (!accessors.is_array()) {
            accessors = nlohmann::json::array();
        }
        accessors.push_back({{"bufferView", views->size() - 1}, {"componentType", componentType},
                             {"count", count}, {"type", type}});
        return accessors.size() - 1;
    };
    for (auto& [name, at] : newAttributes.items()) {
        prim["attributes"][name] = addAccessor(at.get<std::size_t>(), points * 12, points, 5126, "VEC3");
    }
    prim["indices"] = addAccessor(indicesAt, faces * 12, faces * 3, 5125, "SCALAR");
    prim["mode"] = 4; // Draco decodes triangles, whatever mode the primitive named
    eraseExtension(prim, "KHR_draco_mesh_compression");
    return true;
}

} // namespace

bool decodeDraco(nlohmann::json& doc, ModelBuffers& buffers, const DecodeLimits& limits, const std::string& displayName,
                 Diagnostics& diagnostics) {
    auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array()) {
        return true;
    }
    for (std::size_t mi = 0; mi < meshes->size(); ++mi) {
        nlohmann::json& mesh = (*meshes)[mi];
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) {
            continue;
        }
        for (std::size_t pi = 0; pi < mesh["primitives"].size(); ++pi) {
            nlohmann::json& prim = mesh["primitives"][pi];
            nlohmann::json* ext = prim.is_object() ? extensionOf(prim, "KHR_draco_mesh_compression") : nullptr;
            if (!ext) {
                continue;
            }
            const DracoSite site{displayName,
                                 "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) +
                                     "].extensions.KHR_draco_mesh_compression",
                                 diagnostics};
            if (!decodeDracoPrimitive(doc, prim, *ext, buffers, limits, site)) {
                return false;
            }
        }
    }
    return true;
}

} // namespace lab::gltf_detail
