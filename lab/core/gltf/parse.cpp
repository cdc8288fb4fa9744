// parse.cpp — a glTF file parsed by tinygltf behind the lab's guards (parse.h).
#include "core/gltf/parse.h"

#include "core/gltf/compression.h"
#include "core/gltf/data_uri.h"
#include "core/gltf/extensions.h"
#include "core/gltf/glb.h"
#include "core/io/json_text.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace lab::gltf_detail {

namespace fs = std::filesystem;

namespace {

//----------------------------------------------------------------------------------------
// File access: only regular files inside the model's folder
//----------------------------------------------------------------------------------------


// tinygltf joins the base folder and the URI and asks whether that exists. Answer "no" for
// anything that leaves the folder or is not a regular file, and remember why.
bool guardedFileExists(const std::string& path, void* user) {
    auto* guard = static_cast<FileGuard*>(user);
    std::optional<fs::path> relative = relativeInside(guard->folder, fs::path(path));
    if (!relative) {
        return guard->refuse("leaves the model's folder");
    }
    std::error_code ec;
    fs::file_status status = fs::status(guard->folder / *relative, ec);
    if (!fs::exists(status)) {
        return guard->refuse("file not found");
    }
    if (!fs::is_regular_file(status)) {
        return guard->refuse("not a regular file");
    }
    return true;
}

// The default expands with wordexp(), which would run `$(...)` found in a URI. Never expand.
std::string noExpansion(const std::string& path, void*) { return path; }

bool guardedReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto* guard = static_cast<FileGuard*>(user);
    if (!guardedFileExists(path, user)) {
        if (err) {
            *err += guard->refusal;
        }
        return false;
    }
    std::string error;
    std::optional<std::string> bytes = readFile(path, guard->maxBytes, error);
    if (!bytes) {
        guard->refuse(error.c_str()); // copied before `error` goes
        if (err) {
            *err += error;
        }
        return false;
    }
    out->assign(bytes->begin(), bytes->end());
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) {
        *err += "the lab never writes glTF files";
    }
    return false;
}

// The lab ignores glTF images; count them so the user can be told.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void* user) {
    ++*static_cast<int*>(user);
    return true;
}

// Refuses, with the URI and its JSON path, every buffer or image URI that is absolute, has a
// scheme, or climbs out of the model's folder, before tinygltf tries to open anything. The
// file-system callbacks above stay as the second line of defence (symbolic links, for one).
bool checkUris(const nlohmann::json& doc, const std::string& file, Diagnostics& out) {
    bool ok = true;
    for (const char* list : {"buffers", "images"}) {
        auto items = doc.find(list);
        if (items == doc.end() || !items->is_array()) {
            continue;
        }
        for (std::size_t i = 0; i < items->size(); ++i) {
            const nlohmann::json& item = (*items)[i];
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) {
                continue;
            }
            std::string uri = item["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) {
                continue;
            }
            std::string where = std::string(list) + "[" + std::to_string(i) + "].uri";
            if (hasNul(uri)) { // "a\u0000.gltf" would open "a"
                out.push_back({file, where, inQuotes(uri) + " holds a NUL byte"});
                ok = false;
                continue;
            }
            std::size_t colon = uri.find(':'), slash = uri.find('/');
            if (uri.empty() || uri[0] == '/' || uri[0] == '\\' || (colon != std::string::npos && colon < slash)) {
                out.push_back({file, where, inQuotes(uri) + " is absolute or has a scheme; only paths relative to the model's folder are read"});
                ok = false;
                continue;
            }
            int depth = 0;
            for (const fs::path& part : fs::path(uri).lexically_normal()) {
                depth += part == ".." ? -1 : (part == "." || part.empty()) ? 0 : 1;
                if (depth < 0) {
                    break;
                }
            }
            if (depth < 0) {
                out.push_back({file, where, inQuotes(uri) + " leaves the model's folder"});
                ok = false;
            }
        }
    }
    return ok;
}

