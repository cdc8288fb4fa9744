// draco_mesh.h — one Draco mesh decoded: bytes in, plain arrays out.
//
// The decoder's whole interface, as three.js's Draco loader has one: the compressed bytes of a
// KHR_draco_mesh_compression primitive and which attributes it names go in; the points, the
// positions and normals as floats, the triangles as 32-bit indices come out, or the reason and
// where it lies. Everything the decoder's output is checked for (limits, components, every
// triangle's points) is checked inside, so the answer is either usable or a message.
//
// `decodeDracoMesh` runs libdraco (draco_mesh.cpp). The desktop and the command line link it
// (draco_linked.cpp); the page fetches it as a module of its own the first time a model needs it
// (draco_fetched.cpp, lab/platform/web_draco_module.cpp), and the two talk through `packDracoResult`
// and `unpackDracoResult` (draco_wire.cpp): one flat array of bytes each way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace lab::gltf_detail {

// One attribute the extension names (POSITION, NORMAL).
struct DracoAttributeQuery {
    bool listed = false;   // the extension's `attributes` has it
    std::int64_t id = -1;  // its unique id in the Draco data; -1 when what is listed is not one
    bool used = false;     // the primitive's own `attributes` has it: its values are wanted
};

struct DracoQuery {
    DracoAttributeQuery position, normal;
    std::uint64_t maxPoints = 0, maxFaces = 0;
    std::uint64_t maxBytes = 0; // what the decoded arrays may take: the file's limit less what was decoded before
};

// The decoded mesh: `positions` and `normals` hold points × 3 floats when used (else empty),
// `indices` faces × 3 points, each below `points`.
struct DracoMesh {
    std::uint32_t points = 0, faces = 0;
    std::vector<float> positions, normals;
    std::vector<std::uint32_t> indices;
};

// Why the data could not be used: `where` is appended to the extension's place
// (".attributes.NORMAL"), or empty.
struct DracoFailure {
    std::string where, message;
};

using DracoResult = std::variant<DracoMesh, DracoFailure>;

// libdraco's decoder with the checks above. Never throws.
DracoResult decodeDracoMesh(const unsigned char* data, std::size_t size, const DracoQuery& query);

// The result as one array of bytes (little-endian; what the page's module hands back), and back.
// Unpacking checks every length against the bytes and every index against the points: nullopt
// when they do not fit.
std::vector<unsigned char> packDracoResult(const DracoResult& result);
std::optional<DracoResult> unpackDracoResult(const unsigned char* data, std::size_t size);

// The query as 8 doubles (the module's arguments): listed, id, used for each attribute, then the
// point and face limits; the byte limit separately. And back.
struct DracoQueryWords {
    double words[8];
};
DracoQueryWords queryWords(const DracoQuery& query);
DracoQuery queryFromWords(const double* words, double maxBytes);

} // namespace lab::gltf_detail
