// extensions.cpp — the glTF version and extensionsRequired, checked first.
#include "core/gltf/extensions.h"

#include "core/gltf/compression.h"
#include "core/io/safe_text.h"

#include <array>

namespace lab::gltf_detail {

namespace {

// Required extensions that only add data the lab does not draw: materials and textures (the
// preset's material is used), texture formats and transforms, lights and metadata.
constexpr std::array<std::string_view, 11> kIgnored = {
    "KHR_texture_transform", "KHR_texture_basisu", "EXT_texture_webp", "EXT_texture_avif", "MSFT_texture_dds",
    "KHR_lights_punctual",   "KHR_xmp_json_ld",    "KHR_xmp",          "KHR_materials_variants",
    "KHR_techniques_webgl",  "EXT_lights_image_based"};

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// The leading "major.minor" of a version string; nullopt when it is not one.
std::optional<std::pair<int, int>> version(const std::string& text) {
    int major = 0, minor = 0;
    std::size_t i = 0;
    auto digits = [&](int& out) {
        const std::size_t start = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9' && i - start < 6) {
            out = out * 10 + (text[i++] - '0');
        }
        return i > start;
    };
    if (!digits(major) || i >= text.size() || text[i++] != '.' || !digits(minor)) {
        return std::nullopt;
    }
    return std::pair{major, minor};
}

} // namespace

ExtensionSupport extensionSupport(std::string_view name) {
    if (name == "KHR_mesh_quantization" || name == "EXT_mesh_gpu_instancing") {
        return ExtensionSupport::Decoded;
    }
    if (name == "KHR_draco_mesh_compression") {
        return dracoSupported() ? ExtensionSupport::Decoded : ExtensionSupport::NotInThisBuild;
    }
    if (name == "EXT_meshopt_compression") {
        return meshoptSupported() ? ExtensionSupport::Decoded : ExtensionSupport::NotInThisBuild;
    }
    if (startsWith(name, "KHR_materials_") || startsWith(name, "EXT_materials_")) {
        return ExtensionSupport::Ignored;
    }
    for (std::string_view ignored : kIgnored) {
        if (name == ignored) {
            return ExtensionSupport::Ignored;
        }
    }
    return ExtensionSupport::Unknown;
}

bool checkVersionAndExtensions(const nlohmann::json& doc, const std::string& displayName, Diagnostics& diagnostics,
                               std::vector<std::string>& notes) {
    const char* convert = "; the lab reads glTF 2.0: export or convert the model to glTF 2.0";
    auto asset = doc.find("asset");
    // glTF 1.0 kept scenes, meshes and the rest as objects keyed by name; 2.0 has arrays.
    const bool looksLike1 = (doc.contains("scenes") && doc["scenes"].is_object()) ||
                            (doc.contains("meshes") && doc["meshes"].is_object());
    const nlohmann::json* versionText =
        asset != doc.end() && asset->is_object() && asset->contains("version") ? &(*asset)["version"] : nullptr;
    std::optional<std::pair<int, int>> v =
        versionText && versionText->is_string() ? version(versionText->get<std::string>()) : std::nullopt;
    if ((v && v->first == 1) || (!v && looksLike1)) {
        diagnostics.push_back({displayName, "", std::string("a glTF 1.0 file") + convert});
        return false;
    }
    if (v && v->first != 2) {
        diagnostics.push_back({displayName, "asset.version",
                               inQuotes(versionText->get<std::string>()) + " is not a glTF version the lab reads (2.0)"});
        return false;
    }
    if (asset != doc.end() && asset->is_object() && asset->contains("minVersion") && (*asset)["minVersion"].is_string()) {
        std::optional<std::pair<int, int>> min = version((*asset)["minVersion"].get<std::string>());
        if (min && (min->first != 2 || min->second > 0)) {
            diagnostics.push_back({displayName, "asset.minVersion",
                                   "the file needs glTF " + inQuotes((*asset)["minVersion"].get<std::string>()) +
                                       "; the lab reads glTF 2.0"});
            return false;
        }
    }
    auto required = doc.find("extensionsRequired");
    if (required == doc.end() || !required->is_array()) {
        return true;
    }
    std::string ignored;
    for (const nlohmann::json& item : *required) {
        if (!item.is_string()) {
            continue; // tinygltf refuses it in its own words
        }
        const std::string name = item.get<std::string>();
        switch (extensionSupport(name)) {
        case ExtensionSupport::Decoded: break;
        case ExtensionSupport::Ignored:
            if (ignored.find(inQuotes(name)) == std::string::npos) { // each once, on one line
                ignored += (ignored.empty() ? "" : ", ") + inQuotes(name);
            }
            break;
        case ExtensionSupport::NotInThisBuild:
            diagnostics.push_back({displayName, "", "needs the glTF extension " + inQuotes(name) +
                                                        ", which this build of the lab does not decode (the desktop lab and `lab render` do)"});
            return false;
        case ExtensionSupport::Unknown:
            diagnostics.push_back({displayName, "", "needs the glTF extension " + inQuotes(name) + ", which this lab does not support"});
            return false;
        }
    }
    if (!ignored.empty()) {
        notes.push_back("required extension(s) ignored, as they only add data the lab does not draw (it uses the preset's material): " + ignored);
    }
    return true;
}

} // namespace lab::gltf_detail