// How many objects the file declares, against `limits`: each top-level array, and the meshes'
// primitives together. False after a diagnostic naming the array and the limit.
bool checkCounts(const nlohmann::json& doc, const GltfLimits& limits, const std::string& displayName,
                 Diagnostics& diagnostics) {
    std::size_t primitives = 0;
    for (const auto& [key, value] : doc.items()) {
        if (!value.is_array()) {
            continue;
        }
        std::size_t limit = key == "nodes" ? limits.maxNodes : key == "meshes" ? limits.maxMeshes
                          : key == "accessors" ? limits.maxAccessors : limits.maxOtherObjects;
        if (value.size() > limit) {
            diagnostics.push_back({displayName, keyInPath(key, 40),
                                   std::to_string(value.size()) + " objects; the lab reads at most " + std::to_string(limit)});
            return false;
        }
        if (key != "meshes") {
            continue;
        }
        for (const nlohmann::json& mesh : value) {
            auto list = mesh.is_object() ? mesh.find("primitives") : mesh.end();
            primitives += list != mesh.end() && list->is_array() ? list->size() : 0;
        }
        if (primitives > limits.maxPrimitives) {
            diagnostics.push_back({displayName, "meshes", std::to_string(primitives) + " primitives in all; the lab reads at most " +
                                                              std::to_string(limits.maxPrimitives)});
            return false;
        }
    }
    return true;
}

// The JSON of a .gltf, or of a .glb's JSON chunk, checked before any parser recurses into it:
// nested no deeper than `maxDepth`, and every buffer or image URI inside the model's folder.
// `doc` gets the parsed JSON when it is an object (malformed JSON is left for tinygltf to
// report in its own words: `doc` is then not an object).
bool checkJson(std::string_view json, const GltfLimits& limits, const std::string& displayName, Diagnostics& diagnostics,
               nlohmann::json& doc) {
    if (!jsonNestingWithin(json, limits.maxJsonDepth)) {
        diagnostics.push_back({displayName, "", "JSON nested deeper than " + std::to_string(limits.maxJsonDepth) + " levels"});
        return false;
    }
    doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    return !doc.is_object() || (checkCounts(doc, limits, displayName, diagnostics) && checkUris(doc, displayName, diagnostics));
}


// The buffers decoded from data: URIs: each must hold its byteLength (a longer one is read up
// to it, as a .bin file is); its JSON then says 1 byte, as the placeholder holds. False after a
// diagnostic.
bool useDecodedBuffers(nlohmann::json& doc, ParsedModel& parsed, const std::string& displayName, Diagnostics& diagnostics) {
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) {
        return true;
    }
    for (std::size_t i = 0; i < buffers->size() && i < parsed.dataUris.decoded.size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        // The parser must see the placeholder where the pass put it (a duplicate "uri" key, or
        // one written with escapes, would make them disagree): else the buffer is tinygltf's.
        if (!parsed.dataUris.decoded[i] || !buffer.is_object() || !buffer.contains("uri") ||
            buffer["uri"] != kDecodedPlaceholder) {
            continue;
        }
        auto length = buffer.find("byteLength");
        if (length == buffer.end() || !length->is_number_unsigned()) {
            continue; // tinygltf refuses it in its own words
        }
        const auto byteLength = length->get<std::uint64_t>();
        const std::size_t held = parsed.dataUris.bytes[i].size();
        if (byteLength > held) {
            diagnostics.push_back({displayName, "buffers[" + std::to_string(i) + "].byteLength",
                                   std::to_string(byteLength) + " bytes, more than its data: URI holds (" + std::to_string(held) + ")"});
            return false;
        }
        parsed.buffers.bytes[i] = {parsed.dataUris.bytes[i].data(), static_cast<std::size_t>(byteLength)};
        buffer["byteLength"] = 1;
    }
    return true;
}

// A URI's %XX escapes decoded (glTF URIs are URI-encoded: Blender writes a space as %20).
// Nullopt for a broken escape or one that decodes to NUL.
std::optional<std::string> percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) ? std::stoi(std::string(1, c), nullptr, 16) : -1; };
        int hi = i + 2 < uri.size() ? hex(uri[i + 1]) : -1, lo = i + 2 < uri.size() ? hex(uri[i + 2]) : -1;
        if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) {
            return std::nullopt;
        }
        out += static_cast<char>(hi * 16 + lo);
        i += 2;
    }
    return out;
}

