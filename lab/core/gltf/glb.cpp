// glb.cpp — the GLB container: chunks checked against the file, BIN buffers left in place.
#include "core/gltf/glb.h"

#include "core/gltf/data_uri.h"

#include <cstdio>
#include <cstring>

namespace lab::gltf_detail {

namespace {

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au; // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942u;  // "BIN\0"

// What tinygltf gets instead of a buffer or an image stored in the BIN chunk: the one placeholder
// every buffer the loader reads itself becomes (data_uri.h).
constexpr const char* kPlaceholderUri = kDecodedPlaceholder;

std::uint32_t u32(std::string_view bytes, std::uint64_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v; // GLB is little-endian, as is every machine the lab runs on
}

std::string hex(std::uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", v);
    return text;
}

} // namespace

std::optional<GlbChunks> readGlbChunks(std::string_view bytes, std::string& error) {
    const std::uint64_t size = bytes.size();
    if (size < 4 || std::memcmp(bytes.data(), "glTF", 4) != 0) {
        error = "not a GLB file (no \"glTF\" header)";
        return std::nullopt;
    }
    if (size < 12) {
        error = "GLB file of " + std::to_string(size) + " bytes ends inside its 12-byte header";
        return std::nullopt;
    }
    if (u32(bytes, 4) != 2) {
        error = u32(bytes, 4) == 1 ? std::string("a binary glTF 1.0 file (GLB version 1); the lab reads glTF 2.0: export or convert the model to glTF 2.0") : "GLB version " + std::to_string(u32(bytes, 4)) + " (expected 2)";
        return std::nullopt;
    }
    if (u32(bytes, 8) != size) {
        error = "GLB header claims " + std::to_string(u32(bytes, 8)) + " bytes but the file has " + std::to_string(size);
        return std::nullopt;
    }
    if (size < 20) {
        error = "GLB file of " + std::to_string(size) + " bytes ends inside its JSON chunk's header";
        return std::nullopt;
    }
    const std::uint64_t jsonLength = u32(bytes, 12);
    if (u32(bytes, 16) != kJsonChunk) {
        error = "GLB's first chunk is not JSON (type " + hex(u32(bytes, 16)) + ")";
        return std::nullopt;
    }
    if (jsonLength == 0 || 20 + jsonLength > size) {
        error = "GLB JSON chunk of " + std::to_string(jsonLength) + " bytes " +
                (jsonLength == 0 ? std::string("is empty") : "runs past the end of the file");
        return std::nullopt;
    }
    GlbChunks chunks;
    chunks.json = bytes.substr(20, static_cast<std::size_t>(jsonLength));
    // The next chunk starts right after the JSON chunk's data (its length includes its padding).
    const std::uint64_t at = 20 + jsonLength;
    if (at == size) {
        return chunks;
    }
    if (at + 8 > size) {
        error = "GLB file ends inside the header of the chunk after JSON (" + std::to_string(size - at) + " bytes left)";
        return std::nullopt;
    }
    const std::uint64_t binLength = u32(bytes, at);
    if (u32(bytes, at + 4) != kBinChunk) {
        error = "GLB's second chunk is not BIN (type " + hex(u32(bytes, at + 4)) + ")";
        return std::nullopt;
    }
    if (at + 8 + binLength > size) {
        error = "GLB BIN chunk claims " + std::to_string(binLength) + " bytes, more than the file holds (" +
                std::to_string(size - at - 8) + " after its header)";
        return std::nullopt;
    }
    if (binLength % 4 != 0) {
        error = "GLB BIN chunk length " + std::to_string(binLength) + " is not a multiple of 4";
        return std::nullopt;
    }
    chunks.bin = bytes.substr(static_cast<std::size_t>(at + 8), static_cast<std::size_t>(binLength));
    return chunks;
}

std::optional<std::vector<std::optional<std::size_t>>> glbBuffersInPlace(nlohmann::json& doc,
                                                                         const std::optional<std::string_view>& bin,
                                                                         const std::string& displayName,
                                                                         Diagnostics& diagnostics) {
    struct {
        std::vector<std::optional<std::size_t>> inBin;
    } out;
    auto buffers = doc.find("buffers");
    if (buffers != doc.end() && buffers->is_array()) {
        out.inBin.resize(buffers->size());
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            nlohmann::json& buffer = (*buffers)[i];
            // As tinygltf reads a GLB: a buffer whose uri is missing (or not a string) is the BIN chunk.
            if (!buffer.is_object() || (buffer.contains("uri") && buffer["uri"].is_string())) {
                continue;
            }
            auto length = buffer.find("byteLength");
            if (length == buffer.end() || !length->is_number_unsigned()) {
                continue; // tinygltf refuses it in its own words
            }
            const std::string where = "buffers[" + std::to_string(i) + "]";
            const auto byteLength = length->get<std::uint64_t>();
            if (!bin) {
                diagnostics.push_back({displayName, where, "has no uri, so it is the GLB's BIN chunk, but the file has none"});
                return std::nullopt;
            }
            if (byteLength > bin->size()) {
                diagnostics.push_back({displayName, where + ".byteLength",
                                       std::to_string(byteLength) + " bytes, more than the GLB's BIN chunk of " +
                                           std::to_string(bin->size())});
                return std::nullopt;
            }
            out.inBin[i] = static_cast<std::size_t>(byteLength);
            buffer["uri"] = kPlaceholderUri;
            buffer["byteLength"] = 1;
        }
    }
    // Images in a bufferView of a BIN buffer: a placeholder image instead (counted and skipped
    // like any other). Anything tinygltf would refuse is left for it to refuse.
    auto images = doc.find("images");
    const auto views = doc.find("bufferViews");
    if (images != doc.end() && images->is_array() && views != doc.end() && views->is_array()) {
        for (nlohmann::json& image : *images) {
            if (!image.is_object() || image.contains("uri") || !image.contains("bufferView") ||
                !image["bufferView"].is_number_unsigned() || image["bufferView"].get<std::uint64_t>() >= views->size()) {
                continue;
            }
            const nlohmann::json& view = (*views)[image["bufferView"].get<std::size_t>()];
            if (view.is_object() && view.contains("buffer") && view["buffer"].is_number_unsigned() &&
                view["buffer"].get<std::uint64_t>() < out.inBin.size() && out.inBin[view["buffer"].get<std::size_t>()]) {
                image.erase("bufferView");
                image["uri"] = kPlaceholderUri;
            }
        }
    }
    return std::move(out.inBin);
}

} // namespace lab::gltf_detail