// Buffers in files beside the model, read (mapped) by the loader through `guard`, not by
// tinygltf: a file longer than its buffer's byteLength is allowed (the specification allows
// it; tinygltf refuses it), a shorter one refused. Buffers without a uri that are
// EXT_meshopt_compression fallbacks hold nothing: the compressed views are decoded instead.
// Each becomes a placeholder for tinygltf. False after a diagnostic.
bool readOtherBuffers(nlohmann::json& doc, bool isGlb, FileGuard& guard, std::size_t maxBytes, ParsedModel& parsed,
                      const std::string& displayName, Diagnostics& diagnostics) {
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) {
        return true;
    }
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        const std::string where = "buffers[" + std::to_string(i) + "]";
        auto length = buffer.is_object() ? buffer.find("byteLength") : buffer.end();
        if (!buffer.is_object() || length == buffer.end() || !length->is_number_unsigned() || parsed.buffers.bytes[i].data) {
            continue; // resolved already, or refused by tinygltf in its own words
        }
        const auto byteLength = length->get<std::uint64_t>();
        auto uri = buffer.find("uri");
        if (uri == buffer.end()) {
            auto ext = buffer.find("extensions");
            // (Every level's type checked: nlohmann throws on a wrong one, e.g. "fallback": 1.)
            const nlohmann::json* meshopt = ext != buffer.end() && ext->is_object() && ext->contains("EXT_meshopt_compression")
                                                ? &(*ext)["EXT_meshopt_compression"] : nullptr;
            const nlohmann::json* flag = meshopt && meshopt->is_object() && meshopt->contains("fallback") ? &(*meshopt)["fallback"] : nullptr;
            const bool fallback = flag && flag->is_boolean() && flag->get<bool>();
            if (fallback) {
                static const unsigned char kNothing = 0;
                parsed.buffers.bytes[i] = {&kNothing, 0};
                buffer["uri"] = kDecodedPlaceholder;
                buffer["byteLength"] = 1;
            } else if (!isGlb) {
                diagnostics.push_back({displayName, where, "has no uri: a .gltf's buffers are files or data: URIs"});
                return false;
            }
            continue;
        }
        if (!uri->is_string() || uri->get<std::string>().rfind("data:", 0) == 0) {
            if (uri->is_string()) {
                parsed.tinygltfReads[i] = 1; // a data: URI the decoding pass did not follow
            }
            continue;
        }
        std::optional<std::string> name = percentDecoded(uri->get<std::string>());
        if (!name) {
            diagnostics.push_back({displayName, where + ".uri", inQuotes(uri->get<std::string>()) + " has a broken %-escape"});
            return false;
        }
        const std::string path = (guard.folder / *name).string();
        std::string error;
        if (!guardedFileExists(path, &guard)) {
            diagnostics.push_back({displayName, where + ".uri", inQuotes(uri->get<std::string>()) + ": " + guard.refusal});
            return false;
        }
        std::optional<MappedFile> file = MappedFile::open(path, maxBytes, error);
        if (!file) {
            diagnostics.push_back({displayName, where + ".uri", inQuotes(uri->get<std::string>()) + ": " + error});
            return false;
        }
        if (file->bytes().size() < byteLength) {
            diagnostics.push_back({displayName, where + ".byteLength",
                                   std::to_string(byteLength) + " bytes, more than " + inQuotes(*name) + " holds (" +
                                       std::to_string(file->bytes().size()) + ")"});
            return false;
        }
        parsed.external.push_back(std::move(*file));
        parsed.buffers.bytes[i] = {reinterpret_cast<const unsigned char*>(parsed.external.back().bytes().data()),
                                   static_cast<std::size_t>(byteLength)};
        buffer["uri"] = kDecodedPlaceholder;
        buffer["byteLength"] = 1;
    }
    return true;
}

// Every buffer resolved by the loader (a GLB's BIN chunk in place, data: URIs decoded, files
// beside the model mapped) and compressed geometry decoded, after the glTF version and the
// required extensions are checked. False after a diagnostic.
bool resolveBuffers(nlohmann::json& doc, bool isGlb, bool hasDataUris, FileGuard& guard, const GltfLimits& limits,
                    ParsedModel& parsed, const std::string& displayName, Diagnostics& diagnostics) {
    if (!checkVersionAndExtensions(doc, displayName, diagnostics, parsed.notes)) {
        return false;
    }
    const std::size_t bufferCount = doc.contains("buffers") && doc["buffers"].is_array() ? doc["buffers"].size() : 0;
    parsed.buffers.bytes.resize(bufferCount);
    parsed.tinygltfReads.resize(bufferCount);
    if (hasDataUris && !useDecodedBuffers(doc, parsed, displayName, diagnostics)) {
        return false;
    }
    if (!readOtherBuffers(doc, isGlb, guard, limits.maxFileBytes, parsed, displayName, diagnostics)) {
        return false;
    }
    if (isGlb) {
        std::optional<std::vector<std::optional<std::size_t>>> inBin =
            glbBuffersInPlace(doc, parsed.bin, displayName, diagnostics);
        if (!inBin) {
            return false;
        }
        for (std::size_t i = 0; i < inBin->size() && i < bufferCount; ++i) {
            if ((*inBin)[i]) {
                parsed.buffers.bytes[i] = {reinterpret_cast<const unsigned char*>(parsed.bin->data()), *(*inBin)[i]};
            }
        }
    }
    const DecodeLimits decodeLimits{limits.maxVertices, limits.maxTriangles, limits.maxFileBytes};
    if (!decodeMeshopt(doc, parsed.buffers, decodeLimits, displayName, diagnostics) ||
        !decodeDraco(doc, parsed.buffers, decodeLimits, displayName, diagnostics)) {
        return false;
    }
    return true;
}

} // namespace

// The file parsed by tinygltf behind the guards: the GLB's chunks and the JSON checked first,
// the glTF version and required extensions, then every buffer resolved by the loader (a GLB's
// BIN chunk in place, data: URIs decoded, files beside the model mapped) and compressed
// geometry decoded (gltf_compression.h); tinygltf then parses only the JSON, with placeholders
// for the buffers. Images are skipped and counted in `skippedImages`. Nullopt after a diagnostic.
std::optional<ParsedModel> parseModel(std::string_view bytes, FileGuard& guard, int& skippedImages,
                                      const GltfLimits& limits, const std::string& displayName,
                                      Diagnostics& diagnostics) {
    tinygltf::TinyGLTF gltf;
    gltf.SetFsCallbacks({guardedFileExists, noExpansion, guardedReadWholeFile, refuseWrite, &guard});
    gltf.SetImageLoader(skipImage, &skippedImages);

    ParsedModel parsed;
    std::string err, warn, error;
    std::string_view json = bytes;
    std::string rewritten;
    nlohmann::json doc;
    const bool isGlb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (isGlb) {
        std::optional<GlbChunks> chunks = readGlbChunks(bytes, error);
        if (!chunks) {
            diagnostics.push_back({displayName, "", error});
            return std::nullopt;
        }
        json = chunks->json;
        parsed.bin = chunks->bin;
    }
    // Buffers as base64 data: URIs, decoded straight from the file's bytes before any parser
    // copies them (data_uri.h).
    bool badDataUri = false;
    std::optional<DataUriBuffers> dataUris =
        decodeDataUriBuffers(json, limits.maxJsonDepth, limits.maxOtherObjects, displayName, diagnostics, badDataUri);
    if (badDataUri) {
        return std::nullopt;
    }
    if (dataUris) {
        parsed.dataUris = std::move(*dataUris);
        json = parsed.dataUris.json;
    }
    if (!checkJson(json, limits, displayName, diagnostics, doc)) {
        return std::nullopt;
    }
    if (doc.is_object()) { // (malformed JSON goes to tinygltf as it is, to be refused in its words)
        if (!resolveBuffers(doc, isGlb, dataUris.has_value(), guard, limits, parsed, displayName, diagnostics)) {
            return std::nullopt;
        }
        rewritten = doc.dump();
        json = rewritten;
        doc = nullptr; // its memory back before tinygltf builds its own
    }
    bool ok = gltf.LoadASCIIFromString(&parsed.model, &err, &warn, json.data(), static_cast<unsigned>(json.size()),
                                       guard.folder.string());
    if (!ok) {
        std::string message = err.empty() ? "not a valid glTF file" : shortened(err); // it may quote a whole data: URI
        while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
            message.pop_back();
        }
        if (!guard.refusal.empty()) {
            message += " (" + guard.refusal + ")";
        }
        diagnostics.push_back({displayName, "", message});
        return std::nullopt;
    }
    // The buffers tinygltf decoded itself, and any the JSON pass above did not see (malformed JSON never gets here).
    for (std::size_t i = 0; i < parsed.model.buffers.size() && i < parsed.buffers.bytes.size(); ++i) {
        if (i < parsed.tinygltfReads.size() && (parsed.tinygltfReads[i] || !parsed.buffers.bytes[i].data)) {
            const std::vector<unsigned char>& data = parsed.model.buffers[i].data;
            parsed.buffers.bytes[i] = {data.data(), data.size()};
        }
    }
    return parsed;
}

} // namespace lab::gltf_detail
